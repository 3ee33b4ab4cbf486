// Golden bytes from er1.md §1.1 and §2: every command of the table, in both
// motor forms, and the replies the author's comments expect.
#include "families/er1/protocol/er1_commands.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::er1 {
namespace {

constexpr Motor m0 = Motor::port0;
constexpr Motor m1 = Motor::port1;

TEST(Er1Commands, MatchTheSheetsTableInBothMotorForms) {
  EXPECT_EQ(init(m0), (Bytes{0x00, 0x71, 0x00, 0x8F}));
  EXPECT_EQ(init(m1), (Bytes{0x01, 0x70, 0x00, 0x8F}));
  EXPECT_EQ(execute(m0), (Bytes{0x00, 0xE6, 0x00, 0x1A}));
  EXPECT_EQ(execute(m1), (Bytes{0x01, 0xE5, 0x00, 0x1A}));
  EXPECT_EQ(read_position(m0), (Bytes{0x00, 0xE3, 0x00, 0x1D}));
  EXPECT_EQ(read_position(m1), (Bytes{0x01, 0xE2, 0x00, 0x1D}));
  EXPECT_EQ(command16(m1, opcode::voltage, 1), (Bytes{0x01, 0x0F, 0x00, 0xEF, 0x00, 0x01}));
}

TEST(Er1Commands, TheResetSequenceIsReset1To7ThenExecute) {
  const std::vector<Bytes> expected{
      {0x00, 0xC7, 0x00, 0x39},
      {0x00, 0x89, 0x00, 0x77, 0x00, 0x00},
      {0x00, 0x80, 0x00, 0x80, 0x00, 0x00},
      {0x00, 0x5F, 0x00, 0xA0, 0x00, 0x01},
      {0x00, 0xEF, 0x00, 0x11, 0x00, 0x00, 0x00, 0x00},
      {0x00, 0x70, 0x00, 0x90, 0x00, 0x00, 0x00, 0x00},
      {0x00, 0x6F, 0x00, 0x91, 0x00, 0x00, 0x00, 0x00},
      {0x00, 0xE6, 0x00, 0x1A},
  };
  EXPECT_EQ(reset_sequence(m0), expected);
  const auto motor1 = reset_sequence(m1);
  ASSERT_EQ(motor1.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    Bytes shifted = expected[i];
    shifted[0] += 1;
    shifted[1] -= 1;
    EXPECT_EQ(motor1[i], shifted) << i;
  }
}

TEST(Er1Commands, TheSpeedSequencesFromStandstillAndWhileMoving) {
  const std::vector<Bytes> from_standstill{
      {0x00, 0xCF, 0x00, 0x31},
      {0x00, 0xC9, 0x00, 0x34, 0x03, 0x00},
      {0x00, 0x94, 0x00, 0x77, 0x65, 0x90},
      {0x00, 0x5F, 0x00, 0xA0, 0x00, 0x01},
      {0x00, 0x8B, 0x00, 0x11, 0xFF, 0xFD, 0x6E, 0xFA},  // the sheet's worked example
      {0x00, 0xF2, 0x00, 0x90, 0x00, 0x00, 0x00, 0x7E},
  };
  EXPECT_EQ(speed_sequence(m0, -168198, true), from_standstill);
  const auto moving = speed_sequence(m1, -168198, false);
  ASSERT_EQ(moving.size(), 4u);
  EXPECT_EQ(moving[1], (Bytes{0x01, 0xC4, 0x00, 0x34, 0x07, 0x00}));
  EXPECT_EQ(moving[2], (Bytes{0x01, 0x8A, 0x00, 0x11, 0xFF, 0xFD, 0x6E, 0xFA}));
}

TEST(Er1Commands, Accl3GoesOutWithItsChecksumRight) {
  const auto sequence = acceleration_sequence(m0);
  ASSERT_EQ(sequence.size(), 3u);
  EXPECT_EQ(sequence[0], (Bytes{0x00, 0xCF, 0x00, 0x31}));
  EXPECT_EQ(sequence[1], (Bytes{0x00, 0xC5, 0x00, 0x34, 0x07, 0x00}));
  // 1.5 sent 00 F2 00 90 00 00 00 7A, whose sum is 0xFC (er1.md §5.2).
  EXPECT_EQ(sequence[2], (Bytes{0x00, 0xF6, 0x00, 0x90, 0x00, 0x00, 0x00, 0x7A}));
  EXPECT_FALSE(sums_to_zero(Bytes{0x00, 0xF2, 0x00, 0x90, 0x00, 0x00, 0x00, 0x7A}));
}

TEST(Er1Commands, TheStopSequence) {
  const auto stop = stop_sequence(m0);
  ASSERT_EQ(stop.size(), 9u);
  EXPECT_EQ(stop[0], (Bytes{0x00, 0xCC, 0x00, 0x34, 0x00, 0x00}));
  EXPECT_EQ(stop[1], (Bytes{0x00, 0x89, 0x00, 0x77, 0x00, 0x00}));
  EXPECT_EQ(stop[2], (Bytes{0x00, 0x5F, 0x00, 0xA0, 0x00, 0x01}));
  EXPECT_EQ(stop[3], (Bytes{0x00, 0x2F, 0x00, 0xD0, 0x00, 0x01}));
  EXPECT_EQ(stop[4], reset_sequence(m0)[4]);
  EXPECT_EQ(stop[7], execute(m0));
  EXPECT_EQ(stop[8], (Bytes{0x00, 0xC7, 0x00, 0x39}));
  EXPECT_EQ(stop_sequence(m1)[3], (Bytes{0x01, 0x2E, 0x00, 0xD0, 0x00, 0x01}));
}

TEST(Er1Commands, LengthsByOpcode) {
  for (const int op : {0x8F, 0x39, 0x1A, 0x1D, 0x31}) EXPECT_EQ(command_length(static_cast<std::uint8_t>(op)), 4u) << op;
  for (const int op : {0x77, 0x80, 0xA0, 0x34, 0xD0, 0xEF}) EXPECT_EQ(command_length(static_cast<std::uint8_t>(op)), 6u) << op;
  for (const int op : {0x11, 0x90, 0x91}) EXPECT_EQ(command_length(static_cast<std::uint8_t>(op)), 8u) << op;
  EXPECT_EQ(command_length(0x42), 0u);
  EXPECT_EQ(reply_length(opcode::init), 6u);
  EXPECT_EQ(reply_length(opcode::read_position), 6u);
  EXPECT_EQ(reply_length(opcode::read_status), 4u);
  EXPECT_EQ(reply_length(opcode::voltage), 4u);
  EXPECT_EQ(reply_length(opcode::execute), 2u);
}

TEST(Er1Units, SpeedRegisterIsTruncatedCentimetresTimes16819_8) {
  EXPECT_EQ(speed_register(100.0), 168198);
  EXPECT_EQ(speed_register(-100.0), -168198);
  EXPECT_EQ(speed_register(0.1), 168);  // 168.198 truncated
  EXPECT_NEAR(millimetres_per_second(168198), 100.0, 1e-9);
  EXPECT_EQ(speed_register(1e12), 2147483647);
}

TEST(Er1Replies, BalanceTheirSumAndCarryTheCountBigEndian) {
  EXPECT_EQ(init_reply(), (Bytes{0x00, 0xA9, 0x34, 0x10, 0x00, 0x13}));
  EXPECT_EQ(reply(0, {}), (Bytes{0x00, 0x00}));
  const Bytes count = position_reply(-2);
  EXPECT_TRUE(sums_to_zero(count));
  EXPECT_EQ(position_count(count), -2);
  EXPECT_EQ(position_count(Bytes{0x00, 0x00, 0x12, 0x34, 0x56, 0x78}), 0x12345678);
  EXPECT_FALSE(position_count(Bytes{0x00, 0x00}));
}

}  // namespace
}  // namespace playerkit::hardware::er1
