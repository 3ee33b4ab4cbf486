#include "client/typed/laser.hpp"

#include <algorithm>

#include "client/typed/to_wire.hpp"

namespace playerkit::client {

using protocol::to_si;
using protocol::WireUnit;

LaserScan to_si(const protocol::LaserData& data) {
  LaserScan scan;
  scan.min_angle = to_si(WireUnit::kHundredthDegree, data.min_angle);
  scan.max_angle = to_si(WireUnit::kHundredthDegree, data.max_angle);
  scan.resolution = to_si(WireUnit::kHundredthDegree, data.resolution);
  // The same rule as protocol/si_units: an unset range_res means millimetres.
  const double range_res = data.range_res == 0 ? 1.0 : data.range_res;
  const std::size_t count = std::min<std::size_t>(data.range_count, data.ranges.size());
  scan.ranges.reserve(count);
  scan.bearings.reserve(count);
  scan.intensities.assign(data.intensity.begin(), data.intensity.begin() + static_cast<std::ptrdiff_t>(count));
  for (std::size_t i = 0; i < count; ++i) {
    scan.ranges.push_back(to_si(WireUnit::kMillimetre, data.ranges[i] * range_res));
    // From the wire integers, so that no rounding accumulates along the scan.
    scan.bearings.push_back(
        to_si(WireUnit::kHundredthDegree, data.min_angle + static_cast<double>(i) * data.resolution));
  }
  return scan;
}

LaserGeometry to_si(const protocol::LaserGeom& geom) {
  return {planar_pose(geom.pose), to_si(WireUnit::kMillimetre, geom.size[0]),
          to_si(WireUnit::kMillimetre, geom.size[1])};
}

LaserConfig to_si(const protocol::LaserConfig& config) {
  return {to_si(WireUnit::kHundredthDegree, config.min_angle), to_si(WireUnit::kHundredthDegree, config.max_angle),
          to_si(WireUnit::kHundredthDegree, config.resolution), config.range_res, config.intensity != 0};
}

protocol::LaserConfig set_config_request(const LaserConfig& config) {
  protocol::LaserConfig wire;
  wire.subtype = protocol::kLaserSetConfig;
  wire.min_angle = to_wire<std::int16_t>(WireUnit::kHundredthDegree, config.min_angle, "laser config min_angle");
  wire.max_angle = to_wire<std::int16_t>(WireUnit::kHundredthDegree, config.max_angle, "laser config max_angle");
  wire.resolution =
      to_wire<std::uint16_t>(WireUnit::kHundredthDegree, config.resolution, "laser config resolution");
  wire.range_res = config.range_res;
  wire.intensity = config.intensity ? 1 : 0;
  return wire;
}

}  // namespace playerkit::client
