#pragma once
// Sends commands and requests over one client connection, opening each device
// with the access it needs the first time it is used:
//
//   command               'w' (or 'a' if 'w' is not granted); not sent without either
//   request, a query      'r'
//   request with a struct 'a'
//   the `player` device   nothing to open
//
// A request to a device that could not be opened is still sent: the server's
// answer (ERR) is the reply, with a note on stderr saying why.

#include <map>
#include <ostream>

#include "client/client.hpp"
#include "exit_codes.hpp"
#include "protocol/message.hpp"

namespace playerkit::player_send {

class Sender {
 public:
  // Replies go to `replies` as one JSON object per line; notes and errors to `diagnostics`.
  Sender(client::Client& client, std::ostream& replies, std::ostream& diagnostics);

  // The message's own device and payload; its header's other fields are not
  // used. Returns the reply's exit code for a request, kAck for a command
  // handed to the server, kError for a command to a device that cannot be
  // written. Throws client::ClientError for a broken connection or a timeout.
  ExitCode send(const protocol::Message& message);

  // Commands get no reply; a round trip through the `player` device after
  // them returns once the server has read every one. Does nothing if no
  // command was sent since the last call.
  void confirm_commands();

 private:
  bool open_for_writing(protocol::DeviceAddress device);
  void open_for_request(protocol::DeviceAddress device, const protocol::Message& request);
  void explain_refusal(protocol::DeviceAddress device, const client::AccessGrant& grant);

  client::Client& client_;
  std::ostream& replies_;
  std::ostream& diagnostics_;
  std::map<protocol::DeviceAddress, protocol::Access> access_;
  bool commands_unconfirmed_ = false;
};

}  // namespace playerkit::player_send
