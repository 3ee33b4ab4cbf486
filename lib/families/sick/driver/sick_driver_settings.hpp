#pragma once
// Everything a sicklms200 or sickpls device section says: the options
// declared once in sick_option_schema() (what `player-drivers info`, `--check`
// and the README's table come from), read and checked with core::OptionReader
// (errors at the option's file:line:col).
//
// The 1.5 options (port, rate, delay, resolution, range_res, invert, pose)
// keep their names and defaults; the rest are playerkit's (README.md):
// fov, min_angle, max_angle, intensity, size, reply_timeout, retry_interval.

#include <chrono>
#include <string>

#include "families/sick/driver/sick_scan_config.hpp"
#include "core/option_reader.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::sick_laser {

struct SickDriverSettings {
  Model model = Model::lms200;
  std::string port = "/dev/ttyS1";
  int rate = 38400;  // the speed the laser is run at
  std::chrono::seconds delay{0};  // before the first telegram (a laser powered by the port)
  ScanConfig scan;
  // The `fov` option; a SET_CONFIG of another resolution than 25 returns to it.
  int preferred_fov = 180;
  bool invert = false;
  // Mount pose in the robot frame (m, m, rad) and size (m, m), for GET_GEOM.
  double pose_x = 0.0;
  double pose_y = 0.0;
  double pose_yaw = 0.0;
  double size_x = 0.15;
  double size_y = 0.15;
  // Each request's reply (T1 at each speed, T2..T8) is waited for this long.
  std::chrono::milliseconds reply_timeout{1000};
  // Between attempts to reach a laser that went silent or away.
  std::chrono::milliseconds retry_interval{1000};
};

// The options of `model`'s driver (the LMS 200 has fov and intensity; the
// defaults of rate and resolution differ).
const core::OptionSchema& sick_option_schema(Model model);

// Reads `options.section()` against sick_option_schema(model); `options`
// names the driver in its messages ("sicklms200: rate must be ...").
SickDriverSettings read_settings(const core::OptionReader& options, Model model);

}  // namespace playerkit::drivers::sick_laser
