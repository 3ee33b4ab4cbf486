#include "sim/world/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace playerkit::sim::scene_test {

// The test's own picture of the scene: where each body is, tested point by
// point with nothing shared with the library's geometry.
struct MarchedBody {
  ModelId id = kNoModel;
  ModelId root = kNoModel;
  double x = 0.0, y = 0.0, yaw = 0.0;  // the body's centre and heading
  bool circle = false;
  double size_x = 0.0, size_y = 0.0;
  bool solid = true;
  bool present = true;
  double ranger = 1.0;

  [[nodiscard]] bool holds(double px, double py) const {
    const double dx = px - x, dy = py - y;
    const double along = std::cos(yaw) * dx + std::sin(yaw) * dy;
    const double across = -std::sin(yaw) * dx + std::cos(yaw) * dy;
    if (circle) return along * along + across * across <= size_x * size_x / 4.0;
    return std::abs(along) <= size_x / 2.0 && std::abs(across) <= size_y / 2.0;
  }
};

struct MarchHit {
  double range = 0.0;
  ModelId model = kNoModel;
  bool wall = false;
};

bool wall_at(const grid::OccupancyGrid& map, double px, double py) {
  const double col = std::floor((px - map.origin().x()) / map.resolution());
  const double row = std::floor((py - map.origin().y()) / map.resolution());
  if (col < 0 || row < 0 || col >= map.width() || row >= map.height()) return false;
  return map.at(static_cast<int>(col), static_cast<int>(row)) == grid::CellState::occupied;
}

// Samples the ray every `step` metres from `from` to `to`; the first sample
// inside a wall cell or a body that stops it.
template <typename Stops>
MarchHit march(const grid::OccupancyGrid& map, const std::vector<MarchedBody>& bodies, const Eigen::Vector2d& origin,
               double angle, double from, double to, double step, Stops&& stops) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (long k = 0;; ++k) {
    const double t = from + static_cast<double>(k) * step;
    if (t > to) break;
    const double px = origin.x() + t * c, py = origin.y() + t * s;
    if (wall_at(map, px, py)) return {t, kNoModel, true};
    for (const MarchedBody& body : bodies) {
      if (body.solid && body.present && stops(body) && body.holds(px, py)) return {t, body.id, false};
    }
  }
  return {to, kNoModel, false};
}

struct RandomScene {
  grid::OccupancyGrid map;
  Scene scene;
  std::vector<MarchedBody> bodies;
};

// A 5 x 5 m map with scattered wall cells, and bodies on it and off it:
// rectangles and circles, some in tree 0, some invisible to rangers, some
// without a body or not present.
RandomScene random_scene(std::mt19937& random) {
  grid::OccupancyGrid map(100, 100, 0.05, {-2.5, -2.5}, grid::CellState::free);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      if (unit(random) < 0.01) map.set(col, row, grid::CellState::occupied);
    }
  }
  RandomScene world{map, Scene(map), {}};
  for (ModelId id = 0; id < 40; ++id) {
    MarchedBody body;
    body.id = id;
    body.root = id < 5 ? 0 : id;
    body.circle = unit(random) < 0.4;
    body.size_x = 0.05 + 0.75 * unit(random);
    body.size_y = 0.05 + 0.75 * unit(random);
    body.solid = id % 13 != 7;
    body.present = id % 11 != 3;
    body.ranger = id % 9 == 4 ? -1.0 : 1.0;
    const geometry::Pose2 pose{-4.0 + 8.0 * unit(random), -4.0 + 8.0 * unit(random), -3.0 + 6.0 * unit(random)};
    const geometry::Pose2 offset{0.2 * unit(random) - 0.1, 0.2 * unit(random) - 0.1, unit(random) - 0.5};
    const geometry::Pose2 centre = pose.compose(offset);
    body.x = centre.x;
    body.y = centre.y;
    body.yaw = centre.yaw;

    SceneModel model;
    model.id = id;
    model.root = body.root;
    model.pose = pose;
    model.body = {.shape = body.circle ? Shape::circle : Shape::rectangle,
                  .size = {body.size_x, body.size_y},
                  .offset = offset,
                  .present = body.solid};
    model.returns.ranger = body.ranger;
    world.scene.add(model);
    if (!body.present) world.scene.set_present(id, false);
    world.bodies.push_back(body);
  }
  return world;
}

