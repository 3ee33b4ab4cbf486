#include "log/carmen_log.hpp"

#include <array>
#include <numbers>
#include <utility>

namespace playerkit::log {
namespace {

constexpr std::array<std::pair<CarmenLaserKind, std::string_view>, 10> kLaserKeywords{{
    {CarmenLaserKind::kFlaser, "FLASER"},
    {CarmenLaserKind::kRlaser, "RLASER"},
    {CarmenLaserKind::kLaser3, "LASER3"},
    {CarmenLaserKind::kLaser4, "LASER4"},
    {CarmenLaserKind::kRawLaser1, "RAWLASER1"},
    {CarmenLaserKind::kRawLaser2, "RAWLASER2"},
    {CarmenLaserKind::kRawLaser3, "RAWLASER3"},
    {CarmenLaserKind::kRawLaser4, "RAWLASER4"},
    {CarmenLaserKind::kRobotLaser1, "ROBOTLASER1"},
    {CarmenLaserKind::kRobotLaser2, "ROBOTLASER2"},
}};

constexpr double kPi = std::numbers::pi;

double degrees(double value) { return value * kPi / 180.0; }

}  // namespace

std::string_view carmen_laser_keyword(CarmenLaserKind kind) {
  for (const auto& [known, keyword] : kLaserKeywords) {
    if (known == kind) return keyword;
  }
  return "?";
}

std::optional<CarmenLaserKind> carmen_laser_kind(std::string_view keyword) {
  for (const auto& [kind, known] : kLaserKeywords) {
    if (known == keyword) return kind;
  }
  return std::nullopt;
}

CarmenLaserConfig guess_carmen_laser_config(std::size_t beams) {
  CarmenLaserConfig config;
  config.laser_type = 0;  // SICK LMS
  config.start_angle = -kPi / 2;
  config.maximum_range = 80.0;
  config.accuracy = 0.01;
  config.remission_mode = 0;
  // An even count is the odd one with its last beam dropped, so the field of
  // view is one step short of the full sweep.
  switch (beams) {
    case 180: config.angular_resolution = degrees(1.0); break;
    case 181: config.angular_resolution = degrees(1.0); break;
    case 360: config.angular_resolution = degrees(0.5); break;
    case 361: config.angular_resolution = degrees(0.5); break;
    case 400: config.angular_resolution = degrees(0.25); break;
    case 401: config.angular_resolution = degrees(0.25); break;
    default:
      config.angular_resolution = beams > 1 ? kPi / static_cast<double>(beams - 1) : 0.0;
      break;
  }
  config.fov = beams > 1 ? config.angular_resolution * static_cast<double>(beams - 1) : 0.0;
  return config;
}

}  // namespace playerkit::log
