#pragma once
// The khepera family as the tools see it: its probe, trace framing and emulator.

#include <optional>

#include "emulators/emulator_kind.hpp"
#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec khepera_family();

// Whether a Khepera answers E (its wheel speeds) on the line.
std::optional<Identification> probe_khepera(const ProbeContext& line);

// `player-drivers emulate khepera`: its options and factory.
emulators::EmulatorKind khepera_emulator_kind();

}  // namespace playerkit::families
