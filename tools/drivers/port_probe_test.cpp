#include "port_probe.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <sstream>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/p2os/p2os_robot_emulator.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "hardware/p2os/commands.hpp"
#include "links/open_link.hpp"
#include "links/pseudo_terminal.hpp"
#include "links/serial_link.hpp"

namespace playerkit::player_drivers {
namespace port_probe_test {

using namespace std::chrono_literals;

emulators::EmulatorRunner emulated(const std::string& name, const emulators::EmulatorOptionValues& options = {},
                                   emulators::Endpoint endpoint = emulators::PtyEndpoint{}) {
  return emulators::EmulatorRunner(emulators::make_emulator(name, options), endpoint);
}

ProbeResult probe(const std::string& port, ProbeSettings settings = {}) {
  return probe_port(port, settings, [] { return false; });
}

TEST(PortProbe, FindsAPioneerListeningAtANonDefaultBaud) {
  auto robot = emulated("p2os", {{"baud", "38400"}, {"model", "p3at"}, {"name", "rover"}});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "p2os");
  EXPECT_EQ(result.found->model, "Pioneer p3at \"rover\"");
  EXPECT_EQ(result.baud, 38400);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"p2os_position\" port \"" + robot.device_path() + "\" )");
}

TEST(PortProbe, FindsAnLms200AtItsPowerUpSpeed) {
  auto laser = emulated("sicklms200");
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sicklms200");
  EXPECT_EQ(result.found->model, "LMS200;30106");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "laser:0 ( driver \"sicklms200\" port \"" + laser.device_path() + "\" )");
  EXPECT_TRUE(result.note.empty()) << result.note;
}

TEST(PortProbe, FindsAPls) {
  auto laser = emulated("sickpls");
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sickpls");
  EXPECT_EQ(result.found->model, "PLS");
  EXPECT_EQ(result.baud, 9600);
}

TEST(PortProbe, FindsALaserLeftAt500000AndSaysTheDriverWillNot) {
  auto laser = emulated("sicklms200", {{"baud", "500000"}, {"type", "LMS291-S05"}});
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "LMS291-S05");
  EXPECT_EQ(result.baud, 500000);
  EXPECT_NE(result.note.find("power-cycle it"), std::string::npos) << result.note;
}

TEST(PortProbe, ClosesARobotStillConnectedFromAnEarlierSession) {
  auto robot = emulated("p2os");
  // An earlier session synchronised and opened the robot and still has the
  // port open (without a lock), so the robot keeps sending SIPs: a real
  // robot never notices a port being closed.
  auto session = links::open_link(robot.device_path(), {.baud = 9600, .exclusive = false});
  ASSERT_TRUE(probe_p2os(*session, {links::deadline_in(2s), links::deadline_in(4s)}));
  namespace p2os = hardware::p2os;
  session->write_all(p2os::command_frame(p2os::Command::plain(p2os::command::open)), links::deadline_in(1s));
  for (int i = 0; i < 100 && !robot.with_emulator<emulators::DeviceEmulator>([](emulators::DeviceEmulator& e) {
                                return e.describe().find("connected,") != std::string::npos;
                              });
       ++i) {
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_TRUE(robot.with_emulator<emulators::P2osRobotEmulator>([](emulators::P2osRobotEmulator& e) {
    return e.connected();
  })) << robot.with_emulator<emulators::DeviceEmulator>([](emulators::DeviceEmulator& e) { return e.describe(); });
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->model, "Pioneer p3dx \"playerkit\"");
  // Command 2 is SYNC2 and CLOSE: two handshakes and the CLOSE in between.
  EXPECT_EQ(robot.with_emulator<emulators::P2osRobotEmulator>(
                [](emulators::P2osRobotEmulator& e) { return e.packets_received(p2os::command::close); }),
            3u);
}

TEST(PortProbe, AsksOnceOverTcp) {
  auto laser = emulated("sicklms200", {}, emulators::TcpEndpoint{});
  const ProbeResult result = probe(laser.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "sicklms200");
  EXPECT_EQ(result.baud, 0);
  std::ostringstream text;
  write_probe_result(result, false, text);
  EXPECT_EQ(text.str(), laser.device_path() + ": sicklms200, LMS200;30106\n    " + result.config_line + "\n");
}

TEST(PortProbe, NothingBehindAPortIsNotAPortProblem) {
  links::PseudoTerminal silent;
  ProbeSettings quick;
  quick.first_reply = 50ms;
  std::vector<std::string> progress;
  quick.progress = [&progress](std::string_view line) { progress.emplace_back(line); };
  const ProbeResult result = probe(silent.slave_path(), quick);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + silent.slave_path() +
                                     " (tried SICK LMS 200 / PLS at 9600, 38400, 19200, 500000 baud and P2OS at 9600, "
                                     "38400, 19200, 115200, 57600 baud)",
                                 0),
            0u)
      << result.problem;
  EXPECT_EQ(progress.size(), probe_attempts(true).size());
  EXPECT_EQ(progress.front(), silent.slave_path() + ": SICK (LMS password) at 9600 8N1: no answer");
}

TEST(PortProbe, AMissingPortSaysSoWithoutOpeningAnything) {
  const std::string missing = "/tmp/player_drivers_port_probe_test_" + std::to_string(::getpid()) + "_nothing";
  const ProbeResult result = probe(missing);
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no such port " + missing, 0), 0u) << result.problem;
  std::ostringstream json;
  write_probe_result(result, true, json);
  const auto line = nlohmann::json::parse(json.str());
  EXPECT_EQ(line["found"], false);
  EXPECT_EQ(line["port_unusable"], true);
}

TEST(PortProbe, ABusyPortNamesItsHolder) {
  auto laser = emulated("sicklms200");
  const auto holder = links::SerialLink::open(laser.device_path(), {.baud = 9600});
  const ProbeResult result = probe(laser.device_path());
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_NE(result.problem.find("is busy: held by pid " + std::to_string(::getpid())), std::string::npos)
      << result.problem;
}

TEST(PortProbe, AStopEndsTheProbe) {
  links::PseudoTerminal silent;
  const ProbeResult result = probe_port(silent.slave_path(), {}, [] { return true; });
  EXPECT_TRUE(result.interrupted);
  EXPECT_FALSE(result.found);
}

TEST(PortProbe, TextReport) {
  ProbeResult result;
  result.port = "/dev/ttyUSB0";
  result.found = Identification{"p2os", "Pioneer p3dx \"robot\""};
  result.baud = 9600;
  result.config_line = "position:0 ( driver \"p2os_position\" port \"/dev/ttyUSB0\" )";
  result.note = "a note";
  std::ostringstream text;
  write_probe_result(result, false, text);
  EXPECT_EQ(text.str(),
            "/dev/ttyUSB0: p2os at 9600 baud, Pioneer p3dx \"robot\"\n"
            "    position:0 ( driver \"p2os_position\" port \"/dev/ttyUSB0\" )\n"
            "    (a note)\n");
}

}  // namespace port_probe_test
}  // namespace playerkit::player_drivers
