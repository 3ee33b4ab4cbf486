#include "families/sick/driver/sick_driver_settings.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

namespace playerkit::drivers::sick_laser {

namespace {

constexpr double kCentidegreesPerRadian = 18000.0 / std::numbers::pi;

std::string shown_degrees(int cdeg) {
  std::ostringstream out;
  out << cdeg / 100.0;
  return out.str();
}

int centidegrees(double radians) { return static_cast<int>(std::lround(radians * kCentidegreesPerRadian)); }

std::chrono::milliseconds seconds_option(const core::OptionReader& options, std::string_view name,
                                         double fallback, double minimum, double maximum) {
  const double seconds = options.number({name}, fallback, minimum, maximum);
  return std::chrono::milliseconds(std::lround(seconds * 1000.0));
}

}  // namespace

SickDriverSettings read_settings(const core::OptionReader& options, Model model) {
  const bool lms = model == Model::lms200;
  SickDriverSettings s;
  s.model = model;
  s.port = options.text({"port"}, "/dev/ttyS1");
  s.rate = options.choice({"rate"}, lms ? 38400 : 9600, {9600, 38400, 500000});
  s.delay = std::chrono::seconds(options.integer({"delay"}, 0, 0, 3600));

  ScanConfig& scan = s.scan;
  scan = default_scan_config(model);
  scan.resolution_cdeg = lms ? options.choice({"resolution"}, 50, {25, 50, 100})
                             : options.choice({"resolution"}, 50, {50, 100});
  if (lms) {
    // 1.5 chose the width from the resolution: 100 deg for 0.25 deg, else 180.
    const int derived = scan.resolution_cdeg == 25 ? 100 : 180;
    scan.fov_deg = options.choice({"fov"}, derived, {100, 180});
    if (scan.resolution_cdeg == 25 && scan.fov_deg != 100) {
      options.fail({"fov"}, "must be 100 with resolution 25: the LMS 200 scans 0.25 deg over 100 deg only");
    }
    s.preferred_fov = options.has({"fov"}) ? scan.fov_deg : 180;
    scan.intensity = options.flag({"intensity"}, true);
  }
  scan.range_res = options.choice({"range_res"}, 1, {1, 10, 100});

  const int half = scan.fov_deg * 50;
  const auto angle_option = [&](std::string_view name, int fallback) {
    constexpr double kAny = std::numeric_limits<double>::max();
    const int cdeg = centidegrees(options.angle({name}, fallback / kCentidegreesPerRadian, -kAny, kAny));
    if (cdeg < -half || cdeg > half) {
      options.fail({name}, "must lie within the field of view, -" + std::to_string(half / 100) + " to " +
                               std::to_string(half / 100) + " deg (got " + shown_degrees(cdeg) + " deg)");
    }
    return cdeg;
  };
  scan.min_angle_cdeg = angle_option("min_angle", -half);
  scan.max_angle_cdeg = angle_option("max_angle", half);
  if (scan.min_angle_cdeg > scan.max_angle_cdeg) options.fail({"max_angle"}, "must not be below min_angle");

  s.invert = options.flag({"invert"}, false);
  s.pose_x = options.tuple_length({"pose"}, 0, 0.0);
  s.pose_y = options.tuple_length({"pose"}, 1, 0.0);
  s.pose_yaw = options.tuple_angle({"pose"}, 2, 0.0);
  s.size_x = options.tuple_length({"size"}, 0, 0.15);
  s.size_y = options.tuple_length({"size"}, 1, 0.15);
  // GET_GEOM carries millimetres in int16.
  constexpr double kLongest = 32.767;
  if (std::abs(s.pose_x) > kLongest || std::abs(s.pose_y) > kLongest) {
    options.fail({"pose"}, "must lie within 32.767 m of the robot's origin");
  }
  if (s.size_x < 0.0 || s.size_y < 0.0 || s.size_x > kLongest || s.size_y > kLongest) {
    options.fail({"size"}, "must be between 0 and 32.767 m");
  }
  s.reply_timeout = seconds_option(options, "reply_timeout", 1.0, 0.05, 30.0);
  s.retry_interval = seconds_option(options, "retry_interval", 1.0, 0.05, 600.0);
  return s;
}

}  // namespace playerkit::drivers::sick_laser
