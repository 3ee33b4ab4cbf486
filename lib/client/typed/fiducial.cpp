#include "client/typed/fiducial.hpp"

#include <algorithm>

#include "client/typed/to_wire.hpp"

namespace playerkit::client {

using protocol::to_si;
using protocol::WireUnit;

std::vector<Fiducial> to_si(const protocol::FiducialData& data) {
  const std::size_t n = std::min<std::size_t>(data.count, data.fiducials.size());
  std::vector<Fiducial> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& f = data.fiducials[i];
    out.push_back({f.id, to_si(WireUnit::kMillimetre, f.pose[0]), to_si(WireUnit::kDegree, f.pose[1]),
                   to_si(WireUnit::kDegree, f.pose[2]), to_si(WireUnit::kMillimetre, f.upose[0]),
                   to_si(WireUnit::kDegree, f.upose[1]), to_si(WireUnit::kDegree, f.upose[2])});
  }
  return out;
}

FiducialGeometry to_si(const protocol::FiducialGeom& geom) {
  return {planar_pose(geom.pose), to_si(WireUnit::kMillimetre, geom.size[0]),
          to_si(WireUnit::kMillimetre, geom.size[1]), to_si(WireUnit::kMillimetre, geom.fiducial_size[0]),
          to_si(WireUnit::kMillimetre, geom.fiducial_size[1])};
}

FiducialFov to_si(const protocol::FiducialFov& fov) {
  return {to_si(WireUnit::kMillimetre, fov.min_range), to_si(WireUnit::kMillimetre, fov.max_range),
          to_si(WireUnit::kDegree, fov.view_angle)};
}

protocol::FiducialFov set_fov_request(const FiducialFov& fov) {
  protocol::FiducialFov wire;
  wire.subtype = protocol::kFiducialSetFov;
  wire.min_range = to_wire<std::uint16_t>(WireUnit::kMillimetre, fov.min_range, "fiducial fov min_range");
  wire.max_range = to_wire<std::uint16_t>(WireUnit::kMillimetre, fov.max_range, "fiducial fov max_range");
  wire.view_angle = to_wire<std::uint16_t>(WireUnit::kDegree, fov.view_angle, "fiducial fov view_angle");
  return wire;
}

}  // namespace playerkit::client
