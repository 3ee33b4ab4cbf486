#pragma once
// Test fixtures shared by the amcl tests: a 10 m x 6 m walled room with two
// obstacles placed so that no rotation maps the room onto itself, office
// corridors, and a simulated laser that ray casts them.

#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

namespace playerkit::amcl::test {

inline constexpr double room_resolution = 0.05;

inline void fill_box(grid::OccupancyGrid& map, double x0, double y0, double x1, double y1,
                     grid::CellState state) {
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const Eigen::Vector2d centre = map.cell_centre({col, row});
      if (centre.x() >= x0 && centre.x() <= x1 && centre.y() >= y0 && centre.y() <= y1) {
        map.set(col, row, state);
      }
    }
  }
}

// Room interior [0.1, 9.9] x [0.1, 5.9], walls 0.1 m thick; a 1 m x 1 m box
// centred at (6.5, 2.0) and a 0.4 m x 1.2 m pillar centred at (2.0, 4.3).
inline std::shared_ptr<grid::OccupancyGrid> make_room() {
  auto map = std::make_shared<grid::OccupancyGrid>(200, 120, room_resolution,
                                                   Eigen::Vector2d(0.0, 0.0),
                                                   grid::CellState::occupied);
  fill_box(*map, 0.1, 0.1, 9.9, 5.9, grid::CellState::free);
  fill_box(*map, 6.0, 1.5, 7.0, 2.5, grid::CellState::occupied);
  fill_box(*map, 1.8, 3.7, 2.2, 4.9, grid::CellState::occupied);
  return map;
}

// Office corridors as a map made from scans has them: free space, walls
// 0.1 m thick, unknown beyond. A 1.2 m corridor along x (interior y 2.4 to
// 3.6, x 0.5 to 16), a side corridor up from x 7.4-8.6 to y 12.5, and two
// door niches (x 3.0-3.8 above it, x 12.0-12.8 below) so that it is not
// the same everywhere along x.
inline std::shared_ptr<grid::OccupancyGrid> make_corridors() {
  auto map = std::make_shared<grid::OccupancyGrid>(340, 260, room_resolution, Eigen::Vector2d(0.0, 0.0),
                                                   grid::CellState::unknown);
  constexpr double wall = 0.1;
  const double spaces[][4] = {{0.5, 2.4, 16.0, 3.6}, {7.4, 3.6, 8.6, 12.5}, {3.0, 3.6, 3.8, 4.4}, {12.0, 1.6, 12.8, 2.4}};
  for (const auto& box : spaces) {
    fill_box(*map, box[0] - wall, box[1] - wall, box[2] + wall, box[3] + wall, grid::CellState::occupied);
  }
  for (const auto& box : spaces) fill_box(*map, box[0], box[1], box[2], box[3], grid::CellState::free);
  return map;
}

struct LaserSpec {
  std::size_t beams = 181;
  double field_of_view = std::numbers::pi;  // centred on the sensor's x axis
  double max_range = 8.0;
  geometry::Pose2 sensor_pose{0.1, 0.0, 0.0};
};

// The scan a laser at `robot` would read, with Gaussian range noise.
inline LaserScan simulate_scan(const grid::OccupancyGrid& map, const geometry::Pose2& robot,
                               const LaserSpec& spec = {}, double range_noise = 0.0,
                               std::mt19937_64* rng = nullptr) {
  LaserScan scan;
  scan.max_range = spec.max_range;
  scan.sensor_pose = spec.sensor_pose;
  const geometry::Pose2 sensor = robot.compose(spec.sensor_pose);
  std::normal_distribution<double> noise(0.0, range_noise);
  for (std::size_t i = 0; i < spec.beams; ++i) {
    const double bearing = -spec.field_of_view / 2 +
                           spec.field_of_view * static_cast<double>(i) /
                               static_cast<double>(spec.beams - 1);
    double range = grid::cast_ray(map, sensor.translation(), sensor.yaw + bearing, spec.max_range,
                                  grid::RayStop::occupied);
    if (range < spec.max_range && rng != nullptr && range_noise > 0.0) {
      range = std::clamp(range + noise(*rng), 0.0, spec.max_range - 1e-6);
    }
    scan.ranges.push_back(range);
    scan.bearings.push_back(bearing);
  }
  return scan;
}

}  // namespace playerkit::amcl::test
