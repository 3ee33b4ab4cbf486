#include "algorithms/amcl/amcl_parameters.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace playerkit::amcl {
namespace {

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(std::string("amcl parameters: ") + message);
}

bool is_probability(double value) { return std::isfinite(value) && value >= 0.0 && value <= 1.0; }
bool is_non_negative(double value) { return std::isfinite(value) && value >= 0.0; }
bool is_positive(double value) { return std::isfinite(value) && value > 0.0; }

}  // namespace

void validate(const AmclParameters& p) {
  require(p.min_particles >= 1, "min_particles must be at least 1");
  require(p.min_particles <= p.max_particles, "min_particles exceeds max_particles");
  require(p.kld_error > 0.0 && p.kld_error < 1.0, "kld_error must lie in (0, 1)");
  require(is_non_negative(p.kld_z), "kld_z must be non-negative");
  require(is_probability(p.alpha_slow) && is_probability(p.alpha_fast),
          "alpha_slow and alpha_fast must lie in [0, 1]");
  require(p.alpha_slow <= p.alpha_fast, "alpha_slow must not exceed alpha_fast");
  require(is_non_negative(p.global_particles_per_square_metre),
          "global_particles_per_square_metre must be non-negative");
  require(is_probability(p.search_alpha_slow) && is_probability(p.search_alpha_fast),
          "search_alpha_slow and search_alpha_fast must lie in [0, 1]");
  require(p.search_alpha_slow <= p.search_alpha_fast, "search_alpha_slow must not exceed search_alpha_fast");
  require(is_probability(p.search_end_weight) && p.search_end_weight > 0.0,
          "search_end_weight must lie in (0, 1]");
  require(is_positive(p.search_end_spread), "search_end_spread must be positive");
  require(p.search_end_updates >= 1, "search_end_updates must be at least 1");
  require(is_non_negative(p.seed_search_position_step), "seed_search_position_step must be at least 0 (0: off)");
  require(is_positive(p.seed_search_heading_step) && p.seed_search_heading_step <= std::numbers::pi,
          "seed_search_heading_step must lie in (0, pi]");
  require(p.seed_search_candidates >= 1, "seed_search_candidates must be at least 1");
  require(is_non_negative(p.seed_search_distance), "seed_search_distance must be non-negative");
  require(p.seed_search_scans_most >= 1, "seed_search_scans_most must be at least 1");
  require(p.seed_search_pool_factor >= 1, "seed_search_pool_factor must be at least 1");
  require(is_probability(p.seed_search_uniform_share), "seed_search_uniform_share must lie in [0, 1]");
  require(is_non_negative(p.seed_search_below_density), "seed_search_below_density must be non-negative");
  require(is_non_negative(p.rotation_noise_from_rotation) &&
              is_non_negative(p.rotation_noise_from_translation) &&
              is_non_negative(p.translation_noise_from_translation) &&
              is_non_negative(p.translation_noise_from_rotation) &&
              is_non_negative(p.strafe_noise_from_translation),
          "motion noise coefficients must be non-negative");
  require(p.laser_max_beams >= 1, "laser_max_beams must be at least 1");
  require(is_non_negative(p.z_hit) && is_non_negative(p.z_short) && is_non_negative(p.z_max) &&
              is_non_negative(p.z_rand),
          "z_hit, z_short, z_max and z_rand must be non-negative");
  require(p.z_hit + p.z_short + p.z_max + p.z_rand > 0.0, "the z_* mixture weights are all zero");
  require(is_positive(p.sigma_hit), "sigma_hit must be positive");
  require(is_positive(p.lambda_short), "lambda_short must be positive");
  require(is_positive(p.likelihood_max_distance), "likelihood_max_distance must be positive");
  require(is_non_negative(p.short_reading_margin) && is_non_negative(p.short_reading_through_wall_margin),
          "short_reading_margin and short_reading_through_wall_margin must be non-negative");
  require(is_probability(p.short_reading_through_wall_share),
          "short_reading_through_wall_share must lie in [0, 1]");
  require(is_positive(p.scan_likelihood_exponent) && p.scan_likelihood_exponent <= 1.0,
          "scan_likelihood_exponent must lie in (0, 1]");
  require(is_positive(p.beam_scan_likelihood_exponent) && p.beam_scan_likelihood_exponent <= 1.0,
          "beam_scan_likelihood_exponent must lie in (0, 1]");
  require(is_non_negative(p.update_min_distance) && is_non_negative(p.update_min_angle),
          "update thresholds must be non-negative");
  require(is_non_negative(p.uncertain_heading_deviation) && is_non_negative(p.uncertain_position_deviation),
          "uncertain_heading_deviation and uncertain_position_deviation must be at least 0 (0: off)");
  require(p.resample_interval >= 1, "resample_interval must be at least 1");
  require(is_positive(p.cluster_cell_size) && is_positive(p.cluster_angle_size),
          "cluster bin sizes must be positive");
  require(p.max_hypotheses >= 1, "max_hypotheses must be at least 1");
}

}  // namespace playerkit::amcl
