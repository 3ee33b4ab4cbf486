#include "families/nomad/nomad_emulator_kind.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"

namespace playerkit::families {

emulators::EmulatorKind nomad_emulator_kind() {
  return {
      .name = "nomad",
      .summary = "a Nomad 200 behind Nomadic's server (Nclient over TCP: use --tcp)",
      .interface_name = "nomad",
      .driver = "nomad",
      .mount = emulators::EmulatorMount::robot,
      .options =
          {
              {"pose", "0,0,0", "where it starts in the map: x m, y m, heading deg"},
              {"odometry_scale", "1", "odometry's distance per true distance"},
              {"rotation_scale", "1", "odometry's angle per true angle"},
              {"reply_delay", "20", "ms the server takes to answer a request"},
              {"ir_range", "36", "inches the infrared sensors see at most"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            emulators::NomadEmulatorOptions options;
            options.start_pose = reader.pose("pose", {});
            options.translation_scale = reader.number("odometry_scale", 1.0, 0.5, 1.5);
            options.rotation_scale = reader.number("rotation_scale", 1.0, 0.5, 1.5);
            options.reply_delay = std::chrono::milliseconds(reader.integer("reply_delay", 20, 0, 1000));
            options.ir_range_inches = reader.integer("ir_range", 36, 1, 255);
            options.map = world.map;
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::NomadEmulator>(options));
          },
  };
}

}  // namespace playerkit::families
