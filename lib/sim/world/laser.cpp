#include "sim/world/laser.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace playerkit::sim {

LaserScan scan_laser(const Scene& scene, const LaserSpec& spec, const geometry::Pose2& sensor_pose,
                     ModelId own_root, NoiseDraws& noise) {
  LaserScan scan;
  scan.range_max = spec.range_max;
  const int samples = std::max(spec.samples, 0);
  if (samples == 0) return scan;

  const bool single = samples == 1;
  const double spacing = single ? 0.0 : spec.fov / static_cast<double>(samples - 1);
  scan.min_angle = single ? 0.0 : -spec.fov / 2.0;
  scan.max_angle = single ? 0.0 : spec.fov / 2.0;
  const auto count = static_cast<std::size_t>(samples);

  // Every sample draws the same numbers in the same order whatever it
  // meets, so one beam's noise never depends on what another beam hit.
  thread_local std::vector<double> gaussian, proportional;
  thread_local std::vector<SceneRay> rays;
  thread_local std::vector<RayHit> hits;
  gaussian.resize(count);
  proportional.resize(count);
  rays.resize(count);
  hits.resize(count);
  const Eigen::Vector2d origin = sensor_pose.translation();
  const double jitter_width = spacing * spec.angle_jitter;
  // Beam i points at yaw + min_angle + i * spacing: the first direction
  // turned i times by the spacing (no trigonometry per beam; the rounding
  // this gathers over 361 beams is about 1e-14 rad).
  const Eigen::Vector2d turn(std::cos(spacing), std::sin(spacing));
  Eigen::Vector2d direction(std::cos(sensor_pose.yaw + scan.min_angle), std::sin(sensor_pose.yaw + scan.min_angle));
  for (std::size_t i = 0; i < count; ++i) {
    const double jitter = jitter_width != 0.0 ? jitter_width * noise.uniform(-0.5, 0.5) : 0.0;
    gaussian[i] = noise.gaussian(spec.noise_sd);
    proportional[i] =
        spec.noise_proportional != 0.0 ? noise.uniform(-spec.noise_proportional, spec.noise_proportional) : 0.0;
    rays[i].origin = origin;
    if (jitter != 0.0) {
      const double angle = sensor_pose.yaw + scan.min_angle + spacing * static_cast<double>(i) + jitter;
      rays[i].direction = {std::cos(angle), std::sin(angle)};
    } else {
      rays[i].direction = direction;
    }
    direction = {direction.x() * turn.x() - direction.y() * turn.y(),
                 direction.x() * turn.y() + direction.y() * turn.x()};
  }
  scene.cast_all(rays, spec.range_max, own_root, hits);

  scan.ranges.reserve(count);
  scan.intensities.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const RayHit& hit = hits[i];
    double range = hit.range;
    if (range < spec.range_max) range += gaussian[i] + proportional[i] * range;
    scan.ranges.push_back(std::min(std::max(range, 0.0), spec.range_max));
    const bool bright = hit.model != kNoModel && scene.model(hit.model).returns.laser_bright;
    scan.intensities.push_back(bright ? 1 : 0);
  }
  return scan;
}

}  // namespace playerkit::sim
