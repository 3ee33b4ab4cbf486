#include "families/reb/reb_family.hpp"

#include <memory>

#include "families/reb/protocol/reb_lines.hpp"
#include "families/reb/reb_emulator_kind.hpp"

namespace playerkit::families {

FamilySpec reb_family() {
  return {
      .name = "reb",
      .summary = "UMass UBot: K-Team Kameleon with the Robotics Extension Board (LPRSerCom ASCII, 38400 8N2)",
      .probes = {{.label = "REB (LPRSerCom)",
                  .bauds = {38400},  // the only speed 1.5 and the board use (reb.md §1)
                  .line = links::SerialSettings{.baud = 38400, .stop_bits = 2},
                  .ask = probe_reb}},
      .framing = {std::make_shared<framing::TerminatedLineFormat>(hardware::reb::command_line_options()),
                  std::make_shared<framing::TerminatedLineFormat>(hardware::reb::reply_line_options())},
      .emulators = {reb_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info reb_position",
              "player-drivers run reb port=/dev/ttySA1 -n 5",
              "player-drivers emulate reb --link /tmp/reb",
              "player-drivers emulate reb sicklms200 --link /tmp/reb --link /tmp/laser --map data/maps/cave.pgm",
          },
  };
}

}  // namespace playerkit::families
