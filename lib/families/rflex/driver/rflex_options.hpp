#pragma once
// The options of the rflex drivers (rflex.md §4, manual §7.34), declared once
// per role in schemas (core::OptionSchema) that the reader, `player-serve
// --check`, `player-drivers info` and the README's table all use.
//
// 1.5 read every value into one structure shared by the seven drivers, so a
// robot is one RflexSettings whichever device opens it: each option is read
// from the sections of the role that declares it (odo_distance_conversion
// from rflex_position's), the link's from any rflex section. A value written
// differently on two sections is an error at the second (1.5 took the
// first-constructed section's port and silently ignored the rest).

#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"
#include "families/rflex/driver/rflex_role.hpp"

namespace playerkit::drivers::rflex {

inline constexpr std::string_view kDefaultRflexPort = "/dev/ttyR0";

// A sensor's pose in 1.5's units: mm, mm, radians.
struct MountPose {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
  friend bool operator==(const MountPose&, const MountPose&) = default;
};

struct BumperPanel {
  double x = 0.0, y = 0.0, theta_degrees = 0.0, length = 0.0, radius = 0.0;  // mm, mm, deg, mm, mm
  friend bool operator==(const BumperPanel&, const BumperPanel&) = default;
};

struct RflexSettings {
  // the link
  std::string port{kDefaultRflexPort};
  std::chrono::milliseconds connect_timeout{3000};
  std::chrono::milliseconds report_timeout{1000};
  // rflex_position
  double mm_length = 0.5;
  double mm_width = 0.5;
  double odo_distance_conversion = 103.0;  // arb per mm; the B21r's (1.5: 0, a division by zero)
  double odo_angle_conversion = 35000.0;  // arb per rad
  double default_trans_acceleration = 0.1;  // mm/s²
  double default_rot_acceleration = 0.1;    // rad/s²
  bool joystick = false;
  double joy_pos_ratio = 0.0;
  double joy_ang_ratio = 0.0;
  // rflex_sonar
  double range_distance_conversion = 1.476;  // arb per mm; the B21r's (1.5: 1)
  int max_num_sonars = 64;
  int num_sonars = 24;
  int sonar_age = 1;
  int num_sonar_banks = 8;
  int num_sonars_possible_per_bank = 16;
  std::vector<int> num_sonars_in_bank = std::vector<int>(8, 8);
  int sonar_echo_delay = 3000;
  int sonar_ping_delay = 0;
  int sonar_set_delay = 0;
  std::vector<MountPose> sonar_poses;
  // rflex_bumper
  int bumper_count = 0;
  std::vector<BumperPanel> bumper_def;
  int bumper_address = 0x40;
  // rflex_power
  int power_offset = 0;  // dV
  // rflex_ir
  int ir_pose_count = 8;
  int ir_base_bank = 0;
  int ir_bank_count = 0;
  std::vector<int> ir_banks;
  int ir_min_range = 100;
  int ir_max_range = 800;
  std::vector<std::array<double, 2>> ir_calibration;  // a, b per sensor
  std::vector<MountPose> ir_poses;  // mm, mm, radians (written in degrees)

  friend bool operator==(const RflexSettings&, const RflexSettings&) = default;
};

// The options of `role`'s section: the link's, then the role's own.
const core::OptionSchema& rflex_option_schema(RflexRole role);

// The robot of `context`'s section: every rflex section on its server port.
// Throws config::ConfigError at the offending value.
RflexSettings read_rflex_settings(const core::DriverContext& context);

// "rflex /dev/ttyR0": the key under which the robot's connection is shared.
std::string connection_key(const RflexSettings& settings);

}  // namespace playerkit::drivers::rflex
