#pragma once
// The paths robots took, for a picture of the world: a caller feeds it the
// world after each step (or as often as it likes) and the renderer draws
// each robot's trail. Bounded: a trail keeps its newest points only.
//
//   render::Trails trails({.max_points = 2000});
//   for (...) { world.step(); trails.record(world); }
//   render::write_world_png("run.png", world, &trails);

#include <Eigen/Core>

#include <cstddef>
#include <deque>
#include <map>
#include <vector>

#include "sim/world/model_spec.hpp"
#include "sim/world/world.hpp"

namespace playerkit::sim::render {

struct TrailOptions {
  std::size_t max_points = 2000;  // per robot; the oldest go first
  // A point closer than this to the trail's last one is not kept, so a
  // robot standing still does not use up its trail.
  double min_spacing = 0.02;  // m
};

class Trails {
 public:
  explicit Trails(TrailOptions options = {});

  // The true position of every top-level position model (every robot).
  void record(const World& world);
  // One point of one model's trail, in world metres.
  void add(ModelId model, const Eigen::Vector2d& point);
  void clear();

  // Models with a trail, in id order.
  [[nodiscard]] std::vector<ModelId> models() const;
  // Oldest first; empty for a model without one.
  [[nodiscard]] std::vector<Eigen::Vector2d> points(ModelId model) const;
  [[nodiscard]] const TrailOptions& options() const { return options_; }

 private:
  TrailOptions options_;
  std::map<ModelId, std::deque<Eigen::Vector2d>> trails_;
};

}  // namespace playerkit::sim::render
