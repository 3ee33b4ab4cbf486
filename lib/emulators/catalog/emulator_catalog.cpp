#include "emulators/catalog/emulator_catalog.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "emulators/catalog/emulator_option_reader.hpp"
#include "emulators/p2os/p2os_robot_emulator.hpp"
#include "emulators/sick/sick_lms200_emulator.hpp"
#include "emulators/sick/sick_pls_emulator.hpp"

namespace playerkit::emulators {

namespace {

std::vector<EmulatorOptionDoc> sick_options(bool lms) {
  std::vector<EmulatorOptionDoc> options = {
      {"pose", "0,0,0", "where the laser stands in the map: x,y,yaw in m, m, deg (alone)"},
      {"mount", "0,0,0", "where the laser sits on the emulated robot: x,y,yaw in m, m, deg"},
      {"noise", "0", "standard deviation of the range noise, m"},
      {"seed", "1", "seed of the noise"},
      {"max_range", lms ? "8.191" : "81.91", "longest range measured, m (what a beam that meets nothing reads)"},
      {"baud", "9600", "the line speed at power-up: 9600, 19200, 38400 or 500000"},
      {"model_baud", "1", "1: bytes sent at another speed than the laser's are line noise; 0: any speed works"},
  };
  if (lms) options.push_back({"type", "LMS200;30106", "the type text the laser reports (at most 20 characters)"});
  return options;
}

std::vector<EmulatorKind> make_kinds() {
  return {
      {"p2os", "a Pioneer robot's P2OS controller: handshake, SIPs, motors, sonar, gripper, gyro, CMUcam", "position",
       "p2os_position", false,
       {
           {"model", "p3dx", "the robot it claims to be: a subclass of the P2OS table (p3dx, p3at, p2de, amigo, ...)"},
           {"name", "playerkit", "the robot's name in the SYNC2 reply (at most 19 characters)"},
           {"pose", "0,0,0", "where it starts in the map: x,y,yaw in m, m, deg"},
           {"baud", "0", "the only line speed it listens at (9600, 19200, 38400, 57600, 115200); 0: any"},
           {"battery", "12.5", "battery voltage, V"},
           {"odometry_scale", "0", "odometry error: measured distance = true x (1 + this)"},
           {"rotation_scale", "0", "odometry error: measured rotation = true x (1 + this)"},
           {"drift", "0", "odometry error: heading drift, deg per m driven"},
           {"seed", "1", "seed of the odometry noise"},
           {"sonar_range", "5", "longest sonar reading, m"},
           {"watchdog", "2", "stop when no packet came for this long while moving, s; 0: off"},
           {"sip_period", "100", "time between two SIPs, ms"},
           {"gripper", "1", "1: it has a gripper"},
           {"cmucam", "1", "1: a CMUcam answers on AUX2"},
       }},
      {"sicklms200", "a SICK LMS 200 laser range-finder (9600 baud at power-up, 180 deg, mm)", "laser", "sicklms200",
       true, sick_options(true)},
      {"sickpls", "a SICK PLS laser scanner (9600 baud at power-up, 180 deg at 0.5 deg, cm)", "laser", "sickpls", true,
       sick_options(false)},
  };
}

std::chrono::nanoseconds from_seconds(double seconds) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(seconds));
}

