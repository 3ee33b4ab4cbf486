#pragma once
// `player-log record`: a client-side Player log. From a server: subscribe to
// the devices (lib/client) and write each data message as a log line, a
// "sync" line per SYNCH once data has been written, flushing every line so
// that a signal loses nothing already received. From stdin ("-"): lines of
// `player-cat --format log`, each checked with the log reader and kept as is.

#include <cstdint>
#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "client/endpoint.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {

struct RecordOptions {
  bool from_stdin = false;
  client::ServerEndpoint server;
  std::vector<protocol::DeviceAddress> devices;
  std::string output;  // "-" = stdout
  std::optional<double> duration;    // s
  std::optional<std::uint64_t> count;  // data messages
  double timeout = 5.0;  // s, connecting and each request
  bool strict = false;   // stdin: a malformed line is fatal
};

// The targets as typed: ["-"] or [HOST[:PORT]] DEVICE...; throws UsageError.
void parse_record_targets(const std::vector<std::string>& targets, RecordOptions& options);

// Returns the exit status; errors are reported on err.
int run_record(const RecordOptions& options, std::istream& in, std::ostream& out, std::ostream& err,
               const std::function<bool()>& stop_requested);

}  // namespace playerkit::plog
