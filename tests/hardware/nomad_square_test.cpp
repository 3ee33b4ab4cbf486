// A client of lib/client drives an emulated Nomad 200 around a square
// through a real server with the manual's configuration (section 7.29:
// nomad, nomad_position and nomad_sonar on it), the robot behind its
// emulated server on a loopback TCP port; the true pose must end where the
// commands put it, within the odometry error given to the emulator.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace nomad_square_test {

using namespace std::chrono_literals;
using emulators::NomadEmulator;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};

emulators::NomadEmulatorOptions with_odometry_error() {
  emulators::NomadEmulatorOptions options;
  options.odometry_error.translation_scale = 0.02;  // the encoders read 2 % long
  options.odometry_error.rotation_scale = -0.01;
  return options;
}

geometry::Pose2 true_pose(emulators::EmulatorRunner& robot) {
  return robot.with_emulator<NomadEmulator>([](NomadEmulator& e) { return e.true_pose(); });
}

TEST(NomadSquare, AClientDrivesTheEmulatedRobotAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot(std::make_unique<NomadEmulator>(with_odometry_error()), emulators::TcpEndpoint{});
  const std::string address = robot.device_path();  // tcp:127.0.0.1:N
  const std::string port = address.substr(address.rfind(':') + 1);
  testing::TestServer server("nomad:0 ( driver \"nomad\" host \"127.0.0.1\" port " + port + " )\n"
                             "position:0 ( driver \"nomad_position\" nomad_index 0 )\n"
                             "sonar:0 ( driver \"nomad_sonar\" nomad_index 0 )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  const geometry::Pose2 start = true_pose(robot);

  // The Nomad has no motor switch in its protocol: 1.5 NACKed the request.
  const hardware_test::SquareDrive drive = hardware_test::drive_square(
      client, {.side = 0.6, .top_speed = 0.3, .top_turn_rate = 0.7, .enable_motors = false});
  ASSERT_TRUE(drive.finished) << drive.failure;

  // The odometry closed the square; the true square is smaller by the
  // encoders' 2 % and turned by their 1 %: about 2 cm and 4 degrees in all,
  // plus whole degrees of heading and the stops' lateness at about 17 Hz.
  const geometry::Pose2 end = true_pose(robot);
  EXPECT_NEAR(end.x, start.x, 0.1);
  EXPECT_NEAR(end.y, start.y, 0.1);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);
  EXPECT_EQ(robot.with_emulator<NomadEmulator>([](NomadEmulator& e) { return e.state().translation_velocity; }), 0);

  ASSERT_TRUE(drive.odometry);
  EXPECT_NEAR(drive.odometry->pose.x, 0.0, 0.03);
  EXPECT_NEAR(drive.odometry->pose.y, 0.0, 0.03);
}

}  // namespace nomad_square_test
}  // namespace playerkit
