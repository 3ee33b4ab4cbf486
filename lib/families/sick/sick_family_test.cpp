// The sick family as the tools see it: its two emulator kinds (options,
// defaults, refusals, riding on a robot) and its probes, against the
// emulated lasers.

#include "families/sick/sick_family.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/port_probe.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "families/sick/emulator/sick_pls_emulator.hpp"
#include "families/sick/protocol/requests.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::families {
namespace sick_family_test {

using namespace std::chrono_literals;

const std::vector<std::string> kLasers = {"sicklms200", "sickpls"};

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(sick_family().emulators); }

FamilyRegistry only_sick() {
  FamilyRegistry registry;
  registry.add(sick_family());
  return registry;
}

std::unique_ptr<emulators::DeviceEmulator> make(const std::string& name, const emulators::EmulatorOptionValues& options,
                                                const emulators::EmulatorWorld& world = {}) {
  return catalog().make(name, options, world);
}

// The message of the std::invalid_argument `make` throws ("" when it does not).
std::string refusal(const std::string& name, const emulators::EmulatorOptionValues& options,
                    const emulators::EmulatorWorld& world = {}) {
  try {
    (void)make(name, options, world);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// A world with a robot standing still at `pose`, counting how often it is asked.
emulators::EmulatorWorld carried_by(geometry::Pose2 pose, int* asked = nullptr) {
  return {.map = nullptr, .carrier_pose = [pose, asked] {
            if (asked) ++*asked;
            return pose;
          }};
}

emulators::EmulatorRunner emulated(const std::string& name, const emulators::EmulatorOptionValues& options = {},
                                   emulators::Endpoint endpoint = emulators::PtyEndpoint{}) {
  return emulators::EmulatorRunner(make(name, options), endpoint);
}

ProbeResult probe(const std::string& port, const ProbeSettings& settings = {}) {
  return probe_port(port, only_sick(), settings, [] { return false; });
}

TEST(SickFamily, OffersTwoLasersThatRideOnARobot) {
  const auto kinds = catalog();
  EXPECT_EQ(kinds.names(), "sicklms200, sickpls");
  for (const auto& name : kLasers) {
    const emulators::EmulatorKind* laser = kinds.find(name);
    ASSERT_NE(laser, nullptr) << name;
    EXPECT_EQ(laser->driver, name);
    EXPECT_EQ(laser->interface_name, "laser");
    EXPECT_EQ(laser->mount, emulators::EmulatorMount::rider) << name;
  }
  EXPECT_EQ(kinds.find("sicklms"), nullptr);
  EXPECT_EQ(config_example(*kinds.find("sickpls"), "/tmp/laser"), "laser:0 ( driver \"sickpls\" port \"/tmp/laser\" )");
}

TEST(SickFamily, EveryKindDocumentsItsOptions) {
  for (const auto& kind : sick_family().emulators) {
    EXPECT_FALSE(kind.summary.empty()) << kind.name;
    for (const auto& option : kind.options) {
      EXPECT_FALSE(option.summary.empty()) << kind.name << " " << option.name;
      EXPECT_FALSE(option.default_value.empty()) << kind.name << " " << option.name;
    }
  }
}

// Which model a kind's emulator is: "LMS", "PLS", or "" for neither.
std::string model_of(const emulators::DeviceEmulator& made) {
  const bool lms = dynamic_cast<const emulators::SickLms200Emulator*>(&made) != nullptr;
  const bool pls = dynamic_cast<const emulators::SickPlsEmulator*>(&made) != nullptr;
  return lms ? "LMS" : pls ? "PLS" : "";
}

TEST(SickFamily, EachKindBuildsItsOwnModel) {
  // Not one factory for all, which would make every kind but one the same model.
  for (const auto& kind : sick_family().emulators) {
    const std::string model = model_of(*make(kind.name, {}));
    if (kind.name == "sicklms200") {
      EXPECT_EQ(model, "LMS");
    } else if (kind.name == "sickpls") {
      EXPECT_EQ(model, "PLS");
    } else {
      ADD_FAILURE() << "a new kind " << kind.name << " (a " << model << "): say here which model it must build";
    }
  }
}

TEST(SickFamily, DefaultsAreThoseOfTheEmulators) {
  for (const auto& name : kLasers) {
    auto made = make(name, {});
    auto* laser = dynamic_cast<emulators::SickLaserEmulator*>(made.get());
    ASSERT_NE(laser, nullptr) << name;
    EXPECT_EQ(laser->baud(), 9600) << name;
    EXPECT_EQ(laser->world_pose(), std::nullopt) << name;
  }
  // All the unit can encode: 8191 mm on an LMS, 8191 cm on a PLS.
  EXPECT_DOUBLE_EQ(dynamic_cast<emulators::SickLaserEmulator&>(*make("sicklms200", {})).max_range_m(), 8.191);
  EXPECT_DOUBLE_EQ(dynamic_cast<emulators::SickLaserEmulator&>(*make("sickpls", {})).max_range_m(), 81.91);
}

TEST(SickFamily, OptionsReachTheLaser) {
  for (const auto& name : kLasers) {
    auto made = make(name, {{"max_range", "5"}, {"baud", "38400"}, {"model_baud", "0"}});
    auto& laser = dynamic_cast<emulators::SickLaserEmulator&>(*made);
    EXPECT_DOUBLE_EQ(laser.max_range_m(), 5.0) << name;
    EXPECT_EQ(laser.line_baud(), 38400) << name;
    EXPECT_EQ(laser.baud(), 0) << name;  // any speed works
  }
  auto lms = make("sicklms200", {{"type", "LMS291-S05"}});
  EXPECT_NE(lms->describe().find("LMS291-S05"), std::string::npos) << lms->describe();
}

TEST(SickFamily, BadOptionsAreRefusedByName) {
  EXPECT_EQ(refusal("sicklms200", {{"nosie", "0.1"}}),
            "sicklms200: no option 'nosie'; its options are pose, mount, noise, seed, max_range, baud, model_baud, "
            "type");
  EXPECT_EQ(refusal("sicklms200", {{"noise", "-1"}}), "sicklms200: noise=-1: expected a number from 0 to 1");
  EXPECT_EQ(refusal("sickpls", {{"type", "PLS"}}),
            "sickpls: no option 'type'; its options are pose, mount, noise, seed, max_range, baud, model_baud");
  EXPECT_EQ(refusal("sicklms200", {{"baud", "115200"}}),
            "sicklms200: baud=115200: a SICK laser runs at 9600, 19200, 38400 or 500000");
  EXPECT_EQ(refusal("sickpls", {{"baud", "115200"}}),
            "sickpls: baud=115200: a SICK laser runs at 9600, 19200, 38400 or 500000");
  EXPECT_EQ(refusal("sickpls", {{"max_range", "0"}}), "sickpls: max_range=0: expected a number from 0.01 to 81.91");
  EXPECT_EQ(refusal("sicklms200", {{"model_baud", "2"}}),
            "sicklms200: model_baud=2: expected 1 or 0 (yes/no, on/off)");
  // What only the emulator itself can check still names it.
  EXPECT_EQ(refusal("sicklms200", {{"type", "LMS200;30106 and more text"}}),
            "sicklms200: SICK emulator: type text \"LMS200;30106 and more text\" is over 20 characters");
}

TEST(SickFamily, ALaserAloneStandsAtItsPoseAndRefusesAMount) {
  for (const auto& name : kLasers) {
    EXPECT_EQ(refusal(name, {{"mount", "0.1,0,0"}}),
              name + ": mount=0.1,0,0: no robot is emulated to carry the laser; use pose=x,y,yaw");
    EXPECT_EQ(refusal(name, {{"pose", "1,1,0"}}, carried_by({})),
              name + ": pose=1,1,0: this laser rides on the emulated robot; say where with mount=x,y,yaw");
    EXPECT_EQ(refusal(name, {{"pose", "1,1"}}), name + ": pose=1,1: expected x,y,yaw in metres, metres and degrees, "
                                                       "e.g. 1.5,-2,90");
    EXPECT_NE(make(name, {{"pose", "1,1,0"}}), nullptr);
    EXPECT_NE(make(name, {{"mount", "0.1,0,0"}}, carried_by({})), nullptr);
  }
}

TEST(SickFamily, ACarriedLaserAsksItsCarrierAtEveryScan) {
  for (const auto& name : kLasers) {
    int asked = 0;
    auto laser = make(name, {{"mount", "0.2,0,0"}, {"model_baud", "0"}}, carried_by({1.0, 0.0, 0.0}, &asked));
    laser->receive(hardware::sick::encode_request(hardware::sick::StreamAllRequest{}), emulators::Duration{0}, 0);
    laser->advance(2s);
    std::size_t scans = 0;
    for (const auto& telegram : laser->take_output()) scans += telegram.bytes.size() > 100 ? 1 : 0;
    ASSERT_GT(scans, 0u) << name;
    EXPECT_GE(asked, static_cast<int>(scans)) << name;
  }
}

TEST(SickFamily, ProbeFindsAnLms200AtItsPowerUpSpeed) {
  auto laser = emulated("sicklms200");
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sicklms200");
  EXPECT_EQ(result.found->model, "LMS200;30106");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "laser:0 ( driver \"sicklms200\" port \"" + laser.device_path() + "\" )");
  EXPECT_TRUE(result.found->note.empty()) << result.found->note;
}

TEST(SickFamily, ProbeFindsAPls) {
  auto laser = emulated("sickpls");
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sickpls");
  EXPECT_EQ(result.found->model, "PLS");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "laser:0 ( driver \"sickpls\" port \"" + laser.device_path() + "\" )");
}

