// The reb family as the tools see it: its emulator kind, its probe against
// the emulated board on a pseudo-terminal, its trace framing.

#include "families/reb/reb_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::families {
namespace reb_family_test {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(reb_family().emulators); }

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(reb_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("reb", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RebFamily, OffersTheBoardAsARobotWithTheSharedRobotOptions) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* board = kinds.find("reb");
  ASSERT_NE(board, nullptr);
  EXPECT_EQ(board->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*board, "/tmp/reb"), "position:0 ( driver \"reb_position\" port \"/tmp/reb\" )");
  for (const char* name : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "subclass", "battery"}) {
    EXPECT_TRUE(std::any_of(board->options.begin(), board->options.end(),
                            [name](const auto& option) { return option.name == name; }))
        << name;
  }
  const auto made = catalog().make("reb", {{"pose", "1,2,90"}}, {});
  ASSERT_TRUE(made->world_pose());
  EXPECT_DOUBLE_EQ(made->world_pose()->x, 1.0);
  EXPECT_NE(refusal({{"subclass", "medium"}}).find("subclass"), std::string::npos);
  EXPECT_NE(refusal({{"battery", "-1"}}).find("battery"), std::string::npos);
  EXPECT_EQ(refusal({{"subclass", "fast"}, {"battery", "6"}}), "");
}

TEST(RebFamily, ProbeFindsTheBoardAt38400AndPrintsThePositionSection) {
  emulators::EmulatorRunner board(catalog().make("reb", {}, {}), emulators::PtyEndpoint{});
  const ProbeResult result = probe(board.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "reb");
  EXPECT_EQ(result.baud, 38400);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"reb_position\" port \"" + board.device_path() + "\" )");
}

TEST(RebFamily, ProbeFindsNothingOnASilentLine) {
  links::PseudoTerminal nobody;
  EXPECT_FALSE(probe(nobody.slave_path()).found);
}

TEST(RebFamily, TraceFramingCutsCommandsAtCrAndRepliesAtCrLf) {
  const auto framing = reb_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  const std::string commands = "D,2,-24\rH,0\r";
  const auto first = framing.outgoing->scan(std::span(reinterpret_cast<const std::uint8_t*>(commands.data()), commands.size()));
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 8u);
  const std::string replies = "h,-77\r\n:\r\n";
  const std::span bytes(reinterpret_cast<const std::uint8_t*>(replies.data()), replies.size());
  const auto reply = framing.incoming->scan(bytes);
  EXPECT_EQ(reply.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(reply.length, 7u);
  EXPECT_EQ(framing.incoming->scan(bytes.subspan(7)).length, 3u);
}

}  // namespace reb_family_test
}  // namespace playerkit::families
