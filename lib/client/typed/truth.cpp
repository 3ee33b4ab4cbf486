#include "client/typed/truth.hpp"

#include "client/typed/to_wire.hpp"

namespace playerkit::client {

using protocol::to_si;
using protocol::WireUnit;

Pose2D to_si(const protocol::TruthData& data) {
  return {to_si(WireUnit::kMillimetre, data.px), to_si(WireUnit::kMillimetre, data.py),
          to_si(WireUnit::kDegree, data.pa)};
}

Pose2D to_si(const protocol::TruthPose& pose) {
  return {to_si(WireUnit::kMillimetre, pose.px), to_si(WireUnit::kMillimetre, pose.py),
          to_si(WireUnit::kDegree, pose.pa)};
}

protocol::TruthPose set_pose_request(const Pose2D& pose, bool on_root) {
  protocol::TruthPose wire;
  wire.subtype = on_root ? protocol::kTruthSetPoseOnRoot : protocol::kTruthSetPose;
  wire.px = to_wire<std::int32_t>(WireUnit::kMillimetre, pose.x, "truth pose x");
  wire.py = to_wire<std::int32_t>(WireUnit::kMillimetre, pose.y, "truth pose y");
  wire.pa = to_wire<std::int32_t>(WireUnit::kDegree, pose.yaw, "truth pose yaw");
  return wire;
}

}  // namespace playerkit::client
