#pragma once
// The ranges an emulated SICK laser measures: each beam ray-cast through the
// map (RangeCaster, cast_ray's answers at a fraction of the cost, so 75
// scans of 361 beams a second cost little), the nearest reflector segment
// met, and seeded Gaussian noise. Pure: the pose and angles come in.

#include "algorithms/grid/range_caster.hpp"
#include "families/sick/emulator/sick_emulator_options.hpp"

#include <optional>
#include <random>
#include <vector>

namespace playerkit::emulators {

struct SickBeamReading {
  double range_m = 0.0;           // at most the max range
  std::uint8_t reflector_level = 0;
  bool returned = false;          // false: nothing within the max range
};

class SickLaserScene {
 public:
  // Copies what it needs from `options`; throws std::invalid_argument for a
  // reflector level over 7 or a negative noise sigma.
  explicit SickLaserScene(const SickEmulatorOptions& options);

  // One beam from `origin` along world angle `angle` (radians). Noise, when
  // configured, is drawn here, so the order of calls matters (seeded,
  // deterministic).
  SickBeamReading measure(const Eigen::Vector2d& origin, double angle, double max_range_m);

 private:
  double wall_range(const Eigen::Vector2d& origin, double angle, double max_range_m) const;
  double noisy(double range_m, double max_range_m);

  std::optional<grid::RangeCaster> caster_;
  double cell_size_ = 0.0;
  std::optional<double> range_without_map_m_;
  std::vector<SickReflector> reflectors_;
  double noise_sigma_m_ = 0.0;
  std::mt19937_64 random_;
};

}  // namespace playerkit::emulators
