#include "algorithms/amcl/low_variance_resampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace playerkit::amcl {
namespace low_variance_resampler_test {

std::vector<std::size_t> counts_of(const std::vector<std::uint32_t>& indices, std::size_t n) {
  std::vector<std::size_t> counts(n, 0);
  for (std::uint32_t i : indices) ++counts.at(i);
  return counts;
}

TEST(LowVarianceResample, EachParticleGetsFloorOrCeilOfItsShare) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> weights(50);
  for (double& w : weights) w = unit(rng) * unit(rng);
  double total = 0.0;
  for (double w : weights) total += w;
  std::vector<std::uint32_t> indices;
  for (int trial = 0; trial < 20; ++trial) {
    low_variance_resample(weights, 1000, unit(rng), indices);
    ASSERT_EQ(indices.size(), 1000u);
    EXPECT_TRUE(std::is_sorted(indices.begin(), indices.end()));
    const auto counts = counts_of(indices, weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const double share = 1000.0 * weights[i] / total;
      EXPECT_GE(static_cast<double>(counts[i]), std::floor(share) - 1e-9) << i;
      EXPECT_LE(static_cast<double>(counts[i]), std::ceil(share) + 1e-9) << i;
    }
  }
}

TEST(LowVarianceResample, CountsAreProportionalChiSquare) {
  // Weights 1:2:3:4 resampled 100 times each into 10 slots: over the runs the
  // counts follow the weights. Chi-square with 3 degrees of freedom: the
  // 99.9% quantile is 16.27 (a systematic sampler does far better than that).
  const std::vector<double> weights{1, 2, 3, 4};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::size_t> totals(4, 0);
  std::vector<std::uint32_t> indices;
  for (int trial = 0; trial < 100; ++trial) {
    low_variance_resample(weights, 7, unit(rng), indices);
    const auto counts = counts_of(indices, 4);
    for (std::size_t i = 0; i < 4; ++i) totals[i] += counts[i];
  }
  double chi_square = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double expected = 700.0 * weights[i] / 10.0;
    chi_square += (static_cast<double>(totals[i]) - expected) *
                  (static_cast<double>(totals[i]) - expected) / expected;
  }
  EXPECT_LT(chi_square, 16.27);
}

TEST(LowVarianceResample, OneHeavyParticleTakesEverySlot) {
  std::vector<double> weights(100, 0.0);
  weights[42] = 3.5;
  std::vector<std::uint32_t> indices;
  for (double offset : {0.0, 0.5, 0.999999}) {
    low_variance_resample(weights, 500, offset, indices);
    EXPECT_EQ(counts_of(indices, 100)[42], 500u);
  }
}

TEST(LowVarianceResample, NeverDrawsZeroWeights) {
  const std::vector<double> weights{0.0, 1.0, 0.0, 0.0, 1.0, 0.0};
  std::vector<std::uint32_t> indices;
  for (double offset : {0.0, 0.25, 0.5, 0.9999999999}) {
    low_variance_resample(weights, 9, offset, indices);
    for (std::uint32_t i : indices) EXPECT_TRUE(i == 1 || i == 4) << i;
  }
}

TEST(LowVarianceResample, RejectsWeightsWithoutMass) {
  std::vector<std::uint32_t> indices;
  EXPECT_THROW(low_variance_resample(std::vector<double>{0.0, 0.0}, 3, 0.5, indices),
               std::invalid_argument);
}

}  // namespace low_variance_resampler_test
}  // namespace playerkit::amcl
