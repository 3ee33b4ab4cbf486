// Golden-byte tests of the `aio` interface (wire-format.md §5 "aio").

#include "protocol/messages/aio.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace aio_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(AioData::kWireSize == 33);  // player_aio_data_t

AioData three_samples() {
  AioData d{.count = 3};
  d.anin[0] = 0x01020304;
  d.anin[1] = ~0x05060708;
  d.anin[2] = 0x090A0B0C;
  return d;
}

Bytes three_samples_bytes() {
  return WireBytes(33)
      .at(0, {0x03})                    // count   @0 uint8 = 3
      .at(1, {0x01, 0x02, 0x03, 0x04})  // anin[0] @1 int32
      .at(5, {0xFA, 0xF9, 0xF8, 0xF7})  // anin[1] @5 int32 = ~0x05060708
      .at(9, {0x09, 0x0A, 0x0B, 0x0C})  // anin[2] @9 int32
      .zeros(13, 5 * 4)                 // anin[3..7] @13..32
      .done();
}

TEST(AioGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(three_samples(), three_samples_bytes()));
  EXPECT_TRUE(DecodesTo(three_samples_bytes(), three_samples()));
  const auto j = to_json(three_samples());
  EXPECT_TRUE(golden::HasFields(j, {"count", "anin"}));
  EXPECT_EQ(j.at("anin"), (nlohmann::json{0x01020304, -0x05060709, 0x090A0B0C}));
  EXPECT_TRUE(SurvivesJson(three_samples()));
}

TEST(AioGolden, CountAndLengthAreChecked) {
  Bytes bytes = three_samples_bytes();
  bytes[0] = 9;  // count @0 = 9 > PLAYER_AIO_MAX_SAMPLES
  EXPECT_TRUE(Rejects<AioData>(bytes, "anin", 8, 9));
  bytes[0] = 8;
  EXPECT_TRUE(golden::Accepts<AioData>(bytes));
  EXPECT_TRUE(Rejects<AioData>(golden::drop_last(three_samples_bytes()), "anin", 33, 32));
  EXPECT_TRUE(Rejects<AioData>(golden::kEmpty, "count", 33, 0));
  EXPECT_TRUE(Rejects<AioData>(golden::with_extra_byte(three_samples_bytes()), "", 33, 34));
}

}  // namespace aio_test
}  // namespace playerkit::protocol
