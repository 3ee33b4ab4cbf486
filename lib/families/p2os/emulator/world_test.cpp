// The emulated robot in a map: stalling against walls, and sonar ranges
// checked against a ray march written here, independent of lib/grid.

#include "families/p2os/emulator/test_support.hpp"

#include <numbers>

namespace playerkit::emulators {
namespace world_test {

using namespace testing;
namespace command = hw::command;
using hw::Command;
constexpr double kPi = std::numbers::pi;

// 4 m × 4 m of free cells from (−2, −2), 5 cm cells, a wall filling x >= 1.5.
grid::OccupancyGrid wall_at_x_1_5() {
  grid::OccupancyGrid map(80, 80, 0.05, {-2.0, -2.0}, grid::CellState::free);
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 70; col < map.width(); ++col) map.set(col, row, grid::CellState::occupied);
  }
  return map;
}

// A 5 m room with a one-cell wall all round, a block inside, unknown cells
// in a corner (which sonar sees through).
grid::OccupancyGrid room() {
  grid::OccupancyGrid map(100, 100, 0.05, {-2.5, -2.5}, grid::CellState::free);
  for (int i = 0; i < 100; ++i) {
    map.set(i, 0, grid::CellState::occupied);
    map.set(i, 99, grid::CellState::occupied);
    map.set(0, i, grid::CellState::occupied);
    map.set(99, i, grid::CellState::occupied);
  }
  for (int row = 44; row < 52; ++row) {
    for (int col = 66; col < 74; ++col) map.set(col, row, grid::CellState::occupied);
  }
  for (int row = 80; row < 90; ++row) {
    for (int col = 10; col < 20; ++col) map.set(col, row, grid::CellState::unknown);
  }
  return map;
}

struct Driving {
  explicit Driving(P2osEmulatorOptions options) : robot(options), host(robot) {
    host.connect();
    host.send(command::enable, 1);
    host.wait(200ms);
    host.take_frames();
  }
  P2osRobotEmulator robot;
  Host host;
};

TEST(P2osWorld, StallsAgainstAWallWithStallBitsAndAFrontBumper) {
  const grid::OccupancyGrid map = wall_at_x_1_5();
  P2osEmulatorOptions options;
  options.map = &map;  // p3dx: radius 250 mm
  Driving d(options);
  d.host.keep_sending(Command::with_integer(command::vel, 300), 8s);  // 2.4 m if nothing stopped it
  const double x = d.robot.true_pose().x;
  EXPECT_LE(x, 1.25);
  EXPECT_GE(x, 1.25 - 0.003);  // within one 10 ms step at 0.3 m/s
  EXPECT_NEAR(d.robot.true_pose().y, 0.0, 1e-12);
  const auto sips = d.host.take_sips();
  ASSERT_EQ(sips.size(), 80u);
  EXPECT_FALSE(sips.front().left_stalled());
  EXPECT_EQ(sips.front().front_bumpers(), 0);
  const hw::StandardSip& last = sips.back();
  EXPECT_TRUE(last.left_stalled());
  EXPECT_TRUE(last.right_stalled());
  EXPECT_EQ(last.front_bumpers(), 0x04) << "the middle one of five";
  EXPECT_EQ(last.rear_bumpers(), 0);
  EXPECT_EQ(last.left_velocity, 0) << "stalled wheels do not turn";
  EXPECT_EQ(d.robot.wheel_velocities(), (mobile_base::WheelVelocities{0.0, 0.0}));

  // Turning in place against the wall is possible; backing off too. (RVEL
  // alone would keep VEL's 300 mm/s: stop first.)
  d.host.send(command::stop);
  d.host.keep_sending(Command::with_integer(command::rvel, 90), 1s);
  EXPECT_NEAR(d.robot.true_pose().x, x, 1e-12);
  EXPECT_NEAR(d.robot.true_pose().yaw, kPi / 2, 1e-9);
  d.host.keep_sending(Command::with_integer(command::rvel, -90), 1s);
  d.host.send(command::stop);
  EXPECT_NEAR(d.robot.true_pose().yaw, 0.0, 1e-9);
  d.host.take_frames();
  d.host.keep_sending(Command::with_integer(command::vel, -200), 1s);
  d.host.send(command::stop);
  EXPECT_NEAR(d.robot.true_pose().x, x - 0.2, 1e-9);
  const auto backing = d.host.take_sips();
  ASSERT_FALSE(backing.empty());
  EXPECT_FALSE(backing.back().left_stalled());
  EXPECT_EQ(backing.back().front_bumpers(), 0);
}

TEST(P2osWorld, ReversingIntoAWallPressesARearBumper) {
  const grid::OccupancyGrid map = wall_at_x_1_5();
  P2osEmulatorOptions options;
  options.map = &map;
  options.initial_pose = {1.0, 0.5, kPi};
  Driving d(options);
  d.host.keep_sending(Command::with_integer(command::vel, -200), 3s);
  EXPECT_NEAR(d.robot.true_pose().x, 1.25, 0.003);
  const auto sips = d.host.take_sips();
  EXPECT_TRUE(sips.back().left_stalled());
  EXPECT_EQ(sips.back().rear_bumpers(), 0x04);
  EXPECT_EQ(sips.back().front_bumpers(), 0);
}

