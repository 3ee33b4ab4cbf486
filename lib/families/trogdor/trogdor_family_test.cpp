// The trogdor family as the tools see it: its emulator kind (a robot with
// the shared body options), its probe against the emulated robot on a
// pseudo-terminal, and its trace framing.

#include "families/trogdor/trogdor_family.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"

namespace playerkit::families {
namespace {

namespace hw = hardware::trogdor;

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(trogdor_family().emulators); }

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(trogdor_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("trogdor", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TrogdorFamily, OffersTheRobotAsAMobileBaseWithTheSharedOptions) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("trogdor");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/trogdor"), "position:0 ( driver \"trogdor\" port \"/tmp/trogdor\" )");
  for (const char* shared : {"pose", "odometry_scale", "rotation_scale", "drift", "seed"}) {
    EXPECT_TRUE(std::any_of(robot->options.begin(), robot->options.end(),
                            [&](const auto& option) { return option.name == shared; }))
        << shared;
  }
  const auto made = catalog().make("trogdor", {{"pose", "1,2,90"}}, {});
  ASSERT_TRUE(made->world_pose());
  EXPECT_NEAR(made->world_pose()->x, 1, 1e-9);
  EXPECT_NEAR(made->world_pose()->yaw, M_PI / 2, 1e-9);
}

TEST(TrogdorFamily, RefusesACounterOfZero) {
  EXPECT_NE(refusal({{"counts", "0"}}).find("counts"), std::string::npos);
  EXPECT_EQ(refusal({{"counts", "5"}, {"encoder_error", "1"}}), "");
}

TEST(TrogdorFamily, ProbeFindsTheRobotAt57600) {
  emulators::EmulatorRunner robot(catalog().make("trogdor", {{"counts", "4242"}}, {}), emulators::PtyEndpoint{});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "trogdor");
  EXPECT_EQ(result.found->model, "Botrics O-Bot (Trogdor) cerebellum, wheel counters 4242 / 4242");
  EXPECT_EQ(result.baud, 57600);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"trogdor\" port \"" + robot.device_path() + "\" )");
}

TEST(TrogdorFamily, TraceFramingCutsMessagesAndReplies) {
  const auto framing = trogdor_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  hw::Bytes host = hw::init();
  const hw::Bytes velocities = hw::set_velocities({3, 4});
  host.insert(host.end(), velocities.begin(), velocities.end());
  EXPECT_EQ(framing.outgoing->scan(host).length, 3u);
  EXPECT_EQ(framing.outgoing->scan(std::span(host).subspan(3)).length, 10u);
  hw::Bytes replies{hw::kAck, hw::kAck};
  const hw::Bytes block = hw::odometry_block({.left_count = 9, .right_count = 9});
  replies.insert(replies.end(), block.begin(), block.end());
  EXPECT_EQ(framing.incoming->scan(replies).length, 1u);
  EXPECT_EQ(framing.incoming->scan(std::span(replies).subspan(1)).length, 19u);
}

}  // namespace
}  // namespace playerkit::families
