#pragma once
// Internal: the static map of a world, an occupancy grid built from the
// world's bitmaps and walls.

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/worldfile/worldfile_location.hpp"

namespace playerkit::sim::worldfile {

// A rectangle of wall: `size` centred on `centre`, turned by its yaw.
struct WallRectangle {
  geometry::Pose2 centre;
  Eigen::Vector2d size = Eigen::Vector2d::Zero();
};

enum class WallPixels {
  non_zero,  // Stage 1.3: any non-zero pixel is a wall
  dark,      // Stage 2 and later: first channel <= 127 is a wall
};

// One bitmap placed in the world. Pixel (c, g), g counted from the BOTTOM
// row, covers [(c - centre.x) sx, (c + 1 - centre.x) sx] x [(g - centre.y) sy,
// (g + 1 - centre.y) sy] in the frame `pose`.
struct BitmapPlacement {
  std::filesystem::path file;
  SourceLocation where;  // of the property naming the file, for errors
  WallPixels walls = WallPixels::dark;
  // Stage 1.3: metres per pixel, and whether the image's centre (true) or
  // its bottom-left corner (false) sits at `pose`.
  std::optional<double> metres_per_pixel;
  bool centred = true;
  // Stage 3/4 (metres_per_pixel empty): the dark pixels' bounding box is
  // stretched to this size and centred on `pose`.
  Eigen::Vector2d stretch_to = Eigen::Vector2d::Zero();
  geometry::Pose2 pose;
};

// Where a bitmap's pixels lie in the world, so that the map's cells can be
// its pixels.
struct PixelLattice {
  double pixel = 0.0;  // the finer of the pixel's two edges, metres
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();  // a pixel corner in the world
  bool axis_aligned = true;  // turned by a whole number of right angles
};

struct MapPlan;

// A bitmap as wall rectangles (runs of wall pixels along rows), added to
// `plan` with its pixel lattice. Throws WorldFileError at `where` for an
// unreadable image.
void add_bitmap_walls(const BitmapPlacement& bitmap, MapPlan& plan, std::vector<std::string>& warnings);

struct MapPlan {
  double resolution = 0.05;
  std::vector<WallRectangle> walls;
  std::vector<PixelLattice> bitmaps;  // one per bitmap with walls
  std::vector<Eigen::Vector2d> must_cover;  // model positions the grid must hold
  // Stage 1.3: the world is [0, max(minimum_size, extent)] in x and y, and
  // closed by a wall one cell inside its border. Otherwise the grid covers
  // what is there plus a margin, all free outside the walls.
  bool positive_quadrant = false;
  Eigen::Vector2d minimum_size = Eigen::Vector2d::Zero();
  SourceLocation where;  // the world file, for errors
};

// Every cell a wall overlaps (more than touching) is occupied, the others
// free. The cell is `resolution`, or the finest bitmap pixel where that is
// coarser and every bitmap is axis-aligned: then the cells are laid on that
// bitmap's pixels, which they match one for one (rays and collisions cost
// what the bitmap's detail needs, not what `resolution` would). The grid is
// made coarser (a whole multiple of that cell) when it would have more than
// grid::kMaxGridCells cells, never coarser than the finest bitmap pixel (an
// error then); a warning says so.
grid::OccupancyGrid build_map(const MapPlan& plan, std::vector<std::string>& warnings);

// Marks the cells `wall` overlaps occupied.
void mark_wall(grid::OccupancyGrid& grid, const WallRectangle& wall);

}  // namespace playerkit::sim::worldfile
