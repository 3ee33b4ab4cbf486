// player-serve: the Player 1.5 device server. See --help.

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "check_config.hpp"

namespace {

constexpr const char* kExamples = R"(Examples:
  player-serve --check robot.cfg       validate robot.cfg and list its devices
  player-serve -p 7000 robot.cfg       serve robot.cfg on port 7000

Exit status: 0 success, 1 runtime error, 2 usage error or invalid configuration.)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-serve: serve the devices of a Player configuration file over TCP,\n"
               "wire-compatible with Player 1.5 clients."};
  app.footer(kExamples);
  app.set_version_flag("--version", std::string("player-serve (playerkit) ") + PLAYERKIT_VERSION +
                                        ", Player protocol " + PLAYERKIT_PLAYER_VERSION);

  std::string config_path;
  std::uint16_t port = 6665;
  bool check = false;
  app.add_option("CONFIG", config_path, "configuration file (.cfg)")->required();
  app.add_option("-p,--port", port, "TCP port for devices outside a robot section")->capture_default_str();
  app.add_flag("--check", check, "validate the configuration, list its devices, and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  if (check) return playerkit::serve::check_config(config_path, port, std::cout, std::cerr);

  std::cerr << "player-serve: serving devices is not built yet; "
               "--check validates a configuration\n";
  return 1;
}