struct Tally {
  int walls = 0, bodies = 0, nothing = 0;
};

// The scene's answer for one ray against the march: nothing the march
// (1 mm steps) meets lies before it, and a march in 1 µm steps around it
// finds what the scene found, there.
template <typename Stops>
void expect_cast_matches_march(const RandomScene& world, const Eigen::Vector2d& origin, double angle,
                               double max_range, ModelId ignore_root, const ModelFilter& filter, Stops&& stops,
                               Tally& tally) {
  const RayHit hit = world.scene.cast(origin, angle, max_range, ignore_root, filter);
  const MarchHit coarse = march(world.map, world.bodies, origin, angle, 0.0, max_range, 1e-3, stops);
  SCOPED_TRACE(testing::Message() << "ray from (" << origin.x() << ", " << origin.y() << ") at " << angle
                                  << " rad; scene " << hit.range << " (model " << hit.model << ", wall "
                                  << hit.wall << "), march " << coarse.range << " (model " << coarse.model << ")");
  ASSERT_LE(hit.range, coarse.range + 1e-9);
  if (hit.range >= max_range) {
    EXPECT_EQ(hit.model, kNoModel);
    EXPECT_FALSE(hit.wall);
    ++tally.nothing;
    return;
  }
  const double from = std::max(0.0, hit.range - 1e-3);
  const MarchHit fine = march(world.map, world.bodies, origin, angle, from, hit.range + 1e-3, 1e-6, stops);
  EXPECT_NEAR(fine.range, hit.range, 2e-6);
  // What the scene names is there just past its range (where two things
  // begin at once, either may be named).
  const double px = origin.x() + (hit.range + 2e-6) * std::cos(angle);
  const double py = origin.y() + (hit.range + 2e-6) * std::sin(angle);
  if (hit.wall) {
    EXPECT_EQ(hit.model, kNoModel);
    EXPECT_TRUE(wall_at(world.map, px, py));
  } else {
    ASSERT_GE(hit.model, 0);
    const MarchedBody& body = world.bodies[static_cast<std::size_t>(hit.model)];
    EXPECT_TRUE(body.solid && body.present && stops(body) && body.holds(px, py));
  }
  ++(hit.wall ? tally.walls : tally.bodies);
}

TEST(Scene, CastMatchesAnIndependentRayMarchOverRandomRays) {
  std::mt19937 random(20261201);
  RandomScene world = random_scene(random);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Tally tally;
  for (int round = 0; round < 2; ++round) {
    for (int ray = 0; ray < 150; ++ray) {
      const Eigen::Vector2d origin{-3.0 + 6.0 * unit(random), -3.0 + 6.0 * unit(random)};
      const double angle = -std::numbers::pi + 2.0 * std::numbers::pi * unit(random);
      const ModelId ignore = ray % 2 == 0 ? 0 : kNoModel;
      expect_cast_matches_march(
          world, origin, angle, 4.0, ignore, nullptr,
          [&](const MarchedBody& body) { return body.ranger >= 0.0 && body.root != ignore; }, tally);
      if (HasFatalFailure()) return;
    }
    // Everything moves (some far off the map) and presence flips: the
    // scene must follow.
    for (MarchedBody& body : world.bodies) {
      const geometry::Pose2 pose{-6.0 + 12.0 * unit(random), -6.0 + 12.0 * unit(random), unit(random)};
      world.scene.update(body.id, pose);
      const geometry::Pose2 centre = world.scene.model(body.id).body_pose;
      body.x = centre.x;
      body.y = centre.y;
      body.yaw = centre.yaw;
      body.present = !body.present;
      world.scene.set_present(body.id, body.present);
    }
  }
  // Every kind of answer was checked, many times.
  EXPECT_GT(tally.walls, 30);
  EXPECT_GT(tally.bodies, 30);
  EXPECT_GT(tally.nothing, 10);
}

