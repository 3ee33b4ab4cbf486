// The amtecpowercube family as the tools see it: its emulator kind, its
// probe against the emulated wrist on a pseudo-terminal, its trace framing.

#include "families/amtecpowercube/amtecpowercube_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/amtecpowercube/protocol/powercube_frames.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"

namespace playerkit::families {
namespace {

namespace pc = hardware::powercube;

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(amtecpowercube_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("amtecpowercube", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(amtecpowercube_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("amtecpowercube", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(AmtecPowercubeFamily, OffersTheWristAsAStandalonePtz) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* wrist = kinds.find("amtecpowercube");
  ASSERT_NE(wrist, nullptr);
  EXPECT_EQ(wrist->mount, emulators::EmulatorMount::standalone);
  EXPECT_EQ(config_example(*wrist, "/tmp/cube"), "ptz:0 ( driver \"amtecpowercube\" port \"/tmp/cube\" )");
  for (const auto& option : wrist->options) {
    EXPECT_FALSE(option.summary.empty()) << option.name;
    EXPECT_FALSE(option.default_value.empty()) << option.name;
  }
}

TEST(AmtecPowercubeFamily, RefusesSettingsAWristCannotHave) {
  EXPECT_NE(refusal({{"pan_min", "5"}}).find("pan limits"), std::string::npos);
  EXPECT_NE(refusal({{"modules", "three"}}).find("modules"), std::string::npos);
  EXPECT_NE(refusal({{"tilt_start", "120"}}).find("tilt start"), std::string::npos);
  EXPECT_EQ(refusal({{"max_speed", "45"}, {"pan_start", "-20"}, {"modules", "pan"}}), "");
}

TEST(AmtecPowercubeFamily, ProbeFindsBothModulesAndMovesNothing) {
  auto wrist = emulated({{"pan_start", "12"}});
  const ProbeResult result = probe(wrist.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "amtecpowercube");
  EXPECT_EQ(result.found->model, "Amtec PowerCube wrist, pan module 12 and tilt module 11");
  EXPECT_EQ(result.baud, 38400);
  EXPECT_EQ(result.config_line, "ptz:0 ( driver \"amtecpowercube\" port \"" + wrist.device_path() + "\" )");
  EXPECT_EQ(wrist.with_emulator<emulators::DeviceEmulator>([](emulators::DeviceEmulator& e) { return e.describe(); }),
            "PowerCube wrist, pan (12) 12.00 deg, not homed, tilt (11) 0.00 deg, not homed");
}

TEST(AmtecPowercubeFamily, ProbeSaysWhichModuleIsMissing) {
  auto wrist = emulated({{"modules", "tilt"}});
  const ProbeResult result = probe(wrist.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "Amtec PowerCube, only the tilt module 11 answers");
  EXPECT_NE(result.found->note.find("both modules"), std::string::npos);
}

TEST(AmtecPowercubeFamily, TraceFramingCutsFramesBothWays) {
  const auto framing = amtecpowercube_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  std::vector<std::uint8_t> bytes = pc::encode(pc::Module::pan, pc::halt_data());
  const std::size_t first = bytes.size();
  const auto reply = pc::encode(pc::Module::pan, pc::value_reply_data(pc::Parameter::state, pc::state_bit::homed));
  bytes.insert(bytes.end(), reply.begin(), reply.end());
  const auto scan = framing.incoming->scan(bytes);
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(scan.length, first);
  EXPECT_EQ(framing.outgoing->scan(std::span(bytes).subspan(first)).length, reply.size());
}

}  // namespace
}  // namespace playerkit::families
