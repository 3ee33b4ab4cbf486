#pragma once
// Writes CARMEN log lines for the conversion from Player logs: ODOM and the old
// FLASER record, as CARMEN's logger wrote them ("%f" poses, velocities and
// times, i.e. 6 decimals; "%.3f" ranges, i.e. millimetres). CarmenLogReader
// reads them back. Each function returns one line ending in "\n".
//
//   out << log::carmen_log_header();
//   out << log::format_odom(odometry) << log::format_flaser(scan);

#include <string>

#include "log/carmen_log.hpp"

namespace playerkit::log {

// The comment lines a CARMEN log starts with (naming what this writer writes).
std::string carmen_log_header();

// "ODOM x y theta tv rv accel ipc_timestamp host logger_timestamp".
// Throws std::invalid_argument on a non-finite number or a host that is empty
// or holds whitespace (it would split the line into other fields).
std::string format_odom(const CarmenOdometry& odometry);

// "FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp host
// logger_timestamp", whatever the laser's kind. FLASER does not hold the beam
// layout: a reader guesses it from n (guess_carmen_laser_config), so a scan
// whose config differs from that guess loses its angles. Needs laser_pose and
// robot_pose (the odometry); throws std::invalid_argument without them, and as
// format_odom does.
std::string format_flaser(const CarmenLaser& laser);

}  // namespace playerkit::log
