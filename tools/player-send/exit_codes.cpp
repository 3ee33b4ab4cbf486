#include "exit_codes.hpp"

namespace playerkit::player_send {

ExitCode exit_code_for_reply(protocol::MessageType reply_type) {
  switch (reply_type) {
    case protocol::MessageType::kAck: return ExitCode::kAck;
    case protocol::MessageType::kNack: return ExitCode::kNack;
    case protocol::MessageType::kError: return ExitCode::kError;
    default: return ExitCode::kConnection;
  }
}

ExitCode combine(ExitCode so_far, ExitCode next) { return so_far == ExitCode::kAck ? next : so_far; }

}  // namespace playerkit::player_send
