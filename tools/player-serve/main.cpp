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
  player-serve -s data/worlds/simple.world   simulate a Stage world and serve every device
                                       in it (each robot on its port; without a port on -p),
                                       stamped with simulation time, plus simulation:0
  player-serve -s cave.world -p 0 --speedup 0 --sim-time 60
                                       one minute of simulation as fast as it goes, then
                                       the world stands still and is served as it is
  player-serve -s cave.world --paused  start paused; player-send simulation:0 cmd cmd=2
                                       steps once, cmd=0 runs, cmd=1 pauses
  player-serve -s cave.world gz.cfg    also the devices of gz.cfg on that world, e.g.
                                       position:1 ( driver "gz_position" gz_id "robot1" )
                                       or writelog and amcl on the simulated devices
  player-serve --check -s cave.world   read the world and list what it would serve
  player-serve -s cave.world --picture run.png
                                       run.png shows the world when serving ends (SIGINT,
                                       SIGTERM, SIGHUP): the map, the robots and their trails,
                                       the latest laser and sonar rays; written now by
                                       player-send simulation:0 cmd cmd=3, or, to wait until
                                       it is written (ACK; NACK when it cannot be):
                                       echo '{"type":"req","device":"simulation:0",
                                         "data":{"raw":[3]}}' | player-send --stdin

Signals: SIGINT, SIGTERM and SIGHUP stop accepting clients, shut every device
down and exit 0.
Exit status: 0 success, 1 runtime error (port in use, plugin or device set-up
failed), 2 usage error, invalid configuration or invalid world file (reported
as file:line:col).)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-serve: serve the devices of a Player configuration file, or of a simulated\n"
               "Stage world, over TCP, wire-compatible with Player 1.5 clients."};
  app.footer(kExamples);
  app.set_version_flag("--version", std::string("player-serve (playerkit) ") + PLAYERKIT_VERSION +
                                        ", Player protocol " + PLAYERKIT_PLAYER_VERSION);

  playerkit::serve::ServeCommandLine command_line;
  app.add_option("CONFIG", command_line.config_path, "configuration file (.cfg); optional with -s");
  app.add_option("-p,--port", command_line.port, "TCP port for devices outside a robot section")
      ->capture_default_str();
  app.add_option("-k,--key", command_line.key, "require clients to authenticate with this key (31 characters used)");
  // One file per -d: CONFIG is optional (with -s), so a greedy -d would swallow it.
  app.add_option("-d,--plugin", command_line.plugins, "load drivers from this shared object (repeatable)")
      ->allow_extra_args(false);
  app.add_option("--bind", command_line.bind_address, "address to listen on")->capture_default_str();
  app.add_option("-r,--readlog", command_line.readlog,
                 "replay this log file: the devices with driver readlog serve its data");
  app.add_option("-f,--readlogspeed", command_line.readlog_speed, "replay speed factor for -r (2 = twice as fast)");
  app.add_option("-t,--transport", command_line.transport, "tcp (udp is not available)")->capture_default_str();
  app.add_option("-s,--world", command_line.world,
                 "simulate this Stage world file (1.3 or 3/4) and serve every device in it");
  app.add_option("--speedup", command_line.speedup, "with -s: times real time; 0 = as fast as possible (default 1)");
  app.add_option("--seed", command_line.seed, "with -s: seed of sensor noise and odometry errors (default 0)");
  app.add_option("--sim-time", command_line.sim_time,
                 "with -s: stop the simulation after this many simulated seconds (serving goes on)");
  app.add_flag("--paused", command_line.paused, "with -s: start paused (the simulation device runs it)");
  app.add_option("--picture", command_line.picture,
                 "with -s: a PNG of the world (map, robots, trails, the latest rays) written when serving "
                 "ends and whenever the simulation device gets byte 3")
      ->type_name("FILE.png");
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
