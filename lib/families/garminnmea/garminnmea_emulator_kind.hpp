#pragma once
// `player-drivers emulate garminnmea`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind garminnmea_emulator_kind();

}  // namespace playerkit::families