// A sensor's rays cast together answer, bit for bit, what each cast alone
// answers (which the march above checks), from on and off the map.
TEST(Scene, CastAllAnswersWhatCastAnswersForEachRay) {
  std::mt19937 random(314);
  const RandomScene world = random_scene(random);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int walls = 0, bodies = 0, off_map = 0;
  for (const ModelId ignore : {kNoModel, ModelId{0}}) {
    std::vector<SceneRay> rays;
    std::vector<double> angles;
    for (int ray = 0; ray < 300; ++ray) {
      const Eigen::Vector2d origin{-4.0 + 8.0 * unit(random), -4.0 + 8.0 * unit(random)};
      const double angle = -std::numbers::pi + 2.0 * std::numbers::pi * unit(random);
      rays.push_back({origin, {std::cos(angle), std::sin(angle)}});
      angles.push_back(angle);
      off_map += std::abs(origin.x()) > 2.5 || std::abs(origin.y()) > 2.5;
    }
    std::vector<RayHit> hits(rays.size());
    world.scene.cast_all(rays, 4.0, ignore, hits);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const RayHit alone = world.scene.cast(rays[i].origin, angles[i], 4.0, ignore);
      const RayHit by_direction = world.scene.cast(rays[i].origin, rays[i].direction, 4.0, ignore);
      EXPECT_EQ(hits[i].range, alone.range) << i;
      EXPECT_EQ(hits[i].model, alone.model) << i;
      EXPECT_EQ(hits[i].wall, alone.wall) << i;
      EXPECT_EQ(by_direction.range, alone.range) << i;
      EXPECT_EQ(by_direction.model, alone.model) << i;
      walls += alone.wall;
      bodies += alone.model != kNoModel;
    }
  }
  EXPECT_GT(walls, 100);
  EXPECT_GT(bodies, 100);
  EXPECT_GT(off_map, 100);
  // A laser's fan from one point and a sonar's ring of close points, as
  // sensors cast them: bodies are then filed by direction, and each ray
  // looks only at those that may lie its way.
  int fan_bodies = 0;
  for (int place = 0; place < 40; ++place) {
    const Eigen::Vector2d centre{-3.5 + 7.0 * unit(random), -3.5 + 7.0 * unit(random)};
    const double ring = place % 2 == 0 ? 0.0 : 0.2;
    std::vector<SceneRay> rays;
    const int count = place % 4 == 3 ? 12 : 360;  // a few rays are cast one by one inside
    for (int ray = 0; ray < count; ++ray) {
      const double angle = 2.0 * std::numbers::pi * ray / count + 0.1 * place;
      const Eigen::Vector2d direction{std::cos(angle), std::sin(angle)};
      rays.push_back({centre + ring * direction, direction});
    }
    std::vector<RayHit> hits(rays.size());
    world.scene.cast_all(rays, 3.0, kNoModel, hits);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const RayHit alone = world.scene.cast(rays[i].origin, rays[i].direction, 3.0, kNoModel);
      EXPECT_EQ(hits[i].range, alone.range) << place << " " << i;
      EXPECT_EQ(hits[i].model, alone.model) << place << " " << i;
      fan_bodies += alone.model != kNoModel;
    }
    if (ring == 0.0) {  // one origin: the fan answers alike
      std::vector<Eigen::Vector2d> directions;
      for (const SceneRay& ray : rays) directions.push_back(ray.direction);
      std::vector<RayHit> fan_hits(rays.size());
      world.scene.cast_fan(centre, directions, 3.0, kNoModel, fan_hits);
      for (std::size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(fan_hits[i].range, hits[i].range) << place << " " << i;
        EXPECT_EQ(fan_hits[i].model, hits[i].model) << place << " " << i;
        EXPECT_EQ(fan_hits[i].wall, hits[i].wall) << place << " " << i;
      }
    }
  }
  EXPECT_GT(fan_bodies, 1000);
  std::vector<RayHit> too_few(1);
  EXPECT_THROW(world.scene.cast_all(std::vector<SceneRay>(2), 4.0, kNoModel, too_few), std::invalid_argument);
  EXPECT_THROW(world.scene.cast_fan({0.0, 0.0}, std::vector<Eigen::Vector2d>(2), 4.0, kNoModel, too_few),
               std::invalid_argument);
}

