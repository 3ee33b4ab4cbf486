// A client of lib/client drives an emulated Segway RMP around a square
// through a real server, with 1.5's configuration form (rmpposition, the
// manual's limits) over an slcan adapter on a pseudo-terminal; the emulated
// robot's true pose must end where the commands put it, within the
// odometry error given to the emulator.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace segwayrmp_square_test {

using namespace std::chrono_literals;
using emulators::SegwayRmpEmulator;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};

emulators::SegwayRmpEmulatorOptions with_odometry_error() {
  emulators::SegwayRmpEmulatorOptions options;
  options.odometry_error.translation_scale = 0.02;  // the encoders read 2 % long
  options.odometry_error.rotation_scale = -0.01;
  return options;
}

geometry::Pose2 true_pose(emulators::EmulatorRunner& robot) {
  return *robot.with_emulator<SegwayRmpEmulator>([](SegwayRmpEmulator& e) { return e.world_pose(); });
}

TEST(SegwayRmpSquare, AClientDrivesTheEmulatedRobotAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot(std::make_unique<SegwayRmpEmulator>(with_odometry_error()),
                                  emulators::PtyEndpoint{});
  testing::TestServer server("position:0 ( driver \"rmpposition\" canio \"slcan\" port \"" + robot.device_path() +
                                 "\" max_xspeed 500 max_yawspeed 40 )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  const geometry::Pose2 start = true_pose(robot);

  // Within the configured 500 mm/s and 40 deg/s (0.70 rad/s).
  const hardware_test::SquareDrive drive = hardware_test::drive_square(
      client, {.side = 0.5, .top_speed = 0.45, .top_turn_rate = 0.65, .heading_tolerance = 0.02});
  ASSERT_TRUE(drive.finished) << drive.failure;

  // The odometry closed the square; the true square is smaller by the
  // encoders' 2 % and turned by their 1 %, plus the stops' lateness.
  const geometry::Pose2 end = true_pose(robot);
  EXPECT_NEAR(end.x, start.x, 0.12);
  EXPECT_NEAR(end.y, start.y, 0.12);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);
  EXPECT_EQ(robot.with_emulator<SegwayRmpEmulator>([](SegwayRmpEmulator& e) { return e.commanded_speed(); }), 0.0);
  EXPECT_EQ(robot.with_emulator<SegwayRmpEmulator>([](SegwayRmpEmulator& e) { return e.watchdog_stops(); }), 0u);

  ASSERT_TRUE(drive.odometry);
  EXPECT_NEAR(drive.odometry->pose.x, 0.0, 0.03);
  EXPECT_NEAR(drive.odometry->pose.y, 0.0, 0.03);
}

}  // namespace segwayrmp_square_test
}  // namespace playerkit