std::unique_ptr<DeviceEmulator> make_p2os(const EmulatorKind& kind, const EmulatorOptionReader& options,
                                          const EmulatorWorld& world) {
  P2osEmulatorOptions settings;
  settings.subclass = options.text("model", settings.subclass);
  settings.robot_name = options.text("name", settings.robot_name);
  settings.initial_pose = options.pose("pose", {});
  settings.model_baud = options.integer("baud", 0, 0, 4000000);
  if (settings.model_baud != 0 && settings.model_baud != 9600 && settings.model_baud != 19200 &&
      settings.model_baud != 38400 && settings.model_baud != 57600 && settings.model_baud != 115200) {
    options.fail("baud", "a P2OS controller runs at 9600, 19200, 38400, 57600 or 115200 (0: any speed)");
  }
  settings.battery_volts = options.number("battery", settings.battery_volts, 0.0, 25.5);
  settings.odometry_error.translation_scale = options.number("odometry_scale", 0.0, -0.5, 0.5);
  settings.odometry_error.rotation_scale = options.number("rotation_scale", 0.0, -0.5, 0.5);
  settings.odometry_error.heading_drift_per_metre = options.number("drift", 0.0, -90.0, 90.0) * std::numbers::pi / 180.0;
  settings.odometry_error.seed = static_cast<std::uint64_t>(options.integer("seed", 1, 0, 2147483647));
  settings.sonar_max_range = options.number("sonar_range", settings.sonar_max_range, 0.1, 50.0);
  const double watchdog = options.number("watchdog", 2.0, 0.0, 3600.0);
  settings.watchdog = watchdog > 0.0 ? std::optional<Duration>(from_seconds(watchdog)) : std::nullopt;
  settings.sip_period = std::chrono::milliseconds(options.integer("sip_period", 100, 10, 10000));
  settings.has_gripper = options.flag("gripper", true);
  settings.has_cmucam = options.flag("cmucam", true);
  settings.map = world.map;
  try {
    return std::make_unique<P2osRobotEmulator>(settings);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(kind.name + ": " + e.what());
  }
}

std::unique_ptr<DeviceEmulator> make_sick(const EmulatorKind& kind, const EmulatorOptionReader& options,
                                          const EmulatorWorld& world) {
  SickEmulatorOptions settings;
  settings.map = world.map;
  if (world.carrier_pose) {
    if (options.has("pose")) {
      options.fail("pose", "this laser rides on the emulated robot; say where with mount=x,y,yaw");
    }
    const geometry::Pose2 mount = options.pose("mount", {});
    settings.pose_source = [carrier = world.carrier_pose, mount] { return carrier().compose(mount); };
  } else {
    if (options.has("mount")) options.fail("mount", "no robot is emulated to carry the laser; use pose=x,y,yaw");
    settings.pose = options.pose("pose", {});
  }
  settings.range_noise_sigma_m = options.number("noise", 0.0, 0.0, 1.0);
  settings.noise_seed = static_cast<std::uint64_t>(options.integer("seed", 1, 0, 2147483647));
  if (options.has("max_range")) settings.max_range_m = options.number("max_range", 8.0, 0.01, 81.91);
  settings.power_up_baud = options.integer("baud", 9600, 1, 4000000);
  if (settings.power_up_baud != 9600 && settings.power_up_baud != 19200 && settings.power_up_baud != 38400 &&
      settings.power_up_baud != 500000) {
    options.fail("baud", "a SICK laser runs at 9600, 19200, 38400 or 500000");
  }
  settings.model_baud_rates = options.flag("model_baud", true);
  if (options.has("type")) settings.type = options.text("type", "");
  try {
    if (kind.name == "sicklms200") return std::make_unique<SickLms200Emulator>(settings);
    return std::make_unique<SickPlsEmulator>(settings);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(kind.name + ": " + e.what());
  }
}

}  // namespace

const std::vector<EmulatorKind>& emulator_kinds() {
  static const std::vector<EmulatorKind> kinds = make_kinds();
  return kinds;
}

const EmulatorKind* find_emulator_kind(std::string_view name) {
  for (const auto& kind : emulator_kinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::string emulator_names() {
  std::string names;
  for (const auto& kind : emulator_kinds()) names += (names.empty() ? "" : ", ") + kind.name;
  return names;
}

std::string config_example(const EmulatorKind& kind, std::string_view port) {
  return kind.interface_name + ":0 ( driver \"" + kind.driver + "\" port \"" + std::string(port) + "\" )";
}

std::unique_ptr<DeviceEmulator> make_emulator(std::string_view name, const EmulatorOptionValues& options,
                                              const EmulatorWorld& world) {
  const EmulatorKind* kind = find_emulator_kind(name);
  if (!kind) {
    throw std::invalid_argument("no emulator '" + std::string(name) + "'; there are " + emulator_names());
  }
  const EmulatorOptionReader reader(*kind, options);
  if (kind->name == "p2os") return make_p2os(*kind, reader, world);
  return make_sick(*kind, reader, world);
}

}  // namespace playerkit::emulators
