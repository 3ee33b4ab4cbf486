#include <utility>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers::sim {

geometry::Pose2 pose_on_robot(const World& world, ModelId model) {
  return world.true_pose(world.root_of(model)).between(world.true_pose(model));
}

SimPositionDriver::SimPositionDriver(std::shared_ptr<SimulationHost> host, ModelId model, HeadingRange heading)
    : SimulatedDevice(std::move(host), model), heading_(heading) {}

void SimPositionDriver::apply_command(World& world, const core::Command& command) {
  const auto wanted = decode_padded<protocol::PositionCommand>(command.payload);
  if (wanted.type == 1) {
    world.command_pose(model(), {wanted.xpos / kMillimetresPerMetre, wanted.ypos / kMillimetresPerMetre,
                                 radians(wanted.yaw)});
    return;
  }
  world.command_velocity(model(), {wanted.xspeed / kMillimetresPerMetre, wanted.yspeed / kMillimetresPerMetre,
                                   radians(wanted.yawspeed)});
}

double SimPositionDriver::reading_time(const World& world) const { return world.position(model()).time; }

std::optional<std::vector<std::uint8_t>> SimPositionDriver::encode_reading(const World& world) {
  const playerkit::sim::PositionReading& reading = world.position(model());
  protocol::PositionData data;
  data.xpos = wire_value<std::int32_t>(reading.pose.x * kMillimetresPerMetre);
  data.ypos = wire_value<std::int32_t>(reading.pose.y * kMillimetresPerMetre);
  data.yaw = heading_degrees(reading.pose.yaw, heading_);
  data.xspeed = wire_value<std::int32_t>(reading.velocity.x * kMillimetresPerMetre);
  data.yspeed = wire_value<std::int32_t>(reading.velocity.y * kMillimetresPerMetre);
  data.yawspeed = wire_value<std::int32_t>(degrees(reading.velocity.yaw));
  data.stall = reading.stalled ? 1 : 0;
  return protocol::encode(data);
}

core::RequestResult SimPositionDriver::answer(World& world, const core::Request& request) {
  switch (request.subtype()) {
    case protocol::kPositionGetGeomReq: {
      const playerkit::sim::Body& body = world.spec(model()).body;
      protocol::PositionGeom geom;
      geom.subtype = protocol::kPositionGetGeomReq;
      geom.pose = {wire_value<std::int16_t>(body.offset.x * kMillimetresPerMetre),
                   wire_value<std::int16_t>(body.offset.y * kMillimetresPerMetre),
                   wire_value<std::int16_t>(degrees(body.offset.yaw))};
      const double width = body.shape == playerkit::sim::Shape::circle ? body.size.x() : body.size.y();
      geom.size = {wire_value<std::uint16_t>(body.size.x() * kMillimetresPerMetre),
                   wire_value<std::uint16_t>(width * kMillimetresPerMetre)};
      return core::RequestResult::ack(protocol::encode(geom));
    }
    // Motors are always on in a simulation; control modes are the command's type.
    case protocol::kPositionMotorPowerReq:
    case protocol::kPositionVelocityModeReq:
    case protocol::kPositionPositionModeReq:
      return core::RequestResult::ack();
    case protocol::kPositionResetOdomReq:
      world.set_odometry(model(), {});
      return core::RequestResult::ack();
    case protocol::kPositionSetOdomReq: {
      if (request.payload.size() < protocol::PositionSetOdomRequest::kWireSize) break;
      const auto pose = decode_padded<protocol::PositionSetOdomRequest>(request.payload);
      world.set_odometry(model(), {pose.x / kMillimetresPerMetre, pose.y / kMillimetresPerMetre, radians(pose.theta)});
      return core::RequestResult::ack();
    }
    default:
      break;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::sim
