#pragma once
// The nomad family as the tools see it: no serial probe (the robot is behind
// Nomadic's server on TCP: `player-drivers run nomad host=H port=P`), the
// Nclient trace framing and the emulated robot.

#include "families/family_spec.hpp"

namespace playerkit::families {

FamilySpec nomad_family();

}  // namespace playerkit::families
