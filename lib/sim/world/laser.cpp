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
  thread_local std::vector<double> jitters, gaussian, proportional;
  thread_local std::vector<Eigen::Vector2d> directions;
  thread_local std::vector<RayHit> hits;
  jitters.assign(count, 0.0);
  gaussian.assign(count, 0.0);
  proportional.assign(count, 0.0);
  directions.resize(count);
  hits.resize(count);
  const double jitter_width = spacing * spec.angle_jitter;
  if (jitter_width != 0.0 || spec.noise_sd != 0.0 || spec.noise_proportional != 0.0) {
    for (std::size_t i = 0; i < count; ++i) {
      if (jitter_width != 0.0) jitters[i] = jitter_width * noise.uniform(-0.5, 0.5);
      gaussian[i] = noise.gaussian(spec.noise_sd);
      if (spec.noise_proportional != 0.0) {
        proportional[i] = noise.uniform(-spec.noise_proportional, spec.noise_proportional);
      }
    }
  }
  // Beam i points at yaw + min_angle + i * spacing: the first direction
  // turned i times by the spacing (no trigonometry per beam; the rounding
  // this gathers over 361 beams is about 1e-14 rad). Scalars, not an Eigen
  // vector: stored as two halves and loaded as one, a vector stalled every
  // beam on store forwarding.
  const Eigen::Vector2d origin = sensor_pose.translation();
  const double turn_cos = std::cos(spacing), turn_sin = std::sin(spacing);
  double direction_x = std::cos(sensor_pose.yaw + scan.min_angle);
  double direction_y = std::sin(sensor_pose.yaw + scan.min_angle);
  for (std::size_t i = 0; i < count; ++i) {
    if (jitters[i] != 0.0) {
      const double angle = sensor_pose.yaw + scan.min_angle + spacing * static_cast<double>(i) + jitters[i];
      directions[i] = {std::cos(angle), std::sin(angle)};
    } else {
      directions[i] = {direction_x, direction_y};
    }
    const double turned_x = direction_x * turn_cos - direction_y * turn_sin;
    direction_y = direction_x * turn_sin + direction_y * turn_cos;
    direction_x = turned_x;
  }
  scene.cast_fan(origin, directions, spec.range_max, own_root, hits);

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
