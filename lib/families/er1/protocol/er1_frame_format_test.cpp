// The framing of commands (by opcode) and of replies (by what is awaited).
#include "families/er1/protocol/er1_frame_format.hpp"

#include <gtest/gtest.h>

#include "families/er1/protocol/er1_commands.hpp"

namespace playerkit::hardware::er1 {
namespace {

using framing::FrameScan;

TEST(Er1CommandFormat, CutsEachCommandAtTheLengthItsOpcodeGives) {
  const CommandFormat format;
  Bytes stream = set_velocity(Motor::port1, 5);
  EXPECT_EQ(format.scan(stream).kind, FrameScan::Kind::frame);
  EXPECT_EQ(format.scan(stream).length, 8u);
  EXPECT_EQ(format.scan(std::span(stream).first(5)).kind, FrameScan::Kind::need_more);
  // 1.5's ACCL_3, checksum wrong, is still a command.
  const Bytes accl3{0x00, 0xF2, 0x00, 0x90, 0x00, 0x00, 0x00, 0x7A};
  EXPECT_EQ(format.scan(accl3).kind, FrameScan::Kind::frame);
}

TEST(Er1CommandFormat, SkipsWhatCannotStartACommand) {
  const CommandFormat format;
  EXPECT_EQ(format.scan(Bytes{0x07, 0x71, 0x00, 0x8F}).kind, FrameScan::Kind::skip);
  EXPECT_EQ(format.scan(Bytes{0x00, 0x71, 0x05, 0x8F}).kind, FrameScan::Kind::skip);
  EXPECT_EQ(format.scan(Bytes{0x00, 0x71, 0x00, 0x42}).kind, FrameScan::Kind::skip);
}

TEST(Er1ReplyFormat, TakesTheAwaitedLengthWhenItsSumIsZero) {
  ReplyFormat format(6);
  EXPECT_EQ(format.scan(init_reply()).kind, FrameScan::Kind::frame);
  EXPECT_EQ(format.scan(Bytes{0x00, 0xA9, 0x34}).kind, FrameScan::Kind::need_more);
  EXPECT_EQ(format.scan(Bytes{0x00, 0xA8, 0x34, 0x10, 0x00, 0x13}).kind, FrameScan::Kind::bad_checksum);
  format.expect(2);
  EXPECT_EQ(format.scan(Bytes{0x01, 0xFF}).kind, FrameScan::Kind::frame);  // the reset reply of er1.md §1.1
}

}  // namespace
}  // namespace playerkit::hardware::er1
