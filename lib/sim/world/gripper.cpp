// Grippers: picking up, carrying and putting down gripper_return models.

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/world/world_state.hpp"

namespace playerkit::sim {

namespace {

// The gripper's mouth: the middle of its body's front edge, facing ahead,
// and how wide the paddles stand apart (the body's width).
struct GripperMouth {
  geometry::Pose2 front;
  double width = 0.0;
};

GripperMouth mouth_of(const SceneModel& gripper) {
  const Eigen::Vector2d& size = gripper.body.size;
  const bool circle = gripper.body.shape == Shape::circle;
  const double depth = std::abs(size.x());
  return {gripper.body_pose.compose({depth / 2.0, 0.0, 0.0}), circle ? depth : std::abs(size.y())};
}

// What a gripper may take: a present, free, top-level gripper_return model
// that is not its own robot. A carried model's scene root is its carrier's.
bool can_be_gripped(const SceneModel& model, ModelId gripper_root) {
  return model.present && model.returns.gripper && model.root == model.id && model.id != gripper_root;
}

// The nearest grippable model whose body centre is between `from` and `to`
// metres ahead of the mouth and between the paddles.
std::optional<ModelId> gripper_finds(const Scene& scene, ModelId gripper_id, double from, double to,
                                     std::vector<ModelId>& near) {
  const SceneModel& gripper = scene.model(gripper_id);
  const GripperMouth mouth = mouth_of(gripper);
  const Eigen::Vector2d middle = mouth.front.transform({(from + to) / 2.0, 0.0});
  scene.models_near(middle, std::hypot((to - from) / 2.0, mouth.width / 2.0), near);
  std::optional<ModelId> nearest;
  double nearest_ahead = 0.0;
  for (const ModelId id : near) {
    const SceneModel& model = scene.model(id);
    if (!can_be_gripped(model, gripper.root)) continue;
    const Eigen::Vector2d local = mouth.front.inverse().transform(model.body_pose.translation());
    if (local.x() < from || local.x() > to || std::abs(local.y()) > mouth.width / 2.0) continue;
    if (!nearest || local.x() < nearest_ahead) {
      nearest = id;
      nearest_ahead = local.x();
    }
  }
  return nearest;
}

}  // namespace

void World::State::update_grippers() {
  for (const ModelId id : grippers) {
    ModelRecord& model = models[static_cast<std::size_t>(id)];
    if (model.active) refresh_gripper_reading(id, std::get<GripperState>(model.device));
  }
}

void World::State::refresh_gripper_reading(ModelId id, GripperState& gripper) {
  const double reach = std::get<GripperSpec>(models[static_cast<std::size_t>(id)].spec.params).reach;
  GripperReading& reading = gripper.reading;
  reading.paddles = gripper.closed ? GripperPaddles::closed : GripperPaddles::open;
  // The inner beam crosses between the paddles, the outer one just ahead of their tips.
  reading.inner_beam = !gripper.held.empty() || gripper_finds(scene, id, 0.0, reach, near_scratch).has_value();
  reading.outer_beam = gripper_finds(scene, id, reach, 2.0 * reach, near_scratch).has_value();
  reading.carried = static_cast<int>(gripper.held.size()) + gripper.consumed;
  reading.time = time;
}

void World::State::release(GripperState& gripper, ModelId held) {
  gripper.held.erase(std::remove(gripper.held.begin(), gripper.held.end(), held), gripper.held.end());
  ModelRecord& model = record(held);
  model.carried_by = kNoModel;
  model.local = global(held);  // put down where it is: in front of the paddles
  set_scene_root(held, held);
}

void World::close_gripper(ModelId id) {
  State& world = *state_;
  auto& gripper = world.device<GripperState>(id, "gripper");
  const auto& spec = std::get<GripperSpec>(world.record(id).spec.params);
  gripper.closed = true;
  const bool room = spec.consume || static_cast<int>(gripper.held.size()) < spec.capacity;
  const std::optional<ModelId> taken =
      room ? gripper_finds(world.scene, id, 0.0, spec.reach, world.near_scratch) : std::nullopt;
  if (taken) {
    if (spec.consume) {
      world.for_each_riding(*taken, world.global(*taken), false,
                            [&](ModelId riding, const geometry::Pose2&, bool) { world.scene.set_present(riding, false); });
      ++gripper.consumed;
    } else {
      // Carried: it rides on the gripper where it was picked up, in its tree.
      ModelRecord& model = world.record(*taken);
      model.carried_by = id;
      model.local = world.global(id).between(world.global(*taken));
      gripper.held.push_back(*taken);
      world.set_scene_root(*taken, world.scene.model(id).root);
    }
  }
  world.refresh_gripper_reading(id, gripper);
}

void World::open_gripper(ModelId id) {
  State& world = *state_;
  auto& gripper = world.device<GripperState>(id, "gripper");
  gripper.closed = false;
  const std::vector<ModelId> held = gripper.held;
  for (const ModelId model : held) world.release(gripper, model);
  world.refresh_gripper_reading(id, gripper);
}

const GripperReading& World::gripper(ModelId id) const { return state_->device<GripperState>(id, "gripper").reading; }

}  // namespace playerkit::sim
