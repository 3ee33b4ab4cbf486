#include "families/khepera/khepera_family.hpp"

#include <memory>

#include "families/khepera/protocol/khepera_commands.hpp"

namespace playerkit::families {

FamilySpec khepera_family() {
  namespace hw = hardware::khepera;
  return {
      .name = "khepera",
      .summary = "K-Team Khepera robots (ASCII over RS-232): wheels and IR on one link",
      // The BIOS runs at 38400 and 1.5 fixed it there (khepera.md §1, quirk 1).
      .probes = {{.label = "Khepera", .bauds = {38400}, .line = {}, .ask = probe_khepera}},
      .framing = {std::make_shared<framing::TerminatedLineFormat>(hw::command_line_options()),
                  std::make_shared<framing::TerminatedLineFormat>(hw::reply_line_options())},
      .emulators = {khepera_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info khepera_position",
              "player-drivers run khepera port=/dev/ttyUSB0 -n 5",
              "player-drivers emulate khepera --link /tmp/khepera --map data/maps/stage-cave.yaml pose=0,0,90",
          },
  };
}

}  // namespace playerkit::families
