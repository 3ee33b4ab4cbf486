// What each read device reports, against the emulated robot's world and
// state: sonar (ranges, geometry, power), bumpers and stall, gripper, power,
// aio/dio, compass, gyro, sound and the CMUcam.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "algorithms/grid/occupancy_grid.hpp"
#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/gripper.hpp"
#include "protocol/messages/aio.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/dio.hpp"
#include "protocol/messages/gripper.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/sound.hpp"

namespace playerkit::drivers {
namespace p2os_sensors_test {

using namespace p2os_testing;
namespace command = hardware::p2os::command;
namespace gripper_state = hardware::p2os::gripper_state;

// A wall across the world at x = 1.5 m (and beyond), the robot at the origin.
grid::OccupancyGrid wall_ahead(double wall_x) {
  grid::OccupancyGrid map(100, 100, 0.05, {-2.5, -2.5}, grid::CellState::free);
  const int first = static_cast<int>(std::round((wall_x + 2.5) / 0.05));
  for (int row = 0; row < map.height(); ++row) {
    for (int col = first; col < map.width(); ++col) map.set(col, row, grid::CellState::occupied);
  }
  return map;
}

TEST(P2osSensors, SonarRangesAreWhatTheRobotMeasures) {
  const grid::OccupancyGrid map = wall_ahead(1.5);
  emulators::P2osEmulatorOptions options;
  options.map = &map;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  ASSERT_TRUE(devices.sonar().subscribe());
  const auto data = data_when<protocol::SonarData>(devices.sonar(), [](const auto& d) { return d.ranges[3] > 0; });
  ASSERT_TRUE(data);
  ASSERT_EQ(data->range_count, 16);
  for (int i = 0; i < 16; ++i) {
    const double expected = robot.with([i](P2osRobotEmulator& e) { return e.sonar_range(i); }) * 1000.0;
    EXPECT_NEAR(data->ranges[static_cast<std::size_t>(i)], expected, 1.0) << "transducer " << i;
  }
  // The front pair sees the wall: (1.5 - 0.21) m / cos 10 degrees.
  EXPECT_NEAR(data->ranges[3], 1310, 30);
  EXPECT_NEAR(data->ranges[4], 1310, 30);
  EXPECT_EQ(data->ranges[12], 5000);  // nothing behind: the emulator's maximum
}

TEST(P2osSensors, SonarPowerFollowsSubscriptionsAndRequests) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  auto sonar_on = [&] { return robot.with([](P2osRobotEmulator& e) { return e.sonar_enabled(); }); };
  ASSERT_TRUE(devices.power().subscribe());
  EXPECT_TRUE(eventually([&] { return !sonar_on(); }));  // nobody wants them: off (1.5 too)
  ASSERT_TRUE(devices.sonar().subscribe());
  EXPECT_TRUE(eventually(sonar_on));
  ASSERT_TRUE(acked(ask(devices.sonar(), protocol::SonarPowerConfig{2, 0})));
  EXPECT_TRUE(eventually([&] { return !sonar_on(); }));
  ASSERT_TRUE(acked(ask(devices.sonar(), protocol::SonarPowerConfig{2, 1})));
  EXPECT_TRUE(eventually(sonar_on));
  devices.sonar().unsubscribe();
  EXPECT_TRUE(eventually([&] { return !sonar_on(); }));
}

TEST(P2osSensors, DrivingIntoAWallStallsAndPressesAFrontBumper) {
  const grid::OccupancyGrid map = wall_ahead(0.6);
  emulators::P2osEmulatorOptions options;
  options.map = &map;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(devices.device(protocol::kBumperCode).subscribe());
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 300});
  const auto stalled =
      data_when<protocol::PositionData>(devices.position(), [](const auto& d) { return d.stall != 0; }, 10s);
  ASSERT_TRUE(stalled && stalled->stall != 0);
  const auto bumper = data_when<protocol::BumperData>(devices.device(protocol::kBumperCode), [](const auto& d) {
    int front = 0;
    for (int i = 0; i < 5; ++i) front += d.bumpers[static_cast<std::size_t>(i)];
    return front > 0;
  });
  ASSERT_TRUE(bumper);
  EXPECT_EQ(bumper->bumper_count, 10);
  int rear = 0;
  for (int i = 5; i < 10; ++i) rear += bumper->bumpers[static_cast<std::size_t>(i)];
  EXPECT_EQ(rear, 0);
}

