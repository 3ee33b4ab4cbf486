#include "families/amtecpowercube/amtecpowercube_emulator_kind.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "families/amtecpowercube/emulator/powercube_emulator.hpp"

namespace playerkit::families {

emulators::EmulatorKind amtecpowercube_emulator_kind() {
  return {
      .name = "amtecpowercube",
      .summary = "an Amtec PowerCube wrist: pan module 12, tilt module 11 (38400 baud, DLE-stuffed frames)",
      .interface_name = "ptz",
      .driver = "amtecpowercube",
      .mount = emulators::EmulatorMount::standalone,
      .options =
          {
              {"max_speed", "90", "top speed of either module, deg/s"},
              {"acceleration", "360", "acceleration and braking of either module, deg/s^2"},
              {"pan_min", "-170", "lowest pan module position, degrees (clockwise positive)"},
              {"pan_max", "170", "highest pan module position, degrees"},
              {"tilt_min", "-110", "lowest tilt position, degrees"},
              {"tilt_max", "110", "highest tilt position, degrees"},
              {"pan_start", "0", "pan module position at power-up, before homing, degrees"},
              {"tilt_start", "0", "tilt position at power-up, before homing, degrees"},
              {"modules", "both", "the modules on the line: both, pan or tilt"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld&) {
            constexpr double kTurn = 3600;  // ten turns: any module's reach
            emulators::PowercubeEmulatorOptions options;
            options.max_speed = reader.number("max_speed", options.max_speed, 0.001, 3600);
            options.acceleration = reader.number("acceleration", options.acceleration, 0.001, 1e6);
            options.pan_min = reader.number("pan_min", options.pan_min, -kTurn, kTurn);
            options.pan_max = reader.number("pan_max", options.pan_max, -kTurn, kTurn);
            options.tilt_min = reader.number("tilt_min", options.tilt_min, -kTurn, kTurn);
            options.tilt_max = reader.number("tilt_max", options.tilt_max, -kTurn, kTurn);
            options.pan_start = reader.number("pan_start", options.pan_start, -kTurn, kTurn);
            options.tilt_start = reader.number("tilt_start", options.tilt_start, -kTurn, kTurn);
            const std::string modules = reader.text("modules", "both");
            if (modules != "both" && modules != "pan" && modules != "tilt") {
              reader.fail("modules", "must be both, pan or tilt");
            }
            options.pan_present = modules != "tilt";
            options.tilt_present = modules != "pan";
            // Limits out of order throw std::invalid_argument naming them.
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::PowercubeEmulator>(options));
          },
  };
}

}  // namespace playerkit::families
