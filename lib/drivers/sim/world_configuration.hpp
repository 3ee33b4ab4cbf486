#pragma once
// `player-serve -s WORLD` serves every device of the world with no
// configuration file, as Player 1.5 with Stage 1.3 did: each device on its
// robot's port (the world's `port`, else -p), in world order, its driver the
// world file's type word (`position`, `laser`, `lbd`, ...), which is what
// 1.5 reported for them. The devices are written as configuration text, so
// that they are made exactly like the devices of a .cfg:
//
//   robot:6665 ( )
//   position:0 ( driver "position" model "robot1" )
//   laser:0 ( driver "laser" model "robot1.laser:0" )
//   ...
//   simulation:0 ( driver "simulation" alwayson 1 )   # on the default port, last
//
// plus a `simulation` device (run control, simulated_drivers.hpp) on the
// default port.

#include <cstdint>
#include <string>
#include <vector>

#include "sim/world/world.hpp"
#include "sim/worldfile/world_loader.hpp"

namespace playerkit::drivers::sim {

// Throws std::runtime_error for a model name a configuration cannot hold
// (a double quote or a line break in it).
[[nodiscard]] std::string world_configuration(const playerkit::sim::World& world,
                                              const std::vector<playerkit::sim::worldfile::SimDevice>& devices,
                                              std::uint16_t default_port);

// The driver that serves a world device: its type word when a simulated
// driver has that name, else the Stage 1.3 word of its interface.
[[nodiscard]] std::string world_device_driver(const playerkit::sim::worldfile::SimDevice& device);

}  // namespace playerkit::drivers::sim
