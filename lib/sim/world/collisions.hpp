#pragma once
// Internal: whether a body standing somewhere overlaps a wall of the map
// (collisions.cpp also holds World::State::collides_at, which adds the
// other models' bodies).

#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/world/body_geometry.hpp"

namespace playerkit::sim {

// Whether the body shares area with an occupied cell. The whole footprint
// counts, not only its outline as in Stage, so a robot placed inside a
// wall cannot drive out through it. Outside the map is open floor.
[[nodiscard]] bool body_overlaps_walls(const grid::OccupancyGrid& map, const PlacedBody& body);

}  // namespace playerkit::sim
