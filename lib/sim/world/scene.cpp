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

// cast_all's broad phase: the bodies its rays may meet, in sectors of
// directions around the rays' centre.
constexpr int kDirectionSectors = 64;
// Fewer rays than this (a sonar ring) cost less one by one through the
// broad phase's cells than gathering and filing the bodies does (measured:
// 1000 sonar robots in the hospital run a fifth faster so).
constexpr std::size_t kFewestRaysToFile = 32;

// A number in [0, 4) that grows with a direction's angle from +x,
// counter-clockwise, without trigonometry.
double pseudo_angle(const Eigen::Vector2d& direction) {
  const double sum = std::abs(direction.x()) + std::abs(direction.y());
  if (!(sum > 0.0)) return 0.0;
  const double turn = direction.y() / sum;  // in [-1, 1]
  if (direction.x() >= 0.0) return turn >= 0.0 ? turn : 4.0 + turn;
  return 2.0 - turn;
}

int direction_sector(const Eigen::Vector2d& direction) {
  const auto sector = static_cast<int>(pseudo_angle(direction) * (kDirectionSectors / 4));
  return std::clamp(sector, 0, kDirectionSectors - 1);
}

// A body a batch of rays may meet, as its bounding circle.
struct BatchBody {
  ModelId id = kNoModel;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double reach = 0.0;  // bounding radius, a hair larger against rounding
};

}  // namespace

Scene::Scene(grid::OccupancyGrid map) : map_(std::move(map)), walls_(map_, grid::RayStop::occupied) {
  if (map_.empty()) return;
  map_low_ = map_.origin();
  map_high_ = map_low_ + map_.resolution() * Eigen::Vector2d(map_.width(), map_.height());
  index_.cover(map_low_, map_high_);
}

bool Scene::on_map(const Eigen::Vector2d& point) const {
  return !map_.empty() && point.x() >= map_low_.x() && point.y() >= map_low_.y() && point.x() < map_high_.x() &&
         point.y() < map_high_.y();
}

// The caster answers rays that start on the map; one that starts off it
// (robots may leave a Stage 4 map) is started where it enters the map.
Scene::WallWalk Scene::wall_walk(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                 double max_range) const {
  WallWalk walk;
  if (map_.empty()) return walk;
  if (on_map(origin)) return {.on_map = true, .ray = {origin, direction, max_range}, .offset = 0.0};
  const Eigen::Vector2d& low = map_low_;
  const Eigen::Vector2d& high = map_high_;
  double enter = 0.0;
  double leave = max_range;
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) {
      if (origin[axis] < low[axis] || origin[axis] >= high[axis]) return walk;
      continue;
    }
    double near_side = (low[axis] - origin[axis]) / direction[axis];
    double far_side = (high[axis] - origin[axis]) / direction[axis];
    if (near_side > far_side) std::swap(near_side, far_side);
    enter = std::max(enter, near_side);
    leave = std::min(leave, far_side);
  }
  if (!(enter < leave)) return walk;
  // A hair inside, so that rounding cannot leave the start off the map.
  const Eigen::Vector2d hair = Eigen::Vector2d::Constant(1e-9 * (1.0 + high.cwiseAbs().maxCoeff()));
  const Eigen::Vector2d start = (origin + enter * direction).cwiseMax(low + hair).cwiseMin(high - hair);
  return {.on_map = true, .ray = {start, direction, max_range - enter}, .offset = enter};
}

RayHit Scene::cast(const Eigen::Vector2d& origin, double angle, double max_range, ModelId ignore_root,
                   const ModelFilter& stops) const {
  if (!std::isfinite(angle)) return {.range = max_range};
  return cast(origin, Eigen::Vector2d(std::cos(angle), std::sin(angle)), max_range, ignore_root, stops);
}