TEST(P2osSensors, GripperCommandsMoveThePaddlesAndTheStateShowsIt) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& gripper = devices.device(protocol::kGripperCode);
  ASSERT_TRUE(gripper.subscribe());
  auto data = data_when<protocol::GripperData>(gripper, [](const auto& d) { return d.state != 0; });
  ASSERT_TRUE(data);
  EXPECT_TRUE(data->state & gripper_state::paddles_closed);  // the emulator starts stored
  EXPECT_EQ(robot.received(command::gripper), 0u);            // 1.5 sent GRIPstore here

  write_command(gripper, protocol::GripperCommand{hardware::p2os::gripper_command::open, 0});
  data = data_when<protocol::GripperData>(
      gripper, [](const auto& d) { return (d.state & gripper_state::paddles_open) != 0; });
  ASSERT_TRUE(data);
  EXPECT_TRUE(data->state & gripper_state::paddles_open);
  // The same command again is not sent again (as 1.5); GRIPpress also sends its value.
  write_command(gripper, protocol::GripperCommand{hardware::p2os::gripper_command::open, 0});
  write_command(gripper, protocol::GripperCommand{hardware::p2os::gripper_command::press, 40});
  EXPECT_TRUE(eventually([&] { return robot.received(command::gripper_value) == 1u; }));
  EXPECT_EQ(robot.received(command::gripper), 2u);

  robot.with([](P2osRobotEmulator& e) {
    e.set_gripper_beams(true, false);
    return 0;
  });
  data = data_when<protocol::GripperData>(
      gripper, [](const auto& d) { return (d.beams & hardware::p2os::gripper_beam::outer_beam) != 0; });
  ASSERT_TRUE(data);
  EXPECT_FALSE(data->beams & hardware::p2os::gripper_beam::inner_beam);
}

TEST(P2osSensors, PowerIsTheBatteryInDecivolts) {
  emulators::P2osEmulatorOptions options;
  options.battery_volts = 12.5;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  ASSERT_TRUE(devices.power().subscribe());
  auto data = data_when<protocol::PowerData>(devices.power(), [](const auto& d) { return d.charge != 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->charge, 125);
  robot.with([](P2osRobotEmulator& e) {
    e.set_battery_volts(11.3);
    return 0;
  });
  data = data_when<protocol::PowerData>(devices.power(), [](const auto& d) { return d.charge == 113; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->charge, 113);
}

TEST(P2osSensors, AnalogAndDigitalInputs) {
  emulators::P2osEmulatorOptions options;
  options.has_gripper = false;  // all eight DIGIN bits are inputs
  options.analog_input = 200;
  options.digital_inputs = 0xA5;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& aio = devices.device(protocol::kAioCode);
  core::Device& dio = devices.device(protocol::kDioCode);
  ASSERT_TRUE(aio.subscribe());
  ASSERT_TRUE(dio.subscribe());
  const auto analog = data_when<protocol::AioData>(aio, [](const auto& d) { return d.anin[0] != 0; });
  ASSERT_TRUE(analog);
  EXPECT_EQ(analog->count, 1);
  EXPECT_EQ(analog->anin[0], 200);  // 1.5 sent 200 × 2^24 (quirk 13)
  const auto digital = data_when<protocol::DioData>(dio, [](const auto& d) { return d.digin != 0; });
  ASSERT_TRUE(digital);
  EXPECT_EQ(digital->count, 8);
  EXPECT_EQ(digital->digin, 0xA5u);
}

TEST(P2osSensors, CompassIsTheTrueHeadingInTwoDegreeSteps) {
  emulators::P2osEmulatorOptions options;
  options.initial_pose = {0.0, 0.0, 100.0 * std::numbers::pi / 180.0};
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& compass = devices.position(1);
  ASSERT_TRUE(compass.subscribe());
  const auto data = data_when<protocol::PositionData>(compass, [](const auto& d) { return d.yaw != 0; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->yaw, 100, 2);
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->yawspeed, 0);
}

TEST(P2osSensors, GyroRateWhileAGyroDeviceIsSubscribed) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& gyro = devices.position(2);
  auto gyro_on = [&] { return robot.with([](P2osRobotEmulator& e) { return e.gyro_enabled(); }); };
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(more_data(devices.position(), 3));
  EXPECT_EQ(robot.received(command::gyro), 0u);  // no gyro device subscribed, no GYRO command

  ASSERT_TRUE(gyro.subscribe());
  EXPECT_TRUE(eventually(gyro_on));
  auto data = data_when<protocol::PositionData>(gyro, [](const auto& d) { return d.yawspeed != 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->yawspeed, 512);  // at rest

  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.yawspeed = 40});
  data = data_when<protocol::PositionData>(gyro, [](const auto& d) { return std::abs(d.yawspeed - 512) > 20; });
  ASSERT_TRUE(data);
  EXPECT_LT(data->yawspeed, 512);  // counter-clockwise reads below 512

  gyro.unsubscribe();
  EXPECT_TRUE(eventually([&] { return !gyro_on(); }));
}

