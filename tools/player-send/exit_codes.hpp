#pragma once
// player-send's exit status: the reply's type for requests, and distinct codes
// for what went wrong before any reply could come.

#include "exit_status.hpp"
#include "protocol/constants.hpp"

namespace playerkit::player_send {

// The values are tools/common's table (exit_status.hpp).
enum class ExitCode : int {
  kAck = tools::kExitOk,             // ACK, or every command delivered to the server
  kConnection = tools::kExitFailure,  // connection refused or lost, timeout, authentication refused
  kUsage = tools::kExitUsage,         // bad arguments or input: unknown device, request, field or value
  kNack = tools::kExitNack,           // the device refused the request
  kError = tools::kExitError,         // the server answered ERR, or the device could not be opened for it
};

// ACK → 0, NACK → 3, ERR → 4; anything else is not a reply and counts as a
// broken conversation (1).
ExitCode exit_code_for_reply(protocol::MessageType reply_type);

// The status of a run that sent several messages: the first failure wins, so a
// NACK early on is not hidden by later ACKs.
ExitCode combine(ExitCode so_far, ExitCode next);

constexpr int to_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace playerkit::player_send
