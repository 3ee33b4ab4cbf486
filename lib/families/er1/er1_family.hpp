#pragma once
// The er1 family as the tools see it: its probe, trace framing and emulator.

#include "emulators/emulator_kind.hpp"
#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec er1_family();

// Whether an ER1's Robot Control Module answers on the line (for `probe`).
std::optional<Identification> probe_er1(const ProbeContext& line);

// `player-drivers emulate er1`: its options and factory.
emulators::EmulatorKind er1_emulator_kind();

}  // namespace playerkit::families
