#pragma once
// The daemon: load drivers and a configuration, serve until a signal, shut
// every device down. `player-serve CONFIG` and `player-log replay LOG` are this
// with different options.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/driver_registry.hpp"
#include "core/logger.hpp"

namespace playerkit::daemon {

// -s WORLD: serve every device of a simulated world (lib/drivers/sim).
struct SimulationOptions {
  std::string world;                // a Stage world file
  double speedup = 1.0;             // × real time; 0: as fast as possible
  std::uint64_t seed = 0;           // noise and odometry error draws
  std::optional<double> sim_time;   // stop stepping after this many simulated seconds
  bool paused = false;              // start paused (the simulation device runs it)
  // --picture: a PNG of the world written when serving ends and on request
  // (the simulation device's byte 3); empty: none. Never over `picture_inputs`.
  std::string picture;
  std::vector<std::string> picture_inputs;
};

struct ServeOptions {
  std::string program_name = "player-serve";  // prefixes every log line
  // Empty with a simulation and no configuration file.
  std::string config_path;
  // When set, the configuration itself (config_path names it in messages).
  std::optional<std::string> config_text;
  std::uint16_t port = 6665;  // 0: any free port (printed at start-up)
  std::string bind_address = "0.0.0.0";
  std::optional<std::string> auth_key;
  std::vector<std::string> plugins;
  // Drivers beyond the built-in ones and the plugins' (those of a hardware
  // family made in a test); they replace drivers of the same name.
  std::vector<core::DriverSpec> extra_drivers;
  core::LogLevel log_level = core::LogLevel::kInfo;
  // -r: readlog devices replay this file and the server clock follows it.
  std::optional<std::string> readlog;
  double readlog_speed = 1.0;  // -f
  // drivers::ReadlogSettings' data_queue, duration and burst.
  std::size_t readlog_data_queue = 0;
  std::optional<double> readlog_duration;
  bool readlog_burst = false;
  std::optional<SimulationOptions> simulation;

  // A configuration file (or text) to read besides the world.
  [[nodiscard]] bool has_configuration() const { return config_text.has_value() || !config_path.empty(); }
  // What is served, for messages: the configuration file, else the world.
  [[nodiscard]] std::string served_name() const;
};

// The built-in drivers plus those of the plugins. Throws core::PluginError.
core::DriverRegistry load_drivers(const std::vector<std::string>& plugins, core::Logger& logger);

enum class ServeResult {
  stopped,            // a clean shutdown on SIGINT, SIGTERM or SIGHUP
  failed,             // serving failed: port in use, plugin, device set-up
  bad_configuration,  // the configuration is wrong (file:line:col logged)
};

// Serves until a signal. Diagnostics go to stderr.
ServeResult serve(const ServeOptions& options);

}  // namespace playerkit::daemon
