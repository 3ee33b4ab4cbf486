// The sonyevid30 family as the tools see it: its emulator kind, its probe
// against the emulated camera on a pseudo-terminal, its trace framing.

#include "families/sonyevid30/sonyevid30_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"
#include "families/sonyevid30/emulator/evid30_emulator.hpp"
#include "families/sonyevid30/protocol/visca.hpp"

namespace playerkit::families {
namespace {

namespace visca = hardware::sonyevid30;

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(sonyevid30_family().emulators); }

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(sonyevid30_family());
  return probe_port(port, registry, {}, [] { return false; });
}

TEST(Sonyevid30Family, OffersTheCameraAsAStandalonePtz) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* camera = kinds.find("sonyevid30");
  ASSERT_NE(camera, nullptr);
  EXPECT_EQ(camera->mount, emulators::EmulatorMount::standalone);
  EXPECT_EQ(config_example(*camera, "/tmp/cam"), "ptz:0 ( driver \"sonyevid30\" port \"/tmp/cam\" )");
  EXPECT_NO_THROW((void)kinds.make("sonyevid30", {{"pan_speed", "20"}, {"zoom_time", "0.5"}}, {}));
  EXPECT_THROW((void)kinds.make("sonyevid30", {{"pan_speed", "0"}}, {}), std::invalid_argument);
}

TEST(Sonyevid30Family, ProbeFindsTheCameraAndWhereItPoints) {
  emulators::EmulatorRunner camera(catalog().make("sonyevid30", {}, {}), emulators::PtyEndpoint{});
  camera.with_emulator<emulators::Evid30Emulator>([](emulators::Evid30Emulator& e) {
    e.receive(visca::absolute_pan_tilt(-264, 120), emulators::Duration{0}, 9600);
    e.advance(std::chrono::seconds(5));
    (void)e.take_output();
  });
  const ProbeResult result = probe(camera.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sonyevid30");
  EXPECT_EQ(result.found->model, "VISCA camera 1 (Sony EVI-D30), pan 30 tilt 10 degrees");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "ptz:0 ( driver \"sonyevid30\" port \"" + camera.device_path() + "\" )");
}

TEST(Sonyevid30Family, TraceFramingCutsPacketsBothWays) {
  const auto framing = sonyevid30_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  visca::Bytes replies = visca::ack(1);
  const visca::Bytes answer = visca::zoom_reply(0x17B);
  replies.insert(replies.end(), answer.begin(), answer.end());
  const auto first = framing.incoming->scan(replies);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 3u);
  EXPECT_EQ(framing.incoming->scan(std::span(replies).subspan(3)).length, answer.size());
  const visca::Bytes sent = visca::absolute_pan_tilt(-264, 120);
  EXPECT_EQ(framing.outgoing->scan(sent).length, sent.size());
  const visca::Bytes broadcast{0x88, 0x30, 0x01, 0xFF};
  EXPECT_EQ(framing.outgoing->scan(broadcast).length, 4u);
}

}  // namespace
}  // namespace playerkit::families
