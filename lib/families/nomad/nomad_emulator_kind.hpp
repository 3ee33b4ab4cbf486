#pragma once
// `player-drivers emulate nomad`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind nomad_emulator_kind();

}  // namespace playerkit::families
