#include "families/flockofbirds/protocol/bird_commands.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "framing/fixed_length_format.hpp"

namespace playerkit::hardware::flockofbirds {
namespace bird_commands_test {

using Bytes = std::vector<std::uint8_t>;

// flockofbirds.md §2.1: what the reference driver sends.
TEST(BirdCommands, TheBytesOfTheSheet) {
  EXPECT_EQ(command(CommandByte::position_angles), Bytes{0x59});
  EXPECT_EQ(command(CommandByte::point), Bytes{0x42});
  EXPECT_EQ(command(CommandByte::stream), Bytes{0x40});
  EXPECT_EQ(examine_position_scaling(), (Bytes{0x4F, 0x03}));
  EXPECT_EQ(change_position_scaling(PositionScaling::inches_72), (Bytes{0x50, 0x03, 0x01, 0x00}));
  EXPECT_EQ(change_position_scaling(PositionScaling::inches_36), (Bytes{0x50, 0x03, 0x00, 0x00}));
}

TEST(BirdCommands, TheScalingAnswer) {
  EXPECT_EQ(scaling_from_reply(scaling_reply(PositionScaling::inches_36)), PositionScaling::inches_36);
  EXPECT_EQ(scaling_from_reply(scaling_reply(PositionScaling::inches_72)), PositionScaling::inches_72);
  EXPECT_EQ(scaling_reply(PositionScaling::inches_72), (std::array<std::uint8_t, 2>{0x01, 0x00}));
  EXPECT_EQ(scaling_from_reply(Bytes{0x02, 0x00}), std::nullopt);
  EXPECT_EQ(scaling_from_reply(Bytes{0x00, 0x01}), std::nullopt);
  EXPECT_EQ(scaling_from_reply(Bytes{0x00}), std::nullopt);
  const framing::FixedLengthFormat format(scaling_reply_format_options());
  EXPECT_EQ(format.scan(Bytes{0x01, 0x00}).kind, framing::FrameScan::Kind::frame);
  EXPECT_NE(format.scan(Bytes{0xAA, 0x00}).kind, framing::FrameScan::Kind::frame);
}

TEST(BirdCommands, TheBirdReadsCommandsWithTheirParametersHoweverCut) {
  const Bytes stream{0x59, 0x42, 0x4F, 0x03, 0x50, 0x03, 0x01, 0x00, 0x40, 0x7A};
  const std::vector<BirdCommand> expected{
      {.byte = CommandByte::position_angles, .raw = 0x59, .parameter = 0, .value = {}},
      {.byte = CommandByte::point, .raw = 0x42, .parameter = 0, .value = {}},
      {.byte = CommandByte::examine_value, .raw = 0x4F, .parameter = 3, .value = {}},
      {.byte = CommandByte::change_value, .raw = 0x50, .parameter = 3, .value = {0x01, 0x00}},
      {.byte = CommandByte::stream, .raw = 0x40, .parameter = 0, .value = {}},
      {.byte = static_cast<CommandByte>(0x7A), .raw = 0x7A, .parameter = 0, .value = {}},
  };
  CommandReader whole;
  EXPECT_EQ(whole.feed(stream), expected);
  CommandReader byte_by_byte;
  std::vector<BirdCommand> got;
  for (const std::uint8_t byte : stream) {
    for (auto& c : byte_by_byte.feed(std::span(&byte, 1))) got.push_back(std::move(c));
  }
  EXPECT_EQ(got, expected);
}

TEST(BirdCommands, AResetForgetsAHalfReceivedCommand) {
  CommandReader reader;
  EXPECT_TRUE(reader.feed(Bytes{0x50, 0x03}).empty());
  reader.reset();
  const auto commands = reader.feed(Bytes{0x42});
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].byte, CommandByte::point);
}

}  // namespace bird_commands_test
}  // namespace playerkit::hardware::flockofbirds
