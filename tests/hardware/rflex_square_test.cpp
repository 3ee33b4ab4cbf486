// A client of lib/client drives an emulated B21r (RFLEX) around a square
// through a real server with 1.5's configuration form (manual section 7.34:
// position, sonar and power on one line); the emulated robot's true pose
// must end where the commands put it, within the odometry error given to
// the emulator. The robot powers up braked: the client's MOTOR_POWER
// releases it.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/rflex/emulator/rflex_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace rflex_square_test {

using namespace std::chrono_literals;
using emulators::rflex::RflexEmulator;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};

emulators::rflex::RflexEmulatorOptions braked_b21r_with_odometry_error() {
  emulators::rflex::RflexEmulatorOptions options;
  options.brake_at_start = true;
  options.odometry_error.translation_scale = 0.02;  // the counters read 2 % long
  options.odometry_error.rotation_scale = -0.01;
  return options;
}

geometry::Pose2 true_pose(emulators::EmulatorRunner& robot) {
  return robot.with_emulator<RflexEmulator>([](RflexEmulator& e) { return e.drive().true_pose(); });
}

TEST(RflexSquare, AClientDrivesTheEmulatedB21rAroundASquareThroughTheServer) {
  emulators::EmulatorRunner robot(std::make_unique<RflexEmulator>(braked_b21r_with_odometry_error()),
                                  emulators::PtyEndpoint{});
  testing::TestServer server(
      "position:0 ( driver \"rflex_position\" rflex_serial_port \"" + robot.device_path() +
          "\" mm_length 520 mm_width 520 odo_distance_conversion 103 odo_angle_conversion 35000 "
          "default_trans_acceleration 500.0 default_rot_acceleration 1.0 )\n"
          "sonar:0 ( driver \"rflex_sonar\" range_distance_conversion 1.476 num_sonars 24 num_sonar_banks 3 "
          "num_sonars_in_bank [8 8 8] sonar_echo_delay 30000 )\n"
          "power:0 ( driver \"rflex_power\" rflex_power_offset 12 rflex_done 1 )\n",
      {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  const geometry::Pose2 start = true_pose(robot);

  const hardware_test::SquareDrive drive = hardware_test::drive_square(client, {.side = 0.5, .top_speed = 0.4});
  ASSERT_TRUE(drive.finished) << drive.failure;

  // The odometry closed the square; the true one is smaller by the counters'
  // 2 % and turned by their 1 %: about 2 cm and 4 degrees in all, plus the
  // stops' lateness at 10 Hz reports on a loaded machine.
  const geometry::Pose2 end = true_pose(robot);
  EXPECT_NEAR(end.x, start.x, 0.15);
  EXPECT_NEAR(end.y, start.y, 0.15);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);
  ASSERT_TRUE(drive.odometry);
  EXPECT_NEAR(drive.odometry->pose.x, 0.0, 0.05);
  EXPECT_NEAR(drive.odometry->pose.y, 0.0, 0.05);
  EXPECT_FALSE(robot.with_emulator<RflexEmulator>([](RflexEmulator& e) { return e.braked(); }));
}

}  // namespace rflex_square_test
}  // namespace playerkit
