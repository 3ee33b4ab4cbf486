#pragma once
// A drive through Player's cave map for the amcl driver tests: the true
// path, scans ray-cast from it, and odometry that is slightly wrong (5% long
// on distance, a slow heading drift, and in a frame of its own), written as
// a Player text log that readlog replays.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"
#include "drivers/logfile/logfile_test_support.hpp"
#include "log/text_log_writer.hpp"
#include "map/map_file.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers::testing {

inline std::filesystem::path cave_map_path() {
  return std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "maps" / "cave.pnm";
}

// As Player's own test_localize.cfg (and the manual's Stage example).
inline grid::OccupancyGrid load_cave() {
  return map::load_map(cave_map_path(), {.resolution = 0.03, .negate = true});
}

struct DriveStep {
  geometry::Pose2 truth;
  geometry::Pose2 odometry;
  protocol::Timestamp time;
};

// 6 m east along y = 1 m through the large room of the cave, then a 90
// degree turn on the spot, one step per 0.1 s.
inline std::vector<DriveStep> cave_drive() {
  std::vector<DriveStep> steps;
  geometry::Pose2 truth{0.0, 1.0, 0.0};
  geometry::Pose2 odometry{10.0, -3.0, 0.5};  // an odometry frame unrelated to the map's
  constexpr double kStep = 0.1;
  for (int i = 0; i < 70; ++i) {
    steps.push_back({truth, odometry, {1000 + static_cast<std::uint32_t>(i / 10),
                                        static_cast<std::uint32_t>(i % 10) * 100000}});
    // The robot's true motion, then what its wheels make of it.
    const geometry::Pose2 motion = i < 60 ? geometry::Pose2{kStep, 0.0, 0.0}
                                          : geometry::Pose2{0.0, 0.0, std::numbers::pi / 20.0};
    truth = truth.compose(motion);
    odometry = odometry.compose({motion.x * 1.05, 0.0, motion.yaw * 1.03 + 0.002});
  }
  return steps;
}

inline constexpr double kScanMaxRange = 8.0;

// 181 beams over 180 degrees, 1 degree apart, in mm, as a SICK LMS200 reports.
inline protocol::LaserData cast_scan(const grid::OccupancyGrid& map, const geometry::Pose2& pose) {
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = 1;
  scan.range_count = 181;
  for (int i = 0; i < 181; ++i) {
    const double bearing = (-90.0 + i) * std::numbers::pi / 180.0;
    const double range = grid::cast_ray(map, pose.translation(), pose.yaw + bearing, kScanMaxRange);
    scan.ranges[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(std::lround(range * 1000.0));
  }
  return scan;
}

inline protocol::PositionData odometry_data(const geometry::Pose2& odometry) {
  protocol::PositionData data;
  data.xpos = static_cast<std::int32_t>(std::lround(odometry.x * 1000.0));
  data.ypos = static_cast<std::int32_t>(std::lround(odometry.y * 1000.0));
  long degrees = std::lround(odometry.yaw * 180.0 / std::numbers::pi);
  data.yaw = static_cast<std::int32_t>((degrees % 360 + 360) % 360);  // 1.5 reports 0..359
  return data;
}

// position:0 then laser:0 per step, same data time, logged 10 ms later.
inline void write_cave_log(const std::filesystem::path& path, const std::vector<DriveStep>& steps) {
  const grid::OccupancyGrid map = load_cave();
  std::ofstream out(path);
  out << log::log_file_header();
  for (const DriveStep& step : steps) {
    const protocol::Timestamp logged{step.time.sec, step.time.usec + 10000};
    out << log::format_data_line(data_message({protocol::kPositionCode, 0},
                                              protocol::encode(odometry_data(step.odometry)), logged, step.time),
                                 "testhost", 6665);
    out << log::format_data_line(data_message({protocol::kLaserCode, 0},
                                              protocol::encode(cast_scan(map, step.truth)), logged, step.time),
                                 "testhost", 6665);
  }
}

}  // namespace playerkit::drivers::testing
