#include "client/typed/ranging.hpp"

#include <algorithm>

#include "protocol/si_units.hpp"

namespace playerkit::client {
namespace {

template <class Array, class Count>
std::vector<double> ranges_in_metres(const Array& ranges, Count count) {
  const std::size_t n = std::min<std::size_t>(count, ranges.size());
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(protocol::to_si(protocol::WireUnit::kMillimetre, ranges[i]));
  return out;
}

template <class Array, class Count>
SensorPoses poses_of(const Array& poses, Count count) {
  const std::size_t n = std::min<std::size_t>(count, poses.size());
  SensorPoses out;
  out.poses.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.poses.push_back(planar_pose(poses[i]));
  return out;
}

}  // namespace

SonarScan to_si(const protocol::SonarData& data) { return {ranges_in_metres(data.ranges, data.range_count)}; }

SensorPoses to_si(const protocol::SonarGeom& geom) { return poses_of(geom.poses, geom.pose_count); }

IrScan to_si(const protocol::IrData& data) {
  IrScan scan{ranges_in_metres(data.ranges, data.range_count), {}};
  const std::size_t n = std::min<std::size_t>(data.range_count, data.voltages.size());
  scan.voltages.assign(data.voltages.begin(), data.voltages.begin() + static_cast<std::ptrdiff_t>(n));
  return scan;
}

SensorPoses to_si(const protocol::IrPose& poses) { return poses_of(poses.poses, poses.pose_count); }

SensorPoses to_si(const protocol::IrPoseRequest& reply) { return to_si(reply.poses); }

}  // namespace playerkit::client
