#pragma once
// `player-serve -s WORLD`: the world loaded (lib/sim/worldfile), the
// simulated drivers registered on it (lib/drivers/sim, replacing the built-in
// ones that have no world), and its devices as a configuration read like any
// other. A .cfg given too is read after it, on the same world.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "config/config_file.hpp"
#include "core/driver_registry.hpp"
#include "daemon/serve.hpp"

namespace playerkit::drivers::sim {
class SimulationSource;
}

namespace playerkit::daemon {

struct ServedWorld {
  std::shared_ptr<drivers::sim::SimulationSource> source;
  std::string devices;                // its devices as configuration text
  std::string summary;                // "simple.world (Stage 1.3): 4 devices, step 0.1 s"
  std::vector<std::string> warnings;  // the world file's, "file:line:col: ..."
};

// Throws sim::worldfile::WorldFileError ("file:line:col: message") and
// std::runtime_error (a model name no configuration can hold; a build
// without the simulator, PLAYERKIT_DRIVERS_SIM=OFF).
ServedWorld load_served_world(const SimulationOptions& options, std::uint16_t default_port);

// The simulated drivers, serving `world`.
void register_world_drivers(core::DriverRegistry& registry, const ServedWorld& world);

// The world's devices as a configuration named "<world> (devices)". Throws
// config::ConfigError.
config::ConfigFile world_device_configuration(const ServedWorld& world, const core::DriverRegistry& registry,
                                              std::uint16_t default_port);

}  // namespace playerkit::daemon
