// Golden-byte tests of the message header (wire-format.md §3.2, §4).

#include "protocol/messages/header.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace header_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(MessageHeader::kWireSize == 32);  // player_msghdr_t — 32 bytes

// The worked example of §4: the SYNCH ending a data round sent at 1086000000.250000 s.
TEST(HeaderGolden, SynchExampleOfTheSpec) {
  const Bytes spec_example{0x58, 0x78,              // stx            @0   0x5878 "Xx"
                           0x00, 0x05,              // type           @2   5 = SYNCH
                           0x00, 0x01,              // device         @4   1 = player
                           0x00, 0x00,              // device_index   @6   0
                           0x40, 0xBB, 0x0B, 0x80,  // time_sec       @8   1086000000
                           0x00, 0x03, 0xD0, 0x90,  // time_usec      @12  250000
                           0x40, 0xBB, 0x0B, 0x80,  // timestamp_sec  @16  1086000000
                           0x00, 0x03, 0xD0, 0x90,  // timestamp_usec @20  250000
                           0x00, 0x00, 0x00, 0x00,  // reserved       @24  0 on TCP
                           0x00, 0x00, 0x00, 0x00};  // size          @28  0
  const MessageHeader synch{.stx = 0x5878,
                            .type = 5,
                            .device = 1,
                            .device_index = 0,
                            .time_sec = 1086000000,
                            .time_usec = 250000,
                            .timestamp_sec = 1086000000,
                            .timestamp_usec = 250000,
                            .reserved = 0,
                            .size = 0};
  ASSERT_EQ(spec_example.size(), 32u);
  EXPECT_TRUE(EncodesTo(synch, spec_example));
  EXPECT_TRUE(DecodesTo(spec_example, synch));
  EXPECT_TRUE(SurvivesJson(synch));
}

MessageHeader distinctive_header() {
  return {.stx = 0x5878,
          .type = 0x0304,
          .device = 0x0506,
          .device_index = 0x0708,
          .time_sec = 0x11121314,
          .time_usec = 0x21222324,
          .timestamp_sec = 0x31323334,
          .timestamp_usec = 0x41424344,
          .reserved = 0x51525354,
          .size = 0x61626364};
}

Bytes distinctive_header_bytes() {
  return WireBytes(32)
      .at(0, {0x58, 0x78})              // stx            @0  uint16
      .at(2, {0x03, 0x04})              // type           @2  uint16
      .at(4, {0x05, 0x06})              // device         @4  uint16
      .at(6, {0x07, 0x08})              // device_index   @6  uint16
      .at(8, {0x11, 0x12, 0x13, 0x14})  // time_sec       @8  uint32
      .at(12, {0x21, 0x22, 0x23, 0x24})  // time_usec     @12 uint32
      .at(16, {0x31, 0x32, 0x33, 0x34})  // timestamp_sec @16 uint32
      .at(20, {0x41, 0x42, 0x43, 0x44})  // timestamp_usec @20 uint32
      .at(24, {0x51, 0x52, 0x53, 0x54})  // reserved      @24 uint32
      .at(28, {0x61, 0x62, 0x63, 0x64})  // size          @28 uint32
      .done();
}

TEST(HeaderGolden, EveryFieldAtItsSpecOffsetBigEndian) {
  EXPECT_TRUE(EncodesTo(distinctive_header(), distinctive_header_bytes()));
  EXPECT_TRUE(DecodesTo(distinctive_header_bytes(), distinctive_header()));
}

TEST(HeaderGolden, UdpClientIdSitsInBytes26And27) {
  // §3.2: the UDP client id is the second half of `reserved`, a big-endian uint16.
  MessageHeader h{.stx = 0x5878, .type = 3, .device = 1, .reserved = 0x0203};
  const Bytes bytes = encode(h);
  ASSERT_EQ(bytes.size(), 32u);
  EXPECT_EQ(bytes[24], 0x00);
  EXPECT_EQ(bytes[25], 0x00);
  EXPECT_EQ(bytes[26], 0x02);
  EXPECT_EQ(bytes[27], 0x03);
}

TEST(HeaderGolden, JsonUsesTheSpecFieldNames) {
  const auto j = to_json(distinctive_header());
  EXPECT_TRUE(golden::HasFields(j, {"stx", "type", "device", "device_index", "time_sec", "time_usec",
                                    "timestamp_sec", "timestamp_usec", "reserved", "size"}));
  EXPECT_EQ(j.at("stx"), 0x5878);
  EXPECT_EQ(j.at("device_index"), 0x0708);
  EXPECT_EQ(j.at("size"), 0x61626364);
  EXPECT_TRUE(SurvivesJson(distinctive_header()));
}

TEST(HeaderGolden, TruncatedOrOversizedHeaderIsRejected) {
  const Bytes golden_bytes = distinctive_header_bytes();
  EXPECT_TRUE(Rejects<MessageHeader>(golden::drop_last(golden_bytes), "size", 32, 31));
  EXPECT_TRUE(Rejects<MessageHeader>(golden::kEmpty, "stx", 32, 0));
  EXPECT_TRUE(Rejects<MessageHeader>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 27), "reserved", 32, 27));
  EXPECT_TRUE(Rejects<MessageHeader>(golden::with_extra_byte(golden_bytes), "", 32, 33));
}

}  // namespace header_test
}  // namespace playerkit::protocol
