#include "help_text.hpp"

#include <algorithm>
#include <string_view>

#include "emulators/runner/fault_plan.hpp"

namespace playerkit::player_drivers {

namespace {

// The families' examples of one subcommand ("run", "emulate"), indented.
std::string family_examples(const families::FamilyRegistry& families, std::string_view subcommand) {
  const std::string prefix = "player-drivers " + std::string(subcommand) + " ";
  std::string lines;
  for (const auto& family : families.all()) {
    for (const auto& example : family.examples) {
      if (example.starts_with(prefix)) lines += "  " + example + "\n";
    }
  }
  return lines;
}

// Every kind the fault plan takes, from its own list, so none goes unmentioned.
std::string fault_list() {
  std::string lines;
  for (const emulators::FaultKind& kind : emulators::fault_kinds()) {
    std::string argument(kind.argument);
    argument.resize(std::max<std::size_t>(argument.size(), 16), ' ');
    lines += "  " + argument + std::string(kind.summary) + "\n";
  }
  return lines;
}

std::string probe_list(const families::FamilyRegistry& families) {
  std::string lines;
  for (const auto& family : families.all()) {
    for (const auto& probe : family.probes) {
      std::string rates;
      for (const int baud : probe.bauds) rates += (rates.empty() ? "" : ", ") + std::to_string(baud);
      lines += "  " + probe.label + " (" + family.name + "): " + rates + " baud\n";
    }
  }
  return lines.empty() ? "  (none: no family that can be probed is built)\n" : lines;
}

std::string emulator_list(const families::FamilyRegistry& families) {
  const auto catalog = families.emulator_catalog();
  std::size_t width = 0;
  for (const auto& kind : catalog.kinds()) width = std::max(width, kind.name.size());
  std::string lines;
  for (const auto& kind : catalog.kinds()) {
    lines += "  " + kind.name + std::string(width + 2 - kind.name.size(), ' ') + kind.summary + "\n";
  }
  return lines.empty() ? "  (none: no family with an emulator is built)\n" : lines;
}

}  // namespace

std::string main_footer(const families::FamilyRegistry& families) {
  return "Examples:\n"
         "  player-drivers list                              every driver: interfaces, access, hardware, summary\n"
         "  player-drivers list --interface laser --json     the laser drivers as JSON lines\n"
         "  player-drivers info NAME                         options, requests, manual section, a config to paste\n" +
         family_examples(families, "info") +
         "  player-drivers run lifomcom --req push channel=news data.data=hello\n" +
         family_examples(families, "run") +
         "  player-drivers probe /dev/ttyUSB0 /dev/ttyUSB1   which device answers where, and its config line\n" +
         family_examples(families, "emulate") +
         "\n"
         "Each subcommand's --help has more (player-drivers run --help).\n"
         "\n"
         "Exit status: 0 done; 1 the work failed (a port, a device, the daemon, a map;\n"
         "probe: some port not identified); 2 usage error (bad flag, unknown driver or\n"
         "emulator, an option the driver refuses); run --req: 3 NACK, 4 ERR.\n"
         "Signals: SIGINT and SIGTERM stop run, probe and emulate cleanly.";
}

std::string run_footer(const families::FamilyRegistry& families) {
  return "NAME is a driver (player-drivers list) or a family of drivers served together on\n"
         "one link (a robot's devices). OPTION=VALUE are the driver's configuration\n"
         "options (player-drivers info NAME); numbers, [tuples] and \"strings\" go in as\n"
         "written, other text as a string.\n"
         "\n"
         "Data goes to stdout as player-cat prints it. With --stdin, JSON lines in\n"
         "player-send's form are sent as commands and requests while the data is\n"
         "printed (replies as JSON lines too); the run ends with the input unless -n\n"
         "or --duration say otherwise. --req sends one request, prints the reply and\n"
         "exits with its status.\n"
         "\n"
         "Examples:\n"
         "  player-drivers run readlog filename=run.log --device laser:0 --field ranges.0\n"
         "  player-drivers run lifomcom --req push channel=news data.data=hello --serve 6665\n" +
         family_examples(families, "run") +
         "\n"
         "Exit status: 0 done (count, duration, end of --stdin, a signal), 1 the daemon,\n"
         "a device or the connection failed, 2 usage (unknown driver, an option it\n"
         "refuses, bad flags), 3 NACK and 4 ERR (--req, --stdin).";
}

std::string probe_footer(const families::FamilyRegistry& families) {
  return "Before opening a port, probe checks what most often goes wrong: a missing\n"
         "port (and similar ones that exist), permissions (and the group to join), a\n"
         "port held by another program (and which). Then it asks the devices of each\n"
         "family built, every probe's likeliest baud rate first, at most --budget\n"
         "seconds a port. A device found is left ready for its driver.\n"
         "\n"
         "Probes (baud rates, likeliest first):\n" +
         probe_list(families) +
         "\n"
         "Examples:\n"
         "  player-drivers probe /dev/ttyUSB0\n"
         "  player-drivers probe /dev/ttyUSB0 /dev/ttyUSB1 tcp:192.168.1.20:4001 --json\n"
         "\n"
         "Exit status: 0 every port identified, 1 some port was not (the message says\n"
         "why), 2 usage.";
}

std::string emulate_footer(const families::FamilyRegistry& families) {
  return "Emulators (each NAME may be followed by KEY=VALUE options; an unknown KEY\n"
         "lists the emulator's options):\n" +
         emulator_list(families) +
         "Poses are metres, metres, degrees. With a robot and a sensor that rides, the\n"
         "sensor rides on the robot (mount=x,y,yaw). --link PATH and --tcp PORT go to\n"
         "the emulators in the order given; an emulator without one gets a\n"
         "pseudo-terminal of its own. A map image needs --map-scale unless a .yaml of\n"
         "the same name lies beside it.\n"
         "\n"
         "Examples:\n" +
         family_examples(families, "emulate") +
         "  player-drivers emulate NAME --tcp 0 --map data/maps/stage-cave.png --stats\n"
         "\n"
         "Faults (--fault KIND=VALUE, repeatable; P a probability, S seconds):\n" +
         fault_list() +
         "Exit status: 0 stopped (a signal or --duration), 1 a line or the map could\n"
         "not be had, 2 usage (unknown emulator or option).";
}

}  // namespace playerkit::player_drivers
