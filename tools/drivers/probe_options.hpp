#pragma once
// The small subcommands' flags, checked: `list --interface NAME` and
// `probe PORT...`. Pure; UsageError names the flag at fault.

#include <string>
#include <vector>

#include "driver_listing.hpp"
#include "drivers_exit_status.hpp"
#include "families/port_probe.hpp"

namespace playerkit::player_drivers {

struct ListCommandLine {
  std::string interface;  // empty: all
  bool json = false;
};

// Throws UsageError for an interface name Player 1.5 does not have.
ListOptions make_list_options(const ListCommandLine& command_line);

struct ProbeCommandLine {
  std::vector<std::string> ports;
  bool json = false;
  bool verbose = false;
  double budget = 30.0;  // seconds per port: room for thirty families' likeliest rates
};

struct ProbeOptions {
  std::vector<std::string> ports;
  bool json = false;
  families::ProbeSettings settings;  // progress is left for the caller to set with -v
  bool verbose = false;
};

// Throws UsageError: no port, a port named twice, a budget outside 1..120 s.
ProbeOptions make_probe_options(const ProbeCommandLine& command_line);

}  // namespace playerkit::player_drivers
