// Golden-byte tests of the `speech` interface (wire-format.md §5 "speech").

#include "protocol/messages/speech.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace speech_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(SpeechCommand::kWireSize == 256);  // player_speech_cmd_t

TEST(SpeechGolden, Command) {
  const SpeechCommand value{.string = "Hello, world."};
  const Bytes golden_bytes = WireBytes(256)
                                 .at(0, {'H', 'e', 'l', 'l', 'o', ',', ' ', 'w', 'o', 'r', 'l', 'd', '.'})  // string @0
                                 .zeros(13, 243)  // NUL padding @13..255
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"string"}));
  EXPECT_EQ(j.at("string"), "Hello, world.");
  EXPECT_TRUE(SurvivesJson(value));
}

TEST(SpeechGolden, LongestTextFits255Characters) {
  const std::string text(255, 'x');
  const SpeechCommand value{.string = std::string_view(text)};
  const Bytes golden_bytes = WireBytes(256).text(0, text, 255).at(255, {0x00}).done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_TRUE(SurvivesJson(value));
}

TEST(SpeechGolden, TruncatedOrOversizedIsRejected) {
  const Bytes golden_bytes = WireBytes(256).text(0, "Hello, world.", 256).done();
  EXPECT_TRUE(Rejects<SpeechCommand>(golden::drop_last(golden_bytes), "string", 256, 255));
  EXPECT_TRUE(Rejects<SpeechCommand>(golden::kEmpty, "string", 256, 0));
  EXPECT_TRUE(Rejects<SpeechCommand>(golden::with_extra_byte(golden_bytes), "", 256, 257));
}

}  // namespace speech_test
}  // namespace playerkit::protocol
