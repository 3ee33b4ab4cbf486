#include "families/rflex/emulator/rflex_emulator.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "families/rflex/protocol/rflex_packet.hpp"

namespace playerkit::emulators::rflex {
namespace rflex_emulator_test {

namespace hw = hardware::rflex;
using namespace std::chrono_literals;

// The emulator on a simulated clock: commands in, packets out.
struct Bench {
  explicit Bench(RflexEmulatorOptions options = {}) : robot(std::move(options)) {}

  void send(const hw::Packet& packet) { robot.receive(hw::encode_packet(packet), now, 115200); }
  std::vector<hw::Packet> run_for(Duration time) {
    now += time;
    robot.advance(now);
    std::vector<hw::Packet> packets;
    for (const Telegram& telegram : robot.take_output()) {
      const auto packet = hw::decode_packet(telegram.bytes);
      EXPECT_TRUE(packet) << "a telegram that is not one packet";
      if (packet) packets.push_back(*packet);
    }
    return packets;
  }
  void start_reports() { send(hw::motion_report_request(100000, 3)); }
  void drive(std::uint32_t translation, bool forward, std::uint32_t rotation, bool left) {
    send(hw::axis_set_direction({hw::kTranslationAxis, translation, 0, 30000, forward}));
    send(hw::axis_set_direction({hw::kRotationAxis, rotation, 100000, 35000, left}));
  }

