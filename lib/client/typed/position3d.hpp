#pragma once
// The position3d interface in SI units (wire: mm, arc-seconds and their rates).

#include "client/typed/pose.hpp"
#include "protocol/messages/position3d.hpp"

namespace playerkit::client {

struct Position3dState {
  Pose3D pose;
  Velocity3D velocity;
  bool stall = false;
};

// Wire resolution: 1 mm, 1 arc-second (4.8e-6 rad) and their rates.
struct Position3dCommand {
  Pose3D target;
  Velocity3D velocity;
};

Position3dState to_si(const protocol::Position3dData& data);
Position3dCommand to_si(const protocol::Position3dCommand& command);
// Rounded to the nearest wire unit, clamped to int32; NaN or infinity throws.
protocol::Position3dCommand to_wire(const Position3dCommand& command);

}  // namespace playerkit::client
