#pragma once
// cast_ray's answers, faster, for callers that cast many rays through one
// unchanging map (the beam laser model casts one per beam per particle).
//
// Ray marching ("sphere tracing", Hart 1996) on a distance map to the
// stopping cells: where the nearest stopping cell is d away, the ray can
// jump almost d at once instead of walking every cell. Near a stopping cell
// the jumps shrink, and the last stretch is the same exact cell walk
// cast_ray uses, so the returned range is cast_ray's up to floating-point
// rounding (about 1e-12 m). Where rounding decides the path (a ray through
// a cell corner, whose two side cells one walk or the other may visit), the
// whole ray is walked as cast_ray walks it, so it decides the same way.
//
// Faster when consecutive rays start near one another, as a particle
// cloud's do: 1.4-2x per ray on 5 cm indoor maps, more where rays run long
// through open space. On a huge map with every ray starting somewhere new,
// each jump waits on a cache miss, and cast_ray's walk, whose memory reads
// do not depend on one another, is faster.

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace playerkit::grid {

class RangeCaster {
 public:
  RangeCaster() = default;
  // Runs a distance transform of the grid (about 0.3 s for 4000 x 4000
  // cells), so build one per map and keep it; it holds a byte per cell and
  // does not refer to the grid afterwards. `max_jump` (metres, at most 255
  // cells are used) caps a single jump; it changes only the speed, never an
  // answer.
  RangeCaster(const OccupancyGrid& grid, RayStop stop, double max_jump = 10.0);

  // cast_ray(grid, origin, angle, max_range, stop) to ~1e-12 m: the distance to
  // where the ray enters the first stopping cell, or max_range if it meets
  // none within max_range or leaves the grid first (an origin outside the
  // grid gives max_range; one inside a stopping cell gives 0).
  double range(const Eigen::Vector2d& origin, double angle, double max_range) const;

  RayStop stop() const { return stop_; }

 private:
  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(col);
  }

  // Per cell, whole cells (rounded down, capped at max_jump and 255) from
  // its centre to the nearest stopping cell's, from a DistanceMap; 0 only in
  // stopping cells, which is how walks tell where to stop.
  std::vector<std::uint8_t> clearance_;
  RayStop stop_ = RayStop::occupied_or_unknown;
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
};

}  // namespace playerkit::grid
