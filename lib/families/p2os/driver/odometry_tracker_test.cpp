#include "families/p2os/driver/odometry_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::drivers::p2os {
namespace odometry_tracker_test {

namespace hw = hardware::p2os;

const hw::RobotParams& p3dx() { return *hw::find_robot_params("Pioneer", "p3dx"); }  // 0.485 mm per unit

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(WrappedStep, IsTheShortestSignedDifferenceOf12BitCounters) {
  EXPECT_EQ(wrapped_step(110, 100), 10);
  EXPECT_EQ(wrapped_step(100, 110), -10);
  EXPECT_EQ(wrapped_step(4, 4090), 10);    // forward over the wrap
  EXPECT_EQ(wrapped_step(4090, 4), -10);   // backward over it
  EXPECT_EQ(wrapped_step(0x1005, 0x0FFB), 10);  // upper bits are not part of the counter
}

TEST(OdometryTracker, TheFirstSipIsTheOriginWithTheRobotsOwnHeading) {
  OdometryTracker odometry(p3dx());
  EXPECT_FALSE(odometry.ready());
  odometry.update(1234, 567, 1024);  // 1024 units = 90 degrees
  ASSERT_TRUE(odometry.ready());
  EXPECT_DOUBLE_EQ(odometry.pose().x, 0.0);
  EXPECT_DOUBLE_EQ(odometry.pose().y, 0.0);
  EXPECT_NEAR(odometry.pose().yaw, 1024 * 0.001534, 1e-9);
}

TEST(OdometryTracker, StepsAddUpAcrossThe12BitWrap) {
  OdometryTracker odometry(p3dx());
  odometry.update(3900, 0, 0);
  // 40 SIPs of +50 units: 2000 units, crossing 4096 once.
  std::uint16_t x = 3900;
  for (int i = 0; i < 40; ++i) {
    x = static_cast<std::uint16_t>((x + 50) % 4096);
    odometry.update(x, 0, 0);
  }
  EXPECT_NEAR(odometry.pose().x, 2000 * 0.485, 1e-6);
  // And back again, further than one wrap.
  for (int i = 0; i < 120; ++i) {
    x = static_cast<std::uint16_t>((x + 4096 - 50) % 4096);
    odometry.update(x, 0, 0);
  }
  EXPECT_NEAR(odometry.pose().x, -4000 * 0.485, 1e-6);
}

TEST(OdometryTracker, AcceptsStepsOverTheReferences100Millimetres) {
  // 400 units = 194 mm in one SIP: a robot at 1.9 m/s. 1.5 dropped it.
  OdometryTracker odometry(p3dx());
  odometry.update(0, 0, 0);
  odometry.update(400, 0, 0);
  EXPECT_NEAR(odometry.pose().x, 194.0, 1e-6);
}

TEST(OdometryTracker, SetPoseTakesTheWholeHeadingAndRotatesLaterMotion) {
  OdometryTracker odometry(p3dx());
  odometry.update(100, 100, 0);
  odometry.set_pose({1000.0, 2000.0, 90 * kDegree});
  EXPECT_NEAR(odometry.pose().x, 1000.0, 1e-9);
  EXPECT_NEAR(odometry.pose().y, 2000.0, 1e-9);
  EXPECT_NEAR(odometry.pose().yaw, 90 * kDegree, 1e-9);
  // The robot drives 200 units along its own x: seen through SET_ODOM that
  // is along +y.
  odometry.update(300, 100, 0);
  EXPECT_NEAR(odometry.pose().x, 1000.0, 1e-6);
  EXPECT_NEAR(odometry.pose().y, 2000.0 + 200 * 0.485, 1e-6);
  EXPECT_NEAR(odometry.pose().yaw, 90 * kDegree, 1e-9);
}

TEST(OdometryTracker, NegativeHeadingsAreNotTheReferencesUpper16Bits) {
  OdometryTracker odometry(p3dx());
  odometry.update(0, 0, 0);
  odometry.set_pose({0.0, 0.0, -30 * kDegree});
  EXPECT_NEAR(odometry.pose().yaw, -30 * kDegree, 1e-9);
}

TEST(OdometryTracker, ResetIsZeroAtOnceAndContinuousThroughTheRobotsJump) {
  OdometryTracker odometry(p3dx());
  odometry.update(2000, 1000, 512);
  odometry.update(2100, 1000, 512);  // moving along x
  odometry.robot_reset_sent();
  EXPECT_NEAR(odometry.pose().x, 0.0, 1e-9);
  EXPECT_NEAR(odometry.pose().y, 0.0, 1e-9);
  EXPECT_NEAR(odometry.pose().yaw, 0.0, 1e-9);
  // A SIP the robot sent before it obeyed: still its old counters.
  odometry.update(2200, 1000, 512);
  const double before_jump = odometry.pose().x;
  EXPECT_NEAR(std::hypot(odometry.pose().x, odometry.pose().y), 100 * 0.485, 1e-6);
  // Then the counters restart from zero and the robot keeps going.
  odometry.update(100, 0, 0);
  EXPECT_NEAR(odometry.pose().x, before_jump + 100 * 0.485, 1e-6);
  odometry.update(200, 0, 0);
  EXPECT_NEAR(odometry.pose().x, before_jump + 200 * 0.485, 1e-6);
}

TEST(OdometryTracker, AResetTheRobotIgnoresCausesNoJump) {
  OdometryTracker odometry(p3dx());
  odometry.update(3000, 3000, 100);
  odometry.robot_reset_sent();
  for (int i = 0; i < 10; ++i) odometry.update(3000, 3000, 100);  // standing, counters unchanged
  EXPECT_NEAR(odometry.pose().x, 0.0, 1e-9);
  EXPECT_NEAR(odometry.pose().y, 0.0, 1e-9);
  EXPECT_NEAR(odometry.pose().yaw, 0.0, 1e-9);
}

TEST(OdometryTracker, AResetBeforeTheFirstSipCountsFromWhereTheRobotObeyedIt) {
  OdometryTracker odometry(p3dx());
  odometry.robot_reset_sent();
  odometry.update(20, 0, 0);  // the robot obeyed, then drove 20 units
  EXPECT_NEAR(odometry.pose().x, 20 * 0.485, 1e-6);
  EXPECT_NEAR(odometry.pose().yaw, 0.0, 1e-9);
}

TEST(OdometryTracker, AResetBeforeTheFirstSipIsContinuousWhenTheFirstSipPrecedesIt) {
  OdometryTracker odometry(p3dx());
  odometry.robot_reset_sent();
  odometry.update(500, 500, 300);  // sent before the robot obeyed
  const geometry::Pose2 first = odometry.pose();
  odometry.update(10, 0, 0);  // obeyed, then drove 10 units
  EXPECT_NEAR(odometry.pose().x, first.x + 10 * 0.485 * std::cos(first.yaw), 1e-6);
  EXPECT_NEAR(odometry.pose().y, first.y + 10 * 0.485 * std::sin(first.yaw), 1e-6);
  EXPECT_NEAR(odometry.pose().yaw, first.yaw, 1e-9);
}

TEST(OdometryTracker, ANewSessionContinuesWhereTheLastOneStood) {
  OdometryTracker odometry(p3dx());
  odometry.update(0, 0, 0);
  odometry.update(1000, 0, 1024);
  const geometry::Pose2 before = odometry.pose();
  odometry.start_session(p3dx());
  odometry.update(0, 0, 0);  // OPEN zeroed the robot's counters
  EXPECT_NEAR(odometry.pose().x, before.x, 1e-9);
  EXPECT_NEAR(odometry.pose().y, before.y, 1e-9);
  EXPECT_NEAR(odometry.pose().yaw, before.yaw, 1e-9);
  odometry.update(100, 0, 0);  // forward in the robot's new frame = along the old heading
  EXPECT_NEAR(odometry.pose().x, before.x + 100 * 0.485 * std::cos(before.yaw), 1e-6);
  EXPECT_NEAR(odometry.pose().y, before.y + 100 * 0.485 * std::sin(before.yaw), 1e-6);
}

TEST(OdometryTracker, Pioneer1HeadingsHave1024UnitsPerTurn) {
  OdometryTracker odometry(*hw::find_robot_params("Pioneer", "pion1m"));
  odometry.update(0, 0, 256);
  EXPECT_NEAR(odometry.pose().yaw, 256 * 0.006136, 1e-9);  // about 90 degrees
}

}  // namespace odometry_tracker_test
}  // namespace playerkit::drivers::p2os
