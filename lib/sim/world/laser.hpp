#pragma once
// A scanning laser in the scene: samples evenly over the fov, first and
// last on its edges (one sample: straight ahead), each the range to the
// first wall or unrelated model with ranger return >= 0, with the spec's
// noise below range_max.

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/noise.hpp"
#include "sim/world/readings.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim {

// `sensor_pose`: the global pose of the scan origin. `own_root`: the
// sensor's robot, whose bodies the rays pass through. Leaves `time` 0.
[[nodiscard]] LaserScan scan_laser(const Scene& scene, const LaserSpec& spec, const geometry::Pose2& sensor_pose,
                                   ModelId own_root, NoiseDraws& noise);

}  // namespace playerkit::sim
