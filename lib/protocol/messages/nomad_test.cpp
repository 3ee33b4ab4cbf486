// Golden-byte tests of the `nomad` interface (wire-format.md §5 "nomad").

#include "protocol/messages/nomad.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace nomad_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(NomadData::kWireSize == 104);    // player_nomad_data_t
static_assert(NomadCommand::kWireSize == 12);  // player_nomad_cmd_t

NomadData sample() {
  NomadData d{.x = 0x01020304,
              .y = ~0x05060708,
              .a = 0x090A0B0C,
              .vel_trans = ~0x11121314,
              .vel_steer = 0x15161718,
              .vel_turret = ~0x191A1B1C};
  for (std::size_t i = 0; i < 16; ++i) {
    d.sonar[i] = static_cast<std::uint16_t>(((0x20 + i) << 8) | (0x80 + i));
    d.ir[i] = static_cast<std::uint16_t>(((0x40 + i) << 8) | (0xC0 + i));
    d.bumper[i] = static_cast<std::uint8_t>(0x60 + i);
  }
  return d;
}

Bytes sample_bytes() {
  WireBytes w(104);
  w.at(0, {0x01, 0x02, 0x03, 0x04})      // x          @0  int32
      .at(4, {0xFA, 0xF9, 0xF8, 0xF7})   // y          @4  int32 = ~0x05060708
      .at(8, {0x09, 0x0A, 0x0B, 0x0C})   // a          @8  int32
      .at(12, {0xEE, 0xED, 0xEC, 0xEB})  // vel_trans  @12 int32 = ~0x11121314
      .at(16, {0x15, 0x16, 0x17, 0x18})  // vel_steer  @16 int32
      .at(20, {0xE6, 0xE5, 0xE4, 0xE3});  // vel_turret @20 int32 = ~0x191A1B1C
  for (std::size_t i = 0; i < 16; ++i) {
    const auto k = static_cast<std::uint8_t>(i);
    w.at(24 + 2 * i, {static_cast<std::uint8_t>(0x20 + k), static_cast<std::uint8_t>(0x80 + k)});  // sonar[i] @24+2i
    w.at(56 + 2 * i, {static_cast<std::uint8_t>(0x40 + k), static_cast<std::uint8_t>(0xC0 + k)});  // ir[i]    @56+2i
    w.at(88 + i, {static_cast<std::uint8_t>(0x60 + k)});                                           // bumper[i] @88+i
  }
  return w.done();
}

TEST(NomadGolden, DataPacket) {
  const Bytes golden_bytes = sample_bytes();
  EXPECT_EQ(golden_bytes[24], 0x20);   // sonar[0] high byte
  EXPECT_EQ(golden_bytes[87], 0xCF);   // ir[15] low byte
  EXPECT_EQ(golden_bytes[103], 0x6F);  // bumper[15]
  EXPECT_TRUE(EncodesTo(sample(), golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, sample()));
  const auto j = to_json(sample());
  EXPECT_TRUE(golden::HasFields(j, {"x", "y", "a", "vel_trans", "vel_steer", "vel_turret", "sonar", "ir", "bumper"}));
  EXPECT_EQ(j.at("vel_turret"), -0x191A1B1D);
  EXPECT_EQ(j.at("sonar").size(), 16u);
  EXPECT_EQ(j.at("ir")[15], 0x4FCF);
  EXPECT_TRUE(SurvivesJson(sample()));
  EXPECT_TRUE(Rejects<NomadData>(golden::drop_last(golden_bytes), "bumper", 104, 103));
  EXPECT_TRUE(Rejects<NomadData>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 60), "ir", 104, 60));
  EXPECT_TRUE(Rejects<NomadData>(golden::kEmpty, "x", 104, 0));
  EXPECT_TRUE(Rejects<NomadData>(golden::with_extra_byte(golden_bytes), "", 104, 105));
}

TEST(NomadGolden, Command) {
  const NomadCommand value{.vel_trans = 0x01020304, .vel_steer = ~0x05060708, .vel_turret = 0x090A0B0C};
  const Bytes golden_bytes{0x01, 0x02, 0x03, 0x04,   // vel_trans  @0 int32
                           0xFA, 0xF9, 0xF8, 0xF7,   // vel_steer  @4 int32 = ~0x05060708
                           0x09, 0x0A, 0x0B, 0x0C};  // vel_turret @8 int32
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"vel_trans", "vel_steer", "vel_turret"}));
  EXPECT_TRUE(Rejects<NomadCommand>(golden::drop_last(golden_bytes), "vel_turret", 12, 11));
  EXPECT_TRUE(Rejects<NomadCommand>(golden::with_extra_byte(golden_bytes), "", 12, 13));
}

}  // namespace nomad_test
}  // namespace playerkit::protocol
