#include "sim/world/sonar.hpp"

#include <algorithm>

namespace playerkit::sim {

SonarScan scan_sonar(const Scene& scene, const SonarSpec& spec, const geometry::Pose2& model_pose, ModelId own_root,
                     NoiseDraws& noise) {
  SonarScan scan;
  scan.ranges.reserve(spec.transducers.size());
  const ModelFilter rangers_see;  // empty: the scene's own test (a body, ranger return >= 0)
  for (const geometry::Pose2& transducer : spec.transducers) {
    // Drawn for every transducer, hit or not, so each one's noise is fixed
    // by its place in the ring alone.
    const double gaussian = noise.gaussian(spec.noise_sd);
    const geometry::Pose2 ray = model_pose.compose(transducer);
    double range = scene.cast(ray.translation(), ray.yaw, spec.range_max, own_root, rangers_see).range;
    if (range < spec.range_max) range += gaussian;
    scan.ranges.push_back(std::min(std::max(range, spec.range_min), spec.range_max));
  }
  return scan;
}

}  // namespace playerkit::sim
