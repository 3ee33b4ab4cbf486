#include "sim/render/trails.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <limits>

#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::render {
namespace trails_test {

using world_test_support::model;

grid::OccupancyGrid floor_map() { return grid::OccupancyGrid::centred(100, 100, 0.1, grid::CellState::free); }

TEST(Trails, RecordsEveryRobotsTruePoseAndNothingElse) {
  World world({.step = 0.1, .seed = 1}, floor_map());
  ModelSpec robot = model("r0", kNoModel, {1.0, 2.0, 0.0}, PositionSpec{});
  const ModelId r0 = world.add(robot);
  robot.name = "r1";
  robot.pose = {-3.0, 0.5, 1.0};
  const ModelId r1 = world.add(robot);
  world.add(model("laser", r0, {}, LaserSpec{}));
  world.add(model("box", kNoModel, {2.0, 2.0, 0.0}, ObjectSpec{}));

  Trails trails;
  trails.record(world);
  ASSERT_EQ(trails.models(), (std::vector<ModelId>{r0, r1}));
  ASSERT_EQ(trails.points(r0).size(), 1u);
  EXPECT_EQ(trails.points(r0)[0], Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(trails.points(r1)[0], Eigen::Vector2d(-3.0, 0.5));

  // Driven forward 0.5 m/s for a second: the trail follows the true pose.
  world.set_active(r0, true);
  world.command_velocity(r0, {0.5, 0.0, 0.0});
  for (int i = 0; i < 10; ++i) {
    world.step();
    trails.record(world);
  }
  const auto points = trails.points(r0);
  ASSERT_EQ(points.size(), 11u);
  EXPECT_NEAR(points.back().x(), 1.5, 1e-9);
  EXPECT_NEAR(points.back().y(), 2.0, 1e-9);
  EXPECT_EQ(trails.points(r1).size(), 1u);  // standing still: no new points
}

TEST(Trails, KeepsTheNewestPointsOnly) {
  Trails trails({.max_points = 3, .min_spacing = 0.0});
  for (int i = 0; i < 5; ++i) trails.add(7, {double(i), 0.0});
  EXPECT_EQ(trails.points(7),
            (std::vector<Eigen::Vector2d>{{2.0, 0.0}, {3.0, 0.0}, {4.0, 0.0}}));
}

TEST(Trails, SkipsPointsCloserThanTheSpacingAndNonFiniteOnes) {
  Trails trails({.max_points = 10, .min_spacing = 0.1});
  trails.add(0, {0.0, 0.0});
  trails.add(0, {0.05, 0.0});
  trails.add(0, {std::numeric_limits<double>::quiet_NaN(), 0.0});
  trails.add(0, {0.0, 0.1});
  EXPECT_EQ(trails.points(0), (std::vector<Eigen::Vector2d>{{0.0, 0.0}, {0.0, 0.1}}));
  EXPECT_TRUE(trails.points(5).empty());
  trails.clear();
  EXPECT_TRUE(trails.models().empty());
}

}  // namespace trails_test
}  // namespace playerkit::sim::render
