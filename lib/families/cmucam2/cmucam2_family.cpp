#include "families/cmucam2/cmucam2_family.hpp"

#include <memory>

#include "families/cmucam2/cmucam2_emulator_kind.hpp"
#include "families/cmucam2/protocol/cmucam_protocol.hpp"

namespace playerkit::families {

FamilySpec cmucam2_family() {
  // Both directions are CR-ended lines (a lone CR is a command); the
  // camera's prompt is a telegram of its own.
  const auto commands = std::make_shared<framing::TerminatedLineFormat>(hardware::cmucam2::command_line_options());
  const auto replies = std::make_shared<framing::TerminatedLineFormat>(hardware::cmucam2::reply_line_options());
  return {
      .name = "cmucam2",
      .summary = "CMUcam2 colour tracker and its servos (ASCII, 115200 baud)",
      .probes = {{.label = "CMUcam2",
                  // 115200 is the camera's jumper default (cmucam2.md §1); the others its jumper options.
                  .bauds = {115200, 38400, 19200, 9600},
                  .line = {},
                  .ask = probe_cmucam2}},
      .framing = {commands, replies},
      .emulators = {cmucam2_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info cmucam2",
              "player-drivers run cmucam2 port=/dev/ttyUSB0 -n 5",
              "player-drivers emulate cmucam2 --link /tmp/cmucam2",
              "player-drivers emulate cmucam2 --link /tmp/cmucam2 image=scene.ppm",
          },
  };
}

}  // namespace playerkit::families
