// Golden-byte tests of the `audiomixer` interface (wire-format.md §5 "audiomixer").

#include "protocol/messages/audiomixer.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace audiomixer_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(AudioMixerConfig::kWireSize == 21);   // player_audiomixer_config_t
static_assert(AudioMixerCommand::kWireSize == 5);   // player_audiomixer_cmd_t

TEST(AudioMixerGolden, ConfigReply) {
  const AudioMixerConfig value{.subtype = 0x01,
                               .masterLeft = 0x0102,
                               .masterRight = 0x0304,
                               .pcmLeft = 0x0506,
                               .pcmRight = 0x0708,
                               .lineLeft = 0x090A,
                               .lineRight = 0x0B0C,
                               .micLeft = 0x0D0E,
                               .micRight = 0x0F10,
                               .iGain = 0x1112,
                               .oGain = 0x1314};
  const Bytes golden_bytes{0x01,         // subtype     @0  uint8
                           0x01, 0x02,   // masterLeft  @1  uint16
                           0x03, 0x04,   // masterRight @3
                           0x05, 0x06,   // pcmLeft     @5
                           0x07, 0x08,   // pcmRight    @7
                           0x09, 0x0A,   // lineLeft    @9
                           0x0B, 0x0C,   // lineRight   @11
                           0x0D, 0x0E,   // micLeft     @13
                           0x0F, 0x10,   // micRight    @15
                           0x11, 0x12,   // iGain       @17
                           0x13, 0x14};  // oGain       @19
  ASSERT_EQ(golden_bytes.size(), 21u);
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "masterLeft", "masterRight", "pcmLeft", "pcmRight", "lineLeft",
                                    "lineRight", "micLeft", "micRight", "iGain", "oGain"}));
  EXPECT_EQ(j.at("masterLeft"), 0x0102);
  EXPECT_EQ(j.at("oGain"), 0x1314);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<AudioMixerConfig>(golden::drop_last(golden_bytes), "oGain", 21, 20));
  EXPECT_TRUE(Rejects<AudioMixerConfig>(golden::kEmpty, "subtype", 21, 0));
  EXPECT_TRUE(Rejects<AudioMixerConfig>(golden::with_extra_byte(golden_bytes), "", 21, 22));
}

TEST(AudioMixerGolden, Command) {
  const AudioMixerCommand value{.subtype = kAudiomixerSetMic, .left = 0x0102, .right = 0x0304};
  const Bytes golden_bytes{0x04,         // subtype @0 uint8 = PLAYER_AUDIOMIXER_SET_MIC (4)
                           0x01, 0x02,   // left    @1 uint16
                           0x03, 0x04};  // right   @3 uint16
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "left", "right"}));
  EXPECT_TRUE(Rejects<AudioMixerCommand>(golden::drop_last(golden_bytes), "right", 5, 4));
  EXPECT_TRUE(Rejects<AudioMixerCommand>(golden::with_extra_byte(golden_bytes), "", 5, 6));
}

}  // namespace audiomixer_test
}  // namespace playerkit::protocol
