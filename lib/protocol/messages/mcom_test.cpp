// Golden-byte tests of the `mcom` interface (wire-format.md §5 "mcom").

#include "protocol/messages/mcom.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace mcom_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(McomData::kWireSize == 129);    // player_mcom_data_t
static_assert(McomConfig::kWireSize == 140);  // player_mcom_config_t (= MCOM_COMMAND_BUFFER_SIZE)
static_assert(McomReturn::kWireSize == 139);  // player_mcom_return_t
static_assert(kMcomCommandBufferSize == 140);

const McomData kHello{.full = 0x01, .data = "hello"};

TEST(McomGolden, DataSlot) {
  const Bytes golden_bytes = WireBytes(129)
                                 .at(0, {0x01})          // full @0 char
                                 .text(1, "hello", 128)  // data @1 char[128]
                                 .done();
  EXPECT_TRUE(MatchesGolden(kHello, golden_bytes));
  const auto j = to_json(kHello);
  EXPECT_TRUE(golden::HasFields(j, {"full", "data"}));
  EXPECT_EQ(j.at("data"), "hello");
  EXPECT_TRUE(Rejects<McomData>(golden::drop_last(golden_bytes), "data", 129, 128));
  EXPECT_TRUE(Rejects<McomData>(golden::kEmpty, "full", 129, 0));
}

TEST(McomGolden, ConfigRequest) {
  const McomConfig value{.command = kMcomReadReq, .type = 0x0102, .channel = "chan", .data = kHello};
  const Bytes golden_bytes = WireBytes(140)
                                 .at(0, {0x02})           // command      @0  uint8 = PLAYER_MCOM_READ_REQ (2)
                                 .at(1, {0x01, 0x02})     // type         @1  uint16
                                 .text(3, "chan", 8)      // channel      @3  char[8]
                                 .at(11, {0x01})          // data.full    @11 char
                                 .text(12, "hello", 128)  // data.data    @12 char[128]
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"command", "type", "channel", "data"}));
  EXPECT_EQ(j.at("channel"), "chan");
  EXPECT_EQ(j.at("data").at("data"), "hello");
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<McomConfig>(golden::drop_last(golden_bytes), "data", 140, 139));
  EXPECT_TRUE(Rejects<McomConfig>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 10), "channel", 140, 10));
  EXPECT_TRUE(Rejects<McomConfig>(golden::with_extra_byte(golden_bytes), "", 140, 141));
}

TEST(McomGolden, Return) {
  const McomReturn value{.type = 0x0304, .channel = "robots", .data = kHello};
  const Bytes golden_bytes = WireBytes(139)
                                 .at(0, {0x03, 0x04})     // type      @0  uint16
                                 .text(2, "robots", 8)    // channel   @2  char[8]
                                 .at(10, {0x01})          // data.full @10 char
                                 .text(11, "hello", 128)  // data.data @11 char[128]
                                 .done();
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"type", "channel", "data"}));
  EXPECT_TRUE(Rejects<McomReturn>(golden::drop_last(golden_bytes), "data", 139, 138));
  EXPECT_TRUE(Rejects<McomReturn>(golden::with_extra_byte(golden_bytes), "", 139, 140));
}

// data[128] is "message bytes" (wire-format.md), not necessarily text: the codec
// keeps bytes after a NUL on the wire, and the JSON codec promises that any byte
// sequence of a text field survives a round trip.
// mcom data is text (lifomcom stores C strings): JSON carries it up to the first
// NUL, and what follows a NUL is padding, as for every text field.
TEST(McomGolden, MessageTextEndsAtTheFirstNulInJson) {
  const Bytes bytes = WireBytes(129)
                          .at(0, {0x01})                   // full @0
                          .at(1, {'a', 0x00, 'b', 0xFF})   // data @1: 'a' NUL 'b' 0xFF
                          .zeros(5, 124)
                          .done();
  const McomData decoded = decode<McomData>(bytes);
  EXPECT_TRUE(EncodesTo(decoded, bytes));
  const auto j = to_json(decoded);
  EXPECT_EQ(j.at("data"), "a");
  const Bytes reencoded = encode(from_json<McomData>(j));
  EXPECT_EQ(reencoded, (WireBytes(129).at(0, {0x01}).at(1, {'a'}).zeros(2, 127).done()));
}

}  // namespace mcom_test
}  // namespace playerkit::protocol
