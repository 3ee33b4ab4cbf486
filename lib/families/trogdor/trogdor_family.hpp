#pragma once
// The trogdor family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec trogdor_family();

// Whether a Trogdor cerebellum answers GET_ODOM on the line (for `probe`).
std::optional<Identification> probe_trogdor(const ProbeContext& line);

// `player-drivers emulate trogdor`: a robot the riders' lasers can sit on.
emulators::EmulatorKind trogdor_emulator_kind();

}  // namespace playerkit::families
