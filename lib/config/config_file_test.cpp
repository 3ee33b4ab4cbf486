// Device declarations, ports and warnings (server-behaviour.md §9.4).

#include "config/config_file.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "config/test_support.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::config {
namespace config_file_test {

using testing::data_path;
using testing::error_of;

ConfigFile parse(std::string_view text, const LoadOptions& options = {}) {
  return ConfigFile::parse(text, "t.cfg", options);
}

std::string error_for(std::string_view text, const LoadOptions& options = {}) {
  return error_of([&] { (void)parse(text, options); });
}

std::vector<std::string> messages_of(const std::vector<Warning>& warnings) {
  std::vector<std::string> messages;
  for (const Warning& warning : warnings) messages.push_back(warning.to_string());
  return messages;
}

TEST(ConfigFile, DeviceFromASection) {
  const ConfigFile config = parse("\nlaser:1 ( driver \"sickpls\" port \"/dev/ttyS2\" )\n");
  ASSERT_EQ(config.devices().size(), 1u);
  const DeviceDeclaration& laser = config.devices()[0];
  EXPECT_EQ(laser.address, (protocol::DeviceAddress{protocol::kLaserCode, 1}));
  EXPECT_EQ(laser.interface_name, "laser");
  EXPECT_EQ(laser.driver, "sickpls");
  EXPECT_FALSE(laser.alwayson);
  EXPECT_EQ(laser.port, 6665);
  EXPECT_EQ(laser.robot_name, "");
  EXPECT_EQ(laser.section, 0u);
  EXPECT_EQ(laser.where, (SourceLocation{"t.cfg", 2, 1}));
  EXPECT_EQ(config.section(laser.section).read_string("port", ""), "/dev/ttyS2");
  EXPECT_EQ(config.filename(), "t.cfg");
}

TEST(ConfigFile, DefaultDriverWhenNoneIsGiven) {
  const ConfigFile config =
      parse("laser:0 ()\nnull:0 ()\nlocalize:0 ()\ncomms:0 ()\nposition ()\n");
  ASSERT_EQ(config.devices().size(), 5u);
  EXPECT_EQ(config.devices()[0].driver, "sicklms200");
  EXPECT_EQ(config.devices()[1].driver, "writelog");
  EXPECT_EQ(config.devices()[2].driver, "amcl");
  EXPECT_EQ(config.devices()[3].driver, "udpbroadcast");
  EXPECT_EQ(config.devices()[4].driver, "p2os_position");
}

TEST(ConfigFile, EveryDeclarableInterfaceGetsItsDefaultDriver) {
  for (const protocol::InterfaceInfo& info : protocol::all_interfaces()) {
    if (info.default_driver.empty()) continue;
    const ConfigFile config = parse(std::string(info.name) + ":2 ()");
    ASSERT_EQ(config.devices().size(), 1u) << info.name;
    EXPECT_EQ(config.devices()[0].driver, info.default_driver);
    EXPECT_EQ(config.devices()[0].address, (protocol::DeviceAddress{info.code, 2}));
  }
}

TEST(ConfigFile, IndexDefaultsToZero) {
  const ConfigFile config = parse("sonar ( driver \"p2os_sonar\" )");
  EXPECT_EQ(config.devices().at(0).address, (protocol::DeviceAddress{protocol::kSonarCode, 0}));
}

TEST(ConfigFile, Alwayson) {
  const ConfigFile config = parse(
      "null:0 ( alwayson 1 )\nnull:1 ( alwayson 0 )\nnull:2 ( alwayson \"yes\" )\nnull:3 ( "
      "alwayson 2 )");
  ASSERT_EQ(config.devices().size(), 4u);
  EXPECT_TRUE(config.devices()[0].alwayson);
  EXPECT_FALSE(config.devices()[1].alwayson);
  EXPECT_FALSE(config.devices()[2].alwayson);  // atoi("yes") is 0
  EXPECT_TRUE(config.devices()[3].alwayson);
}

TEST(ConfigFile, LaterDeclarationReplacesTheEarlierInItsPlace) {
  const ConfigFile config = parse(
      "laser:0 ( driver \"sicklms200\" port \"/dev/ttyS1\" )\n"
      "sonar:0 ()\n"
      "laser:0 ( driver \"sickpls\" )\n");
  ASSERT_EQ(config.devices().size(), 2u);
  EXPECT_EQ(config.devices()[0].interface_name, "laser");
  EXPECT_EQ(config.devices()[0].driver, "sickpls");
  EXPECT_EQ(config.devices()[0].section, 2u);
  EXPECT_EQ(config.devices()[0].where, (SourceLocation{"t.cfg", 3, 1}));
  EXPECT_EQ(config.devices()[1].interface_name, "sonar");
  EXPECT_EQ(messages_of(config.warnings()),
            (std::vector<std::string>{
                "t.cfg:3:1: warning: laser:0 on port 6665 replaces the earlier declaration at "
                "t.cfg:1:1"}));
  // The replaced section's options are covered by that warning.
  EXPECT_TRUE(config.unused_properties().empty());
}

TEST(ConfigFile, SameDeviceOnDifferentPortsIsNotAReplacement) {
  const ConfigFile config = parse("laser:0 ()\nrobot:7000 ( laser:0 () )\n");
  ASSERT_EQ(config.devices().size(), 2u);
  EXPECT_EQ(config.devices()[0].port, 6665);
  EXPECT_EQ(config.devices()[1].port, 7000);
  EXPECT_TRUE(config.warnings().empty());
}

TEST(ConfigFile, RobotSectionSetsPortAndName) {
  const ConfigFile config = parse("robot:6666:bob ( laser:0 () )");
  ASSERT_EQ(config.devices().size(), 1u);
  EXPECT_EQ(config.devices()[0].port, 6666);
  EXPECT_EQ(config.devices()[0].robot_name, "bob");
  EXPECT_EQ(config.devices()[0].section, 1u);
  EXPECT_EQ(config.section(1).parent(), 0);
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{6666}));
}

