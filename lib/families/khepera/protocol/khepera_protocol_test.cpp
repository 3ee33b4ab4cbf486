#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "families/khepera/protocol/khepera_commands.hpp"
#include "families/khepera/protocol/khepera_units.hpp"

namespace playerkit::hardware::khepera {
namespace {

std::string text(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

// khepera.md §1.1 and §2: the sheet's own examples and every command used.
TEST(KheperaCommands, EncodesTheSheetsBytes) {
  EXPECT_EQ(text(encode_command(set_speed(8, -8))), "D,8,-8\n");
  EXPECT_EQ(text(encode_command(read_speed())), "E\n");
  EXPECT_EQ(text(encode_command(set_position(0, 0))), "G,0,0\n");
  EXPECT_EQ(text(encode_command(read_position())), "H\n");
  EXPECT_EQ(text(encode_command(read_proximity())), "N\n");
  EXPECT_EQ(text(encode_reply({'E', {8, -8}})), "e,8,-8\r\n");
  EXPECT_EQ(text(encode_reply({'d', {}})), "d\r\n");
}

TEST(KheperaCommands, ParsesRepliesToTheirCommand) {
  EXPECT_EQ(parse_reply_to('E', "e,8,-8", 2), (Message{'e', {8, -8}}));
  EXPECT_EQ(parse_reply_to('D', "d\r", 0), (Message{'d', {}}));
  EXPECT_EQ(parse_reply_to('N', "n,1,2,3,4,5,6,7,1023", 8)->values.back(), 1023);
  EXPECT_EQ(parse_reply_to('H', "h,-2147483648,2147483647", 2)->values.front(), -2147483648LL);
  EXPECT_FALSE(parse_reply_to('E', "h,1,2", 2));    // another command's
  EXPECT_FALSE(parse_reply_to('E', "e,1", 2));      // too few values
  EXPECT_FALSE(parse_reply_to('E', "e,1,", 2));     // a trailing comma
  EXPECT_FALSE(parse_reply_to('E', "e,1,x", 2));    // no number
  EXPECT_FALSE(parse_reply_to('E', "e1,2", std::nullopt));
  EXPECT_FALSE(parse_line(""));
  EXPECT_EQ(parse_line("D,+5,-5\n"), (Message{'D', {5, -5}}));
}

TEST(KheperaCommands, FindsARepliesBehindNoise) {
  EXPECT_EQ(find_reply_to('E', "\x93z,e#e,8,-8", 2), (Message{'e', {8, -8}}));
  EXPECT_EQ(find_reply_to('H', "h,1,2", 2), (Message{'h', {1, 2}}));
  EXPECT_FALSE(find_reply_to('E', "xxe,8", 2));
  EXPECT_FALSE(find_reply_to('E', "e,8,-8junk", 2));  // noise after it: no telling what was lost
}

TEST(KheperaUnits, SpeedsAreTheCommandedOnes) {
  const WheelGeometry geometry;
  // 100 mm/s is 1 mm per 10 ms, 12 pulses (1.5 sent trunc(100 / 12) = 8).
  EXPECT_EQ(wheel_speeds(0.1, 0.0, geometry, kFastestWheel), (WheelSpeeds{12, 12}));
  // A turn on the spot: each wheel at omega * 28.5 mm.
  const auto turn = wheel_speeds(0.0, std::numbers::pi / 2, geometry, kFastestWheel);
  EXPECT_EQ(turn, (WheelSpeeds{-5, 5}));
  // Too fast: both wheels shrink together, the arc kept.
  const auto fast = wheel_speeds(2.0, 1.0, geometry, kFastestWheel);
  EXPECT_EQ(fast.right, 127);
  EXPECT_NEAR(static_cast<double>(fast.left) / static_cast<double>(fast.right), (2.0 - 0.0285) / (2.0 + 0.0285), 0.01);
  EXPECT_NEAR(wheel_metres_per_second(12, geometry), 0.1, 1e-12);
}

TEST(KheperaUnits, MotionFromCounters) {
  const WheelGeometry geometry;
  const auto straight = body_motion(1200, 1200, geometry);
  EXPECT_NEAR(straight.distance, 0.1, 1e-12);
  EXPECT_NEAR(straight.turn, 0.0, 1e-12);
  // Right wheel forward: counter-clockwise, positive (1.5 had the sign inverted).
  const auto left_turn = body_motion(-120, 120, geometry);
  EXPECT_NEAR(left_turn.turn, 20.0 / 57.0, 1e-12);
  EXPECT_EQ(counter_step(-2147483648LL, 2147483647LL), 1);
  EXPECT_EQ(counter_step(5, 9), -4);
}

TEST(KheperaUnits, IrCalibrationBothWays) {
  const IrCalibration calibration;
  EXPECT_NEAR(ir_range_mm(1, calibration), 64.158, 1e-9);
  EXPECT_DOUBLE_EQ(ir_range_mm(0, calibration), ir_range_mm(1, calibration));
  EXPECT_EQ(ir_reading(1000.0, calibration), 1);
  EXPECT_EQ(ir_reading(1.0, calibration), 1023);
  const auto reading = ir_reading(40.0, calibration);
  EXPECT_NEAR(ir_range_mm(reading, calibration), 40.0, 0.5);
}

}  // namespace
}  // namespace playerkit::hardware::khepera