TEST(Scene, AFilterDecidesWhichBodiesStopARay) {
  std::mt19937 random(7);
  const RandomScene world = random_scene(random);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Circles only, ranger return or not.
  const ModelFilter circles = [](const SceneModel& model) { return model.body.shape == Shape::circle; };
  Tally tally;
  for (int ray = 0; ray < 150; ++ray) {
    const Eigen::Vector2d origin{-3.0 + 6.0 * unit(random), -3.0 + 6.0 * unit(random)};
    const double angle = -std::numbers::pi + 2.0 * std::numbers::pi * unit(random);
    expect_cast_matches_march(
        world, origin, angle, 4.0, kNoModel, circles,
        [](const MarchedBody& body) { return body.circle; }, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.bodies, 10);
}

SceneModel box_at(ModelId id, double x, double y, double size) {
  SceneModel model;
  model.id = id;
  model.root = id;
  model.pose = {x, y, 0.0};
  model.body.size = {size, size};
  return model;
}

TEST(Scene, ARayFromInsideABodyStopsAtOnce) {
  Scene scene(grid::OccupancyGrid(40, 40, 0.05, {0.0, 0.0}, grid::CellState::free));
  scene.add(box_at(0, 0.5, 1.0, 0.4));
  const RayHit inside = scene.cast({0.5, 1.0}, 0.3, 5.0, kNoModel);
  EXPECT_EQ(inside.range, 0.0);
  EXPECT_EQ(inside.model, 0);
  EXPECT_FALSE(inside.wall);
}

TEST(Scene, BodiesFarOffTheMapAreStillHitAndFound) {
  Scene scene(grid::OccupancyGrid(20, 20, 0.05, {0.0, 0.0}, grid::CellState::free));
  scene.add(box_at(0, 500.0, -300.0, 1.0));
  scene.add(box_at(1, 0.5, 0.5, 0.2));
  const RayHit far = scene.cast({480.0, -300.0}, 0.0, 50.0, kNoModel);
  EXPECT_NEAR(far.range, 19.5, 1e-9);
  EXPECT_EQ(far.model, 0);
  // Moved from the map to far away and back.
  scene.update(1, {-2000.0, 10.0, 0.0});
  EXPECT_EQ(scene.cast({-2010.0, 10.0}, 0.0, 20.0, kNoModel).model, 1);
  EXPECT_EQ(scene.cast({0.0, 0.5}, 0.0, 2.0, kNoModel).model, kNoModel);
  scene.update(1, {0.5, 0.5, 0.0});
  EXPECT_EQ(scene.cast({0.0, 0.5}, 0.0, 2.0, kNoModel).model, 1);
  EXPECT_EQ(scene.models_near({500.0, -299.0}, 0.6), std::vector<ModelId>{0});
}

TEST(Scene, ModelsNearAreThoseWhoseBoundingCircleComesWithinTheRadius) {
  std::mt19937 random(99);
  const RandomScene world = random_scene(random);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int query = 0; query < 200; ++query) {
    const Eigen::Vector2d centre{-5.0 + 10.0 * unit(random), -5.0 + 10.0 * unit(random)};
    const double radius = 3.0 * unit(random);
    std::vector<ModelId> expected;
    for (const MarchedBody& body : world.bodies) {
      if (!body.present) continue;
      const double bounding =
          !body.solid ? 0.0 : body.circle ? body.size_x / 2.0 : std::hypot(body.size_x, body.size_y) / 2.0;
      if (std::hypot(body.x - centre.x(), body.y - centre.y()) <= radius + bounding) expected.push_back(body.id);
    }
    EXPECT_EQ(world.scene.models_near(centre, radius), expected) << "query " << query;
  }
}

