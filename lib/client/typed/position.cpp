#include "client/typed/position.hpp"

#include "client/typed/to_wire.hpp"

namespace playerkit::client {

using protocol::to_si;
using protocol::WireUnit;

PositionState to_si(const protocol::PositionData& data) {
  return {{to_si(WireUnit::kMillimetre, data.xpos), to_si(WireUnit::kMillimetre, data.ypos),
           to_si(WireUnit::kDegree, data.yaw)},
          {to_si(WireUnit::kMillimetrePerSecond, data.xspeed), to_si(WireUnit::kMillimetrePerSecond, data.yspeed),
           to_si(WireUnit::kDegreePerSecond, data.yawspeed)},
          data.stall != 0};
}

PositionCommand to_si(const protocol::PositionCommand& command) {
  return {{to_si(WireUnit::kMillimetre, command.xpos), to_si(WireUnit::kMillimetre, command.ypos),
           to_si(WireUnit::kDegree, command.yaw)},
          {to_si(WireUnit::kMillimetrePerSecond, command.xspeed),
           to_si(WireUnit::kMillimetrePerSecond, command.yspeed),
           to_si(WireUnit::kDegreePerSecond, command.yawspeed)},
          command.state != 0,
          command.type != 0};
}

PositionGeometry to_si(const protocol::PositionGeom& geom) {
  return {planar_pose(geom.pose), to_si(WireUnit::kMillimetre, geom.size[0]),
          to_si(WireUnit::kMillimetre, geom.size[1])};
}

protocol::PositionCommand to_wire(const PositionCommand& command) {
  protocol::PositionCommand wire;
  wire.xpos = to_wire<std::int32_t>(WireUnit::kMillimetre, command.target.x, "position command target.x");
  wire.ypos = to_wire<std::int32_t>(WireUnit::kMillimetre, command.target.y, "position command target.y");
  wire.yaw = to_wire<std::int32_t>(WireUnit::kDegree, command.target.yaw, "position command target.yaw");
  wire.xspeed =
      to_wire<std::int32_t>(WireUnit::kMillimetrePerSecond, command.velocity.x, "position command velocity.x");
  wire.yspeed =
      to_wire<std::int32_t>(WireUnit::kMillimetrePerSecond, command.velocity.y, "position command velocity.y");
  wire.yawspeed =
      to_wire<std::int32_t>(WireUnit::kDegreePerSecond, command.velocity.yaw, "position command velocity.yaw");
  wire.state = command.motors_on ? 1 : 0;
  wire.type = command.position_mode ? 1 : 0;
  return wire;
}

protocol::PositionSetOdomRequest set_odom_request(const Pose2D& pose) {
  protocol::PositionSetOdomRequest wire;
  wire.subtype = protocol::kPositionSetOdomReq;
  wire.x = to_wire<std::int32_t>(WireUnit::kMillimetre, pose.x, "set-odom x");
  wire.y = to_wire<std::int32_t>(WireUnit::kMillimetre, pose.y, "set-odom y");
  wire.theta = to_wire<std::int32_t>(WireUnit::kDegree, pose.yaw, "set-odom yaw");
  return wire;
}

}  // namespace playerkit::client
