#include "families/sick/driver/sick_driver_settings.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "links/port_option.hpp"

namespace playerkit::drivers::sick_laser {

namespace {

constexpr double kCentidegreesPerRadian = 18000.0 / std::numbers::pi;
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
// GET_GEOM carries millimetres in int16.
constexpr double kLongest = 32.767;

std::string shown_degrees(int cdeg) {
  std::ostringstream out;
  out << cdeg / 100.0;
  return out.str();
}

int centidegrees(double radians) { return static_cast<int>(std::lround(radians * kCentidegreesPerRadian)); }

core::OptionSchema make_schema(Model model) {
  using core::OptionSpec;
  using core::OptionType;
  const bool lms = model == Model::lms200;
  constexpr double kAny = std::numeric_limits<double>::max();
  core::OptionSchema schema{
      links::port_option("/dev/ttyS1"),
      OptionSpec::choice("rate", lms ? 38400 : 9600, {9600, 38400, 500000})
          .unit("baud")
          .doc("the speed the laser is run at (500000 needs an adapter that can)"),
      OptionSpec::integer("delay", 0, 0, 3600)
          .unit("s")
          .doc("wait before the first telegram (35 for a laser powered when the port opens)"),
      lms ? OptionSpec::choice("resolution", 50, {25, 50, 100}).unit("0.01 deg").doc("angular step")
          : OptionSpec::choice("resolution", 50, {50, 100}).unit("0.01 deg").doc("angular step (100: every second value)"),
  };
  if (lms) {
    // 1.5 chose the width from the resolution: 100 deg for 0.25 deg, else 180.
    schema.add(OptionSpec::choice("fov", 180, {100, 180})
                   .unit("deg")
                   .shown_default("180 (100 with resolution 25)")
                   .doc("field of view (100 is needed for resolution 25)"));
    schema.add(OptionSpec::flag("intensity", true).doc("1: reflector level 0-7 per beam in `intensity`; 0: all zero"));
  }
  schema.add(OptionSpec::choice("range_res", 1, {1, 10, 100}).doc("ranges in mm (1), cm (10) or dm (100)"));
  // Within the field of view, which depends on fov and resolution: checked
  // in read_settings.
  const auto angle_limit = [&](std::string name, double degrees, std::string lms_default, std::string doc) {
    OptionSpec spec = OptionSpec::angle(std::move(name), degrees * kRadiansPerDegree, -kAny, kAny).doc(std::move(doc));
    return lms ? OptionSpec(std::move(spec).shown_default(std::move(lms_default))) : spec;
  };
  schema.add(angle_limit("min_angle", -90, "-90 (-50 at fov 100)", "first beam of the scan, within the field of view (narrower: the laser streams that subrange, T8)"));
  schema.add(angle_limit("max_angle", 90, "90 (50 at fov 100)", "last beam of the scan, within the field of view (narrower: the laser streams that subrange, T8)"));
  schema.add(OptionSpec::flag("invert", false).doc("1 for a laser mounted upside down: beams and angles mirrored"));
  schema.add(OptionSpec::tuple("pose", {OptionType::length, OptionType::length, OptionType::angle}, {0.0, 0.0, 0.0})
                 .unit("m m deg")
                 .doc("mounting pose on the robot (GET_GEOM), within 32.767 m of its origin"));
  schema.add(OptionSpec::tuple("size", {OptionType::length, OptionType::length}, {0.15, 0.15})
                 .unit("m m")
                 .doc("the laser's footprint (GET_GEOM), 0 to 32.767 m"));
  schema.add(OptionSpec::number("reply_timeout", 1.0, 0.05, 30.0).unit("s").doc("wait for each reply of the laser"));
  schema.add(OptionSpec::number("retry_interval", 1.0, 0.05, 600.0)
                 .unit("s")
                 .doc("between attempts to reach a laser that went silent or away"));
  return schema;
}

}  // namespace

const core::OptionSchema& sick_option_schema(Model model) {
  static const core::OptionSchema lms200 = make_schema(Model::lms200);
  static const core::OptionSchema pls = make_schema(Model::pls);
  return model == Model::lms200 ? lms200 : pls;
}

SickDriverSettings read_settings(const core::OptionReader& given, Model model) {
  const core::OptionReader options(given.section(), given.driver_name(), sick_option_schema(model));
  const bool lms = model == Model::lms200;
  SickDriverSettings s;
  s.model = model;
  s.port = options.text("port");
  s.rate = options.integer("rate");
  s.delay = std::chrono::seconds(options.integer("delay"));

  ScanConfig& scan = s.scan;
  scan = default_scan_config(model);
  scan.resolution_cdeg = options.integer("resolution");
  if (lms) {
    const int derived = scan.resolution_cdeg == 25 ? 100 : 180;
    scan.fov_deg = options.has("fov") ? options.integer("fov") : derived;
    if (scan.resolution_cdeg == 25 && scan.fov_deg != 100) {
      options.fail({"fov"}, "must be 100 with resolution 25: the LMS 200 scans 0.25 deg over 100 deg only");
    }
    s.preferred_fov = options.has("fov") ? scan.fov_deg : 180;
    scan.intensity = options.flag("intensity");
  }
  scan.range_res = options.integer("range_res");

  const int half = scan.fov_deg * 50;
  const auto angle_option = [&](std::string_view name, int fallback) {
    const int cdeg = options.has(name) ? centidegrees(options.angle(name)) : fallback;
    if (cdeg < -half || cdeg > half) {
      options.fail({name}, "must lie within the field of view, -" + std::to_string(half / 100) + " to " +
                               std::to_string(half / 100) + " deg (got " + shown_degrees(cdeg) + " deg)");
    }
    return cdeg;
  };
  scan.min_angle_cdeg = angle_option("min_angle", -half);
  scan.max_angle_cdeg = angle_option("max_angle", half);
  if (scan.min_angle_cdeg > scan.max_angle_cdeg) options.fail({"max_angle"}, "must not be below min_angle");

  s.invert = options.flag("invert");
  s.pose_x = options.element("pose", 0);
  s.pose_y = options.element("pose", 1);
  s.pose_yaw = options.element("pose", 2);
  s.size_x = options.element("size", 0);
  s.size_y = options.element("size", 1);
  if (std::abs(s.pose_x) > kLongest || std::abs(s.pose_y) > kLongest) {
    options.fail({"pose"}, "must lie within 32.767 m of the robot's origin");
  }
  if (s.size_x < 0.0 || s.size_y < 0.0 || s.size_x > kLongest || s.size_y > kLongest) {
    options.fail({"size"}, "must be between 0 and 32.767 m");
  }
  s.reply_timeout = options.seconds("reply_timeout");
  s.retry_interval = options.seconds("retry_interval");
  return s;
}

}  // namespace playerkit::drivers::sick_laser
