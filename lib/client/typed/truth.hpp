#pragma once
// Ground truth (simulators) in SI units.

#include "client/typed/pose.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::client {

Pose2D to_si(const protocol::TruthData& data);
Pose2D to_si(const protocol::TruthPose& pose);  // the get-pose reply

// A set-pose request (set-pose-on-root with on_root): mm and whole degrees,
// rounded, clamped to int32; NaN or infinity throws std::invalid_argument.
protocol::TruthPose set_pose_request(const Pose2D& pose, bool on_root = false);

}  // namespace playerkit::client
