#pragma once
// A sonar ring in the scene: one ray per transducer along its heading,
// raised to range_min, range_max where nothing is met.

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/noise.hpp"
#include "sim/world/readings.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim {

// `model_pose`: the global pose of the sonar model, the frame its
// transducer poses are given in. Leaves `time` 0.
[[nodiscard]] SonarScan scan_sonar(const Scene& scene, const SonarSpec& spec, const geometry::Pose2& model_pose,
                                   ModelId own_root, NoiseDraws& noise);

}  // namespace playerkit::sim
