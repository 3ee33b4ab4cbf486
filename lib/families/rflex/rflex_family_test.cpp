// The rflex family as the tools see it: its emulator kind and its probe,
// against the emulated controller on a pseudo-terminal.

#include "families/rflex/rflex_family.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <span>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::families {
namespace {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(rflex_family().emulators); }

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(rflex_family());
  return probe_port(port, registry, {}, [] { return false; });
}

TEST(RflexFamily, OffersTheControllerAsARobotWithEveryRobotsOptions) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("rflex");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/r"), "position:0 ( driver \"rflex_position\" port \"/tmp/r\" )");
  for (const char* shared : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "model"}) {
    EXPECT_TRUE(std::any_of(robot->options.begin(), robot->options.end(),
                            [&](const auto& option) { return option.name == shared; }))
        << shared;
  }
  try {
    (void)kinds.make("rflex", {{"model", "pioneer"}}, {});
    ADD_FAILURE() << "an unknown model was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("b21r, atrvjr and magellan"), std::string::npos) << e.what();
  }
}

TEST(RflexFamily, ProbeFindsTheControllerAndItsBattery) {
  emulators::EmulatorRunner robot(catalog().make("rflex", {{"model", "atrvjr"}, {"brake", "1"}}, {}),
                                  emulators::PtyEndpoint{});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "rflex");
  EXPECT_EQ(result.found->model, "an RFLEX controller (battery 24.5 V, braked)");
  EXPECT_EQ(result.baud, 115200);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"rflex_position\" port \"" + robot.device_path() + "\" )");
}

TEST(RflexFamily, ProbeFindsNothingOnASilentLine) {
  links::PseudoTerminal nobody;
  EXPECT_FALSE(probe(nobody.slave_path()).found);
}

// A line that sends back what it is sent (a loopback plug) is no controller.
TEST(RflexFamily, ProbeDoesNotTakeAnEchoForAnAnswer) {
  links::PseudoTerminal loopback;
  std::jthread echoing([&loopback](std::stop_token stop) {
    std::vector<std::uint8_t> buffer(256);
    while (!stop.stop_requested()) {
      const std::size_t got = loopback.read_some(buffer, links::deadline_in(std::chrono::milliseconds(50))).count;
      if (got > 0) {
        (void)loopback.write_all(std::span(buffer).first(got), links::deadline_in(std::chrono::milliseconds(200)));
      }
    }
  });
  EXPECT_FALSE(probe(loopback.slave_path()).found);
}

TEST(RflexFamily, TraceFramingCutsPacketsBothWays) {
  const auto framing = rflex_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  const auto bytes = hardware::rflex::encode_packet(hardware::rflex::system_status({1, 2640, 0}, 3));
  const auto scan = framing.incoming->scan(bytes);
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(scan.length, 18u);
}

}  // namespace
}  // namespace playerkit::families
