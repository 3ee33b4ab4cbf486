#include "families/ptu46/ptu46_emulator_kind.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "families/ptu46/emulator/ptu46_emulator.hpp"

namespace playerkit::families {

emulators::EmulatorKind ptu46_emulator_kind() {
  return {
      .name = "ptu46",
      .summary = "a Directed Perception PTU-46 pan-tilt unit (ASCII, 9600 baud, positions of 185.1428\")",
      .interface_name = "ptz",
      .driver = "ptu46",
      .mount = emulators::EmulatorMount::standalone,
      .options =
          {
              {"resolution", "185.1428", "arc-seconds a position, both axes"},
              {"pan_min", "-3090", "lowest pan position (below 0)"},
              {"pan_max", "3090", "highest pan position (above 0)"},
              {"tilt_min", "-907", "lowest tilt position (below 0)"},
              {"tilt_max", "604", "highest tilt position (above 0)"},
              {"lower_speed", "0", "lowest speed allowed, positions/s"},
              {"upper_speed", "2902", "highest speed allowed, positions/s"},
              {"speed", "1000", "the speed at power-up, positions/s"},
              {"echo", "1", "1: the unit echoes what it is sent until told ED, as at power-up"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld&) {
            constexpr int kWidest = 1'000'000;
            emulators::Ptu46EmulatorOptions options;
            options.resolution_arc_seconds = reader.number("resolution", options.resolution_arc_seconds, 0.001, 3600);
            options.pan_min = reader.integer("pan_min", -3090, -kWidest, -1);
            options.pan_max = reader.integer("pan_max", 3090, 1, kWidest);
            options.tilt_min = reader.integer("tilt_min", -907, -kWidest, -1);
            options.tilt_max = reader.integer("tilt_max", 604, 1, kWidest);
            options.lower_speed = reader.integer("lower_speed", 0, 0, kWidest);
            options.upper_speed = reader.integer("upper_speed", 2902, 1, kWidest);
            options.start_speed = reader.integer("speed", 1000, 0, kWidest);
            options.echo_at_power_up = reader.flag("echo", true);
            // Limits out of order throw std::invalid_argument naming them.
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::Ptu46Emulator>(options));
          },
  };
}

}  // namespace playerkit::families
