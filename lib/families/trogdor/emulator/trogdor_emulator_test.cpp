// The emulated cerebellum on a simulated clock, byte by byte, against
// trogdor.md §6: one ACK per message, the odometry block behind GET_ODOM's,
// counters that follow the wheels and are never 0, 'e'/'d', DEINIT.
#include "families/trogdor/emulator/trogdor_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "families/trogdor/protocol/trogdor_units.hpp"

namespace playerkit::emulators {
namespace {

namespace hw = hardware::trogdor;
using namespace std::chrono_literals;

struct TrogdorEmulatorTest : ::testing::Test {
  TrogdorEmulator robot{{}, nullptr};
  Duration now{0};

  hw::Bytes send(const hw::Bytes& message, Duration at = Duration{-1}) {
    if (at >= Duration{0}) now = at;
    robot.receive(message, now, TrogdorEmulator::kBaud);
    hw::Bytes out;
    for (const Telegram& telegram : robot.take_output()) out.insert(out.end(), telegram.bytes.begin(), telegram.bytes.end());
    return out;
  }
  hw::OdometryReading odometry(Duration at) {
    const hw::Bytes reply = send(hw::get_odometry(), at);
    EXPECT_EQ(reply.size(), 19u);
    EXPECT_EQ(reply[0], hw::kAck);
    return hw::parse_odometry_block(std::span(reply).subspan(1)).value_or(hw::OdometryReading{});
  }
};

TEST_F(TrogdorEmulatorTest, AcknowledgesEveryMessageOnce) {
  EXPECT_EQ(send(hw::init()), hw::Bytes{hw::kAck});
  EXPECT_TRUE(robot.initialised());
  EXPECT_EQ(send(hw::set_accelerations({10, 10})), hw::Bytes{hw::kAck});
  EXPECT_EQ(robot.accelerations(), (hw::WheelPair{10, 10}));
  EXPECT_EQ(send(hw::enable_velocity_control()), hw::Bytes{hw::kAck});
  EXPECT_EQ(send(hw::deinit()), hw::Bytes{hw::kAck});
  EXPECT_FALSE(robot.initialised());
  const hw::Bytes voltage = send(hw::get_voltage());
  ASSERT_EQ(voltage.size(), 6u);
  EXPECT_EQ(hw::parse_voltage_block(std::span(voltage).subspan(1)), 120);
}

TEST_F(TrogdorEmulatorTest, MessagesMayArriveByteByByte) {
  const hw::Bytes message = hw::set_velocities({20, 30});
  for (std::size_t i = 0; i + 1 < message.size(); ++i) EXPECT_TRUE(send({message[i]}).empty());
  EXPECT_EQ(send({message.back()}), hw::Bytes{hw::kAck});
  EXPECT_EQ(robot.velocities(), (hw::WheelPair{20, 30}));
}

TEST_F(TrogdorEmulatorTest, RefusesABadXorAnUnknownByteAndABrokenInit) {
  hw::Bytes bad = hw::set_velocities({50, 50});
  bad.back() ^= 0x10;
  EXPECT_EQ(send(bad), hw::Bytes{hw::kNack});
  EXPECT_EQ(robot.velocities(), (hw::WheelPair{0, 0}));
  EXPECT_EQ(send({'Z'}), hw::Bytes{hw::kNack});
  EXPECT_EQ(send({253, 7}), hw::Bytes{hw::kNack});
  EXPECT_EQ(send(hw::init()), hw::Bytes{hw::kAck});  // in step again
  EXPECT_EQ(robot.refused(), 3u);
}

TEST_F(TrogdorEmulatorTest, AHalfWrittenMessageIsForgotten) {
  EXPECT_TRUE(send({'v', 1, 2}).empty());
  EXPECT_EQ(send(hw::get_odometry(), 1s).size(), 19u);
}

TEST_F(TrogdorEmulatorTest, CountersStartAwayFromZeroAndFollowTheWheels) {
  const hw::OdometryReading first = odometry(0s);
  EXPECT_EQ(first.left_count, 1'000'000);
  EXPECT_EQ(first.right_count, 1'000'000);
  EXPECT_FALSE(first.encoder_error);
  send(hw::set_velocities({33, 33}));
  const hw::OdometryReading later = odometry(2s);
  // 33 units for 2 s: 33 x 516.13 x 2 ticks a wheel.
  EXPECT_NEAR(later.left_count - first.left_count, 33 * 516.13 * 2, 30);
  EXPECT_NEAR(later.right_count - first.right_count, 33 * 516.13 * 2, 30);
  EXPECT_EQ(later.left_velocity, 33);
  EXPECT_EQ(later.right_velocity, 33);
  EXPECT_NEAR(robot.drive().true_pose().x, 33 * hw::metres_per_second_per_unit() * 2, 0.01);
}

TEST_F(TrogdorEmulatorTest, ReportsVelocitiesRightFirstOnTheWire) {
  send(hw::set_velocities({-10, 10}));
  const hw::Bytes reply = send(hw::get_odometry(), 1s);
  EXPECT_EQ(hw::get_int32(reply, 1 + 8), 10);   // right
  EXPECT_EQ(hw::get_int32(reply, 1 + 12), -10);  // left
  EXPECT_GT(robot.drive().true_pose().yaw, 0.5);
}

TEST_F(TrogdorEmulatorTest, ACounterNeverReadsZero) {
  TrogdorEmulator low({.start_count = 1}, nullptr);
  low.receive(hw::set_velocities({-5, -5}), 0s, 0);
  low.take_output();
  for (int ms = 0; ms <= 20; ms += 1) {
    low.receive(hw::get_odometry(), Duration(std::chrono::microseconds(ms * 20)), 0);
    for (const Telegram& telegram : low.take_output()) {
      const auto reading = hw::parse_odometry_block(std::span(telegram.bytes).subspan(1));
      ASSERT_TRUE(reading);
      EXPECT_NE(reading->left_count, 0);
      EXPECT_NE(reading->right_count, 0);
    }
  }
}

TEST_F(TrogdorEmulatorTest, DisabledOrDeinitialisedItStands) {
  send(hw::set_velocities({40, 40}));
  send(hw::disable_velocity_control(), 0s);
  EXPECT_FALSE(robot.motion_enabled());
  const hw::OdometryReading stopped = odometry(1s);
  EXPECT_EQ(stopped.left_velocity, 0);
  EXPECT_EQ(robot.drive().true_pose().x, 0);
  send(hw::enable_velocity_control());
  odometry(2s);
  EXPECT_GT(robot.drive().true_pose().x, 0.5);
  send(hw::deinit());
  EXPECT_EQ(robot.velocities(), (hw::WheelPair{0, 0}));
  const double x = robot.drive().true_pose().x;
  odometry(3s);
  EXPECT_EQ(robot.drive().true_pose().x, x);
}

TEST_F(TrogdorEmulatorTest, OdometryErrorShowsInTheCounters) {
  TrogdorEmulatorOptions options;
  options.body.odometry_error.translation_scale = 0.1;
  TrogdorEmulator erring(options, nullptr);
  erring.receive(hw::set_velocities({20, 20}), 0s, 0);
  erring.take_output();
  erring.receive(hw::get_odometry(), 1s, 0);
  const auto reading = hw::parse_odometry_block(std::span(erring.take_output().back().bytes).subspan(1));
  ASSERT_TRUE(reading);
  const double counted = (reading->left_count - 1'000'000) * hw::metres_per_tick();
  EXPECT_NEAR(counted, erring.drive().true_pose().x * 1.1, 0.002);
}

TEST_F(TrogdorEmulatorTest, IgnoresBytesAtAnotherSpeed) {
  robot.receive(hw::get_odometry(), 0s, 9600);
  EXPECT_TRUE(robot.take_output().empty());
}

}  // namespace
}  // namespace playerkit::emulators
