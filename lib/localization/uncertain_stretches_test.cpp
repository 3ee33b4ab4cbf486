#include "localization/uncertain_stretches.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

namespace playerkit::localization {
namespace uncertain_stretches_test {

Eigen::Matrix3d spread(double sx, double sy, double syaw) { return Eigen::Vector3d(sx * sx, sy * sy, syaw * syaw).asDiagonal(); }

TEST(UncertainStretches, TheEllipsesLongAxisCountsNotTheAxesOfTheMap) {
  Eigen::Matrix3d along_the_diagonal = Eigen::Matrix3d::Zero();
  along_the_diagonal.topLeftCorner<2, 2>() << 0.5, 0.49, 0.49, 0.5;  // 0.99 m^2 along (1,1)
  EXPECT_NEAR(position_2sigma(along_the_diagonal), 2.0 * std::sqrt(0.99), 1e-12);
  EXPECT_NEAR(heading_2sigma(spread(0.1, 0.1, 0.05)), 0.1, 1e-12);
}

TEST(UncertainStretches, EachUnsureStretchIsReportedOnceWithItsWorst) {
  UncertaintyWatch watch;  // 1 m, 60 degrees
  const double degree = std::numbers::pi / 180.0;
  EXPECT_FALSE(watch.observe(0.0, spread(0.45, 0.1, 25 * degree)));  // 0.9 m, 50 degrees: sure enough
  EXPECT_FALSE(watch.observe(1.0, spread(0.6, 0.1, 2 * degree)));   // 1.2 m: lost
  EXPECT_FALSE(watch.observe(2.0, spread(0.1, 0.1, 35 * degree)));  // 70 degrees: lost
  const auto ended = watch.observe(3.0, spread(0.1, 0.1, 2 * degree));
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->start_time, 1.0);
  EXPECT_EQ(ended->end_time, 2.0);
  EXPECT_EQ(ended->rows, 2u);
  EXPECT_NEAR(ended->worst_position_2sigma_m, 1.2, 1e-12);
  EXPECT_NEAR(ended->worst_heading_2sigma_rad, 70 * degree, 1e-12);
  EXPECT_FALSE(watch.observe(4.0, spread(0.1, 0.1, 2 * degree)));
  EXPECT_FALSE(watch.finish());
}

TEST(UncertainStretches, AStretchOpenAtTheEndAndANanCovarianceAreUnsure) {
  UncertaintyWatch watch;
  Eigen::Matrix3d broken = Eigen::Matrix3d::Identity();
  broken(2, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(watch.observe(5.0, broken));
  const auto last = watch.finish();
  ASSERT_TRUE(last);
  EXPECT_EQ(last->rows, 1u);
  EXPECT_FALSE(watch.finish());
}

}  // namespace uncertain_stretches_test
}  // namespace playerkit::localization
