// Golden-byte tests of the `sound` interface (wire-format.md §5 "sound").

#include "protocol/messages/sound.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace sound_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(SoundCommand::kWireSize == 2);  // player_sound_cmd_t

TEST(SoundGolden, Command) {
  const SoundCommand value{.index = 0x0102};
  const Bytes golden_bytes{0x01, 0x02};  // index @0 uint16
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"index"}));
  EXPECT_EQ(j.at("index"), 0x0102);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<SoundCommand>(Bytes{0x01}, "index", 2, 1));
  EXPECT_TRUE(Rejects<SoundCommand>(golden::kEmpty, "index", 2, 0));
  EXPECT_TRUE(Rejects<SoundCommand>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace sound_test
}  // namespace playerkit::protocol
