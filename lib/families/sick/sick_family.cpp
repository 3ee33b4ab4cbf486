#include "families/sick/sick_family.hpp"

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/sick_emulator_kinds.hpp"
#include "families/sick/sick_probe.hpp"

namespace playerkit::families {

FamilySpec sick_family() {
  namespace sick = hardware::sick;
  // Both lasers power up at 9600; 38400 is where the drivers leave them.
  const std::vector<int> bauds = {9600, 38400, 19200, 500000};
  return {
      .name = "sick",
      .summary = "SICK LMS 200 and PLS laser range-finders over RS-232/422",
      .probes =
          {
              {.label = "SICK (LMS password)",
               .bauds = bauds,
               .line = {},
               .ask = [](const ProbeContext& line) { return probe_sick(line, sick::Model::lms200); }},
              {.label = "SICK (PLS password)",
               .bauds = bauds,
               .line = {.parity = links::Parity::even},
               .ask = [](const ProbeContext& line) { return probe_sick(line, sick::Model::pls); }},
          },
      .framing = {std::make_shared<sick::SickFrameFormat>(sick::SickFrameFormat::requests()),
                  std::make_shared<sick::SickFrameFormat>(sick::SickFrameFormat::replies())},
      .emulators = {sicklms200_emulator_kind(), sickpls_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info sicklms200",
              "player-drivers run sicklms200 port=/dev/ttyUSB0 rate=38400 -n 3 --si --format json",
              "player-drivers run sicklms200 port=/tmp/laser --req get-geom",
              "player-drivers run sicklms200 port=/dev/ttyUSB0 --stats --trace --duration 10",
              "player-drivers emulate sicklms200 --link /tmp/laser",
          },
  };
}

}  // namespace playerkit::families
