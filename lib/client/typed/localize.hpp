#pragma once
// Localization hypotheses in SI units: means in m and rad, covariances in m^2,
// m*rad and rad^2, weights as fractions (the wire carries them times 1e6).

#include <array>
#include <cstdint>
#include <vector>

#include "client/typed/pose.hpp"
#include "protocol/messages/localize.hpp"

namespace playerkit::client {

// Row and column order: x, y, yaw.
using Covariance3 = std::array<std::array<double, 3>, 3>;

struct LocalizeHypothesis {
  Pose2D mean;
  Covariance3 covariance{};
  double weight = 0;
};

struct LocalizeEstimate {
  std::uint16_t pending_count = 0;  // observations not yet processed
  double pending_time = 0;          // s, time of the last processed observation
  std::vector<LocalizeHypothesis> hypotheses;
};

LocalizeEstimate to_si(const protocol::LocalizeData& data);

// A set-pose request: mm and arc-seconds (covariance mm^2, mm*arcsec, arcsec^2),
// rounded, clamped to int32 / int64; NaN or infinity throws std::invalid_argument.
protocol::LocalizeSetPose set_pose_request(const Pose2D& mean, const Covariance3& covariance);

}  // namespace playerkit::client
