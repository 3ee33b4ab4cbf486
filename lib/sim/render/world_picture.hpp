#pragma once
// A picture of a simulated world, as Stage's window showed it: the map
// (walls dark, floor white, unknown and outside grey), each robot's trail,
// the latest laser and sonar rays (faint lines from the sensor to where each
// reading ended, a dot where it hit something), fiducial sightings (a green
// line to the fiducial, its id beside it), every model's body in its colour
// with each robot's heading, and the simulation time in the top left corner.
//
//   const auto snapshot = render::take_snapshot(world, &trails);  // world locked
//   const render::Picture picture = render::draw_world(snapshot);  // unlocked
//   render::write_png("world.png", picture);

#include <cstdint>
#include <vector>

#include "sim/render/picture_frame.hpp"
#include "sim/render/world_snapshot.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim::render {

struct PictureOptions {
  // The longer side of the picture; the scale (pixels per metre) follows.
  int max_side_pixels = 1600;
  bool caption = true;  // "t = 12.3 s" in the top left corner
};

// The colours the picture uses for what is not a model's own colour.
namespace colors {
inline constexpr Rgb kWall{32, 32, 32};
inline constexpr Rgb kFloor{255, 255, 255};
inline constexpr Rgb kUnknown{205, 205, 205};  // map_saver's unknown; also outside the map
inline constexpr Rgb kLaserRay{0, 110, 255};   // blended at kRayOpacity over what lies below
inline constexpr Rgb kSonarRay{255, 140, 0};
inline constexpr double kRayOpacity = 0.3;
inline constexpr Rgb kLaserHit{0, 70, 220};
inline constexpr Rgb kSonarHit{210, 100, 0};
inline constexpr Rgb kSighting{0, 150, 0};
inline constexpr Rgb kHeading{0, 0, 0};
}  // namespace colors

struct Picture {
  PictureFrame frame;
  std::vector<std::uint8_t> rgb;  // width x height x 3, rows from the top

  [[nodiscard]] int width() const { return frame.width(); }
  [[nodiscard]] int height() const { return frame.height(); }
  // Unchecked: col < width(), row < height().
  [[nodiscard]] Rgb at(int col, int row) const;
};

// The frame holds the map and every body (bodies far off the map are cut
// off two map sizes beyond it). Throws std::invalid_argument for a
// max_side_pixels below 1.
[[nodiscard]] PictureFrame frame_for(const WorldSnapshot& snapshot, int max_side_pixels);
[[nodiscard]] Picture draw_world(const WorldSnapshot& snapshot, const PictureOptions& options = {});

}  // namespace playerkit::sim::render
