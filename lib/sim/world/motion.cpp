// Position models: commands, one step of motion, odometry and gps.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/world/kinematics.hpp"
#include "sim/world/world_state.hpp"

namespace playerkit::sim {

namespace {

bool is_finite_pose(const geometry::Pose2& pose) {
  return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw);
}

}  // namespace

void World::State::move_positions() {
  for (const ModelId id : positions) {
    ModelRecord& model = models[static_cast<std::size_t>(id)];
    auto& position = std::get<PositionState>(model.device);
    if (model.active || position.always_on) {
      move_position(id, position);
    } else {
      position.stalled = false;
    }
    refresh_position_reading(id, position);
  }
}

void World::State::move_position(ModelId id, PositionState& position) {
  ModelRecord& model = models[static_cast<std::size_t>(id)];
  const auto& spec = std::get<PositionSpec>(model.spec.params);
  const double dt = settings.step;
  if (position.goal) position.command = go_to_command(spec, position.reading.pose, *position.goal, dt);
  position.velocity = accelerate(position.velocity, drive_velocity(spec, position.command), spec.max_acceleration, dt);

  const geometry::Pose2 motion = step_motion(position.velocity, dt);
  if (motion.x == 0.0 && motion.y == 0.0 && motion.yaw == 0.0) {
    position.stalled = false;
    return;
  }
  const geometry::Pose2 moved = model.local.compose(motion);
  const geometry::Pose2 pose = parent_global(id).compose(moved);
  if (collides_at(id, pose)) {
    // Stage: the move is undone, the command kept; Stage 1.3 (Player
    // 1.5's) odometry does not advance either (stage-worlds.md §3.5).
    position.stalled = true;
    return;
  }
  position.stalled = false;
  model.local = moved;
  place(id, pose);
  position.odometry = position.odometry.compose(odometry_motion(motion, position.odom_error));
}

void World::State::refresh_position_reading(ModelId id, PositionState& position) const {
  const auto& spec = std::get<PositionSpec>(models[static_cast<std::size_t>(id)].spec.params);
  PositionReading& reading = position.reading;
  reading.pose = spec.localization == Localization::gps
                     ? position.origin.between(global(id))
                     : position.odometry;
  reading.velocity = {position.velocity.x(), position.velocity.y(), position.velocity.z()};
  reading.stalled = position.stalled;
  reading.time = time;
}

void World::command_velocity(ModelId id, const Eigen::Vector3d& velocity) {
  auto& position = state_->device<PositionState>(id, "position");
  if (!velocity.allFinite()) {
    throw std::invalid_argument("command_velocity: " + state_->describe(id) + ": the velocity is not finite");
  }
  position.command = velocity;
  position.goal.reset();
}

void World::command_pose(ModelId id, const geometry::Pose2& goal) {
  auto& position = state_->device<PositionState>(id, "position");
  if (!is_finite_pose(goal)) {
    throw std::invalid_argument("command_pose: " + state_->describe(id) + ": the goal is not finite");
  }
  position.goal = goal;
}

void World::set_odometry(ModelId id, const geometry::Pose2& pose) {
  State& world = *state_;
  auto& position = world.device<PositionState>(id, "position");
  if (!is_finite_pose(pose)) {
    throw std::invalid_argument("set_odometry: " + world.describe(id) + ": the pose is not finite");
  }
  if (std::get<PositionSpec>(world.record(id).spec.params).localization == Localization::gps) {
    // gps reports the true pose in the origin's frame: move the frame so
    // that the true pose reads `pose` there.
    position.origin = world.global(id).compose(pose.inverse());
  }
  position.odometry = {pose.x, pose.y, geometry::normalize_angle(pose.yaw)};
  world.refresh_position_reading(id, position);
}

const PositionReading& World::position(ModelId id) const {
  return state_->device<PositionState>(id, "position").reading;
}

}  // namespace playerkit::sim
