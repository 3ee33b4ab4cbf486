// Golden-byte tests of the `audio` interface (wire-format.md §5 "audio").

#include "protocol/messages/audio.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace audio_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(AudioData::kWireSize == 20);    // player_audio_data_t
static_assert(AudioCommand::kWireSize == 6);  // player_audio_cmd_t

const AudioData kData{.frequency0 = 0x0102,
                      .amplitude0 = 0x0304,
                      .frequency1 = 0x0506,
                      .amplitude1 = 0x0708,
                      .frequency2 = 0x090A,
                      .amplitude2 = 0x0B0C,
                      .frequency3 = 0x0D0E,
                      .amplitude3 = 0x0F10,
                      .frequency4 = 0x1112,
                      .amplitude4 = 0x1314};
const Bytes kDataBytes{0x01, 0x02,   // frequency0 @0  uint16
                       0x03, 0x04,   // amplitude0 @2  uint16
                       0x05, 0x06,   // frequency1 @4
                       0x07, 0x08,   // amplitude1 @6
                       0x09, 0x0A,   // frequency2 @8
                       0x0B, 0x0C,   // amplitude2 @10
                       0x0D, 0x0E,   // frequency3 @12
                       0x0F, 0x10,   // amplitude3 @14
                       0x11, 0x12,   // frequency4 @16
                       0x13, 0x14};  // amplitude4 @18

TEST(AudioGolden, DataPacket) {
  ASSERT_EQ(kDataBytes.size(), 20u);
  EXPECT_TRUE(EncodesTo(kData, kDataBytes));
  EXPECT_TRUE(DecodesTo(kDataBytes, kData));
  const auto j = to_json(kData);
  EXPECT_TRUE(golden::HasFields(j, {"frequency0", "amplitude0", "frequency1", "amplitude1", "frequency2",
                                    "amplitude2", "frequency3", "amplitude3", "frequency4", "amplitude4"}));
  EXPECT_EQ(j.at("frequency0"), 0x0102);
  EXPECT_EQ(j.at("amplitude4"), 0x1314);
  EXPECT_TRUE(SurvivesJson(kData));
  EXPECT_TRUE(Rejects<AudioData>(golden::drop_last(kDataBytes), "amplitude4", 20, 19));
  EXPECT_TRUE(Rejects<AudioData>(golden::kEmpty, "frequency0", 20, 0));
  EXPECT_TRUE(Rejects<AudioData>(golden::with_extra_byte(kDataBytes), "", 20, 21));
}

TEST(AudioGolden, Command) {
  const AudioCommand value{.frequency = 0x0102, .amplitude = 0x0304, .duration = 0x0506};
  const Bytes golden_bytes{0x01, 0x02,   // frequency @0 uint16
                           0x03, 0x04,   // amplitude @2 uint16
                           0x05, 0x06};  // duration  @4 uint16
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"frequency", "amplitude", "duration"}));
  EXPECT_TRUE(Rejects<AudioCommand>(golden::drop_last(golden_bytes), "duration", 6, 5));
  EXPECT_TRUE(Rejects<AudioCommand>(golden::with_extra_byte(golden_bytes), "", 6, 7));
}

}  // namespace audio_test
}  // namespace playerkit::protocol
