#include "families/nomad/protocol/nomad_units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace playerkit::hardware::nomad {

namespace {

std::int32_t rounded_word(double value) {
  if (!std::isfinite(value)) return 0;
  constexpr double kLowest = std::numeric_limits<std::int32_t>::min();
  constexpr double kHighest = std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(std::lround(std::clamp(value, kLowest, kHighest)));
}

}  // namespace

std::int32_t tenth_inches_from_mm(double millimetres) { return rounded_word(millimetres * 10.0 / kMillimetresPerInch); }

double mm_from_tenth_inches(std::int32_t tenths) { return tenths * kMillimetresPerInch / 10.0; }

std::int32_t tenth_degrees_from_degrees(double degrees) { return rounded_word(degrees * 10.0); }

double degrees_from_tenth_degrees(std::int32_t tenths) { return tenths / 10.0; }

double mm_from_inches(std::int32_t inches) { return inches * kMillimetresPerInch; }

}  // namespace playerkit::hardware::nomad
