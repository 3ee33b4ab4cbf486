#pragma once
// `player-serve --check`: everything serving would verify before accepting a
// client (daemon::check_configuration: the -r log, the configuration, every
// driver's options, files and the devices it needs), then what it would
// serve. No port is opened, no hardware touched, no file written.

#include <iosfwd>

#include "daemon/serve.hpp"

namespace playerkit::serve {

// Prints the devices to out, warnings and errors to err. Returns the exit
// status: 0 when serving could start, 2 when the configuration or the -r log
// is wrong, 1 when a plugin cannot be loaded.
int check_config(const daemon::ServeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace playerkit::serve
