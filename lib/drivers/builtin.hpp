#pragma once
// The drivers compiled into playerkit. The server calls this once before
// loading plugins, so a plugin of the same name replaces a built-in driver.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

// Adds null, lifomcom and udpbroadcast.
void register_builtin_drivers(core::DriverRegistry& registry);

}  // namespace playerkit::drivers
