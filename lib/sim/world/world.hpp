#pragma once
// A simulated world: a static map, models on it, and a fixed-step clock.
// Pure: no I/O, no threads, no wall time. Everything random is drawn from
// the seed, per model and per step, so the same seed and the same calls at
// the same simulation times give the same world, however fast it is run
// and whichever devices are being read.
//
//   sim::World world({.step = 0.1, .seed = 7}, map);
//   const auto robot = world.add({.name = "r0", .params = sim::PositionSpec{}});
//   const auto laser = world.add({.parent = robot, .params = sim::LaserSpec{}});
//   world.set_active(robot, true);             // a client subscribed
//   world.set_active(laser, true);
//   world.command_velocity(robot, {0.5, 0.0, 0.1});
//   for (int i = 0; i < 10; ++i) world.step();  // one second
//   const sim::LaserScan& scan = world.laser(laser);

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/readings.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim {

struct WorldSettings {
  double step = 0.1;        // s of simulation time per step (Stage's interval_sim)
  std::uint64_t seed = 0;   // sensor noise, odometry error draws
};

// A call named a model that does not exist or is of another kind.
class ModelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class World {
 public:
  // `map`: occupied cells are walls, everything else open floor.
  World(WorldSettings settings, grid::OccupancyGrid map);
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // Adds a model; its parent must exist already. Fills in a generated name
  // (`<type>:<n>`) when the spec has none. Throws ModelError for an unknown
  // parent or a duplicate name.
  ModelId add(ModelSpec spec);

  // ---- time ----
  // Moves every active position model by one step (collisions undo a move
  // and set its stall flag), then updates every active sensor whose
  // interval has passed.
  void step();
  [[nodiscard]] double time() const;            // s since the world was made
  [[nodiscard]] std::uint64_t steps() const;
  [[nodiscard]] const WorldSettings& settings() const;

  // ---- models ----
  [[nodiscard]] std::size_t size() const;
  [[nodiscard]] const ModelSpec& spec(ModelId id) const;
  [[nodiscard]] std::optional<ModelId> find(std::string_view name) const;
  [[nodiscard]] std::vector<ModelId> children(ModelId id) const;  // in creation order
  [[nodiscard]] ModelId root_of(ModelId id) const;
  [[nodiscard]] const Scene& scene() const;

  // Subscribed or not (Stage computes a device's data only while someone
  // reads it, and a position model moves only while subscribed). A model's
  // last deactivation stops a position model (commanded velocity zero).
  void set_active(ModelId id, bool active);
  [[nodiscard]] bool active(ModelId id) const;

  // ---- truth ----
  [[nodiscard]] geometry::Pose2 true_pose(ModelId id) const;  // global
  // Teleports a model (and what rides on it, and what its gripper holds);
  // odometry does not see the jump. A top-level model only.
  void set_true_pose(ModelId id, const geometry::Pose2& pose);

  // ---- position ----
  void command_velocity(ModelId position, const Eigen::Vector3d& velocity);  // x, y (m/s), yaw (rad/s)
  // (a car-drive model reads x as its speed and yaw as its steering angle, rad)
  // Drives towards a goal pose in the localization frame (Stage's go-to:
  // 0.4 m/s and 1 rad/s caps, 2 cm tolerance), until a velocity command.
  void command_pose(ModelId position, const geometry::Pose2& goal);
  void set_odometry(ModelId position, const geometry::Pose2& pose);
  [[nodiscard]] const PositionReading& position(ModelId position) const;

  // ---- sensors: the latest reading (time says when it was taken) ----
  [[nodiscard]] const LaserScan& laser(ModelId laser) const;
  [[nodiscard]] const SonarScan& sonar(ModelId sonar) const;
  [[nodiscard]] const FiducialScan& fiducials(ModelId finder) const;
  [[nodiscard]] const BlobScan& blobs(ModelId blobfinder) const;
  [[nodiscard]] const PtzReading& ptz(ModelId ptz) const;
  [[nodiscard]] const GripperReading& gripper(ModelId gripper) const;
  [[nodiscard]] const PowerReading& power(ModelId power) const;

  // ---- actuators ----
  // The laser's scan: fov and samples (Stage 1.3's set-config).
  void configure_laser(ModelId laser, double fov, int samples);
  void command_ptz(ModelId ptz, double pan, double tilt, double fov);
  void close_gripper(ModelId gripper);  // picks up a gripper_return model between the paddles
  void open_gripper(ModelId gripper);   // puts down what it holds

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace playerkit::sim
