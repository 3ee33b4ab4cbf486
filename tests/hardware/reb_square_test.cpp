// A client of lib/client drives an emulated UBot (REB, LPRSerCom) around a
// square through a real server with the manual's configuration (section
// 7.33, its three devices); the emulated robot's true pose must end where
// the commands put it, within the odometry error given to the emulator.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/reb/emulator/reb_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace reb_square_test {

using namespace std::chrono_literals;
using emulators::RebEmulator;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};

emulators::RebEmulatorOptions with_odometry_error() {
  emulators::RebEmulatorOptions options;
  options.body.odometry_error.translation_scale = 0.02;  // the encoders read 2 % long
  options.body.odometry_error.rotation_scale = -0.01;
  return options;
}

geometry::Pose2 true_pose(emulators::EmulatorRunner& robot) {
  return robot.with_emulator<RebEmulator>([](RebEmulator& e) { return e.drive().true_pose(); });
}

TEST(RebSquare, AClientDrivesTheEmulatedUbotAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot(std::make_unique<RebEmulator>(with_odometry_error()), emulators::PtyEndpoint{});
  testing::TestServer server("position:0 ( driver \"reb_position\" port \"" + robot.device_path() +
                                 "\" subclass \"slow\" )\n"
                                 "ir:0 ( driver \"reb_ir\" )\n"
                                 "power:0 ( driver \"reb_power\" )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  const geometry::Pose2 start = true_pose(robot);

  // 0.2 m/s and 1.2 rad/s keep both wheels far under the board's 700 mm/s.
  const hardware_test::SquareDrive drive = hardware_test::drive_square(client, {.side = 0.5, .top_speed = 0.2});
  ASSERT_TRUE(drive.finished) << drive.failure;

  // The odometry closed the square; the true one is smaller by the encoders'
  // 2 % and turned by their 1 %: about 2 cm and 4 degrees in all, plus the
  // stops' lateness at 40 Hz odometry on a loaded machine.
  const geometry::Pose2 end = true_pose(robot);
  EXPECT_NEAR(end.x, start.x, 0.1);
  EXPECT_NEAR(end.y, start.y, 0.1);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);
  ASSERT_TRUE(drive.odometry);
  EXPECT_NEAR(drive.odometry->pose.x, 0.0, 0.03);
  EXPECT_NEAR(drive.odometry->pose.y, 0.0, 0.03);
}

}  // namespace reb_square_test
}  // namespace playerkit
