#include "algorithms/amcl/amcl_parameters.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace playerkit::amcl {
namespace amcl_parameters_test {

TEST(AmclParameters, DefaultsAreValidAndMatchPlayer15WherePlayerHadThem) {
  const AmclParameters p;
  EXPECT_NO_THROW(validate(p));
  EXPECT_EQ(p.min_particles, 100u);
  EXPECT_DOUBLE_EQ(p.kld_error, 0.01);
  EXPECT_DOUBLE_EQ(p.kld_z, 3.0);
  EXPECT_DOUBLE_EQ(p.update_min_distance, 0.2);
  EXPECT_NEAR(p.update_min_angle, 0.5236, 1e-4);
}

TEST(AmclParameters, RejectsNonsense) {
  const auto rejects = [](auto change) {
    AmclParameters p;
    change(p);
    EXPECT_THROW(validate(p), std::invalid_argument);
  };
  rejects([](AmclParameters& p) { p.min_particles = 6000; });
  rejects([](AmclParameters& p) { p.min_particles = 0; });
  rejects([](AmclParameters& p) { p.kld_error = 0.0; });
  rejects([](AmclParameters& p) { p.alpha_slow = 0.5; p.alpha_fast = 0.1; });
  rejects([](AmclParameters& p) { p.translation_noise_from_rotation = -0.1; });
  rejects([](AmclParameters& p) { p.sigma_hit = 0.0; });
  rejects([](AmclParameters& p) { p.z_hit = p.z_short = p.z_max = p.z_rand = 0.0; });
  rejects([](AmclParameters& p) { p.resample_interval = 0; });
  rejects([](AmclParameters& p) { p.cluster_angle_size = -1.0; });
  rejects([](AmclParameters& p) { p.laser_max_beams = 0; });
  rejects([](AmclParameters& p) { p.scan_likelihood_exponent = 0.0; });
  rejects([](AmclParameters& p) { p.scan_likelihood_exponent = 1.5; });
  rejects([](AmclParameters& p) { p.beam_scan_likelihood_exponent = 0.0; });
  rejects([](AmclParameters& p) { p.beam_scan_likelihood_exponent = 1.5; });
  rejects([](AmclParameters& p) { p.seed_search_position_step = -0.5; });
  rejects([](AmclParameters& p) { p.seed_search_heading_step = 0.0; });
  rejects([](AmclParameters& p) { p.seed_search_candidates = 0; });
  rejects([](AmclParameters& p) { p.seed_search_uniform_share = 1.5; });
  rejects([](AmclParameters& p) { p.seed_search_below_density = -1.0; });
  rejects([](AmclParameters& p) { p.seed_search_distance = -1.0; });
  rejects([](AmclParameters& p) { p.seed_search_pool_factor = 0; });
}

}  // namespace amcl_parameters_test
}  // namespace playerkit::amcl
