// Golden-byte tests of the `idar` interface (wire-format.md §5 "idar").

#include "protocol/messages/idar.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace idar_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(IdarTx::kWireSize == 18);      // idartx_t
static_assert(IdarRx::kWireSize == 29);      // idarrx_t
static_assert(IdarConfig::kWireSize == 19);  // player_idar_config_t

IdarTx five_byte_tx() {
  IdarTx tx{.len = 5, .intensity = 0xC8};
  for (std::size_t i = 0; i < 5; ++i) tx.mesg[i] = static_cast<std::uint8_t>(0xA1 + i);
  return tx;
}

// idartx_t at `at` (18 bytes): mesg @+0 uint8[16], len @+16, intensity @+17.
void put_five_byte_tx(WireBytes& w, std::size_t at) {
  w.at(at, {0xA1, 0xA2, 0xA3, 0xA4, 0xA5})  // mesg[0..4]
      .zeros(at + 5, 11)                    // mesg[5..15]
      .at(at + 16, {0x05})                  // len = 5
      .at(at + 17, {0xC8});                 // intensity
}

TEST(IdarGolden, TransmitMessage) {
  WireBytes w(18);
  put_five_byte_tx(w, 0);
  const Bytes golden_bytes = w.done();
  EXPECT_TRUE(EncodesTo(five_byte_tx(), golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, five_byte_tx()));
  const auto j = to_json(five_byte_tx());
  EXPECT_TRUE(golden::HasFields(j, {"mesg", "len", "intensity"}));
  EXPECT_EQ(j.at("mesg"), (nlohmann::json{0xA1, 0xA2, 0xA3, 0xA4, 0xA5}));
  EXPECT_TRUE(SurvivesJson(five_byte_tx()));
  EXPECT_TRUE(Rejects<IdarTx>(golden::drop_last(golden_bytes), "intensity", 18, 17));
  Bytes bad = golden_bytes;
  bad[16] = 17;  // len @16 = 17 > IDARBUFLEN
  EXPECT_TRUE(Rejects<IdarTx>(bad, "mesg", 16, 17));
}

TEST(IdarGolden, ReceivedMessage) {
  IdarRx rx{.len = 3, .intensity = 0x64, .reflection = 0x01, .timestamp_sec = 0x01020304,
            .timestamp_usec = 0x05060708, .range = 0x090A};
  rx.mesg[0] = 0xB1;
  rx.mesg[1] = 0xB2;
  rx.mesg[2] = 0xB3;
  const Bytes golden_bytes = WireBytes(29)
                                 .at(0, {0xB1, 0xB2, 0xB3})          // mesg[0..2]     @0  uint8
                                 .zeros(3, 13)                       // mesg[3..15]    @3..15
                                 .at(16, {0x03})                     // len            @16 uint8
                                 .at(17, {0x64})                     // intensity      @17 uint8
                                 .at(18, {0x01})                     // reflection     @18 uint8
                                 .at(19, {0x01, 0x02, 0x03, 0x04})   // timestamp_sec  @19 uint32
                                 .at(23, {0x05, 0x06, 0x07, 0x08})   // timestamp_usec @23 uint32
                                 .at(27, {0x09, 0x0A})               // range          @27 uint16
                                 .done();
  EXPECT_TRUE(MatchesGolden(rx, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(rx), {"mesg", "len", "intensity", "reflection", "timestamp_sec",
                                              "timestamp_usec", "range"}));
  EXPECT_TRUE(Rejects<IdarRx>(golden::drop_last(golden_bytes), "range", 29, 28));
  EXPECT_TRUE(Rejects<IdarRx>(golden::with_extra_byte(golden_bytes), "", 29, 30));
}

Bytes config_bytes() {
  WireBytes w(19);
  w.at(0, {0x03});         // instruction @0 uint8 = IDAR_TRANSMIT_RECEIVE (3)
  put_five_byte_tx(w, 1);  // tx @1, 18 bytes: mesg @1, len @17, intensity @18
  return w.done();
}

TEST(IdarGolden, ConfigRequest) {
  const IdarConfig value{.instruction = kIdarTransmitReceive, .tx = five_byte_tx()};
  EXPECT_TRUE(EncodesTo(value, config_bytes()));
  EXPECT_TRUE(DecodesTo(config_bytes(), value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"instruction", "tx"}));
  EXPECT_EQ(j.at("tx").at("len"), 5);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<IdarConfig>(golden::drop_last(config_bytes()), "tx", 19, 18));
  EXPECT_TRUE(Rejects<IdarConfig>(golden::kEmpty, "instruction", 19, 0));
  EXPECT_TRUE(Rejects<IdarConfig>(golden::with_extra_byte(config_bytes()), "", 19, 20));
}

// tx.len counts tx.mesg[16] whether idartx_t stands alone (rejected above) or is
// embedded in the config request.
TEST(IdarGolden, ConfigWithTxLengthLargerThan16IsRejected) {
  Bytes bytes = config_bytes();
  bytes[17] = 17;  // tx.len @1+16 = 17
  EXPECT_THROW((void)decode<IdarConfig>(bytes), DecodeError);
}

}  // namespace idar_test
}  // namespace playerkit::protocol
