#include "localization/localize_wire.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace playerkit::localization {

namespace {

constexpr double kRadiansPerHundredthDegree = geometry::kRadiansPerDegree / 100.0;

std::int32_t to_int32(double value) {
  constexpr double lo = std::numeric_limits<std::int32_t>::min();
  constexpr double hi = std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(std::clamp(std::round(value), lo, hi));
}

std::int64_t to_int64(double value) {
  // Doubles at the int64 limits round outwards; stay a little inside them.
  constexpr double limit = 9.0e18;
  return static_cast<std::int64_t>(std::clamp(std::round(value), -limit, limit));
}

// Scale of each pose component in wire units: mm, mm, arc-seconds.
constexpr std::array<double, 3> kWireScale{kMillimetresPerMetre, kMillimetresPerMetre, kArcsecondsPerRadian};

}  // namespace

geometry::Pose2 odometry_pose(const protocol::PositionData& data) {
  return {data.xpos / kMillimetresPerMetre, data.ypos / kMillimetresPerMetre,
          geometry::normalize_angle(data.yaw * geometry::kRadiansPerDegree)};
}

amcl::LaserScan laser_scan(const protocol::LaserData& data, const geometry::Pose2& sensor_pose,
                           double max_range) {
  amcl::LaserScan scan;
  scan.sensor_pose = sensor_pose;
  scan.max_range = max_range;
  const double metres_per_unit = std::max<int>(data.range_res, 1) / kMillimetresPerMetre;
  const std::size_t count = std::min<std::size_t>(data.range_count, data.ranges.size());
  scan.ranges.reserve(count);
  scan.bearings.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    scan.ranges.push_back(data.ranges[i] * metres_per_unit);
    scan.bearings.push_back((data.min_angle + static_cast<double>(i) * data.resolution) *
                            kRadiansPerHundredthDegree);
  }
  return scan;
}

protocol::LocalizeHypothesis to_wire(const amcl::Hypothesis& hypothesis) {
  protocol::LocalizeHypothesis wire;
  const std::array<double, 3> mean{hypothesis.mean.x, hypothesis.mean.y,
                                   geometry::normalize_angle(hypothesis.mean.yaw)};
  for (int i = 0; i < 3; ++i) {
    wire.mean[i] = to_int32(mean[i] * kWireScale[i]);
    for (int j = 0; j < 3; ++j) {
      wire.cov[i][j] = to_int64(hypothesis.covariance(i, j) * kWireScale[i] * kWireScale[j]);
    }
  }
  wire.alpha = static_cast<std::uint32_t>(std::clamp(std::round(hypothesis.weight * 1e6), 0.0, 1e6));
  return wire;
}

geometry::Pose2 pose_from_wire(const std::array<std::int32_t, 3>& mean) {
  return {mean[0] / kWireScale[0], mean[1] / kWireScale[1], geometry::normalize_angle(mean[2] / kWireScale[2])};
}

Eigen::Matrix3d covariance_from_wire(const std::array<std::array<std::int64_t, 3>, 3>& cov) {
  Eigen::Matrix3d covariance;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      covariance(i, j) = static_cast<double>(cov[i][j]) / (kWireScale[i] * kWireScale[j]);
    }
  }
  return covariance;
}

protocol::LocalizeData localize_data(std::span<const amcl::Hypothesis> hypotheses,
                                     std::uint16_t pending_count, protocol::Timestamp pending_time) {
  protocol::LocalizeData data;
  data.pending_count = pending_count;
  data.pending_time_sec = pending_time.sec;
  data.pending_time_usec = pending_time.usec;
  const std::size_t count = std::min(hypotheses.size(), protocol::kLocalizeMaxHypoths);
  data.hypoth_count = static_cast<std::uint32_t>(count);
  for (std::size_t i = 0; i < count; ++i) data.hypoths[i] = to_wire(hypotheses[i]);
  return data;
}

}  // namespace playerkit::localization
