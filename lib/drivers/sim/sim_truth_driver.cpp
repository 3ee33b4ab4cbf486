#include <utility>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::drivers::sim {

SimTruthDriver::SimTruthDriver(std::shared_ptr<SimulationHost> host, ModelId model, HeadingRange heading)
    : SimulatedDevice(std::move(host), model, false), heading_(heading) {}

// The truth of a robot is its true pose: the world's, stepped every step.
double SimTruthDriver::reading_time(const World& world) const { return world.time(); }

std::optional<std::vector<std::uint8_t>> SimTruthDriver::encode_reading(const World& world) {
  const geometry::Pose2 pose = world.true_pose(world.root_of(model()));
  protocol::TruthData data;
  data.px = wire_value<std::int32_t>(pose.x * kMillimetresPerMetre);
  data.py = wire_value<std::int32_t>(pose.y * kMillimetresPerMetre);
  data.pa = heading_degrees(pose.yaw, heading_);
  return protocol::encode(data);
}

core::RequestResult SimTruthDriver::answer(World& world, const core::Request& request) {
  const ModelId robot = world.root_of(model());
  switch (request.subtype()) {
    case protocol::kTruthGetPose: {
      const geometry::Pose2 pose = world.true_pose(robot);
      protocol::TruthPose reply;
      reply.subtype = protocol::kTruthGetPose;
      reply.px = wire_value<std::int32_t>(pose.x * kMillimetresPerMetre);
      reply.py = wire_value<std::int32_t>(pose.y * kMillimetresPerMetre);
      reply.pa = heading_degrees(pose.yaw, heading_);
      return core::RequestResult::ack(protocol::encode(reply));
    }
    case protocol::kTruthSetPose:
    case protocol::kTruthSetPoseOnRoot: {
      if (request.payload.size() < protocol::TruthPose::kWireSize) break;
      const auto wanted = decode_padded<protocol::TruthPose>(request.payload);
      world.set_true_pose(robot, {wanted.px / kMillimetresPerMetre, wanted.py / kMillimetresPerMetre,
                                  radians(wanted.pa)});
      return core::RequestResult::ack();
    }
    case protocol::kTruthGetFiducialId: {
      protocol::TruthFiducialId reply;
      reply.subtype = protocol::kTruthGetFiducialId;
      reply.id = wire_value<std::int16_t>(world.spec(robot).returns.fiducial_id);
      return core::RequestResult::ack(protocol::encode(reply));
    }
    default:
      break;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::sim
