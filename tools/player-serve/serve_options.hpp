#pragma once
// What player-serve was asked to do, checked: the flags as CLI11 fills them
// (ServeCommandLine) become daemon::ServeOptions plus whether only --check was
// asked, or a UsageError whose text follows "player-serve: ". Pure, so the
// rules are unit-tested (serve_options_test.cpp).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "daemon/serve.hpp"
#include "exit_status.hpp"

namespace playerkit::serve {

using tools::UsageError;

// The flags as typed; empty strings mean "not given".
struct ServeCommandLine {
  std::string config_path;  // may be empty with -s
  std::uint16_t port = daemon::ServeOptions().port;
  std::string key;
  std::vector<std::string> plugins;
  std::string bind_address = daemon::ServeOptions().bind_address;
  std::string readlog;
  double readlog_speed = 1.0;
  std::string transport = "tcp";
  std::string world;             // -s: a Stage world file to simulate
  std::optional<double> speedup;  // --speedup (-s only)
  std::optional<std::uint64_t> seed;  // --seed (-s only)
  std::optional<double> sim_time;     // --sim-time (-s only)
  bool paused = false;                // --paused (-s only)
  std::string picture;                // --picture FILE.png (-s only)
  std::string gazebo_id;        // -g: Player's Gazebo, not available
  bool quiet = false;
  bool verbose = false;
  bool check = false;
};

struct ServeRequest {
  daemon::ServeOptions options;
  bool check_only = false;  // --check: validate the configuration, serve nothing
};

// Throws UsageError.
ServeRequest make_serve_options(const ServeCommandLine& command_line);

}  // namespace playerkit::serve
