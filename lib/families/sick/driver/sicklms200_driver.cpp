#include "families/sick/driver/sicklms200_driver.hpp"

#include <memory>

#include "core/option_reader.hpp"
#include "families/sick/driver/sick_driver_docs.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

core::DriverSpec sicklms200_driver_spec() {
  core::DriverSpec spec;
  spec.name = "sicklms200";
  spec.interfaces = {protocol::kLaserCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext& context) {
    const core::OptionReader options(context.section, "sicklms200");
    return std::make_unique<sick_laser::SickLaserDriver>(
        sick_laser::read_settings(options, hardware::sick::Model::lms200));
  };
  spec.limits = core::DeviceLimits{.request_queue = 10};  // as 1.5 registered it
  spec.summary = "SICK LMS 200 laser range-finder on a serial port (or a tcp: bridge)";
  spec.doc = sick_laser::sick_driver_doc(hardware::sick::Model::lms200);
  return spec;
}

}  // namespace playerkit::drivers
