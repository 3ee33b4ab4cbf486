#include "families/p2os/p2os_family.hpp"

#include "families/p2os/p2os_emulator_kind.hpp"
#include "families/p2os/p2os_probe.hpp"
#include "families/p2os/protocol/frame_format.hpp"

namespace playerkit::families {

FamilySpec p2os_family() {
  namespace p2os = hardware::p2os;
  return {
      .name = "p2os",
      .summary = "Pioneer robots (P2OS/AROS): eleven devices on one serial link",
      // A Pioneer's controller is set to one of five rates; 9600 is the factory's.
      .probes = {{.label = "P2OS", .bauds = {9600, 38400, 19200, 115200, 57600}, .line = {}, .ask = probe_p2os}},
      .framing = {std::make_shared<p2os::P2osFrameFormat>(p2os::kMaxLengthByteToRobot),
                  std::make_shared<p2os::P2osFrameFormat>(p2os::kMaxLengthByteFromRobot)},
      .emulators = {p2os_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info p2os",
              "player-drivers run p2os port=/dev/ttyUSB0 --device position:0 --stats",
              "player-drivers run p2os port=/dev/ttyUSB0 --device position:0 --stdin < drive.jsonl",
              "player-drivers emulate p2os model=p3at baud=38400 --link /tmp/robot --fault bad-checksum=0.01",
          },
  };
}

}  // namespace playerkit::families
