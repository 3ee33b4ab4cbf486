#include "algorithms/geometry/sin_cos.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

namespace playerkit::geometry {
namespace sin_cos_test {

// How many doubles lie between a and b.
std::int64_t ulps_apart(double a, double b) {
  const auto ordered = [](double x) {
    const auto bits = std::bit_cast<std::int64_t>(x);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t d = ordered(a) - ordered(b);
  return d < 0 ? -d : d;
}

// Against glibc, which is within 1 ulp of the truth: ours within 2 of it,
// and within 1e-16 absolutely near the zeros, where ulps are tiny.
void expect_close(double angle) {
  const SinCos t = sin_cos(angle);
  const double s = std::sin(angle), c = std::cos(angle);
  EXPECT_TRUE(ulps_apart(t.sin, s) <= 2 || std::abs(t.sin - s) < 1e-16) << angle << ": " << t.sin << " vs " << s;
  EXPECT_TRUE(ulps_apart(t.cos, c) <= 2 || std::abs(t.cos - c) < 1e-16) << angle << ": " << t.cos << " vs " << c;
}

TEST(SinCos, AgreesWithLibmOverTheAnglesParticlesHave) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> heading(-2.0 * std::numbers::pi, 2.0 * std::numbers::pi);
  for (int i = 0; i < 200000; ++i) expect_close(heading(random));
  std::uniform_real_distribution<double> wide(-1e5, 1e5);
  for (int i = 0; i < 20000; ++i) expect_close(wide(random));
}

TEST(SinCos, ExactWhereTheValuesAre) {
  EXPECT_EQ(sin_cos(0.0).sin, 0.0);
  EXPECT_EQ(sin_cos(0.0).cos, 1.0);
  EXPECT_EQ(sin_cos(1e-300).sin, 1e-300);
  EXPECT_EQ(sin_cos(1e-300).cos, 1.0);
}

TEST(SinCos, EveryQuarterTurnHasTheRightSigns) {
  for (int k = -8; k <= 8; ++k) {
    for (const double offset : {-0.7, -0.3, 0.0, 0.3, 0.7}) expect_close(k * std::numbers::pi / 2 + offset);
  }
}

TEST(SinCos, BeyondTheReductionItIsLibm) {
  for (const double angle : {1e5 + 1.0, -3e7, 1e300}) {
    EXPECT_EQ(sin_cos(angle).sin, std::sin(angle));
    EXPECT_EQ(sin_cos(angle).cos, std::cos(angle));
  }
  EXPECT_TRUE(std::isnan(sin_cos(std::numeric_limits<double>::quiet_NaN()).sin));
  EXPECT_TRUE(std::isnan(sin_cos(std::numeric_limits<double>::infinity()).cos));
}

}  // namespace sin_cos_test
}  // namespace playerkit::geometry
