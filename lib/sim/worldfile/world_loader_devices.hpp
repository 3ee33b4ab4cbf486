#pragma once
// Internal: the Player address of every device a world offers (§3.6, §4.3).
//
// Stage 1.3: each device entity on its robot's port (or its own `port`;
// none: the default port), index = its explicit `index` or else the lowest
// index still free for that port and interface. (Stage 1.3 put every
// index-less device at 0, a second sonar overwriting the first.)
//
// Stage 3/4 (no ports in the world): everything on the default port; the
// k-th robot (top-level position model, in world order) gets its devices at
// index k where free, else at the lowest free index; devices on no robot
// come last, at the lowest free index.

#include <vector>

#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/world_loader_context.hpp"

namespace playerkit::sim::worldfile {

// Throws WorldFileError when two devices are given the same explicit address.
std::vector<SimDevice> assign_device_indices(const LoadContext& context);

}  // namespace playerkit::sim::worldfile
