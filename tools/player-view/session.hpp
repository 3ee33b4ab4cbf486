#pragma once
// player-view's Player side: connect, subscribe to the devices (the ones
// named, or every one the server lists that opens for reading), ask the
// geometry the scene needs. Shared by pictures and (later) the live page.

#include <chrono>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "client/client.hpp"
#include "view/scene.hpp"
#include "view_options.hpp"

namespace playerkit::player_view {

// A problem to report as "player-view: <what>", exit status 1.
class ViewFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Session {
  client::Client connection;
  std::vector<protocol::DeviceAddress> devices;  // subscribed
};

// Throws ViewFailure (a device named but refused, nothing readable) or
// client::ClientError (unreachable, not a Player server). Devices found by
// listing that refuse are skipped with a line on `err`.
Session open_session(const ViewOptions& options, std::ostream& err);

// Asks each device for what places its drawing on the robot (laser pose,
// sonar and IR poses, the base's size); a device that does not answer is
// drawn with defaults.
void ask_geometry(Session& session, view::Scene& scene, std::chrono::milliseconds timeout);

}  // namespace playerkit::player_view
