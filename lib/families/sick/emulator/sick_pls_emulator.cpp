#include "families/sick/emulator/sick_pls_emulator.hpp"

#include <utility>

namespace playerkit::emulators {

namespace {

SickModelProfile pls_profile() {
  return {.model = hardware::sick::Model::pls,
          .display_name = "SICK PLS",
          .bits_per_byte = 11,  // 8E1: the parity bit costs line time
          .rotation_period = std::chrono::milliseconds(40),
          .configurable = false};
}

}  // namespace

SickPlsEmulator::SickPlsEmulator(SickEmulatorOptions options)
    : SickLaserEmulator(pls_profile(), std::move(options)) {}

}  // namespace playerkit::emulators
