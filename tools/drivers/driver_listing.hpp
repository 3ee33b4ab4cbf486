#pragma once
// `player-drivers list` and `player-drivers info`: what the driver registry
// knows, as aligned text for people or JSON lines for programs. Drivers
// without documentation (plugins, older drivers) still list and show what
// the registry has, with a generated config section.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "core/driver_registry.hpp"

namespace playerkit::player_drivers {

struct ListOptions {
  std::optional<std::uint16_t> interface;  // only drivers serving it
  bool json = false;                        // one JSON object per driver and line
};

// One line per driver, sorted by name; then (text only) the families.
// Returns the number of drivers listed.
std::size_t write_driver_list(const core::DriverRegistry& registry, const ListOptions& options, std::ostream& out);

// A driver's summary, options (type, default, unit), requests, manual section
// and a config section to paste; for a family, its drivers and the sections
// of all of them. json: one JSON object. Throws UsageError for an unknown name.
void write_driver_info(const core::DriverRegistry& registry, std::string_view name, bool json, std::ostream& out);

// The driver's documented example, else `<interface>:0 ( driver "NAME" )`.
std::string config_section(const core::DriverSpec& spec);

// "r (read: data, requests)" and the like.
std::string access_text(protocol::Access access);

}  // namespace playerkit::player_drivers
