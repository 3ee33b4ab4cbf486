// The I/O thread sleeps until there is something to do: a packet, a device's
// command or request, a device coming or going, the SIP timeout. Against a
// robot sending a SIP only every 30 s, whatever the thread does between two
// SIPs it did because it was woken, not because its next SIP came.
#include <gtest/gtest.h>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {
namespace p2os_wakeup_test {

using namespace p2os_testing;
namespace command = hardware::p2os::command;

emulators::P2osEmulatorOptions slow_robot() {
  emulators::P2osEmulatorOptions options;
  options.sip_period = std::chrono::seconds(30);
  options.watchdog.reset();  // it would stop the wheels between two SIPs
  return options;
}

constexpr std::string_view kRobot =
    "position:0 ( driver \"p2os_position\" port \"$PORT\" sip_timeout 60 )\n"
    "sonar:0 ( driver \"p2os_sonar\" )\n";

std::uint64_t sips_sent(EmulatedRobot& robot) {
  return robot.with([](P2osRobotEmulator& e) { return e.counters().sips_sent; });
}

TEST(P2osWakeup, ACommandReachesTheRobotWithoutWaitingForTheNextSip) {
  EmulatedRobot robot(slow_robot());
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  const auto sips = sips_sent(robot);
  // A request wakes the thread: MOTOR_POWER is on the line and ACKed.
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1}, 10s)));
  ASSERT_TRUE(eventually([&] { return robot.motors_enabled(); }, 10s));
  // So does a command: its VEL2 reaches the robot and the wheels turn.
  const auto vel2_before = robot.received(command::vel2);
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 200});
  EXPECT_TRUE(eventually([&] { return robot.received(command::vel2) > vel2_before; }, 10s));
  EXPECT_TRUE(eventually([&] { return !robot.wheels_stopped(); }, 10s));
  EXPECT_EQ(sips_sent(robot), sips) << "the thread waited for a SIP";
}

TEST(P2osWakeup, ADeviceArrivingIsServedWithoutWaitingForTheNextSip) {
  EmulatedRobot robot(slow_robot());
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  ASSERT_TRUE(eventually([&] { return robot.connected(); }, 10s));
  const auto sips = sips_sent(robot);
  const auto sonar_before = robot.received(command::sonar);
  ASSERT_TRUE(devices.sonar().subscribe());
  EXPECT_TRUE(eventually([&] { return robot.received(command::sonar) > sonar_before; }, 10s));
  EXPECT_EQ(sips_sent(robot), sips) << "the thread waited for a SIP";
}

TEST(P2osWakeup, TheLastDeviceLeavingStopsTheThreadAsleepBetweenSips) {
  EmulatedRobot robot(slow_robot());
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1}, 10s)));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 200});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }, 10s));
  const auto sips = sips_sent(robot);
  const auto closes_before = robot.received(command::close);  // command 2 is SYNC2 too
  // Stop, motors off, CLOSE, the line closed; the sleeping thread woken for it.
  devices.position().unsubscribe();
  EXPECT_TRUE(eventually([&] { return robot.runner().stats().host_disconnects == 1u; }, 10s));
  EXPECT_TRUE(eventually([&] { return robot.received(command::close) == closes_before + 1; }, 10s));
  EXPECT_GT(robot.received(command::stop), 0u);
  EXPECT_TRUE(robot.wheels_stopped());
  EXPECT_FALSE(robot.motors_enabled());
  EXPECT_EQ(sips_sent(robot), sips);
}

}  // namespace p2os_wakeup_test
}  // namespace playerkit::drivers
