#pragma once
// The p2os family as the tools see it: its probe, trace framing and emulator.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec p2os_family();

}  // namespace playerkit::families
