#include "sender.hpp"

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "protocol/payload_json.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {

namespace {

using protocol::Access;

bool can_write(Access access) { return access == Access::kWrite || access == Access::kAll; }

bool is_open(Access access) { return can_write(access) || access == Access::kRead; }

std::string letter(Access access) { return std::string(1, static_cast<char>(access)); }

// A reply whose payload does not fit the struct the catalog names is still
// shown, byte for byte.
nlohmann::json reply_json(const protocol::Message& reply, std::optional<std::uint16_t> subtype,
                          std::ostream& diagnostics) {
  try {
    return protocol::message_to_json(reply, subtype);
  } catch (const protocol::DecodeError& e) {
    diagnostics << "player-send: the reply does not fit its struct (" << e.what() << "); showing its bytes\n";
    auto j = protocol::message_to_json(protocol::Message{reply.header, {}}, subtype);
    j["data"] = {{"raw", reply.payload}};
    return j;
  }
}

}  // namespace

Sender::Sender(client::Client& client, std::ostream& replies, std::ostream& diagnostics)
    : client_(client), replies_(replies), diagnostics_(diagnostics) {}

ExitCode Sender::send(const protocol::Message& message) {
  const auto device = message.device();
  const bool to_player = device.interface == protocol::kPlayerCode;
  if (message.type() == protocol::MessageType::kCommand) {
    if (!to_player && !open_for_writing(device)) return ExitCode::kError;
    client_.write_command(device, message.payload);
    commands_unconfirmed_ = true;
    return ExitCode::kAck;
  }
  if (message.type() != protocol::MessageType::kRequest) {
    throw UsageError("only commands and requests can be sent, not " + std::string(to_string(message.type())));
  }
  if (!to_player) open_for_request(device, message);
  const auto reply = client_.request(device, message.payload);
  const auto* kind = protocol::request_kind_of(device.interface, message.payload);
  const auto subtype = kind ? std::optional<std::uint16_t>(kind->subtype) : std::nullopt;
  replies_ << reply_json(reply, subtype, diagnostics_).dump() << std::endl;
  return exit_code_for_reply(reply.type());
}

void Sender::confirm_commands() {
  if (!commands_unconfirmed_) return;
  // DEVLIST changes nothing and is answered at once, after what came before it.
  const std::vector<std::uint8_t> devlist{0, static_cast<std::uint8_t>(protocol::kPlayerDevlistReq)};
  client_.request({protocol::kPlayerCode, 0}, devlist);
  commands_unconfirmed_ = false;
}

bool Sender::open_for_writing(protocol::DeviceAddress device) {
  const auto known = access_.find(device);
  if (known != access_.end() && can_write(known->second)) return true;
  const bool reading = known != access_.end() && known->second == Access::kRead;
  auto grant = client_.request_access(device, reading ? Access::kAll : Access::kWrite);
  if (!can_write(grant.access)) grant = client_.request_access(device, Access::kAll);
  access_[device] = grant.access;
  if (can_write(grant.access)) return true;
  diagnostics_ << "player-send: command not sent: ";
  explain_refusal(device, grant);
  return false;
}

void Sender::open_for_request(protocol::DeviceAddress device, const protocol::Message& request) {
  const auto known = access_.find(device);
  if (known != access_.end() && is_open(known->second)) return;
  // Reading is enough to ask; a request that carries settings opens fully, as
  // the 1.5 client libraries did for configurable devices.
  const auto* kind = protocol::request_kind_of(device.interface, request.payload);
  const bool query = kind && kind->form == protocol::RequestForm::kQuery;
  const auto grant = client_.request_access(device, query ? Access::kRead : Access::kAll);
  access_[device] = grant.access;
  if (is_open(grant.access)) return;
  diagnostics_ << "player-send: note: ";
  explain_refusal(device, grant);
  diagnostics_ << "player-send: sending the request anyway; the server answers it\n";
}

void Sender::explain_refusal(protocol::DeviceAddress device, const client::AccessGrant& grant) {
  const auto name = protocol::to_string(device);
  if (grant.driver_name.empty()) {
    diagnostics_ << name << " is not served on this port (not in the server's configuration)\n";
  } else if (grant.access == Access::kError) {
    diagnostics_ << name << " (driver " << grant.driver_name
                 << ") could not be opened: its set-up failed (see the server's log)\n";
  } else {
    diagnostics_ << name << " (driver " << grant.driver_name << "): the server granted access '"
                 << letter(grant.access) << "', not write access\n";
  }
}

}  // namespace playerkit::player_send
