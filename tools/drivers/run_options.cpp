#include "run_options.hpp"

#include <cmath>

namespace playerkit::player_drivers {

RunOptions make_run_options(const RunCommandLine& command_line) {
  RunOptions options;
  if (command_line.words.empty()) {
    throw UsageError("run: name a driver (player-drivers list shows them) or a family of drivers served together");
  }
  options.plan.name = command_line.words.front();
  if (options.plan.name.find('=') != std::string::npos) {
    throw UsageError("run: the driver's name comes first, then its OPTION=VALUE pairs (got '" + options.plan.name +
                     "')");
  }
  for (std::size_t i = 1; i < command_line.words.size(); ++i) {
    options.plan.options.push_back(parse_option_assignment(command_line.words[i]));
  }
  options.plugins = command_line.plugins;

  if (!command_line.device.empty()) {
    options.device = protocol::parse_device_address(command_line.device);
    if (!options.device) {
      throw UsageError("--device '" + command_line.device + "' is not a device: write interface[:index], e.g. laser:0");
    }
  }

  // player-cat checks its own flags; the device named here is a stand-in
  // until the plan says which devices there are.
  cat::CommandLine cat_line;
  cat_line.targets = {"127.0.0.1:6665", "null:0"};
  cat_line.format = command_line.format;
  cat_line.count = command_line.count;
  cat_line.duration = command_line.duration;
  cat_line.fields = command_line.fields;
  cat_line.si = command_line.si;
  cat_line.timestamps = command_line.timestamps;
  cat_line.timeout = command_line.timeout;
  cat::make_cat_options(cat_line);
  cat_line.targets.clear();
  options.cat_line = cat_line;

  options.from_stdin = command_line.from_stdin;
  options.request = command_line.request;
  if (!options.request.empty()) {
    if (options.from_stdin) throw UsageError("--req sends one request, --stdin many: choose one");
    if (command_line.count || command_line.duration) {
      throw UsageError("--req sends one request, prints the reply and exits: -n and --duration do not apply");
    }
    if (options.request.front().find('=') != std::string::npos) {
      throw UsageError("--req: name the request first (e.g. --req get-geom), then FIELD=VALUE pairs");
    }
  }

  if (command_line.serve_port) {
    if (*command_line.serve_port < 0 || *command_line.serve_port > 65535) {
      throw UsageError("--serve: a port number is 0 (any free port) to 65535");
    }
    options.serve_port = static_cast<std::uint16_t>(*command_line.serve_port);
    options.bind_address = command_line.bind.empty() ? "0.0.0.0" : command_line.bind;
  } else if (!command_line.bind.empty()) {
    throw UsageError("--bind says where --serve listens: it needs --serve PORT");
  }
  if (!command_line.record.empty()) options.plan.record_file = command_line.record;
  options.stats = command_line.stats;
  options.trace = command_line.trace;
  options.verbose = command_line.verbose;
  return options;
}

}  // namespace playerkit::player_drivers
