#pragma once
// `player-log replay`: serve a log's devices over TCP without writing a
// configuration: one readlog device per logged device, on one port. A CARMEN
// log is first converted to a temporary Player log (removed at exit).

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/logger.hpp"
#include "log_tool.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {

struct ReplayOptions {
  std::string input;
  std::uint16_t port = 6665;  // 0: any free port (the start-up line says which)
  std::string bind_address = "0.0.0.0";
  double rate = 1.0;          // 2: twice as fast as logged
  bool loop = false;          // start again at the end
  double start = 0.0;         // seconds into the log
  std::optional<double> duration;                  // seconds of log per pass
  std::vector<protocol::DeviceAddress> devices;    // empty: every device the log holds
  bool burst = false;         // as fast as clients read, never dropping
  core::LogLevel log_level = core::LogLevel::kInfo;
};

// The configuration text that serves `devices` with readlog from `start`
// seconds into the log, rewinding at the end when `loop`.
std::string replay_configuration(const std::vector<protocol::DeviceAddress>& devices, double start, bool loop);

// The devices of a Player log that readlog can serve, by interface and index.
// Throws std::runtime_error.
std::vector<protocol::DeviceAddress> replayable_devices(const std::string& player_log, Progress& progress);

// Serves until SIGINT/SIGTERM; returns the exit status (0 after a signal).
// Throws UsageError (a --devices entry the log does not hold) and
// std::runtime_error (unreadable log).
int run_replay(const ReplayOptions& options, std::ostream& err, Progress& progress);

}  // namespace playerkit::plog
