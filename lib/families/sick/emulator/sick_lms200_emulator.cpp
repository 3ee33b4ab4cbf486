#include "families/sick/emulator/sick_lms200_emulator.hpp"

#include <utility>

namespace playerkit::emulators {

namespace {

SickModelProfile lms200_profile() {
  return {.model = hardware::sick::Model::lms200,
          .display_name = "SICK LMS 200",
          .bits_per_byte = 10,  // 8N1
          .rotation_period = std::chrono::nanoseconds(1'000'000'000 / 75),
          .configurable = true};
}

}  // namespace

SickLms200Emulator::SickLms200Emulator(SickEmulatorOptions options)
    : SickLaserEmulator(lms200_profile(), std::move(options)) {}

}  // namespace playerkit::emulators
