// The nomad drivers against the emulated Nomad 200 on a loopback TCP port,
// through the kit's driver harness: the reference's setup, the cycle both
// ways, both forms of the server's address, the position and sonar views,
// bad options at their place, and the robot stopped at shutdown.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "families/nomad/driver/nomad_options.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/nomad.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::testing {
namespace nomad_driver_test {

using emulators::NomadEmulator;
namespace type = hardware::nomad::message_type;

struct NomadDriverTest : ::testing::Test {
  explicit NomadDriverTest(LineOptions options = {.tcp = true})
      : robot([] { return std::make_unique<NomadEmulator>(); }, std::move(options)) {}

  core::Device& nomad() { return devices.device(protocol::kNomadCode); }
  core::Device& position() { return devices.device(protocol::kPositionCode); }
  core::Device& sonar() { return devices.device(protocol::kSonarCode); }
  void start(const std::string& extra = "") {
    devices.load("nomad:0 ( driver \"nomad\" port \"$PORT\" " + extra + ")\n", robot.port());
    ASSERT_TRUE(nomad().subscribe()) << devices.log.all();
  }
  void start_views(const std::string& position_options = "") {
    devices.load("nomad:0 ( driver \"nomad\" port \"$PORT\" )\n"
                 "position:0 ( driver \"nomad_position\" " + position_options + ")\n"
                 "sonar:0 ( driver \"nomad_sonar\" nomad_index 0 )\n",
                 robot.port());
    // The server's event loop, for the views (drivers without a thread).
    event_loop = std::jthread([this](const std::stop_token& stop) {
      while (!stop.stop_requested()) {
        position().update();
        sonar().update();
        std::this_thread::sleep_for(5ms);
      }
    });
  }
  std::int32_t emulated(std::int32_t hardware::nomad::RobotState::*field) {
    return robot.with([field](NomadEmulator& e) { return e.state().*field; });
  }

  EmulatedLine<NomadEmulator> robot;
  ConfiguredDevices devices;
  std::jthread event_loop;  // last: stopped before the devices go
};

TEST_F(NomadDriverTest, SetsTheRobotUpAsPlayerDidAndPublishesItsState) {
  start();
  for (const std::int16_t step : {type::kConnectRobot, type::kSensorMask, type::kCommandTimeout, type::kZero,
                                  type::kAccelerations, type::kSpeeds}) {
    EXPECT_EQ(robot.with([step](NomadEmulator& e) { return e.requests_of(step); }), 1U) << step;
  }
  const auto data = next_data<protocol::NomadData>(nomad());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->x, 0);
  EXPECT_EQ(data->sonar[0], 6477);  // nothing within 255 inches
  EXPECT_EQ(data->ir[15], 914);     // nor within the infrared's 36
  EXPECT_TRUE(robot.wait_until([](NomadEmulator& e) { return e.requests_of(type::kGetState) > 2; }));
  EXPECT_EQ(robot.with([](NomadEmulator& e) { return e.requests_of(type::kVelocityMode); }),
            robot.with([](NomadEmulator& e) { return e.requests_of(type::kGetState); }));
}

