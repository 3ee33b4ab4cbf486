#include "drivers/null/null_driver.hpp"

#include <memory>

#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

core::DriverSpec null_driver_spec() {
  core::DriverSpec spec;
  spec.name = "null";
  spec.interfaces = {protocol::kNullCode};
  // Read like writelog, 1.5's server for this interface: there is never
  // anything to write to it.
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext&) { return std::make_unique<NullDriver>(); };
  spec.limits = core::DeviceLimits{};
  spec.summary = "placeholder device on the null interface: no data, every request NACK";
  spec.doc.example = "null:0 ( driver \"null\" )";
  return spec;
}

}  // namespace playerkit::drivers
