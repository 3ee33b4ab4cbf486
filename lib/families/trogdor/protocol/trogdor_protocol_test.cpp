// Golden bytes from trogdor.md §1.2's worked examples, the units of §3, and
// where the reply format cuts.
#include <gtest/gtest.h>

#include <cmath>

#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "families/trogdor/protocol/trogdor_reply_format.hpp"
#include "families/trogdor/protocol/trogdor_units.hpp"

namespace playerkit::hardware::trogdor {
namespace {

using framing::FrameScan;

TEST(TrogdorMessages, MatchTheSheetsWorkedExamples) {
  EXPECT_EQ(set_velocities({.left = 100, .right = -100}),
            (Bytes{0x76, 0x64, 0x00, 0x00, 0x00, 0x9C, 0xFF, 0xFF, 0xFF, 0x71}));
  EXPECT_EQ(set_accelerations({10, 10}), (Bytes{0x61, 0x0A, 0, 0, 0, 0x0A, 0, 0, 0, 0x61}));
  EXPECT_EQ(init(), (Bytes{253, 252, 251}));
  EXPECT_EQ(deinit(), Bytes{250});
  EXPECT_EQ(get_odometry(), Bytes{111});
  EXPECT_EQ(enable_velocity_control(), Bytes{101});
  EXPECT_EQ(disable_velocity_control(), Bytes{100});
  EXPECT_EQ(get_voltage(), Bytes{98});
}

TEST(TrogdorMessages, OdometryBlockRightVelocityFirst) {
  const Bytes golden{0xE8, 0x03, 0, 0, 0xD0, 0x07, 0, 0, 0x21, 0, 0, 0, 0x21, 0, 0, 0, 0x00, 0x3C};
  const OdometryReading reading{.left_count = 1000, .right_count = 2000, .left_velocity = 33, .right_velocity = 33};
  EXPECT_EQ(odometry_block(reading), golden);
  EXPECT_EQ(parse_odometry_block(golden), reading);

  const OdometryReading turning{.left_count = -5, .right_count = 7, .left_velocity = -2, .right_velocity = 9,
                                .encoder_error = true};
  const Bytes block = odometry_block(turning);
  EXPECT_EQ(block[8], 9);     // right velocity first
  EXPECT_EQ(block[12], 0xFE);  // then left
  EXPECT_EQ(parse_odometry_block(block), turning);

  Bytes corrupt = golden;
  corrupt[3] ^= 0x40;
  EXPECT_EQ(parse_odometry_block(corrupt), std::nullopt);
  EXPECT_EQ(parse_odometry_block(std::span(golden).first(17)), std::nullopt);
  EXPECT_EQ(parse_voltage_block(voltage_block(-1234)), -1234);
}

TEST(TrogdorUnits, FollowTheReferenceConstants) {
  EXPECT_NEAR(metres_per_tick(), 2.92358e-5, 1e-9);
  EXPECT_NEAR(metres_per_second_per_unit(), 0.0150895, 1e-7);
  EXPECT_NEAR(ticks_per_second_per_unit(), 516.13, 0.01);
}

TEST(TrogdorUnits, CommandAsWheelUnits) {
  // 0.5 m/s straight: 33.1 units, rounded.
  EXPECT_EQ(wheel_units_for(500, 0), (WheelPair{33, 33}));
  // 90 deg/s on the spot: each wheel 0.24897 m/s, 16.4997 units.
  EXPECT_EQ(wheel_units_for(0, 90), (WheelPair{-16, 16}));
  EXPECT_EQ(wheel_units_for(0, 0), (WheelPair{0, 0}));
  // 1 to 4 units are raised to the controller's minimum of 5; less than half a unit is 0.
  EXPECT_EQ(wheel_units_for(30, 0), (WheelPair{5, 5}));
  EXPECT_EQ(wheel_units_for(5, 0), (WheelPair{0, 0}));
  EXPECT_EQ(wheel_units_for(-30, 0), (WheelPair{-5, -5}));
}

TEST(TrogdorUnits, TooFastKeepsTheCurve) {
  const WheelPair units = wheel_units_for(8000, 180);
  EXPECT_EQ(units.right, 331);  // 5 m/s
  EXPECT_GT(units.left, 0);
  EXPECT_NEAR(static_cast<double>(units.left) / units.right, (8 - 0.498) / (8 + 0.498), 0.01);
}

TEST(TrogdorUnits, BodyVelocityFromWheels) {
  const BodyVelocity straight = body_velocity(33, 33);
  EXPECT_NEAR(straight.forward, 0.49795, 1e-4);
  EXPECT_EQ(straight.turn_rate, 0);
  const BodyVelocity spin = body_velocity(-10, 10);
  EXPECT_EQ(spin.forward, 0);
  EXPECT_NEAR(spin.turn_rate, 2 * 10 * 0.0150895 / 0.317, 1e-5);
}

FrameScan scan(const framing::FrameFormat& format, const Bytes& bytes) { return format.scan(bytes); }

TEST(TrogdorReplyFormat, CutsWhatWasAskedFor) {
  TrogdorReplyFormat format(ReplyShape::ack);
  EXPECT_EQ(scan(format, {kAck, 1, 2}).length, 1u);
  EXPECT_EQ(scan(format, {kNack}).kind, FrameScan::Kind::frame);
  EXPECT_EQ(scan(format, {'x', 'y', kAck}).kind, FrameScan::Kind::skip);
  EXPECT_EQ(scan(format, {'x', 'y', kAck}).length, 2u);

  format.expect(ReplyShape::ack_then_odometry);
  Bytes reply{kAck};
  const Bytes block = odometry_block({.left_count = 1000, .right_count = 2000});
  reply.insert(reply.end(), block.begin(), block.end());
  EXPECT_EQ(scan(format, Bytes(reply.begin(), reply.begin() + 5)).kind, FrameScan::Kind::need_more);
  EXPECT_EQ(scan(format, reply).kind, FrameScan::Kind::frame);
  EXPECT_EQ(scan(format, reply).length, kLongestReply);
  EXPECT_EQ(scan(format, {kNack}).length, 1u);  // a refusal has no block
  reply.back() ^= 1;
  EXPECT_EQ(scan(format, reply).kind, FrameScan::Kind::bad_checksum);
}

TEST(TrogdorReplyFormat, TraceGuessesTheBlock) {
  const TrogdorReplyFormat format(ReplyShape::guess);
  Bytes reply{kAck};
  const Bytes block = odometry_block({.left_count = 1, .right_count = 2});
  reply.insert(reply.end(), block.begin(), block.end());
  EXPECT_EQ(scan(format, reply).length, kLongestReply);
  EXPECT_EQ(scan(format, {kAck, kAck}).length, 1u);
}

TEST(TrogdorHostFormat, CutsEachMessage) {
  const TrogdorHostFormat format;
  EXPECT_EQ(scan(format, init()).length, 3u);
  EXPECT_EQ(scan(format, {253, 252}).kind, FrameScan::Kind::need_more);
  EXPECT_EQ(scan(format, {253, 1, 2}).kind, FrameScan::Kind::skip);
  EXPECT_EQ(scan(format, set_velocities({1, 2})).length, 10u);
  Bytes bad = set_velocities({1, 2});
  bad.back() ^= 1;
  EXPECT_EQ(scan(format, bad).kind, FrameScan::Kind::bad_checksum);
  EXPECT_EQ(scan(format, get_odometry()).length, 1u);
  EXPECT_EQ(scan(format, {'Z'}).kind, FrameScan::Kind::skip);
}

}  // namespace
}  // namespace playerkit::hardware::trogdor
