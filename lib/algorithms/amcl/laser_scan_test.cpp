#include "algorithms/amcl/laser_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace playerkit::amcl {
namespace laser_scan_test {

LaserScan straight_scan(std::size_t count) {
  LaserScan scan;
  for (std::size_t i = 0; i < count; ++i) {
    scan.ranges.push_back(1.0 + static_cast<double>(i));
    scan.bearings.push_back(0.01 * static_cast<double>(i));
  }
  scan.max_range = 1000.0;
  return scan;
}

TEST(PrepareBeams, SubsamplesEvenlyIncludingBothEnds) {
  PreparedBeams beams;
  prepare_beams(straight_scan(181), 30, beams);
  ASSERT_EQ(beams.size(), 30u);
  EXPECT_EQ(beams.ranges.front(), 1.0);
  EXPECT_EQ(beams.ranges.back(), 181.0);
  for (std::size_t i = 1; i < beams.size(); ++i) {
    const double gap = beams.ranges[i] - beams.ranges[i - 1];
    EXPECT_GE(gap, 6.0);
    EXPECT_LE(gap, 7.0);
  }
  prepare_beams(straight_scan(10), 30, beams);
  EXPECT_EQ(beams.size(), 10u);
}

TEST(PrepareBeams, PrecomputesAnglesAndEndpointsInTheRobotFrame) {
  LaserScan scan;
  scan.ranges = {2.0};
  scan.bearings = {0.5};
  scan.sensor_pose = {0.3, -0.1, 0.25};
  PreparedBeams beams;
  prepare_beams(scan, 30, beams);
  ASSERT_EQ(beams.size(), 1u);
  EXPECT_DOUBLE_EQ(beams.robot_angle[0], 0.75);
  EXPECT_NEAR(beams.end_x[0], 0.3 + 2.0 * std::cos(0.75), 1e-12);
  EXPECT_NEAR(beams.end_y[0], -0.1 + 2.0 * std::sin(0.75), 1e-12);
}

TEST(PrepareBeams, MarksNoReturnAndSkipsUnusableReadings) {
  LaserScan scan;
  scan.max_range = 8.0;
  scan.min_range = 0.05;
  scan.ranges = {1.0, 8.0, 9.5, std::numeric_limits<double>::infinity(),
                 std::numeric_limits<double>::quiet_NaN(), 0.01, 2.0};
  scan.bearings = {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  PreparedBeams beams;
  prepare_beams(scan, 100, beams);
  ASSERT_EQ(beams.size(), 5u);
  EXPECT_EQ(beams.no_return, (std::vector<unsigned char>{0, 1, 1, 1, 0}));
  EXPECT_EQ(beams.ranges[2], 8.0);  // clamped to max_range
  EXPECT_EQ(beams.ranges[4], 2.0);
}

// Left-out readings do not take a place in the budget: the kept beams
// spread over what remains.
TEST(PrepareBeams, SpreadsOverTheReadingsNotLeftOut) {
  const LaserScan scan = straight_scan(100);
  std::vector<unsigned char> left_out(100, 0);
  for (std::size_t i = 0; i < 80; ++i) left_out[i] = 1;
  PreparedBeams beams;
  prepare_beams(scan, 10, beams, &left_out);
  ASSERT_EQ(beams.size(), 10u);
  EXPECT_EQ(beams.ranges.front(), 81.0);
  EXPECT_EQ(beams.ranges.back(), 100.0);
  for (std::size_t i = 1; i < beams.size(); ++i) {
    EXPECT_GE(beams.ranges[i] - beams.ranges[i - 1], 2.0);
  }
  left_out.assign(100, 1);
  prepare_beams(scan, 10, beams, &left_out);
  EXPECT_EQ(beams.size(), 0u);
}

TEST(PrepareBeams, RejectsMismatchedArrays) {
  LaserScan scan;
  scan.ranges = {1.0, 2.0};
  scan.bearings = {0.0};
  PreparedBeams beams;
  EXPECT_THROW(prepare_beams(scan, 30, beams), std::invalid_argument);
  scan.bearings = {0.0, 0.1};
  const std::vector<unsigned char> left_out(3, 0);
  EXPECT_THROW(prepare_beams(scan, 30, beams, &left_out), std::invalid_argument);
}

}  // namespace laser_scan_test
}  // namespace playerkit::amcl
