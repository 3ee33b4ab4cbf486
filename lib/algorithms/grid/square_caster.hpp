#pragma once
// cast_ray's answers for a simulator: many rays from everywhere, each cast
// once, through one unchanging map of walls.
//
// Per cell, the Chebyshev distance k (in cells, capped at 255) to the
// nearest stopping cell: the square of 2k - 1 cells centred on the cell
// holds none. A ray leaves that square in one step, at a crossing computed
// exactly (no safety margin, unlike a Euclidean distance map's jumps), and
// looks up the cell it enters; a cell with k = 0 stops it. Next to a wall
// the square is the cell itself, so the walk is cast_ray's cell walk there,
// and in open space it crosses many cells a step (about 6 steps a ray in a
// cave at 3 cm where cast_ray walks 90 cells).
//
// Each step is a chain of dependent arithmetic and one memory read, with no
// branch that depends on the map; ranges() walks four rays side by side so
// that their chains overlap, or sixteen on a processor with AVX2
// (square_caster_avx2.cpp, chosen at run time, the same answers).
//
// Every crossing is computed from the ray's origin, never accumulated, so a
// ray's answer depends on the ray alone; it is cast_ray's up to rounding
// (about 1e-12 m), except that where a ray passes through a cell corner, or
// within rounding of one, the two may take different cells beside it (and
// from there meet different walls).
//
// Compared with RangeCaster (a Euclidean distance map; for a particle
// cloud's rays, which start near one another): the same byte a cell, a
// build without a distance transform, and fewer, branch-free steps
// (bench/distance_map_bench: 2-5x faster per ray).

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace playerkit::grid {

namespace lanes {
struct LaneStart;  // square_caster_lanes.hpp
}

class SquareCaster {
 public:
  SquareCaster() = default;
  // Two passes over the cells (a 4000 x 4000 grid in well under a second);
  // holds a byte a cell and does not refer to the grid afterwards.
  SquareCaster(const OccupancyGrid& grid, RayStop stop);

  // cast_ray(grid, origin, angle, max_range, stop) up to rounding: the
  // distance to where the ray enters the first stopping cell, or max_range
  // if it meets none within max_range or leaves the grid first (an origin
  // outside the grid gives max_range; one inside a stopping cell gives 0).
  [[nodiscard]] double range(const Eigen::Vector2d& origin, double angle, double max_range) const;
  // The same along `direction`, a unit vector (cos angle, sin angle), for
  // callers that turn one vector from ray to ray instead of calling trig.
  [[nodiscard]] double range(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                             double max_range) const;

  struct Ray {
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // a unit vector
    double max_range = 0.0;
  };
  // How ranges() walks many rays: `automatic` takes the vector walk (AVX2,
  // sixteen walks side by side) for 32 rays or more on a processor that has
  // it, `scalar` the portable one (four side by side). Their answers are
  // the same bit for bit.
  enum class Walker { automatic, scalar };
  // range(ray.origin, ray.direction, ray.max_range) for every ray, into
  // `ranges` (as many as rays; throws std::invalid_argument otherwise):
  // the same answers, bit for bit, in less time than one by one.
  void ranges(std::span<const Ray> rays, std::span<double> ranges, Walker walker = Walker::automatic) const;
  // Whether this processor has the vector walk (AVX2).
  [[nodiscard]] static bool has_vector_walker();
  // ranges() for a fan: rays from one origin with one max_range (a laser's
  // scan), given by their unit directions. The same answers bit for bit;
  // the origin's part of starting each walk is done once.
  void fan_ranges(const Eigen::Vector2d& origin, std::span<const Eigen::Vector2d> directions, double max_range,
                  std::span<double> ranges, Walker walker = Walker::automatic) const;

  // How far around `point` (in x and in y, metres) no cell stops a ray:
  // (k - 1) cells for the clearance k of its cell; 0 in a stopping cell or
  // off the grid. A body within that square needs no cell-by-cell test.
  [[nodiscard]] double clear_around(const Eigen::Vector2d& point) const;

  [[nodiscard]] RayStop stop() const { return stop_; }

 private:
  // What a ray's steps read, fixed for the ray: cell units from the grid's
  // corner. The walk's position (cell, where it was entered) lives in the
  // callers' locals, so that it stays in registers from step to step.
  struct Walk {
    double x = 0.0, y = 0.0;    // origin
    double dx = 0.0, dy = 0.0;  // direction
    double inverse_x = 0.0, inverse_y = 0.0;
    double length = 0.0;        // max_range
    int step_x = 1, step_y = 1;
    // The ray these were computed for: a laser's rays share their origin and
    // max_range, and the divisions that give x, y and length are worth keeping.
    double from_x = std::numeric_limits<double>::quiet_NaN(), from_y = from_x, from_range = from_x;
  };
  struct Start {
    bool walks = false;  // false: answered at once, with `range`
    int col = 0, row = 0;
    int clearance = 0;  // of the cell (col, row)
    double range = 0.0;
  };
  static constexpr int kWalking = 0, kHit = 1, kGone = 2;
  Start start(Walk& walk, const Ray& ray) const;
  // start() in its two parts: the origin's and max_range's (`walks` false
  // when the origin is off the grid), then the direction's (false: it has
  // none). A fan does the first once.
  Start start_origin(Walk& walk, const Eigen::Vector2d& origin, double max_range) const;
  bool start_direction(Walk& walk, const Eigen::Vector2d& direction) const;
  int advance(const Walk& walk, int& col, int& row, double& along, int& clearance) const;
  [[nodiscard]] bool takes_vector_walk(std::size_t rays, Walker walker) const;
  static lanes::LaneStart lane_start(const Walk& walk, const Start& begun, double max_range);
  void scalar_ranges(std::span<const Ray> rays, std::span<double> ranges) const;
  void vector_ranges(std::span<const Ray> rays, std::span<double> ranges) const;

  // Per cell (row-major): 0 for a stopping cell, else the Chebyshev
  // distance in cells to the nearest one, capped at 255. Three bytes more
  // than cells: the vector walk reads four bytes at a cell.
  std::vector<std::uint8_t> clearance_;
  RayStop stop_ = RayStop::occupied_or_unknown;
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
};

}  // namespace playerkit::grid
