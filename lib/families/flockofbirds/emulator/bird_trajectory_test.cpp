#include "families/flockofbirds/emulator/bird_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace playerkit::emulators {
namespace bird_trajectory_test {

using namespace std::chrono_literals;
namespace fob = hardware::flockofbirds;

TEST(BirdTrajectory, ReadsCommentsAndBlankLines) {
  const auto trajectory = BirdTrajectory::parse("# t x y z az el roll\n\n0 1 2 3 4 5 6  # first\n2.5 1 2 3 4 5 6\n", true);
  EXPECT_TRUE(trajectory.scripted());
  EXPECT_EQ(trajectory.size(), 2u);
  EXPECT_DOUBLE_EQ(trajectory.duration_seconds(), 2.5);
  EXPECT_DOUBLE_EQ(trajectory.at(1s).z_mm, 3);
}

TEST(BirdTrajectory, LoopsWhenAskedAndHoldsOtherwise) {
  const std::string text = "10 0 0 0 0 0 0\n12 200 0 0 0 0 0\n";
  EXPECT_NEAR(BirdTrajectory::parse(text, true).at(3s).x_mm, 100, 1e-9);  // 3 s = 1 s into the second round
  EXPECT_NEAR(BirdTrajectory::parse(text, false).at(3s).x_mm, 200, 1e-9);
  EXPECT_NEAR(BirdTrajectory::parse(text, true).at(500ms).x_mm, 50, 1e-9);
}

TEST(BirdTrajectory, RefusesBadLinesNamingThem) {
  const auto refusal = [](const std::string& text) {
    try {
      (void)BirdTrajectory::parse(text, true);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(refusal("0 1 2 3 4 5\n"), "trajectory line 1: expected 7 numbers (t x y z azimuth elevation roll)");
  EXPECT_EQ(refusal("0 1 2 3 4 5 6\n0 1 2 3 4 5 6\n"), "trajectory line 2: the time must increase");
  EXPECT_EQ(refusal("0 1 2 x 4 5 6\n"), "trajectory line 1: 'x' is not a number");
  EXPECT_EQ(refusal("# nothing\n"), "trajectory: no pose in it");
}

TEST(BirdTrajectory, TheBuiltInMotionStaysInFrontOfTheTransmitter) {
  const BirdTrajectory motion;
  EXPECT_FALSE(motion.scripted());
  for (int ms = 0; ms < 40000; ms += 250) {
    const fob::BirdPose pose = motion.at(std::chrono::milliseconds(ms));
    EXPECT_GE(pose.x_mm, 199.9);
    EXPECT_LE(pose.x_mm, 400.1);
    EXPECT_LE(std::fabs(pose.y_mm), 150.1);
    EXPECT_LE(std::fabs(pose.azimuth_deg), 90.1);
  }
  EXPECT_NE(motion.at(0s), motion.at(1s));
}

}  // namespace bird_trajectory_test
}  // namespace playerkit::emulators
