#pragma once
// The segwayrmp family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec segwayrmp_family();

// Whether a Segway RMP talks behind an slcan adapter on the line (for `probe`).
std::optional<Identification> probe_segwayrmp(const ProbeContext& line);

// `player-drivers emulate segwayrmp`: its options and factory.
emulators::EmulatorKind segwayrmp_emulator_kind();

}  // namespace playerkit::families
