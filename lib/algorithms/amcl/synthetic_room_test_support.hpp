#pragma once
// Test fixtures shared by the amcl tests: a 10 m x 6 m walled room with two
// obstacles placed so that no rotation maps the room onto itself, and a
// simulated laser that ray casts it.

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
