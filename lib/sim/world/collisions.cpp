#include "sim/world/collisions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/world/world_state.hpp"

namespace playerkit::sim {

namespace {

// A move longer than this many pieces is checked at its end only beyond
// them; at 0.1 s steps it takes a body 2 cm thick moving 64 cm per step.
constexpr int kMostCollisionPieces = 64;

// Whether a solid body of the mover's tree collides: it and the other
// model are both obstacles, present, and not of one tree.
bool is_obstacle_body(const SceneModel& model) {
  return model.present && model.body.present && model.returns.obstacle;
}

}  // namespace

bool body_overlaps_walls(const grid::OccupancyGrid& map, const PlacedBody& body) {
  if (map.empty()) return false;
  // The body's axis-aligned bounding box.
  const double c = std::abs(body.cos_yaw), s = std::abs(body.sin_yaw);
  const Eigen::Vector2d reach = body.circle ? Eigen::Vector2d::Constant(body.half_x)
                                            : Eigen::Vector2d(body.half_x * c + body.half_y * s,
                                                              body.half_x * s + body.half_y * c);
  const double resolution = map.resolution();
  const Eigen::Vector2i low = grid::cell_containing(body.centre - reach, map.origin(), resolution)
                                  .cwiseMax(Eigen::Vector2i::Zero());
  const Eigen::Vector2i high = grid::cell_containing(body.centre + reach, map.origin(), resolution)
                                   .cwiseMin(Eigen::Vector2i(map.width() - 1, map.height() - 1));
  for (int row = low.y(); row <= high.y(); ++row) {
    for (int col = low.x(); col <= high.x(); ++col) {
      if (map.at(col, row) != grid::CellState::occupied) continue;
      const Eigen::Vector2d corner = map.origin() + resolution * Eigen::Vector2d(col, row);
      if (bodies_overlap(cell_body(corner, corner + Eigen::Vector2d::Constant(resolution)), body)) return true;
    }
  }
  return false;
}

bool World::State::collides_at(ModelId id, const geometry::Pose2& pose) {
  const ModelId mover_root = scene.model(id).root;
  // Carried models ride along but do not collide: they would otherwise
  // stop their carrier on everything they touch.
  const auto tree_collides = [&](const geometry::Pose2& at) {
    bool hit = false;
    for_each_riding(id, at, false, [&](ModelId riding, const geometry::Pose2& riding_pose, bool carried) {
      const SceneModel& model = scene.model(riding);
      if (hit || carried || !is_obstacle_body(model)) return;
      const PlacedBody body = place_body(model.body, riding_pose.compose(model.body.offset));
      // In open floor the cell-by-cell test is not needed.
      const bool clear_of_walls = body.bounding_radius < scene.walls_clear_around(body.centre);
      if (!clear_of_walls && body_overlaps_walls(scene.map(), body)) {
        hit = true;
        return;
      }
      scene.models_near(body.centre, body.bounding_radius, near_scratch);
      for (const ModelId other_id : near_scratch) {
        const SceneModel& other = scene.model(other_id);
        if (other.root == mover_root || !is_obstacle_body(other)) continue;
        if (bodies_overlap(body, place_body(other.body, other.body_pose))) {
          hit = true;
          return;
        }
      }
    });
    return hit;
  };

  // Long moves are checked in pieces no longer than the thinnest body is
  // half wide, so that nothing passes through a thin wall in one step.
  const geometry::Pose2& from = global(id);
  double thinnest = std::numeric_limits<double>::infinity();
  for_each_riding(id, from, false, [&](ModelId riding, const geometry::Pose2&, bool carried) {
    const SceneModel& model = scene.model(riding);
    if (carried || !is_obstacle_body(model)) return;
    const PlacedBody shape = place_body(model.body, {});
    thinnest = std::min({thinnest, shape.half_x, shape.half_y});
  });
  if (thinnest == std::numeric_limits<double>::infinity()) return false;  // nothing of it collides
  const double piece = std::max({thinnest, scene.map().empty() ? 0.0 : scene.map().resolution() / 2.0, 1e-3});
  const double travel = std::hypot(pose.x - from.x, pose.y - from.y);
  const int pieces = static_cast<int>(std::clamp(std::ceil(travel / piece), 1.0, double(kMostCollisionPieces)));
  const double turn = geometry::angle_difference(pose.yaw, from.yaw);
  for (int k = 1; k < pieces; ++k) {
    const double f = static_cast<double>(k) / pieces;
    const geometry::Pose2 between{from.x + f * (pose.x - from.x), from.y + f * (pose.y - from.y), from.yaw + f * turn};
    if (tree_collides(between)) return true;
  }
  return tree_collides(pose);
}

}  // namespace playerkit::sim
