// The segwayrmp family as the tools see it: its emulator kind (a robot that
// carries riders) and its probe, against the emulated RMP on a pseudo-terminal.
#include "families/segwayrmp/segwayrmp_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "links/pseudo_terminal.hpp"
#include "support/eventually.hpp"

namespace playerkit::families {
namespace segwayrmp_family_test {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(segwayrmp_family().emulators); }

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(segwayrmp_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("segwayrmp", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SegwayRmpFamily, OffersTheRobotAsAMobileBaseWithTheSharedRobotOptions) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("segwayrmp");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/rmp"), "position:0 ( driver \"segwayrmp\" port \"/tmp/rmp\" )");
  for (const char* shared : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "watchdog", "rate"}) {
    EXPECT_TRUE(std::any_of(robot->options.begin(), robot->options.end(),
                            [&](const auto& option) { return option.name == shared; }))
        << shared;
  }
  const auto made = catalog().make("segwayrmp", {{"pose", "1,2,90"}}, {});
  ASSERT_TRUE(made->world_pose());
  EXPECT_NEAR(made->world_pose()->x, 1.0, 1e-9);
  EXPECT_NEAR(made->world_pose()->yaw, M_PI / 2, 1e-9);
}

TEST(SegwayRmpFamily, RefusesValuesTheRobotCannotHave) {
  EXPECT_NE(refusal({{"rate", "0"}}).find("rate"), std::string::npos);
  EXPECT_NE(refusal({{"watchdog", "-1"}}).find("watchdog"), std::string::npos);
  EXPECT_EQ(refusal({{"rate", "50"}, {"battery", "80"}}), "");
}

TEST(SegwayRmpFamily, ProbeFindsTheRobotBehindItsAdapterAndLeavesTheChannelClosed) {
  emulators::EmulatorRunner robot(catalog().make("segwayrmp", {}, {}), emulators::PtyEndpoint{});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "segwayrmp");
  EXPECT_EQ(result.config_line, "position:0 ( driver \"segwayrmp\" port \"" + robot.device_path() + "\" )");
  // The probe's closing C reaches the emulator's thread a moment later.
  EXPECT_TRUE(::playerkit::testing::eventually([&] {
    return robot.with_emulator<emulators::SegwayRmpEmulator>(
        [](emulators::SegwayRmpEmulator& e) { return !e.channel_open(); });
  }));
}

TEST(SegwayRmpFamily, ProbeFindsNothingOnASilentLine) {
  links::PseudoTerminal silent;
  const ProbeResult result = probe(silent.slave_path());
  EXPECT_FALSE(result.found);
}

}  // namespace segwayrmp_family_test
}  // namespace playerkit::families
