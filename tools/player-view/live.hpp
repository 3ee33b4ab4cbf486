#pragma once
// --http: the live page. One Player connection feeds a Scene; its frame goes
// to every open page kPagesPerSecond times a second (page_server.hpp).

#include <functional>
#include <ostream>

#include "view_options.hpp"

namespace playerkit::player_view {

// Serves until `stop_requested` (polled at least every 100 ms): kExitOk.
// kExitFailure, with a message on `err`, when the server cannot be reached,
// a device is refused, the connection is lost, the map cannot be read, or
// the HTTP port cannot be listened on. Says where the page is on `err`:
// "player-view: serving http://127.0.0.1:PORT/".
int run_live(const ViewOptions& options, std::ostream& err, const std::function<bool()>& stop_requested);

}  // namespace playerkit::player_view
