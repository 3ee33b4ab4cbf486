#pragma once
// The global unit_length / unit_angle settings (manual §4.4). Lengths and angles
// read through a Section are scaled by these factors to metres and radians.

#include <numbers>
#include <optional>
#include <string_view>

namespace playerkit::config {

struct Units {
  double length = 1.0;                      // metres per length unit; "m" by default
  double angle = std::numbers::pi / 180.0;  // radians per angle unit; "degrees" by default
};

// "m" -> 1, "cm" -> 0.01, "mm" -> 0.001; nullopt for anything else.
std::optional<double> length_unit(std::string_view name);
// "degrees" -> pi/180, "radians" -> 1; nullopt for anything else.
std::optional<double> angle_unit(std::string_view name);

}  // namespace playerkit::config
