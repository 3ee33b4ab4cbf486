#pragma once
// The rflex family as the tools see it: its probe, trace framing and emulator.

#include <optional>

#include "emulators/emulator_kind.hpp"
#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec rflex_family();

// Whether an RFLEX controller answers SYS_STATUS on the line (rflex.md §2.1),
// and its battery voltage. nullopt when nothing RFLEX answered by the deadlines.
std::optional<Identification> probe_rflex(const ProbeContext& line);

// `player-drivers emulate rflex`: the controller on a robot (model=b21r,
// atrvjr, magellan) with the options every emulated robot shares.
emulators::EmulatorKind rflex_emulator_kind();

}  // namespace playerkit::families
