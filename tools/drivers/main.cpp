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
#include "families/builtin_families.hpp"
#include "help_text.hpp"
#include "known_drivers.hpp"
#include "emulate_options.hpp"
#include "emulate_session.hpp"
#include "probe_output.hpp"
#include "probe_options.hpp"
#include "run_options.hpp"
#include "run_session.hpp"

namespace {

namespace drivers = playerkit::player_drivers;
namespace families = playerkit::families;

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
  return drivers::known_drivers(plugins, families::builtin_families(), logger);
}

int probe(const drivers::ProbeOptions& options) {
  families::ProbeSettings settings = options.settings;
  if (options.verbose) settings.progress = [](std::string_view line) { std::cerr << "player-drivers: " << line << "\n"; };
  bool all_found = true;
  for (const auto& port : options.ports) {
    if (stop_requested()) return drivers::kExitFailure;
    if (options.verbose) std::cerr << "player-drivers: probing " << port << "\n";
    const auto result = families::probe_port(port, families::builtin_families(), settings, stop_requested);
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
  const families::FamilyRegistry& hardware = families::builtin_families();
  app.footer(drivers::main_footer(hardware));
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
  info->add_option("NAME", info_name, "a driver, or a family of drivers")->required();
  info->add_flag("--json", info_json, "one JSON object");

  drivers::RunCommandLine run_line;
  auto* run = app.add_subcommand("run", "one driver (or a robot's family) standalone: no config file, no server");
  run->footer(drivers::run_footer(hardware));
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
  probe_command->footer(drivers::probe_footer(hardware));
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
  emulate->footer(drivers::emulate_footer(hardware));
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
      return drivers::run_driver(options, hardware, {std::cout, std::cerr, STDIN_FILENO}, stop_requested);
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
    const auto catalog = hardware.emulator_catalog();
    const auto options = drivers::make_emulate_options(emulate_line, catalog);
    install_signal_handlers();
    return drivers::run_emulators(options, catalog, std::cout, std::cerr, stop_requested);
  } catch (const drivers::UsageError& e) {
    return usage_error(e);
  } catch (const playerkit::core::PluginError& e) {
    std::cerr << "player-drivers: " << e.what() << "\n";
    return drivers::kExitFailure;
  }
}
