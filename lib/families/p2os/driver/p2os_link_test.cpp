// The shared link, against an emulated Pioneer on a pseudo-terminal: which
// subscription opens it, which keeps it, and what the last one leaving does.
#include <gtest/gtest.h>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers {
namespace p2os_link_test {

using namespace p2os_testing;
namespace command = hardware::p2os::command;

constexpr std::string_view kRobot =
    "position:0 ( driver \"p2os_position\" )\n"
    "sonar:0 ( driver \"p2os_sonar\" port \"$PORT\" )\n"
    "power:0 ( driver \"p2os_power\" )\n";

TEST(P2osLink, NothingIsOpenedBeforeTheFirstSubscription) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  EXPECT_FALSE(devices.connection(devices.sonar()).robot_answering());
  EXPECT_EQ(robot.runner().stats().host_connects, 0u);
  EXPECT_EQ(robot.received(command::sync0), 0u);
}

TEST(P2osLink, SubscribingSonarAloneOpensTheLinkAndItsDataFlows) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  EXPECT_TRUE(eventually([&] { return robot.connected(); }));
  EXPECT_TRUE(devices.connection(devices.sonar()).robot_answering());
  const auto sonar = data_when<protocol::SonarData>(devices.sonar(), [](const auto& d) { return d.ranges[0] > 0; });
  ASSERT_TRUE(sonar);
  EXPECT_EQ(sonar->range_count, 16);  // the emulator claims a p3dx
  // Sonar polling was switched on for it; the position device gets nothing.
  EXPECT_TRUE(robot.with([](P2osRobotEmulator& e) { return e.sonar_enabled(); }));
  EXPECT_EQ(data_sequence(devices.position()), 0u);
  EXPECT_EQ(devices.log.count("connected to playerkit (Pioneer p3dx, 9600 baud)"), 1u) << devices.log.all();
}

TEST(P2osLink, AddingPositionThenDroppingSonarKeepsTheSameSession) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(more_data(devices.position()));
  devices.sonar().unsubscribe();
  // The robot switches its sonar off, the position data keeps coming, and
  // nobody handshook again.
  EXPECT_TRUE(eventually([&] { return !robot.with([](P2osRobotEmulator& e) { return e.sonar_enabled(); }); }));
  EXPECT_TRUE(more_data(devices.position(), 5));
  EXPECT_TRUE(robot.connected());
  // Command 1 is SYNC1 and OPEN: one of each, one session.
  EXPECT_EQ(robot.received(command::sync1), 2u);
  EXPECT_EQ(robot.runner().stats().host_connects, 1u);
  EXPECT_EQ(robot.runner().stats().host_disconnects, 0u);
}

TEST(P2osLink, TheLastDeviceLeavingStopsTheRobotAndClosesTheLine) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(devices.power().subscribe());
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 300, .yawspeed = 10});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); })) << devices.log.all();

  devices.position().unsubscribe();
  // Still open for the power device, but the wheels stop and the motors go off.
  EXPECT_TRUE(eventually([&] { return robot.wheels_stopped() && !robot.motors_enabled(); }));
  EXPECT_TRUE(robot.connected());
  EXPECT_TRUE(more_data(devices.power()));

  const auto stops_before = robot.received(command::stop);
  const auto closes_before = robot.received(command::close);  // command 2 is SYNC2 too
  devices.power().unsubscribe();
  EXPECT_FALSE(devices.connection(devices.power()).robot_answering());
  // STOP, then CLOSE, then the port closes.
  EXPECT_TRUE(eventually([&] { return robot.runner().stats().host_disconnects == 1u; }));
  EXPECT_TRUE(eventually([&] { return robot.received(command::close) == closes_before + 1; }));
  EXPECT_EQ(robot.received(command::stop), stops_before + 1);
  EXPECT_EQ(robot.received(command::close), closes_before + 1);
  EXPECT_FALSE(robot.connected());
  EXPECT_TRUE(robot.wheels_stopped());
  EXPECT_FALSE(robot.motors_enabled());
}

