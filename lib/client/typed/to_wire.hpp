#pragma once
// SI value to wire integer, the one way every typed command is built: convert
// (protocol/si_units.hpp), round to the nearest integer (halves away from zero),
// clamp to the wire field's range. NaN or infinity is refused with
// std::invalid_argument naming the field, because a command built from it would
// mean nothing to the robot.

#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "protocol/si_units.hpp"

namespace playerkit::client {

template <std::integral Int>
Int round_to_wire(double wire_value, std::string_view field) {
  if (!std::isfinite(wire_value)) {
    throw std::invalid_argument(std::string(field) + ": " + std::to_string(wire_value) +
                                " is not a finite value");
  }
  // Compared as doubles: the largest int64 is not representable, its double (2^63) is above it.
  constexpr double kMax = static_cast<double>(std::numeric_limits<Int>::max());
  constexpr double kMin = static_cast<double>(std::numeric_limits<Int>::min());
  const double rounded = std::round(wire_value);
  if (rounded >= kMax) return std::numeric_limits<Int>::max();
  if (rounded <= kMin) return std::numeric_limits<Int>::min();
  return static_cast<Int>(rounded);
}

template <std::integral Int>
Int to_wire(protocol::WireUnit unit, double value_in_si, std::string_view field) {
  if (!std::isfinite(value_in_si)) {
    throw std::invalid_argument(std::string(field) + ": " + std::to_string(value_in_si) + " is not a finite value");
  }
  return round_to_wire<Int>(protocol::from_si(unit, value_in_si), field);
}

}  // namespace playerkit::client
