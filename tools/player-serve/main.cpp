// player-serve: the Player 1.5 device server. See --help.

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "check_config.hpp"
#include "core/plugin.hpp"
#include "daemon/serve.hpp"
#include "exit_status.hpp"
#include "serve_exit_status.hpp"

namespace tools = playerkit::tools;

namespace {

constexpr const char* kExamples = R"(Examples:
  player-serve robot.cfg               serve robot.cfg on port 6665 until Ctrl-C
  player-serve -p 7000 robot.cfg       devices outside robot sections on port 7000
  player-serve -p 0 robot.cfg          any free port; the log line says which
  player-serve -k secret robot.cfg     clients must authenticate with key "secret"
  player-serve -d ./libmydriver.so robot.cfg   load extra drivers from a plugin
  player-serve --check robot.cfg       validate robot.cfg and list its devices
  player-serve -r run.log -f 2 replay.cfg   replay run.log at twice its speed to the
                                       readlog devices of replay.cfg, e.g.
                                       position:0 ( driver "readlog" )

Signals: SIGINT, SIGTERM and SIGHUP stop accepting clients, shut every device
down and exit 0.
Exit status: 0 success, 1 runtime error (port in use, plugin or device set-up
failed), 2 usage error or invalid configuration.)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-serve: serve the devices of a Player configuration file over TCP,\n"
               "wire-compatible with Player 1.5 clients."};
  app.footer(kExamples);
  app.set_version_flag("--version", std::string("player-serve (playerkit) ") + PLAYERKIT_VERSION +
                                        ", Player protocol " + PLAYERKIT_PLAYER_VERSION);

  playerkit::daemon::ServeOptions options;
  bool check = false;
  bool quiet = false;
  bool verbose = false;
  std::string readlog;
  double readlog_speed = 1.0;
  std::string stage_directory;
  std::string gazebo_id;
  std::string key;
  std::string transport = "tcp";
  app.add_option("CONFIG", options.config_path, "configuration file (.cfg)")->required();
  app.add_option("-p,--port", options.port, "TCP port for devices outside a robot section")
      ->capture_default_str();
  app.add_option("-k,--key", key, "require clients to authenticate with this key (31 characters used)");
  app.add_option("-d,--plugin", options.plugins, "load drivers from this shared object (repeatable)");
  app.add_option("--bind", options.bind_address, "address to listen on")->capture_default_str();
  app.add_option("-r,--readlog", readlog, "replay this log file: the devices with driver readlog serve its data");
  app.add_option("-f,--readlogspeed", readlog_speed, "replay speed factor for -r (2 = twice as fast)");
  app.add_option("-t,--transport", transport, "tcp (udp is not available)")->capture_default_str();
  app.add_option("-s", stage_directory, "Stage devices (not available in playerkit)");
  app.add_option("-g", gazebo_id, "Gazebo server (not available in playerkit)");
  app.add_flag("-q,--quiet", quiet, "errors only");
  app.add_flag("-v,--verbose", verbose, "also debug messages (client traffic problems, set-up)");
  app.add_flag("--check", check, "validate the configuration, list its devices, and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? tools::kExitOk : tools::kExitUsage;
  }

  if (!stage_directory.empty() || !gazebo_id.empty()) {
    std::cerr << "player-serve: " << (stage_directory.empty() ? "Gazebo (-g)" : "Stage (-s)")
              << " is not available: playerkit serves real and logged devices only\n";
    return tools::kExitUsage;
  }
  if (transport != "tcp") {
    std::cerr << "player-serve: transport '" << transport
              << "' is not available: playerkit serves clients over TCP only\n";
    return tools::kExitUsage;
  }
  if (!(readlog_speed > 0 && readlog_speed < 1e6)) {
    std::cerr << "player-serve: -f " << readlog_speed << ": the replay speed must be above 0 and below 1000000\n";
    return tools::kExitUsage;
  }
  if (!readlog.empty()) {
    options.readlog = readlog;
    options.readlog_speed = readlog_speed;
  }
  if (check) {
    playerkit::core::Logger logger("player-serve");
    logger.set_level(playerkit::core::LogLevel::kError);
    try {
      const auto registry = playerkit::daemon::load_drivers(options.plugins, logger);
      return playerkit::serve::check_config(
          options.config_path, options.port,
          [&registry](std::string_view driver) { return registry.contains(driver); }, std::cout,
          std::cerr);
    } catch (const playerkit::core::PluginError& e) {
      std::cerr << "player-serve: " << e.what() << "\n";
      return tools::kExitFailure;
    }
  }

  if (!key.empty()) options.auth_key = key;
  if (quiet) options.log_level = playerkit::core::LogLevel::kError;
  if (verbose) options.log_level = playerkit::core::LogLevel::kDebug;
  return tools::exit_status_for(playerkit::daemon::serve(options));
}
