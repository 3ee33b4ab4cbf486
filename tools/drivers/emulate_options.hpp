#pragma once
// What `player-drivers emulate` was asked to do, checked: names with their
// KEY=VALUE options, the lines (--link PATH / --tcp PORT, in the order
// given, one per emulator), the map, the faults. Pure; the emulators check
// their own options when they are made.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "drivers_exit_status.hpp"
#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/catalog/emulator_rig.hpp"
#include "emulators/runner/fault_plan.hpp"

namespace playerkit::player_drivers {

struct EndpointArgument {
  enum class Kind { link, tcp };
  Kind kind = Kind::link;
  std::string text;  // the path, or the port number as typed
};

struct EmulateCommandLine {
  std::vector<std::string> words;          // NAME [KEY=VALUE...] [NAME [KEY=VALUE...]]...
  std::vector<EndpointArgument> endpoints;  // in the order given
  std::string map;
  std::optional<double> map_scale;
  bool map_negate = false;
  std::vector<std::string> faults;
  bool stats = false;
  std::optional<double> duration;
};

struct EmulateOptions {
  std::vector<emulators::EmulatorRequest> requests;
  std::optional<std::filesystem::path> map;
  std::optional<double> map_scale;  // m/pixel for an image; unset: the image's .yaml beside it
  bool map_negate = false;
  emulators::FaultPlan faults;
  bool stats = false;
  std::optional<double> duration;  // seconds; unset: until a signal
};

// Names are checked against `catalog`. Throws UsageError.
EmulateOptions make_emulate_options(const EmulateCommandLine& command_line, const emulators::EmulatorCatalog& catalog);

}  // namespace playerkit::player_drivers
