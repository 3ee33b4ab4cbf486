// Golden-byte tests of the `comms` interface (wire-format.md §5 "comms", §6: a comms
// payload is any number of bytes; player_comms_*_t only names the first one).

#include "protocol/messages/comms.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace comms_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(CommsData::kWireSize == 1);     // player_comms_data_t: names the first byte only
static_assert(CommsCommand::kWireSize == 1);  // player_comms_cmd_t

TEST(CommsGolden, EmptyPayload) {
  const CommsData empty{};
  EXPECT_TRUE(EncodesTo(empty, Bytes{}));
  EXPECT_TRUE(DecodesTo(Bytes{}, empty));
  EXPECT_EQ(to_json(empty), (nlohmann::json{{"msg", nlohmann::json::array()}}));
  EXPECT_TRUE(SurvivesJson(empty));
}

TEST(CommsGolden, OneBytePayload) {
  const CommsData one{.msg = {0xA5}};
  const Bytes golden_bytes{0xA5};  // msg @0 uint8
  EXPECT_TRUE(EncodesTo(one, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, one));
  const auto j = to_json(one);
  EXPECT_TRUE(golden::HasFields(j, {"msg"}));
  EXPECT_EQ(j.at("msg"), (nlohmann::json{0xA5}));
  EXPECT_TRUE(SurvivesJson(one));
}

TEST(CommsGolden, HundredBytePayload) {
  CommsData hundred;
  WireBytes wire(100);
  for (std::size_t i = 0; i < 100; ++i) {
    const auto b = static_cast<std::uint8_t>(0xFF - i);  // msg[i] @i = 0xFF, 0xFE, ... 0x9C
    hundred.msg.push_back(b);
    wire.at(i, {b});
  }
  const Bytes golden_bytes = wire.done();
  EXPECT_EQ(golden_bytes.back(), 0x9C);
  EXPECT_TRUE(EncodesTo(hundred, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, hundred));
  EXPECT_EQ(to_json(hundred).at("msg").size(), 100u);
  EXPECT_TRUE(SurvivesJson(hundred));
}

TEST(CommsGolden, CommandOfAnyLength) {
  const CommsCommand three{.msg = {0x01, 0x02, 0x03}};
  EXPECT_TRUE(EncodesTo(three, Bytes{0x01, 0x02, 0x03}));
  EXPECT_TRUE(DecodesTo(Bytes{0x01, 0x02, 0x03}, three));
  EXPECT_TRUE(DecodesTo(Bytes{}, CommsCommand{}));
  EXPECT_TRUE(SurvivesJson(three));
}

TEST(CommsGolden, PayloadLimitIs8160Bytes) {
  // PLAYER_MAX_MESSAGE_SIZE (8192) minus the 32-byte header.
  const Bytes largest(8160, 0x33);
  EXPECT_TRUE(golden::Accepts<CommsData>(largest));
  EXPECT_TRUE(golden::Accepts<CommsCommand>(largest));
  EXPECT_TRUE(Rejects<CommsData>(golden::with_extra_byte(largest), "", 8160, 8161));
  EXPECT_TRUE(Rejects<CommsCommand>(golden::with_extra_byte(largest), "", 8160, 8161));

  CommsData too_big{.msg = Bytes(8161, 0x33)};
  EXPECT_THROW((void)encode(too_big), EncodeError);
}

}  // namespace comms_test
}  // namespace playerkit::protocol
