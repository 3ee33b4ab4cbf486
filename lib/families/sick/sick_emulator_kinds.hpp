#pragma once
// `player-drivers emulate sicklms200 | sickpls`: each model's options and factory.

#include "emulators/emulator_kind.hpp"

namespace playerkit::families {

emulators::EmulatorKind sicklms200_emulator_kind();
emulators::EmulatorKind sickpls_emulator_kind();

}  // namespace playerkit::families
