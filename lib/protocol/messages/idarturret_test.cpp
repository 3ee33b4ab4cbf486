// Golden-byte tests of the `idarturret` interface (wire-format.md §5 "idarturret").

// idarturret.hpp uses IdarRx/IdarTx but does not include idar.hpp (not self-contained;
// reported), so idar.hpp must come first for this file to compile.
#include "protocol/messages/idar.hpp"
#include "protocol/messages/idarturret.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace idarturret_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(IdarTurretReply::kWireSize == 232);   // player_idarturret_reply_t: 8 × 29
static_assert(IdarTurretConfig::kWireSize == 145);  // player_idarturret_config_t: 1 + 8 × 18

IdarTurretReply two_receptions() {
  IdarTurretReply r;
  r.rx[0] = {.len = 3, .intensity = 0x64, .reflection = 0x01, .timestamp_sec = 0x01020304,
             .timestamp_usec = 0x05060708, .range = 0x090A};
  r.rx[0].mesg[0] = 0xB1;
  r.rx[0].mesg[1] = 0xB2;
  r.rx[0].mesg[2] = 0xB3;
  r.rx[7] = {.len = 1, .intensity = 0x11, .reflection = 0x00, .timestamp_sec = 0x11121314,
             .timestamp_usec = 0x15161718, .range = 0x191A};
  r.rx[7].mesg[0] = 0xC1;
  return r;
}

// idarrx_t is 29 bytes: mesg @+0 [16], len @+16, intensity @+17, reflection @+18,
// timestamp_sec @+19, timestamp_usec @+23, range @+27.
Bytes two_receptions_bytes() {
  return WireBytes(232)
      // rx[0] @0
      .at(0, {0xB1, 0xB2, 0xB3})
      .zeros(3, 13)
      .at(16, {0x03, 0x64, 0x01})                                  // len, intensity, reflection
      .at(19, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08})   // timestamp_sec, timestamp_usec
      .at(27, {0x09, 0x0A})                                        // range
      .zeros(29, 6 * 29)                                           // rx[1..6] @29..202
      // rx[7] @203
      .at(203, {0xC1})
      .zeros(204, 15)
      .at(219, {0x01, 0x11, 0x00})                                 // len @219, intensity, reflection
      .at(222, {0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18})  // timestamp_sec @222, timestamp_usec @226
      .at(230, {0x19, 0x1A})                                       // range @230
      .done();
}

TEST(IdarTurretGolden, Reply) {
  EXPECT_TRUE(EncodesTo(two_receptions(), two_receptions_bytes()));
  EXPECT_TRUE(DecodesTo(two_receptions_bytes(), two_receptions()));
  const auto j = to_json(two_receptions());
  EXPECT_TRUE(golden::HasFields(j, {"rx"}));
  ASSERT_EQ(j.at("rx").size(), 8u);
  EXPECT_EQ(j.at("rx")[7].at("range"), 0x191A);
  EXPECT_EQ(j.at("rx")[0].at("mesg"), (nlohmann::json{0xB1, 0xB2, 0xB3}));
  EXPECT_TRUE(SurvivesJson(two_receptions()));
  EXPECT_TRUE(Rejects<IdarTurretReply>(golden::drop_last(two_receptions_bytes()), "rx", 232, 231));
  EXPECT_TRUE(Rejects<IdarTurretReply>(golden::with_extra_byte(two_receptions_bytes()), "", 232, 233));
}

// Each rx[i].len counts rx[i].mesg[16]; a decoded reply must not claim 17 bytes.
TEST(IdarTurretGolden, ReplyWithMessageLengthLargerThan16IsRejected) {
  Bytes bytes = two_receptions_bytes();
  bytes[219] = 17;  // rx[7].len @203+16 = 17
  EXPECT_THROW((void)decode<IdarTurretReply>(bytes), DecodeError);
}

IdarTurretConfig two_transmissions() {
  IdarTurretConfig c{.instruction = kIdarTransmit};
  c.tx[0] = {.len = 2, .intensity = 0xC8};
  c.tx[0].mesg[0] = 0xA1;
  c.tx[0].mesg[1] = 0xA2;
  c.tx[7] = {.len = 16, .intensity = 0x7F};
  for (std::size_t i = 0; i < 16; ++i) c.tx[7].mesg[i] = static_cast<std::uint8_t>(0xE0 + i);
  return c;
}

Bytes two_transmissions_bytes() {
  WireBytes w(145);
  w.at(0, {0x00})              // instruction @0 uint8 = IDAR_TRANSMIT (0)
      .at(1, {0xA1, 0xA2})     // tx[0] @1: mesg[0..1]
      .zeros(3, 14)            //        mesg[2..15] @3..16
      .at(17, {0x02, 0xC8})    //        len @17, intensity @18
      .zeros(19, 6 * 18);      // tx[1..6] @19..126
  for (std::size_t i = 0; i < 16; ++i) {
    w.at(127 + i, {static_cast<std::uint8_t>(0xE0 + i)});  // tx[7] @127: mesg[i] = 0xE0 + i
  }
  w.at(143, {0x10, 0x7F});  // tx[7].len @143 = 16, intensity @144
  return w.done();
}

TEST(IdarTurretGolden, Config) {
  EXPECT_TRUE(EncodesTo(two_transmissions(), two_transmissions_bytes()));
  EXPECT_TRUE(DecodesTo(two_transmissions_bytes(), two_transmissions()));
  const auto j = to_json(two_transmissions());
  EXPECT_TRUE(golden::HasFields(j, {"instruction", "tx"}));
  ASSERT_EQ(j.at("tx").size(), 8u);
  EXPECT_EQ(j.at("tx")[7].at("mesg").size(), 16u);
  EXPECT_TRUE(SurvivesJson(two_transmissions()));
  EXPECT_TRUE(Rejects<IdarTurretConfig>(golden::drop_last(two_transmissions_bytes()), "tx", 145, 144));
  EXPECT_TRUE(Rejects<IdarTurretConfig>(golden::kEmpty, "instruction", 145, 0));
  EXPECT_TRUE(Rejects<IdarTurretConfig>(golden::with_extra_byte(two_transmissions_bytes()), "", 145, 146));
}

}  // namespace idarturret_test
}  // namespace playerkit::protocol
