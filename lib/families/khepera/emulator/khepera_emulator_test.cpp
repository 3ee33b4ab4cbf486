// The emulated Khepera on a simulated clock: khepera.md §6 point by point.
#include "families/khepera/emulator/khepera_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace playerkit::emulators {
namespace {

using namespace std::chrono_literals;

// A host typing at the robot on a simulated clock.
struct Host {
  explicit Host(KheperaEmulatorOptions options = {}) : robot(std::move(options)) {}

  // Everything the robot sent back for `text`, telegrams joined.
  std::string send(const std::string& text, int baud = 38400) {
    robot.receive(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), now, baud);
    std::string out;
    for (const Telegram& telegram : robot.take_output()) out.append(telegram.bytes.begin(), telegram.bytes.end());
    return out;
  }
  void wait(Duration duration) {
    const Duration until = now + duration;
    while (robot.next_deadline() <= until) {
      now = robot.next_deadline();
      robot.advance(now);
    }
    now = until;
    robot.advance(now);
  }

  KheperaEmulator robot;
  Duration now{0};
};

TEST(KheperaEmulator, AnswersEachCommandAtOnceWithItsLowerCaseLetter) {
  Host host;
  EXPECT_EQ(host.send("\r\n"), "");  // 1.5's start-up CR LF: no answer
  EXPECT_EQ(host.send("E\n"), "e,0,0\r\n");
  EXPECT_EQ(host.send("D,8,-8\n"), "d\r\n");
  EXPECT_EQ(host.send("E\n"), "e,8,-8\r\n");  // the sheet's example
  EXPECT_EQ(host.send("G,100,-100\n"), "g\r\n");
  EXPECT_EQ(host.send("H\n"), "h,100,-100\r\n");
  EXPECT_EQ(host.send("N\n"), "n,1,1,1,1,1,1,1,1\r\n");  // nothing near: never 0
  // A command split across writes, CR LF ends, unknown and malformed ones.
  EXPECT_EQ(host.send("D,1"), "");
  EXPECT_EQ(host.send(",2\r\n"), "d\r\n");
  EXPECT_EQ(host.send("X\n"), "");
  EXPECT_EQ(host.send("D,1\n"), "");
  EXPECT_EQ(host.robot.speeds(), (hardware::khepera::WheelSpeeds{1, 2}));
}

TEST(KheperaEmulator, CountersAdvanceBySpeedEveryTenMilliseconds) {
  Host host;
  host.send("G,0,0\n");
  host.send("D,10,-5\n");
  host.wait(1s);
  EXPECT_EQ(host.robot.left_counter(), 1000);
  EXPECT_EQ(host.robot.right_counter(), -500);
  host.send("D,0,0\n");
  host.wait(1s);
  EXPECT_EQ(host.send("H\n"), "h,1000,-500\r\n");
}

TEST(KheperaEmulator, SpeedsAreLimitedToTheBiosRange) {
  Host host;
  host.send("D,500,-500\n");
  EXPECT_EQ(host.send("E\n"), "e,127,-127\r\n");
}

TEST(KheperaEmulator, TheBodyDrivesWhereTheWheelsTakeIt) {
  Host host;
  // 12 pulses / 10 ms is 100 mm/s on both wheels: 0.2 m straight ahead in 2 s.
  host.send("D,12,12\n");
  host.wait(2s);
  EXPECT_NEAR(host.robot.true_pose().x, 0.2, 1e-6);
  EXPECT_NEAR(host.robot.true_pose().y, 0.0, 1e-9);
  // Right wheel forward, left back: counter-clockwise on the spot.
  host.send("D,-6,6\n");
  host.wait(1s);
  const double turn = 2.0 * 6 * (1.0 / 12.0) / 57.0 * 100.0;  // rad in 1 s
  EXPECT_NEAR(host.robot.true_pose().yaw, turn, 1e-6);
  EXPECT_NEAR(host.robot.true_pose().x, 0.2, 1e-6);
}

TEST(KheperaEmulator, OdometryErrorReachesTheCounters) {
  KheperaEmulatorOptions options;
  options.odometry_error.translation_scale = 0.1;
  Host host(options);
  host.send("D,12,12\n");
  host.wait(1s);
  EXPECT_NEAR(host.robot.true_pose().x, 0.1, 1e-6);
  EXPECT_NEAR(static_cast<double>(host.robot.left_counter()), 1320.0, 1.0);  // 10 % more than turned
}

TEST(KheperaEmulator, ProximityGrowsAsAWallComesNear) {
  // A wall across x = 0.1 m, cells of 5 mm.
  grid::OccupancyGrid map(100, 100, 0.005, Eigen::Vector2d(-0.25, -0.25), grid::CellState::free);
  for (int row = 0; row < 100; ++row) map.set(70, row, grid::CellState::occupied);
  KheperaEmulatorOptions options;
  options.map = &map;
  options.initial_pose = {0.0, 0.0, 0.0};
  Host host(options);
  EXPECT_EQ(host.robot.proximity()[2], 1);  // 75 mm from the front sensor: out of reach
  host.robot.receive({}, host.now, 38400);
  host.send("D,6,6\n");  // 50 mm/s
  host.wait(800ms);      // the front sensors 35 mm from the wall
  const auto near = host.robot.proximity();
  EXPECT_GT(near[2], 50);
  EXPECT_EQ(near[2], near[3]);
  EXPECT_EQ(near[6], 1);  // the rear ones see nothing
  const double range = hardware::khepera::ir_range_mm(near[2], {});
  EXPECT_NEAR(range, 35.0, 3.0);
}

TEST(KheperaEmulator, BytesAtAnotherSpeedAreNoise) {
  Host host;
  EXPECT_EQ(host.send("E\n", 9600), "");
  EXPECT_EQ(host.send("E\n", 38400), "e,0,0\r\n");
}

}  // namespace
}  // namespace playerkit::emulators
