// What a section's word declares: robot:<port>[:<name>] or <interface>[:<index>].

#include "config/section_type.hpp"

#include <gtest/gtest.h>

#include "config/test_support.hpp"

namespace playerkit::config {
namespace section_type_test {

using testing::error_of;

const SourceLocation kWhere{"t.cfg", 4, 2};

DeviceType device(std::string_view type) {
  return std::get<DeviceType>(parse_section_type(type, kWhere));
}

RobotType robot(std::string_view type) {
  return std::get<RobotType>(parse_section_type(type, kWhere));
}

std::string error_for(std::string_view type) {
  return error_of([&] { (void)parse_section_type(type, kWhere); });
}

TEST(SectionType, InterfaceWithIndex) {
  const DeviceType laser = device("laser:3");
  EXPECT_EQ(laser.interface->code, protocol::kLaserCode);
  EXPECT_EQ(laser.index, 3);
  EXPECT_EQ(device("position3d:65535").index, 65535);
}

TEST(SectionType, IndexDefaultsToZero) {
  const DeviceType position = device("position");
  EXPECT_EQ(position.interface->code, protocol::kPositionCode);
  EXPECT_EQ(position.index, 0);
}

TEST(SectionType, EveryDeclarableInterfaceIsAccepted) {
  for (const protocol::InterfaceInfo& info : protocol::all_interfaces()) {
    if (info.default_driver.empty()) continue;
    EXPECT_EQ(device(std::string(info.name) + ":1").interface->code, info.code) << info.name;
  }
}

TEST(SectionType, RobotWithPortAndName) {
  const RobotType bob = robot("robot:6666:bob");
  EXPECT_EQ(bob.port, 6666);
  EXPECT_EQ(bob.name, "bob");
  EXPECT_EQ(robot("robot:7000").name, "");
  EXPECT_EQ(robot("robot:7000").port, 7000);
  EXPECT_EQ(robot("robot:7000:").name, "");
  EXPECT_EQ(robot("robot:7000:a:b").name, "a:b");
}

TEST(SectionType, RobotWithoutPortIsRejected) {
  const std::string expected =
      "t.cfg:4:2: robot section without a port: auto-assigning ports is not supported "
      "(write robot:<port> or robot:<port>:<name>)";
  EXPECT_EQ(error_for("robot"), expected);
  EXPECT_EQ(error_for("robot:"), expected);
  EXPECT_EQ(error_for("robot::bob"), expected);
}

TEST(SectionType, RobotPortMustBeANumberInRange) {
  EXPECT_EQ(error_for("robot:abc"),
            "t.cfg:4:2: invalid port 'abc' in 'robot:abc' (expected a number from 1 to 65535)");
  EXPECT_EQ(error_for("robot:0"),
            "t.cfg:4:2: invalid port '0' in 'robot:0' (expected a number from 1 to 65535)");
  EXPECT_EQ(
      error_for("robot:70000:x"),
      "t.cfg:4:2: invalid port '70000' in 'robot:70000:x' (expected a number from 1 to 65535)");
}

TEST(SectionType, IndexMustBeAPlainNumberInRange) {
  EXPECT_EQ(error_for("laser:x"),
            "t.cfg:4:2: invalid index 'x' in 'laser:x' (expected a number from 0 to 65535)");
  EXPECT_EQ(error_for("laser:1x"),
            "t.cfg:4:2: invalid index '1x' in 'laser:1x' (expected a number from 0 to 65535)");
  EXPECT_EQ(error_for("laser:-1"),
            "t.cfg:4:2: invalid index '-1' in 'laser:-1' (expected a number from 0 to 65535)");
  EXPECT_EQ(
      error_for("laser:65536"),
      "t.cfg:4:2: invalid index '65536' in 'laser:65536' (expected a number from 0 to 65535)");
  EXPECT_EQ(error_for("laser:"),
            "t.cfg:4:2: invalid index '' in 'laser:' (expected a number from 0 to 65535)");
  EXPECT_EQ(error_for("laser:0:1"),
            "t.cfg:4:2: invalid index '0:1' in 'laser:0:1' (expected a number from 0 to 65535)");
}

TEST(SectionType, UnknownInterfaceSuggestsTheClosestName) {
  EXPECT_EQ(error_for("lazer:0"), "t.cfg:4:2: unknown interface 'lazer' (did you mean 'laser'?)");
  EXPECT_EQ(error_for("Sonar"), "t.cfg:4:2: unknown interface 'Sonar' (did you mean 'sonar'?)");
  EXPECT_EQ(error_for("driver"), "t.cfg:4:2: unknown interface 'driver'");
}

TEST(SectionType, InterfacesWithoutDefaultDriverCannotBeDeclared) {
  for (const char* name : {"player", "idar", "idarturret", "descartes"}) {
    EXPECT_EQ(error_for(std::string(name) + ":0"), "t.cfg:4:2: interface '" + std::string(name) +
                                                       "' cannot be declared in a config file");
  }
}

TEST(SectionType, UndeclarableInterfacesAreNotSuggested) {
  // "playr" is one edit from "player", which cannot be declared anyway.
  EXPECT_EQ(error_for("playr:0"), "t.cfg:4:2: unknown interface 'playr'");
}

}  // namespace section_type_test
}  // namespace playerkit::config
