// The cmucam2 family as the tools see it: its emulator kind and its probe,
// against the emulated camera on a pseudo-terminal.

#include "families/cmucam2/cmucam2_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"

namespace playerkit::families {
namespace cmucam2_family_test {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(cmucam2_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("cmucam2", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(cmucam2_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("cmucam2", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Cmucam2Family, OffersTheCameraAsAStandaloneBlobfinder) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* camera = kinds.find("cmucam2");
  ASSERT_NE(camera, nullptr);
  EXPECT_EQ(camera->mount, emulators::EmulatorMount::standalone);
  EXPECT_EQ(config_example(*camera, "/tmp/cam"), "blobfinder:0 ( driver \"cmucam2\" port \"/tmp/cam\" )");
  for (const auto& option : camera->options) EXPECT_FALSE(option.summary.empty()) << option.name;
}

TEST(Cmucam2Family, RefusesOptionsACameraCannotHave) {
  EXPECT_NE(refusal({{"blob", "1,2,3"}}).find("blob"), std::string::npos);
  EXPECT_NE(refusal({{"blob2", "1,2,0,10,10,10"}}).find("blob2"), std::string::npos);
  EXPECT_NE(refusal({{"image", "/nonexistent/scene.ppm"}}).find("cannot be read"), std::string::npos);
  EXPECT_NE(refusal({{"frame_ms", "0"}}).find("frame_ms"), std::string::npos);
  EXPECT_EQ(refusal({{"blob", "0,0,5,10,200,10"}, {"prompt_after_packet", "0"}}), "");
}

TEST(Cmucam2Family, ProbeFindsTheCameraByItsVersion) {
  auto camera = emulated();
  const ProbeResult result = probe(camera.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "cmucam2");
  EXPECT_EQ(result.found->model, "CMUcam2 v1.00 c6");
  EXPECT_EQ(result.baud, 115200);
  EXPECT_EQ(result.config_line, "blobfinder:0 ( driver \"cmucam2\" port \"" + camera.device_path() + "\" )");
}

TEST(Cmucam2Family, TraceFramingCutsLinesAndThePrompt) {
  const auto framing = cmucam2_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  const std::string replies = "ACK\rT 26 72 19 62 33 82 25 199\r:";
  const std::span bytes(reinterpret_cast<const std::uint8_t*>(replies.data()), replies.size());
  const auto first = framing.incoming->scan(bytes);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 4u);
  const auto second = framing.incoming->scan(bytes.subspan(4));
  EXPECT_EQ(second.length, replies.size() - 5);
  const auto prompt = framing.incoming->scan(bytes.subspan(replies.size() - 1));
  EXPECT_EQ(prompt.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(prompt.length, 1u);
  // The lone CR that returns the camera to idle is a command of its own.
  ASSERT_NE(framing.outgoing, nullptr);
  const std::uint8_t cr = '\r';
  EXPECT_EQ(framing.outgoing->scan(std::span(&cr, 1)).kind, framing::FrameScan::Kind::frame);
}

}  // namespace cmucam2_family_test
}  // namespace playerkit::families
