#pragma once
// The reb family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec reb_family();

// Whether a REB running LPRSerCom answers on the line (for `probe`).
std::optional<Identification> probe_reb(const ProbeContext& line);

}  // namespace playerkit::families
