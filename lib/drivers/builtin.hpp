#pragma once
// The drivers compiled into playerkit. The server calls this once before
// loading plugins, so a plugin of the same name replaces a built-in driver.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

// Adds every driver of every family built (lib/drivers/<family>, each left
// out with -DPLAYERKIT_DRIVERS_<FAMILY>=OFF), each spec's `family` set.
void register_builtin_drivers(core::DriverRegistry& registry);

}  // namespace playerkit::drivers
