#include "families/sick/protocol/codes.hpp"

#include <algorithm>
#include <numbers>

namespace playerkit::hardware::sick {
namespace {

struct BaudCode {
  int baud;
  std::uint8_t code;
};
constexpr std::array<BaudCode, 4> kBaudCodes = {
    {{9600, 0x42}, {19200, 0x41}, {38400, 0x40}, {500000, 0x48}}};

constexpr double kRadiansPerCentidegree = std::numbers::pi / 18000.0;

}  // namespace

std::optional<std::uint8_t> baud_code(int baud) {
  for (const auto& entry : kBaudCodes) {
    if (entry.baud == baud) return entry.code;
  }
  return std::nullopt;
}

std::optional<int> baud_of_code(std::uint8_t code) {
  for (const auto& entry : kBaudCodes) {
    if (entry.code == code) return entry.baud;
  }
  return std::nullopt;
}

std::optional<double> metres_per_step(Unit unit) {
  switch (unit) {
    case Unit::centimetre: return 0.01;
    case Unit::millimetre: return 0.001;
  }
  return std::nullopt;
}

bool Variant::supported() const {
  return std::find(kLms200Variants.begin(), kLms200Variants.end(), *this) != kLms200Variants.end();
}

double Variant::first_angle_rad() const { return -width_deg * 50 * kRadiansPerCentidegree; }

double Variant::step_rad() const { return resolution_cdeg * kRadiansPerCentidegree; }

}  // namespace playerkit::hardware::sick
