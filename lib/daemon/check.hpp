#pragma once
// `player-serve --check`: everything serve() verifies before it accepts a
// client, short of opening hardware, sockets or output files. The same steps
// as Daemon::load(), without binding a port:
//
//  * the -r log: readable, a Player text log (a CARMEN log is refused saying
//    that player-log replays it), a first line to replay;
//  * the -s world: read, every model made, its devices listed;
//  * the configuration: syntax, declarations, drivers that exist in this
//    build (built-in and plugins) and serve the declared interface;
//  * every driver created: each reads and checks its options and the files it
//    reads or writes (readlog's log, amcl's map, writelog's directory);
//  * every driver's check(): the devices it needs (writelog's sources, amcl's
//    position and laser) exist;
//  * the whole: at least one device to serve.
//
// Device set-up (serial ports, remote servers, broadcast sockets) is not
// tried: that needs the hardware and the network.

#include <string>
#include <vector>

#include "config/config_file.hpp"
#include "core/driver_registry.hpp"
#include "core/device_table.hpp"
#include "daemon/serve.hpp"

namespace playerkit::daemon {

struct CheckedConfiguration {
  // With -s the world's devices first (simulation.hpp), then the
  // configuration file if one was given.
  std::vector<config::ConfigFile> configs;
  // "file:line:col: warning: ...": replaced declarations, options no driver read.
  std::vector<std::string> warnings;
};

// Throws config::ConfigError (file:line:col, or the file for the whole),
// sim::worldfile::WorldFileError (file:line:col), std::runtime_error naming
// the -r log or the world, core::PluginError.
CheckedConfiguration check_configuration(const ServeOptions& options);

// The readlog driver -r serves (check and serve alike); its devices claim the
// server clock with the log's time.
core::DriverSpec replay_driver_spec(const ServeOptions& options);

// The -r log is one readlog can replay (drivers::first_replay_time). Throws
// std::runtime_error naming the file.
void check_replay_log(const std::string& path);

// Player 1.5's device list holds 64 entries: one warning per port serving
// more (clients listing devices see the first 64; every device still opens).
std::vector<std::string> device_list_warnings(const core::DeviceTable& devices);

// What no single declaration shows: something to serve. Throws
// config::ConfigError naming the file.
void check_served(const core::DeviceTable& devices, const std::string& config_path);

}  // namespace playerkit::daemon
