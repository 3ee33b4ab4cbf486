#pragma once
// The robot parameter table of Player 1.5 (robot_params.cc, generated from
// Saphira .p files; p2os.md §4.2) and the sonar poses of §4.3. The SYNC2
// reply's class and subclass pick a row; 1.5 falls back to row 0 (AmigoBot)
// when nothing matches, which is how a p3dx-sh ends up with AmigoBot values.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace playerkit::hardware::p2os {

struct SonarPose {
  int x = 0;        // mm, forward
  int y = 0;        // mm, left
  int heading = 0;  // degrees, counter-clockwise from forward
  friend bool operator==(const SonarPose&, const SonarPose&) = default;
};

// Fields 1.5 stores but never uses, given by the sheet for eight robots only.
struct RobotExtraParams {
  bool front_bumpers = false;
  bool rear_bumpers = false;
  int num_front_bumpers = 0;
  int num_rear_bumpers = 0;
  double gyro_scaler = 0.0;
  bool has_move_command = false;
  bool holonomic = false;
  bool laser_possessed = false;
  bool laser_flipped = false;
  bool laser_power_controlled = false;
  std::string_view laser_port;
  int laser_x = 0;  // mm
  int laser_y = 0;  // mm
  bool table_sensing_ir = false;
  bool new_table_sensing_ir = false;
  bool request_encoder_packets = false;
  bool request_io_packets = false;
  int robot_diagonal = 0;  // mm
  int robot_length = 0;    // mm
  int robot_width = 0;     // mm
  bool settable_accs_decs = false;
  bool settable_vel_maxes = false;
  int switch_to_baud_rate = 0;
  int trans_accel = 0, trans_decel = 0, rot_accel = 0, rot_decel = 0;
  int trans_vel_max = 0, rot_vel_max = 0;
};

struct RobotParams {
  int index = 0;                // row number as 1.5 numbers it
  std::string_view robot_class; // "Pioneer" for every row
  std::string_view subclass;    // "p3dx"
  double angle_conv_factor = 0; // rad per THPOS unit
  double diff_conv_factor = 0;  // 1/mm: yaw rate = (right − left) × this / 2
  double dist_conv_factor = 0;  // mm per XPOS/YPOS unit
  double range_conv_factor = 0; // mm per sonar unit
  double vel_conv_factor = 0;   // mm/s per wheel velocity unit
  int vel2_divisor = 0;         // mm/s per VEL2 unit
  int sonar_count = 0;
  int max_velocity = 0;         // mm/s
  int max_rot_velocity = 0;     // deg/s
  int radius = 0;               // mm
  // The poses of §4.3; empty for rows the sheet gives none for.
  std::span<const SonarPose> sonar_poses;
  std::optional<RobotExtraParams> extra;

  // 2 / DiffConvFactor, in mm.
  double wheelbase() const { return 2.0 / diff_conv_factor; }
  // THPOS units in one turn: 4096 for P2/P3 rows, 1024 for Pioneer 1 rows.
  int heading_units_per_turn() const;
};

// All 23 rows, in 1.5's order (index 0 ... 22).
std::span<const RobotParams> robot_params_table();

// The row whose class and subclass both match, ignoring case; nullptr if none.
const RobotParams* find_robot_params(std::string_view robot_class, std::string_view subclass);

// As 1.5 selects: the matching row, or row 0 (amigo) when none matches.
const RobotParams& select_robot_params(std::string_view robot_class, std::string_view subclass);

}  // namespace playerkit::hardware::p2os
