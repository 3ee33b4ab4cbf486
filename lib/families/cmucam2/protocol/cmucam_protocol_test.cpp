// The CMUcam2's text, byte for byte as cmucam2.md gives it.

#include "families/cmucam2/protocol/cmucam_protocol.hpp"

#include <gtest/gtest.h>

#include <string>

#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::cmucam2 {
namespace {

std::string text_of(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

TEST(CmucamCommands, AreWordsAndDecimalArgumentsEndedByCr) {
  EXPECT_EQ(text_of(encode(poll_mode(true))), "PM 1\r");  // cmucam2.md §2.1
  EXPECT_EQ(text_of(encode(poll_mode(false))), "PM 0\r");
  // The sheet's example bounds, in the camera's R, G, B order (without 1.5's trailing space).
  const ColorBounds red{200, 240, 16, 60, 16, 60};
  EXPECT_EQ(text_of(encode(track_color(red))), "TC 200 240 16 60 16 60\r");
  EXPECT_EQ(text_of(encode("")), "\r");  // the lone CR: stop streaming, back to idle
  EXPECT_EQ(text_of(encode(set_servo(1, 46))), "SV 1 46\r");
  EXPECT_EQ(text_of(encode(get_servo(0))), "GS 0\r");
  EXPECT_EQ(text_of(encode(get_version())), "GV\r");
}

TEST(CmucamCommands, AreReadAsTheCameraReadsThemSpacesAnywhere) {
  const auto command = parse_command("TC 200 240 16 60 16 60 ");  // 1.5's make_command (§1.1)
  ASSERT_TRUE(command);
  EXPECT_EQ(command->name, "TC");
  EXPECT_EQ(command->arguments, (std::vector<int>{200, 240, 16, 60, 16, 60}));
  EXPECT_EQ(parse_command("pm 1")->name, "PM");
  EXPECT_TRUE(parse_command("GV")->arguments.empty());
  EXPECT_FALSE(parse_command("TC 2x0"));
  EXPECT_FALSE(parse_command("12"));
  EXPECT_FALSE(parse_command(""));
}

TEST(CmucamReplies, AckNckPromptAndTPackets) {
  EXPECT_EQ(classify("ACK"), ReplyLine::ack);
  EXPECT_EQ(classify("NCK"), ReplyLine::nck);
  EXPECT_EQ(classify(":"), ReplyLine::prompt);
  EXPECT_EQ(classify("\x13#ACK"), ReplyLine::ack);  // behind line noise
  EXPECT_EQ(*parse_t_packet("x T 1 2 3 4 5 6 7 8"), (TPacket{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(classify("T 1 2 3 4 5 6 7 8"), ReplyLine::other);
  const auto packet = parse_t_packet("T 45 71 30 60 58 82 42 97");
  ASSERT_TRUE(packet);
  EXPECT_EQ(*packet, (TPacket{45, 71, 30, 60, 58, 82, 42, 97}));
  EXPECT_EQ(t_packet_line(*packet), "T 45 71 30 60 58 82 42 97");
  // The longest packet of an 88 x 143 frame: what follows its 'T', CR
  // included, fits the 33 bytes the 1.5 driver reads into (§6.4).
  EXPECT_LE(t_packet_line({88, 143, 88, 143, 88, 143, 255, 255}).size(), 33u);
  EXPECT_FALSE(parse_t_packet("T 1 2 3 4 5 6 7"));
  EXPECT_FALSE(parse_t_packet("T 1 2 3 4 5 6 7 300"));
  EXPECT_FALSE(parse_t_packet("ACK"));
  EXPECT_EQ(parse_number("128"), 128);
  EXPECT_FALSE(parse_number("ACK"));
}

TEST(CmucamReplies, ThePromptIsATelegramOfItsOwn) {
  const framing::TerminatedLineFormat format(reply_line_options());
  const std::string wire = "ACK\rT 1 2 3 4 5 6 7 8\r:";
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(wire.data()), wire.size());
  const auto first = format.scan(bytes);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 4u);
  const auto last = format.scan(bytes.subspan(wire.size() - 1));
  EXPECT_EQ(last.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(last.length, 1u);
}

TEST(CmucamColors, BoundsAreCheckedAndTheirMiddlePacked) {
  EXPECT_TRUE((ColorBounds{200, 240, 16, 60, 16, 60}.valid()));
  EXPECT_FALSE((ColorBounds{240, 200, 16, 60, 16, 60}.valid()));
  EXPECT_FALSE((ColorBounds{200, 256, 16, 60, 16, 60}.valid()));
  EXPECT_EQ((ColorBounds{200, 240, 16, 60, 16, 60}.packed_middle()), 0xdc2626u);
  EXPECT_TRUE((ColorBounds{200, 240, 16, 60, 16, 60}.contains(220, 30, 30)));
  EXPECT_FALSE((ColorBounds{200, 240, 16, 60, 16, 60}.contains(220, 30, 61)));
}

}  // namespace
}  // namespace playerkit::hardware::cmucam2
