#include "emulators/mobile_base/differential_drive.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::emulators::mobile_base {
namespace differential_drive_test {

constexpr double kPi = std::numbers::pi;

const DriveGeometry kGeometry{.wheelbase = 0.4, .footprint_radius = 0.25, .max_speed = 1.0,
                              .max_turn_rate = 2.0};

TEST(DriveArc, StraightAndQuarterCircle) {
  const geometry::Pose2 straight = drive_arc({1.0, 1.0, kPi / 2}, 2.0, 0.0);
  EXPECT_NEAR(straight.x, 1.0, 1e-12);
  EXPECT_NEAR(straight.y, 3.0, 1e-12);
  // A quarter circle of radius 1 to the left, from the origin facing +x.
  const geometry::Pose2 quarter = drive_arc({}, kPi / 2, kPi / 2);
  EXPECT_NEAR(quarter.x, 1.0, 1e-12);
  EXPECT_NEAR(quarter.y, 1.0, 1e-12);
  EXPECT_NEAR(quarter.yaw, kPi / 2, 1e-12);
}

TEST(DifferentialDrive, ResultDoesNotDependOnTheStepSize) {
  DifferentialDrive coarse(kGeometry, {}, nullptr, {});
  DifferentialDrive fine(kGeometry, {}, nullptr, {});
  coarse.command(0.5, 0.7);
  fine.command(0.5, 0.7);
  coarse.run(3.0, 0.1);
  fine.run(3.0, 0.001);
  EXPECT_NEAR(coarse.true_pose().x, fine.true_pose().x, 1e-9);
  EXPECT_NEAR(coarse.true_pose().y, fine.true_pose().y, 1e-9);
  EXPECT_NEAR(coarse.true_pose().yaw, fine.true_pose().yaw, 1e-9);
}

TEST(DifferentialDrive, WheelsAndSetpointsAgree) {
  DifferentialDrive drive(kGeometry, {}, nullptr, {});
  drive.command_wheels({0.2, 0.4});
  EXPECT_NEAR(drive.commanded_speed(), 0.3, 1e-12);
  EXPECT_NEAR(drive.commanded_turn_rate(), 0.5, 1e-12);
  EXPECT_NEAR(drive.wheels().left, 0.2, 1e-12);
  EXPECT_NEAR(drive.wheels().right, 0.4, 1e-12);
}

TEST(DifferentialDrive, SetpointsAreClampedAndNonFiniteIsStop) {
  DifferentialDrive drive(kGeometry, {}, nullptr, {});
  drive.command(5.0, -9.0);
  EXPECT_EQ(drive.commanded_speed(), 1.0);
  EXPECT_EQ(drive.commanded_turn_rate(), -2.0);
  drive.command(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(drive.commanded_to_move());
}

TEST(DifferentialDrive, OdometryScalesAndDrift) {
  OdometryError error;
  error.translation_scale = -0.1;
  error.heading_drift_per_metre = 0.01;
  DifferentialDrive drive(kGeometry, error, nullptr, {2.0, 3.0, 1.0});
  drive.command(0.5, 0.0);
  drive.run(4.0, 0.01);
  EXPECT_NEAR(drive.true_pose().x, 2.0 + 2.0 * std::cos(1.0), 1e-9);
  EXPECT_NEAR(drive.odometry().yaw, 0.02, 1e-9);
  // A gentle left arc of 1.8 m measured length.
  const double radius = 1.8 / 0.02;
  EXPECT_NEAR(drive.odometry().x, radius * std::sin(0.02), 1e-9);
  drive.reset_odometry();
  EXPECT_EQ(drive.odometry(), geometry::Pose2{});
}

TEST(DifferentialDrive, ContactIsReportedOnceAndClearedOnTaking) {
  grid::OccupancyGrid map(20, 20, 0.1, {-1.0, -1.0}, grid::CellState::free);
  for (int row = 0; row < 20; ++row) map.set(15, row, grid::CellState::occupied);  // x in [0.5, 0.6)
  DifferentialDrive drive(kGeometry, {}, &map, {});
  drive.command(0.5, 0.0);
  drive.run(2.0, 0.01);
  EXPECT_NEAR(drive.true_pose().x, 0.25, 0.005);
  const Contact contact = drive.take_contact();
  EXPECT_TRUE(contact.stalled);
  EXPECT_NEAR(contact.bearing, 0.0, 1e-9);
  EXPECT_FALSE(drive.take_contact().stalled);
  EXPECT_EQ(drive.wheels(), (WheelVelocities{0.0, 0.0}));
}

}  // namespace differential_drive_test
}  // namespace playerkit::emulators::mobile_base
