#include "client/typed/message_as.hpp"

#include <string>
#include <vector>

#include "protocol/catalog.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::client {
namespace {

std::string device_of(const protocol::Message& message) { return protocol::to_string(message.device()); }

std::string article(std::string_view type) { return type == "ack" || type == "err" ? "an " : "a "; }

// "position, position3d", or "no interface" when no interface carries the struct that way.
template <class Carries>
std::string interfaces_carrying(Carries carries) {
  std::string names;
  for (const auto& m : protocol::all_messages()) {
    if (!carries(m)) continue;
    if (!names.empty()) names += ", ";
    names += protocol::interface_name(m.interface);
  }
  return names.empty() ? std::string("no interface") : names;
}

void check_fixed(const protocol::Message& message, std::string_view wire_name, protocol::MessageType wanted,
                 const protocol::PayloadCodec* protocol::InterfaceMessages::*slot) {
  const std::string what(protocol::to_string(wanted));
  if (message.type() != wanted) {
    const std::string got(protocol::to_string(message.type()));
    throw MessageKindError(device_of(message) + ": expected a " + what + " message carrying " +
                           std::string(wire_name) + ", got " + article(got) + got + " message");
  }
  const auto* messages = protocol::find_messages(message.header.device);
  const protocol::PayloadCodec* codec = messages ? messages->*slot : nullptr;
  if (codec && codec->wire_name == wire_name) return;
  const std::string carried = codec ? std::string(codec->wire_name) : "no known struct";
  throw MessageKindError(device_of(message) + ": its " + what + " carries " + carried + ", not " +
                         std::string(wire_name) + " (the " + what + " of " +
                         interfaces_carrying([&](const protocol::InterfaceMessages& m) {
                           const auto* c = m.*slot;
                           return c && c->wire_name == wire_name;
                         }) +
                         ")");
}

}  // namespace

namespace detail {

void check_data(const protocol::Message& message, std::string_view wire_name) {
  check_fixed(message, wire_name, protocol::MessageType::kData, &protocol::InterfaceMessages::data);
}

void check_command(const protocol::Message& message, std::string_view wire_name) {
  check_fixed(message, wire_name, protocol::MessageType::kCommand, &protocol::InterfaceMessages::command);
}

void check_reply(const protocol::Message& message, std::string_view wire_name,
                 std::optional<std::uint16_t> request_subtype) {
  const auto type = message.type();
  if (type == protocol::MessageType::kNack || type == protocol::MessageType::kError) {
    const std::string got(protocol::to_string(type));
    throw MessageKindError(device_of(message) + ": the request was refused (" + got + "), there is no " +
                           std::string(wire_name) + " to read");
  }
  if (type != protocol::MessageType::kAck) {
    const std::string got(protocol::to_string(type));
    throw MessageKindError(device_of(message) + ": expected an ack carrying " + std::string(wire_name) + ", got " +
                           article(got) + got + " message");
  }
  const auto* messages = protocol::find_messages(message.header.device);
  std::vector<const protocol::RequestKind*> answered_with;
  if (messages) {
    for (const auto& kind : messages->requests) {
      if (kind.reply && kind.reply->wire_name == wire_name) answered_with.push_back(&kind);
    }
  }
  if (answered_with.empty()) {
    throw MessageKindError(device_of(message) + ": no request of " +
                           protocol::interface_name(message.header.device) + " is answered with " +
                           std::string(wire_name));
  }
  if (!request_subtype) return;
  for (const auto* kind : answered_with) {
    if (kind->subtype == *request_subtype) return;
  }
  const auto* kind = messages->find_request(*request_subtype);
  const std::string name = kind ? std::string(kind->name) : "subtype " + std::to_string(*request_subtype);
  const std::string carried =
      kind && kind->reply ? std::string(kind->reply->wire_name) : std::string("no known struct");
  throw MessageKindError(device_of(message) + ": the reply to " + name + " carries " + carried + ", not " +
                         std::string(wire_name));
}

}  // namespace detail
}  // namespace playerkit::client
