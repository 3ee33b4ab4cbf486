#pragma once
// The flockofbirds family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec flockofbirds_family();

// Whether a Flock of Birds answers on the line, and its scaling (for `probe`).
std::optional<Identification> probe_flockofbirds(const ProbeContext& line);

}  // namespace playerkit::families
