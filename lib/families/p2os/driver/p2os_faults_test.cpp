// A bad line and a robot that is slow, silent or goes away: injected by the
// emulator runner (bad checksums, garbage, truncated packets, a silent
// start, a vanishing line), seen through counters, log lines, availability.
#include <gtest/gtest.h>

#include <thread>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {
namespace p2os_faults_test {

using namespace p2os_testing;

std::string robot_config(const std::string& robot_options = "") {
  return "position:0 ( driver \"p2os_position\" port \"$PORT\" " + robot_options + " )\n"
         "sonar:0 ( driver \"p2os_sonar\" )\n"
         "power:0 ( driver \"p2os_power\" )\n";
}

emulators::FaultPlan faults(std::initializer_list<std::string_view> arguments) {
  emulators::FaultPlan plan;
  for (std::string_view argument : arguments) emulators::add_fault(plan, argument);
  return plan;
}

class P2osLineFaults : public ::testing::TestWithParam<std::string> {};

TEST_P(P2osLineFaults, DataKeepsFlowingAndTheLinkCountsWhatItDropped) {
  EmulatedRobot robot({}, faults({GetParam()}));
  RobotDevices devices(robot.port(), robot_config());
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(more_data(devices.position(), 30, 10s));
  core::Device& any = devices.position();
  const auto dropped = devices.counter(any, "checksum_errors") + devices.counter(any, "resyncs");
  EXPECT_GT(dropped, 0u);
  EXPECT_GT(devices.counter(any, "bytes_dropped"), 0u);
  EXPECT_GE(devices.counter(any, "sips"), 30u);
  EXPECT_EQ(devices.counter(any, "robot_lost"), 0u);
  // Commands still get through.
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  EXPECT_TRUE(eventually([&] { return robot.motors_enabled(); }));
}

INSTANTIATE_TEST_SUITE_P(Faults, P2osLineFaults,
                         ::testing::Values("bad-checksum=0.2", "garbage=0.2", "truncate=0.1"),
                         [](const ::testing::TestParamInfo<std::string>& row) {
                           std::string name = row.param.substr(0, row.param.find('='));
                           std::erase(name, '-');
                           return name;
                         });

TEST(P2osFaults, BadChecksumsAreCountedAsSuch) {
  EmulatedRobot robot({}, faults({"bad-checksum=0.3"}));
  RobotDevices devices(robot.port(), robot_config());
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  ASSERT_TRUE(more_data(devices.sonar(), 20, 10s));
  EXPECT_GT(devices.counter(devices.sonar(), "checksum_errors"), 0u);
}

TEST(P2osFaults, ARobotSilentBeyondTheTimeoutRefusesTheSubscriptionNamingThePort) {
  EmulatedRobot robot({}, faults({"silent-start=2"}));
  RobotDevices devices(robot.port(), robot_config("connect_timeout 0.5"));
  EXPECT_FALSE(devices.position().subscribe());
  EXPECT_EQ(devices.position().subscriptions(), 0);
  EXPECT_EQ(devices.connection(devices.position()).users(), 0);
  EXPECT_EQ(devices.log.count("position:0@6665 (p2os_position): setup failed: no answer from a P2OS robot on " +
                                  robot.port(),
                              core::LogLevel::kError),
            1u)
      << devices.log.all();
  EXPECT_EQ(devices.log.count("9600, 38400, 19200, 115200, 57600 baud", core::LogLevel::kError), 1u);
  // Once the robot has woken up, the next subscription works.
  ASSERT_TRUE(eventually([&] { return robot.runner().now() > std::chrono::milliseconds(2100); }));
  EXPECT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_TRUE(more_data(devices.position()));
}

TEST(P2osFaults, ARobotSlowToWakeWithinTheTimeoutIsWaitedFor) {
  EmulatedRobot robot({}, faults({"silent-start=0.7"}));
  RobotDevices devices(robot.port(), robot_config("connect_timeout 5"));
  EXPECT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  EXPECT_TRUE(more_data(devices.sonar()));
  EXPECT_GT(devices.counter(devices.sonar(), "timeouts"), 0u);  // the SYNC0s nobody answered
}

TEST(P2osFaults, AMissingPortRefusesTheSubscriptionNamingIt) {
  RobotDevices devices("/tmp/playerkit-no-such-pioneer", robot_config());
  EXPECT_FALSE(devices.sonar().subscribe());
  EXPECT_EQ(devices.log.count("/tmp/playerkit-no-such-pioneer", core::LogLevel::kError), 1u) << devices.log.all();
}

TEST(P2osFaults, AVanishedRobotIsReconnectedInTheBackground) {
  // The line goes dead 1 s after the emulator starts, for 2.5 s.
  EmulatedRobot robot({}, faults({"vanish=1:2.5"}));
  RobotDevices devices(robot.port(), robot_config("sip_timeout 0.5"));
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  ASSERT_TRUE(more_data(position));

  // Gone: one log line, the devices unavailable, no more data.
  ASSERT_TRUE(eventually([&] { return !position.available(); }, 5s)) << devices.log.all();
  // The link's thread marks the devices one after another: wait out the gap.
  EXPECT_TRUE(eventually([&] { return !devices.sonar().available(); }, 1s));
  const std::uint64_t frozen = data_sequence(position);
  EXPECT_FALSE(devices.power().subscribe());  // newcomers are refused meanwhile
  EXPECT_TRUE(nacked(ask(position, protocol::PositionPowerConfig{2, 1})));  // needs the robot
  EXPECT_TRUE(acked(ask(position, std::vector<std::uint8_t>{protocol::kPositionGetGeomReq})));  // does not
  std::this_thread::sleep_for(300ms);
  EXPECT_EQ(data_sequence(position), frozen);

  // Back: one log line, available again, data again, motors as the client left them.
  ASSERT_TRUE(eventually([&] { return position.available(); }, 10s)) << devices.log.all();
  EXPECT_TRUE(devices.sonar().available());
  EXPECT_TRUE(more_data(position, 3));
  EXPECT_TRUE(eventually([&] { return robot.motors_enabled(); }));
  EXPECT_TRUE(robot.wheels_stopped());
  EXPECT_TRUE(devices.power().subscribe());
  EXPECT_EQ(devices.log.count("lost the robot (no SIP for", core::LogLevel::kWarning), 1u) << devices.log.all();
  EXPECT_EQ(devices.log.count("the robot is back after", core::LogLevel::kWarning), 1u) << devices.log.all();
  EXPECT_EQ(devices.counter(position, "robot_lost"), 1u);
  EXPECT_EQ(devices.counter(position, "reconnects"), 1u);
}

TEST(P2osFaults, TheByteTraceSeesBothDirections) {
  // Declared before the devices: their shutdown still writes to the line.
  std::mutex mutex;
  std::vector<std::uint8_t> out, in;
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  // Set before the link exists, as `player-drivers run --trace` does.
  ASSERT_TRUE(devices.sonar().driver().set_byte_trace(
      [&](bool outgoing, std::span<const std::uint8_t> bytes, std::chrono::steady_clock::time_point) {
        std::lock_guard lock(mutex);
        (outgoing ? out : in).insert((outgoing ? out : in).end(), bytes.begin(), bytes.end());
      }));
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(more_data(devices.sonar(), 2));
  std::lock_guard lock(mutex);
  ASSERT_GE(out.size(), 6u);
  EXPECT_EQ((std::vector<std::uint8_t>(out.begin(), out.begin() + 6)),
            (std::vector<std::uint8_t>{0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00}));  // SYNC0
  ASSERT_GE(in.size(), 6u);
  EXPECT_EQ((std::vector<std::uint8_t>(in.begin(), in.begin() + 6)),
            (std::vector<std::uint8_t>{0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00}));  // its echo
}

}  // namespace p2os_faults_test
}  // namespace playerkit::drivers
