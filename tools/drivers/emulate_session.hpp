#pragma once
// `player-drivers emulate`: the emulators on their lines (an EmulatorRig)
// until a signal or --duration. Stdout gets one line per emulator saying
// where it is and a config section for its driver:
//
//   p2os on /tmp/robot: position:0 ( driver "p2os_position" port "/tmp/robot" )
//   sicklms200 on /tmp/laser: laser:0 ( driver "sicklms200" port "/tmp/laser" )
//
// --stats prints each emulator's line counters and state every second on stderr.

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>

#include "algorithms/grid/occupancy_grid.hpp"
#include "emulate_options.hpp"

namespace playerkit::player_drivers {

// The map of --map: a ROS .yaml as it says; an image at --map-scale, or
// through the .yaml of the same name beside it. Throws UsageError for an
// image without a scale, map::MapFileError for a file that does not load.
// `how` says which way it was read.
std::shared_ptr<const grid::OccupancyGrid> load_emulator_map(const EmulateOptions& options, std::string& how);

// Returns 0 after a stop or --duration; 1 when a line or the map cannot be
// had; 2 for an option an emulator refuses.
int run_emulators(const EmulateOptions& options, const emulators::EmulatorCatalog& catalog, std::ostream& out,
                  std::ostream& err, const std::function<bool()>& stop_requested);

}  // namespace playerkit::player_drivers
