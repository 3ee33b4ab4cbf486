#pragma once
// The position interface (odometry, motion commands, geometry) in SI units.

#include "client/typed/pose.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::client {

struct PositionState {
  Pose2D pose;          // odometry
  Velocity2D velocity;  // in the robot frame
  bool stall = false;
};

// What to send the base. Wire resolution: 1 mm, 1 mm/s, 1 degree and 1 deg/s, so
// yaw and yaw rate round to the nearest whole degree (0.0175 rad).
struct PositionCommand {
  Pose2D target;        // position mode (type 1)
  Velocity2D velocity;  // velocity mode (type 0)
  bool motors_on = true;     // `state`; its meaning beyond on/off is driver specific
  bool position_mode = false;  // `type`: false = velocity command, true = position command
};

struct PositionGeometry {
  Pose2D pose;        // of the base in the robot frame
  double length = 0;  // m
  double width = 0;   // m
};

PositionState to_si(const protocol::PositionData& data);
PositionCommand to_si(const protocol::PositionCommand& command);
PositionGeometry to_si(const protocol::PositionGeom& geom);

// Rounded to the nearest wire unit, clamped to int32; NaN or infinity throws
// std::invalid_argument.
protocol::PositionCommand to_wire(const PositionCommand& command);
protocol::PositionSetOdomRequest set_odom_request(const Pose2D& pose);

}  // namespace playerkit::client
