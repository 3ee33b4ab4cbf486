// A client of lib/client drives an emulated Khepera around a small square
// through a real server with the manual's configuration (khepera_position
// and khepera_ir); the emulated robot's true pose must end where the
// commands put it, its odometry a few per cent wrong.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/khepera/emulator/khepera_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ir.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace khepera_square_test {

using namespace std::chrono_literals;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kIr{protocol::kIrCode, 0};
constexpr double kOdometryScale = 0.02;  // the encoders count 2 % more than the wheels roll

emulators::KheperaEmulatorOptions robot_options() {
  emulators::KheperaEmulatorOptions options;
  options.odometry_error.translation_scale = kOdometryScale;
  return options;
}

TEST(KheperaSquare, AClientDrivesTheEmulatedRobotAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot{std::make_unique<emulators::KheperaEmulator>(robot_options()),
                                  emulators::PtyEndpoint{}};
  const auto true_pose = [&robot] {
    return robot.with_emulator<emulators::KheperaEmulator>(
        [](emulators::KheperaEmulator& khepera) { return khepera.true_pose(); });
  };
  // The manual's configuration (section 7.21), the port pointing at the emulator.
  testing::TestServer server("position:0 ( driver \"khepera_position\" port \"" + robot.device_path() +
                                 "\" )\nir:0 ( driver \"khepera_ir\" )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  ASSERT_EQ(client.request_access(kIr, protocol::Access::kRead).access, protocol::Access::kRead);
  const geometry::Pose2 start = true_pose();
  int ir_readings = 0;
  // A Khepera's square: 0.3 m sides at 0.1 m/s. Its wheels move in steps of
  // 8.3 mm/s (one pulse per 10 ms), so the slowest turn is 0.3 rad/s.
  const hardware_test::SquareDrive drive = hardware_test::drive_square(
      client,
      {.side = 0.3,
       .top_speed = 0.1,
       .slowest_speed = 0.02,
       .top_turn_rate = 1.0,
       .slowest_turn_rate = 0.3,
       .distance_tolerance = 0.004,
       .heading_tolerance = 0.02,
       .leg_limit = 20s},
      [&](const protocol::Message& message) {
        if (message.type() == protocol::MessageType::kData && message.device() == kIr) ++ir_readings;
      });
  ASSERT_TRUE(drive.finished) << drive.failure;

  // The odometry closed each leg: the true square's sides are 2 % short, its
  // corners square, so it closes too, within what stopping on 20 Hz odometry
  // with whole degrees on the wire allows.
  const geometry::Pose2 end = true_pose();
  EXPECT_NEAR(end.x, start.x, 0.03);
  EXPECT_NEAR(end.y, start.y, 0.03);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);

  // The client's odometry is the true motion seen through the encoders'
  // error: 2 % longer, same heading.
  ASSERT_TRUE(drive.odometry);
  const auto& odometry = drive.odometry->pose;
  const geometry::Pose2 moved = start.inverse().compose(end);
  EXPECT_NEAR(odometry.x, moved.x * (1.0 + kOdometryScale), 0.01);
  EXPECT_NEAR(odometry.y, moved.y * (1.0 + kOdometryScale), 0.01);
  EXPECT_NEAR(geometry::angle_difference(odometry.yaw, moved.yaw), 0.0, 0.03);
  EXPECT_GT(ir_readings, 10);
}

}  // namespace khepera_square_test
}  // namespace playerkit