TEST(ConfigFile, RobotSectionAppliesToEveryFollowingDevice) {
  // As in 1.5, a robot section is a switch, not a scope: the sonar after it,
  // outside its parentheses, is on 7000 too.
  const ConfigFile config = parse(
      "position:0 ()\n"
      "robot:7000:bee ( laser:0 () )\n"
      "sonar:0 ()\n"
      "robot:7001 ( )\n"
      "laser:0 ()\n");
  ASSERT_EQ(config.devices().size(), 4u);
  EXPECT_EQ(config.devices()[0].port, 6665);
  EXPECT_EQ(config.devices()[0].robot_name, "");
  EXPECT_EQ(config.devices()[1].port, 7000);
  EXPECT_EQ(config.devices()[2].port, 7000);
  EXPECT_EQ(config.devices()[2].robot_name, "bee");
  EXPECT_EQ(config.devices()[3].port, 7001);
  EXPECT_EQ(config.devices()[3].robot_name, "");
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{6665, 7000, 7001}));
}

TEST(ConfigFile, PortsInOrderOfFirstUse) {
  EXPECT_EQ(parse("robot:7000 ()\nrobot:6666 ( laser:0 () )\nrobot:7000 ( sonar:0 () )").ports(),
            (std::vector<std::uint16_t>{7000, 6666}));
  EXPECT_TRUE(parse("").ports().empty());
  EXPECT_TRUE(parse("define x laser ( )").ports().empty());
}

TEST(ConfigFile, DefaultPortComesFromTheOptions) {
  LoadOptions options;
  options.default_port = 7000;
  const ConfigFile config = parse("position:0 ()\nlaser:0 ()", options);
  EXPECT_EQ(config.devices()[0].port, 7000);
  EXPECT_EQ(config.devices()[1].port, 7000);
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{7000}));
}

