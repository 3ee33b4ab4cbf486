#pragma once
// A fiducial finder in the scene: every present, unrelated model with a
// fiducial id and the finder's key, within range and fov, whose centre a
// line-of-sight ray reaches without meeting a wall or another model first.

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/readings.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim {

// Sightings ordered by range, nearest first. Leaves `time` 0.
[[nodiscard]] FiducialScan find_fiducials(const Scene& scene, const FiducialSpec& spec,
                                          const geometry::Pose2& finder_pose, ModelId own_root);

}  // namespace playerkit::sim
