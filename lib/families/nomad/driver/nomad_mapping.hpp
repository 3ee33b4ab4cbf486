#pragma once
// The robot's state as Player's nomad, position and sonar structs, and the
// commands back (nomad.md §2), with the reference's field mix-ups undone:
// y is y, a is the heading, each velocity in its own field, all big-endian
// through the codec, sonar in millimetres from the robot's inches.

#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "families/nomad/protocol/nomad_requests.hpp"
#include "protocol/messages/nomad.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::nomad {

// Robot units to Player's: mm, degrees in [0, 360), mm/s, deg/s, mm.
[[nodiscard]] protocol::NomadData nomad_data(const hardware::nomad::RobotState& state);

// A nomad command (mm/s, deg/s, deg/s) as VM's words (0.1 in/s, 0.1 deg/s).
struct VelocityWords {
  std::int32_t translation = 0;
  std::int32_t steering = 0;
  std::int32_t turret = 0;
  friend bool operator==(const VelocityWords&, const VelocityWords&) = default;
};
[[nodiscard]] VelocityWords velocity_words(const protocol::NomadCommand& command);

// The position device's view: x, y, heading (the steering angle), forward
// speed and turn rate; stalled while a bumper is pressed.
[[nodiscard]] protocol::PositionData position_data(const protocol::NomadData& data);
// Forward speed and turn rate; the turret turns with the steering so that
// the sonar ring keeps facing the heading its geometry is given in.
[[nodiscard]] protocol::NomadCommand nomad_command(const protocol::PositionCommand& command);

[[nodiscard]] protocol::SonarData sonar_data(const protocol::NomadData& data);
// 16 transducers on the 400 mm ring, i at i x 22.5 degrees (nomad.md §2.3).
[[nodiscard]] std::vector<geometry::Pose2> sonar_poses();

// The body: centred, 800 mm across (nomad.md §2.2).
inline constexpr double kBodyDiameter = 2 * protocol::kNomadRadiusMm / 1000.0;

}  // namespace playerkit::drivers::nomad
