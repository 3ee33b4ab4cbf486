#pragma once
// The sick family as the tools see it: probes, trace framing and emulators.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec sick_family();

}  // namespace playerkit::families
