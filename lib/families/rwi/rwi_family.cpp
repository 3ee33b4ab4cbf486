#include "families/rwi/rwi_family.hpp"

namespace playerkit::families {

FamilySpec rwi_family() {
  return {
      .name = "rwi",
      .summary = "RWI B21r/ATRV through RWI's Mobility middleware: refused (unobtainable); use the rflex family",
      .probes = {},
      .framing = {},
      .emulators = {},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples = {"player-drivers info rwi_position"},
  };
}

}  // namespace playerkit::families
