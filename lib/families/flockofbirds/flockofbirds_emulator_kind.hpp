#pragma once
// `player-drivers emulate flockofbirds`: its options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind flockofbirds_emulator_kind();

}  // namespace playerkit::families