TEST(P2osWorld, SlidesAlongAWallItAlreadyTouches) {
  const grid::OccupancyGrid map = wall_at_x_1_5();
  P2osEmulatorOptions options;
  options.map = &map;
  options.initial_pose = {1.26, -1.0, kPi / 2};  // 24 cm from the wall: overlapping
  Driving d(options);
  d.host.keep_sending(Command::with_integer(command::vel, 250), 4s);
  EXPECT_NEAR(d.robot.true_pose().y, 0.0, 1e-9);
  EXPECT_FALSE(d.host.take_sips().back().left_stalled());
}

TEST(P2osWorld, RowsWithoutBumpersReportOnlyTheStall) {
  const grid::OccupancyGrid map = wall_at_x_1_5();
  P2osEmulatorOptions options;
  options.map = &map;
  options.subclass = "amigo";  // 0 bumpers in the sheet, radius 180 mm
  Driving d(options);
  d.host.keep_sending(Command::with_integer(command::vel, 300), 8s);
  EXPECT_NEAR(d.robot.true_pose().x, 1.5 - 0.18, 0.003);
  const hw::StandardSip last = d.host.take_sips().back();
  EXPECT_TRUE(last.left_stalled());
  EXPECT_EQ(last.front_bumpers(), 0);
}

// The range from `origin` along `angle` to the first occupied cell, by
// marching in 0.25 mm steps.
double marched_range(const grid::OccupancyGrid& map, double x, double y, double angle, double max_range) {
  const double step = 0.00025;
  for (int i = 0; i * step <= max_range; ++i) {
    const double d = i * step;
    const Eigen::Vector2d point(x + d * std::cos(angle), y + d * std::sin(angle));
    if (map.state_at_world(point) == grid::CellState::occupied) return d;
  }
  return max_range;
}

void expect_sonar_matches_march(const std::string& subclass, const geometry::Pose2& pose) {
  SCOPED_TRACE(subclass);
  const grid::OccupancyGrid map = room();
  P2osEmulatorOptions options;
  options.map = &map;
  options.subclass = subclass;
  options.initial_pose = pose;
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  host.wait(100ms);
  const auto sips = host.take_sips();
  ASSERT_EQ(sips.size(), 1u);
  const hw::RobotParams& row = robot.params();
  ASSERT_EQ(static_cast<int>(sips[0].sonar.size()), row.sonar_count);
  int short_readings = 0;
  for (const hw::SonarReading& reading : sips[0].sonar) {
    const hw::SonarPose& mount = row.sonar_poses[reading.index];
    const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
    const double x = pose.x + (c * mount.x - s * mount.y) / 1000.0;
    const double y = pose.y + (s * mount.x + c * mount.y) / 1000.0;
    const double expected_mm = 1000.0 * marched_range(map, x, y, pose.yaw + mount.heading * kPi / 180.0, 5.0);
    const double reported_mm = reading.range * row.range_conv_factor;
    EXPECT_NEAR(reported_mm, expected_mm, 0.5 + row.range_conv_factor) << "sonar " << int(reading.index);
    if (expected_mm < 4999.0) ++short_readings;
  }
  EXPECT_GT(short_readings, row.sonar_count / 2) << "the room is seen, not just max range";
}

TEST(P2osWorld, SonarRangesEqualAnIndependentRayMarch) {
  expect_sonar_matches_march("p3dx", {0.3, -0.2, 0.4});
  expect_sonar_matches_march("p3dx", {-1.7, 1.1, -2.9});   // near the unknown corner
  expect_sonar_matches_march("p2dx", {0.6, -0.4, 0.05});   // RangeConv 0.268, next to the block
  expect_sonar_matches_march("perfpb", {0.0, 0.0, 1.0});
  expect_sonar_matches_march("amigo", {1.9, 1.9, 0.8});
}

TEST(P2osWorld, WithoutAMapSonarsReadMaxRange) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.wait(100ms);
  const auto sips = host.take_sips();
  ASSERT_EQ(sips.size(), 1u);
  ASSERT_EQ(sips[0].sonar.size(), 16u);
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(sips[0].sonar[static_cast<std::size_t>(i)].index, i);
    EXPECT_EQ(sips[0].sonar[static_cast<std::size_t>(i)].range, 5000);
  }
}

TEST(P2osWorld, SonarCommandSwitchesReadingsAndFlags) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::sonar, 0);
  host.wait(200ms);
  for (const auto& sip : host.take_sips()) {
    EXPECT_TRUE(sip.sonar.empty());
    EXPECT_EQ(sip.flags & 0x1E, 0);
  }
  host.send(command::sonar, 1);
  host.wait(100ms);
  const auto sips = host.take_sips();
  ASSERT_EQ(sips.size(), 1u);
  EXPECT_EQ(sips[0].sonar.size(), 16u);
  EXPECT_EQ(sips[0].flags & 0x1E, 0x06) << "two arrays of eight";
  EXPECT_TRUE(robot.sonar_enabled());
}

TEST(P2osWorld, SonarsCanCycleAFewPerSip) {
  P2osEmulatorOptions options;
  options.sonars_per_sip = 5;
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  host.wait(400ms);
  std::vector<int> order;
  for (const auto& sip : host.take_sips()) {
    EXPECT_EQ(sip.sonar.size(), 5u);
    for (const auto& reading : sip.sonar) order.push_back(reading.index);
  }
  const std::vector<int> expected{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3};
  EXPECT_EQ(order, expected);
}

}  // namespace world_test
}  // namespace playerkit::emulators
