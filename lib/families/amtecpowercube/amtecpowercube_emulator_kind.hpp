#pragma once
// `player-drivers emulate amtecpowercube`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind amtecpowercube_emulator_kind();

}  // namespace playerkit::families
