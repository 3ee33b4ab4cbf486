#pragma once
// A name on player-drivers' command line: a driver ("sicklms200") or a driver
// family ("p2os": every driver of one robot, served together on one link).

#include <string>
#include <string_view>
#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::player_drivers {

struct DriverSelection {
  std::string name;                             // as asked
  bool family = false;                          // a family name, not a driver's
  std::vector<const core::DriverSpec*> drivers;  // one, or the family's in serving order
};

// A driver of that name wins over a family of that name (the `null` driver
// of the `null` family). Throws UsageError: no such driver or family, with
// the nearest name when it looks like a typo.
DriverSelection select_drivers(const core::DriverRegistry& registry, std::string_view name);

// The drivers of `family`, in serving order: those named <family>_<interface>
// after an interface they serve first (p2os_position before p2os_compass and
// p2os_gyro, so that it is position:0), then the rest, each group by name.
std::vector<const core::DriverSpec*> family_drivers(const core::DriverRegistry& registry, std::string_view family);

// Family names, sorted, each once.
std::vector<std::string> family_names(const core::DriverRegistry& registry);

}  // namespace playerkit::player_drivers
