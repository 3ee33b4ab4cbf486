// player-drivers: hardware bring-up from the terminal. See --help.

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <csignal>
#include <iostream>
#include <string>

#include "parse_errors.hpp"
#include "core/plugin.hpp"
#include "daemon/serve.hpp"
#include "driver_listing.hpp"
#include "drivers_exit_status.hpp"
#include "emulate_options.hpp"
#include "emulate_session.hpp"
#include "port_probe.hpp"
#include "probe_options.hpp"
#include "run_options.hpp"
#include "run_session.hpp"

namespace {

namespace drivers = playerkit::player_drivers;

constexpr const char* kFooter = R"(Examples:
  player-drivers list                              every driver: interfaces, access, hardware, summary
  player-drivers list --interface laser --json     the laser drivers as JSON lines
  player-drivers info sicklms200                   options, requests, manual section, a config to paste
  player-drivers run sicklms200 port=/dev/ttyUSB0 -n 5 --format json
  player-drivers run p2os port=/dev/ttyUSB0 --device position:0 --stats
  player-drivers run lifomcom --req push channel=news data.data=hello
  player-drivers run sicklms200 port=/tmp/laser --serve 6665 --record run.log
  player-drivers probe /dev/ttyUSB0 /dev/ttyUSB1   which device answers where, and its config line
  player-drivers emulate p2os sicklms200 --link /tmp/robot --link /tmp/laser --map data/maps/stage-cave.png

Each subcommand's --help has more (player-drivers run --help).

Exit status: 0 done; 1 the work failed (a port, a device, the daemon, a map;
probe: some port not identified); 2 usage error (bad flag, unknown driver or
emulator, an option the driver refuses); run --req: 3 NACK, 4 ERR.
Signals: SIGINT and SIGTERM stop run, probe and emulate cleanly.)";

constexpr const char* kRunFooter = R"(NAME is a driver (player-drivers list) or a family of drivers served together on
one link (p2os: all of a Pioneer's devices). OPTION=VALUE are the driver's
configuration options (player-drivers info NAME); numbers, [tuples] and
"strings" go in as written, other text as a string.

Data goes to stdout as player-cat prints it. With --stdin, JSON lines in
player-send's form are sent as commands and requests while the data is
printed (replies as JSON lines too); the run ends with the input unless -n
or --duration say otherwise. --req sends one request, prints the reply and
exits with its status.

Examples:
  player-drivers run sicklms200 port=/dev/ttyUSB0 rate=38400 -n 3 --si --format json
  player-drivers run readlog filename=run.log --device laser:0 --field ranges.0
  player-drivers run p2os port=/dev/ttyUSB0 --device position:0 --stdin < drive.jsonl
  player-drivers run sicklms200 port=/tmp/laser --req get-geom
  player-drivers run sicklms200 port=/dev/ttyUSB0 --serve 6665    also for player-cat, playerv ...
  player-drivers run sicklms200 port=/dev/ttyUSB0 --stats --trace --duration 10

Exit status: 0 done (count, duration, end of --stdin, a signal), 1 the daemon,
a device or the connection failed, 2 usage (unknown driver, an option it
refuses, bad flags), 3 NACK and 4 ERR (--req, --stdin).)";

constexpr const char* kProbeFooter = R"(Before opening a port, probe checks what most often goes wrong: a missing
port (and similar ones that exist), permissions (and the group to join), a
port held by another program (and which). Then it asks P2OS robots (SYNC0..2)
and SICK LMS 200 / PLS lasers (installation mode, type) at their baud rates,
the likeliest first, at most --budget seconds a port. The device is left
ready for its driver (a Pioneer synchronised, a laser in installation mode).

Examples:
  player-drivers probe /dev/ttyUSB0
  player-drivers probe /dev/ttyUSB0 /dev/ttyUSB1 tcp:192.168.1.20:4001 --json

Exit status: 0 every port identified, 1 some port was not (the message says
why), 2 usage.)";

constexpr const char* kEmulateFooter = R"(Emulators (each NAME may be followed by KEY=VALUE options):
  p2os        a Pioneer's P2OS controller: model=p3dx pose=x,y,yaw baud=0 battery=12.5 ...
  sicklms200  a SICK LMS 200: pose=x,y,yaw (or mount=x,y,yaw on a robot) noise=0 baud=9600 ...
  sickpls     a SICK PLS: the same options but type
Poses are metres, metres, degrees. With a robot and a laser, the laser rides
on the robot. --link PATH and --tcp PORT go to the emulators in the order
given; an emulator without one gets a pseudo-terminal of its own. A map image
needs --map-scale unless a .yaml of the same name lies beside it.

