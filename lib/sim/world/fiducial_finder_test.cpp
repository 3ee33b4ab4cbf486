#include "sim/world/fiducial_finder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/world/sensor_test_support.hpp"

namespace playerkit::sim::fiducial_finder_test {

using namespace sensor_test_support;
using geometry::Pose2;
constexpr double kPi = std::numbers::pi;

Returns fiducial(int id, int key = 0) { return {.fiducial_id = id, .fiducial_key = key}; }

// The finder rides on a robot at (-4, 0) facing 0.2 rad left of +x.
// Targets (the room's x runs from -4.95 to 4.95):
//   A  id 3 at (-2, 1)         in view, 2.24 m
//   G  id 9 at (0, -1.5)       no body, in view, 4.27 m
//   B  id 4 at (2, 0.5)        in view, 6.02 m: beyond range_max_id
//   C  id 5 at (-4.5, 2)       behind the finder's side (bearing 92.5°)
//   D  id 6 at (0, -2.8)       behind a wall
//   E  id 7 key 2 at (-3, 1.5) another key
//   F  id 8 at (-1, 3.5)       behind a box rangers see through
//   H  id 10 at (4.3, -1.5)    8.43 m: beyond range_max
// plus a box with no fiducial id, and fiducials on the finder's own robot.
struct Room {
  Scene scene;
  ModelId robot = kNoModel, a = kNoModel, g = kNoModel, b = kNoModel, c = kNoModel, d = kNoModel, e = kNoModel,
          f = kNoModel, h = kNoModel;
  const Pose2 finder{-4.0, 0.0, 0.2};

  Room() : scene(make_map()) {
    robot = add_model(scene, {-4.0, 0.0, 0.2}, disc(0.4), fiducial(11));
    add_model(scene, {-4.05, 0.0, 0.2}, box(0.1, 0.1), fiducial(12), {}, robot);
    a = add_model(scene, {-2.0, 1.0, 1.0}, box(0.3, 0.3), fiducial(3));
    g = add_model(scene, {0.0, -1.5, -3.0}, no_body(), fiducial(9));
    b = add_model(scene, {2.0, 0.5, -2.5}, box(0.3, 0.3), fiducial(4));
    c = add_model(scene, {-4.5, 2.0, 0.0}, box(0.3, 0.3), fiducial(5));
    d = add_model(scene, {0.0, -2.8, 0.0}, box(0.3, 0.3), fiducial(6));
    e = add_model(scene, {-3.0, 1.5, 0.5}, box(0.2, 0.2), fiducial(7, 2));
    f = add_model(scene, {-1.0, 3.5, 0.0}, box(0.3, 0.3), fiducial(8));
    add_model(scene, {-2.5, 1.75, 0.0}, box(0.4, 0.4), {.obstacle = false, .ranger = -1.0});
    h = add_model(scene, {4.3, -1.5, 0.0}, box(0.3, 0.3), fiducial(10));
    add_model(scene, {-2.0, -2.0, 0.0}, box(0.4, 0.4));
  }

  static grid::OccupancyGrid make_map() {
    grid::OccupancyGrid map = room();
    add_wall(map, -1.0, -3.0, -0.8, -1.5);
    return map;
  }

