#include "core/robot_option.hpp"

#include <gtest/gtest.h>

#include <optional>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/device_table.hpp"

namespace playerkit::core {
namespace robot_option_test {

struct RobotOptionFixture : ::testing::Test {
  void load(std::string_view text) {
    config::LoadOptions options;
    options.driver_exists = [](std::string_view) { return true; };
    file = config::ConfigFile::parse(text, "robot.cfg", options);
  }
  // The option as the driver of device number `device` (config order) sees it.
  RobotOption port_for(std::size_t device) {
    const auto& declaration = file->devices().at(device);
    const DriverContext context{*file, file->section(declaration.section), {declaration.port, declaration.address},
                                "",    table,
                                clock, logger,
                                table.connections()};
    return robot_option(context, {"p2os_position", "p2os_sonar"}, "port", "/tmp/default-port");
  }
  std::optional<config::ConfigFile> file;
  DeviceTable table;
  ServerClock clock;
  Logger logger;
};

TEST_F(RobotOptionFixture, APortWrittenOnOneDeviceServesTheWholeRobot) {
  load("position:0 ( driver \"p2os_position\" )\n"
       "sonar:0 ( driver \"p2os_sonar\" port \"/tmp/robot-usb\" )\n");
  EXPECT_EQ(port_for(0).value, "/tmp/robot-usb");
  EXPECT_TRUE(port_for(0).given);
  EXPECT_EQ(port_for(1).value, "/tmp/robot-usb");
}

TEST_F(RobotOptionFixture, NoPortAnywhereGivesTheFallback) {
  load("position:0 ( driver \"p2os_position\" )\n");
  EXPECT_EQ(port_for(0).value, "/tmp/default-port");
  EXPECT_FALSE(port_for(0).given);
}

TEST_F(RobotOptionFixture, RobotsOnOtherServerPortsAndOtherFamiliesAreSeparate) {
  load("position:0 ( driver \"p2os_position\" port \"/tmp/robot-1\" )\n"
       "laser:0 ( driver \"sicklms200\" port \"/tmp/laser-2\" )\n"
       "robot:6666 ( position:0 ( driver \"p2os_position\" port \"/tmp/robot-3\" ) )\n");
  EXPECT_EQ(port_for(0).value, "/tmp/robot-1");
  EXPECT_EQ(port_for(2).value, "/tmp/robot-3");
}

TEST_F(RobotOptionFixture, TwoDifferentPortsForOneRobotAreAnErrorAtTheSecond) {
  load("position:0 ( driver \"p2os_position\" port \"/tmp/robot-0\" )\n"
       "sonar:0 ( driver \"p2os_sonar\" port \"/tmp/robot-1\" )\n");
  try {
    (void)port_for(0);
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& error) {
    EXPECT_EQ(error.where().line, 2);
    EXPECT_NE(error.message().find("differs from \"/tmp/robot-0\" given at robot.cfg:1:"), std::string::npos)
        << error.what();
  }
}

TEST_F(RobotOptionFixture, TheSameValueTwiceIsFine) {
  load("position:0 ( driver \"p2os_position\" port \"/tmp/robot-0\" )\n"
       "sonar:0 ( driver \"p2os_sonar\" port \"/tmp/robot-0\" )\n");
  EXPECT_EQ(port_for(1).value, "/tmp/robot-0");
}

}  // namespace robot_option_test
}  // namespace playerkit::core
