#pragma once
// For the sensor tests only: a walled room to put bodies in, and a ray cast
// of its own (a march in 0.5 mm steps testing the map cell and each body's
// shape at every point) to check the scene's answers against.

#include <Eigen/Core>

#include <cmath>
#include <utility>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim::sensor_test_support {

inline constexpr double kCell = 0.05;  // m
inline constexpr double kMarchStep = 0.0005;  // m

// A 10 x 10 m room centred on the origin, its border cells walls, free
// inside. Further walls are filled with add_wall.
inline grid::OccupancyGrid room() {
  grid::OccupancyGrid map = grid::OccupancyGrid::centred(200, 200, kCell, grid::CellState::free);
  for (int i = 0; i < 200; ++i) {
    map.set(i, 0, grid::CellState::occupied);
    map.set(i, 199, grid::CellState::occupied);
    map.set(0, i, grid::CellState::occupied);
    map.set(199, i, grid::CellState::occupied);
  }
  return map;
}

// Marks occupied every cell whose centre lies in [x0, x1] x [y0, y1].
inline void add_wall(grid::OccupancyGrid& map, double x0, double y0, double x1, double y1) {
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const Eigen::Vector2d centre = map.cell_centre({col, row});
      if (centre.x() >= x0 && centre.x() <= x1 && centre.y() >= y0 && centre.y() <= y1) {
        map.set(col, row, grid::CellState::occupied);
      }
    }
  }
}

// Adds a model with the next id; `root` kNoModel makes it its own root.
inline ModelId add_model(Scene& scene, const geometry::Pose2& pose, Body body, Returns returns = {},
                         Rgb color = {}, ModelId root = kNoModel) {
  const auto id = static_cast<ModelId>(scene.models().size());
  SceneModel model;
  model.id = id;
  model.root = root == kNoModel ? id : root;
  model.pose = pose;
  model.body_pose = pose.compose(body.offset);
  model.body = std::move(body);
  model.color = color;
  model.returns = returns;
  scene.add(std::move(model));
  return id;
}

inline Body box(double length, double width) { return {.shape = Shape::rectangle, .size = {length, width}}; }
inline Body disc(double diameter) { return {.shape = Shape::circle, .size = {diameter, diameter}}; }
inline Body no_body() { return {.present = false}; }

// A body in the plain numbers the march tests points against.
struct MarchedBody {
  ModelId id = kNoModel;
  double x = 0.0, y = 0.0, cos_yaw = 1.0, sin_yaw = 0.0;
  bool circle = false;
  double half_length = 0.0, half_width = 0.0;  // a circle's radius in half_length

  bool contains(double px, double py) const {
    const double dx = px - x, dy = py - y;
    const double along = cos_yaw * dx + sin_yaw * dy, across = -sin_yaw * dx + cos_yaw * dy;
    if (circle) return along * along + across * across <= half_length * half_length;
    return std::abs(along) <= half_length && std::abs(across) <= half_width;
  }
};

struct MarchedHit {
  double range = 0.0;
  ModelId model = kNoModel;
};

// The first point along the ray, in kMarchStep steps, inside an occupied
// cell or inside the body of a model outside `own_root`'s tree that
// `stops` accepts; max_range when there is none. Never short of the true
// range, and less than one step beyond it.
template <typename Stops>
MarchedHit march(const Scene& scene, const Eigen::Vector2d& origin, double angle, double max_range, ModelId own_root,
                 Stops stops) {
  std::vector<MarchedBody> bodies;
  for (const SceneModel& model : scene.models()) {
    if (!model.present || !model.body.present || model.root == own_root || !stops(model)) continue;
    const bool circle = model.body.shape == Shape::circle;
    bodies.push_back({model.id, model.body_pose.x, model.body_pose.y, std::cos(model.body_pose.yaw),
                      std::sin(model.body_pose.yaw), circle, model.body.size.x() / 2.0,
                      circle ? 0.0 : model.body.size.y() / 2.0});
  }
  const grid::OccupancyGrid& map = scene.map();
  const double dx = std::cos(angle), dy = std::sin(angle);
  const auto steps = static_cast<long>(std::ceil(max_range / kMarchStep));
  for (long step = 0; step < steps; ++step) {
    const double distance = static_cast<double>(step) * kMarchStep;
    const double px = origin.x() + distance * dx, py = origin.y() + distance * dy;
    const auto col = static_cast<int>(std::floor((px - map.origin().x()) / map.resolution()));
    const auto row = static_cast<int>(std::floor((py - map.origin().y()) / map.resolution()));
    if (map.contains(col, row) && map.at(col, row) == grid::CellState::occupied) return {distance, kNoModel};
    for (const MarchedBody& body : bodies) {
      if (body.contains(px, py)) return {distance, body.id};
    }
  }
  return {max_range, kNoModel};
}

// What rangers (lasers, sonars) stop on.
inline bool ranger_stops(const SceneModel& model) { return model.returns.ranger >= 0.0; }
// What cameras and line-of-sight rays stop on: every body.
inline bool any_body_stops(const SceneModel&) { return true; }

// Sample mean and standard deviation.
template <typename Values>
std::pair<double, double> mean_and_sd(const Values& values) {
  double sum = 0.0, squares = 0.0;
  for (const double v : values) sum += v;
  const double mean = sum / static_cast<double>(values.size());
  for (const double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / static_cast<double>(values.size() - 1))};
}

}  // namespace playerkit::sim::sensor_test_support
