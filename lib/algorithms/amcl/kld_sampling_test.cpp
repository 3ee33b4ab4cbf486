#include "algorithms/amcl/kld_sampling.hpp"

#include <gtest/gtest.h>

namespace playerkit::amcl {
namespace kld_sampling_test {

TEST(KldSampling, MatchesFox2001FormulaByHand) {
  // k = 2, error 0.01, z = 3: a = 2/9; (1 - 2/9 + sqrt(2/9) * 3)^3 =
  // (0.77778 + 1.41421)^3 = 2.19199^3 = 10.5321; times 1 / 0.02 = 526.61.
  EXPECT_NEAR(kld_sample_bound(2, 0.01, 3.0), 526.607, 1e-3);
  // k = 10: 9 / 0.02 * (1 - 2/81 + sqrt(2/81) * 3)^3 = 450 * 1.44394^3.
  EXPECT_NEAR(kld_sample_bound(10, 0.01, 3.0), 1362.573, 1e-3);
  EXPECT_NEAR(kld_sample_bound(100, 0.01, 3.0), 7331.504, 1e-3);
  EXPECT_NEAR(kld_sample_bound(50, 0.05, 2.0), 707.305, 1e-3);
  EXPECT_EQ(kld_sample_bound(1, 0.01, 3.0), 0.0);
  EXPECT_EQ(kld_sample_bound(0, 0.01, 3.0), 0.0);
}

TEST(KldSampling, GrowsWithBinsAndShrinksWithAllowedError) {
  EXPECT_LT(kld_sample_bound(10, 0.01, 3.0), kld_sample_bound(11, 0.01, 3.0));
  EXPECT_GT(kld_sample_bound(10, 0.01, 3.0), kld_sample_bound(10, 0.02, 3.0));
  EXPECT_GT(kld_sample_bound(10, 0.01, 3.0), kld_sample_bound(10, 0.01, 2.0));
}

TEST(KldSampling, CountIsRoundedUpAndClamped) {
  EXPECT_EQ(kld_particle_count(2, 0.01, 3.0, 100, 5000), 527u);
  EXPECT_EQ(kld_particle_count(1, 0.01, 3.0, 100, 5000), 100u);
  EXPECT_EQ(kld_particle_count(100, 0.01, 3.0, 100, 5000), 5000u);
}

}  // namespace kld_sampling_test
}  // namespace playerkit::amcl
