// The garminnmea family as the tools see it: its emulator kind (a log or a
// robot's pose), its probe and its trace framing, against the emulated
// receiver on a pseudo-terminal.

#include "families/garminnmea/garminnmea_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/garminnmea/emulator/garminnmea_emulator.hpp"
#include "families/port_probe.hpp"

namespace playerkit::families {
namespace garminnmea_family_test {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(garminnmea_family().emulators); }

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {}) {
  return emulators::EmulatorRunner(catalog().make("garminnmea", options, {}), emulators::PtyEndpoint{});
}

ProbeResult probe(const std::string& port) {
  FamilyRegistry registry;
  registry.add(garminnmea_family());
  return probe_port(port, registry, {}, [] { return false; });
}

std::string refusal(const emulators::EmulatorOptionValues& options, const emulators::EmulatorWorld& world = {}) {
  try {
    (void)catalog().make("garminnmea", options, world);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string log_path(const char* name) { return std::string(PLAYERKIT_TEST_DATA_DIR) + "/gpsd-garmin/" + name; }

TEST(GarminNmeaFamily, OffersTheReceiverAsARider) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* receiver = kinds.find("garminnmea");
  ASSERT_NE(receiver, nullptr);
  EXPECT_EQ(receiver->mount, emulators::EmulatorMount::rider);
  EXPECT_EQ(config_example(*receiver, "/tmp/gps"), "gps:0 ( driver \"garminnmea\" port \"/tmp/gps\" )");
  for (const auto& option : receiver->options) EXPECT_FALSE(option.summary.empty()) << option.name;
}

TEST(GarminNmeaFamily, RefusesOptionsThatDoNotFit) {
  EXPECT_NE(refusal({{"origin", "95,10"}}).find("origin"), std::string::npos);
  EXPECT_NE(refusal({{"utc", "2004-13-01T00:00:00"}}).find("utc"), std::string::npos);
  EXPECT_NE(refusal({{"mount", "0.1,0,0"}}).find("no robot"), std::string::npos);
  EXPECT_NE(refusal({{"log", "/nonexistent/gps.log"}}).find("cannot read"), std::string::npos);
  EXPECT_NE(refusal({{"log", log_path("garmin48.log")}, {"origin", "1,2"}}).find("origin"), std::string::npos);
  EXPECT_NE(refusal({{"rate", "2"}}).find("only with log"), std::string::npos);
  const emulators::EmulatorWorld on_a_robot{.map = nullptr, .carrier_pose = [] { return geometry::Pose2{}; }};
  EXPECT_NE(refusal({{"pose", "1,1,0"}}, on_a_robot).find("rides on the emulated robot"), std::string::npos);
  EXPECT_EQ(refusal({{"mount", "0.1,0,0"}, {"origin", "-45.4576,167.1527"}}, on_a_robot), "");
  EXPECT_EQ(refusal({{"log", log_path("garmin38.log")}, {"loop", "1"}, {"rate", "5"}, {"start", "0.5"}}), "");
}

TEST(GarminNmeaFamily, ProbeHearsAReceiverAt4800) {
  auto receiver = emulated();
  const ProbeResult result = probe(receiver.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "garminnmea");
  EXPECT_EQ(result.found->model.rfind("Garmin GPS receiver (", 0), 0u) << result.found->model;
  EXPECT_NE(result.found->model.find("GPGGA"), std::string::npos) << result.found->model;
  EXPECT_EQ(result.baud, 4800);
  EXPECT_EQ(result.config_line, "gps:0 ( driver \"garminnmea\" port \"" + receiver.device_path() + "\" )");
  // Probing sends nothing but an empty line (CR LF), which a receiver ignores.
  EXPECT_EQ(receiver.with_emulator<emulators::GarminNmeaEmulator>(
                [](emulators::GarminNmeaEmulator& e) { return e.bytes_received(); }),
            2u);
}

TEST(GarminNmeaFamily, ProbeHearsARealLogPlayedBack) {
  auto receiver = emulated({{"log", log_path("garmin48.log")}, {"loop", "1"}, {"rate", "4"}});
  const ProbeResult result = probe(receiver.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_NE(result.found->model.find("GP"), std::string::npos) << result.found->model;
}

TEST(GarminNmeaFamily, TraceFramingCutsSentencesOnePerLine) {
  const auto framing = garminnmea_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  EXPECT_EQ(framing.outgoing, nullptr);  // RTCM corrections are binary
  const std::string stream = "$PGRME,15.0,M,22.5,M,27.0,M*1A\r\n$PGRMZ,125,f,3*1D\r\n";
  const std::span bytes(reinterpret_cast<const std::uint8_t*>(stream.data()), stream.size());
  const auto first = framing.incoming->scan(bytes);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 32u);
  EXPECT_EQ(framing.incoming->scan(bytes.subspan(first.length)).kind, framing::FrameScan::Kind::frame);
}

}  // namespace garminnmea_family_test
}  // namespace playerkit::families
