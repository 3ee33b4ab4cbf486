#include "families/sick/driver/sickpls_driver.hpp"

#include <memory>

#include "core/option_reader.hpp"
#include "families/sick/driver/sick_driver_docs.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

core::DriverSpec sickpls_driver_spec() {
  core::DriverSpec spec;
  spec.name = "sickpls";
  spec.interfaces = {protocol::kLaserCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext& context) {
    const core::OptionReader options(context.section, "sickpls");
    return std::make_unique<sick_laser::SickLaserDriver>(
        sick_laser::read_settings(options, hardware::sick::Model::pls));
  };
  spec.limits = core::DeviceLimits{.request_queue = 10};  // as 1.5 registered it
  spec.summary = "SICK PLS laser scanner on a serial port (8E1; or a tcp: bridge)";
  spec.doc = sick_laser::sick_driver_doc(hardware::sick::Model::pls);
  return spec;
}

}  // namespace playerkit::drivers