RayHit Scene::cast(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, double max_range,
                   ModelId ignore_root, const ModelFilter& stops) const {
  RayHit hit{.range = max_range};
  if (!(max_range > 0.0) || !direction.allFinite() || !origin.allFinite()) return hit;
  if (const WallWalk walk = wall_walk(origin, direction, max_range); walk.on_map) {
    const double rest = walls_.range(walk.ray.origin, walk.ray.direction, walk.ray.max_range);
    if (rest < walk.ray.max_range) hit = {.range = walk.offset + rest, .model = kNoModel, .wall = true};
  }
  nearest_body(origin, direction, ignore_root, stops, hit);
  return hit;
}

void Scene::cast_all(std::span<const SceneRay> rays, double max_range, ModelId ignore_root,
                     std::span<RayHit> hits) const {
  if (rays.size() != hits.size()) {
    throw std::invalid_argument("Scene::cast_all: " + std::to_string(rays.size()) + " rays but room for " +
                                std::to_string(hits.size()) + " hits");
  }
  // Reused from call to call (no allocation once grown); one set a thread.
  thread_local std::vector<grid::SquareCaster::Ray> walked;
  thread_local std::vector<std::size_t> walked_ray;  // which of `rays` each walked ray is
  thread_local std::vector<double> offsets;
  thread_local std::vector<double> walls;
  walked.resize(rays.size());
  walked_ray.resize(rays.size());
  offsets.resize(rays.size());
  std::size_t count = 0;
  const bool usable = max_range > 0.0 && !map_.empty();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits[i] = {.range = max_range};
    const SceneRay& ray = rays[i];
    if (!usable || !ray.direction.allFinite() || !ray.origin.allFinite()) continue;
    // Most rays start on the map (wall_walk's first case, inline).
    const WallWalk walk = on_map(ray.origin)
                              ? WallWalk{.on_map = true, .ray = {ray.origin, ray.direction, max_range}, .offset = 0.0}
                              : wall_walk(ray.origin, ray.direction, max_range);
    if (!walk.on_map) continue;
    walked[count] = walk.ray;
    walked_ray[count] = i;
    offsets[count] = walk.offset;
    ++count;
  }
  walls.resize(count);
  walls_.ranges(std::span(walked).first(count), walls);
  for (std::size_t k = 0; k < count; ++k) {
    if (walls[k] < walked[k].max_range) hits[walked_ray[k]] = {.range = offsets[k] + walls[k], .model = kNoModel, .wall = true};
  }
  add_bodies(rays, max_range, ignore_root, hits);
}

void Scene::cast_fan(const Eigen::Vector2d& origin, std::span<const Eigen::Vector2d> directions, double max_range,
                     ModelId ignore_root, std::span<RayHit> hits) const {
  if (directions.size() != hits.size()) {
    throw std::invalid_argument("Scene::cast_fan: " + std::to_string(directions.size()) + " directions but room for " +
                                std::to_string(hits.size()) + " hits");
  }
  thread_local std::vector<SceneRay> rays;  // for the cases cast_all answers, and the bodies
  const auto as_rays = [&] {
    rays.resize(directions.size());
    for (std::size_t i = 0; i < directions.size(); ++i) rays[i] = {origin, directions[i]};
    return std::span<const SceneRay>(rays);
  };
  if (!(max_range > 0.0) || !on_map(origin)) {  // nothing to walk, or a walk that starts where the ray enters the map
    cast_all(as_rays(), max_range, ignore_root, hits);
    return;
  }
  thread_local std::vector<double> walls;
  walls.resize(directions.size());
  walls_.fan_ranges(origin, directions, max_range, walls);
  for (std::size_t i = 0; i < directions.size(); ++i) {
    hits[i] = walls[i] < max_range ? RayHit{.range = walls[i], .model = kNoModel, .wall = true}
                                   : RayHit{.range = max_range};
  }
  if (visible_bodies_beyond(ignore_root)) add_bodies(as_rays(), max_range, ignore_root, hits);
}

