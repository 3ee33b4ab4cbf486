// player-serve: the Player 1.5 device server. See --help.

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "check_config.hpp"
#include "serve_options.hpp"
#include "daemon/serve.hpp"
#include "exit_status.hpp"
#include "parse_errors.hpp"
#include "serve_exit_status.hpp"
#include "text/printable.hpp"

namespace tools = playerkit::tools;

namespace {

constexpr const char* kExamples = R"(Examples:
  player-serve robot.cfg               serve robot.cfg on port 6665 until Ctrl-C
  player-serve -p 7000 robot.cfg       devices outside robot sections on port 7000
  player-serve -p 0 robot.cfg          any free port; the log line says which
  player-serve -k secret robot.cfg     clients must authenticate with key "secret"
  player-serve -d ./libmydriver.so robot.cfg   load extra drivers from a plugin
  player-serve --check robot.cfg       check robot.cfg as serving would (drivers, their
                                       options and files, the devices they need; no port,
                                       no hardware) and list its devices
  player-serve --check -r run.log replay.cfg   the same with the log to replay
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

  playerkit::serve::ServeCommandLine command_line;
  app.add_option("CONFIG", command_line.config_path, "configuration file (.cfg)")->required();
  app.add_option("-p,--port", command_line.port, "TCP port for devices outside a robot section")
      ->capture_default_str();
  app.add_option("-k,--key", command_line.key, "require clients to authenticate with this key (31 characters used)");
  app.add_option("-d,--plugin", command_line.plugins, "load drivers from this shared object (repeatable)");
  app.add_option("--bind", command_line.bind_address, "address to listen on")->capture_default_str();
  app.add_option("-r,--readlog", command_line.readlog,
                 "replay this log file: the devices with driver readlog serve its data");
  app.add_option("-f,--readlogspeed", command_line.readlog_speed, "replay speed factor for -r (2 = twice as fast)");
  app.add_option("-t,--transport", command_line.transport, "tcp (udp is not available)")->capture_default_str();
  app.add_option("-s", command_line.stage_directory, "Stage devices (not available in playerkit)");
  app.add_option("-g", command_line.gazebo_id, "Gazebo server (not available in playerkit)");
  app.add_flag("-q,--quiet", command_line.quiet, "errors only");
  app.add_flag("-v,--verbose", command_line.verbose, "also debug messages (client traffic problems, set-up)");
  app.add_flag("--check", command_line.check,
               "check everything serving would before accepting clients, short of hardware and network "
               "(the -r log, drivers, their options and files), list the devices, and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return tools::report_parse_error(app, e, std::cerr);
  }

  playerkit::serve::ServeRequest request;
  try {
    request = playerkit::serve::make_serve_options(command_line);
  } catch (const tools::UsageError& e) {
    std::cerr << "player-serve: " << playerkit::text::printable(e.what()) << "\n";
    return tools::kExitUsage;
  }
  const auto& options = request.options;
  if (request.check_only) return playerkit::serve::check_config(options, std::cout, std::cerr);
  return tools::exit_status_for(playerkit::daemon::serve(options));
}
