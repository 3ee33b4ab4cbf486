// The ptu46 family as the tools see it: its emulator kind and its probe,
// against the emulated unit on a pseudo-terminal.

#include "families/ptu46/ptu46_family.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::families {
namespace {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(ptu46_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("ptu46", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(ptu46_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("ptu46", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Ptu46Family, OffersTheUnitAsAStandalonePtz) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* unit = kinds.find("ptu46");
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->mount, emulators::EmulatorMount::standalone);
  EXPECT_EQ(config_example(*unit, "/tmp/ptu"), "ptz:0 ( driver \"ptu46\" port \"/tmp/ptu\" )");
  for (const auto& option : unit->options) {
    EXPECT_FALSE(option.summary.empty()) << option.name;
    EXPECT_FALSE(option.default_value.empty()) << option.name;
  }
}

TEST(Ptu46Family, RefusesLimitsAUnitCannotHave) {
  EXPECT_NE(refusal({{"pan_min", "0"}}).find("pan_min"), std::string::npos);
  EXPECT_NE(refusal({{"lower_speed", "3000"}}).find("speed limits"), std::string::npos);
  EXPECT_EQ(refusal({{"resolution", "92.5714"}, {"tilt_max", "1200"}}), "");
}

TEST(Ptu46Family, ProbeFindsAUnitFreshFromPowerUpWithItsEchoOn) {
  auto unit = emulated();
  const ProbeResult result = probe(unit.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "ptu46");
  EXPECT_EQ(result.found->model, "PTU-46, 185.1428 arc-seconds a pan position");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "ptz:0 ( driver \"ptu46\" port \"" + unit.device_path() + "\" )");
}

TEST(Ptu46Family, ProbeFindsAUnitWithEchoOffAndAnotherResolution) {
  auto unit = emulated({{"echo", "0"}, {"resolution", "92.5714"}});
  const ProbeResult result = probe(unit.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "PTU-46, 92.5714 arc-seconds a pan position");
}

// A GPS receiver talking at 9600: every sentence ends "*hh", which a '*'
// found anywhere would take for a value reply.
TEST(Ptu46Family, ProbeDoesNotTakeAnNmeaSentencesChecksumForAnAnswer) {
  links::PseudoTerminal receiver;
  const std::string sentence = "$GPGSV,3,1,11,03,69,066,44,06,51,292,48,07,19,150,00,08,18,043,00*44\r\n";
  std::jthread talking([&receiver, &sentence](std::stop_token stop) {
    const std::vector<std::uint8_t> bytes(sentence.begin(), sentence.end());
    while (!stop.stop_requested()) {
      (void)receiver.write_all(bytes, links::deadline_in(std::chrono::milliseconds(200)));
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  const ProbeResult result = probe(receiver.slave_path());
  EXPECT_FALSE(result.found) << result.found->driver;
}

TEST(Ptu46Family, TraceFramingCutsRepliesIntoLines) {
  const auto framing = ptu46_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  EXPECT_EQ(framing.outgoing, nullptr);
  const std::string replies = "* 583\r\n! Illegal Command\r\n";
  const std::span bytes(reinterpret_cast<const std::uint8_t*>(replies.data()), replies.size());
  const auto first = framing.incoming->scan(bytes);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 7u);
  const auto second = framing.incoming->scan(bytes.subspan(first.length));
  EXPECT_EQ(second.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(second.length, replies.size() - 7);
}

}  // namespace
}  // namespace playerkit::families
