#include "emulators/catalog/emulator_catalog.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "emulators/p2os/p2os_robot_emulator.hpp"
#include "emulators/sick/sick_lms200_emulator.hpp"
#include "emulators/sick/sick_pls_emulator.hpp"
#include "hardware/sick/requests.hpp"

namespace playerkit::emulators {
namespace emulator_catalog_test {

using namespace std::chrono_literals;

// The message of the std::invalid_argument `make` throws ("" when it does not).
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EmulatorCatalog, NamesTheThreeEmulatorsAndTheirDrivers) {
  EXPECT_EQ(emulator_names(), "p2os, sicklms200, sickpls");
  ASSERT_NE(find_emulator_kind("sickpls"), nullptr);
  EXPECT_EQ(find_emulator_kind("sickpls")->driver, "sickpls");
  EXPECT_TRUE(find_emulator_kind("sickpls")->rides_on_robot);
  EXPECT_FALSE(find_emulator_kind("p2os")->rides_on_robot);
  EXPECT_EQ(find_emulator_kind("sicklms"), nullptr);
  EXPECT_EQ(config_example(*find_emulator_kind("p2os"), "/tmp/robot"),
            "position:0 ( driver \"p2os_position\" port \"/tmp/robot\" )");
}

TEST(EmulatorCatalog, EveryKindDocumentsItsOptions) {
  for (const auto& kind : emulator_kinds()) {
    EXPECT_FALSE(kind.summary.empty()) << kind.name;
    for (const auto& option : kind.options) {
      EXPECT_FALSE(option.summary.empty()) << kind.name << " " << option.name;
      EXPECT_FALSE(option.default_value.empty()) << kind.name << " " << option.name;
    }
  }
}

TEST(EmulatorCatalog, UnknownNameListsTheNames) {
  EXPECT_EQ(refusal([] { make_emulator("sicklms", {}); }),
            "no emulator 'sicklms'; there are p2os, sicklms200, sickpls");
}

TEST(EmulatorCatalog, P2osOptionsReachTheRobot) {
  auto made = make_emulator("p2os", {{"model", "p3at"}, {"pose", "1.5,-2,90"}, {"baud", "38400"}, {"name", "rover"}});
  auto& robot = dynamic_cast<P2osRobotEmulator&>(*made);
  EXPECT_EQ(robot.params().subclass, "p3at");
  EXPECT_EQ(robot.baud(), 38400);
  EXPECT_DOUBLE_EQ(robot.true_pose().x, 1.5);
  EXPECT_DOUBLE_EQ(robot.true_pose().y, -2.0);
  EXPECT_NEAR(robot.true_pose().yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_NE(robot.describe().find("\"rover\""), std::string::npos) << robot.describe();
}

TEST(EmulatorCatalog, DefaultsAreThoseOfTheEmulators) {
  auto made = make_emulator("p2os", {});
  auto& robot = dynamic_cast<P2osRobotEmulator&>(*made);
  EXPECT_EQ(robot.params().subclass, "p3dx");
  EXPECT_EQ(robot.baud(), 0);
  auto laser = make_emulator("sicklms200", {});
  EXPECT_EQ(laser->protocol_name(), "sicklms200");
  EXPECT_EQ(laser->baud(), 9600);
  EXPECT_EQ(make_emulator("sickpls", {})->protocol_name(), "sickpls");
}

TEST(EmulatorCatalog, BadOptionsAreRefusedByName) {
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"nosie", "0.1"}}); }),
            "sicklms200: no option 'nosie'; its options are pose, mount, noise, seed, max_range, baud, model_baud, "
            "type");
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"noise", "-1"}}); }),
            "sicklms200: noise=-1: expected a number from 0 to 1");
  EXPECT_EQ(refusal([] { make_emulator("sickpls", {{"type", "PLS"}}); }).substr(0, 30), "sickpls: no option 'type'; its");
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"baud", "115200"}}); }),
            "sicklms200: baud=115200: a SICK laser runs at 9600, 19200, 38400 or 500000");
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"baud", "4800"}}); }),
            "p2os: baud=4800: a P2OS controller runs at 9600, 19200, 38400, 57600 or 115200 (0: any speed)");
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"pose", "1,2"}}); }),
            "p2os: pose=1,2: expected x,y,yaw in metres, metres and degrees, e.g. 1.5,-2,90");
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"pose", "1,2,3,4"}}); }).substr(0, 18), "p2os: pose=1,2,3,4");
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"gripper", "maybe"}}); }),
            "p2os: gripper=maybe: expected 1 or 0 (yes/no, on/off)");
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"seed", "1"}, {"seed", "2"}}); }),
            "p2os: option 'seed' is given twice");
  // What only the emulator itself can check still names it.
  EXPECT_EQ(refusal([] { make_emulator("p2os", {{"model", "p9zz"}}); }).substr(0, 6), "p2os: ");
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"type", "LMS200;30106 and more text"}}); }).substr(0, 12),
            "sicklms200: ");
}

TEST(EmulatorCatalog, ALaserAloneStandsAtItsPoseAndRefusesAMount) {
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"mount", "0.1,0,0"}}); }),
            "sicklms200: mount=0.1,0,0: no robot is emulated to carry the laser; use pose=x,y,yaw");
  EXPECT_EQ(refusal([] { make_emulator("sicklms200", {{"pose", "1,1,0"}}, {.map = nullptr, .carrier_pose = [] {
                                                                             return geometry::Pose2{};
                                                                           }}); }),
            "sicklms200: pose=1,1,0: this laser rides on the emulated robot; say where with mount=x,y,yaw");
}

TEST(EmulatorCatalog, ACarriedLaserAsksItsCarrierAtEveryScan) {
  int asked = 0;
  auto laser = make_emulator("sicklms200", {{"mount", "0.2,0,0"}, {"model_baud", "0"}},
                             {.map = nullptr, .carrier_pose = [&asked] {
                                ++asked;
                                return geometry::Pose2{1.0, 0.0, 0.0};
                              }});
  laser->receive(hardware::sick::encode_request(hardware::sick::StreamAllRequest{}), Duration{0}, 0);
  const Duration later = 2s;
  laser->advance(later);
  std::size_t scans = 0;
  for (const auto& telegram : laser->take_output()) scans += telegram.bytes.size() > 100 ? 1 : 0;
  ASSERT_GT(scans, 0u);
  EXPECT_GE(asked, static_cast<int>(scans));
}

}  // namespace emulator_catalog_test
}  // namespace playerkit::emulators
