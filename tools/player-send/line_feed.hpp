#pragma once
// `player-send --stdin`: one message per line (json_line.hpp), sent in order,
// optionally paced.
//
// A line that cannot be understood, or a command to a device that cannot be
// opened for writing, stops the feed with its line number on stderr: the lines
// before it were sent, nothing after it is read. Stopping rather than skipping
// because a stream of commands with a hole in it (a lost "stop") is worse than
// one that ends where the fault is, and a pipe's writer sees player-send exit.
// A lost connection or a timeout stops it the same way (exit 1).
// A NACK or ERR reply does not stop the feed: it is printed like any reply.
// Blank lines are skipped.

#include <istream>
#include <optional>
#include <ostream>

#include "exit_codes.hpp"
#include "sender.hpp"

namespace playerkit::player_send {

// Returns kUsage, kError or kConnection (lost connection, timeout) for a line
// that stopped the feed, otherwise the code of the first reply that was not
// an ACK (kAck if all were). rate_hz spaces the messages 1/rate_hz seconds apart.
ExitCode send_lines(std::istream& in, Sender& sender, std::optional<double> rate_hz, std::ostream& diagnostics);

}  // namespace playerkit::player_send
