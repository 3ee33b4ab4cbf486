#include "framing/terminated_packet_format.hpp"

#include <gtest/gtest.h>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace terminated_packet_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// What a VISCA camera emulator reads: anything a host sends to a camera.
TerminatedPacketFormat host_packets() {
  return TerminatedPacketFormat({.header_mask = 0xF0, .header_value = 0x80, .name = "visca host"});
}

// sonyevid30.md §2.2 replies; the inquiry reply is §2.1's layout with the
// worked example's pan 0xFEF8 and tilt 0x0078.
const Bytes kAck = hex("90 41 FF");
const Bytes kCompletion = hex("90 51 FF");
const Bytes kSyntaxError = hex("90 60 02 FF");
const Bytes kPanTiltReply = hex("90 50 0F 0E 0F 08 00 00 07 08 FF");

TEST(TerminatedPacketFormat, CameraRepliesFromTheSheet) {
  const TerminatedPacketFormat format;
  EXPECT_EQ(format.name(), "visca");
  for (const Bytes& reply : {kAck, kCompletion, kSyntaxError, kPanTiltReply, hex("90 61 04 FF")}) {
    const FrameScan scan = format.scan(reply);
    EXPECT_EQ(scan.kind, Kind::frame);
    EXPECT_EQ(scan.length, reply.size());
  }
  // Back to back as the camera sends an ACK and its completion, at any cut.
  for (const std::size_t piece : {std::size_t{1}, std::size_t{2}, std::size_t{17}}) {
    const Cut result = cut(format, concat({kAck, kCompletion, kPanTiltReply}), piece);
    EXPECT_EQ(result.frames, (std::vector<Bytes>{kAck, kCompletion, kPanTiltReply})) << piece;
    EXPECT_EQ(result.left_over, 0u);
  }
}

TEST(TerminatedPacketFormat, HostCommandsFromTheSheetIncludingBroadcasts) {
  const auto format = host_packets();
  // §2.1: the inquiry, the worked absolute pan/tilt (15 bytes) and zoom
  // examples, a cancel; §6.1: broadcasts address set and IF_Clear.
  const std::vector<Bytes> commands = {hex("81 09 06 12 FF"), hex("81 01 06 02 18 14 0F 0E 0F 08 00 00 07 08 FF"),
                                       hex("81 01 04 47 00 01 07 0B FF"), hex("81 21 FF"), hex("88 30 01 FF"),
                                       hex("88 01 00 01 FF")};
  Bytes stream;
  for (const Bytes& command : commands) stream = concat({stream, command});
  const Cut result = cut(format, stream, 4);
  EXPECT_EQ(result.frames, commands);
  EXPECT_EQ(result.skipped, 0u);
  // A camera's reply is no host command.
  EXPECT_EQ(format.scan(kAck).kind, Kind::skip);
}

TEST(TerminatedPacketFormat, ARepeatedHeaderStartsThePacketAtTheLastOne) {
  // sonyevid30.md §1.1: a message starts at the first 0x90 whose successor is not 0x90.
  const TerminatedPacketFormat format;
  const Cut result = cut(format, concat({hex("90 90"), kAck}));
  EXPECT_EQ(result.frames, std::vector<Bytes>{kAck});
  EXPECT_EQ(result.skipped, 2u);
}

TEST(TerminatedPacketFormat, NoiseAndPacketsThatLostTheirEndAreSkipped) {
  const TerminatedPacketFormat format;
  // Line noise, a broadcast (0x88, not this camera's), a reply cut short, then whole replies.
  const auto stream = concat({hex("00 FF 38 FF"), hex("88 30 02 FF"), hex("90 50 0F 0E"), kCompletion, kPanTiltReply});
  const Cut result = cut(format, stream, 3);
  EXPECT_EQ(result.frames, (std::vector<Bytes>{kCompletion, kPanTiltReply}));
  EXPECT_EQ(result.skipped, 12u);
  EXPECT_EQ(result.left_over, 0u);
}

TEST(TerminatedPacketFormat, AHeaderAndTerminatorAloneAreNoPacket) {
  const TerminatedPacketFormat format;
  EXPECT_EQ(format.scan(hex("90 FF")).kind, Kind::skip);
  EXPECT_EQ(cut(format, concat({hex("90 FF"), kAck})).frames, std::vector<Bytes>{kAck});
}

TEST(TerminatedPacketFormat, APacketWithoutTerminatorIsDroppedAtTheLongestLength) {
  const TerminatedPacketFormat format;
  Bytes endless = {0x90};
  endless.insert(endless.end(), 40, 0x01);
  const Cut result = cut(format, concat({endless, kAck}), 5);
  EXPECT_EQ(result.frames, std::vector<Bytes>{kAck});
  EXPECT_EQ(result.left_over, 0u);
  // Exactly the longest packet passes.
  Bytes longest = {0x81};
  longest.insert(longest.end(), 14, 0x01);
  longest.push_back(0xFF);
  EXPECT_EQ(host_packets().scan(longest).kind, Kind::frame);
  longest.insert(longest.begin() + 1, 0x01);
  EXPECT_EQ(host_packets().scan(longest).kind, Kind::skip);
  // Only noise: nothing waits.
  EXPECT_EQ(cut(format, Bytes(100, 0x01), 8).left_over, 0u);
}

TEST(TerminatedPacketFormat, PartialPacketsWait) {
  const TerminatedPacketFormat format;
  EXPECT_EQ(format.scan({}).kind, Kind::need_more);
  EXPECT_EQ(format.scan(hex("90 50 0F")).kind, Kind::need_more);
}

}  // namespace terminated_packet_format_test
}  // namespace playerkit::framing