  // What the geometry says the finder reads of a target at (x, y) heading yaw.
  FiducialSighting expected(int id, double x, double y, double yaw, ModelId model) const {
    const double dx = x - finder.x, dy = y - finder.y;
    return {id, std::hypot(dx, dy), geometry::normalize_angle(std::atan2(dy, dx) - finder.yaw),
            geometry::normalize_angle(yaw - finder.yaw), model};
  }
};

void expect_sightings(const FiducialScan& scan, const std::vector<FiducialSighting>& expected) {
  ASSERT_EQ(scan.sightings.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(scan.sightings[i].model, expected[i].model);
    EXPECT_EQ(scan.sightings[i].id, expected[i].id);
    EXPECT_NEAR(scan.sightings[i].range, expected[i].range, 1e-12);
    EXPECT_NEAR(scan.sightings[i].bearing, expected[i].bearing, 1e-12);
    EXPECT_NEAR(scan.sightings[i].orientation, expected[i].orientation, 1e-12);
  }
}

TEST(FiducialFinder, SeesTargetsInRangeAndViewNearestFirstWithIdsWithinRangeMaxId) {
  const Room room;
  const FiducialSpec spec{.range_max = 8.0, .range_max_id = 5.0, .fov = kPi};
  const FiducialScan scan = find_fiducials(room.scene, spec, room.finder, room.robot);
  expect_sightings(scan, {room.expected(3, -2.0, 1.0, 1.0, room.a),
                          // -3.0 - 0.2 wraps to 2pi - 3.2
                          room.expected(9, 0.0, -1.5, -3.0, room.g),
                          room.expected(0, 2.0, 0.5, -2.5, room.b)});
  EXPECT_NEAR(scan.sightings[1].orientation, 2.0 * kPi - 3.2, 1e-12);
  EXPECT_EQ(scan.time, 0.0);
}

TEST(FiducialFinder, TargetsBeyondRangeMaxAppearWhenTheRangeGrows) {
  const Room room;
  const FiducialScan scan =
      find_fiducials(room.scene, {.range_max = 9.0, .range_max_id = 7.0, .fov = kPi}, room.finder, room.robot);
  expect_sightings(scan, {room.expected(3, -2.0, 1.0, 1.0, room.a), room.expected(9, 0.0, -1.5, -3.0, room.g),
                          room.expected(4, 2.0, 0.5, -2.5, room.b), room.expected(0, 4.3, -1.5, 0.0, room.h)});
}

TEST(FiducialFinder, OnlyTheFinderKeySeesTargetsOfThatKey) {
  const Room room;
  const FiducialScan scan =
      find_fiducials(room.scene, {.range_max = 8.0, .fov = kPi, .key = 2}, room.finder, room.robot);
  expect_sightings(scan, {room.expected(7, -3.0, 1.5, 0.5, room.e)});
}

TEST(FiducialFinder, ANarrowFieldOfViewKeepsOnlyWhatIsInIt) {
  const Room room;
  // ±0.2 rad: A is 0.26 rad left, G 0.56 right; B is 0.117 right.
  const FiducialScan scan = find_fiducials(room.scene, {.range_max = 8.0, .fov = 0.4}, room.finder, room.robot);
  expect_sightings(scan, {room.expected(0, 2.0, 0.5, -2.5, room.b)});
}

TEST(FiducialFinder, WideningTheViewAddsTheTargetBehindTheFinderSide) {
  const Room room;
  const FiducialScan scan = find_fiducials(room.scene, {.range_max = 8.0, .fov = 2.0 * kPi}, room.finder, room.robot);
  // C, 2.06 m away at a bearing of 1.61 rad, now the nearest.
  expect_sightings(scan, {room.expected(5, -4.5, 2.0, 0.0, room.c), room.expected(3, -2.0, 1.0, 1.0, room.a),
                          room.expected(9, 0.0, -1.5, -3.0, room.g), room.expected(0, 2.0, 0.5, -2.5, room.b)});
}

TEST(FiducialFinder, RangeMinDropsNearTargets) {
  const Room room;
  const FiducialScan scan =
      find_fiducials(room.scene, {.range_min = 2.3, .range_max = 8.0, .fov = kPi}, room.finder, room.robot);
  ASSERT_EQ(scan.sightings.size(), 2u);
  EXPECT_EQ(scan.sightings[0].model, room.g);
  EXPECT_EQ(scan.sightings[1].model, room.b);
}

TEST(FiducialFinder, WallsAndOtherBodiesHideTargetsThatAreOtherwiseSeen) {
  const Room room;
  // A finder beside each hidden target sees it: only what stood in between hid it.
  const FiducialSpec spec{.range_max = 8.0, .fov = 2.0 * kPi};
  const FiducialScan near_d = find_fiducials(room.scene, spec, {0.0, -2.2, 0.0}, room.robot);
  const FiducialScan near_f = find_fiducials(room.scene, spec, {-1.0, 3.0, 0.0}, room.robot);
  const auto sees = [](const FiducialScan& scan, ModelId model) {
    for (const auto& s : scan.sightings) {
      if (s.model == model) return true;
    }
    return false;
  };
  EXPECT_TRUE(sees(near_d, room.d));
  EXPECT_TRUE(sees(near_f, room.f));
  const FiducialScan from_robot = find_fiducials(room.scene, spec, room.finder, room.robot);
  EXPECT_FALSE(sees(from_robot, room.d));
  EXPECT_FALSE(sees(from_robot, room.f));
  // Nor does the finder ever report its own robot's fiducials.
  for (const auto& s : from_robot.sightings) EXPECT_NE(s.model, room.robot);
  for (const auto& s : from_robot.sightings) EXPECT_NE(s.model, room.robot + 1);
}

TEST(FiducialFinder, ARobotsOwnFiducialsAreSeenByOtherRobots) {
  const Room room;
  // A finder on the target A (its own robot) looking back at the first robot.
  const FiducialScan scan =
      find_fiducials(room.scene, {.range_max = 8.0, .fov = 2.0 * kPi}, {-2.0, 1.0, 0.0}, room.a);
  bool robot_seen = false, its_box_seen = false;
  for (const auto& s : scan.sightings) {
    robot_seen = robot_seen || (s.model == room.robot && s.id == 11);
    its_box_seen = its_box_seen || s.model == room.robot + 1;
  }
  EXPECT_TRUE(robot_seen);
  // The box sits inside the robot's disc, so the disc hides it.
  EXPECT_FALSE(its_box_seen);
}

TEST(FiducialFinder, ModelsThatAreNoLongerPresentAreNotSeen) {
  Room room;
  room.scene.set_present(room.a, false);  // picked up by a gripper that consumes
  const FiducialScan scan = find_fiducials(room.scene, {.range_max = 8.0, .fov = kPi}, room.finder, room.robot);
  expect_sightings(scan, {room.expected(9, 0.0, -1.5, -3.0, room.g), room.expected(0, 2.0, 0.5, -2.5, room.b)});
}

TEST(FiducialFinder, RangeAndBearingAreToTheBodyCentre) {
  Scene scene(room());
  const ModelId robot = add_model(scene, {}, disc(0.3));
  Body offset_box = box(0.2, 0.2);
  offset_box.offset = {0.5, 0.0, 0.0};
  // The model at (2, 1) facing +y: its body centre is at (2, 1.5).
  const ModelId target = add_model(scene, {2.0, 1.0, kPi / 2.0}, offset_box, fiducial(1));
  const FiducialScan scan = find_fiducials(scene, {.fov = kPi}, {}, robot);
  ASSERT_EQ(scan.sightings.size(), 1u);
  EXPECT_EQ(scan.sightings[0].model, target);
  EXPECT_NEAR(scan.sightings[0].range, std::hypot(2.0, 1.5), 1e-12);
  EXPECT_NEAR(scan.sightings[0].bearing, std::atan2(1.5, 2.0), 1e-12);
  EXPECT_NEAR(scan.sightings[0].orientation, kPi / 2.0, 1e-12);
}

}  // namespace playerkit::sim::fiducial_finder_test
