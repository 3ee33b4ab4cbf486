#include "families/p2os/p2os_emulator_kind.hpp"

#include <chrono>
#include <optional>

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"

namespace playerkit::families {

namespace {

std::chrono::nanoseconds from_seconds(double seconds) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(seconds));
}

std::unique_ptr<emulators::DeviceEmulator> make_robot(const emulators::EmulatorOptionReader& options,
                                                      const emulators::EmulatorWorld& world) {
  emulators::P2osEmulatorOptions settings;
  settings.subclass = options.text("model", settings.subclass);
  settings.robot_name = options.text("name", settings.robot_name);
  settings.model_baud = options.integer("baud", 0, 0, 4000000);
  if (settings.model_baud != 0 && settings.model_baud != 9600 && settings.model_baud != 19200 &&
      settings.model_baud != 38400 && settings.model_baud != 57600 && settings.model_baud != 115200) {
    options.fail("baud", "a P2OS controller runs at 9600, 19200, 38400, 57600 or 115200 (0: any speed)");
  }
  settings.battery_volts = options.number("battery", settings.battery_volts, 0.0, 25.5);
  const emulators::mobile_base::RobotBodyOptions body = emulators::mobile_base::read_robot_options(options);
  settings.initial_pose = body.initial_pose;
  settings.odometry_error = body.odometry_error;
  settings.sonar_max_range = options.number("sonar_range", settings.sonar_max_range, 0.1, 50.0);
  const double watchdog = options.number("watchdog", 2.0, 0.0, 3600.0);
  settings.watchdog = watchdog > 0.0 ? std::optional<emulators::Duration>(from_seconds(watchdog)) : std::nullopt;
  settings.sip_period = std::chrono::milliseconds(options.integer("sip_period", 100, 10, 10000));
  settings.has_gripper = options.flag("gripper", true);
  settings.has_cmucam = options.flag("cmucam", true);
  settings.map = world.map;
  return std::make_unique<emulators::P2osRobotEmulator>(settings);
}

std::vector<emulators::EmulatorOptionDoc> robot_options() {
  std::vector<emulators::EmulatorOptionDoc> docs{
      {"model", "p3dx", "the robot it claims to be: a subclass of the P2OS table (p3dx, p3at, p2de, amigo, ...)"},
      {"name", "playerkit", "the robot's name in the SYNC2 reply (at most 19 characters)"},
  };
  for (auto& shared : emulators::mobile_base::robot_option_docs()) docs.push_back(std::move(shared));
  const std::vector<emulators::EmulatorOptionDoc> pioneer{
      {"baud", "0", "the only line speed it listens at (9600, 19200, 38400, 57600, 115200); 0: any"},
      {"battery", "12.5", "battery voltage, V"},
      {"sonar_range", "5", "longest sonar reading, m"},
      {"watchdog", "2", "stop when no packet came for this long while moving, s; 0: off"},
      {"sip_period", "100", "time between two SIPs, ms"},
      {"gripper", "1", "1: it has a gripper"},
      {"cmucam", "1", "1: a CMUcam answers on AUX2"},
  };
  docs.insert(docs.end(), pioneer.begin(), pioneer.end());
  return docs;
}

}  // namespace

emulators::EmulatorKind p2os_emulator_kind() {
  return {
      .name = "p2os",
      .summary = "a Pioneer robot's P2OS controller: handshake, SIPs, motors, sonar, gripper, gyro, CMUcam",
      .interface_name = "position",
      .driver = "p2os_position",
      .mount = emulators::EmulatorMount::robot,
      .options = robot_options(),
      .make = make_robot,
  };
}

}  // namespace playerkit::families
