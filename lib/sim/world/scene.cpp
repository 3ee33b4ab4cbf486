#include "sim/world/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace playerkit::sim {

namespace {

IndexedBody indexed_body(const SceneModel& model) {
  IndexedBody indexed;
  indexed.root = model.root;
  indexed.solid = model.body.present;
  indexed.ranger_visible = model.returns.ranger >= 0.0;
  indexed.obstacle = model.returns.obstacle;
  if (indexed.solid) {
    indexed.shape = place_body(model.body, model.body_pose);
  } else {
    indexed.shape.centre = model.body_pose.translation();  // a point, for models_near
  }
  return indexed;
}

// The RangeCaster answers rays that start on the map; one that starts off
// it (robots may leave a Stage 4 map) is started where it enters the map.
double wall_range_from_anywhere(const grid::OccupancyGrid& map, const grid::RangeCaster& walls,
                                const Eigen::Vector2d& origin, double angle, double max_range) {
  if (map.empty()) return max_range;
  const Eigen::Vector2d low = map.origin();
  const Eigen::Vector2d high = low + map.resolution() * Eigen::Vector2d(map.width(), map.height());
  if ((origin.array() >= low.array()).all() && (origin.array() < high.array()).all()) {
    return walls.range(origin, angle, max_range);
  }
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  double enter = 0.0;
  double leave = max_range;
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) {
      if (origin[axis] < low[axis] || origin[axis] >= high[axis]) return max_range;
      continue;
    }
    double near_side = (low[axis] - origin[axis]) / direction[axis];
    double far_side = (high[axis] - origin[axis]) / direction[axis];
    if (near_side > far_side) std::swap(near_side, far_side);
    enter = std::max(enter, near_side);
    leave = std::min(leave, far_side);
  }
  if (!(enter < leave)) return max_range;
  // A hair inside, so that rounding cannot leave the start off the map.
  const Eigen::Vector2d hair = Eigen::Vector2d::Constant(1e-9 * (1.0 + high.cwiseAbs().maxCoeff()));
  const Eigen::Vector2d start = (origin + enter * direction).cwiseMax(low + hair).cwiseMin(high - hair);
  const double rest = walls.range(start, angle, max_range - enter);
  return rest < max_range - enter ? enter + rest : max_range;
}

}  // namespace

Scene::Scene(grid::OccupancyGrid map) : map_(std::move(map)), walls_(map_, grid::RayStop::occupied) {
  if (map_.empty()) return;
  const Eigen::Vector2d extent(map_.width() * map_.resolution(), map_.height() * map_.resolution());
  index_.cover(map_.origin(), map_.origin() + extent);
}

RayHit Scene::cast(const Eigen::Vector2d& origin, double angle, double max_range, ModelId ignore_root,
                   const ModelFilter& stops) const {
  RayHit hit{.range = max_range};
  if (!(max_range > 0.0) || !std::isfinite(angle) || !origin.allFinite()) return hit;
  const double wall = wall_range_from_anywhere(map_, walls_, origin, angle, max_range);
  if (wall < max_range) hit = {.range = wall, .model = kNoModel, .wall = true};
  if (!index_.has_solid_bodies()) return hit;

  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  const bool default_stops = !stops;
  const auto try_body = [&](ModelId id) {
    // Walls win ties; the filter runs only for a body that would be nearer.
    const double entry = ray_entry(index_.body(id).shape, origin, direction);
    if (!(entry < hit.range)) return;
    if (!default_stops && !stops(models_[static_cast<std::size_t>(id)])) return;
    hit = {.range = entry, .model = id, .wall = false};
  };
  for (const ModelId id : index_.oversized()) {
    const IndexedBody& body = index_.body(id);
    if (body.solid && body.root != ignore_root && (!default_stops || body.ranger_visible)) try_body(id);
  }
  index_.along_ray(origin, direction, hit.range, [&](std::span<const CellSlot> listed, double leaves_cell) {
    for (const CellSlot& slot : listed) {
      if (slot.root == ignore_root || (default_stops && !slot.ranger_visible)) continue;
      // Most bodies are off the ray, behind it or beyond what it already
      // met: their bounding circle says so without the exact test.
      const double to_x = slot.x - origin.x(), to_y = slot.y - origin.y();
      const double along = to_x * direction.x() + to_y * direction.y();
      if (along + slot.reach < 0.0 || along - slot.reach >= hit.range) continue;
      if (std::abs(to_x * direction.y() - to_y * direction.x()) > slot.reach) continue;
      try_body(slot.id);
    }
    // Cells further on lie beyond leaves_cell: nothing there can be nearer.
    return hit.range > leaves_cell;
  });
  return hit;
}

std::vector<ModelId> Scene::models_near(const Eigen::Vector2d& centre, double radius) const {
  std::vector<ModelId> near;
  models_near(centre, radius, near);
  return near;
}

void Scene::models_near(const Eigen::Vector2d& centre, double radius, std::vector<ModelId>& near) const {
  near.clear();
  if (!centre.allFinite() || !(radius >= 0.0)) return;
  // A model is listed in every cell its bounding circle's box touches, so
  // one whose circle comes within `radius` shares a cell with the query's
  // square; the test below drops those that only share the cell.
  index_.near(centre, radius, [&](ModelId id) {
    const PlacedBody& shape = index_.body(id).shape;
    const double reach = radius + shape.bounding_radius;
    if ((shape.centre - centre).squaredNorm() <= reach * reach) near.push_back(id);
  });
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
}

void Scene::add(SceneModel model) {
  if (model.id < 0) throw std::invalid_argument("Scene::add: model id " + std::to_string(model.id) + " is negative");
  const auto slot = static_cast<std::size_t>(model.id);
  if (slot < models_.size() && models_[slot].id != kNoModel) {
    throw std::invalid_argument("Scene::add: model id " + std::to_string(model.id) + " is taken");
  }
  if (slot >= models_.size()) models_.resize(slot + 1);
  model.body_pose = model.pose.compose(model.body.offset);
  models_[slot] = std::move(model);
  if (models_[slot].present) index_.put(models_[slot].id, indexed_body(models_[slot]));
}

void Scene::update(ModelId id, const geometry::Pose2& pose) {
  SceneModel& model = models_.at(static_cast<std::size_t>(id));
  model.pose = pose;
  model.body_pose = pose.compose(model.body.offset);
  if (model.present) index_.put(id, indexed_body(model));
}

void Scene::set_present(ModelId id, bool present) {
  SceneModel& model = models_.at(static_cast<std::size_t>(id));
  model.present = present;
  if (present) {
    index_.put(id, indexed_body(model));
  } else {
    index_.remove(id);
  }
}

void Scene::set_root(ModelId id, ModelId root) {
  SceneModel& model = models_.at(static_cast<std::size_t>(id));
  model.root = root;
  if (model.present) index_.put(id, indexed_body(model));
}

}  // namespace playerkit::sim
