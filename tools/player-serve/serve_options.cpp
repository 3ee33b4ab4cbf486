#include "serve_options.hpp"

#include <filesystem>
#include <sstream>

#include "output_file.hpp"

namespace playerkit::serve {

namespace {

// The simulation flags, checked; nothing without -s.
std::optional<daemon::SimulationOptions> simulation_options(const ServeCommandLine& command_line) {
  if (command_line.world.empty()) {
    const char* stray = command_line.speedup    ? "--speedup"
                        : command_line.seed     ? "--seed"
                        : command_line.sim_time ? "--sim-time"
                        : command_line.paused   ? "--paused"
                        : !command_line.picture.empty() ? "--picture"
                                                : nullptr;
    if (stray != nullptr) throw UsageError(std::string(stray) + " runs a simulation; it needs -s WORLD");
    return std::nullopt;
  }
  if (!command_line.readlog.empty()) {
    throw UsageError("-r and -s both set the server's clock (log time, simulation time); give one of them");
  }
  daemon::SimulationOptions simulation;
  simulation.world = command_line.world;
  if (command_line.speedup) {
    const double speedup = *command_line.speedup;
    if (!(speedup >= 0 && speedup < 1e6)) {
      std::ostringstream message;
      message << "--speedup " << speedup << ": the speedup must be 0 (as fast as possible) or above, below 1000000";
      throw UsageError(message.str());
    }
    simulation.speedup = speedup;
  }
  if (command_line.sim_time) {
    const double seconds = *command_line.sim_time;
    if (!(seconds > 0 && seconds < 1e9)) {
      std::ostringstream message;
      message << "--sim-time " << seconds << ": the simulated seconds must be above 0 and below 1e9";
      throw UsageError(message.str());
    }
    simulation.sim_time = seconds;
  }
  simulation.seed = command_line.seed.value_or(0);
  simulation.paused = command_line.paused;
  if (!command_line.picture.empty()) {
    // Checked now: the picture is written when serving ends, long after.
    simulation.picture_inputs = {command_line.world};
    if (!command_line.config_path.empty()) simulation.picture_inputs.push_back(command_line.config_path);
    tools::refuse_output_over_inputs(command_line.picture, simulation.picture_inputs);
    const std::filesystem::path directory = std::filesystem::path(command_line.picture).parent_path();
    std::error_code error;
    if (!directory.empty() && !std::filesystem::is_directory(directory, error)) {
      throw UsageError("--picture " + command_line.picture + ": the directory " + directory.string() +
                       " does not exist");
    }
    simulation.picture = command_line.picture;
  }
  return simulation;
}

}  // namespace

ServeRequest make_serve_options(const ServeCommandLine& command_line) {
  if (!command_line.gazebo_id.empty()) {
    throw UsageError("Gazebo (-g) is not available: the gz_* drivers serve a simulated world instead "
                     "(player-serve -s WORLD gazebo.cfg)");
  }
  if (command_line.config_path.empty() && command_line.world.empty()) {
    throw UsageError("nothing to serve: give a configuration file, -s WORLD, or both");
  }
  if (command_line.transport != "tcp") {
    throw UsageError("transport '" + command_line.transport +
                     "' is not available: playerkit serves clients over TCP only");
  }
  const double speed = command_line.readlog_speed;
  if (!(speed > 0 && speed < 1e6)) {
    std::ostringstream message;  // the number as the user's stream would print it
    message << "-f " << speed << ": the replay speed must be above 0 and below 1000000";
    throw UsageError(message.str());
  }

  ServeRequest request;
  request.options.simulation = simulation_options(command_line);
  request.check_only = command_line.check;
  auto& options = request.options;
  options.config_path = command_line.config_path;
  options.port = command_line.port;
  options.bind_address = command_line.bind_address;
  options.plugins = command_line.plugins;
  if (!command_line.readlog.empty()) {
    options.readlog = command_line.readlog;
    options.readlog_speed = speed;
  }
  if (!command_line.key.empty()) options.auth_key = command_line.key;
  if (command_line.quiet) options.log_level = core::LogLevel::kError;
  if (command_line.verbose) options.log_level = core::LogLevel::kDebug;
  return request;
}

}  // namespace playerkit::serve
