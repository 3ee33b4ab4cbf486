#pragma once
// An emulated SICK LMS 200 (sicklms200.md §6): everything of
// SickLaserEmulator plus get type (BA), the five variants (BB), and the
// configuration block (F4/F7) with measuring mode (reflector levels in bits
// 13-15) and unit (mm or cm). Lines are 8N1; the mirror turns at 75 Hz.

#include "families/sick/emulator/sick_laser_emulator.hpp"

namespace playerkit::emulators {

class SickLms200Emulator final : public SickLaserEmulator {
 public:
  explicit SickLms200Emulator(SickEmulatorOptions options = {});
};

}  // namespace playerkit::emulators
