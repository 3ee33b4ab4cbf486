#pragma once
// `player-drivers emulate cmucam2`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind cmucam2_emulator_kind();

}  // namespace playerkit::families
