#include "client/typed/localize.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"

namespace playerkit::client {
namespace localize_test {

TEST(TypedLocalize, HypothesesGolden) {
  protocol::LocalizeData d;
  d.pending_count = 2;
  d.pending_time_sec = 5;
  d.pending_time_usec = 250000;
  d.hypoth_count = 1;
  d.hypoths[0].mean = {1000, -500, 324000};  // 90 degrees in arc-seconds
  // 1 m^2, 0.25 m^2, 1 mm*degree (3600 mm*arcsec), (10 degrees)^2 in arcsec^2
  d.hypoths[0].cov = {{{1000000, 0, 3600}, {0, 250000, 0}, {3600, 0, 1296000000}}};
  d.hypoths[0].alpha = 750000;
  // Through the wire, so the int64 covariance takes its real path.
  const LocalizeEstimate e = to_si(protocol::decode<protocol::LocalizeData>(protocol::encode(d)));
  EXPECT_EQ(e.pending_count, 2);
  EXPECT_DOUBLE_EQ(e.pending_time, 5.25);
  ASSERT_EQ(e.hypotheses.size(), 1u);
  const auto& h = e.hypotheses[0];
  EXPECT_DOUBLE_EQ(h.mean.x, 1.0);
  EXPECT_DOUBLE_EQ(h.mean.y, -0.5);
  EXPECT_DOUBLE_EQ(h.mean.yaw, 1.5707963267948966);
  EXPECT_DOUBLE_EQ(h.covariance[0][0], 1.0);
  EXPECT_DOUBLE_EQ(h.covariance[1][1], 0.25);
  EXPECT_DOUBLE_EQ(h.covariance[0][2], 1.7453292519943296e-05);
  EXPECT_DOUBLE_EQ(h.covariance[2][0], 1.7453292519943296e-05);
  EXPECT_DOUBLE_EQ(h.covariance[2][2], 0.030461741978670857);
  EXPECT_DOUBLE_EQ(h.covariance[0][1], 0.0);
  EXPECT_DOUBLE_EQ(h.weight, 0.75);
}

TEST(TypedLocalize, SetPoseRoundTrips) {
  const Pose2D mean{2.5, -1.25, -3.141592653589793};
  const Covariance3 cov{{{0.25, 0.0, 0.001}, {0.0, 0.25, 0.0}, {0.001, 0.0, 0.0685}}};
  const protocol::LocalizeSetPose w = set_pose_request(mean, cov);
  EXPECT_EQ(w.subtype, protocol::kLocalizeSetPoseReq);
  EXPECT_EQ(w.mean, (std::array<std::int32_t, 3>{2500, -1250, -648000}));
  EXPECT_EQ(w.cov[0][0], 250000);
  EXPECT_EQ(w.cov[0][2], 206265);  // 0.001 m*rad = 1 mm * 206264.8 arcsec
  EXPECT_EQ(w.cov[2][2], 2914344165);  // 0.0685 rad^2 in arcsec^2, beyond int32: int64 holds it

  protocol::LocalizeData d;
  d.hypoth_count = 1;
  d.hypoths[0].mean = w.mean;
  d.hypoths[0].cov = w.cov;
  const auto back = to_si(d).hypotheses.at(0);
  EXPECT_NEAR(back.mean.x, mean.x, 0.0005);
  EXPECT_NEAR(back.mean.yaw, mean.yaw, 4.9e-6 / 2);
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(back.covariance[r][c], cov[r][c], 1e-9) << r << c;
  }
}

TEST(TypedLocalize, SetPoseRefusesNonFinite) {
  Covariance3 cov{};
  cov[1][1] = std::numeric_limits<double>::infinity();
  try {
    (void)set_pose_request({}, cov);
    FAIL() << "infinity accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("covariance[1][1]"), std::string::npos) << e.what();
  }
}

}  // namespace localize_test
}  // namespace playerkit::client
