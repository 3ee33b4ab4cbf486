#pragma once
// Turns a loaded config file into devices: one driver per device declaration,
// created through the registry, in file order.

#include "config/config_file.hpp"
#include "core/clock.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/logger.hpp"
#include "core/server_clock.hpp"

namespace playerkit::core {

// Load options whose driver check asks this registry, so that an unknown driver
// is reported at its file:line:col while the file is read.
config::LoadOptions load_options_for(const DriverRegistry& registry, std::uint16_t default_port);

// Adds a device per declaration of `config` to `devices`. Throws
// config::ConfigError (file:line:col) for a driver that is not registered,
// does not serve the declared interface, fails while reading its options, or
// claims `clock` when another device's clock holds it (a second replay or
// simulation keeping the server's time).
void instantiate_devices(const config::ConfigFile& config, const DriverRegistry& registry,
                         DeviceTable& devices, ServerClock& clock, Logger& logger);

// Driver::check() on the device of every declaration of `config`, once all
// are instantiated. Throws config::ConfigError at the declaration of the
// first device whose check fails.
void check_devices(const config::ConfigFile& config, DeviceTable& devices);

}  // namespace playerkit::core
