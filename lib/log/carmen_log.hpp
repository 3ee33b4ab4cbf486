#pragma once
// The records of a CARMEN log (the robot toolkit's `logger`/`playback` format,
// one message per line, SI units: metres, radians, seconds), as CARMEN writes
// them. Reading: carmen_log_reader.hpp; writing: carmen_log_writer.hpp.
//
// Field orders follow CARMEN's own description of its format: the comment
// header that CARMEN's logger writes (src/logtools/writelog.c,
// carmen_logwrite_write_header), its line parsers (src/logtools/readlog.c) and
// http://carmen.sourceforge.net/logger_playback.html; checked against the
// Radish logs in tests/data/radish/. Every line ends with the same three fields:
// `ipc_timestamp ipc_hostname logger_timestamp`.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace playerkit::log {

struct CarmenPose {
  double x = 0;
  double y = 0;
  double theta = 0;

  friend bool operator==(const CarmenPose&, const CarmenPose&) = default;
};

// The three fields that end every line.
struct CarmenStamp {
  double ipc_timestamp = 0;  // when the message was made, s (often since the epoch)
  std::string host;          // the IPC host that sent it
  double logger_timestamp = 0;  // when the logger received it, s since logging began

  friend bool operator==(const CarmenStamp&, const CarmenStamp&) = default;
};

// `PARAM name value`: one robot parameter (the value is text; it may hold spaces).
struct CarmenParam {
  std::string name;
  std::string value;
  CarmenStamp stamp;

  friend bool operator==(const CarmenParam&, const CarmenParam&) = default;
};

// `ODOM x y theta tv rv accel`: odometry pose, translational and rotational
// velocity (m/s, rad/s) and acceleration (m/s^2).
struct CarmenOdometry {
  CarmenPose pose;
  double tv = 0;
  double rv = 0;
  double acceleration = 0;
  CarmenStamp stamp;

  friend bool operator==(const CarmenOdometry&, const CarmenOdometry&) = default;
};

// `TRUEPOS true_x true_y true_theta odom_x odom_y odom_theta` (the simulator's
// ground truth beside the odometry).
struct CarmenTruePos {
  CarmenPose true_pose;
  CarmenPose odometry_pose;
  CarmenStamp stamp;

  friend bool operator==(const CarmenTruePos&, const CarmenTruePos&) = default;
};

enum class CarmenLaserKind {
  kFlaser,       // old front laser: n ranges, laser pose, odometry pose
  kRlaser,       // old rear laser, same layout
  kLaser3,       // old third/fourth laser: n ranges only
  kLaser4,
  kRawLaser1,    // laser config, ranges, remissions; no pose
  kRawLaser2,
  kRawLaser3,
  kRawLaser4,
  kRobotLaser1,  // laser config, ranges, remissions, laser and robot pose, motion
  kRobotLaser2,
};

// "FLASER", "RAWLASER3", ...
std::string_view carmen_laser_keyword(CarmenLaserKind kind);
// The kind a keyword names, or nullopt.
std::optional<CarmenLaserKind> carmen_laser_kind(std::string_view keyword);

// What a laser is and how its beams are spread: beam i points at
// start_angle + i * angular_resolution in the laser's frame (counter-clockwise,
// 0 = straight ahead). CARMEN's laser_config_t.
struct CarmenLaserConfig {
  int laser_type = 0;          // 0 SICK LMS, 1 SICK PLS, 2 Hokuyo URG, 3 simulated, 4 SICK S300
  double start_angle = 0;      // rad
  double fov = 0;              // rad
  double angular_resolution = 0;  // rad between beams
  double maximum_range = 0;    // m
  double accuracy = 0;         // m
  int remission_mode = 0;      // 0 none, 1 direct, 2 normalized

  friend bool operator==(const CarmenLaserConfig&, const CarmenLaserConfig&) = default;
};

// The old records (FLASER, RLASER, LASER3, LASER4) do not say how their beams
// are spread. CARMEN's readlog guesses from the beam count (a SICK LMS starting
// at -90 deg), and so does this, with its values: 180 beams = 1 deg steps over
// 179 deg; 360 = 0.5 deg over 179.5 deg; 181 and 361 = 1 and 0.5 deg over 180
// deg; 400/401 = 0.25 deg; any other n spreads n beams evenly over 180 deg.
// Maximum range 80 m, accuracy 0.01 m (CARMEN's guesses; the Radish SICK logs
// hold 81.83/81.91 m "no return" readings beyond it).
CarmenLaserConfig guess_carmen_laser_config(std::size_t beams);

// ROBOTLASER's motion fields after the poses.
struct CarmenLaserMotion {
  double tv = 0;  // m/s
  double rv = 0;  // rad/s
  double forward_safety_dist = 0;  // m
  double side_safety_dist = 0;     // m
  std::optional<double> turn_axis;  // written by later CARMEN versions only

  friend bool operator==(const CarmenLaserMotion&, const CarmenLaserMotion&) = default;
};

// Any laser record. Which optional parts are present depends on the kind:
//   FLASER/RLASER:  laser_pose = "x y theta", robot_pose = "odom_x odom_y odom_theta"
//                   (the odometry pose at scan time), config guessed;
//   LASER3/LASER4:  ranges only, config guessed;
//   RAWLASERn:      config from the line, remissions;
//   ROBOTLASERn:    config, remissions, both poses, motion.
struct CarmenLaser {
  CarmenLaserKind kind = CarmenLaserKind::kFlaser;
  CarmenLaserConfig config;
  bool config_guessed = false;  // true when the record has no config (see above)
  std::vector<double> ranges;   // m, in beam order
  std::vector<double> remissions;
  std::optional<CarmenPose> laser_pose;
  std::optional<CarmenPose> robot_pose;
  std::optional<CarmenLaserMotion> motion;
  CarmenStamp stamp;

  friend bool operator==(const CarmenLaser&, const CarmenLaser&) = default;
};

using CarmenRecord = std::variant<CarmenParam, CarmenOdometry, CarmenTruePos, CarmenLaser>;

}  // namespace playerkit::log
