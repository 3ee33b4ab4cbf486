#include "sim/render/trails.hpp"

#include <variant>

namespace playerkit::sim::render {

Trails::Trails(TrailOptions options) : options_(options) {}

void Trails::record(const World& world) {
  for (std::size_t index = 0; index < world.size(); ++index) {
    const auto id = static_cast<ModelId>(index);
    const ModelSpec& spec = world.spec(id);
    if (spec.parent != kNoModel || !std::holds_alternative<PositionSpec>(spec.params)) continue;
    add(id, world.true_pose(id).translation());
  }
}

void Trails::add(ModelId model, const Eigen::Vector2d& point) {
  if (options_.max_points == 0 || !point.allFinite()) return;
  std::deque<Eigen::Vector2d>& trail = trails_[model];
  if (!trail.empty() && (point - trail.back()).norm() < options_.min_spacing) return;
  trail.push_back(point);
  while (trail.size() > options_.max_points) trail.pop_front();
}

void Trails::clear() { trails_.clear(); }

std::vector<ModelId> Trails::models() const {
  std::vector<ModelId> ids;
  for (const auto& [id, trail] : trails_) {
    if (!trail.empty()) ids.push_back(id);
  }
  return ids;
}

std::vector<Eigen::Vector2d> Trails::points(ModelId model) const {
  const auto found = trails_.find(model);
  if (found == trails_.end()) return {};
  return {found->second.begin(), found->second.end()};
}

}  // namespace playerkit::sim::render