void Scene::add_bodies(std::span<const SceneRay> rays, double max_range, ModelId ignore_root,
                       std::span<RayHit> hits) const {
  if (!visible_bodies_beyond(ignore_root) || !(max_range > 0.0)) return;
  if (rays.size() >= kFewestRaysToFile) {
    nearest_bodies(rays, ignore_root, hits);
    return;
  }
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (rays[i].direction.allFinite() && rays[i].origin.allFinite()) {
      nearest_body(rays[i].origin, rays[i].direction, ignore_root, nullptr, hits[i]);
    }
  }
}

// The rays' bodies at once: every body within reach of any ray is found
// once, and filed under the sectors of directions (seen from the rays'
// centre) in which a ray could meet it, so that a ray tests only the few
// bodies of its sector. A sensor's rays fan out from one place (a laser)
// or a few close places (a sonar ring), so each sector holds few bodies.
void Scene::nearest_bodies(std::span<const SceneRay> rays, ModelId ignore_root, std::span<RayHit> hits) const {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  std::size_t counted = 0;
  for (const SceneRay& ray : rays) {
    if (!ray.origin.allFinite() || !ray.direction.allFinite()) continue;
    centre += ray.origin;
    ++counted;
  }
  if (counted == 0) return;
  centre /= static_cast<double>(counted);
  // Every ray ends within `gather` of the centre: at its wall, or at
  // max_range (hits hold the walls' answers so far).
  double spread_squared = 0.0, longest = 0.0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const SceneRay& ray = rays[i];
    if (!ray.origin.allFinite() || !ray.direction.allFinite()) continue;
    spread_squared = std::max(spread_squared, (ray.origin - centre).squaredNorm());
    longest = std::max(longest, hits[i].range);
  }
  const double spread = std::sqrt(spread_squared), gather = spread + longest;

  // Bodies whose bounding circle comes within reach of some ray.
  thread_local std::vector<ModelId> near;
  near.clear();
  index_.near_solid(centre, gather, [&](const CellSlot& slot) {
    if (slot.root == ignore_root || !slot.ranger_visible) return;
    const double dx = slot.x - centre.x(), dy = slot.y - centre.y(), within = gather + slot.reach;
    if (dx * dx + dy * dy <= within * within) near.push_back(slot.id);
  });
  if (near.empty()) return;
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());

  // The bounding circle rejects most: off the ray, behind it, or beyond
  // what it already met. Walls win ties, as in cast().
  const auto try_body = [this](const SceneRay& ray, ModelId id, const Eigen::Vector2d& centre_of, double reach,
                               RayHit& hit) {
    const double to_x = centre_of.x() - ray.origin.x(), to_y = centre_of.y() - ray.origin.y();
    const double along = to_x * ray.direction.x() + to_y * ray.direction.y();
    if (along + reach < 0.0 || along - reach >= hit.range) return;
    if (std::abs(to_x * ray.direction.y() - to_y * ray.direction.x()) > reach) return;
    const double entry = ray_entry(index_.body(id).shape, ray.origin, ray.direction);
    if (entry < hit.range) hit = {.range = entry, .model = id, .wall = false};
  };

  // Sectors as one array: bodies of sector k are filed[first[k], first[k + 1]).
  thread_local std::vector<BatchBody> bodies;
  thread_local std::vector<std::pair<int, int>> spans;  // each body's sectors, first to last counter-clockwise
  thread_local std::vector<int> first;
  thread_local std::vector<int> filed;
  bodies.clear();
  spans.clear();
  first.assign(kDirectionSectors + 1, 0);
  const auto each_sector = [](std::pair<int, int> span, auto&& visit) {
    for (int sector = span.first;; sector = (sector + 1) % kDirectionSectors) {
      visit(sector);
      if (sector == span.second) break;
    }
  };
  for (const ModelId id : near) {
    const PlacedBody& shape = index_.body(id).shape;
    const double reach = shape.bounding_radius * (1.0 + 1e-9) + 1e-12;
    bodies.push_back({id, shape.centre, reach});
    // The directions from `centre` along which a line comes within
    // reach + spread of the body's centre: any ray of the batch that meets
    // the body points along one of them.
    const Eigen::Vector2d to_body = shape.centre - centre;
    const double distance = to_body.norm();
    const double widened = reach + spread;
    std::pair<int, int> span{0, kDirectionSectors - 1};
    if (distance > widened * (1.0 + 1e-9)) {
      const double sine = widened / distance, cosine = std::sqrt(1.0 - sine * sine);
      const Eigen::Vector2d toward = to_body / distance;
      const Eigen::Vector2d left(cosine * toward.x() - sine * toward.y(), sine * toward.x() + cosine * toward.y());
      const Eigen::Vector2d right(cosine * toward.x() + sine * toward.y(), -sine * toward.x() + cosine * toward.y());
      // One sector more each side: rounding in the tangents and sectors.
      span = {(direction_sector(right) + kDirectionSectors - 1) % kDirectionSectors,
              (direction_sector(left) + 1) % kDirectionSectors};
      const int covered = (span.second - span.first + kDirectionSectors) % kDirectionSectors + 1;
      if (covered >= kDirectionSectors - 1) span = {0, kDirectionSectors - 1};
    }
    spans.push_back(span);
    each_sector(span, [&](int sector) { ++first[static_cast<std::size_t>(sector) + 1]; });
  }
  for (int sector = 0; sector < kDirectionSectors; ++sector) {
    first[static_cast<std::size_t>(sector) + 1] += first[static_cast<std::size_t>(sector)];
  }
  filed.resize(static_cast<std::size_t>(first.back()));
  {
    thread_local std::vector<int> fill;
    fill.assign(first.begin(), first.end() - 1);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      each_sector(spans[b], [&](int sector) {
        filed[static_cast<std::size_t>(fill[static_cast<std::size_t>(sector)]++)] = static_cast<int>(b);
      });
    }
  }

  for (std::size_t i = 0; i < rays.size(); ++i) {
    const SceneRay& ray = rays[i];
    if (!ray.origin.allFinite() || !ray.direction.allFinite()) continue;
    RayHit& hit = hits[i];
    const auto sector = static_cast<std::size_t>(direction_sector(ray.direction));
    for (int k = first[sector]; k < first[sector + 1]; ++k) {
      const BatchBody& body = bodies[static_cast<std::size_t>(filed[static_cast<std::size_t>(k)])];
      try_body(ray, body.id, body.centre, body.reach, hit);
    }
  }
}

