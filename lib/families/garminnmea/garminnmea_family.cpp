#include "families/garminnmea/garminnmea_family.hpp"

#include <memory>

#include "families/garminnmea/garminnmea_emulator_kind.hpp"
#include "framing/nmea_format.hpp"

namespace playerkit::families {

FamilySpec garminnmea_family() {
  return {
      .name = "garminnmea",
      .summary = "Garmin (any NMEA 0183) GPS receivers",
      .probes = {{.label = "NMEA 0183",
                  // 4800 is the standard's; the sheet's other speeds after it.
                  .bauds = {4800, 9600, 19200, 38400},
                  .line = {},
                  .ask = probe_garminnmea}},
      // The host sends only RTCM corrections (binary): printed as they come.
      .framing = {nullptr, std::make_shared<framing::NmeaFormat>()},
      .emulators = {garminnmea_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info garminnmea",
              "player-drivers run garminnmea port=/dev/ttyUSB0 dgps_enable=0 --format json -n 5",
              "player-drivers run garminnmea port=/tmp/gps --trace",
              "player-drivers emulate garminnmea --link /tmp/gps",
              "player-drivers emulate garminnmea --link /tmp/gps log=track.nmea loop=1 rate=10",
          },
  };
}

}  // namespace playerkit::families
