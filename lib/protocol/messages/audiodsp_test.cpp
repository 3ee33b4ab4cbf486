// Golden-byte tests of the `audiodsp` interface (wire-format.md §5 "audiodsp").

#include "protocol/messages/audiodsp.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace audiodsp_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(AudioDspData::kWireSize == 20);     // player_audiodsp_data_t
static_assert(AudioDspCommand::kWireSize == 75);  // player_audiodsp_cmd_t
static_assert(AudioDspConfig::kWireSize == 6);    // player_audiodsp_config_t

TEST(AudioDspGolden, DataPacket) {
  const AudioDspData value{.freq = {0x0102, 0x0304, 0x0506, 0x0708, 0x090A},
                           .amp = {0x1112, 0x1314, 0x1516, 0x1718, 0x191A}};
  const Bytes golden_bytes{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A,   // freq[0..4] @0  uint16
                           0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18, 0x19, 0x1A};  // amp[0..4]  @10 uint16
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"freq", "amp"}));
  EXPECT_EQ(j.at("freq"), (nlohmann::json{0x0102, 0x0304, 0x0506, 0x0708, 0x090A}));
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<AudioDspData>(golden::drop_last(golden_bytes), "amp", 20, 19));
  EXPECT_TRUE(Rejects<AudioDspData>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 9), "freq", 20, 9));
  EXPECT_TRUE(Rejects<AudioDspData>(golden::with_extra_byte(golden_bytes), "", 20, 21));
}

AudioDspCommand chirp() {
  AudioDspCommand c{.subtype = kAudiodspPlayChirp, .frequency = 0x0102, .amplitude = 0x0304, .duration = 0x05060708};
  c.bitString[0] = 0xB1;
  c.bitString[1] = 0xB2;
  c.bitString[2] = 0xB3;
  c.bitStringLen = 3;
  return c;
}

Bytes chirp_bytes() {
  return WireBytes(75)
      .at(0, {0x04})                    // subtype      @0  uint8 = PLAYER_AUDIODSP_PLAY_CHIRP (4)
      .at(1, {0x01, 0x02})              // frequency    @1  uint16
      .at(3, {0x03, 0x04})              // amplitude    @3  uint16
      .at(5, {0x05, 0x06, 0x07, 0x08})  // duration     @5  uint32
      .at(9, {0xB1, 0xB2, 0xB3})        // bitString[0..2] @9 uchar
      .zeros(12, 61)                    // bitString[3..63] @12..72
      .at(73, {0x00, 0x03})             // bitStringLen @73 uint16 = 3
      .done();
}

TEST(AudioDspGolden, ChirpCommand) {
  EXPECT_TRUE(EncodesTo(chirp(), chirp_bytes()));
  EXPECT_TRUE(DecodesTo(chirp_bytes(), chirp()));
  const auto j = to_json(chirp());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "frequency", "amplitude", "duration", "bitString", "bitStringLen"}));
  EXPECT_EQ(j.at("duration"), 0x05060708);
  EXPECT_EQ(j.at("bitString"), (nlohmann::json{0xB1, 0xB2, 0xB3}));
  EXPECT_EQ(j.at("bitStringLen"), 3);
  EXPECT_TRUE(SurvivesJson(chirp()));
}

TEST(AudioDspGolden, CommandLengthAndCountAreChecked) {
  EXPECT_TRUE(Rejects<AudioDspCommand>(golden::drop_last(chirp_bytes()), "bitStringLen", 75, 74));
  EXPECT_TRUE(Rejects<AudioDspCommand>(Bytes(chirp_bytes().size() - 3, 0), "bitString", 75, 72));
  EXPECT_TRUE(Rejects<AudioDspCommand>(golden::with_extra_byte(chirp_bytes()), "", 75, 76));
  Bytes bytes = chirp_bytes();
  bytes[73] = 0x00;
  bytes[74] = 65;  // bitStringLen @73 = 65 > 64 (the count follows its array)
  EXPECT_TRUE(Rejects<AudioDspCommand>(bytes, "bitString", 64, 65));
}

TEST(AudioDspGolden, Config) {
  const AudioDspConfig value{.subtype = kAudiodspSetConfig, .sampleFormat = ~0x0102, .sampleRate = 44100, .channels = 2};
  const Bytes golden_bytes{0x01,        // subtype      @0 uint8 = PLAYER_AUDIODSP_SET_CONFIG (1)
                           0xFE, 0xFD,  // sampleFormat @1 int16 = ~0x0102
                           0xAC, 0x44,  // sampleRate   @3 uint16 = 44100
                           0x02};       // channels     @5 uint8
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "sampleFormat", "sampleRate", "channels"}));
  EXPECT_EQ(j.at("sampleFormat"), -0x0103);
  EXPECT_EQ(j.at("sampleRate"), 44100);
  EXPECT_TRUE(Rejects<AudioDspConfig>(golden::drop_last(golden_bytes), "channels", 6, 5));
  EXPECT_TRUE(Rejects<AudioDspConfig>(golden::with_extra_byte(golden_bytes), "", 6, 7));
}

}  // namespace audiodsp_test
}  // namespace playerkit::protocol
