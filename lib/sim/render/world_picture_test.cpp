#include "sim/render/world_picture.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "sim/render/world_snapshot.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::render {
namespace world_picture_test {

using world_test_support::model;

// A 4 x 4 m floor centred on the origin in 5 cm cells, with a wall filling
// 1.5 <= x < 1.7 from bottom to top. At 1600 px a side: 400 px/m, so the
// map's bottom left corner (-2, -2) is pixel (0, 1600).
constexpr double kCell = 0.05;
constexpr double kWallX = 1.5;
// Points on pixel centres: 0.00125 m is half a pixel.
constexpr double kHalfPixel = 0.00125;
constexpr Rgb kRobotColor{20, 120, 200};
constexpr Rgb kDiscColor{200, 30, 30};

grid::OccupancyGrid walled_floor() {
  auto map = grid::OccupancyGrid::centred(80, 80, kCell, grid::CellState::free);
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 70; col < 74; ++col) map.set(col, row, grid::CellState::occupied);  // x = 1.5 .. 1.7
  }
  return map;
}

struct TinyWorld {
  World world{{.step = 0.1, .seed = 3}, walled_floor()};
  ModelId robot = kNoModel;
  ModelId laser = kNoModel;
  ModelId finder = kNoModel;
  ModelId disc = kNoModel;
  ModelId beacon = kNoModel;

  TinyWorld() {
    ModelSpec robot_spec = model("robot", kNoModel, {-1.0, kHalfPixel, 0.0}, PositionSpec{});
    robot_spec.body.size = {0.4, 0.4};
    robot_spec.color = kRobotColor;
    robot = world.add(robot_spec);
    // Three beams: -45, 0 and +45 degrees, from 0.1 m ahead of the robot's centre.
    LaserSpec beams;
    beams.fov = std::numbers::pi / 2;
    beams.samples = 3;
    ModelSpec laser_spec = model("laser", robot, {0.1, 0.0, 0.0}, beams);
    laser_spec.body.present = false;
    laser = world.add(laser_spec);
    ModelSpec finder_spec = model("finder", laser, {}, FiducialSpec{});
    finder_spec.body.present = false;
    finder = world.add(finder_spec);
    ModelSpec disc_spec = model("disc", kNoModel, {0.5, 1.2, 0.0}, ObjectSpec{});
    disc_spec.body.shape = Shape::circle;
    disc_spec.body.size = {0.4, 0.4};
    disc_spec.color = kDiscColor;
    disc = world.add(disc_spec);
    ModelSpec beacon_spec = model("beacon", kNoModel, {0.5, -1.2, 0.0}, ObjectSpec{});
    beacon_spec.body.shape = Shape::circle;
    beacon_spec.body.size = {0.2, 0.2};
    beacon_spec.returns.fiducial_id = 3;
    beacon = world.add(beacon_spec);
    world.set_active(laser, true);
    world.set_active(finder, true);
    world.step();
  }
};

Rgb pixel_at(const Picture& picture, const Eigen::Vector2d& world) {
  const Eigen::Vector2i pixel = picture.frame.pixel_of(world);
  EXPECT_TRUE(picture.frame.contains(pixel)) << world.transpose();
  return picture.at(pixel.x(), pixel.y());
}

::testing::AssertionResult near(const Rgb& actual, const Rgb& expected, int tolerance = 0) {
  if (std::abs(actual.r - expected.r) <= tolerance && std::abs(actual.g - expected.g) <= tolerance &&
      std::abs(actual.b - expected.b) <= tolerance) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "rgb(" << int(actual.r) << ", " << int(actual.g) << ", " << int(actual.b)
                                       << ") is not rgb(" << int(expected.r) << ", " << int(expected.g) << ", "
                                       << int(expected.b) << ") within " << tolerance;
}

bool dark(const Rgb& color) { return color.r < 64 && color.g < 64 && color.b < 64; }

// `over` laid at `opacity` on white, rounded.
Rgb tinted_white(const Rgb& over, double opacity) {
  const auto channel = [&](std::uint8_t value) {
    return static_cast<std::uint8_t>(std::lround(255.0 + (value - 255.0) * opacity));
  };
  return {channel(over.r), channel(over.g), channel(over.b)};
}

TEST(WorldPicture, TheMapFillsTheLongSideAtFourHundredPixelsAMetre) {
  TinyWorld tiny;
  const Picture picture = draw_world(take_snapshot(tiny.world));
  EXPECT_EQ(picture.width(), 1600);
  EXPECT_EQ(picture.height(), 1600);
  EXPECT_DOUBLE_EQ(picture.frame.pixels_per_metre(), 400.0);
  EXPECT_EQ(picture.rgb.size(), 1600u * 1600u * 3u);
  EXPECT_EQ(picture.frame.pixel_of({-2.0 + kHalfPixel, -2.0 + kHalfPixel}), Eigen::Vector2i(0, 1599));
}

