#pragma once
// The sonyevid30 family as the tools see it: its probe, trace framing and emulator.

#include "emulators/emulator_kind.hpp"
#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec sonyevid30_family();

// Whether a VISCA camera at address 1 answers a pan/tilt inquiry, and where it points (for `probe`).
std::optional<Identification> probe_sonyevid30(const ProbeContext& line);

// `player-drivers emulate sonyevid30`: its options and factory.
emulators::EmulatorKind sonyevid30_emulator_kind();

}  // namespace playerkit::families
