// The drivers as registered, and their options read from config text in
// 1.5's form (no robot is opened: nothing subscribes).
#include <gtest/gtest.h>


#include "config/errors.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "families/p2os/driver/p2os_options.hpp"
#include "families/p2os/driver/p2os_test_support.hpp"

namespace playerkit::drivers {
namespace p2os_options_test {

using namespace p2os_testing;

TEST(P2osDrivers, AllElevenAreRegisteredWithTheirInterfacesAccessAndDocs) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  struct Expected {
    std::string_view name;
    std::uint16_t interface;
    protocol::Access access;
  };
  const std::vector<Expected> expected = {
      {"p2os_position", protocol::kPositionCode, protocol::Access::kAll},
      {"p2os_sonar", protocol::kSonarCode, protocol::Access::kRead},
      {"p2os_gripper", protocol::kGripperCode, protocol::Access::kAll},
      {"p2os_power", protocol::kPowerCode, protocol::Access::kRead},
      {"p2os_bumper", protocol::kBumperCode, protocol::Access::kRead},
      {"p2os_aio", protocol::kAioCode, protocol::Access::kRead},
      {"p2os_dio", protocol::kDioCode, protocol::Access::kRead},
      {"p2os_cmucam", protocol::kBlobfinderCode, protocol::Access::kRead},
      {"p2os_compass", protocol::kPositionCode, protocol::Access::kRead},
      {"p2os_gyro", protocol::kPositionCode, protocol::Access::kRead},
      {"p2os_sound", protocol::kSoundCode, protocol::Access::kAll},
  };
  for (const Expected& e : expected) {
    const core::DriverSpec* spec = registry.find(e.name);
    ASSERT_NE(spec, nullptr) << e.name;
    EXPECT_EQ(spec->family, "p2os");
    EXPECT_EQ(spec->interfaces, std::vector<std::uint16_t>{e.interface}) << e.name;
    EXPECT_EQ(spec->access, e.access) << e.name;
    EXPECT_GE(spec->limits.request_queue, 2u) << e.name << ": 1.5's one shared slot gave ERR";
    EXPECT_EQ(spec->doc.manual_section, "7.30");
    EXPECT_TRUE(spec->doc.needs_hardware);
    EXPECT_FALSE(spec->doc.requests.empty()) << e.name;
    EXPECT_EQ(spec->doc.option_rows().front().name, "port");
    EXPECT_FALSE(spec->summary.empty());

    // Every example section is a valid configuration.
    testing::BuiltinDevices builtin;
    EXPECT_NO_THROW(builtin.load(spec->doc.example + "\n")) << spec->doc.example;
  }
  EXPECT_EQ(registry.find("p2os_position")->doc.option_rows().back().name, "use_vel_band");
}

TEST(P2osOptions, APortOnAnyOneSectionServesTheWholeRobotThroughOneConnection) {
  RobotDevices devices("/dev/ttyUSB7",
                       "position:0 ( driver \"p2os_position\" )\n"
                       "sonar:0 ( driver \"p2os_sonar\" port \"$PORT\" )\n"
                       "power:0 ( driver \"p2os_power\" )\n");
  p2os::P2osConnection& connection = devices.connection(devices.position());
  EXPECT_EQ(&connection, &devices.connection(devices.sonar()));
  EXPECT_EQ(&connection, &devices.connection(devices.power()));
  EXPECT_EQ(connection.options().port, "/dev/ttyUSB7");
  EXPECT_EQ(devices.builtin.devices.connections().size(), 1u);
}

TEST(P2osOptions, WithoutAPortItIsTtyS0) {
  RobotDevices devices("", "position:0 ( driver \"p2os_position\" )\n");
  EXPECT_EQ(devices.connection(devices.position()).options().port, "/dev/ttyS0");
}

TEST(P2osOptions, RobotOptionsMayBeWrittenOnAnySection) {
  RobotDevices devices("/dev/ttyUSB0",
                       "position:0 ( driver \"p2os_position\" port \"$PORT\" max_xspeed 300 )\n"
                       "sonar:0 ( driver \"p2os_sonar\" joystick 1 radio 1 connect_timeout 2.5 sip_timeout 1 )\n");
  const p2os::RobotLinkOptions& options = devices.connection(devices.position()).options();
  EXPECT_TRUE(options.joystick);
  EXPECT_TRUE(options.radio);
  EXPECT_EQ(options.connect_timeout, std::chrono::milliseconds(2500));
  EXPECT_EQ(options.sip_timeout, std::chrono::milliseconds(1000));
  const auto& driver = dynamic_cast<p2os::P2osDeviceDriver&>(devices.position().driver());
  EXPECT_EQ(driver.limits().max_xspeed, 300);
  EXPECT_EQ(driver.limits().max_yawspeed, 100);
  EXPECT_FALSE(driver.limits().use_vel_band);
  EXPECT_TRUE(devices.builtin.devices.connections().size() == 1u);
}

TEST(P2osOptions, TwoRobotsOnTwoServerPortsHaveTwoConnections) {
  RobotDevices devices("/dev/ttyUSB0",
                       "position:0 ( driver \"p2os_position\" port \"/dev/ttyUSB0\" )\n"
                       "robot:6666 ( position:0 ( driver \"p2os_position\" port \"/dev/ttyUSB1\" ) )\n");
  EXPECT_EQ(devices.builtin.devices.connections().size(), 2u);
}

std::string config_error(const std::string& text) {
  try {
    RobotDevices devices("/dev/ttyUSB0", text);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(P2osOptions, BadOptionsAreConfigErrorsAtTheirValue) {
  EXPECT_NE(config_error("position:0 ( driver \"p2os_position\" port \"/dev/ttyS0\" )\n"
                         "sonar:0 ( driver \"p2os_sonar\" port \"/dev/ttyS1\" )\n")
                .find("test.cfg:2:"),
            std::string::npos);
  const std::string bad_tcp = config_error("sonar:0 ( driver \"p2os_sonar\" port \"tcp:robot\" )\n");
  EXPECT_NE(bad_tcp.find("test.cfg:1:"), std::string::npos) << bad_tcp;
  EXPECT_NE(bad_tcp.find("p2os_sonar: port is not a serial port or tcp:HOST:PORT"), std::string::npos) << bad_tcp;
  const std::string speed = config_error("position:0 ( driver \"p2os_position\" max_xspeed -5 )\n");
  EXPECT_NE(speed.find("test.cfg:1:"), std::string::npos) << speed;
  EXPECT_NE(speed.find("max_xspeed"), std::string::npos) << speed;
  const std::string timeout = config_error("sonar:0 ( driver \"p2os_sonar\" sip_timeout 0 )\n");
  EXPECT_NE(timeout.find("sip_timeout"), std::string::npos) << timeout;
  const std::string joystick = config_error(
      "position:0 ( driver \"p2os_position\" joystick 1 )\n"
      "sonar:0 ( driver \"p2os_sonar\" joystick 0 )\n");
  EXPECT_NE(joystick.find("test.cfg:2:"), std::string::npos) << joystick;
  EXPECT_NE(joystick.find("joystick 0 differs from 1 given at test.cfg:1:"), std::string::npos) << joystick;
}

TEST(P2osOptions, ABadTcpPortIsRefusedOnEverySectionThatWritesIt) {
  // The first section's port is fine, the second's cannot be opened: both are checked.
  const std::string error = config_error(
      "position:0 ( driver \"p2os_position\" )\n"
      "sonar:0 ( driver \"p2os_sonar\" port \"tcp:localhost:99999\" )\n");
  EXPECT_EQ(error.rfind("test.cfg:2:", 0), 0u) << error;
  EXPECT_NE(error.find("'99999' is not a TCP port (1..65535)"), std::string::npos) << error;
}

// The README's table is the schema's own (between "<!-- options
// p2os_position -->" and "<!-- end options -->").
TEST(P2osOptions, TheReadmeTableIsGeneratedFromTheSchema) {
  EXPECT_EQ(testing::readme_options_table(
                std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/p2os/driver/README.md", "p2os_position"),
            p2os::p2os_option_schema(p2os::P2osRole::position).markdown());
}

}  // namespace p2os_options_test
}  // namespace playerkit::drivers
