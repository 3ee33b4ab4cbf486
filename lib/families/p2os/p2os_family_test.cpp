// The p2os family as the tools see it: its emulator kind (options, defaults,
// refusals) and its probe, against the emulated Pioneer.

#include "families/p2os/p2os_family.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "families/p2os/p2os_probe.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/port_probe.hpp"
#include "links/open_link.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::families {
namespace p2os_family_test {

using namespace std::chrono_literals;

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(p2os_family().emulators); }

FamilyRegistry only_p2os() {
  FamilyRegistry registry;
  registry.add(p2os_family());
  return registry;
}

std::unique_ptr<emulators::DeviceEmulator> make(const emulators::EmulatorOptionValues& options) {
  return catalog().make("p2os", options);
}

// The message of the std::invalid_argument `make` throws ("" when it does not).
std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)make(options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

emulators::EmulatorRunner emulated(const emulators::EmulatorOptionValues& options = {},
                                   emulators::Endpoint endpoint = emulators::PtyEndpoint{}) {
  return emulators::EmulatorRunner(make(options), endpoint);
}

ProbeResult probe(const std::string& port, const ProbeSettings& settings = {}) {
  return probe_port(port, only_p2os(), settings, [] { return false; });
}

TEST(P2osFamily, OffersOneRobotToEmulate) {
  const auto kinds = catalog();
  EXPECT_EQ(kinds.names(), "p2os");
  const emulators::EmulatorKind* robot = kinds.find("p2os");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->driver, "p2os_position");
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/robot"), "position:0 ( driver \"p2os_position\" port \"/tmp/robot\" )");
}

TEST(P2osFamily, EveryKindDocumentsItsOptions) {
  for (const auto& kind : p2os_family().emulators) {
    EXPECT_FALSE(kind.summary.empty()) << kind.name;
    for (const auto& option : kind.options) {
      EXPECT_FALSE(option.summary.empty()) << kind.name << " " << option.name;
      EXPECT_FALSE(option.default_value.empty()) << kind.name << " " << option.name;
    }
  }
}

TEST(P2osFamily, OptionsReachTheRobot) {
  auto made = make({{"model", "p3at"}, {"pose", "1.5,-2,90"}, {"baud", "38400"}, {"name", "rover"}});
  auto* robot = dynamic_cast<emulators::P2osRobotEmulator*>(made.get());
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->params().subclass, "p3at");
  EXPECT_EQ(robot->baud(), 38400);
  EXPECT_DOUBLE_EQ(robot->true_pose().x, 1.5);
  EXPECT_DOUBLE_EQ(robot->true_pose().y, -2.0);
  EXPECT_NEAR(robot->true_pose().yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_NE(robot->describe().find("\"rover\""), std::string::npos) << robot->describe();
}

TEST(P2osFamily, TheRobotsWorldPoseIsItsTruePose) {
  auto made = make({{"pose", "1.5,-2,90"}});
  const std::optional<geometry::Pose2> pose = made->world_pose();
  ASSERT_TRUE(pose);
  EXPECT_DOUBLE_EQ(pose->x, 1.5);
  EXPECT_DOUBLE_EQ(pose->y, -2.0);
  EXPECT_NEAR(pose->yaw, std::numbers::pi / 2, 1e-12);
}

TEST(P2osFamily, DefaultsAreThoseOfTheEmulator) {
  auto made = make({});
  auto* robot = dynamic_cast<emulators::P2osRobotEmulator*>(made.get());
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->params().subclass, "p3dx");
  EXPECT_EQ(robot->baud(), 0);
  EXPECT_DOUBLE_EQ(robot->true_pose().x, 0.0);
  EXPECT_NE(robot->describe().find("\"playerkit\""), std::string::npos) << robot->describe();
}

TEST(P2osFamily, BadOptionsAreRefusedByName) {
  EXPECT_EQ(refusal({{"baud", "4800"}}),
            "p2os: baud=4800: a P2OS controller runs at 9600, 19200, 38400, 57600 or 115200 (0: any speed)");
  EXPECT_EQ(refusal({{"pose", "1,2"}}), "p2os: pose=1,2: expected x,y,yaw in metres, metres and degrees, e.g. 1.5,-2,90");
  EXPECT_EQ(refusal({{"pose", "1,2,3,4"}}).substr(0, 18), "p2os: pose=1,2,3,4");
  EXPECT_EQ(refusal({{"gripper", "maybe"}}), "p2os: gripper=maybe: expected 1 or 0 (yes/no, on/off)");
  EXPECT_EQ(refusal({{"seed", "1"}, {"seed", "2"}}), "p2os: option 'seed' is given twice");
  EXPECT_EQ(refusal({{"type", "PLS"}}),
            "p2os: no option 'type'; its options are model, name, pose, odometry_scale, rotation_scale, drift, seed, "
            "baud, battery, sonar_range, watchdog, sip_period, gripper, cmucam");
  // What only the emulator itself can check still names it.
  EXPECT_EQ(refusal({{"model", "p9zz"}}).substr(0, 6), "p2os: ");
}

