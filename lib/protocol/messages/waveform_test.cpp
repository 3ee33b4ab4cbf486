// Golden-byte tests of the `waveform` interface (wire-format.md §5 "waveform").

#include "protocol/messages/waveform.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace waveform_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(WaveformData::kWireSize == 4106);  // player_waveform_data_t

WaveformData five_samples() {
  WaveformData d{.rate = 0x01020304, .depth = 0x0506, .samples = 5};
  for (std::size_t i = 0; i < 5; ++i) d.data[i] = static_cast<std::uint8_t>(0xD1 + i);
  return d;
}

Bytes five_samples_bytes() {
  return WireBytes(4106)
      .at(0, {0x01, 0x02, 0x03, 0x04})        // rate    @0  uint32
      .at(4, {0x05, 0x06})                    // depth   @4  uint16
      .at(6, {0x00, 0x00, 0x00, 0x05})        // samples @6  uint32 = 5
      .at(10, {0xD1, 0xD2, 0xD3, 0xD4, 0xD5})  // data[0..4] @10 uint8
      .zeros(15, 4091)                        // data[5..4095] @15..4105
      .done();
}

TEST(WaveformGolden, DataPacketIsTheFull4106Bytes) {
  EXPECT_TRUE(EncodesTo(five_samples(), five_samples_bytes()));
  EXPECT_TRUE(DecodesTo(five_samples_bytes(), five_samples()));
}

TEST(WaveformGolden, DataJsonShowsOnlyTheCountedSamples) {
  const auto j = to_json(five_samples());
  EXPECT_TRUE(golden::HasFields(j, {"rate", "depth", "samples", "data"}));
  EXPECT_EQ(j.at("rate"), 0x01020304);
  EXPECT_EQ(j.at("samples"), 5);
  EXPECT_EQ(j.at("data"), (nlohmann::json{0xD1, 0xD2, 0xD3, 0xD4, 0xD5}));
  EXPECT_TRUE(SurvivesJson(five_samples()));
}

TEST(WaveformGolden, SampleCountIsChecked) {
  Bytes bytes = five_samples_bytes();
  bytes[8] = 0x10;
  bytes[9] = 0x01;  // samples @6 = 0x00001001 = 4097
  EXPECT_TRUE(Rejects<WaveformData>(bytes, "data", 4096, 4097));
  bytes[9] = 0x00;  // 4096: a full buffer
  EXPECT_TRUE(golden::Accepts<WaveformData>(bytes));
}

TEST(WaveformGolden, TruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<WaveformData>(golden::drop_last(five_samples_bytes()), "data", 4106, 4105));
  EXPECT_TRUE(Rejects<WaveformData>(golden::kEmpty, "rate", 4106, 0));
  EXPECT_TRUE(Rejects<WaveformData>(Bytes{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x00}, "samples", 4106, 7));
  EXPECT_TRUE(Rejects<WaveformData>(golden::with_extra_byte(five_samples_bytes()), "", 4106, 4107));
}

}  // namespace waveform_test
}  // namespace playerkit::protocol
