// Built without the simulator's drivers (PLAYERKIT_DRIVERS_SIM=OFF): -s says so.
#include <stdexcept>

#include "daemon/simulation.hpp"

namespace playerkit::daemon {

namespace {

[[noreturn]] void no_simulator() {
  throw std::runtime_error("-s: this playerkit was built without the simulator (PLAYERKIT_DRIVERS_SIM=OFF)");
}

}  // namespace

ServedWorld load_served_world(const SimulationOptions&, std::uint16_t) { no_simulator(); }

void register_world_drivers(core::DriverRegistry&, const ServedWorld&) { no_simulator(); }

config::ConfigFile world_device_configuration(const ServedWorld&, const core::DriverRegistry&, std::uint16_t) {
  no_simulator();
}

}  // namespace playerkit::daemon
