// The khepera family as the tools see it: its emulator kind, its probe
// against the emulated robot on a pseudo-terminal, its trace framing.

#include "families/khepera/khepera_family.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"

namespace playerkit::families {
namespace {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(khepera_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("khepera", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(khepera_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("khepera", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(KheperaFamily, OffersTheRobotAsAMountForSensors) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("khepera");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/k"), "position:0 ( driver \"khepera_position\" port \"/tmp/k\" )");
  // Every robot emulator's shared options, then the Khepera's own.
  for (const std::string name : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "encoder_res",
                                 "wheelbase", "radius", "baud"}) {
    EXPECT_TRUE(std::any_of(robot->options.begin(), robot->options.end(),
                            [&](const auto& option) { return option.name == name; }))
        << name;
  }
  const auto made = catalog().make("khepera", {{"pose", "1,2,90"}}, {});
  ASSERT_TRUE(made->world_pose());
  EXPECT_DOUBLE_EQ(made->world_pose()->x, 1.0);
}

TEST(KheperaFamily, RefusesValuesARobotCannotHave) {
  EXPECT_NE(refusal({{"wheelbase", "0"}}).find("wheelbase"), std::string::npos);
  EXPECT_NE(refusal({{"odometry_scale", "3"}}).find("odometry_scale"), std::string::npos);
  EXPECT_EQ(refusal({{"encoder_res", "0.05"}, {"drift", "1"}}), "");
}

TEST(KheperaFamily, ProbeFindsTheRobotAt38400) {
  auto robot = emulated();
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "khepera");
  EXPECT_EQ(result.found->model, "Khepera, wheels at 0,0 pulses/10 ms");
  EXPECT_EQ(result.baud, 38400);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"khepera_position\" port \"" + robot.device_path() + "\" )");
}

TEST(KheperaFamily, TraceFramingCutsCommandsAndReplies) {
  const auto framing = khepera_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  const std::string commands = "D,8,-8\nE\n";
  const auto sent = framing.outgoing->scan(std::span(reinterpret_cast<const std::uint8_t*>(commands.data()),
                                                     commands.size()));
  EXPECT_EQ(sent.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(sent.length, 7u);
  const std::string replies = "e,8,-8\r\nd\r\n";
  const auto got = framing.incoming->scan(std::span(reinterpret_cast<const std::uint8_t*>(replies.data()),
                                                    replies.size()));
  EXPECT_EQ(got.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(got.length, 8u);
}

}  // namespace
}  // namespace playerkit::families
