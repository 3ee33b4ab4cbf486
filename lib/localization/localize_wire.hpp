#pragma once
// Between the filter's SI types and the Player 1.5 wire structs the amcl
// driver reads (position, laser) and writes (localize). Wire units: mm,
// degrees (position), 1/100 degree (laser angles), arc-seconds (localize
// yaw), covariance in mm^2, mm*arcsec and arcsec^2.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/pose_estimate.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "protocol/message.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/localize.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::localization {

inline constexpr double kArcsecondsPerRadian = 180.0 * 3600.0 / std::numbers::pi;
inline constexpr double kMillimetresPerMetre = 1000.0;

geometry::Pose2 odometry_pose(const protocol::PositionData& data);

// Beam i lies at min_angle + i * resolution; a zero range_res counts as 1.
amcl::LaserScan laser_scan(const protocol::LaserData& data, const geometry::Pose2& sensor_pose,
                           double max_range);

protocol::LocalizeHypothesis to_wire(const amcl::Hypothesis& hypothesis);
// (mean, covariance) of a wire hypothesis or set-pose request, in m and rad.
geometry::Pose2 pose_from_wire(const std::array<std::int32_t, 3>& mean);
Eigen::Matrix3d covariance_from_wire(const std::array<std::array<std::int64_t, 3>, 3>& cov);

// At most kLocalizeMaxHypoths of `hypotheses`, heaviest first as given.
protocol::LocalizeData localize_data(std::span<const amcl::Hypothesis> hypotheses,
                                     std::uint16_t pending_count, protocol::Timestamp pending_time);

}  // namespace playerkit::localization