TEST(WorldPicture, WallsAreDarkAndUntouchedFloorWhite) {
  TinyWorld tiny;
  const Picture picture = draw_world(take_snapshot(tiny.world));
  EXPECT_TRUE(dark(pixel_at(picture, {1.6, 1.0})));
  EXPECT_TRUE(dark(pixel_at(picture, {kWallX + 0.01, -1.9})));
  EXPECT_TRUE(near(pixel_at(picture, {kWallX - 0.01, -1.9}), colors::kFloor));  // the cell before the wall
  EXPECT_TRUE(near(pixel_at(picture, {-1.5, 1.5}), colors::kFloor));
  EXPECT_TRUE(near(pixel_at(picture, {0.75, 1.2}), colors::kFloor));  // beside the disc
}

TEST(WorldPicture, BodiesInTheirColourWithTheRobotsHeading) {
  TinyWorld tiny;
  const Picture picture = draw_world(take_snapshot(tiny.world));
  EXPECT_TRUE(near(pixel_at(picture, {-1.1, 0.1}), kRobotColor));   // behind the robot's centre
  EXPECT_TRUE(near(pixel_at(picture, {-1.15, -0.15}), kRobotColor));
  EXPECT_TRUE(near(pixel_at(picture, {-0.9, kHalfPixel}), colors::kHeading));  // on the heading, ahead of the centre
  EXPECT_TRUE(near(pixel_at(picture, {-1.25, 0.1}), colors::kFloor));  // just outside the body
  EXPECT_TRUE(near(pixel_at(picture, {0.5, 1.2}), kDiscColor));
  EXPECT_TRUE(near(pixel_at(picture, {0.5 + 0.15, 1.2}), kDiscColor));
  EXPECT_TRUE(near(pixel_at(picture, {0.5 + 0.15, 1.2 + 0.15}), colors::kFloor));  // outside the circle, inside its box
}

TEST(WorldPicture, TheLaserRaysAreFaintLinesFromTheSensorToTheHit) {
  TinyWorld tiny;
  const Picture picture = draw_world(take_snapshot(tiny.world));
  // The beam straight ahead runs from (-0.9, y) to the wall at 1.5 along a pixel row.
  const Rgb ray = tinted_white(colors::kLaserRay, colors::kRayOpacity);
  for (const double x : {-0.5, 0.0, 0.3, 1.0, 1.4}) {
    EXPECT_TRUE(near(pixel_at(picture, {x + kHalfPixel, kHalfPixel}), ray, 1)) << x;
    EXPECT_TRUE(near(pixel_at(picture, {x + kHalfPixel, kHalfPixel + 0.01}), colors::kFloor)) << x;  // 4 px off it
  }
  // The +45 degree beam, until the disc stops it.
  EXPECT_TRUE(near(pixel_at(picture, {-0.4 + kHalfPixel, 0.5 + kHalfPixel}), ray, 1));
  // A hit is marked at the wall.
  EXPECT_TRUE(near(pixel_at(picture, {kWallX - kHalfPixel, kHalfPixel}), colors::kLaserHit, 40));
}

TEST(WorldPicture, TrailsInTheRobotsColourDarkened) {
  TinyWorld tiny;
  Trails trails({.max_points = 10, .min_spacing = 0.0});
  trails.add(tiny.robot, {-1.5, -1.0 + kHalfPixel});
  trails.add(tiny.robot, {1.0, -1.0 + kHalfPixel});
  const Picture picture = draw_world(take_snapshot(tiny.world, &trails));
  const Rgb darker{12, 72, 120};  // 3/5 of (20, 120, 200)
  EXPECT_TRUE(near(pixel_at(picture, {-0.5, -1.0 + kHalfPixel}), darker, 2));
  EXPECT_TRUE(near(pixel_at(picture, {-0.5, -1.0 + kHalfPixel + 0.05}), colors::kFloor));
  EXPECT_TRUE(near(pixel_at(picture, {-1.9, -1.0 + kHalfPixel}), colors::kFloor));  // before its start
}