TEST(SickFamily, ProbeFindsALaserLeftAt500000AndSaysTheDriverWillNot) {
  auto laser = emulated("sicklms200", {{"baud", "500000"}, {"type", "LMS291-S05"}});
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "LMS291-S05");
  EXPECT_EQ(result.baud, 500000);
  EXPECT_NE(result.found->note.find("power-cycle it"), std::string::npos) << result.found->note;
}

TEST(SickFamily, ProbeAsksOnceOverTcp) {
  auto laser = emulated("sicklms200", {}, emulators::TcpEndpoint{});
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sicklms200");
  EXPECT_EQ(result.found->model, "LMS200;30106");
  EXPECT_EQ(result.baud, 0);
  EXPECT_EQ(result.config_line, "laser:0 ( driver \"sicklms200\" port \"" + laser.device_path() + "\" )");
}

TEST(SickFamily, ProbeTriesBothPasswordsAtTheFourRates) {
  links::PseudoTerminal silent;
  ProbeSettings quick;
  quick.first_reply = 50ms;
  std::vector<std::string> progress;
  quick.progress = [&progress](std::string_view line) { progress.emplace_back(line); };
  const ProbeResult result = probe(silent.slave_path(), quick);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + silent.slave_path() +
                                     " (tried SICK (LMS password) at 9600, 38400, 19200, 500000 baud; "
                                     "SICK (PLS password) at 9600, 38400, 19200, 500000 baud)",
                                 0),
            0u)
      << result.problem;
  ASSERT_EQ(progress.size(), 8u);
  EXPECT_EQ(progress[0], silent.slave_path() + ": SICK (LMS password) at 9600 8N1: no answer");
  EXPECT_EQ(progress[1], silent.slave_path() + ": SICK (PLS password) at 9600 8E1: no answer");
}

}  // namespace sick_family_test
}  // namespace playerkit::families
