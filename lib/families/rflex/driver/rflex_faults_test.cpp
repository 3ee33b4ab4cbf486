// A bad line and a robot that is silent or goes away, injected by the
// emulator runner, seen through counters, log lines and availability.
#include <gtest/gtest.h>

#include <mutex>
#include <thread>

#include "families/rflex/driver/rflex_test_support.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {
namespace rflex_faults_test {

using namespace rflex_testing;

std::string robot_config(const std::string& link_options = "") {
  return "position:0 ( driver \"rflex_position\" rflex_serial_port \"$PORT\" " + link_options + " )\n"
         "power:0 ( driver \"rflex_power\" )\n";
}

class RflexLineFaults : public ::testing::TestWithParam<std::string> {};

TEST_P(RflexLineFaults, DataKeepsFlowingAndTheLinkCountsWhatItDropped) {
  EmulatedRflex robot({}, faults({GetParam()}));
  RflexDevices devices(robot.port(), robot_config());
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  ASSERT_TRUE(devices.power().subscribe());
  ASSERT_TRUE(more_data(devices.position(), 20, 10s));
  core::Device& any = devices.position();
  EXPECT_GT(devices.counter(any, "checksum_errors") + devices.counter(any, "resyncs"), 0u);
  EXPECT_EQ(devices.counter(any, "robot_lost"), 0u);
  // Commands still get through.
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 0})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.braked(); }));
}

INSTANTIATE_TEST_SUITE_P(Faults, RflexLineFaults, ::testing::Values("bad-checksum=0.2", "garbage=0.2", "truncate=0.1", "drop=0.02"),
                         [](const ::testing::TestParamInfo<std::string>& row) {
                           std::string name = row.param.substr(0, row.param.find('='));
                           std::erase(name, '-');
                           return name;
                         });

TEST(RflexFaults, ASilentRobotRefusesTheSubscriptionWithinTheTimeoutNamingThePort) {
  EmulatedRflex robot({}, faults({"silent-start=3"}));
  RflexDevices devices(robot.port(), robot_config("connect_timeout 0.5"));
  // Refused: had it waited for the robot to wake (3 s), it would have been accepted.
  EXPECT_FALSE(devices.position().subscribe());
  EXPECT_EQ(devices.log.count("no RFLEX controller answered within 0.5 s", core::LogLevel::kError), 1u)
      << devices.log.all();
  EXPECT_EQ(devices.log.count(robot.port(), core::LogLevel::kError), 1u);
  ASSERT_TRUE(eventually([&] { return robot.runner().now() > 3100ms; }));
  EXPECT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_TRUE(more_data(devices.position()));
}

// Deaf and mute for a second after the line opens (a controller still
// booting): the setup keeps asking within its timeout instead of failing.
TEST(RflexFaults, ARobotSlowToWakeIsWaitedForWithinTheTimeout) {
  EmulatedRflex robot({}, faults({"slow-start=1"}));
  RflexDevices devices(robot.port(), robot_config("connect_timeout 5"));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_GE(robot.runner().now(), 1s);
  EXPECT_TRUE(more_data(devices.position(), 3));
  EXPECT_EQ(devices.log.count("no RFLEX controller answered", core::LogLevel::kError), 0u) << devices.log.all();
}

TEST(RflexFaults, AVanishedRobotIsSoughtAgainAndItsDataResumes) {
  EmulatedRflex robot({}, faults({"vanish=1:2"}));
  RflexDevices devices(robot.port(), robot_config("report_timeout 0.4"));
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe()) << devices.log.all();
  ASSERT_TRUE(more_data(position));
  ASSERT_TRUE(eventually([&] { return !position.available(); }, 5s)) << devices.log.all();
  const std::uint64_t frozen = data_sequence(position);
  std::this_thread::sleep_for(300ms);
  EXPECT_EQ(data_sequence(position), frozen);
  EXPECT_TRUE(nacked(ask(position, protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1})));
  ASSERT_TRUE(eventually([&] { return position.available(); }, 10s)) << devices.log.all();
  EXPECT_TRUE(more_data(position, 3));
  EXPECT_EQ(devices.log.count("lost the robot (no packet from the RFLEX controller", core::LogLevel::kWarning), 1u)
      << devices.log.all();
  EXPECT_EQ(devices.counter(position, "robot_lost"), 1u);
  EXPECT_EQ(devices.counter(position, "reconnects"), 1u);
}

TEST(RflexFaults, TheByteTraceSeesBothDirections) {
  std::mutex mutex;
  std::vector<std::uint8_t> out, in;
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), robot_config());
  ASSERT_TRUE(devices.power().driver().set_byte_trace(
      [&](bool outgoing, std::span<const std::uint8_t> bytes, std::chrono::steady_clock::time_point) {
        std::lock_guard lock(mutex);
        (outgoing ? out : in).insert((outgoing ? out : in).end(), bytes.begin(), bytes.end());
      }));
  ASSERT_TRUE(devices.power().subscribe());
  ASSERT_TRUE(more_data(devices.power(), 2));
  std::lock_guard lock(mutex);
  ASSERT_GE(out.size(), 17u);  // MOT_SYSTEM_REPORT_REQ first
  EXPECT_EQ((std::vector<std::uint8_t>(out.begin(), out.begin() + 5)),
            (std::vector<std::uint8_t>{0x1B, 0x02, 0x02, 0x00, 0x22}));
  ASSERT_GE(in.size(), 2u);
  EXPECT_EQ(in[0], 0x1B);
}

}  // namespace rflex_faults_test
}  // namespace playerkit::drivers
