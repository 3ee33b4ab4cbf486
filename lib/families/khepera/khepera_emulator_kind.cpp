#include <memory>

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/khepera/emulator/khepera_emulator.hpp"
#include "families/khepera/khepera_family.hpp"

namespace playerkit::families {

namespace {

std::unique_ptr<emulators::DeviceEmulator> make_robot(const emulators::EmulatorOptionReader& options,
                                                      const emulators::EmulatorWorld& world) {
  emulators::KheperaEmulatorOptions settings;
  const auto body = emulators::mobile_base::read_robot_options(options);
  settings.initial_pose = body.initial_pose;
  settings.odometry_error = body.odometry_error;
  settings.wheels.millimetres_per_pulse =
      options.number("encoder_res", settings.wheels.millimetres_per_pulse, 0.001, 10.0);
  settings.wheels.wheelbase_mm = options.number("wheelbase", settings.wheels.wheelbase_mm, 10.0, 1000.0);
  settings.footprint_radius = options.number("radius", settings.footprint_radius, 0.005, 1.0);
  settings.model_baud = options.integer("baud", 38400, 0, 4000000);
  settings.map = world.map;
  return std::make_unique<emulators::KheperaEmulator>(settings);
}

}  // namespace

emulators::EmulatorKind khepera_emulator_kind() {
  std::vector<emulators::EmulatorOptionDoc> options = emulators::mobile_base::robot_option_docs();
  options.push_back({"encoder_res", "0.0833333", "mm a wheel travels per encoder pulse (12 pulses a mm)"});
  options.push_back({"wheelbase", "57", "distance between the wheels, mm (1.5's default size)"});
  options.push_back({"radius", "0.0285", "radius of the round body that stalls against the map, m"});
  options.push_back({"baud", "38400", "the only line speed it listens at; 0: any"});
  return {
      .name = "khepera",
      .summary = "a K-Team Khepera: wheel speeds and counters, 8 IR proximity sensors seeing the map",
      .interface_name = "position",
      .driver = "khepera_position",
      .mount = emulators::EmulatorMount::robot,
      .options = std::move(options),
      .make = make_robot,
  };
}

}  // namespace playerkit::families
