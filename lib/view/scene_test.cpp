#include "view/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::view {
namespace scene_test {

using client::Pose2D;
using protocol::DeviceAddress;

constexpr DeviceAddress kLaser{protocol::kLaserCode, 0};
constexpr DeviceAddress kSonar{protocol::kSonarCode, 0};
constexpr DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr DeviceAddress kTruth{protocol::kTruthCode, 0};
constexpr DeviceAddress kLocalize{protocol::kLocalizeCode, 0};

template <typename T>
protocol::Message data(DeviceAddress device, const T& payload) {
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, device, {}, {});
  message.payload = protocol::encode(payload);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

protocol::Message odometry(std::int32_t x_mm, std::int32_t y_mm, std::int32_t yaw_deg) {
  protocol::PositionData position;
  position.xpos = x_mm;
  position.ypos = y_mm;
  position.yaw = yaw_deg;
  return data(kPosition, position);
}

protocol::Message truth(std::int32_t x_mm, std::int32_t y_mm, std::int32_t yaw_deg) {
  protocol::TruthData pose;
  pose.px = x_mm;
  pose.py = y_mm;
  pose.pa = yaw_deg;
  return data(kTruth, pose);
}

// Three beams at -90, 0 and +90 degrees, 1, 2 and 3 m; the middle one bright.
protocol::Message three_beam_scan() {
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 9000;
  scan.range_res = 1;
  scan.range_count = 3;
  scan.ranges[0] = 1000;
  scan.ranges[1] = 2000;
  scan.ranges[2] = 3000;
  scan.intensity[1] = 1;
  return data(kLaser, scan);
}

void expect_near(const Point& actual, double x, double y) {
  EXPECT_NEAR(actual.x, x, 1e-6);
  EXPECT_NEAR(actual.y, y, 1e-6);
}

TEST(Scene, AnEmptySceneDrawsTheRobotAtTheOrigin) {
  Scene scene;
  EXPECT_FALSE(scene.robot_pose());
  const Frame frame = scene.frame(0.0);
  ASSERT_EQ(frame.bodies.size(), 1u);
  EXPECT_EQ(frame.bodies[0].pose, Pose2D{});
  EXPECT_TRUE(frame.bodies[0].filled);
  EXPECT_DOUBLE_EQ(frame.bodies[0].length, kDefaultRobotLength);
}

TEST(Scene, LaserPointsHangOffTheRobotPose) {
  Scene scene;
  scene.apply(odometry(1000, 2000, 90), 0.0);
  scene.apply(three_beam_scan(), 0.0);
  const Frame frame = scene.frame(0.0);
  expect_near(frame.centre, 1.0, 2.0);
  // The robot faces +y: the beam at -90 degrees points to +x.
  ASSERT_EQ(frame.dots.size(), 2u);
  ASSERT_EQ(frame.dots[0].points.size(), 2u);
  expect_near(frame.dots[0].points[0], 2.0, 2.0);
  expect_near(frame.dots[0].points[1], -2.0, 2.0);
  EXPECT_EQ(frame.dots[0].colour, colours::kLaserPoint);
  ASSERT_EQ(frame.dots[1].points.size(), 1u);  // the bright return
  expect_near(frame.dots[1].points[0], 1.0, 4.0);
  EXPECT_EQ(frame.dots[1].colour, colours::kLaserBright);
  // The fan: the sensor, then every return.
  ASSERT_EQ(frame.areas.size(), 1u);
  ASSERT_EQ(frame.areas[0].points.size(), 4u);
  expect_near(frame.areas[0].points[0], 1.0, 2.0);
}

TEST(Scene, TheLaserPoseOnTheRobotMovesItsPoints) {
  Scene scene;
  scene.set_mount_pose(kLaser, {0.5, 0.0, 0.0});
  scene.apply(three_beam_scan(), 0.0);
  const Frame frame = scene.frame(0.0);
  expect_near(frame.dots[1].points[0], 2.5, 0.0);
}

TEST(Scene, TruthPlacesTheRobotAndIsDrawnAsAnOutline) {
  Scene scene;
  scene.apply(odometry(0, 0, 0), 0.0);
  scene.apply(truth(2000, 2000, 45), 0.0);
  ASSERT_TRUE(scene.robot_pose());
  EXPECT_NEAR(scene.robot_pose()->x, 2.0, 1e-9);
  const Frame frame = scene.frame(0.0);
  expect_near(frame.centre, 2.0, 2.0);
  ASSERT_EQ(frame.bodies.size(), 2u);
  EXPECT_FALSE(frame.bodies[0].filled);
  EXPECT_EQ(frame.bodies[0].colour, colours::kTruth);
  EXPECT_NEAR(frame.bodies[1].pose.yaw, std::numbers::pi / 4, 1e-9);
}

TEST(Scene, TheOdometryTrailEndsAtTheRobot) {
  Scene scene;
  scene.apply(odometry(0, 0, 0), 0.0);
  scene.apply(odometry(1000, 0, 0), 0.1);
  scene.apply(odometry(1000, 0, 0), 0.2);  // standing still adds no point
  scene.apply(truth(5000, 5000, 90), 0.2);
  const Frame frame = scene.frame(0.2);
  ASSERT_EQ(frame.lines.size(), 1u);
  const auto& points = frame.lines[0].points;
  ASSERT_EQ(points.size(), 3u);
  // Odometry drove 1 m along its x; drawn from the truth pose (facing +y)
  // the path came from 1 m below it.
  expect_near(points[0], 5.0, 4.0);
  expect_near(points[1], 5.0, 5.0);
  expect_near(points.back(), 5.0, 5.0);
}

TEST(Scene, SonarConesNeedTheTransducerPoses) {
  Scene scene;
  protocol::SonarData sonar;
  sonar.range_count = 2;
  sonar.ranges[0] = 1000;
  sonar.ranges[1] = 500;
  scene.apply(data(kSonar, sonar), 0.0);
  EXPECT_TRUE(scene.frame(0.0).areas.empty());
  scene.set_sensor_poses(kSonar, {{0.1, 0.0, 0.0}, {0.0, 0.1, std::numbers::pi / 2}});
  const Frame frame = scene.frame(0.0);
  ASSERT_EQ(frame.areas.size(), 2u);
  expect_near(frame.areas[0].points.front(), 0.1, 0.0);
  // The arc's middle point lies on the transducer's axis at its range.
  expect_near(frame.areas[0].points[4], 1.1, 0.0);
  expect_near(frame.areas[1].points[4], 0.0, 0.6);
  EXPECT_EQ(frame.areas[1].fill, colours::kSonarCone);
}

TEST(Scene, LocalizeHypothesesBecomeEllipsesAndTheBestPlacesTheRobot) {
  Scene scene;
  protocol::LocalizeData estimate;
  estimate.hypoth_count = 2;
  estimate.hypoths[0].mean = {1000, 0, 0};
  estimate.hypoths[0].cov[0][0] = 40000;  // (200 mm)^2
  estimate.hypoths[0].cov[1][1] = 10000;  // (100 mm)^2
  estimate.hypoths[0].alpha = 200000;
  estimate.hypoths[1].mean = {3000, 4000, 0};
  estimate.hypoths[1].alpha = 800000;
  scene.apply(data(kLocalize, estimate), 0.0);
  expect_near(scene.frame(0.0).centre, 3.0, 4.0);
  const Frame frame = scene.frame(0.0);
  ASSERT_EQ(frame.ellipses.size(), 2u);
  expect_near(frame.ellipses[0].centre, 1.0, 0.0);
  EXPECT_NEAR(frame.ellipses[0].semi_major, 0.4, 1e-9);  // two standard deviations
  EXPECT_NEAR(frame.ellipses[0].semi_minor, 0.2, 1e-9);
  EXPECT_NEAR(frame.ellipses[0].angle, 0.0, 1e-9);
  // A point estimate stays visible.
  EXPECT_DOUBLE_EQ(frame.ellipses[1].semi_major, SceneOptions{}.min_ellipse_axis);
}

TEST(Scene, FiducialsAreBoxesWithTheirIds) {
  Scene scene;
  constexpr DeviceAddress kFiducial{protocol::kFiducialCode, 0};
  scene.set_mount_pose(kFiducial, {0.1, 0.0, 0.0});
  protocol::FiducialData seen;
  seen.count = 2;
  seen.fiducials[0].id = 7;
  seen.fiducials[0].pose = {2000, 90, 0};  // 2 m at 90 degrees
  seen.fiducials[1].id = -1;
  seen.fiducials[1].pose = {1000, 0, 0};
  scene.apply(data(kFiducial, seen), 0.0);
  const Frame frame = scene.frame(0.0);
  ASSERT_EQ(frame.labels.size(), 2u);
  expect_near(frame.labels[0].at, 0.1, 2.0);
  EXPECT_EQ(frame.labels[0].text, "7");
  EXPECT_EQ(frame.labels[1].text, "?");
  expect_near(frame.labels[1].at, 1.1, 0.0);
  ASSERT_EQ(frame.bodies.size(), 3u);  // two fiducials, then the robot
  EXPECT_FALSE(frame.bodies[0].filled);
  EXPECT_EQ(frame.bodies[0].colour, colours::kFiducial);
  EXPECT_NEAR(frame.bodies[0].pose.yaw, std::numbers::pi / 2, 1e-9);
}

TEST(Scene, TheLegendListsEveryDeviceWithItsRate) {
  Scene scene;
  scene.add_device(kSonar);
  for (int i = 0; i < 6; ++i) scene.apply(three_beam_scan(), 0.2 * i);
  const Frame frame = scene.frame(1.0);
  ASSERT_EQ(frame.legend.size(), 2u);
  EXPECT_EQ(frame.legend[0].text, "sonar:0 0.0 Hz");
  EXPECT_EQ(frame.legend[1].text, "laser:0 5.0 Hz");
}

TEST(Scene, DataThatDoesNotDecodeIsCountedButNotDrawn) {
  Scene scene;
  protocol::Message broken = three_beam_scan();
  broken.payload.resize(3);
  EXPECT_TRUE(scene.apply(broken, 0.0));
  EXPECT_TRUE(scene.apply(broken, 0.5));
  const Frame frame = scene.frame(0.5);
  EXPECT_TRUE(frame.dots.empty());
  EXPECT_EQ(frame.legend[0].text, "laser:0 2.0 Hz");
}

TEST(Scene, ComposeAndInvertAreInverses) {
  const Pose2D a{1.0, -2.0, 0.7};
  const Pose2D identity = compose(a, invert(a));
  EXPECT_NEAR(identity.x, 0.0, 1e-12);
  EXPECT_NEAR(identity.y, 0.0, 1e-12);
  EXPECT_NEAR(identity.yaw, 0.0, 1e-12);
}

}  // namespace scene_test
}  // namespace playerkit::view
