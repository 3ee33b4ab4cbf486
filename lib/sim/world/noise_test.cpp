#include "sim/world/noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace playerkit::sim::noise_test {

std::vector<double> uniforms(NoiseDraws draws, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(draws.uniform());
  return values;
}

TEST(NoiseDraws, TheSameSeedModelAndStepGiveTheSameNumbers) {
  EXPECT_EQ(uniforms(NoiseDraws(7, 3, 120), 100), uniforms(NoiseDraws(7, 3, 120), 100));
  NoiseDraws a(7, 3, 120), b(7, 3, 120);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.gaussian(0.1), b.gaussian(0.1));
}

TEST(NoiseDraws, AnotherSeedModelOrStepGivesOtherNumbers) {
  const std::vector<double> base = uniforms(NoiseDraws(7, 3, 120), 20);
  const std::vector<std::vector<double>> others = {
      uniforms(NoiseDraws(8, 3, 120), 20), uniforms(NoiseDraws(7, 4, 120), 20), uniforms(NoiseDraws(7, 3, 121), 20),
      uniforms(NoiseDraws(0, 0, 0), 20),   uniforms(NoiseDraws(7, kNoModel, 120), 20),
      // Swapping model and step must not give the same stream either.
      uniforms(NoiseDraws(7, 120, 3), 20)};
  for (const auto& other : others) {
    int equal = 0;
    for (std::size_t i = 0; i < base.size(); ++i) equal += base[i] == other[i] ? 1 : 0;
    EXPECT_EQ(equal, 0);
  }
}

TEST(NoiseDraws, NeighbouringStepsAreUncorrelated) {
  // The first draw of consecutive steps, as a sensor read every step sees it.
  std::vector<double> firsts;
  for (std::uint64_t step = 0; step < 20000; ++step) firsts.push_back(NoiseDraws(1, 2, step).uniform());
  double covariance = 0.0;
  for (std::size_t i = 1; i < firsts.size(); ++i) covariance += (firsts[i] - 0.5) * (firsts[i - 1] - 0.5);
  const double correlation = covariance / static_cast<double>(firsts.size() - 1) * 12.0;
  EXPECT_NEAR(correlation, 0.0, 4.0 / std::sqrt(20000.0));
}

TEST(NoiseDraws, UniformLiesInZeroToOneWithMeanOneHalf) {
  NoiseDraws draws(11, 5, 9);
  constexpr int kCount = 200000;
  double sum = 0.0, squares = 0.0;
  int low_half = 0;
  for (int i = 0; i < kCount; ++i) {
    const double u = draws.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    squares += (u - 0.5) * (u - 0.5);
    low_half += u < 0.5 ? 1 : 0;
  }
  // Uniform on [0, 1): mean 1/2 (sd of the mean 0.29 / sqrt(n)), variance 1/12.
  EXPECT_NEAR(sum / kCount, 0.5, 4.0 * 0.2887 / std::sqrt(double{kCount}));
  EXPECT_NEAR(squares / kCount, 1.0 / 12.0, 0.01 / 12.0);
  EXPECT_NEAR(low_half, kCount / 2, 4.0 * std::sqrt(kCount / 4.0));
}

TEST(NoiseDraws, UniformBetweenBoundsScalesTheUnitDraw) {
  NoiseDraws unit(3, 3, 3), scaled(3, 3, 3);
  for (int i = 0; i < 1000; ++i) {
    const double u = unit.uniform();
    const double v = scaled.uniform(-2.0, 6.0);
    EXPECT_DOUBLE_EQ(v, -2.0 + 8.0 * u);
    EXPECT_GE(v, -2.0);
    EXPECT_LT(v, 6.0);
  }
}

TEST(NoiseDraws, GaussianHasMeanZeroAndTheGivenStandardDeviation) {
  NoiseDraws draws(2024, 17, 33);
  constexpr int kCount = 100000;
  constexpr double kSd = 0.25;
  double sum = 0.0, squares = 0.0, fourth = 0.0;
  int within_one_sd = 0;
  for (int i = 0; i < kCount; ++i) {
    const double g = draws.gaussian(kSd);
    sum += g;
    squares += g * g;
    fourth += std::pow(g / kSd, 4);
    within_one_sd += std::abs(g) < kSd ? 1 : 0;
  }
  const double mean = sum / kCount;
  const double sd = std::sqrt(squares / kCount - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4.0 * kSd / std::sqrt(double{kCount}));
  EXPECT_NEAR(sd, kSd, kSd * 0.02);
  // A normal's shape, not just its spread: 68.27 % within one sd, kurtosis 3.
  EXPECT_NEAR(within_one_sd / double{kCount}, 0.6827, 0.01);
  EXPECT_NEAR(fourth / kCount, 3.0, 0.1);
}

TEST(NoiseDraws, ZeroStandardDeviationGivesZeroAndDrawsNothing) {
  NoiseDraws used(4, 4, 4), fresh(4, 4, 4);
  EXPECT_EQ(used.gaussian(0.0), 0.0);
  EXPECT_EQ(used.uniform(), fresh.uniform());
}

}  // namespace playerkit::sim::noise_test
