#include "families/sick/driver/sick_scan_config.hpp"

#include <algorithm>
#include <sstream>

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;

namespace {

int half_fov_cdeg(const ScanConfig& config) { return config.fov_deg * 50; }

// (angle + fov/2) / resolution with C truncation, clamped to the variant.
int segment_of(int angle_cdeg, const ScanConfig& config) {
  const int last = config.fov_deg * 100 / config.resolution_cdeg;
  return std::clamp((angle_cdeg + half_fov_cdeg(config)) / config.resolution_cdeg, 0, last);
}

std::string degrees(int cdeg) {
  std::ostringstream out;
  out << cdeg / 100.0;
  return out.str();
}

const char* unit_name(int range_res) {
  switch (range_res) {
    case 1: return "mm";
    case 10: return "cm";
    case 100: return "dm";
    default: return "?";
  }
}

}  // namespace

ScanConfig default_scan_config(Model model) {
  ScanConfig config;
  config.intensity = model == Model::lms200;
  return config;
}

std::optional<std::string> problem_with(const ScanConfig& config, Model model) {
  const int r = config.resolution_cdeg;
  if (model == Model::lms200) {
    if (r != 25 && r != 50 && r != 100) {
      return "resolution " + std::to_string(r) + " is not one of 25, 50, 100 (0.01 deg)";
    }
    if (config.fov_deg != 100 && config.fov_deg != 180) {
      return "fov " + std::to_string(config.fov_deg) + " is not 100 or 180 (deg)";
    }
    if (r == 25 && config.fov_deg != 100) return std::string("resolution 25 (0.25 deg) needs fov 100");
  } else {
    if (r != 50 && r != 100) {
      return "resolution " + std::to_string(r) +
             " is not 50 or 100 (0.01 deg): the PLS scans at 0.5 deg";
    }
    if (config.fov_deg != 180) return std::string("the PLS scans 180 deg only");
  }
  if (config.range_res != 1 && config.range_res != 10 && config.range_res != 100) {
    return "range_res " + std::to_string(config.range_res) + " is not one of 1, 10, 100";
  }
  const int half = half_fov_cdeg(config);
  if (config.min_angle_cdeg < -half || config.max_angle_cdeg > half) {
    return "angles " + degrees(config.min_angle_cdeg) + ".." + degrees(config.max_angle_cdeg) +
           " deg are outside the field of view -" + degrees(half) + ".." + degrees(half) + " deg";
  }
  if (config.min_angle_cdeg > config.max_angle_cdeg) {
    return "min_angle " + degrees(config.min_angle_cdeg) + " deg is above max_angle " +
           degrees(config.max_angle_cdeg) + " deg";
  }
  return std::nullopt;
}

ScanWindow window_of(const ScanConfig& config) {
  return {segment_of(config.min_angle_cdeg, config), segment_of(config.max_angle_cdeg, config)};
}

sick::Variant device_variant(const ScanConfig& config, Model model) {
  if (model == Model::pls) return sick::kPlsVariant;
  return {static_cast<std::uint16_t>(config.fov_deg),
          static_cast<std::uint16_t>(config.resolution_cdeg)};
}

int decimation(const ScanConfig& config, Model model) {
  return config.resolution_cdeg / device_variant(config, model).resolution_cdeg;
}

int device_value_count(const ScanConfig& config, Model model) {
  return (window_of(config).count() - 1) * decimation(config, model) + 1;
}

sick::Request stream_request(const ScanConfig& config, Model model) {
  const ScanWindow window = window_of(config);
  const int step = decimation(config, model);
  const int first = window.first * step + 1;
  const int last = window.last * step + 1;
  if (first == 1 && last == device_variant(config, model).value_count()) {
    return sick::StreamAllRequest{};
  }
  return sick::StreamSubrangeRequest{
      {static_cast<std::uint16_t>(first), static_cast<std::uint16_t>(last)}};
}

sick::Unit device_unit(const ScanConfig& config, Model model) {
  if (model == Model::lms200 && config.range_res == 1) return sick::Unit::millimetre;
  return sick::Unit::centimetre;
}

int window_min_angle(const ScanConfig& config) {
  return window_of(config).first * config.resolution_cdeg - half_fov_cdeg(config);
}

int window_max_angle(const ScanConfig& config) {
  return window_of(config).last * config.resolution_cdeg - half_fov_cdeg(config);
}

protocol::LaserConfig to_laser_config(const ScanConfig& config, Model model, std::uint8_t subtype) {
  protocol::LaserConfig out;
  out.subtype = subtype;
  out.min_angle = static_cast<std::int16_t>(window_min_angle(config));
  out.max_angle = static_cast<std::int16_t>(window_max_angle(config));
  out.resolution = static_cast<std::uint16_t>(config.resolution_cdeg);
  out.range_res = static_cast<std::uint16_t>(config.range_res);
  out.intensity = (model == Model::lms200 && config.intensity) ? 1 : 0;
  return out;
}

ScanConfig from_laser_config(const protocol::LaserConfig& request, Model model, int preferred_fov) {
  ScanConfig config;
  config.resolution_cdeg = request.resolution;
  config.range_res = request.range_res;
  config.intensity = model == Model::lms200 && request.intensity != 0;
  if (model == Model::pls) {
    config.fov_deg = 180;
  } else {
    config.fov_deg = request.resolution == 25 ? 100 : preferred_fov;
  }
  const int half = half_fov_cdeg(config);
  config.min_angle_cdeg = std::clamp<int>(request.min_angle, -half, half);
  config.max_angle_cdeg = std::clamp<int>(request.max_angle, -half, half);
  return config;
}

std::string describe(const ScanConfig& config, Model model) {
  std::string text = std::to_string(config.fov_deg) + " deg at " +
                     degrees(config.resolution_cdeg) + " deg, " +
                     degrees(window_min_angle(config)) + ".." + degrees(window_max_angle(config)) +
                     " deg (" + std::to_string(window_of(config).count()) + " values), " +
                     unit_name(config.range_res);
  if (model == Model::lms200) text += config.intensity ? ", intensity on" : ", intensity off";
  return text;
}

}  // namespace playerkit::drivers::sick_laser
