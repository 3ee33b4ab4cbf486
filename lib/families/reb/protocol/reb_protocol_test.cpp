// Golden text and numbers from reb.md §1.1, §2, §3.
#include <gtest/gtest.h>

#include <string>

#include "families/reb/protocol/reb_lines.hpp"
#include "families/reb/protocol/reb_params.hpp"
#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::reb {
namespace reb_protocol_test {

std::string text_of(const Command& command) {
  const auto bytes = encode(command);
  return {bytes.begin(), bytes.end()};
}

TEST(RebLines, CommandsAreTheSheetsText) {
  EXPECT_EQ(text_of(set_speed(Motor::left, -24)), "D,2,-24\r");
  EXPECT_EQ(text_of(set_speed(Motor::right, 0)), "D,0,0\r");
  EXPECT_EQ(text_of(read_position(Motor::left)), "H,2\r");
  EXPECT_EQ(text_of(set_position(Motor::right, 0)), "G,0,0\r");
  EXPECT_EQ(text_of(move_to(Motor::right, -2656)), "C,0,-2656\r");
  EXPECT_EQ(text_of(read_motion_status(Motor::right)), "K,0\r");
  EXPECT_EQ(text_of(speed_pid(Motor::right, 1000, 0, 10)), "A,0,1000,0,10\r");
  EXPECT_EQ(text_of(position_pid(Motor::left, 100, 0, 10)), "F,2,100,0,10\r");
  EXPECT_EQ(text_of(speed_profile(Motor::left, 24, 24)), "J,2,24,24\r");
  EXPECT_EQ(text_of(read_analog(kBatteryChannel)), "I,15\r");
  EXPECT_EQ(text_of(read_ir()), "W\r");
  EXPECT_EQ(text_of(ir_power(true)), "Y,1\r");
  EXPECT_EQ(text_of(read_speed(Motor::left)), "E,2\r");
}

TEST(RebLines, ParsesCommandsAsTheBoardReadsThem) {
  EXPECT_EQ(parse_command("D,2,-24"), (Command{'D', {2, -24}}));
  EXPECT_EQ(parse_command("W"), (Command{'W', {}}));
  EXPECT_FALSE(parse_command("d,2,1"));
  EXPECT_FALSE(parse_command("D,2,x"));
  EXPECT_FALSE(parse_command("D2"));
  EXPECT_FALSE(parse_command(""));
}

TEST(RebLines, ParsesReplies) {
  EXPECT_EQ(parse_reply("h,12345"), (Reply{'h', {12345}}));
  EXPECT_EQ(parse_reply("k,1,0,-3"), (Reply{'k', {1, 0, -3}}));
  EXPECT_EQ(parse_reply("y"), (Reply{'y', {}}));
  EXPECT_EQ(parse_reply("w,10,20,30,40,50,60,70,80")->values.size(), 8U);
  EXPECT_FALSE(parse_reply(":"));
  EXPECT_FALSE(parse_reply("H,2"));
  EXPECT_FALSE(parse_reply("h,12a"));
  EXPECT_TRUE(is_prompt(":"));
  EXPECT_TRUE(is_prompt("\x13\xfe:"));  // noise before it
  EXPECT_EQ(find_reply("\x7f\x01h,12", 'h'), (Reply{'h', {12}}));
  EXPECT_EQ(find_reply("hh,-3", 'h'), (Reply{'h', {-3}}));
  EXPECT_FALSE(find_reply("h,1x", 'h'));
  EXPECT_FALSE(find_reply("e,1", 'h'));
  EXPECT_EQ(reply_text({'i', {360}}), "i,360");
  EXPECT_EQ(reply_letter('D'), 'd');
}

TEST(RebLines, RepliesAreCutAtCrLfAndCommandsAtCr) {
  const framing::TerminatedLineFormat replies(reply_line_options());
  const std::string reply = "h,12\r\n:\r\n";
  const auto scan = replies.scan(std::span(reinterpret_cast<const std::uint8_t*>(reply.data()), reply.size()));
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(scan.length, 6U);  // the terminator is part of the telegram
}

TEST(RebParams, TheTwoRowsOfTheTable) {
  EXPECT_EQ(params_for("slow").pulses_per_mm, 24.333022);
  EXPECT_EQ(params_for("fast").pulses_per_mm, 7.9223794);
  EXPECT_EQ(params_for("anything").subclass, "slow");
  EXPECT_EQ(params_for("fast").position_kp, 1200);
  EXPECT_EQ(params_for("slow").ir_poses[3], (std::array<double, 3>{-25, 25, 135}));
}

TEST(RebParams, WheelSpeedsInPulsesPer10ms) {
  const RebParams& slow = params_for("slow");
  EXPECT_EQ(pulses_per_10ms(100.0, slow), 24);
  EXPECT_EQ(motor_speeds(100.0, 0.0, slow), (MotorSpeeds{24, -24}));
  // 90 deg/s: each wheel 109.17 mm/s, the left one backwards.
  EXPECT_EQ(motor_speeds(0.0, 90.0, slow), (MotorSpeeds{-27, -27}));
  // Beyond 700 mm/s the faster wheel is clamped and the other scaled alike.
  const MotorSpeeds fast_turn = motor_speeds(700.0, 90.0, slow);
  EXPECT_EQ(fast_turn.right, -pulses_per_10ms(700.0, slow));
  EXPECT_EQ(fast_turn.left, pulses_per_10ms(700.0 * (700.0 - 109.1703) / (700.0 + 109.1703), slow));
  EXPECT_NEAR(mm_per_s(24, slow), 98.63, 0.01);
}

TEST(RebParams, HeadingControlTurnsTowardsTheHeading) {
  const BodyVelocity on_course = heading_control(200.0, 30.0, 0.0);
  EXPECT_DOUBLE_EQ(on_course.speed_mm_s, 200.0);
  EXPECT_DOUBLE_EQ(on_course.turn_rate_deg_s, 0.0);
  const BodyVelocity off = heading_control(200.0, 30.0, 30.0);
  EXPECT_NEAR(off.speed_mm_s, 200.0 * 5.0 / 6.0, 1e-9);
  EXPECT_NEAR(off.turn_rate_deg_s, 15.0, 1e-9);
  EXPECT_NEAR(heading_control(200.0, 30.0, -90.0).turn_rate_deg_s, -30.0, 1e-9);  // capped
  EXPECT_NEAR(heading_control(200.0, 30.0, 350.0).turn_rate_deg_s, -5.0, 1e-9);   // wrapped
}

TEST(RebParams, BatteryAndPositionMoves) {
  EXPECT_EQ(battery_decivolts(360), 72);  // 7.2 V (1.5 said 7200 "decivolts")
  EXPECT_EQ(battery_reading(7.2), 360);
  const RebParams& slow = params_for("slow");
  EXPECT_EQ(move_pulses(100.0, slow), 2433);
  EXPECT_EQ(turn_pulses(90.0, slow), -2656);  // reb.md: -rint(rad * 69.5 * PulsesPerMM)
}

}  // namespace reb_protocol_test
}  // namespace playerkit::hardware::reb
