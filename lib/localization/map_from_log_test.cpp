// A map from the first scans of the intel log (a coarse grid, to stay fast).

#include "localization/map_from_log.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "localization/localization_test_support.hpp"

namespace playerkit::localization {
namespace map_from_log_test {

TEST(MapFromLog, IntelExcerptHasWallsAtBeamEndsAndFreeSpaceWhereTheRobotDrove) {
  grid::OccupancyMappingParameters parameters;
  parameters.resolution = 0.1;
  MapFromLogOptions options;
  options.max_scans = 80;
  const auto result = map_from_log(testing::radish("intel-corrected.log.gz"), parameters, options);
  EXPECT_EQ(result.scans_used, 80u);
  const auto& grid = result.grid;

  std::size_t occupied = 0, free = 0;
  for (const auto cell : grid.cells()) {
    occupied += cell == grid::CellState::occupied;
    free += cell == grid::CellState::free;
  }
  EXPECT_GT(occupied, 300u);
  EXPECT_GT(free, 3 * occupied);

  // The poses the robot scanned from are free (but for a few: a cell needs
  // several beams through it, and the laser looks forward only); most beam
  // ends are walls.
  LoggedScanReader reader(testing::radish("intel-corrected.log.gz"));
  std::size_t ends = 0, ends_occupied = 0, poses_free = 0, poses_occupied = 0;
  for (int i = 0; i < 80; ++i) {
    const auto scan = reader.next();
    ASSERT_TRUE(scan);
    const auto at_pose = grid.state_at_world(scan->truth->translation());
    poses_free += at_pose == grid::CellState::free;
    poses_occupied += at_pose == grid::CellState::occupied;
    for (std::size_t b = 0; b < scan->ranges.size(); b += 5) {
      if (scan->ranges[b] >= 10.0) continue;
      const double bearing = scan->angle_min + static_cast<double>(b) * scan->angle_increment;
      const auto end = scan->truth->transform({scan->ranges[b] * std::cos(bearing), scan->ranges[b] * std::sin(bearing)});
      ++ends;
      ends_occupied += grid.state_at_world(end) == grid::CellState::occupied;
    }
  }
  EXPECT_GE(poses_free, 72u);
  EXPECT_EQ(poses_occupied, 0u);
  EXPECT_GT(ends, 1000u);
  EXPECT_GT(static_cast<double>(ends_occupied), 0.8 * static_cast<double>(ends));
}

TEST(MapFromLog, StrideAndMissingTruthAreHonoured) {
  testing::TemporaryDirectory directory;
  const auto log = directory.write(
      "robot.log",
      "0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.000 +00.000 +00.000 0\n"
      "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n");
  EXPECT_THROW(map_from_log(log, {}, {}), std::runtime_error);  // no truth
  MapFromLogOptions options;
  options.use_odometry_without_truth = true;
  const auto result = map_from_log(log, {}, options);
  EXPECT_EQ(result.scans_used, 1u);
  // One scan: a beam's end is a hit (occupied), the cells it crossed one
  // miss each, not yet enough to call free.
  const geometry::Pose2 laser{1.0, 2.0, 0.5};
  EXPECT_EQ(result.grid.state_at_world(laser.transform({2.0, 0.0})), grid::CellState::occupied);
  EXPECT_EQ(result.grid.state_at_world(laser.transform({1.0, 0.0})), grid::CellState::unknown);

  options = {};
  options.scan_stride = 10;
  options.max_scans = 100;
  EXPECT_EQ(map_from_log(testing::radish("intel-corrected.log.gz"), {.resolution = 0.2}, options).scans_used, 10u);
}

}  // namespace map_from_log_test
}  // namespace playerkit::localization
