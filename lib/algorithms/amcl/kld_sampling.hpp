#pragma once
// KLD-sampling (Fox 2001): how many particles are enough so that, with
// probability 1 - delta, the Kullback-Leibler distance between the particle
// approximation and the true posterior stays below `error`, given that the
// samples so far occupy `occupied_bins` bins of a pose histogram.
//
//   n = (k - 1) / (2 error) * (1 - 2 / (9 (k - 1)) + sqrt(2 / (9 (k - 1))) z)^3
//
// (the Wilson-Hilferty approximation of the chi-square quantile), where z
// is the upper 1 - delta quantile of the standard normal.

#include <cstddef>

namespace playerkit::amcl {

// The unclamped bound; 0 for k <= 1 (a single bin needs no more samples).
double kld_sample_bound(std::size_t occupied_bins, double error, double z);

// The bound rounded up and clamped into [min_particles, max_particles].
std::size_t kld_particle_count(std::size_t occupied_bins, double error, double z,
                               std::size_t min_particles, std::size_t max_particles);

}  // namespace playerkit::amcl
