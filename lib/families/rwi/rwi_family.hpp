#pragma once
// The rwi family as the tools see it: its name and summary; nothing to
// probe, trace or emulate (there is no byte protocol: rwi.md §5).

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec rwi_family();

}  // namespace playerkit::families
