#pragma once
// Internal: what a World holds, shared by the files that implement it
// (world.cpp: models and truth; motion.cpp: position models;
// collisions.cpp; sensors_step.cpp; gripper.cpp; power.cpp).

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/world.hpp"

namespace playerkit::sim {

// When a sensor last took a reading; none: at the next step (it was just
// switched on).
struct SensorClock {
  std::optional<std::uint64_t> last_step;
  // Whether `interval` seconds have passed at step `now`, counted in whole
  // steps so that float time cannot make a reading come a step late.
  [[nodiscard]] bool due(std::uint64_t now, double step, double interval) const {
    if (!last_step) return true;
    return static_cast<double>(now - *last_step) * step >= interval * (1.0 - 1e-9);
  }
};

struct PositionState {
  Eigen::Vector3d command = Eigen::Vector3d::Zero();   // as given (car: speed, unused, steering angle)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // moving at: x, y (robot frame), yaw rate
  std::optional<geometry::Pose2> goal;                 // command_pose, in the localization frame
  bool always_on = false;                              // started with a velocity: moves unsubscribed
  bool stalled = false;
  geometry::Pose2 origin;    // the localization frame, in the world
  geometry::Pose2 odometry;  // in the localization frame
  Eigen::Vector3d odom_error = Eigen::Vector3d::Zero();
  PositionReading reading;
};

struct LaserState {
  LaserSpec spec;  // configure_laser changes fov and samples until deactivation
  SensorClock clock;
  LaserScan scan;
};

struct SonarState {
  SensorClock clock;
  SonarScan scan;
  std::vector<Eigen::Vector2d> headings;  // transducer_headings(spec), computed once
};

struct FiducialState {
  SensorClock clock;
  FiducialScan scan;
};

struct BlobfinderState {
  SensorClock clock;
  BlobScan scan;
};

struct PtzState {
  double pan = 0.0;
  double fov = 0.0;
  SensorClock clock;
  PtzReading reading;
};

struct GripperState {
  bool closed = false;
  std::vector<ModelId> held;  // carried, in pick-up order
  int consumed = 0;
  GripperReading reading;
};

struct PowerState {
  double joules = 0.0;
  SensorClock clock;
  PowerReading reading;
};

// Objects and truth models keep no state of their own.
using DeviceState = std::variant<std::monostate, PositionState, LaserState, SonarState, FiducialState,
                                 BlobfinderState, PtzState, GripperState, PowerState>;

struct ModelRecord {
  ModelSpec spec;
  std::vector<ModelId> children;  // creation order
  ModelId root = kNoModel;        // top-level ancestor (carrying does not change it)
  // Pose in the parent's frame (the world's at top level); while carried,
  // in the carrying gripper's frame.
  geometry::Pose2 local;
  ModelId carried_by = kNoModel;  // the gripper holding it
  bool active = false;
  DeviceState device;
};

struct World::State {
  WorldSettings settings;
  Scene scene;
  std::vector<ModelRecord> models;
  std::map<std::string, ModelId, std::less<>> names;
  std::vector<ModelId> top_level;
  std::vector<ModelId> positions;  // update order: creation order
  std::vector<ModelId> sensors;    // lasers, sonars, finders, blobfinders, ptzs, powers
  std::vector<ModelId> grippers;
  std::vector<ModelId> powers;
  double time = 0.0;
  std::uint64_t steps = 0;
  std::vector<ModelId> near_scratch;  // collision queries, reused

  State(WorldSettings world_settings, grid::OccupancyGrid map)
      : settings(world_settings), scene(std::move(map)) {}

  // Checked access; ModelError names the model and what it is.
  ModelRecord& record(ModelId id);
  [[nodiscard]] const ModelRecord& record(ModelId id) const;
  template <typename Device>
  Device& device(ModelId id, std::string_view wanted) {
    if (auto* found = std::get_if<Device>(&record(id).device)) return *found;
    throw_wrong_kind(id, wanted);
  }
  template <typename Device>
  const Device& device(ModelId id, std::string_view wanted) const {
    if (const auto* found = std::get_if<Device>(&record(id).device)) return *found;
    throw_wrong_kind(id, wanted);
  }
  [[noreturn]] void throw_wrong_kind(ModelId id, std::string_view wanted) const;
  [[nodiscard]] std::string describe(ModelId id) const;  // `model 3 ("r0.laser:0")`

  [[nodiscard]] const geometry::Pose2& global(ModelId id) const { return scene.model(id).pose; }
  [[nodiscard]] geometry::Pose2 parent_global(ModelId id) const;

  // Visits a model and what rides on it (children, and what its gripper
  // holds, flagged `carried`) at their global poses, given the model's.
  template <typename Visit>
  void for_each_riding(ModelId id, const geometry::Pose2& pose, bool carried, Visit&& visit) const {
    visit(id, pose, carried);
    const ModelRecord& model = models[static_cast<std::size_t>(id)];
    for (const ModelId child : model.children) {
      for_each_riding(child, pose.compose(models[static_cast<std::size_t>(child)].local), carried, visit);
    }
    if (const auto* gripper = std::get_if<GripperState>(&model.device)) {
      for (const ModelId held : gripper->held) {
        for_each_riding(held, pose.compose(models[static_cast<std::size_t>(held)].local), true, visit);
      }
    }
  }
  // Puts a model at a global pose, and everything riding on it; keeps the scene current.
  void place(ModelId id, const geometry::Pose2& pose);
  void set_scene_root(ModelId id, ModelId root);  // the model's tree (and what it carries)

  // The steps of step(), each in its own file.
  void move_positions();
  void move_position(ModelId id, PositionState& position);
  void refresh_position_reading(ModelId id, PositionState& position) const;
  [[nodiscard]] bool collides_at(ModelId id, const geometry::Pose2& pose);
  void drain_power();
  void update_sensors();
  void update_sensor(ModelId id);
  void update_grippers();
  void refresh_gripper_reading(ModelId id, GripperState& gripper);
  void release(GripperState& gripper, ModelId held);  // puts it down where it is
};

}  // namespace playerkit::sim
