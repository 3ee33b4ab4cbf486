#include "drivers/builtin.hpp"

namespace playerkit::drivers {

// builtin_drivers.cpp, generated from the families built.
void register_built_families(core::DriverRegistry& registry);

void register_builtin_drivers(core::DriverRegistry& registry) { register_built_families(registry); }

}  // namespace playerkit::drivers
