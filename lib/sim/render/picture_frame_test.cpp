#include "sim/render/picture_frame.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace playerkit::sim::render {
namespace picture_frame_test {

TEST(PictureFrame, TheLongerSideGetsTheMaximumAndPixelsAreSquare) {
  const PictureFrame frame({-5.0, 1.0}, {10.0, 6.0}, 1500);  // 15 x 5 m
  EXPECT_DOUBLE_EQ(frame.pixels_per_metre(), 100.0);
  EXPECT_EQ(frame.width(), 1500);
  EXPECT_EQ(frame.height(), 500);
  // x to the right, y up: the bottom left corner is pixel (0, 500), the top right (1500, 0).
  EXPECT_TRUE(frame.to_pixel({-5.0, 1.0}).isApprox(Eigen::Vector2d(0.0, 500.0)));
  EXPECT_TRUE(frame.to_pixel({10.0, 6.0}).isApprox(Eigen::Vector2d(1500.0, 0.0)));
  EXPECT_TRUE(frame.to_pixel({0.0, 2.0}).isApprox(Eigen::Vector2d(500.0, 400.0)));
  EXPECT_TRUE(frame.to_world({500.0, 400.0}).isApprox(Eigen::Vector2d(0.0, 2.0)));
  EXPECT_EQ(frame.pixel_of({0.004, 2.0 - 0.004}), Eigen::Vector2i(500, 400));
  EXPECT_EQ(frame.pixel_of({-0.004, 2.004}), Eigen::Vector2i(499, 399));
  EXPECT_TRUE(frame.contains({1499, 499}));
  EXPECT_FALSE(frame.contains({1500, 0}));
  EXPECT_FALSE(frame.contains({0, -1}));
}

TEST(PictureFrame, AShortSideIsRoundedUpToWholePixels) {
  const PictureFrame frame({0.0, 0.0}, {2.0, 3.0}, 1000);
  EXPECT_EQ(frame.height(), 1000);
  EXPECT_EQ(frame.width(), 667);  // 2 m at 333.3 px/m
  EXPECT_GE(frame.high().x(), 2.0);
  EXPECT_DOUBLE_EQ(frame.high().y(), 3.0);
}

TEST(PictureFrame, DegenerateBoxesBecomeAMetre) {
  const PictureFrame point({2.0, 3.0}, {2.0, 3.0}, 100);
  EXPECT_EQ(point.width(), 100);
  EXPECT_EQ(point.height(), 100);
  EXPECT_TRUE(point.low().isApprox(Eigen::Vector2d(1.5, 2.5)));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PictureFrame nothing({nan, 0.0}, {1.0, 1.0}, 10);
  EXPECT_TRUE(nothing.low().isApprox(Eigen::Vector2d(-0.5, -0.5)));
  // Reversed corners are the same box.
  const PictureFrame reversed({10.0, 6.0}, {-5.0, 1.0}, 1500);
  EXPECT_EQ(reversed.width(), 1500);
  EXPECT_EQ(reversed.height(), 500);
  EXPECT_THROW(PictureFrame({0.0, 0.0}, {1.0, 1.0}, 0), std::invalid_argument);
}

TEST(PictureFrame, FarPointsDoNotOverflow) {
  const PictureFrame frame({0.0, 0.0}, {1.0, 1.0}, 100);
  const Eigen::Vector2i far = frame.pixel_of({1e300, -std::numeric_limits<double>::infinity()});
  EXPECT_FALSE(frame.contains(far));
  EXPECT_GT(far.x(), 0);
  EXPECT_GT(far.y(), 0);
}

}  // namespace picture_frame_test
}  // namespace playerkit::sim::render
