// Golden-byte tests of the `dio` interface (wire-format.md §5 "dio").

#include "protocol/messages/dio.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace dio_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(DioData::kWireSize == 5);  // player_dio_data_t

TEST(DioGolden, DataPacket) {
  const DioData value{.count = 0x12, .digin = 0xA1B2C3D4};
  const Bytes golden_bytes{0x12,                     // count @0 uint8
                           0xA1, 0xB2, 0xC3, 0xD4};  // digin @1 uint32 bit field
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"count", "digin"}));
  EXPECT_EQ(j.at("digin"), 0xA1B2C3D4u);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<DioData>(golden::drop_last(golden_bytes), "digin", 5, 4));
  EXPECT_TRUE(Rejects<DioData>(golden::kEmpty, "count", 5, 0));
  EXPECT_TRUE(Rejects<DioData>(golden::with_extra_byte(golden_bytes), "", 5, 6));
}

}  // namespace dio_test
}  // namespace playerkit::protocol
