#include "client/typed/truth.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace playerkit::client {
namespace truth_test {

TEST(TypedTruth, PoseGolden) {
  const Pose2D data = to_si(protocol::TruthData{1000, -2000, -180});
  EXPECT_DOUBLE_EQ(data.x, 1.0);
  EXPECT_DOUBLE_EQ(data.y, -2.0);
  EXPECT_DOUBLE_EQ(data.yaw, -3.141592653589793);
  protocol::TruthPose reply;
  reply.px = 5;
  reply.pa = 45;
  const Pose2D p = to_si(reply);
  EXPECT_DOUBLE_EQ(p.x, 0.005);
  EXPECT_DOUBLE_EQ(p.yaw, 0.7853981633974483);
}

TEST(TypedTruth, SetPoseRoundsAndRoundTrips) {
  const Pose2D pose{3.2104, -0.0015, 1.0};
  const protocol::TruthPose w = set_pose_request(pose);
  EXPECT_EQ(w.subtype, protocol::kTruthSetPose);
  EXPECT_EQ(w.px, 3210);
  EXPECT_EQ(w.py, -2);  // -1.5 mm: halves away from zero
  EXPECT_EQ(w.pa, 57);
  EXPECT_EQ(set_pose_request(pose, true).subtype, protocol::kTruthSetPoseOnRoot);
  const Pose2D back = to_si(w);
  EXPECT_NEAR(back.x, pose.x, 0.0005);
  EXPECT_NEAR(back.y, pose.y, 0.0005);
  EXPECT_NEAR(back.yaw, pose.yaw, 0.017453292519943295 / 2);
  EXPECT_THROW((void)set_pose_request({std::numeric_limits<double>::quiet_NaN(), 0, 0}), std::invalid_argument);
}

}  // namespace truth_test
}  // namespace playerkit::client
