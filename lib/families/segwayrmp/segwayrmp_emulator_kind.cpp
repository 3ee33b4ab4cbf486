#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "families/segwayrmp/segwayrmp_family.hpp"

namespace playerkit::families {

namespace {

std::vector<emulators::EmulatorOptionDoc> rmp_options() {
  std::vector<emulators::EmulatorOptionDoc> docs = emulators::mobile_base::robot_option_docs();
  const std::vector<emulators::EmulatorOptionDoc> own{
      {"rate", "100", "status messages a second, each of 0x400-0x404, Hz"},
      {"watchdog", "0.25", "stop when no velocity command came for this long, s; 0: off"},
      {"battery", "100", "the battery slot (x 7.2 = decivolts: 100 reads 72.0 V)"},
      {"acceleration", "0", "largest change of speed, m/s^2, at full acceleration scale; 0: at once"},
      {"pitch", "0", "the balancing robot's lean, degrees"},
  };
  docs.insert(docs.end(), own.begin(), own.end());
  return docs;
}

std::unique_ptr<emulators::DeviceEmulator> make_rmp(const emulators::EmulatorOptionReader& options,
                                                    const emulators::EmulatorWorld& world) {
  emulators::SegwayRmpEmulatorOptions settings;
  const emulators::mobile_base::RobotBodyOptions body = emulators::mobile_base::read_robot_options(options);
  settings.initial_pose = body.initial_pose;
  settings.odometry_error = body.odometry_error;
  settings.status_rate = options.number("rate", settings.status_rate, 1, 1000);
  settings.watchdog = options.number("watchdog", settings.watchdog, 0, 3600);
  settings.battery_percent = options.number("battery", settings.battery_percent, 0, 9000);
  settings.max_acceleration = options.number("acceleration", settings.max_acceleration, 0, 100);
  settings.pitch_degrees = options.number("pitch", settings.pitch_degrees, -90, 90);
  settings.map = world.map;
  return std::make_unique<emulators::SegwayRmpEmulator>(settings);
}

}  // namespace

emulators::EmulatorKind segwayrmp_emulator_kind() {
  return {
      .name = "segwayrmp",
      .summary = "a Segway RMP behind an slcan USB-CAN adapter: status at 100 Hz, velocity commands, watchdog",
      .interface_name = "position",
      .driver = "segwayrmp",
      .mount = emulators::EmulatorMount::robot,
      .options = rmp_options(),
      .make = make_rmp,
  };
}

}  // namespace playerkit::families
