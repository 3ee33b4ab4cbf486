#include "client/typed/localize.hpp"

#include <algorithm>
#include <string>

#include "client/typed/to_wire.hpp"

namespace playerkit::client {
namespace {

using protocol::WireUnit;

// Units of the mean's components, and so of the covariance's rows and columns.
constexpr std::array<WireUnit, 3> kAxes{WireUnit::kMillimetre, WireUnit::kMillimetre, WireUnit::kArcSecond};

}  // namespace

LocalizeEstimate to_si(const protocol::LocalizeData& data) {
  using protocol::to_si;
  LocalizeEstimate out;
  out.pending_count = data.pending_count;
  out.pending_time = data.pending_time_sec + data.pending_time_usec * 1e-6;
  const std::size_t n = std::min<std::size_t>(data.hypoth_count, data.hypoths.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto& h = data.hypoths[i];
    LocalizeHypothesis si;
    si.mean = {to_si(kAxes[0], h.mean[0]), to_si(kAxes[1], h.mean[1]), to_si(kAxes[2], h.mean[2])};
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) {
        si.covariance[r][c] = to_si(kAxes[c], to_si(kAxes[r], static_cast<double>(h.cov[r][c])));
      }
    }
    si.weight = to_si(WireUnit::kMillionth, h.alpha);
    out.hypotheses.push_back(si);
  }
  return out;
}

protocol::LocalizeSetPose set_pose_request(const Pose2D& mean, const Covariance3& covariance) {
  protocol::LocalizeSetPose wire;
  wire.subtype = protocol::kLocalizeSetPoseReq;
  wire.mean[0] = to_wire<std::int32_t>(kAxes[0], mean.x, "localize set-pose mean x");
  wire.mean[1] = to_wire<std::int32_t>(kAxes[1], mean.y, "localize set-pose mean y");
  wire.mean[2] = to_wire<std::int32_t>(kAxes[2], mean.yaw, "localize set-pose mean yaw");
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::string field = "localize set-pose covariance[" + std::to_string(r) + "][" + std::to_string(c) + "]";
      wire.cov[r][c] = round_to_wire<std::int64_t>(
          protocol::from_si(kAxes[c], protocol::from_si(kAxes[r], covariance[r][c])), field);
    }
  }
  return wire;
}

}  // namespace playerkit::client
