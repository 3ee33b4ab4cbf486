#pragma once
// player-cat's work: connect, subscribe, dump until a limit, a signal, or the
// reader of stdout goes away. Streams and the stop test are parameters, so the
// tests run it in-process against a real server.

#include <functional>
#include <ostream>

#include "cat_options.hpp"

namespace playerkit::cat {

// Returns the exit status: kExitOk when a limit was reached, a stop was
// requested or stdout was closed by its reader (EPIPE); kExitFailure, with a
// message on `err`, for connection, server, device and output problems.
// `stop_requested` is polled at least every 100 ms.
int run_cat(const CatOptions& options, std::ostream& out, std::ostream& err,
            const std::function<bool()>& stop_requested);

}  // namespace playerkit::cat
