#pragma once
// `player-drivers emulate reb`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind reb_emulator_kind();

}  // namespace playerkit::families
