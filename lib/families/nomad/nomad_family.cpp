#include "families/nomad/nomad_family.hpp"

#include <memory>

#include "families/nomad/nomad_emulator_kind.hpp"
#include "families/nomad/protocol/nclient_message.hpp"

namespace playerkit::families {

FamilySpec nomad_family() {
  const auto nclient = std::make_shared<hardware::nomad::NclientFormat>();
  return {
      .name = "nomad",
      .summary = "Nomadic Nomad 200 through Nomadic's server over TCP (nomad, position, sonar)",
      // The probe asks serial ports; a Nomad is a TCP server that answers
      // only a client that connects the robot, so it is run, not probed.
      .probes = {},
      .framing = {nclient, nclient},
      .emulators = {nomad_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info nomad",
              "player-drivers run nomad host=robot.local -n 5",
              "player-drivers run nomad host=127.0.0.1 port=7019 --trace",
              "player-drivers emulate nomad --tcp 7019",
          },
  };
}

}  // namespace playerkit::families
