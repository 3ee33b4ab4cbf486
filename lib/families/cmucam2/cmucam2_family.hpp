#pragma once
// The cmucam2 family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec cmucam2_family();

// Whether a CMUcam2 answers on the line, and its version (for `probe`).
std::optional<Identification> probe_cmucam2(const ProbeContext& line);

}  // namespace playerkit::families
