#include "sim/world/laser.hpp"

#include <algorithm>
#include <cmath>

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
  scan.ranges.reserve(static_cast<std::size_t>(samples));
  scan.intensities.reserve(static_cast<std::size_t>(samples));

  const Eigen::Vector2d origin = sensor_pose.translation();
  const double jitter_width = spacing * spec.angle_jitter;
  const ModelFilter rangers_see;  // empty: the scene's own test (a body, ranger return >= 0)

  for (int i = 0; i < samples; ++i) {
    // Every sample draws the same numbers whatever it meets, so one beam's
    // noise never depends on what another beam hit.
    const double jitter = jitter_width != 0.0 ? jitter_width * noise.uniform(-0.5, 0.5) : 0.0;
    const double gaussian = noise.gaussian(spec.noise_sd);
    const double proportional =
        spec.noise_proportional != 0.0 ? noise.uniform(-spec.noise_proportional, spec.noise_proportional) : 0.0;

    const double bearing = scan.min_angle + spacing * static_cast<double>(i) + jitter;
    const RayHit hit = scene.cast(origin, sensor_pose.yaw + bearing, spec.range_max, own_root, rangers_see);

    double range = hit.range;
    if (range < spec.range_max) range += gaussian + proportional * range;
    scan.ranges.push_back(std::min(std::max(range, 0.0), spec.range_max));
    const bool bright = hit.model != kNoModel && scene.model(hit.model).returns.laser_bright;
    scan.intensities.push_back(bright ? 1 : 0);
  }
  return scan;
}

}  // namespace playerkit::sim