TEST(ConfigFile, UnknownDriverSuggestsTheClosestKnownOne) {
  EXPECT_EQ(error_for("laser:0 ( driver \"sicklms2000\" )"),
            "t.cfg:1:18: unknown driver 'sicklms2000' for laser:0 (did you mean 'sicklms200'?)");
  EXPECT_EQ(error_for("localize:0 ( driver \"adaptive_mcl\" )"),
            "t.cfg:1:21: unknown driver 'adaptive_mcl' for localize:0");
  EXPECT_EQ(error_for("position:2 ( driver \"p2os\" )"),
            "t.cfg:1:21: unknown driver 'p2os' for position:2");
}

TEST(ConfigFile, DriverExistsOptionDecidesWhichDriversAreAvailable) {
  LoadOptions options;
  options.driver_exists = [](std::string_view name) {
    return name == "p2os_position" || name == "my_plugin";
  };
  const ConfigFile config = parse("position:0 ()\nlaser:0 ( driver \"my_plugin\" )", options);
  EXPECT_EQ(config.devices().at(1).driver, "my_plugin");
  // A default driver that is not available is reported at the section.
  EXPECT_EQ(error_for("position:0 ()\n  laser:0 ( port \"x\" )", options),
            "t.cfg:2:3: unknown driver 'sicklms200' for laser:0 (the default driver of 'laser')");
  // Only available drivers are suggested.
  EXPECT_EQ(
      error_for("laser:0 ( driver \"p2os_positio\" )", options),
      "t.cfg:1:18: unknown driver 'p2os_positio' for laser:0 (did you mean 'p2os_position'?)");
  EXPECT_EQ(error_for("laser:0 ( driver \"sicklms2000\" )", options),
            "t.cfg:1:18: unknown driver 'sicklms2000' for laser:0");
}

TEST(ConfigFile, SectionErrorsComeThroughWithTheSectionLocation) {
  EXPECT_EQ(error_for("position:0 ()\n  lazer:0 ()"),
            "t.cfg:2:3: unknown interface 'lazer' (did you mean 'laser'?)");
  EXPECT_EQ(error_for("robot ( laser:0 () )"),
            "t.cfg:1:1: robot section without a port: auto-assigning ports is not supported "
            "(write robot:<port> or robot:<port>:<name>)");
}

TEST(ConfigFile, Units) {
  const ConfigFile config = parse("unit_length \"mm\"\nunit_angle \"radians\"\n");
  EXPECT_DOUBLE_EQ(config.unit_length(), 0.001);
  EXPECT_EQ(config.unit_angle(), 1.0);
  const ConfigFile defaults = parse("");
  EXPECT_EQ(defaults.unit_length(), 1.0);
  EXPECT_DOUBLE_EQ(defaults.unit_angle(), std::numbers::pi / 180.0);
}

TEST(ConfigFile, UnusedPropertiesNameThePropertyAndItsLine) {
  const ConfigFile config = parse(
      "laser:0 (\n"
      "  driver \"sicklms200\"\n"
      "  alwayson 1\n"
      "  port \"/dev/ttyS1\"\n"
      "  prot 38400\n"
      ")\n"
      "robot:7000 ( driver \"p2os_position\" )\n");
  EXPECT_EQ(
      messages_of(config.unused_properties()),
      (std::vector<std::string>{"t.cfg:4:3: warning: property 'port' is defined but not used",
                                "t.cfg:5:3: warning: property 'prot' is defined but not used",
                                "t.cfg:7:14: warning: property 'driver' is defined but not used"}));
  // The driver reads its options; only the typo is left.
  (void)config.section(0).read_string("port", "/dev/ttyS0");
  EXPECT_EQ(
      messages_of(config.unused_properties()),
      (std::vector<std::string>{"t.cfg:5:3: warning: property 'prot' is defined but not used",
                                "t.cfg:7:14: warning: property 'driver' is defined but not used"}));
}

