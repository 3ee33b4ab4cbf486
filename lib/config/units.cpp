#include "config/units.hpp"

namespace playerkit::config {

std::optional<double> length_unit(std::string_view name) {
  if (name == "m") return 1.0;
  if (name == "cm") return 0.01;
  if (name == "mm") return 0.001;
  return std::nullopt;
}

std::optional<double> angle_unit(std::string_view name) {
  if (name == "degrees") return std::numbers::pi / 180.0;
  if (name == "radians") return 1.0;
  return std::nullopt;
}

}  // namespace playerkit::config