TEST_F(NomadDriverTest, DrivesAsCommandedAndReportsWhereItGot) {
  start();
  write_command(nomad(), protocol::NomadCommand{.vel_trans = 254, .vel_steer = 10, .vel_turret = -5});
  ASSERT_TRUE(robot.wait_until([](NomadEmulator& e) { return e.state().translation_velocity == 100; }));
  EXPECT_EQ(emulated(&hardware::nomad::RobotState::steering_velocity), 100);
  EXPECT_EQ(emulated(&hardware::nomad::RobotState::turret_velocity), -50);
  const auto data = data_when<protocol::NomadData>(nomad(), [](const auto& d) { return d.x > 100 && d.a > 3; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->vel_trans, 254);
  EXPECT_EQ(data->vel_steer, 10);
  EXPECT_EQ(data->vel_turret, -5);
  EXPECT_GT(data->y, 0);  // the steering has turned it to the left
}

TEST_F(NomadDriverTest, TheRobotIsStoppedWhenTheLastClientLeaves) {
  start();
  write_command(nomad(), protocol::NomadCommand{.vel_trans = 300, .vel_steer = 0, .vel_turret = 0});
  ASSERT_TRUE(robot.wait_until([](NomadEmulator& e) { return e.state().translation_velocity != 0; }));
  nomad().unsubscribe();
  EXPECT_EQ(emulated(&hardware::nomad::RobotState::translation_velocity), 0);
}

TEST_F(NomadDriverTest, HostAndPortAsSeparateOptions) {
  const std::string port = robot.port();  // tcp:127.0.0.1:N
  const std::string number = port.substr(port.rfind(':') + 1);
  start("host \"127.0.0.1\" port " + number + " serial_device \"/tmp/nomad-direct-serial\" serial_speed 9600 ");
  EXPECT_TRUE(next_data<protocol::NomadData>(nomad()));
}

TEST_F(NomadDriverTest, RequestsToTheNomadDeviceAreRefusedAs15Did) {
  start();
  EXPECT_TRUE(nacked(ask(nomad(), std::vector<std::uint8_t>{1})));
}

TEST_F(NomadDriverTest, ThePositionViewDrivesTheRobotAndTurnsTheTurretWithTheSteering) {
  start_views();
  ASSERT_TRUE(position().subscribe()) << devices.log.all();
  write_command(position(), protocol::PositionCommand{.xpos = 0, .ypos = 0, .yaw = 0, .xspeed = 254, .yspeed = 0,
                                                      .yawspeed = 15, .state = 1, .type = 0});
  ASSERT_TRUE(robot.wait_until([](NomadEmulator& e) { return e.state().steering_velocity == 150; }))
      << devices.log.all();
  EXPECT_EQ(emulated(&hardware::nomad::RobotState::turret_velocity), 150);
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 50; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xspeed, 254);
  EXPECT_EQ(data->yawspeed, 15);
  EXPECT_GT(data->yaw, 0);
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size[0], 800);
  EXPECT_EQ(geom.size[1], 800);
  EXPECT_EQ(geom.pose[0], 0);
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{protocol::kPositionResetOdomReq})));
}

TEST_F(NomadDriverTest, TheSonarViewGivesSixteenRangesAndTheirRing) {
  start_views("nomad_index 0 ");
  ASSERT_TRUE(sonar().subscribe()) << devices.log.all();
  const auto data = next_data<protocol::SonarData>(sonar());
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_EQ(data->range_count, 16);
  EXPECT_EQ(data->ranges[7], 6477);
  const auto reply = ask(sonar(), std::vector<std::uint8_t>{protocol::kSonarGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geom = protocol::decode<protocol::SonarGeom>(reply->payload);
  EXPECT_EQ(geom.pose_count, 16);
  EXPECT_EQ(geom.poses[0][0], 400);
  EXPECT_EQ(geom.poses[4][1], 400);
  EXPECT_EQ(geom.poses[2][2], 45);
  EXPECT_EQ(geom.poses[16][0], 0);
  sonar().unsubscribe();
  EXPECT_FALSE(robot.wait_until([](NomadEmulator& e) { return e.state().translation_velocity != 0; }, 100ms));
}

std::string load_error(const std::string& text) {
  ConfiguredDevices devices;
  try {
    devices.load(text);
    for (core::Device* device : devices.builtin.devices.all()) device->driver().check();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(NomadOptions, BadValuesAreRefusedAtTheirPlace) {
  const std::string bad_port = load_error("nomad:0 ( driver \"nomad\" port 99999 )\n");
  EXPECT_NE(bad_port.find(":1:31: nomad: port must be the Nomad server's TCP port"), std::string::npos) << bad_port;
  const std::string two_hosts = load_error("nomad:0 ( driver \"nomad\" host \"a\" port \"tcp:b:7019\" )\n");
  EXPECT_NE(two_hosts.find("give one"), std::string::npos) << two_hosts;
  const std::string no_nomad = load_error("position:0 ( driver \"nomad_position\" nomad_index 2 )\n");
  EXPECT_NE(no_nomad.find("no nomad:2 on port 6665"), std::string::npos) << no_nomad;
  const std::string other_port =
      load_error("nomad:0 ( driver \"nomad\" )\nposition:0 ( driver \"nomad_position\" nomad_port 7000 )\n");
  EXPECT_NE(other_port.find("no nomad:0 on port 7000"), std::string::npos) << other_port;
}

TEST(NomadOptions, TheServerIsOnThisMachineAtPort7019ByDefault) {
  const auto config = config::ConfigFile::parse("nomad:0 ( driver \"nomad\" )\n", "test.cfg");
  const auto settings = nomad::read_nomad_settings(config.sections().back(), "robothost");
  EXPECT_EQ(settings.link, "tcp:robothost:7019");
  EXPECT_FALSE(nomad::machine_name().empty());
  EXPECT_EQ(nomad::server_port_problem("7019"), "");
  EXPECT_EQ(nomad::server_port_problem("tcp:[::1]:7019"), "");
  EXPECT_NE(nomad::server_port_problem("/tmp/nomad-direct-serial"), "");
}

}  // namespace nomad_driver_test
}  // namespace playerkit::drivers::testing