TEST(Scene, ALongRowOfModelsIsMetInOrderAndFollowedAsItMoves) {
  // 400 boxes 0.1 m wide every 0.5 m along y = 0, spanning many grid cells.
  Scene scene(grid::OccupancyGrid(100, 100, 0.1, {-5.0, -5.0}, grid::CellState::free));
  for (ModelId id = 0; id < 400; ++id) scene.add(box_at(id, 0.5 * id, 0.0, 0.1));
  EXPECT_EQ(scene.cast({-1.0, 0.0}, 0.0, 300.0, kNoModel).model, 0);
  EXPECT_EQ(scene.cast({-1.0, 0.0}, 0.0, 300.0, 0).model, 1);
  const RayHit back = scene.cast({199.2, 0.0}, std::numbers::pi, 300.0, kNoModel);
  EXPECT_EQ(back.model, 398);
  EXPECT_NEAR(back.range, 0.15, 1e-9);
  for (ModelId id = 100; id < 400; ++id) scene.update(id, {0.5 * id, 3.0, 0.0});
  EXPECT_EQ(scene.cast({199.2, 0.0}, std::numbers::pi, 300.0, kNoModel).model, 99);
  EXPECT_EQ(scene.cast({199.2, 3.0}, std::numbers::pi, 300.0, kNoModel).model, 398);
  EXPECT_NEAR(scene.cast({199.2, 0.0}, std::numbers::pi, 300.0, kNoModel).range, 199.2 - 49.55, 1e-9);
}

TEST(Scene, SmallMovesWithinOneGridCellAreFollowed) {
  // The broad phase's cells are 2 m from the map's corner: [1, 3] in x and y here.
  Scene scene(grid::OccupancyGrid(100, 100, 0.1, {-5.0, -5.0}, grid::CellState::free));
  scene.add(box_at(0, 1.5, 1.5, 0.2));
  EXPECT_EQ(scene.cast({1.85, 0.0}, std::numbers::pi / 2, 5.0, kNoModel).model, kNoModel);
  for (int step = 1; step <= 30; ++step) {
    const double x = 1.5 + 0.01 * step;
    scene.update(0, {x, 1.5, 0.0});
    EXPECT_NEAR(scene.cast({0.0, 1.5}, 0.0, 5.0, kNoModel).range, x - 0.1, 1e-12);
  }
  // Now in the path of a ray it was nowhere near at first.
  EXPECT_NEAR(scene.cast({1.85, 0.0}, std::numbers::pi / 2, 5.0, kNoModel).range, 1.4, 1e-12);
}

TEST(Scene, CarriedModelsJoinTheirCarriersTree) {
  Scene scene;
  scene.add(box_at(0, 0.0, 0.0, 0.4));
  scene.add(box_at(1, 1.0, 0.0, 0.1));
  EXPECT_EQ(scene.cast({-1.0, 0.0}, 0.0, 5.0, 0).model, 1);
  scene.set_root(1, 0);
  EXPECT_EQ(scene.model(1).root, 0);
  EXPECT_EQ(scene.cast({-1.0, 0.0}, 0.0, 5.0, 0).model, kNoModel);
}

// A laser's fan skips the search for bodies when every body a ray could
// meet belongs to its own robot: carrying, letting go, consuming and
// bringing back a model must keep that decision right.
TEST(Scene, AFanSeesAModelAgainOnceItsCarrierLetsItGo) {
  Scene scene;
  scene.add(box_at(0, 0.0, 0.0, 0.4));  // the robot
  scene.add(box_at(1, 1.0, 0.0, 0.1));  // what it carries
  SceneModel see_through = box_at(2, 3.0, 0.0, 0.1);
  see_through.returns.ranger = -1.0;
  scene.add(see_through);
  const auto front_hit = [&scene] {
    std::vector<SceneRay> fan;
    for (int ray = -20; ray <= 20; ++ray) {  // more than one by one handles
      const double angle = 0.01 * ray;
      fan.push_back({{0.0, 0.0}, {std::cos(angle), std::sin(angle)}});
    }
    std::vector<RayHit> hits(fan.size());
    scene.cast_all(fan, 5.0, 0, hits);
    return hits[20];
  };
  EXPECT_EQ(front_hit().model, 1);
  scene.set_root(1, 0);
  EXPECT_EQ(front_hit().model, kNoModel);
  scene.set_root(1, 1);
  EXPECT_EQ(front_hit().model, 1);
  EXPECT_NEAR(front_hit().range, 0.95, 1e-9);
  scene.set_present(1, false);
  EXPECT_EQ(front_hit().model, kNoModel);
  scene.set_present(1, true);
  EXPECT_EQ(front_hit().model, 1);
}

}  // namespace playerkit::sim::scene_test
