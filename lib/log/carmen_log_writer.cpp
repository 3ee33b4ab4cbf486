#include "log/carmen_log_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace playerkit::log {
namespace {

// printf's "%.<decimals>f" without a locale.
void append_fixed(std::string& out, double value, int decimals, std::string_view what) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("CARMEN line: " + std::string(what) + " is not a finite number");
  }
  char buffer[400];  // enough for any double in fixed notation with 6 decimals
  const auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (error != std::errc{}) {
    throw std::invalid_argument("CARMEN line: " + std::string(what) + " cannot be written");
  }
  out.append(buffer, end);
  out += ' ';
}

void append_pose(std::string& out, const CarmenPose& pose, std::string_view what) {
  append_fixed(out, pose.x, 6, what);
  append_fixed(out, pose.y, 6, what);
  append_fixed(out, pose.theta, 6, what);
}

void append_stamp(std::string& out, const CarmenStamp& stamp) {
  if (stamp.host.empty() ||
      stamp.host.find_first_of(" \t\r\n\v\f") != std::string::npos) {
    throw std::invalid_argument("CARMEN line: host '" + stamp.host +
                                "' must be one word (non-empty, no whitespace)");
  }
  append_fixed(out, stamp.ipc_timestamp, 6, "ipc timestamp");
  out += stamp.host;
  out += ' ';
  append_fixed(out, stamp.logger_timestamp, 6, "logger timestamp");
  out.back() = '\n';
}

}  // namespace

std::string carmen_log_header() {
  return "# CARMEN Logfile\n"
         "# file format is one message per line\n"
         "# message_name [message contents] ipc_timestamp ipc_hostname logger_timestamp\n"
         "# message formats defined: ODOM FLASER\n"
         "# ODOM x y theta tv rv accel\n"
         "# FLASER num_readings [range_readings] x y theta odom_x odom_y odom_theta\n";
}

std::string format_odom(const CarmenOdometry& odometry) {
  std::string out = "ODOM ";
  append_pose(out, odometry.pose, "odometry pose");
  append_fixed(out, odometry.tv, 6, "tv");
  append_fixed(out, odometry.rv, 6, "rv");
  append_fixed(out, odometry.acceleration, 6, "accel");
  append_stamp(out, odometry.stamp);
  return out;
}

std::string format_flaser(const CarmenLaser& laser) {
  if (!laser.laser_pose || !laser.robot_pose) {
    throw std::invalid_argument(
        "FLASER needs the laser pose and the odometry pose; this scan lacks " +
        std::string(!laser.laser_pose ? "the laser pose" : "the odometry pose"));
  }
  std::string out = "FLASER ";
  out.reserve(out.size() + laser.ranges.size() * 7 + 120);
  out += std::to_string(laser.ranges.size());
  out += ' ';
  for (const double range : laser.ranges) append_fixed(out, range, 3, "range");
  append_pose(out, *laser.laser_pose, "laser pose");
  append_pose(out, *laser.robot_pose, "odometry pose");
  append_stamp(out, laser.stamp);
  return out;
}

}  // namespace playerkit::log