TEST(P2osSensors, SoundPlaysEachCommandOnce) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& sound = devices.device(protocol::kSoundCode);
  ASSERT_TRUE(sound.subscribe());
  ASSERT_TRUE(devices.power().subscribe());
  ASSERT_TRUE(more_data(devices.power(), 3));
  EXPECT_EQ(robot.received(command::sound), 0u);  // 1.5 played heap garbage here (quirk 16)
  write_command(sound, protocol::SoundCommand{3});
  EXPECT_TRUE(eventually([&] { return robot.received(command::sound) == 1u; }));
  write_command(sound, protocol::SoundCommand{0});  // index 0: nothing to play
  ASSERT_TRUE(more_data(devices.power(), 3));
  EXPECT_EQ(robot.received(command::sound), 1u);
  EXPECT_EQ(data_sequence(sound), 0u);  // sound has no data
}

TEST(P2osSensors, CmucamTracksAndReportsTheBlob) {
  emulators::P2osEmulatorOptions options;
  options.cmucam_blob = hardware::p2os::CmucamTracking{40, 70, 30, 60, 49, 79, 100, 128};
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kEveryDevice));
  core::Device& camera = devices.device(protocol::kBlobfinderCode);
  ASSERT_TRUE(camera.subscribe());
  const auto data = data_when<protocol::BlobfinderData>(camera, [](const auto& d) { return d.header[0].num == 1; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->width, 80);
  EXPECT_EQ(data->height, 143);
  EXPECT_EQ(camera.latest_data()->payload.size(), 7172u);
  const protocol::BlobfinderBlob& blob = data->blobs[0];
  EXPECT_EQ(blob.x, 40);
  EXPECT_EQ(blob.y, 70);
  EXPECT_EQ(blob.left, 30);
  EXPECT_EQ(blob.bottom, 79);
  EXPECT_EQ(blob.area, 20u * 20u * 128u / 255u);
  EXPECT_EQ(blob.range, 128);
  // Reset (CR, RS, RM 3) and tracking (CR, TC) went through TTY3; replies are polled.
  EXPECT_GE(robot.received(command::tty3), 5u);
  const auto polls = robot.received(command::getaux2);
  EXPECT_TRUE(eventually([&] { return robot.received(command::getaux2) > polls + 2; }));

  const auto texts = robot.received(command::tty3);
  ASSERT_TRUE(acked(ask(camera, protocol::BlobfinderColorConfig{1, 100, 200, 10, 20, 0, 255})));
  EXPECT_TRUE(eventually([&] { return robot.received(command::tty3) == texts + 2; }));  // CR, TC ...
  camera.unsubscribe();
}

}  // namespace p2os_sensors_test
}  // namespace playerkit::drivers
