#pragma once
// Where a simulated device finds its world. `player-serve -s WORLD` loads the
// world once and hands it to a SimulationSource shared by every simulated
// driver it registers (sim_drivers.hpp); the first device created makes the
// SimulationHost in the device table's connection pool, and the others find
// it there. Without a source (the built-in specs) a simulated device is a
// configuration error: there is no world to serve.
//
// A device names its model by name (`model`, or `gz_id` for the gz_* drivers,
// as 1.5's Gazebo drivers did): the model itself when it is of the kind the
// interface needs, else the first such model on it (depth first, pre-order,
// as Stage's Player plugin looked for one), so `gz_id "robot1"` finds
// robot1's laser for a laser device.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "core/driver_registry.hpp"
#include "drivers/sim/simulation_host.hpp"
#include "sim/world/world.hpp"

namespace playerkit::drivers::sim {

class SimulationSource {
 public:
  // `world_name` keys the host and names the world in messages (its file).
  SimulationSource(playerkit::sim::World world, std::string world_name, SimulationSettings settings);

  // The host of this world in `context`'s connection pool, made (and the
  // world handed to it) by the first device. Throws std::logic_error when the
  // world went to another device table's host already.
  [[nodiscard]] std::shared_ptr<SimulationHost> host(const core::DriverContext& context);

  // The host made by host(), while some device holds it; null before.
  [[nodiscard]] std::shared_ptr<SimulationHost> existing_host() const;
  [[nodiscard]] const std::string& world_name() const { return world_name_; }
  [[nodiscard]] const SimulationSettings& settings() const { return settings_; }

 private:
  const std::string world_name_;
  const SimulationSettings settings_;
  mutable std::mutex mutex_;
  std::optional<playerkit::sim::World> world_;  // until a host takes it
  std::weak_ptr<SimulationHost> host_;
};

// What a device of an interface needs its model to be.
enum class ModelKind { position, laser, sonar, fiducial, blobfinder, ptz, gripper, power, any };

[[nodiscard]] ModelKind model_kind_for(std::uint16_t interface_code);
[[nodiscard]] std::string_view model_kind_name(ModelKind kind);
[[nodiscard]] bool is_of_kind(const playerkit::sim::World& world, playerkit::sim::ModelId model, ModelKind kind);

// The model `name` names if it is of `kind`, else the first of `kind` riding
// on it; nullopt with `why` filled in when there is none.
[[nodiscard]] std::optional<playerkit::sim::ModelId> find_model(const playerkit::sim::World& world,
                                                                std::string_view name, ModelKind kind,
                                                                std::string& why);

}  // namespace playerkit::drivers::sim
