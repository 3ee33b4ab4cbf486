#include "algorithms/amcl/standard_normal.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>

namespace playerkit::amcl {
namespace standard_normal_test {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// A million deviates against the normal law: the moments, and the share in
// each of 40 bins from -5 to 5 (every layer's rectangle and wedge, the base
// and the tail beyond 3.44) by a chi-square test.
TEST(StandardNormal, DrawsTheStandardNormalLaw) {
  std::mt19937_64 rng(17);
  const StandardNormal normal;
  constexpr int kDraws = 1'000'000;
  constexpr int kBins = 40;
  constexpr double kLow = -5.0, kHigh = 5.0;
  std::array<int, kBins + 2> counts{};  // below kLow, the bins, above kHigh
  double sum = 0.0, sum_squares = 0.0, sum_fourth = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = normal(rng);
    sum += x;
    sum_squares += x * x;
    sum_fourth += x * x * x * x;
    const int bin = x < kLow ? 0 : x >= kHigh ? kBins + 1 : 1 + static_cast<int>((x - kLow) / (kHigh - kLow) * kBins);
    ++counts[static_cast<std::size_t>(bin)];
  }
  const double mean = sum / kDraws;
  const double variance = sum_squares / kDraws - mean * mean;
  EXPECT_NEAR(mean, 0.0, 0.005);       // 5 standard errors
  EXPECT_NEAR(variance, 1.0, 0.007);   // sd of the estimate: sqrt(2 / n) = 0.0014
  EXPECT_NEAR(sum_fourth / kDraws, 3.0, 0.05);  // kurtosis: the tails have the right weight

  double chi_square = 0.0;
  int cells = 0;
  for (int bin = 0; bin < kBins + 2; ++bin) {
    const double from = bin == 0 ? -INFINITY : kLow + (bin - 1) * (kHigh - kLow) / kBins;
    const double to = bin == kBins + 1 ? INFINITY : kLow + bin * (kHigh - kLow) / kBins;
    const double expected = kDraws * (normal_cdf(to) - normal_cdf(from));
    if (expected < 5.0) continue;  // the far tails: too few for the test
    chi_square += (counts[static_cast<std::size_t>(bin)] - expected) * (counts[static_cast<std::size_t>(bin)] - expected) / expected;
    ++cells;
  }
  // 99.9th percentile of chi-square with about 37 degrees of freedom: 69.3.
  EXPECT_LT(chi_square, 69.3) << cells << " cells";
}

// Beyond the ziggurat's base (3.4426) the deviates come from the tail
// sampler: their share, and their mean, phi(r) / (1 - Phi(r)), about 3.68.
TEST(StandardNormal, TheTailBeyondTheBaseHasTheNormalsShape) {
  const double base = 3.442619855899;
  std::mt19937_64 rng(18);
  const StandardNormal normal;
  constexpr int kDraws = 4'000'000;
  int beyond = 0;
  double sum_beyond = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = std::abs(normal(rng));
    if (x > base) {
      ++beyond;
      sum_beyond += x;
    }
  }
  const double tail_probability = 2.0 * normal_cdf(-base);
  const double expected_beyond = kDraws * tail_probability;  // about 2300
  EXPECT_NEAR(beyond, expected_beyond, 5.0 * std::sqrt(expected_beyond));
  const double density = std::exp(-0.5 * base * base) / std::sqrt(2.0 * std::numbers::pi);
  const double expected_mean = density / normal_cdf(-base);
  // The tail's standard deviation is about 0.26: five standard errors.
  EXPECT_NEAR(sum_beyond / beyond, expected_mean, 5.0 * 0.26 / std::sqrt(expected_beyond));
}

TEST(StandardNormal, TheSameSeedGivesTheSameDeviates) {
  std::mt19937_64 a(5), b(5);
  const StandardNormal normal;
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(normal(a), normal(b));
}

}  // namespace standard_normal_test
}  // namespace playerkit::amcl