TEST(P2osLink, TheLastDeviceLeavingWhileDrivingStopsTheWheels) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 200});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }));
  const auto enables_before = robot.received(command::enable);
  devices.position().unsubscribe();
  EXPECT_TRUE(eventually([&] { return robot.runner().stats().host_disconnects == 1u; }));
  // The port's close and the packets before it reach the robot in order.
  EXPECT_TRUE(eventually([&] { return robot.received(command::stop) > 0u; }));
  EXPECT_GT(robot.received(command::enable), enables_before);  // ENABLE 0 on the way out
  EXPECT_TRUE(robot.wheels_stopped());
  EXPECT_FALSE(robot.motors_enabled());
}

TEST(P2osLink, ASecondSessionHandshakesAgain) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe());
  devices.sonar().unsubscribe();
  // What the first session said last may never reach the robot: the second
  // open flushes the line (TCIOFLUSH), which on a pty also drops what the
  // emulator had not read yet. So count from here.
  const auto sync1_before = robot.received(command::sync1);
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  EXPECT_TRUE(more_data(devices.sonar()));
  // SYNC1 and OPEN (both command 1) again; on a loaded machine a handshake
  // may repeat a SYNC whose answer came late, as the reference driver does.
  EXPECT_GE(robot.received(command::sync1), sync1_before + 2);
  EXPECT_EQ(robot.runner().stats().host_connects, 2u);
}

TEST(P2osLink, EveryDeviceHasItsOwnRequestQueue) {
  // 1.5 shared one request slot between all p2os devices: a second request
  // in flight got ERR. Here each device queues its own.
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(devices.sonar().subscribe());
  const std::vector<std::uint8_t> geometry{1};
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(devices.position().enqueue_request({1, devices.position().address(), geometry, {}}),
              core::Device::RequestStatus::kQueued);
    ASSERT_EQ(devices.sonar().enqueue_request({2, devices.sonar().address(), geometry, {}}),
              core::Device::RequestStatus::kQueued);
  }
  std::vector<core::Reply> position_replies, sonar_replies;
  EXPECT_TRUE(eventually([&] {
    for (auto& r : devices.position().take_replies()) position_replies.push_back(std::move(r));
    for (auto& r : devices.sonar().take_replies()) sonar_replies.push_back(std::move(r));
    return position_replies.size() == 4 && sonar_replies.size() == 4;
  }));
  for (const auto& reply : position_replies) EXPECT_EQ(reply.type, protocol::MessageType::kAck);
  for (const auto& reply : sonar_replies) EXPECT_EQ(reply.client, 2u);
}

TEST(P2osLink, ARobotWithoutASoundDeviceNeverHearsSound) {
  // 1.5 played an uninitialised sound index, and crashed when no p2os_sound
  // was configured (quirk 16).
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(more_data(devices.position(), 5));
  EXPECT_EQ(robot.received(command::sound), 0u);
  // Nor is the gripper stored at start (quirk 10).
  EXPECT_EQ(robot.received(command::gripper), 0u);
}

TEST(P2osLink, TheRobotHearsFromUsEveryCycleSoItsWatchdogNeverStopsIt) {
  EmulatedRobot robot;  // the emulator's watchdog stops it after 2 s without a packet
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 100});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }));
  // One command, then 3 s of nothing from the client: still driving.
  ASSERT_TRUE(more_data(devices.position(), 30, 10s));
  EXPECT_FALSE(robot.wheels_stopped());
  // A packet every 100 ms cycle: about 30 in those 3 s, the last perhaps
  // still on its way when the 30th sample arrives on a loaded machine.
  EXPECT_GE(robot.received(command::vel2), 25u);
}

}  // namespace p2os_link_test
}  // namespace playerkit::drivers
