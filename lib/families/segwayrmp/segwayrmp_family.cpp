#include "families/segwayrmp/segwayrmp_family.hpp"

#include <memory>

#include "links/can/slcan.hpp"

namespace playerkit::families {

FamilySpec segwayrmp_family() {
  return {
      .name = "segwayrmp",
      .summary = "Segway RMP robots over CAN (an slcan USB-CAN adapter or SocketCAN): position, position3d, power",
      .probes = {{.label = "Segway RMP (slcan)",
                  // USB adapters ignore the speed; serial ones (CAN232) leave the factory at 57600.
                  .bauds = {115200, 57600},
                  .line = {},
                  .ask = probe_segwayrmp}},
      // Both directions are slcan lines (commands, acknowledgements, frames).
      .framing = {std::make_shared<links::can::SlcanFormat>(), std::make_shared<links::can::SlcanFormat>()},
      .emulators = {segwayrmp_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info segwayrmp",
              "player-drivers run segwayrmp port=/dev/ttyUSB0 -n 5",
              "player-drivers run segwayrmp canio=socketcan device=can0 -n 5",
              "player-drivers run segwayrmp port=/tmp/rmp --req get-geom --trace",
              "player-drivers emulate segwayrmp --link /tmp/rmp",
          },
  };
}

}  // namespace playerkit::families