void Scene::nearest_body(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, ModelId ignore_root,
                         const ModelFilter& stops, RayHit& hit) const {
  if (!index_.has_solid_bodies()) return;
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
}

bool Scene::visible_bodies_beyond(ModelId ignore_root) const {
  const auto root = static_cast<std::size_t>(ignore_root);
  const int own = ignore_root >= 0 && root < visible_bodies_by_root_.size() ? visible_bodies_by_root_[root] : 0;
  return visible_bodies_ > own;
}

void Scene::count_visible(const SceneModel& model, int change) {
  if (!model.present || !model.body.present || !(model.returns.ranger >= 0.0)) return;
  visible_bodies_ += change;
  if (model.root < 0) return;
  const auto root = static_cast<std::size_t>(model.root);
  if (root >= visible_bodies_by_root_.size()) visible_bodies_by_root_.resize(root + 1, 0);
  visible_bodies_by_root_[root] += change;
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
  count_visible(models_[slot], +1);
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
  count_visible(model, -1);
  model.present = present;
  count_visible(model, +1);
  if (present) {
    index_.put(id, indexed_body(model));
  } else {
    index_.remove(id);
  }
}

void Scene::set_root(ModelId id, ModelId root) {
  SceneModel& model = models_.at(static_cast<std::size_t>(id));
  count_visible(model, -1);
  model.root = root;
  count_visible(model, +1);
  if (model.present) index_.put(id, indexed_body(model));
}

}  // namespace playerkit::sim