Examples:
  player-drivers emulate sicklms200 --link /tmp/laser
  player-drivers emulate p2os model=p3at baud=38400 --link /tmp/robot --fault bad-checksum=0.01
  player-drivers emulate p2os sicklms200 mount=0.16,0,0 --link /tmp/robot --link /tmp/laser \
      --map data/maps/stage-cave.png --stats

Faults (--fault, repeatable): bad-checksum=P garbage=P truncate=P silent-start=S
vanish=AT:FOR seed=N.
Exit status: 0 stopped (a signal or --duration), 1 a line or the map could
not be had, 2 usage (unknown emulator or option).)";

volatile std::sig_atomic_t stop_signal = 0;

void request_stop(int signal_number) { stop_signal = signal_number; }

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
}

bool stop_requested() { return stop_signal != 0; }

int usage_error(const std::exception& e) {
  std::cerr << "player-drivers: " << e.what() << "\nRun with --help for more information.\n";
  return drivers::kExitUsage;
}

playerkit::core::DriverRegistry load_registry(const std::vector<std::string>& plugins) {
  playerkit::core::Logger logger("player-drivers");
  logger.set_level(playerkit::core::LogLevel::kWarning);
  return playerkit::daemon::load_drivers(plugins, logger);
}

int probe(const drivers::ProbeOptions& options) {
  drivers::ProbeSettings settings = options.settings;
  if (options.verbose) settings.progress = [](std::string_view line) { std::cerr << "player-drivers: " << line << "\n"; };
  bool all_found = true;
  for (const auto& port : options.ports) {
    if (stop_requested()) return drivers::kExitFailure;
    if (options.verbose) std::cerr << "player-drivers: probing " << port << "\n";
    const auto result = drivers::probe_port(port, settings, stop_requested);
    all_found = all_found && result.found.has_value();
    drivers::write_probe_result(result, options.json, options.json || result.found ? std::cout : std::cerr);
  }
  return all_found ? drivers::kExitOk : drivers::kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-drivers: bring up robot hardware from the terminal: the drivers built in,\n"
               "one driver (or a robot's family) run standalone, which device answers on a port,\n"
               "and emulated devices to rehearse with."};
  app.name("player-drivers");
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("player-drivers (playerkit) ") + PLAYERKIT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();

  std::vector<std::string> plugins;
  app.add_option("-d,--plugin", plugins, "also the drivers of this shared object (repeatable)")
      ->type_name("PLUGIN")
      ->allow_extra_args(false);

  drivers::ListCommandLine list_line;
  auto* list = app.add_subcommand("list", "every driver: interfaces, access, needs hardware, summary");
  list->add_option("--interface", list_line.interface, "only drivers serving this interface (laser, position, ...)")
      ->type_name("NAME");
  list->add_flag("--json", list_line.json, "one JSON object per driver and line");

  std::string info_name;
  bool info_json = false;
  auto* info = app.add_subcommand("info", "a driver's options, requests, manual section and a config to paste");
  info->add_option("NAME", info_name, "a driver, or a family such as p2os")->required();
  info->add_flag("--json", info_json, "one JSON object");

  drivers::RunCommandLine run_line;
  auto* run = app.add_subcommand("run", "one driver (or a robot's family) standalone: no config file, no server");
  run->footer(kRunFooter);
  run->add_option("NAME", run_line.words, "NAME [OPTION=VALUE...]")->required();
  run->add_option("--device", run_line.device,
                  "the device to serve the driver as (a driver of several interfaces), or of a family the one "
                  "to read and send to")
      ->type_name("DEVICE");
  run->add_option("--format", run_line.format, "text, json, csv or log (as player-cat)")
      ->type_name("FORMAT")
      ->capture_default_str();
  run->add_option("-n,--count", run_line.count, "stop after N data messages")->type_name("N");
  run->add_option("--duration", run_line.duration, "stop after SECONDS")->type_name("SECONDS");
  run->add_option("--field", run_line.fields, "print only this dotted path of the data (repeatable)")
      ->type_name("PATH")
      ->allow_extra_args(false);
  run->add_flag("--si", run_line.si, "SI units (metres, radians) instead of the wire's");
  run->add_option("-t", run_line.timestamps, "times shown: a absolute, d delta, z from the first")
      ->type_name("a|d|z")
      ->capture_default_str();
  run->add_flag("--stdin", run_line.from_stdin, "send player-send's JSON lines from stdin as commands and requests");
  run->add_option("--req", run_line.request, "send one request (player-send's names), print the reply, exit")
      ->type_name("NAME [FIELD=VALUE...]");
  run->add_option("--serve", run_line.serve_port, "also serve the devices to Player clients on PORT (0: any free)")
      ->type_name("PORT");
  run->add_option("--bind", run_line.bind, "with --serve: the address to listen on (default all)")->type_name("ADDRESS");
  run->add_option("--record", run_line.record, "write the data to a Player log file (writelog)")->type_name("FILE");
  run->add_flag("--stats", run_line.stats, "each second on stderr: rate, interval, jitter, the link's counters");
  run->add_flag("--trace", run_line.trace, "hex-dump every telegram both ways on stderr, framed and timestamped");
  run->add_flag("-v,--verbose", run_line.verbose, "the daemon's information messages too");
  run->add_option("--timeout", run_line.timeout, "seconds to wait for the connection and each reply")
      ->type_name("SECONDS")
      ->capture_default_str();

  drivers::ProbeCommandLine probe_line;
  auto* probe_command = app.add_subcommand("probe", "which supported device answers on each port");
  probe_command->footer(kProbeFooter);
  probe_command->add_option("PORT", probe_line.ports, "serial ports (/dev/ttyUSB0) or tcp:HOST:PORT bridges")
      ->required();
  probe_command->add_flag("--json", probe_line.json, "one JSON object per port");
  probe_command->add_flag("-v,--verbose", probe_line.verbose, "each attempt on stderr");
  probe_command->add_option("--budget", probe_line.budget, "at most SECONDS a port")
      ->type_name("SECONDS")
      ->capture_default_str();

  drivers::EmulateCommandLine emulate_line;
  std::vector<std::string> links;
  std::vector<std::string> tcp_ports;
  auto* emulate = app.add_subcommand("emulate", "emulated devices on pseudo-terminals or TCP ports until Ctrl-C");
  emulate->footer(kEmulateFooter);
  emulate->add_option("NAME", emulate_line.words, "NAME [KEY=VALUE...]...")->required();
  auto* link_option = emulate->add_option("--link", links, "a symlink to the emulator's pseudo-terminal (repeatable)")
                          ->type_name("PATH")
                          ->allow_extra_args(false);
  auto* tcp_option = emulate->add_option("--tcp", tcp_ports, "the emulator on a loopback TCP port (0: any free)")
                         ->type_name("PORT")
                         ->allow_extra_args(false);
  emulate->add_option("--map", emulate_line.map, "the world: a map image or a ROS .yaml")->type_name("MAP");
  emulate->add_option("--map-scale", emulate_line.map_scale, "metres per pixel of --map's image")
      ->type_name("METRES");
  emulate->add_flag("--map-negate", emulate_line.map_negate, "--map's image has walls white (Player's map_negate)");
  emulate->add_option("--fault", emulate_line.faults, "a fault on every line: KIND=VALUE (repeatable)")
      ->type_name("KIND=VALUE")
      ->allow_extra_args(false);
  emulate->add_flag("--stats", emulate_line.stats, "each emulator's counters and state every second on stderr");
  emulate->add_option("--duration", emulate_line.duration, "stop after SECONDS")->type_name("SECONDS");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }

  try {
    if (*list) {
      const auto options = drivers::make_list_options(list_line);
      drivers::write_driver_list(load_registry(plugins), options, std::cout);
      return drivers::kExitOk;
    }
    if (*info) {
      drivers::write_driver_info(load_registry(plugins), info_name, info_json, std::cout);
      return drivers::kExitOk;
    }
    if (*run) {
      run_line.plugins = plugins;
      const auto options = drivers::make_run_options(run_line);
      install_signal_handlers();
      return drivers::run_driver(options, {std::cout, std::cerr, STDIN_FILENO}, stop_requested);
    }
    if (*probe_command) {
      const auto options = drivers::make_probe_options(probe_line);
      install_signal_handlers();
      return probe(options);
    }
    // --link and --tcp in the order typed: the n-th goes to the n-th emulator.
    std::size_t next_link = 0, next_tcp = 0;
    for (const CLI::Option* option : emulate->parse_order()) {
      if (option == link_option) emulate_line.endpoints.push_back({drivers::EndpointArgument::Kind::link, links.at(next_link++)});
      if (option == tcp_option) emulate_line.endpoints.push_back({drivers::EndpointArgument::Kind::tcp, tcp_ports.at(next_tcp++)});
    }
    const auto options = drivers::make_emulate_options(emulate_line);
    install_signal_handlers();
    return drivers::run_emulators(options, std::cout, std::cerr, stop_requested);
  } catch (const drivers::UsageError& e) {
    return usage_error(e);
  } catch (const playerkit::core::PluginError& e) {
    std::cerr << "player-drivers: " << e.what() << "\n";
    return drivers::kExitFailure;
  }
}
