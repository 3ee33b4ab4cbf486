#pragma once
// An emulated SICK PLS (sickpls.md §6): installation mode with `SICK_PLS`,
// baud rates, and streaming of its one variant (180 deg at 0.5 deg, 361
// values) as B0 or a B7 subrange, always in centimetres with bits 13-15
// clear (field flags, no field is configured). Get type, variant and
// configuration are not answered (92): the driver never sends them.
// Lines are 8E1 (11 bits a byte); the mirror takes 40 ms a turn.

#include "families/sick/emulator/sick_laser_emulator.hpp"

namespace playerkit::emulators {

class SickPlsEmulator final : public SickLaserEmulator {
 public:
  explicit SickPlsEmulator(SickEmulatorOptions options = {});
};

}  // namespace playerkit::emulators
