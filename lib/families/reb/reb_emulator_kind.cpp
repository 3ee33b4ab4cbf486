#include "families/reb/reb_emulator_kind.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/reb/emulator/reb_emulator.hpp"

namespace playerkit::families {

emulators::EmulatorKind reb_emulator_kind() {
  std::vector<emulators::EmulatorOptionDoc> options = emulators::mobile_base::robot_option_docs();
  options.push_back({"subclass", "slow", "the UBot's encoders: slow (24.33 pulses/mm) or fast (7.92)"});
  options.push_back({"battery", "7.2", "battery voltage, V"});
  options.push_back({"ir_range", "0.8", "farthest obstacle an IR sensor sees, m"});
  return {
      .name = "reb",
      .summary = "a UMass UBot's Robotics Extension Board (LPRSerCom ASCII, 38400 8N2): wheels, 8 IR, battery",
      .interface_name = "position",
      .driver = "reb_position",
      .mount = emulators::EmulatorMount::robot,
      .options = std::move(options),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            emulators::RebEmulatorOptions settings;
            settings.body = emulators::mobile_base::read_robot_options(reader);
            settings.subclass = reader.text("subclass", "slow");
            if (settings.subclass != "slow" && settings.subclass != "fast") {
              reader.fail("subclass", "a UBot is \"slow\" or \"fast\"");
            }
            settings.battery_volts = reader.number("battery", 7.2, 0.0, 20.0);
            settings.ir_range = reader.number("ir_range", 0.8, 0.05, 5.0);
            settings.map = world.map;
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::RebEmulator>(settings));
          },
  };
}

}  // namespace playerkit::families
