#include "known_drivers.hpp"

#include "daemon/serve.hpp"

namespace playerkit::player_drivers {

std::vector<core::DriverSpec> drivers_brought_by(const families::FamilyRegistry& families) {
  std::vector<core::DriverSpec> specs;
  for (const auto& family : families.all()) {
    for (core::DriverSpec spec : family.drivers) {
      spec.family = family.name;
      specs.push_back(std::move(spec));
    }
  }
  return specs;
}

core::DriverRegistry known_drivers(const std::vector<std::string>& plugins, const families::FamilyRegistry& families,
                                   core::Logger& logger) {
  core::DriverRegistry registry = daemon::load_drivers(plugins, logger);
  for (auto& spec : drivers_brought_by(families)) registry.add(std::move(spec));
  return registry;
}

}  // namespace playerkit::player_drivers
