// Golden-byte tests of the `simulation` interface (wire-format.md §5 "simulation").

#include "protocol/messages/simulation.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace simulation_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(SimulationData::kWireSize == 1);     // player_simulation_data_t
static_assert(SimulationCommand::kWireSize == 1);  // player_simulation_cmd_t

TEST(SimulationGolden, DataPacket) {
  const SimulationData value{.data = 0xA5};
  const Bytes golden_bytes{0xA5};  // data @0 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"data"}));
  EXPECT_EQ(to_json(value).at("data"), 0xA5);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<SimulationData>(golden::kEmpty, "data", 1, 0));
  EXPECT_TRUE(Rejects<SimulationData>(golden::with_extra_byte(golden_bytes), "", 1, 2));
}

TEST(SimulationGolden, Command) {
  const SimulationCommand value{.cmd = 0x5B};
  EXPECT_TRUE(MatchesGolden(value, Bytes{0x5B}));  // cmd @0 uint8
  EXPECT_TRUE(golden::HasFields(to_json(value), {"cmd"}));
  EXPECT_TRUE(Rejects<SimulationCommand>(golden::kEmpty, "cmd", 1, 0));
  EXPECT_TRUE(Rejects<SimulationCommand>(Bytes{0x5B, 0x00}, "", 1, 2));
}

}  // namespace simulation_test
}  // namespace playerkit::protocol
