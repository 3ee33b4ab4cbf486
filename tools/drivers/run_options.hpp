#pragma once
// What `player-drivers run` was asked to do, checked: the command line as
// CLI11 fills it (RunCommandLine) becomes RunOptions, or a UsageError naming
// the flag at fault. Pure; what needs the driver registry (the name, the
// options it takes, --device) is checked by run_session when it plans.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cat_options.hpp"
#include "drivers_exit_status.hpp"
#include "protocol/device_address.hpp"
#include "run_plan.hpp"

namespace playerkit::player_drivers {

// The flags as typed; empty strings and nullopt mean "not given".
struct RunCommandLine {
  std::vector<std::string> words;    // NAME OPTION=VALUE...
  std::vector<std::string> plugins;  // -d
  std::string device;                // --device
  // Data, as player-cat prints it.
  std::string format = "text";
  std::optional<std::uint64_t> count;
  std::optional<double> duration;
  std::vector<std::string> fields;
  bool si = false;
  std::string timestamps = "a";
  // Commands and requests, as player-send sends them.
  bool from_stdin = false;
  std::vector<std::string> request;  // --req NAME [FIELD=VALUE...]
  // Serving, recording, watching.
  std::optional<int> serve_port;
  std::string bind;
  std::string record;
  bool stats = false;
  bool trace = false;
  bool verbose = false;
  double timeout = 5.0;
};

struct RunOptions {
  PlanRequest plan;
  std::vector<std::string> plugins;
  // --device: a single driver's address; for a family, the one device read
  // and sent to.
  std::optional<protocol::DeviceAddress> device;
  // player-cat's flags, checked; its server and devices are filled in once
  // the plan says which devices there are.
  cat::CommandLine cat_line;
  bool from_stdin = false;
  std::vector<std::string> request;  // NAME FIELD=VALUE... (empty: no --req)
  std::optional<std::uint16_t> serve_port;  // --serve (0: any free port)
  std::string bind_address = "127.0.0.1";
  bool stats = false;
  bool trace = false;
  bool verbose = false;
};

// Throws UsageError.
RunOptions make_run_options(const RunCommandLine& command_line);

}  // namespace playerkit::player_drivers
