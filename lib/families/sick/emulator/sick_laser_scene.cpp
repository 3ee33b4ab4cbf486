#include "families/sick/emulator/sick_laser_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace playerkit::emulators {
namespace {

// Distance along the ray to the segment, or nullopt if it misses.
std::optional<double> ray_meets_segment(const Eigen::Vector2d& origin,
                                        const Eigen::Vector2d& direction,
                                        const SickReflector& segment) {
  const Eigen::Vector2d along = segment.to - segment.from;
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  const double denominator = cross(direction, along);
  if (std::abs(denominator) < 1e-12) return std::nullopt;  // parallel: grazing tape is not seen
  const Eigen::Vector2d to_start = segment.from - origin;
  const double distance = cross(to_start, along) / denominator;
  const double fraction = cross(to_start, direction) / denominator;
  if (distance < 0.0 || fraction < 0.0 || fraction > 1.0) return std::nullopt;
  return distance;
}

// A double in (0, 1], from the top 53 bits: never 0, so log() is finite.
double unit_interval(std::mt19937_64& random) {
  return (static_cast<double>(random() >> 11) + 1.0) * 0x1.0p-53;
}

}  // namespace

SickLaserScene::SickLaserScene(const SickEmulatorOptions& options)
    : range_without_map_m_(options.range_without_map_m),
      reflectors_(options.reflectors),
      noise_sigma_m_(options.range_noise_sigma_m),
      random_(options.noise_seed) {
  if (!(options.range_noise_sigma_m >= 0.0)) {
    throw std::invalid_argument("SICK emulator: range noise sigma must be >= 0");
  }
  for (const SickReflector& reflector : reflectors_) {
    if (reflector.level > 7) {
      throw std::invalid_argument("SICK emulator: a reflector level is 0..7 (3 bits)");
    }
  }
  if (options.map != nullptr && !options.map->empty()) {
    caster_.emplace(*options.map, options.ray_stop);
    cell_size_ = options.map->resolution();
  }
}

double SickLaserScene::wall_range(const Eigen::Vector2d& origin, double angle,
                                  double max_range_m) const {
  if (caster_) return caster_->range(origin, angle, max_range_m);
  return std::min(range_without_map_m_.value_or(max_range_m), max_range_m);
}

SickBeamReading SickLaserScene::measure(const Eigen::Vector2d& origin, double angle,
                                        double max_range_m) {
  SickBeamReading reading;
  reading.range_m = wall_range(origin, angle, max_range_m);
  if (!reflectors_.empty()) {
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    const double seen_up_to = reading.range_m + 1.5 * cell_size_;
    double nearest = std::numeric_limits<double>::infinity();
    for (const SickReflector& reflector : reflectors_) {
      const auto distance = ray_meets_segment(origin, direction, reflector);
      if (distance && *distance < max_range_m && *distance <= seen_up_to && *distance < nearest) {
        nearest = *distance;
        reading.reflector_level = reflector.level;
      }
    }
    reading.range_m = std::min(reading.range_m, nearest);
  }
  reading.returned = reading.range_m < max_range_m;
  if (reading.returned && noise_sigma_m_ > 0.0) reading.range_m = noisy(reading.range_m, max_range_m);
  return reading;
}

double SickLaserScene::noisy(double range_m, double max_range_m) {
  // Box-Muller on mt19937_64, whose output the standard fixes: the same seed
  // gives the same noise with every standard library.
  const double radius = std::sqrt(-2.0 * std::log(unit_interval(random_)));
  const double gaussian = radius * std::cos(2.0 * std::numbers::pi * unit_interval(random_));
  return std::clamp(range_m + noise_sigma_m_ * gaussian, 0.0, max_range_m);
}

}  // namespace playerkit::emulators
