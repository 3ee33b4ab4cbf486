#pragma once
// `player-drivers run`: the daemon in this process, serving the planned
// devices on loopback (or on --serve PORT), and player-cat's and
// player-send's machinery as its client: data on stdout in player-cat's
// formats, --req and --stdin through player-send's sender, --record through
// a writelog device, --stats and --trace from the devices themselves.
//
//   RunOptions options = make_run_options(command_line);
//   return run_driver(options, families::builtin_families(), {std::cout, std::cerr, STDIN_FILENO},
//                     [] { return stop_signal != 0; });

#include <functional>
#include <ostream>

#include "families/family_registry.hpp"
#include "run_options.hpp"

namespace playerkit::player_drivers {

struct RunStreams {
  std::ostream& out;  // data and replies
  std::ostream& err;  // diagnostics, --stats, --trace
  int input_fd = 0;   // --stdin reads this descriptor
};

// The name of the generated configuration in the daemon's messages, before
// they are explained.
inline constexpr const char* kGeneratedConfigName = "<player-drivers run>";

// Returns the exit status (drivers_exit_status.hpp): 0 done; 1 the daemon,
// a device or the connection failed; 2 an unknown driver or an option it
// refuses (named as typed); with --req (and --stdin) 3 NACK, 4 ERR.
// `families` gives --trace its framing and adds the drivers a family brings
// beyond the built-in list. `stop_requested` is polled at least every 100 ms.
int run_driver(const RunOptions& options, const families::FamilyRegistry& families, const RunStreams& streams,
               const std::function<bool()>& stop_requested);

}  // namespace playerkit::player_drivers
