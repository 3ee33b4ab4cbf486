#include "families/nomad/nomad_emulator_kind.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"

namespace playerkit::families {

namespace {

// Every robot's body options (pose, odometry error), then the server's own.
std::vector<emulators::EmulatorOptionDoc> nomad_emulator_options() {
  auto options = emulators::mobile_base::robot_option_docs();
  options.push_back({"reply_delay", "20", "ms the server takes to answer a request"});
  options.push_back({"ir_range", "36", "inches the infrared sensors see at most"});
  return options;
}

}  // namespace

emulators::EmulatorKind nomad_emulator_kind() {
  return {
      .name = "nomad",
      .summary = "a Nomad 200 behind Nomadic's server (Nclient over TCP: use --tcp)",
      .interface_name = "nomad",
      .driver = "nomad",
      .mount = emulators::EmulatorMount::robot,
      .options = nomad_emulator_options(),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            emulators::NomadEmulatorOptions options;
            const auto body = emulators::mobile_base::read_robot_options(reader);
            options.start_pose = body.initial_pose;
            options.odometry_error = body.odometry_error;
            options.reply_delay = std::chrono::milliseconds(reader.integer("reply_delay", 20, 0, 1000));
            options.ir_range_inches = reader.integer("ir_range", 36, 1, 255);
            options.map = world.map;
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::NomadEmulator>(options));
          },
  };
}

}  // namespace playerkit::families
