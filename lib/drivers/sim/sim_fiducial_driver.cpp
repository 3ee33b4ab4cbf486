#include <algorithm>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/fiducial.hpp"

namespace playerkit::drivers::sim {

namespace {

// Where the finder looks from on its robot: a finder on a laser looks from
// the scan's origin (as the world does, after Stage 1.3).
geometry::Pose2 finder_pose_on_robot(const World& world, ModelId finder) {
  const ModelId parent = world.spec(finder).parent;
  if (parent != playerkit::sim::kNoModel) {
    if (const auto* laser = std::get_if<playerkit::sim::LaserSpec>(&world.spec(parent).params)) {
      return pose_on_robot(world, parent).compose(laser->pose).compose(world.spec(finder).pose);
    }
  }
  return pose_on_robot(world, finder);
}

}  // namespace

double SimFiducialDriver::reading_time(const World& world) const { return world.fiducials(model()).time; }

std::optional<std::vector<std::uint8_t>> SimFiducialDriver::encode_reading(const World& world) {
  const playerkit::sim::FiducialScan& scan = world.fiducials(model());
  protocol::FiducialData data;
  const std::size_t count = std::min(scan.sightings.size(), protocol::kFiducialMaxSamples);
  data.count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    const playerkit::sim::FiducialSighting& sighting = scan.sightings[i];
    protocol::FiducialItem& item = data.fiducials[i];
    // The world reads 0 beyond the identification range; Player says -1.
    item.id = sighting.id != 0 ? wire_value<std::int16_t>(sighting.id) : std::int16_t{-1};
    item.pose = {wire_value<std::int16_t>(sighting.range * kMillimetresPerMetre),
                 wire_value<std::int16_t>(degrees(sighting.bearing)),
                 wire_value<std::int16_t>(degrees(sighting.orientation))};
  }
  return protocol::encode(data);
}

core::RequestResult SimFiducialDriver::answer(World& world, const core::Request& request) {
  const auto& spec = std::get<playerkit::sim::FiducialSpec>(world.spec(model()).params);
  switch (request.subtype()) {
    case protocol::kFiducialGetGeom: {
      const geometry::Pose2 pose = finder_pose_on_robot(world, model());
      const playerkit::sim::Body& body = world.spec(model()).body;
      protocol::FiducialGeom geom;
      geom.subtype = protocol::kFiducialGetGeom;
      geom.pose = {wire_value<std::int16_t>(pose.x * kMillimetresPerMetre),
                   wire_value<std::int16_t>(pose.y * kMillimetresPerMetre),
                   wire_value<std::int16_t>(degrees(pose.yaw))};
      if (body.present) {
        geom.size = {wire_value<std::uint16_t>(body.size.x() * kMillimetresPerMetre),
                     wire_value<std::uint16_t>(body.size.y() * kMillimetresPerMetre)};
      }
      // fiducial_size stays 0: the targets of a world differ in size.
      return core::RequestResult::ack(protocol::encode(geom));
    }
    case protocol::kFiducialGetFov: {
      protocol::FiducialFov fov;
      fov.subtype = protocol::kFiducialGetFov;
      fov.min_range = wire_value<std::uint16_t>(spec.range_min * kMillimetresPerMetre);
      fov.max_range = wire_value<std::uint16_t>(spec.range_max * kMillimetresPerMetre);
      fov.view_angle = wire_value<std::uint16_t>(degrees(spec.fov));
      return core::RequestResult::ack(protocol::encode(fov));
    }
    default:
      return core::RequestResult::nack();
  }
}

}  // namespace playerkit::drivers::sim
