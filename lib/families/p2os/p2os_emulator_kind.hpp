#pragma once
// `player-drivers emulate p2os`: the emulated Pioneer's options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind p2os_emulator_kind();

}  // namespace playerkit::families
