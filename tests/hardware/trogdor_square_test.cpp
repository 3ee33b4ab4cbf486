// A client of lib/client drives an emulated Botrics O-Bot (Trogdor) around a
// square through a real server with the manual's configuration (section
// 7.42); the emulated robot's true pose must end where the commands put it,
// within the odometry error given to the emulator.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/trogdor/emulator/trogdor_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace trogdor_square_test {

using namespace std::chrono_literals;
using emulators::TrogdorEmulator;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};

emulators::TrogdorEmulatorOptions with_odometry_error() {
  emulators::TrogdorEmulatorOptions options;
  options.body.odometry_error.translation_scale = 0.02;  // the encoders read 2 % long
  options.body.odometry_error.rotation_scale = -0.01;
  return options;
}

geometry::Pose2 true_pose(emulators::EmulatorRunner& robot) {
  return robot.with_emulator<TrogdorEmulator>([](TrogdorEmulator& e) { return e.drive().true_pose(); });
}

TEST(TrogdorSquare, AClientDrivesTheEmulatedRobotAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot(std::make_unique<TrogdorEmulator>(with_odometry_error(), nullptr),
                                  emulators::PtyEndpoint{});
  testing::TestServer server("position:0 ( driver \"trogdor\" port \"" + robot.device_path() + "\" )\n", {}, 0,
                             [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  const geometry::Pose2 start = true_pose(robot);

  // The controller turns no wheel slower than 5 units (75 mm/s): the robot
  // spins at 0.48 rad/s at the least, so each turn overshoots by what the
  // client's view of the odometry lags behind.
  const hardware_test::SquareDrive drive = hardware_test::drive_square(
      client, {.side = 0.6, .top_speed = 0.3, .slowest_speed = 0.08, .slowest_turn_rate = 0.48,
               .heading_tolerance = 0.02});
  ASSERT_TRUE(drive.finished) << drive.failure;
  EXPECT_FALSE(robot.with_emulator<TrogdorEmulator>([](TrogdorEmulator& e) { return e.drive().commanded_to_move(); }));

  // The odometry reported is the encoders' view, which the client closed
  // the square on (up to the turns' overshoot)...
  ASSERT_TRUE(drive.odometry);
  EXPECT_NEAR(drive.odometry->pose.x, 0.0, 0.1);
  EXPECT_NEAR(drive.odometry->pose.y, 0.0, 0.1);
  // ...and the robot truly stands where that odometry says, within the
  // encoders' 2 % and 1 %: a few cm and degrees over 2.4 m and four turns.
  const geometry::Pose2 end = true_pose(robot);
  EXPECT_NEAR(end.x - start.x, drive.odometry->pose.x, 0.08);
  EXPECT_NEAR(end.y - start.y, drive.odometry->pose.y, 0.08);
  EXPECT_NEAR(geometry::angle_difference(end.yaw - start.yaw, drive.odometry->pose.yaw), 0.0, 0.1);
}

}  // namespace trogdor_square_test
}  // namespace playerkit
