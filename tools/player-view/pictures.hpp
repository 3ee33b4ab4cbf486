#pragma once
// --snapshot and --record: collect data for a while, then draw it into PNGs.
// Streams and the stop test are parameters, so tests run it in-process
// against a real server.

#include <functional>
#include <ostream>

#include "view_options.hpp"

namespace playerkit::player_view {

// Returns the exit status: kExitOk once the pictures are written (a stop
// request writes the snapshot at once, or ends a recording); kExitFailure,
// with a message on `err`, when the server cannot be reached, a device is
// refused, the connection is lost, or a picture or the map cannot be read
// or written. `stop_requested` is polled at least every 100 ms.
int run_pictures(const ViewOptions& options, std::ostream& out, std::ostream& err,
                 const std::function<bool()>& stop_requested);

}  // namespace playerkit::player_view
