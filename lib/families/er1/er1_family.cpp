#include "families/er1/er1_family.hpp"

#include <memory>

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/er1/emulator/er1_emulator.hpp"
#include "families/er1/protocol/er1_frame_format.hpp"

namespace playerkit::families {

emulators::EmulatorKind er1_emulator_kind() {
  std::vector<emulators::EmulatorOptionDoc> options = emulators::mobile_base::robot_option_docs();
  options.push_back({"axle", "0.38", "distance between the drive wheels, m"});
  options.push_back({"motor_dir", "1", "the wiring: 1 the left motor on motor port 0, -1 on port 1 (as the driver's option)"});
  return {
      .name = "er1",
      .summary = "an Evolution Robotics ER1: its Robot Control Module (230400 baud) and the robot it drives",
      .interface_name = "position",
      .driver = "er1_position",
      .mount = emulators::EmulatorMount::robot,
      .options = std::move(options),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            const auto body = emulators::mobile_base::read_robot_options(reader);
            const int motor_dir = reader.integer("motor_dir", 1, -1, 1);
            if (motor_dir == 0) reader.fail("motor_dir", "1 or -1");
            return std::unique_ptr<emulators::DeviceEmulator>(std::make_unique<emulators::Er1Emulator>(
                emulators::Er1EmulatorOptions{.axle = reader.number("axle", 0.38, 0.05, 5.0),
                                              .left_motor_port = motor_dir < 0 ? 1 : 0,
                                              .initial_pose = body.initial_pose,
                                              .odometry_error = body.odometry_error,
                                              .map = world.map}));
          },
  };
}

FamilySpec er1_family() {
  return {
      .name = "er1",
      .summary = "Evolution Robotics ER1 robots (the Robot Control Module's motors)",
      .probes = {{.label = "ER1 RCM", .bauds = {230400}, .line = {}, .ask = probe_er1}},
      // Commands carry their length in their opcode; a reply's length is
      // known only from the command it answers, so replies print as they came.
      .framing = {std::make_shared<hardware::er1::CommandFormat>(), nullptr},
      .emulators = {er1_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info er1_position",
              "player-drivers run er1_position port=/dev/ttyUSB0 -n 5",
              "player-drivers emulate er1 --link /tmp/er1",
              "player-drivers emulate er1 sicklms200 --link /tmp/er1 --link /tmp/laser --map data/maps/stage-cave.png",
          },
  };
}

}  // namespace playerkit::families
