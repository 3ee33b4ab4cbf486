#pragma once
// `player-drivers emulate ptu46`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind ptu46_emulator_kind();

}  // namespace playerkit::families
