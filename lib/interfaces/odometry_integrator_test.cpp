#include "interfaces/odometry_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::interfaces {
namespace odometry_integrator_test {

constexpr double kQuarterTurn = std::numbers::pi / 2;

TEST(WrappedCounterStep, IsTheShortestSignedDifferenceForAnyWidth) {
  EXPECT_EQ(wrapped_counter_step(110, 100, 12), 10);
  EXPECT_EQ(wrapped_counter_step(4, 4090, 12), 10);    // forward over the 12-bit wrap
  EXPECT_EQ(wrapped_counter_step(4090, 4, 12), -10);   // backward over it
  EXPECT_EQ(wrapped_counter_step(0x1005, 0x0FFB, 12), 10);  // bits above the counter ignored
  EXPECT_EQ(wrapped_counter_step(3, 65533, 16), 6);
  EXPECT_EQ(wrapped_counter_step(65533, 3, 16), -6);
  EXPECT_EQ(wrapped_counter_step(0x8000, 0, 16), -32768);  // half a turn is taken backwards
  EXPECT_EQ(wrapped_counter_step(5, 0xFFFFFFFE, 31), 7);
}

TEST(SignedCounterValue, TheUpperHalfCountsBackwardsFromTheWrap) {
  EXPECT_EQ(signed_counter_value(100, 12), 100);
  EXPECT_EQ(signed_counter_value(4095, 12), -1);
  EXPECT_EQ(signed_counter_value(2048, 12), -2048);
  EXPECT_EQ(signed_counter_value(0xFFFF, 16), -1);
  EXPECT_EQ(signed_counter_value(0x17FFF, 16), 32767);
}

TEST(WrappingCounter, AddsUpStepsAcrossManyWraps) {
  WrappingCounter ticks(16);
  EXPECT_EQ(ticks.update(65000), 0);  // the first reading is where counting starts
  long total = 0;
  std::uint32_t reading = 65000;
  for (int i = 0; i < 100; ++i) {
    reading = (reading + 3000) % 65536;
    total += ticks.update(reading);
  }
  EXPECT_EQ(total, 300000);
  ticks.forget();
  EXPECT_EQ(ticks.update(7), 0);
  EXPECT_EQ(ticks.update(2), -5);
}

TEST(OdometryIntegrator, StepsAndHeadingMakeTheRobotPose) {
  OdometryIntegrator odometry;
  odometry.step_position(10.0, -4.0);
  odometry.set_heading(3 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(odometry.robot().x, 10.0);
  EXPECT_DOUBLE_EQ(odometry.robot().y, -4.0);
  EXPECT_NEAR(odometry.robot().yaw, std::numbers::pi, 1e-12);
  EXPECT_EQ(odometry.reported(), odometry.robot());
}

TEST(OdometryIntegrator, DriveFollowsTheChordOfTheArc) {
  OdometryIntegrator odometry;
  odometry.drive(1.0, kQuarterTurn);
  EXPECT_NEAR(odometry.robot().x, std::cos(kQuarterTurn / 2), 1e-12);
  EXPECT_NEAR(odometry.robot().y, std::sin(kQuarterTurn / 2), 1e-12);
  EXPECT_NEAR(odometry.robot().yaw, kQuarterTurn, 1e-12);
  for (int i = 0; i < 3; ++i) odometry.drive(1.0, kQuarterTurn);  // round a square back to the start
  EXPECT_NEAR(odometry.robot().x, 0.0, 1e-12);
  EXPECT_NEAR(odometry.robot().y, 0.0, 1e-12);
  EXPECT_NEAR(odometry.robot().yaw, 0.0, 1e-12);
}

TEST(OdometryIntegrator, SetReportedRotatesLaterMotion) {
  OdometryIntegrator odometry;
  odometry.step_position(100.0, 100.0);
  odometry.set_reported({1000.0, 2000.0, kQuarterTurn});
  EXPECT_NEAR(odometry.reported().x, 1000.0, 1e-9);
  EXPECT_NEAR(odometry.reported().y, 2000.0, 1e-9);
  EXPECT_NEAR(odometry.reported().yaw, kQuarterTurn, 1e-12);
  odometry.step_position(200.0, 0.0);  // along the robot's x: the reported +y
  EXPECT_NEAR(odometry.reported().x, 1000.0, 1e-9);
  EXPECT_NEAR(odometry.reported().y, 2200.0, 1e-9);
}

TEST(OdometryIntegrator, ResetReportedIsZeroUntilTheRobotMoves) {
  OdometryIntegrator odometry;
  odometry.step_position(5.0, 7.0);
  odometry.set_heading(1.0);
  odometry.reset_reported();
  EXPECT_NEAR(odometry.reported().x, 0.0, 1e-12);
  EXPECT_NEAR(odometry.reported().y, 0.0, 1e-12);
  EXPECT_NEAR(odometry.reported().yaw, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(odometry.robot().x, 5.0);  // the counters are not the reported pose
}

TEST(OdometryIntegrator, RestartedCountersKeepTheReportedPose) {
  OdometryIntegrator odometry;
  odometry.step_position(300.0, 0.0);
  odometry.set_heading(kQuarterTurn);
  const geometry::Pose2 before = odometry.reported();
  odometry.restart_counters({});  // reconnected: the counters read zero
  EXPECT_NEAR(odometry.reported().x, before.x, 1e-9);
  EXPECT_NEAR(odometry.reported().y, before.y, 1e-9);
  EXPECT_NEAR(odometry.reported().yaw, before.yaw, 1e-12);
  odometry.step_position(50.0, 0.0);  // forward in the new frame = along the old heading
  EXPECT_NEAR(odometry.reported().x, 300.0, 1e-9);
  EXPECT_NEAR(odometry.reported().y, 50.0, 1e-9);
}

TEST(OdometryIntegrator, ZeroedCountersStartFromTheLastReportedPose) {
  OdometryIntegrator odometry;
  odometry.step_position(40.0, 0.0);
  odometry.counters_zeroed({10.0, 0.0, 0.0});  // zeroed at x = 40, then moved 10
  EXPECT_NEAR(odometry.reported().x, 50.0, 1e-9);
  EXPECT_DOUBLE_EQ(odometry.robot().x, 10.0);
}

}  // namespace odometry_integrator_test
}  // namespace playerkit::interfaces
