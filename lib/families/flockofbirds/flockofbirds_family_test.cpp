// The flockofbirds family as the tools see it: its emulator kind and its
// probe, against the emulated bird on a pseudo-terminal.

#include "families/flockofbirds/flockofbirds_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/flockofbirds/emulator/flock_emulator.hpp"
#include "families/port_probe.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::families {
namespace flockofbirds_family_test {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(flockofbirds_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("flockofbirds", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(flockofbirds_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("flockofbirds", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(FlockOfBirdsFamily, OffersTheBirdAsAStandalonePosition3d) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* bird = kinds.find("flockofbirds");
  ASSERT_NE(bird, nullptr);
  EXPECT_EQ(bird->mount, emulators::EmulatorMount::standalone);
  EXPECT_EQ(config_example(*bird, "/tmp/bird"), "position3d:0 ( driver \"flockofbirds\" port \"/tmp/bird\" )");
  for (const auto& option : bird->options) {
    EXPECT_FALSE(option.summary.empty()) << option.name;
    EXPECT_FALSE(option.default_value.empty()) << option.name;
  }
}

TEST(FlockOfBirdsFamily, ReadsATrajectoryFileAndRefusesABadOne) {
  const ::playerkit::testing::ScratchDirectory scratch("flockofbirds-family");
  const auto good = scratch.write("poses.txt", "# t x y z az el roll\n0 100 0 0 0 0 0\n1 200 0 0 0 0 0\n");
  const auto bad = scratch.write("bad.txt", "0 100 0 0 0 0 0\n0 200 0 0 0 0 0\n");
  EXPECT_EQ(refusal({{"trajectory", good.string()}, {"loop", "0"}}), "");
  EXPECT_NE(refusal({{"trajectory", bad.string()}}).find("trajectory line 2: the time must increase"), std::string::npos)
      << refusal({{"trajectory", bad.string()}});
  EXPECT_NE(refusal({{"trajectory", scratch.file("none.txt").string()}}).find("cannot read"), std::string::npos);
  EXPECT_NE(refusal({{"scaling", "48"}}).find("36 or 72"), std::string::npos);
  EXPECT_NE(refusal({{"rate", "0"}}).find("rate"), std::string::npos);
}

TEST(FlockOfBirdsFamily, ProbeFindsABirdAndItsScaling) {
  auto bird = emulated();
  const ProbeResult result = probe(bird.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "flockofbirds");
  EXPECT_EQ(result.found->model, "Flock of Birds, 36\" position scaling");
  EXPECT_EQ(result.baud, 115200);
  EXPECT_EQ(result.found->note, "");
  EXPECT_EQ(result.config_line, "position3d:0 ( driver \"flockofbirds\" port \"" + bird.device_path() + "\" )");
}

TEST(FlockOfBirdsFamily, ProbeFindsAStreamingBirdAt9600AndLeavesItInPointMode) {
  auto bird = emulated({{"baud", "9600"}, {"scaling", "72"}});
  bird.with_emulator<emulators::FlockEmulator>([](emulators::FlockEmulator& e) {
    const std::vector<std::uint8_t> stream{0x40};
    e.receive(stream, std::chrono::nanoseconds(0), 0);
    return 0;
  });
  const ProbeResult result = probe(bird.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "Flock of Birds, 72\" position scaling");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.found->note, "the bird runs at 9600 baud: add baudrate 9600 to the section");
  EXPECT_FALSE(bird.with_emulator<emulators::FlockEmulator>([](emulators::FlockEmulator& e) { return e.streaming(); }));
}

TEST(FlockOfBirdsFamily, TraceFramingCutsRecordsOnTheirPhasingBit) {
  const auto framing = flockofbirds_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  EXPECT_EQ(framing.outgoing, nullptr);
  const std::vector<std::uint8_t> bytes{0x00, 0x00, 0xAA, 0x15, 0x2A, 0x75, 0x2A, 0x05, 0x00, 0x20, 0x00, 0x70, 0x47, 0x03};
  const auto noise = framing.incoming->scan(bytes);
  EXPECT_EQ(noise.kind, framing::FrameScan::Kind::skip);  // a scaling answer is not a record
  EXPECT_EQ(noise.length, 2u);
  const auto record = framing.incoming->scan(std::span(bytes).subspan(2));
  EXPECT_EQ(record.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(record.length, 12u);
}

}  // namespace flockofbirds_family_test
}  // namespace playerkit::families
