#pragma once
// A sonar ring in the scene: one ray per transducer along its heading,
// raised to range_min, range_max where nothing is met.

#include <Eigen/Core>

#include <span>
#include <vector>

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

// Each transducer's heading in the model's frame as a unit vector, for the
// overload below: a ring scanned every step needs them only once.
[[nodiscard]] std::vector<Eigen::Vector2d> transducer_headings(const SonarSpec& spec);
// The same scan, given transducer_headings(spec) (the same answers).
[[nodiscard]] SonarScan scan_sonar(const Scene& scene, const SonarSpec& spec,
                                   std::span<const Eigen::Vector2d> headings, const geometry::Pose2& model_pose,
                                   ModelId own_root, NoiseDraws& noise);

}  // namespace playerkit::sim
