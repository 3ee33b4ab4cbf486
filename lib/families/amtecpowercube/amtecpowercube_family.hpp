#pragma once
// The amtecpowercube family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec amtecpowercube_family();

// Which of the wrist's modules answer on the line (for `probe`).
std::optional<Identification> probe_amtecpowercube(const ProbeContext& line);

}  // namespace playerkit::families
