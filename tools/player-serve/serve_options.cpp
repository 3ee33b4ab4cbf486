#include "serve_options.hpp"

#include <sstream>

namespace playerkit::serve {

ServeRequest make_serve_options(const ServeCommandLine& command_line) {
  if (!command_line.stage_directory.empty() || !command_line.gazebo_id.empty()) {
    throw UsageError(std::string(command_line.stage_directory.empty() ? "Gazebo (-g)" : "Stage (-s)") +
                     " is not available: playerkit serves real and logged devices only");
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
