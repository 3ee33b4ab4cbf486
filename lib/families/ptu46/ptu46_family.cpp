#include "families/ptu46/ptu46_family.hpp"

#include <memory>

#include "families/ptu46/ptu46_emulator_kind.hpp"
#include "families/ptu46/protocol/ptu_line_format.hpp"

namespace playerkit::families {

FamilySpec ptu46_family() {
  return {
      .name = "ptu46",
      .summary = "Directed Perception PTU-46 pan-tilt units (ASCII over RS-232)",
      .probes = {{.label = "PTU-46",
                  // The unit leaves the factory at 9600 (ptu46.md §1).
                  .bauds = {9600, 19200, 38400},
                  .line = {},
                  .ask = probe_ptu46}},
      // Commands end in a space, which no line format cuts at: the trace
      // prints them as they were written; replies are lines.
      .framing = {nullptr, std::make_shared<framing::TerminatedLineFormat>(hardware::ptu46::reply_line_options())},
      .emulators = {ptu46_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info ptu46",
              "player-drivers run ptu46 port=/dev/ttyUSB0 -n 5",
              "player-drivers run ptu46 port=/tmp/ptu --req control-mode mode=0 --trace",
              "player-drivers emulate ptu46 --link /tmp/ptu",
          },
  };
}

}  // namespace playerkit::families
