#include "families/flockofbirds/flockofbirds_family.hpp"

#include <memory>

#include "families/flockofbirds/flockofbirds_emulator_kind.hpp"
#include "families/flockofbirds/protocol/bird_record.hpp"
#include "framing/phasing_bit_format.hpp"

namespace playerkit::families {

FamilySpec flockofbirds_family() {
  return {
      .name = "flockofbirds",
      .summary = "Ascension Flock of Birds 6-DOF trackers (binary over RS-232)",
      .probes = {{.label = "Flock of Birds",
                  // 115200 is 1.5's default; the bird's switches offer the rest.
                  .bauds = {115200, 9600, 38400, 19200, 57600},
                  .line = {},
                  .ask = probe_flockofbirds}},
      // Commands are single bytes with no framing: the trace prints them as
      // written; the bird's records are cut on their phasing bit.
      .framing = {nullptr, std::make_shared<framing::PhasingBitFormat>(hardware::flockofbirds::record_format_options())},
      .emulators = {flockofbirds_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info flockofbirds",
              "player-drivers run flockofbirds port=/dev/ttyS0 -n 5",
              "player-drivers run flockofbirds port=/tmp/bird --trace -n 1",
              "player-drivers emulate flockofbirds trajectory=poses.txt --link /tmp/bird",
          },
  };
}

}  // namespace playerkit::families
