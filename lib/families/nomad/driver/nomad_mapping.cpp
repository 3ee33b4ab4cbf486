#include "families/nomad/driver/nomad_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "families/nomad/protocol/nomad_units.hpp"

namespace playerkit::drivers::nomad {

namespace units = hardware::nomad;

namespace {

std::int32_t whole(double value) { return static_cast<std::int32_t>(std::lround(value)); }

std::uint16_t range_mm(std::int32_t inches) {
  return static_cast<std::uint16_t>(std::clamp(std::lround(units::mm_from_inches(std::max(inches, 0))), 0L, 65535L));
}

std::int32_t heading_degrees(std::int32_t tenths) {
  const std::int32_t degrees = whole(units::degrees_from_tenth_degrees(tenths));
  return ((degrees % 360) + 360) % 360;
}

}  // namespace

protocol::NomadData nomad_data(const hardware::nomad::RobotState& state) {
  protocol::NomadData data;
  data.x = whole(units::mm_from_tenth_inches(state.x));
  data.y = whole(units::mm_from_tenth_inches(state.y));
  data.a = heading_degrees(state.steering);
  data.vel_trans = whole(units::mm_from_tenth_inches(state.translation_velocity));
  data.vel_steer = whole(units::degrees_from_tenth_degrees(state.steering_velocity));
  data.vel_turret = whole(units::degrees_from_tenth_degrees(state.turret_velocity));
  for (std::size_t i = 0; i < data.sonar.size() && i < state.sonar.size(); ++i) data.sonar[i] = range_mm(state.sonar[i]);
  for (std::size_t i = 0; i < data.ir.size() && i < state.ir.size(); ++i) data.ir[i] = range_mm(state.ir[i]);
  for (std::size_t i = 0; i < data.bumper.size(); ++i) data.bumper[i] = (state.bumpers >> i) & 1;
  return data;
}

VelocityWords velocity_words(const protocol::NomadCommand& command) {
  return {units::tenth_inches_from_mm(command.vel_trans), units::tenth_degrees_from_degrees(command.vel_steer),
          units::tenth_degrees_from_degrees(command.vel_turret)};
}

protocol::PositionData position_data(const protocol::NomadData& data) {
  protocol::PositionData position;
  position.xpos = data.x;
  position.ypos = data.y;
  position.yaw = data.a;
  position.xspeed = data.vel_trans;
  position.yawspeed = data.vel_steer;
  position.stall = std::any_of(data.bumper.begin(), data.bumper.end(), [](std::uint8_t b) { return b != 0; }) ? 1 : 0;
  return position;
}

protocol::NomadCommand nomad_command(const protocol::PositionCommand& command) {
  return {.vel_trans = command.xspeed, .vel_steer = command.yawspeed, .vel_turret = command.yawspeed};
}

protocol::SonarData sonar_data(const protocol::NomadData& data) {
  protocol::SonarData sonar;
  sonar.range_count = static_cast<std::uint16_t>(data.sonar.size());
  std::copy(data.sonar.begin(), data.sonar.end(), sonar.ranges.begin());
  return sonar;
}

std::vector<geometry::Pose2> sonar_poses() {
  std::vector<geometry::Pose2> poses;
  const double radius = protocol::kNomadRadiusMm / 1000.0;
  for (int i = 0; i < 16; ++i) {
    const double angle = i * std::numbers::pi / 8.0;
    poses.push_back({radius * std::cos(angle), radius * std::sin(angle), angle});
  }
  return poses;
}

}  // namespace playerkit::drivers::nomad
