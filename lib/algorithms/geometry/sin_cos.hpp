#pragma once
// The sine and cosine of one angle, for the loops that take them for every
// particle of a filter (motion, likelihood field, clusters). glibc's sincos
// takes about 20 ns here, half of it saving and restoring the rounding mode;
// this takes a few. Within about 1 ulp of the true values for |angle| up to
// 1e5 (beyond that, and for non-finite angles, it is std::sin and std::cos),
// and the same on every machine and library: results do not depend on libm.
//
//   const geometry::SinCos t = geometry::sin_cos(pose.yaw);
//   x += distance * t.cos;

#include <bit>
#include <cmath>
#include <cstdint>

namespace playerkit::geometry {

struct SinCos {
  double sin;
  double cos;
};

namespace sin_cos_detail {

// pi/2 in three parts, the first two of 33 significant bits, so that q times
// either is exact for |q| < 2^20 (Cody and Waite's reduction).
inline constexpr double kHalfPiHigh = 0x1.921fb544p+0;
inline constexpr double kHalfPiMiddle = 0x1.0b4611a6p-34;
inline constexpr double kHalfPiLow = 0x1.3198a2e037073p-69;
inline constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
inline constexpr double kLargest = 1e5;

// Taylor series on [-pi/4, pi/4], through r^15 and r^16: the first term left
// out is below 1e-16 of the value there.
inline double sin_near_zero(double r) {
  const double z = r * r;
  const double p =
      -1.0 / 6 +
      z * (1.0 / 120 +
           z * (-1.0 / 5040 +
                z * (1.0 / 362880 +
                     z * (-1.0 / 39916800 + z * (1.0 / 6227020800 + z * (-1.0 / 1307674368000.0))))));
  return r + r * z * p;
}

inline double cos_near_zero(double r) {
  const double z = r * r;
  const double p =
      1.0 / 24 +
      z * (-1.0 / 720 +
           z * (1.0 / 40320 +
                z * (-1.0 / 3628800 +
                     z * (1.0 / 479001600 + z * (-1.0 / 87178291200.0 + z * (1.0 / 20922789888000.0))))));
  // 1 - z/2 loses the low bits of z/2; add them back.
  const double half_z = 0.5 * z;
  const double w = 1.0 - half_z;
  return w + (((1.0 - w) - half_z) + z * z * p);
}

}  // namespace sin_cos_detail

inline SinCos sin_cos(double angle) {
  using namespace sin_cos_detail;
  if (!(std::abs(angle) <= kLargest)) return {std::sin(angle), std::cos(angle)};
  // Rounded to the nearest quarter turn by adding 1.5 * 2^52, which leaves no
  // fraction bits (no call to nearbyint); the sum's low bits are the count
  // modulo 4, negative counts included.
  constexpr double kRoundingShift = 0x1.8p52;
  const double shifted = angle * kTwoOverPi + kRoundingShift;
  const double quarter_turns = shifted - kRoundingShift;
  const auto quadrant = std::bit_cast<std::uint64_t>(shifted);
  const double r = ((angle - quarter_turns * kHalfPiHigh) - quarter_turns * kHalfPiMiddle) -
                   quarter_turns * kHalfPiLow;
  const auto s = std::bit_cast<std::uint64_t>(sin_near_zero(r));
  const auto c = std::bit_cast<std::uint64_t>(cos_near_zero(r));
  // Odd quadrants swap the two; quadrants 2 and 3 negate the sine, 1 and 2
  // the cosine. Without branches: the quadrant of a heading is a coin toss.
  const std::uint64_t swap = std::uint64_t{0} - (quadrant & 1);
  constexpr int kSignShift = 62;  // bit 1 of the quadrant to bit 63
  const std::uint64_t sine = ((s & ~swap) | (c & swap)) ^ ((quadrant & 2) << kSignShift);
  const std::uint64_t cosine = ((c & ~swap) | (s & swap)) ^ (((quadrant + 1) & 2) << kSignShift);
  return {std::bit_cast<double>(sine), std::bit_cast<double>(cosine)};
}

}  // namespace playerkit::geometry
