#pragma once
// Internal: which Stage wrote a world (§1.9), from what it contains.

#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

// Stage 1.3 when the world has ports, a bitmap or gui entity, 1.3-only
// device types (ptz, fiducialfinder/lbd, vision, truth, sonar, box, puck,
// ...), sim_timestep; Stage 3/4 when it has block, window, sensor, model,
// ranger or fiducial entities, a floorplan, interval_sim, a `bitmap`
// property or 4-element poses (4 when a sensor is present, 3 with a laser
// entity or a ranger with scount). A world with none of these (3-element
// poses, position and laser entities only) is read as Stage 1.3, Player
// 1.5's own. Throws WorldFileError when the world has clues of both, naming one
// of each.
Dialect detect_dialect(const WorldTree& tree);

}  // namespace playerkit::sim::worldfile
