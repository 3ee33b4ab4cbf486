// The emulated RMP on a simulated clock: the adapter's slcan commands, the
// status messages at their rate in the sheet's units, velocity and status
// commands, the watchdog and the shutdown (segwayrmp.md §6).
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "links/can/slcan.hpp"

namespace playerkit::emulators {
namespace segwayrmp_emulator_test {

namespace rmp = hardware::segwayrmp;
using namespace std::chrono_literals;

struct Session {
  SegwayRmpEmulator robot;
  Duration now{0};

  explicit Session(SegwayRmpEmulatorOptions options = {}) : robot(options) {}

  std::vector<std::string> say(const std::string& text) {
    robot.receive(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), now, 0);
    return lines();
  }
  std::vector<std::string> wait(Duration time) {
    const Duration until = now + time;
    while (robot.next_deadline() <= until) {
      now = std::max(now, robot.next_deadline());
      robot.advance(now);
    }
    now = until;
    robot.advance(now);
    return lines();
  }
  std::vector<std::string> lines() {
    std::vector<std::string> out;
    for (const Telegram& telegram : robot.take_output()) out.emplace_back(telegram.bytes.begin(), telegram.bytes.end());
    return out;
  }
  void command(double mm_per_s, double deg_per_s, rmp::StatusCommand status = rmp::StatusCommand::none,
               std::uint8_t value = 0) {
    const auto frame = rmp::command_frame(
        {.trans = rmp::trans_counts(mm_per_s), .rot = rmp::rot_counts(deg_per_s), .status = status, .status_value = value});
    say(links::can::slcan_frame_line(frame));
  }
  // The last complete status set among `lines`.
  static rmp::Status last_status(const std::vector<std::string>& lines) {
    rmp::StatusAssembler assembler;
    rmp::Status status;
    for (const std::string& line : lines) {
      const auto frame = links::can::parse_slcan_frame(line.substr(0, line.size() - 1));
      if (frame && assembler.add(*frame)) status = assembler.status();
    }
    return status;
  }
};

TEST(SegwayRmpEmulator, TheAdapterAcknowledgesOpensAndRefusesAsLawicelSays) {
  Session session;
  EXPECT_EQ(session.say("C\r"), std::vector<std::string>{"\a"});  // not open
  EXPECT_EQ(session.say("S6\r"), std::vector<std::string>{"\r"});
  EXPECT_EQ(session.say("S9\r"), std::vector<std::string>{"\a"});
  EXPECT_EQ(session.say("V\r"), std::vector<std::string>{"V1013\r"});
  EXPECT_EQ(session.say("t4130\r"), std::vector<std::string>{"\a"});  // closed: nothing goes on the bus
  EXPECT_TRUE(session.wait(100ms).empty());                          // closed: the robot is not heard
  const auto opened = session.say("O\r");
  ASSERT_FALSE(opened.empty());
  EXPECT_EQ(opened.front(), "\r");
  EXPECT_TRUE(session.robot.channel_open());
  EXPECT_EQ(session.say("S4\r").back(), "\a");  // the rate is set while closed
  EXPECT_EQ(session.robot.bitrate(), 500000);
}

TEST(SegwayRmpEmulator, FiveStatusMessagesEveryTenMilliseconds) {
  Session session;
  session.say("S6\rO\r");
  const auto heard = session.wait(1s);
  // One set at the opening and one each 10 ms after it.
  EXPECT_GE(heard.size(), 500u);
  EXPECT_LE(heard.size(), 510u);
  EXPECT_EQ(heard[0].substr(0, 4), "t400");
  EXPECT_EQ(heard[4].substr(0, 4), "t404");
  EXPECT_EQ(heard[0], "t40080000000000640000\r");  // battery 100: 72.0 V
}

TEST(SegwayRmpEmulator, VelocityCommandsMoveTheCountersInTheSheetsUnits) {
  Session session;
  session.say("O\r");
  session.command(500, 0);
  auto heard = session.wait(200ms);
  session.command(500, 0);
  heard = session.wait(200ms);
  const rmp::Status status = Session::last_status(heard);
  // 0.4 s at 0.5 m/s = 0.2 m = 6643 counts (to within one status period).
  EXPECT_NEAR(static_cast<double>(status.fore_aft_displacement), 0.2 * 33215, 0.5 * 0.011 * 33215);
  EXPECT_NEAR(status.left_wheel_velocity, 166, 1);
  EXPECT_NEAR(status.right_wheel_velocity, 166, 1);
  EXPECT_NEAR(session.robot.world_pose()->x, 0.2, 0.01);
  // --stats shows the true pose, what a driver's odometry is checked against (reference check, issue 29).
  const std::string text = session.robot.describe();
  EXPECT_NE(text.find(", at (0.2"), std::string::npos) << text;
}

TEST(SegwayRmpEmulator, TurningCounterClockwiseGrowsYawAndReportsAClockwiseRate) {
  Session session;
  session.say("O\r");
  for (int step = 0; step < 10; ++step) {
    session.command(0, 45);
    session.wait(100ms);
  }
  const auto heard = session.wait(10ms);
  const rmp::Status status = Session::last_status(heard);
  EXPECT_NEAR(static_cast<double>(status.yaw_displacement), 112644 / 8.0, 112644 * 0.012);
  EXPECT_NEAR(status.yaw_rate, -45 * 7.8, 2);
  EXPECT_NEAR(session.robot.world_pose()->yaw, M_PI / 4, 0.03);
}

TEST(SegwayRmpEmulator, TheWatchdogStopsARobotLeftWithoutCommands) {
  Session session;
  session.say("O\r");
  session.command(1000, 0);
  session.wait(200ms);
  EXPECT_GT(session.robot.commanded_speed(), 0.9);
  session.wait(100ms);  // 0.3 s since the command: past 0.25 s
  EXPECT_EQ(session.robot.commanded_speed(), 0.0);
  EXPECT_EQ(session.robot.watchdog_stops(), 1u);
  const double x = session.robot.world_pose()->x;
  session.wait(1s);
  EXPECT_EQ(session.robot.world_pose()->x, x);
}

TEST(SegwayRmpEmulator, StatusCommandsScaleAndResetIntegrators) {
  Session session;
  session.say("O\r");
  session.command(1000, 0);
  session.wait(100ms);
  session.command(0, 0, rmp::StatusCommand::reset_integrators, rmp::kResetForeAft);
  auto heard = session.wait(20ms);
  EXPECT_LT(Session::last_status(heard).fore_aft_displacement, 400u);
  session.command(0, 0, rmp::StatusCommand::velocity_scale, 8);
  EXPECT_EQ(session.robot.scale(rmp::StatusCommand::velocity_scale), 8);
  session.command(1000, 0);
  EXPECT_NEAR(session.robot.commanded_speed(), 0.0, 1e-9);  // the drive takes it at the next step
  session.wait(20ms);
  EXPECT_NEAR(session.robot.commanded_speed(), 0.5, 0.01);
}

TEST(SegwayRmpEmulator, AnAccelerationLimitRampsTheSpeed) {
  Session session({.max_acceleration = 1.0});
  session.say("O\r");
  session.command(1000, 0);
  session.wait(100ms);
  EXPECT_NEAR(session.robot.commanded_speed(), 0.1, 0.011);
}

TEST(SegwayRmpEmulator, ShutdownStopsAndSilencesUntilReopened) {
  Session session;
  session.say("O\r");
  session.command(500, 0);
  session.say(links::can::slcan_frame_line(rmp::shutdown_frame()));
  EXPECT_TRUE(session.robot.shut_down());
  EXPECT_TRUE(session.wait(100ms).empty());
  EXPECT_EQ(session.robot.commanded_speed(), 0.0);
  session.say("C\r");
  session.say("O\r");
  EXPECT_FALSE(session.wait(20ms).empty());
}

}  // namespace segwayrmp_emulator_test
}  // namespace playerkit::emulators
