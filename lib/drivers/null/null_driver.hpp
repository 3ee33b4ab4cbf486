#pragma once
// `null` (manual §6.2): a device on the `null` interface (code 256) that
// publishes nothing, takes no commands and answers every request NACK. Useful
// as a placeholder in a config file; 1.5 had no driver of this name (its
// `null` devices were served by writelog, which is a separate driver here).

#include "core/driver.hpp"
#include "core/driver_registry.hpp"

namespace playerkit::drivers {

// Nothing to override: the Driver defaults are exactly the null behaviour.
class NullDriver final : public core::Driver {};

// Name, interface, access and factory for the registry.
core::DriverSpec null_driver_spec();

}  // namespace playerkit::drivers