TEST(ConfigFile, UnusedMacroPropertyIsReportedOnceAtTheDefine) {
  const ConfigFile config = parse(
      "define pioneer2 position ( driver \"p2os_position\" radoi 1 )\n"
      "pioneer2 ()\n"
      "robot:7000 ( pioneer2 () )\n");
  EXPECT_EQ(
      messages_of(config.unused_properties()),
      (std::vector<std::string>{"t.cfg:1:51: warning: property 'radoi' is defined but not used"}));
}

TEST(ConfigFile, WarningToString) {
  EXPECT_EQ((Warning{SourceLocation{"a.cfg", 2, 5}, "something odd"}).to_string(),
            "a.cfg:2:5: warning: something odd");
}

TEST(ConfigFile, LoadReadsTheFile) {
  const std::string path = data_path("manual-4.1-pioneer.cfg");
  const ConfigFile config = ConfigFile::load(path);
  EXPECT_EQ(config.filename(), path);
  EXPECT_EQ(config.devices().size(), 4u);
  EXPECT_EQ(config.devices()[0].where, (SourceLocation{path, 4, 1}));
}

TEST(ConfigFile, LoadOfAMissingFileNamesIt) {
  const std::string path = data_path("no-such-file.cfg");
  EXPECT_EQ(error_of([&] { (void)ConfigFile::load(path); }), path + ": cannot read config file: no such file");
}

TEST(ConfigFile, ParseResolvesIncludesAgainstTheGivenName) {
  const ConfigFile config = ConfigFile::parse("include \"sub/defines.cfg\"\npioneer2 ( )\n",
                                              data_path("includes/virtual.cfg"));
  ASSERT_EQ(config.devices().size(), 1u);
  EXPECT_EQ(config.devices()[0].driver, "p2os_position");
}

TEST(ConfigFile, UnitsApplyToIncludedFiles) {
  // nested-main.cfg sets cm after including sub/robot.cfg and sub/defines.cfg.
  const ConfigFile config = ConfigFile::load(data_path("includes/nested-main.cfg"));
  ASSERT_EQ(config.devices().size(), 2u);
  const Section& sonar = config.section(config.devices()[0].section);
  EXPECT_EQ(sonar.type(), "sonar:0");
  EXPECT_DOUBLE_EQ(sonar.read_length("range_max", 0), 5.0);
  const Section& pioneer = config.section(config.devices()[1].section);
  EXPECT_EQ(config.devices()[1].driver, "p2os_position");
  EXPECT_DOUBLE_EQ(pioneer.read_length("robot_radius", 0), 0.25);
  EXPECT_EQ(pioneer.read_string("port", ""), "/dev/ttyS1");
  EXPECT_EQ(sonar.read_filename("map", ""), data_path("includes/sub/maps/cave.pgm"));
}

TEST(ConfigFile, ReadmeExample) {
  // tests/data/config/readme-example.cfg is the example of lib/config/README.md.
  const ConfigFile config = ConfigFile::load(data_path("readme-example.cfg"));
  ASSERT_EQ(config.devices().size(), 3u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"position", "p2os_position"}, {"laser", "sicklms200"}, {"null", "writelog"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const DeviceDeclaration& device = config.devices()[i];
    EXPECT_EQ(device.interface_name, expected[i].first);
    EXPECT_EQ(device.driver, expected[i].second);
    EXPECT_EQ(device.port, 6666);
    EXPECT_EQ(device.robot_name, "bob");
  }
  EXPECT_TRUE(config.devices()[2].alwayson);
  EXPECT_EQ(config.section(config.devices()[0].section).read_string("port", ""), "/dev/ttyS1");
  EXPECT_DOUBLE_EQ(config.section(config.devices()[1].section).read_tuple_length("pose", 0, 0),
                   0.1);
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{6666}));
}

}  // namespace config_file_test
}  // namespace playerkit::config
