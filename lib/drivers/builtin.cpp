#include "drivers/builtin.hpp"

#include "drivers/amcl/amcl_driver.hpp"
#include "drivers/comms/udpbroadcast_driver.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "drivers/logfile/writelog_driver.hpp"
#include "drivers/mcom/lifomcom_driver.hpp"
#include "drivers/null/null_driver.hpp"
#include "drivers/passthrough/passthrough_driver.hpp"

namespace playerkit::drivers {

void register_builtin_drivers(core::DriverRegistry& registry) {
  registry.add(null_driver_spec());
  registry.add(lifomcom_driver_spec());
  registry.add(udpbroadcast_driver_spec());
  registry.add(passthrough_driver_spec());
  registry.add(readlog_driver_spec());
  registry.add(writelog_driver_spec());
  registry.add(amcl_driver_spec());
}

}  // namespace playerkit::drivers
