#include "probe_options.hpp"

#include <algorithm>
#include <cmath>

#include "config/closest_name.hpp"
#include "protocol/interfaces.hpp"
#include "text/printable.hpp"

namespace playerkit::player_drivers {

ListOptions make_list_options(const ListCommandLine& command_line) {
  ListOptions options;
  options.json = command_line.json;
  if (command_line.interface.empty()) return options;
  const auto* info = protocol::find_interface(command_line.interface);
  if (!info) {
    std::vector<std::string_view> names;
    for (const auto& known : protocol::all_interfaces()) names.push_back(known.name);
    std::string message = "--interface '" + text::excerpt(command_line.interface) + "' is not a Player interface";
    if (const auto nearest = config::closest_name(command_line.interface, names)) {
      message += "; did you mean '" + *nearest + "'?";
    }
    throw UsageError(message);
  }
  options.interface = info->code;
  return options;
}

ProbeOptions make_probe_options(const ProbeCommandLine& command_line) {
  if (command_line.ports.empty()) {
    throw UsageError("probe: name the ports to try, e.g. /dev/ttyUSB0 (or tcp:HOST:PORT for a serial bridge)");
  }
  for (std::size_t i = 0; i < command_line.ports.size(); ++i) {
    if (std::find(command_line.ports.begin(), command_line.ports.begin() + static_cast<std::ptrdiff_t>(i),
                  command_line.ports[i]) != command_line.ports.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw UsageError("probe: port " + command_line.ports[i] + " is named twice");
    }
  }
  if (!std::isfinite(command_line.budget) || command_line.budget < 1.0 || command_line.budget > 120.0) {
    throw UsageError("--budget: 1 to 120 seconds a port");
  }
  ProbeOptions options;
  options.ports = command_line.ports;
  options.json = command_line.json;
  options.verbose = command_line.verbose;
  options.settings.budget = std::chrono::milliseconds(static_cast<long long>(command_line.budget * 1000.0));
  return options;
}

}  // namespace playerkit::player_drivers
