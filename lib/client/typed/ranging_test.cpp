#include "client/typed/ranging.hpp"

#include <gtest/gtest.h>

namespace playerkit::client {
namespace ranging_test {

TEST(TypedRanging, SonarRangesAndPoses) {
  protocol::SonarData d;
  d.range_count = 3;
  d.ranges[0] = 0;
  d.ranges[1] = 5000;
  d.ranges[2] = 123;
  d.ranges[3] = 777;  // beyond range_count
  EXPECT_EQ(to_si(d).ranges, (std::vector<double>{0.0, 5.0, 0.123}));

  protocol::SonarGeom g;
  g.pose_count = 2;
  g.poses[0] = {100, 0, 0};
  g.poses[1] = {-100, 50, 180};
  const SensorPoses p = to_si(g);
  ASSERT_EQ(p.poses.size(), 2u);
  EXPECT_EQ(p.poses[0], (Pose2D{0.1, 0.0, 0.0}));
  EXPECT_DOUBLE_EQ(p.poses[1].x, -0.1);
  EXPECT_DOUBLE_EQ(p.poses[1].y, 0.05);
  EXPECT_DOUBLE_EQ(p.poses[1].yaw, 3.141592653589793);
}

TEST(TypedRanging, IrRangesKeepRawVoltages) {
  protocol::IrData d;
  d.range_count = 2;
  d.voltages[0] = 512;
  d.voltages[1] = 1023;
  d.ranges[0] = 150;
  d.ranges[1] = 800;
  const IrScan s = to_si(d);
  EXPECT_EQ(s.ranges, (std::vector<double>{0.15, 0.8}));
  EXPECT_EQ(s.voltages, (std::vector<std::uint16_t>{512, 1023}));

  protocol::IrPoseRequest reply;
  reply.subtype = protocol::kIrPoseReq;
  reply.poses.pose_count = 1;
  reply.poses.poses[0] = {10, 20, -90};
  const SensorPoses p = to_si(reply);
  ASSERT_EQ(p.poses.size(), 1u);
  EXPECT_DOUBLE_EQ(p.poses[0].x, 0.01);
  EXPECT_DOUBLE_EQ(p.poses[0].y, 0.02);
  EXPECT_DOUBLE_EQ(p.poses[0].yaw, -1.5707963267948966);
}

TEST(TypedRanging, CountsBeyondTheArrayAreCut) {
  protocol::SonarData d;
  d.range_count = 1000;  // a hand-built value; the decoder refuses such counts
  EXPECT_EQ(to_si(d).ranges.size(), protocol::kSonarMaxSamples);
}

}  // namespace ranging_test
}  // namespace playerkit::client
