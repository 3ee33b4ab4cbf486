#include "families/p2os/protocol/robot_params.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace playerkit::hardware::p2os {
namespace {

// §4.3. Rows of one family share a ring.
constexpr std::array<SonarPose, 8> kAmigoSonars{{
    {73, 105, 90}, {130, 78, 41}, {154, 30, 15}, {154, -30, -15},
    {130, -78, -41}, {73, -105, -90}, {-146, -60, -145}, {-146, 60, 145},
}};

constexpr std::array<SonarPose, 16> kP2dxSonars{{
    {115, 130, 90}, {155, 115, 50}, {190, 80, 30}, {210, 25, 10},
    {210, -25, -10}, {190, -80, -30}, {155, -115, -50}, {115, -130, -90},
    {-115, -130, -90}, {-155, -115, -130}, {-190, -80, -150}, {-210, -25, -170},
    {-210, 25, 170}, {-190, 80, 150}, {-155, 115, 130}, {-115, 130, 90},
}};

constexpr std::array<SonarPose, 16> kP2atSonars{{
    {145, 130, 90}, {185, 115, 50}, {220, 80, 30}, {240, 25, 10},
    {240, -25, -10}, {220, -80, -30}, {185, -115, -50}, {145, -130, -90},
    {-145, -130, -90}, {-185, -115, -130}, {-220, -80, -150}, {-240, -25, -170},
    {-240, 25, 170}, {-220, 80, 150}, {-185, 115, 130}, {-145, 130, 90},
}};

// PeopleBot: the p2dx front ring, a second front ring higher up, the p2dx
// rear ring. The Performance PeopleBot adds a second rear ring.
constexpr std::array<SonarPose, 32> kPerformancePeopleBotSonars{{
    {115, 130, 90}, {155, 115, 50}, {190, 80, 30}, {210, 25, 10},
    {210, -25, -10}, {190, -80, -30}, {155, -115, -50}, {115, -130, -90},
    {50, 130, 90}, {90, 115, 50}, {125, 80, 30}, {145, 25, 10},
    {145, -25, -10}, {125, -80, -30}, {90, -115, -50}, {50, -130, -90},
    {-115, -130, -90}, {-155, -115, -130}, {-190, -80, -150}, {-210, -25, -170},
    {-210, 25, 170}, {-190, 80, 150}, {-155, 115, 130}, {-115, 130, 90},
    {-195, -130, -90}, {-235, -115, -130}, {-270, -80, -150}, {-290, -25, -170},
    {-290, 25, 170}, {-270, 80, 150}, {-235, 115, 130}, {-195, 130, 90},
}};

constexpr std::span<const SonarPose> kPeopleBotSonars =
    std::span<const SonarPose>(kPerformancePeopleBotSonars).first(24);

// The remaining fields, per robot (§4.2, second table). Every listed robot
// has HasMoveCommand, Holonomic, LaserPowerControlled = 1, LaserPort COM3,
// RobotDiagonal 120 and all accelerations and velocity maxima 0.
RobotExtraParams extra(int bumper_flags, int bumper_count, double gyro_scaler, int laser_x,
                       int laser_y) {
  RobotExtraParams e;
  e.front_bumpers = e.rear_bumpers = bumper_flags != 0;
  e.num_front_bumpers = e.num_rear_bumpers = bumper_count;
  e.gyro_scaler = gyro_scaler;
  e.has_move_command = true;
  e.holonomic = true;
  e.laser_power_controlled = true;
  e.laser_port = "COM3";
  e.laser_x = laser_x;
  e.laser_y = laser_y;
  e.robot_diagonal = 120;
  return e;
}

RobotExtraParams pioneer3_extra(int laser_x, int laser_y) {
  RobotExtraParams e = extra(0, 5, 1.626, laser_x, laser_y);
  e.robot_length = 500;
  e.robot_width = 400;
  e.settable_accs_decs = true;
  e.settable_vel_maxes = true;
  e.switch_to_baud_rate = 38400;
  return e;
}

RobotExtraParams performance_peoplebot_extra() {
  RobotExtraParams e = extra(1, 5, 0.0, 21, 0);
  e.table_sensing_ir = true;
  e.new_table_sensing_ir = true;
  e.request_io_packets = true;
  return e;
}

struct Row {
  std::string_view subclass;
  double angle, diff, dist, range, vel;
  int vel2_divisor, sonars, max_vel, max_rvel, radius;
  std::span<const SonarPose> poses;
  std::optional<RobotExtraParams> extra;
};

std::array<RobotParams, 23> build_table() {
  const std::array<Row, 23> rows{{
      {"amigo", 0.001534, 0.011, 0.5083, 1, 0.6154, 20, 8, 1000, 300, 180, kAmigoSonars,
       extra(0, 0, 0.0, 0, 0)},
      {"p2at", 0.001534, 0.0034, 1.32, 0.268, 1, 20, 16, 1200, 300, 500, kP2atSonars,
       extra(0, 5, 0.0, 160, 7)},
      {"p2at8+", 0.001534, 0.0034, 0.465, 1, 1, 20, 16, 1200, 300, 500, kP2atSonars, {}},
      {"p2at8", 0.001534, 0.0034, 1.32, 1, 1, 20, 16, 1200, 300, 500, kP2atSonars, {}},
      {"p2ce", 0.001534, 0.0057, 0.826, 0.268, 1, 20, 16, 2200, 500, 250, {}, {}},
      {"p2d8+", 0.001534, 0.0056, 0.485, 1, 1, 20, 16, 2200, 500, 250, kP2dxSonars, {}},
      {"p2d8", 0.001534, 0.0056, 0.485, 1, 1, 20, 16, 2200, 500, 250, kP2dxSonars, {}},
      {"p2de", 0.001534, 0.0056, 0.969, 0.268, 1, 20, 16, 2200, 500, 250, kP2dxSonars,
       extra(0, 5, 0.0, 17, 8)},
      {"p2df", 0.001534, 0.006, 0.485, 0.268, 1, 20, 16, 2200, 500, 250, {}, {}},
      {"p2dx", 0.001534, 0.0056, 0.84, 0.268, 1, 20, 16, 2200, 500, 250, kP2dxSonars,
       extra(0, 5, 0.0, 17, 8)},
      {"p2it", 0.001534, 0.0032, 1.136, 0.268, 1, 20, 16, 1200, 300, 500, {}, {}},
      {"p2pb", 0.001534, 0.0056, 0.424, 0.268, 1, 20, 24, 2200, 500, 300, kPeopleBotSonars,
       extra(1, 5, 0.0, 17, 8)},
      {"p2pp", 0.001534, 0.006, 0.485, 0.268, 1, 20, 24, 2200, 500, 300, {}, {}},
      {"p3at", 0.001534, 0.0034, 0.465, 1, 1, 20, 16, 1200, 300, 500, kP2atSonars,
       pioneer3_extra(160, 7)},
      {"p3dx", 0.001534, 0.0056, 0.485, 1, 1, 20, 16, 2200, 500, 250, kP2dxSonars,
       pioneer3_extra(18, 0)},
      {"perfpb+", 0.001534, 0.006, 0.485, 1, 1, 20, 32, 2200, 500, 340,
       kPerformancePeopleBotSonars, {}},
      {"perfpb", 0.001534, 0.006, 0.485, 1, 1, 20, 32, 2200, 500, 340,
       kPerformancePeopleBotSonars, performance_peoplebot_extra()},
      {"pion1m", 0.006136, 0.0033, 0.05066, 0.1734, 2.5332, 4, 7, 400, 100, 220, {}, {}},
      {"pion1x", 0.006136, 0.003333, 0.05066, 0.1734, 0.07979, 4, 7, 400, 100, 220, {}, {}},
      {"pionat", 0.006136, 0.003333, 0.07, 0.1734, 2.5332, 4, 7, 500, 100, 330, {}, {}},
      {"powerbot", 0.001534, 0.00373, 0.5813, 1, 1, 20, 31, 2000, 360, 550, {}, {}},
      {"psos1m", 0.006136, 0.0033, 0.05066, 0.1734, 2.5332, 4, 7, 400, 100, 220, {}, {}},
      {"psos1x", 0.006136, 0.003333, 0.05066, 0.1734, 0.07979, 4, 7, 400, 100, 220, {}, {}},
  }};
  std::array<RobotParams, 23> table;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    table[i] = RobotParams{.index = static_cast<int>(i),
                           .robot_class = "Pioneer",
                           .subclass = row.subclass,
                           .angle_conv_factor = row.angle,
                           .diff_conv_factor = row.diff,
                           .dist_conv_factor = row.dist,
                           .range_conv_factor = row.range,
                           .vel_conv_factor = row.vel,
                           .vel2_divisor = row.vel2_divisor,
                           .sonar_count = row.sonars,
                           .max_velocity = row.max_vel,
                           .max_rot_velocity = row.max_rvel,
                           .radius = row.radius,
                           .sonar_poses = row.poses,
                           .extra = row.extra};
  }
  return table;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

}  // namespace

int RobotParams::heading_units_per_turn() const {
  return static_cast<int>(std::lround(2.0 * std::numbers::pi / angle_conv_factor));
}

std::span<const RobotParams> robot_params_table() {
  static const std::array<RobotParams, 23> table = build_table();
  return table;
}

const RobotParams* find_robot_params(std::string_view robot_class, std::string_view subclass) {
  for (const RobotParams& row : robot_params_table()) {
    if (equal_ignoring_case(row.robot_class, robot_class) &&
        equal_ignoring_case(row.subclass, subclass)) {
      return &row;
    }
  }
  return nullptr;
}

const RobotParams& select_robot_params(std::string_view robot_class, std::string_view subclass) {
  const RobotParams* row = find_robot_params(robot_class, subclass);
  return row != nullptr ? *row : robot_params_table().front();
}

}  // namespace playerkit::hardware::p2os
