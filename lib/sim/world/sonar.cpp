#include "sim/world/sonar.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace playerkit::sim {

std::vector<Eigen::Vector2d> transducer_headings(const SonarSpec& spec) {
  std::vector<Eigen::Vector2d> headings;
  headings.reserve(spec.transducers.size());
  for (const geometry::Pose2& transducer : spec.transducers) {
    headings.emplace_back(std::cos(transducer.yaw), std::sin(transducer.yaw));
  }
  return headings;
}

SonarScan scan_sonar(const Scene& scene, const SonarSpec& spec, const geometry::Pose2& model_pose, ModelId own_root,
                     NoiseDraws& noise) {
  return scan_sonar(scene, spec, transducer_headings(spec), model_pose, own_root, noise);
}

SonarScan scan_sonar(const Scene& scene, const SonarSpec& spec, std::span<const Eigen::Vector2d> headings,
                     const geometry::Pose2& model_pose, ModelId own_root, NoiseDraws& noise) {
  SonarScan scan;
  const std::size_t count = std::min(spec.transducers.size(), headings.size());
  thread_local std::vector<SceneRay> rays;
  thread_local std::vector<RayHit> hits;
  rays.resize(count);
  hits.resize(count);
  // Each transducer's ray: the model's pose composed with the transducer's,
  // with the model's turn computed once.
  const double c = std::cos(model_pose.yaw), s = std::sin(model_pose.yaw);
  for (std::size_t i = 0; i < count; ++i) {
    const geometry::Pose2& transducer = spec.transducers[i];
    const Eigen::Vector2d& heading = headings[i];
    rays[i].origin = {model_pose.x + c * transducer.x - s * transducer.y,
                      model_pose.y + s * transducer.x + c * transducer.y};
    rays[i].direction = {c * heading.x() - s * heading.y(), s * heading.x() + c * heading.y()};
  }
  scene.cast_all(rays, spec.range_max, own_root, hits);

  scan.ranges.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Drawn for every transducer, hit or not, so each one's noise is fixed
    // by its place in the ring alone.
    const double gaussian = noise.gaussian(spec.noise_sd);
    double range = hits[i].range;
    if (range < spec.range_max) range += gaussian;
    scan.ranges.push_back(std::min(std::max(range, spec.range_min), spec.range_max));
  }
  return scan;
}

}  // namespace playerkit::sim