TEST(P2osFamily, ProbeFindsAPioneerListeningAtANonDefaultBaud) {
  auto robot = emulated({{"baud", "38400"}, {"model", "p3at"}, {"name", "rover"}});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "p2os");
  EXPECT_EQ(result.found->model, "Pioneer p3at \"rover\"");
  EXPECT_EQ(result.baud, 38400);
  EXPECT_EQ(result.config_line, "position:0 ( driver \"p2os_position\" port \"" + robot.device_path() + "\" )");
  EXPECT_NE(result.found->note.find("add the other p2os_* devices"), std::string::npos) << result.found->note;
}

TEST(P2osFamily, ProbeClosesARobotStillConnectedFromAnEarlierSession) {
  auto robot = emulated();
  // An earlier session synchronised and opened the robot and still has the
  // port open (without a lock), so the robot keeps sending SIPs: a real
  // robot never notices a port being closed.
  auto session = links::open_link(robot.device_path(), {.baud = 9600, .exclusive = false});
  ASSERT_TRUE(probe_p2os(
      {.link = *session, .baud = 9600, .first_reply = links::deadline_in(2s), .finish = links::deadline_in(4s)}));
  namespace p2os = hardware::p2os;
  session->write_all(p2os::command_frame(p2os::Command::plain(p2os::command::open)), links::deadline_in(1s));
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (std::chrono::steady_clock::now() < deadline &&
         !robot.with_emulator<emulators::DeviceEmulator>([](emulators::DeviceEmulator& e) {
           return e.describe().find("connected,") != std::string::npos;
         })) {
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

TEST(P2osFamily, ProbeAsksOnceOverTcp) {
  auto robot = emulated({}, emulators::TcpEndpoint{});
  const ProbeResult result = probe(robot.device_path());
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "p2os");
  EXPECT_EQ(result.baud, 0);
}

TEST(P2osFamily, ProbeTriesTheFiveRatesOfAPioneer) {
  links::PseudoTerminal silent;
  ProbeSettings quick;
  quick.first_reply = 50ms;
  std::vector<std::string> progress;
  quick.progress = [&progress](std::string_view line) { progress.emplace_back(line); };
  const ProbeResult result = probe(silent.slave_path(), quick);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + silent.slave_path() +
                                     " (tried P2OS at 9600, 38400, 19200, 115200, 57600 baud)",
                                 0),
            0u)
      << result.problem;
  ASSERT_EQ(progress.size(), 5u);
  EXPECT_EQ(progress.front(), silent.slave_path() + ": P2OS at 9600 8N1: no answer");
  EXPECT_EQ(progress.back(), silent.slave_path() + ": P2OS at 57600 8N1: no answer");
}

// A line that sends back whatever it is sent: a loopback plug, a modem, a
// PTU-46 fresh from power-up.
class EchoingLine final : public emulators::DeviceEmulator {
 public:
  void receive(std::span<const std::uint8_t> bytes, emulators::Duration, int) override {
    output_.push_back({std::vector<std::uint8_t>(bytes.begin(), bytes.end()), false});
  }
  void advance(emulators::Duration) override {}
  [[nodiscard]] emulators::Duration next_deadline() const override { return emulators::Duration::max(); }
  std::vector<emulators::Telegram> take_output() override { return std::exchange(output_, {}); }
  [[nodiscard]] std::string describe() const override { return "an echoing line"; }

 private:
  std::vector<emulators::Telegram> output_;
};

TEST(P2osFamily, ProbeDoesNotTakeALineThatEchoesForAPioneer) {
  // SYNC0 and SYNC1 come back as a robot would send them; SYNC2 tells.
  emulators::EmulatorRunner line(std::make_unique<EchoingLine>(), emulators::PtyEndpoint{});
  ProbeSettings quick;
  quick.first_reply = 100ms;
  const ProbeResult result = probe(line.device_path(), quick);
  EXPECT_FALSE(result.found) << result.found->model;
  EXPECT_FALSE(result.port_unusable);
}

}  // namespace p2os_family_test
}  // namespace playerkit::families