TEST(WorldPicture, ThinWallsSurviveAShrunkMap) {
  // 20 m x 0.2 m in 1 cm cells, one wall cell wide, at 10 px/m: a pixel holds 100 cells.
  auto map = grid::OccupancyGrid(2000, 20, 0.01, {0.0, 0.0}, grid::CellState::free);
  for (int row = 0; row < 20; ++row) map.set(1234, row, grid::CellState::occupied);
  const World world({.step = 0.1, .seed = 0}, map);
  const Picture picture = draw_world(take_snapshot(world), {.max_side_pixels = 200, .caption = false});
  ASSERT_EQ(picture.width(), 200);
  ASSERT_EQ(picture.height(), 2);
  for (int row = 0; row < picture.height(); ++row) {
    for (int col = 0; col < picture.width(); ++col) {
      // The wall cell's centre is at x = 12.345 m: pixel column 123.
      EXPECT_EQ(dark(picture.at(col, row)), col == 123) << col << "," << row;
    }
  }
}

TEST(WorldSnapshot, LaserRaysAndFiducialSightingsInWorldMetres) {
  TinyWorld tiny;
  const WorldSnapshot snapshot = take_snapshot(tiny.world);
  EXPECT_DOUBLE_EQ(snapshot.time, 0.1);
  EXPECT_EQ(snapshot.map, &tiny.world.scene().map());
  ASSERT_EQ(snapshot.rays.size(), 3u);
  const SnapshotRay& ahead = snapshot.rays[1];
  EXPECT_EQ(ahead.kind, RayKind::laser);
  EXPECT_TRUE(ahead.from.isApprox(Eigen::Vector2d(-0.9, kHalfPixel)));
  EXPECT_NEAR(ahead.to.x(), kWallX, kCell);
  EXPECT_NEAR(ahead.to.y(), kHalfPixel, 1e-9);
  EXPECT_TRUE(ahead.hit);
  // The +45 degree beam meets the disc (radius 0.2 at (0.5, 1.2)) on its surface.
  const SnapshotRay& left = snapshot.rays[2];
  EXPECT_NEAR((left.to - Eigen::Vector2d(0.5, 1.2)).norm(), 0.2, 1e-6);
  EXPECT_NEAR(left.to.y() - left.from.y(), left.to.x() - left.from.x(), 1e-9);

  ASSERT_EQ(snapshot.sightings.size(), 1u);
  EXPECT_EQ(snapshot.sightings[0].id, 3);
  EXPECT_TRUE(snapshot.sightings[0].from.isApprox(Eigen::Vector2d(-0.9, kHalfPixel)));
  EXPECT_NEAR((snapshot.sightings[0].to - Eigen::Vector2d(0.5, -1.2)).norm(), 0.0, 1e-9);

  // Bodies: the robot, the disc and the beacon; the sensors have none.
  ASSERT_EQ(snapshot.bodies.size(), 3u);
  EXPECT_TRUE(snapshot.bodies[0].robot);
  EXPECT_FALSE(snapshot.bodies[1].robot);
  EXPECT_EQ(snapshot.bodies[1].color, kDiscColor);
}

TEST(WorldSnapshot, SonarRaysStartAtEachTransducer) {
  World world({.step = 0.1, .seed = 0}, walled_floor());
  // Facing +y; one transducer 0.2 m ahead looking ahead, one 0.2 m to the left looking right (+x).
  const ModelId robot = world.add(model("robot", kNoModel, {0.0, -1.0, std::numbers::pi / 2}, PositionSpec{}));
  SonarSpec ring;
  ring.transducers = {{0.2, 0.0, 0.0}, {0.0, 0.2, -std::numbers::pi / 2}};
  ring.range_max = 5.0;
  ModelSpec sonar_spec = model("sonar", robot, {}, ring);
  sonar_spec.body.present = false;
  const ModelId sonar = world.add(sonar_spec);
  world.set_active(sonar, true);
  world.step();
  const WorldSnapshot snapshot = take_snapshot(world);
  ASSERT_EQ(snapshot.rays.size(), 2u);
  EXPECT_EQ(snapshot.rays[0].kind, RayKind::sonar);
  EXPECT_TRUE(snapshot.rays[0].from.isApprox(Eigen::Vector2d(0.0, -0.8)));
  EXPECT_NEAR(snapshot.rays[0].to.x(), 0.0, 1e-9);
  EXPECT_NEAR(snapshot.rays[0].to.y(), 4.2, 1e-9);  // nothing ahead: range_max
  EXPECT_FALSE(snapshot.rays[0].hit);
  EXPECT_TRUE(snapshot.rays[1].from.isApprox(Eigen::Vector2d(-0.2, -1.0)));
  EXPECT_NEAR(snapshot.rays[1].to.x(), kWallX, kCell);
  EXPECT_NEAR(snapshot.rays[1].to.y(), -1.0, 1e-9);
  EXPECT_TRUE(snapshot.rays[1].hit);
}

}  // namespace world_picture_test
}  // namespace playerkit::sim::render