  RflexEmulator robot;
  Duration now{0};
};

template <class Read>
auto first_of(const std::vector<hw::Packet>& packets, Read read) -> decltype(read(packets.front())) {
  for (const auto& packet : packets) {
    if (auto value = read(packet)) return value;
  }
  return std::nullopt;
}

TEST(RflexEmulator, ReportsBothAxesEveryPeriodAfterTheRequest) {
  Bench bench;
  EXPECT_TRUE(bench.run_for(1s).empty());  // nothing unasked
  bench.start_reports();
  const auto early = bench.run_for(99ms);
  EXPECT_TRUE(early.empty());
  const auto burst = bench.run_for(1ms);
  ASSERT_EQ(burst.size(), 2U);
  EXPECT_EQ(hw::read_motion_report(burst[0])->axis, 0);
  EXPECT_EQ(hw::read_motion_report(burst[1])->axis, 1);
  EXPECT_EQ(hw::encode_packet(burst[0]).size(), 34U);
  EXPECT_EQ(bench.run_for(1s).size(), 20U);
  bench.send(hw::motion_report_request(0, 0));
  EXPECT_TRUE(bench.run_for(1s).empty());
}

TEST(RflexEmulator, CountersFollowTheCommandedVelocitiesInTheModelsUnits) {
  Bench bench;  // b21r: 103 per mm, 35000 per rad
  bench.start_reports();
  bench.drive(103 * 200, true, 0, true);  // 0.2 m/s
  for (int i = 0; i < 10; ++i) {
    bench.drive(103 * 200, true, 0, true);
    bench.run_for(100ms);
  }
  EXPECT_NEAR(bench.robot.distance_counter(), 103 * 200, 103 * 2);
  EXPECT_NEAR(bench.robot.drive().true_pose().x, 0.2, 0.002);
  bench.drive(0, true, 17500, false);  // -0.5 rad/s
  bench.run_for(1s);
  EXPECT_NEAR(bench.robot.bearing_counter(), -17500, 200);
  EXPECT_NEAR(bench.robot.drive().true_pose().yaw, -0.5, 0.01);
  bench.drive(0, true, 17500, false);
  const auto reports = bench.run_for(100ms);
  ASSERT_EQ(reports.size(), 2U);
  EXPECT_EQ(hw::read_motion_report(reports[1])->velocity, -17500);
  // --stats shows the true pose, what a driver's odometry is checked against (reference check, issue 29).
  const std::string text = bench.robot.describe();
  const geometry::Pose2& pose = bench.robot.drive().true_pose();
  char where[80];
  std::snprintf(where, sizeof where, ", at (%.2f, %.2f, %.0f deg)", pose.x, pose.y, pose.yaw * 180.0 / 3.14159265358979);
  EXPECT_NE(text.find(where), std::string::npos) << text;
  EXPECT_NE(text.find(", at (0.20, "), std::string::npos) << text;
}

TEST(RflexEmulator, BrakeHoldsTheRobotAndDefaultsStopIt) {
  RflexEmulatorOptions options;
  options.brake_at_start = true;
  Bench bench(options);
  bench.drive(10000, true, 0, true);
  bench.run_for(500ms);
  EXPECT_EQ(bench.robot.drive().true_pose().x, 0.0);
  bench.send(hw::brake_release());
  bench.drive(10000, true, 0, true);
  bench.run_for(500ms);
  EXPECT_GT(bench.robot.drive().true_pose().x, 0.0);
  bench.send(hw::set_defaults());
  EXPECT_EQ(bench.robot.translation_command(), 0);
}

TEST(RflexEmulator, TheFailsafeStopsARobotNobodyCommands) {
  Bench bench;
  bench.drive(10300, true, 0, true);
  bench.run_for(3s);
  EXPECT_EQ(bench.robot.translation_command(), 0);
  EXPECT_NEAR(bench.robot.drive().true_pose().x, 0.1, 0.011);  // one second of 0.1 m/s
}

TEST(RflexEmulator, StatusJoystickSonarIrAndBumpers) {
  Bench bench;
  bench.send(hw::system_status_request());
  const auto status = first_of(bench.run_for(1ms), hw::read_system_status);
  ASSERT_TRUE(status);
  EXPECT_EQ(status->voltage, 2640U);
  bench.send(hw::joystick_request());
  EXPECT_TRUE(first_of(bench.run_for(1ms), hw::read_joystick_state));

  bench.send(hw::sonar_run({30000, 0, 0, hw::kSonarRunOn}));
  bench.send(hw::ir_run(true));
  const auto burst = bench.run_for(100ms);
  const auto echoes = first_of(burst, hw::read_sonar_report);
  ASSERT_TRUE(echoes);
  ASSERT_EQ(echoes->size(), 24U);
  EXPECT_EQ((*echoes)[8].id, 16);  // board 1, channel 0
  EXPECT_EQ((*echoes)[0].range, static_cast<std::uint16_t>(5000 * 1.476));  // nothing in range
  const auto banks = first_of(burst, hw::read_ir_report);
  ASSERT_TRUE(banks);
  EXPECT_EQ(banks->size(), 3U);
  bench.send(hw::sonar_run({0, 0, 0, 0}));
  bench.send(hw::ir_run(false));
  EXPECT_TRUE(bench.run_for(1s).empty());

  bench.send(hw::dio_reports_request(100000));
  EXPECT_EQ(bench.run_for(1ms).size(), 14U);  // every panel once
  bench.robot.press_bumper(3, 0x05);
  const auto pressed = first_of(bench.run_for(1ms), hw::read_dio_report);
  ASSERT_TRUE(pressed);
  EXPECT_EQ(pressed->address, 0x43);
  EXPECT_EQ(pressed->value, 0x05);
}

TEST(RflexEmulator, BrokenPacketsAndNoiseAreIgnored) {
  Bench bench;
  auto bytes = hw::encode_packet(hw::system_status_request());
  bytes[6] ^= 0x55;  // the XOR
  std::vector<std::uint8_t> noise{0x00, 0x1B, 0x7F};
  bench.robot.receive(noise, bench.now, 115200);
  bench.robot.receive(bytes, bench.now, 115200);
  EXPECT_TRUE(bench.run_for(1ms).empty());
  // A packet split across two writes still counts.
  const auto good = hw::encode_packet(hw::system_status_request());
  bench.robot.receive(std::span(good).first(4), bench.now, 115200);
  bench.robot.receive(std::span(good).subspan(4), bench.now, 115200);
  EXPECT_EQ(bench.run_for(1ms).size(), 1U);
}

TEST(RflexEmulator, ModelsChooseUnitsAndSensors) {
  RflexEmulatorOptions options;
  options.model = *find_rflex_model("atrvjr");
  Bench bench(options);
  bench.start_reports();
  for (int i = 0; i < 10; ++i) {
    bench.drive(static_cast<std::uint32_t>(90.81 * 100), true, 0, true);
    bench.run_for(100ms);
  }
  EXPECT_NEAR(bench.robot.distance_counter(), 90.81 * 100, 100);
  EXPECT_EQ(find_rflex_model("nothing"), nullptr);
  EXPECT_EQ(find_rflex_model("magellan")->bumper_panels, 16);
}

}  // namespace rflex_emulator_test
}  // namespace playerkit::emulators::rflex
