#include "algorithms/cspace/free_ranges.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace playerkit::cspace {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The sheet's scan (lasercspace.md §6): 181 beams from -90 degrees, one a
// degree, all 8 m but the one straight ahead at 2 m.
std::vector<double> one_post_ahead() {
  std::vector<double> ranges(181, 8.0);
  ranges[90] = 2.0;
  return ranges;
}

// As the wire carries them: whole millimetres, truncated.
int millimetres(double metres) { return static_cast<int>(std::floor(metres * 1000.0 + 1e-9)); }

// By definition: walks out along beam n a centimetre at a time until the
// robot's disc first holds a return that projects onto the beam, then
// bisects that centimetre down to `tolerance`.
double walked_free_range(const std::vector<double>& ranges, ScanGeometry geometry, double radius, int stride,
                         std::size_t n, double tolerance) {
  const double bearing = geometry.first_bearing + static_cast<double>(n) * geometry.bearing_step;
  const double ux = std::cos(bearing);
  const double uy = std::sin(bearing);
  std::vector<std::pair<double, double>> obstacles;
  for (std::size_t i = 0; i < ranges.size(); i += static_cast<std::size_t>(stride)) {
    const double b = geometry.first_bearing + static_cast<double>(i) * geometry.bearing_step;
    const double px = ranges[i] * std::cos(b);
    const double py = ranges[i] * std::sin(b);
    const double along = (px * ux + py * uy) / ranges[n];
    if (along >= 0.0 && along <= 1.0) obstacles.emplace_back(px, py);
  }
  const auto blocked = [&](double t) {
    for (const auto& [px, py] : obstacles) {
      if (std::hypot(t * ux - px, t * uy - py) <= radius) return true;
    }
    return false;
  };
  const double end = ranges[n] - radius;
  if (end <= 0.0 || blocked(0.0)) return 0.0;
  constexpr double kWalk = 0.01;
  for (double t = kWalk; t < end + kWalk; t += kWalk) {
    double free = t - kWalk;
    double hit = std::min(t, end);
    if (!blocked(hit)) continue;
    while (hit - free > tolerance) {
      const double middle = (free + hit) / 2;
      (blocked(middle) ? hit : free) = middle;
    }
    return hit;
  }
  return end;
}

TEST(FreeRanges, MatchesTheSheetsTableForOnePostAhead) {
  const std::vector<double> free = free_ranges(one_post_ahead(), {-90 * kDegree, kDegree}, 0.5);
  ASSERT_EQ(free.size(), 181u);
  const int expected[] = {1500, 1500, 1503, 1508, 1514, 1523, 1534, 1548,
                          1565, 1585, 1609, 1640, 1678, 1730, 1814};
  for (int bearing = 0; bearing < 15; ++bearing) {
    EXPECT_EQ(millimetres(free[90 + bearing]), expected[bearing]) << "bearing " << bearing;
    EXPECT_EQ(millimetres(free[90 - bearing]), expected[bearing]) << "bearing " << -bearing;
  }
  for (int bearing = 15; bearing <= 90; ++bearing) {
    EXPECT_EQ(millimetres(free[90 + bearing]), 7500) << "bearing " << bearing;
    EXPECT_EQ(millimetres(free[90 - bearing]), 7500) << "bearing " << -bearing;
  }
}

TEST(FreeRanges, AgreesWithWalkingOutAlongEachBeamOnRandomScans) {
  std::mt19937 random(20261207);
  std::uniform_real_distribution<double> range(0.3, 8.0);
  std::uniform_real_distribution<double> radius_of(0.1, 0.6);
  std::bernoulli_distribution near(0.3);
  for (int scan = 0; scan < 12; ++scan) {
    std::vector<double> ranges(61);
    for (double& r : ranges) {
      const double far = range(random);
      r = near(random) ? 0.3 + far / 8.0 : far;  // a third of the returns crowd within 1.3 m
    }
    const ScanGeometry geometry{-90 * kDegree, 3 * kDegree};
    const double radius = radius_of(random);
    const int stride = 1 + scan % 3;
    const std::vector<double> free = free_ranges(ranges, geometry, radius, stride);
    for (std::size_t n = 0; n < ranges.size(); ++n) {
      EXPECT_NEAR(free[n], walked_free_range(ranges, geometry, radius, stride, n, 1e-6), 2e-6)
          << "scan " << scan << " beam " << n << " radius " << radius << " stride " << stride;
    }
  }
}

TEST(FreeRanges, AReturnInsideTheRobotLeavesNoRoomAndNothingGoesNegative) {
  const std::vector<double> ranges{0.2, 0.2, 5.0};
  const std::vector<double> free = free_ranges(ranges, {-kDegree, kDegree}, 0.5);
  EXPECT_EQ(free[0], 0.0);
  EXPECT_EQ(free[1], 0.0);
  EXPECT_EQ(free[2], 0.0);  // the returns 0.2 m away lie beside it, inside the disc at the start
}

TEST(FreeRanges, AStrideSkipsReturnsAsObstacles) {
  // With every second return tested, the post at beam 90 (even) still
  // counts; moved to beam 91 (odd) it only shortens its own beam.
  std::vector<double> ranges = one_post_ahead();
  std::swap(ranges[90], ranges[91]);
  const std::vector<double> free = free_ranges(ranges, {-90 * kDegree, kDegree}, 0.5, 2);
  EXPECT_EQ(millimetres(free[91]), 1500);
  EXPECT_EQ(millimetres(free[90]), 7500);
  EXPECT_EQ(millimetres(free_ranges(ranges, {-90 * kDegree, kDegree}, 0.5, 1)[90]), 1500);
}

TEST(FreeRanges, RefusesANegativeRadiusAndAStrideBelowOne) {
  const std::vector<double> ranges{1.0};
  EXPECT_THROW((void)free_ranges(ranges, {}, -0.1), std::invalid_argument);
  EXPECT_THROW((void)free_ranges(ranges, {}, 0.5, 0), std::invalid_argument);
  EXPECT_TRUE(free_ranges({}, {}, 0.5).empty());
}

}  // namespace
}  // namespace playerkit::cspace
