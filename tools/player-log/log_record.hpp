#pragma once
// `player-log record`: a client-side Player log. From a server: subscribe to
// the devices (lib/client) and write each data message as a log line, a
// "sync" line per SYNCH once data has been written. From stdin ("-"): lines of
// `player-cat --format log`, each checked with the log reader and kept as is.
//
// The log streams to its final name (so `tail -f` and `player-log info` see
// it grow), opened only once the recording starts: a recording that cannot
// start (no server, no such device) leaves an older file of that name alone.
// Every line is flushed (gzip, `-o run.log.gz`: at most once a second), and
// SIGINT/SIGTERM end the run between lines, so no line is ever torn; whatever
// ends the run, what was recorded stays. The output may not be stdin's file.

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
  // The server's data frequency (push rounds per second); nullopt: the
  // server's default, Player 1.5's 10 Hz, which keeps only the newest sample
  // of a faster device per round.
  std::optional<std::uint16_t> frequency;
};

// The targets as typed: ["-"] or [HOST[:PORT]] DEVICE...; throws UsageError.
void parse_record_targets(const std::vector<std::string>& targets, RecordOptions& options);

// Returns the exit status; errors are reported on err.
int run_record(const RecordOptions& options, std::istream& in, std::ostream& out, std::ostream& err,
               const std::function<bool()>& stop_requested);

}  // namespace playerkit::plog
