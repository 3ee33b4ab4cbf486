#include <algorithm>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::sim {

double SimSonarDriver::reading_time(const World& world) const { return world.sonar(model()).time; }

std::optional<std::vector<std::uint8_t>> SimSonarDriver::encode_reading(const World& world) {
  const playerkit::sim::SonarScan& scan = world.sonar(model());
  protocol::SonarData data;
  // Player 1.5 carries 64 transducers; sim_drivers warns about more when the device is made.
  const std::size_t count = std::min(scan.ranges.size(), protocol::kSonarMaxSamples);
  data.range_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    data.ranges[i] = wire_value<std::uint16_t>(scan.ranges[i] * kMillimetresPerMetre);
  }
  return protocol::encode(data);
}

core::RequestResult SimSonarDriver::answer(World& world, const core::Request& request) {
  switch (request.subtype()) {
    case protocol::kSonarGetGeomReq: {
      const auto& spec = std::get<playerkit::sim::SonarSpec>(world.spec(model()).params);
      const geometry::Pose2 mount = pose_on_robot(world, model());
      protocol::SonarGeom geom;
      geom.subtype = protocol::kSonarGetGeomReq;
      const std::size_t count = std::min(spec.transducers.size(), protocol::kSonarMaxSamples);
      geom.pose_count = static_cast<std::uint16_t>(count);
      for (std::size_t i = 0; i < count; ++i) {
        const geometry::Pose2 pose = mount.compose(spec.transducers[i]);
        geom.poses[i] = {wire_value<std::int16_t>(pose.x * kMillimetresPerMetre),
                         wire_value<std::int16_t>(pose.y * kMillimetresPerMetre),
                         wire_value<std::int16_t>(degrees(pose.yaw))};
      }
      return core::RequestResult::ack(protocol::encode(geom));
    }
    case protocol::kSonarPowerReq:
      return core::RequestResult::ack();  // simulated transducers are always on
    default:
      return core::RequestResult::nack();
  }
}

}  // namespace playerkit::drivers::sim
