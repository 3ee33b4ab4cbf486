#pragma once
// The ptu46 family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec ptu46_family();

// Whether a PTU-46 answers on the line, and its resolution (for `probe`).
std::optional<Identification> probe_ptu46(const ProbeContext& line);

}  // namespace playerkit::families
