#include "families/amtecpowercube/amtecpowercube_family.hpp"

#include <memory>

#include "families/amtecpowercube/amtecpowercube_emulator_kind.hpp"
#include "families/amtecpowercube/protocol/powercube_frames.hpp"
#include "framing/dle_stuffed_format.hpp"

namespace playerkit::families {

FamilySpec amtecpowercube_family() {
  // Requests and replies are the same kind of frame.
  const auto frames = std::make_shared<framing::DleStuffedFormat>(hardware::powercube::frame_options());
  return {
      .name = "amtecpowercube",
      .summary = "Amtec PowerCube pan-tilt wrists (two modules, DLE-stuffed frames over RS-232)",
      .probes = {{.label = "Amtec PowerCube",
                  // The only speed the reference driver sets (amtecpowercube.md §1).
                  .bauds = {38400},
                  .line = {},
                  .ask = probe_amtecpowercube}},
      .framing = {frames, frames},
      .emulators = {amtecpowercube_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info amtecpowercube",
              "player-drivers run amtecpowercube port=/dev/ttyS0 -n 5",
              "player-drivers run amtecpowercube port=/tmp/cube --req control-mode mode=0 --trace",
              "player-drivers emulate amtecpowercube --link /tmp/cube",
          },
  };
}

}  // namespace playerkit::families
