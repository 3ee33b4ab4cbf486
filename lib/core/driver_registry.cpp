#include "core/driver_registry.hpp"

namespace playerkit::core {

DeviceLimits DriverSpec::limits_for(std::uint16_t interface) const {
  const auto it = interface_limits.find(interface);
  return it == interface_limits.end() ? limits : it->second;
}

void DriverRegistry::add(DriverSpec spec) {
  std::string name = spec.name;
  drivers_.insert_or_assign(std::move(name), std::move(spec));
}

const DriverSpec* DriverRegistry::find(std::string_view name) const {
  const auto it = drivers_.find(name);
  return it == drivers_.end() ? nullptr : &it->second;
}

std::vector<const DriverSpec*> DriverRegistry::all() const {
  std::vector<const DriverSpec*> specs;
  specs.reserve(drivers_.size());
  for (const auto& [name, spec] : drivers_) specs.push_back(&spec);
  return specs;
}

}  // namespace playerkit::core
