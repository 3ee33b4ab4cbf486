#pragma once
// player-view's Player side: connect, subscribe to the devices (the ones
// named, or every one the server lists that opens for reading), ask the
// geometry the scene needs. Shared by pictures and (later) the live page.

#include <chrono>
#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
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

// The --map, if one was given. Throws map::MapFileError.
std::optional<grid::OccupancyGrid> load_view_map(const ViewOptions& options);

// --timeout, and the shorter wait for geometry replies.
std::chrono::milliseconds reply_timeout(const ViewOptions& options);
std::chrono::milliseconds geometry_timeout(const ViewOptions& options);

// Runs `work`; returns kExitOk, or kExitFailure with "player-view: <what>"
// on `err` for whatever it throws (a connection error names the server).
int report_failures(const ViewOptions& options, std::ostream& err, const std::function<void()>& work);

// --drive: the robot's first position device among the subscribed ones,
// opened for writing too. Throws ViewFailure when there is none or the
// server refuses.
protocol::DeviceAddress open_base_for_driving(Session& session, const ViewOptions& options);

// Asks each device for what places its drawing on the robot (laser pose,
// sonar and IR poses, the base's size); a device that does not answer is
// drawn with defaults.
void ask_geometry(Session& session, view::Scene& scene, std::chrono::milliseconds timeout);

}  // namespace playerkit::player_view
