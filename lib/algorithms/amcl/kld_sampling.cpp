#include "algorithms/amcl/kld_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::amcl {

double kld_sample_bound(std::size_t occupied_bins, double error, double z) {
  if (occupied_bins <= 1) return 0.0;
  const double k_minus_1 = static_cast<double>(occupied_bins - 1);
  const double a = 2.0 / (9.0 * k_minus_1);
  const double cube_root = 1.0 - a + std::sqrt(a) * z;
  return k_minus_1 / (2.0 * error) * cube_root * cube_root * cube_root;
}

std::size_t kld_particle_count(std::size_t occupied_bins, double error, double z,
                               std::size_t min_particles, std::size_t max_particles) {
  const double bound = std::ceil(kld_sample_bound(occupied_bins, error, z));
  if (bound >= static_cast<double>(max_particles)) return max_particles;
  return std::clamp(static_cast<std::size_t>(std::max(bound, 0.0)), min_particles, max_particles);
}

}  // namespace playerkit::amcl
