#include "outgoing_message.hpp"

#include <vector>

#include "config/closest_name.hpp"
#include "field_assignments.hpp"
#include "protocol/catalog.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/payload_json.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {

namespace {

std::string suggestion(std::string_view word, std::span<const std::string_view> candidates) {
  const auto closest = config::closest_name(word, candidates);
  return closest ? " (did you mean " + *closest + "?)" : "";
}

const protocol::InterfaceMessages& messages_of(protocol::DeviceAddress device) {
  const auto* messages = protocol::find_messages(device.interface);
  if (!messages) {
    throw UsageError(protocol::interface_name(device.interface) + " is not a Player 1.5 interface");
  }
  return *messages;
}

protocol::Message make_message(protocol::MessageType type, protocol::DeviceAddress device,
                               std::vector<std::uint8_t> payload) {
  protocol::Message message;
  message.header = protocol::make_header(type, device, {}, {});
  message.header.size = static_cast<std::uint32_t>(payload.size());
  message.payload = std::move(payload);
  return message;
}

protocol::Message command_message(protocol::DeviceAddress device, std::span<const std::string> assignments) {
  const auto& messages = messages_of(device);
  const auto name = protocol::interface_name(device.interface);
  if (!messages.command) {
    throw UsageError(name + " takes no commands (Player 1.5 defines none); its requests: " +
                     request_names(device.interface));
  }
  const auto fields = parse_field_assignments(assignments);
  try {
    return make_message(protocol::MessageType::kCommand, device, messages.command->from_json(fields));
  } catch (const protocol::JsonError& e) {
    throw UsageError(name + " cmd: " + e.what());
  } catch (const protocol::EncodeError& e) {
    throw UsageError(name + " cmd: " + e.what());
  }
}

protocol::Message request_message(protocol::DeviceAddress device, std::span<const std::string> words) {
  const auto& messages = messages_of(device);
  const auto name = protocol::interface_name(device.interface);
  if (messages.requests.empty()) throw UsageError(name + " takes no requests (Player 1.5 defines none)");
  if (words.empty()) throw UsageError("req needs a request name; " + name + "'s requests: " + request_names(device.interface));
  const auto* kind = messages.find_request(std::string_view(words.front()));
  if (!kind) {
    std::vector<std::string_view> names;
    for (const auto& k : messages.requests) names.push_back(k.name);
    throw UsageError(name + " has no request '" + words.front() + "'" + suggestion(words.front(), names) +
                     "; its requests: " + request_names(device.interface));
  }
  const auto fields = parse_field_assignments(words.subspan(1));
  try {
    return make_message(protocol::MessageType::kRequest, device, protocol::request_payload(messages, *kind, fields));
  } catch (const protocol::JsonError& e) {
    throw UsageError(name + " req " + std::string(kind->name) + ": " + e.what());
  } catch (const protocol::EncodeError& e) {
    throw UsageError(name + " req " + std::string(kind->name) + ": " + e.what());
  }
}

}  // namespace

std::string request_names(std::uint16_t interface) {
  const auto* messages = protocol::find_messages(interface);
  std::string names;
  if (messages) {
    for (const auto& kind : messages->requests) names += (names.empty() ? "" : ", ") + std::string(kind.name);
  }
  return names.empty() ? "none" : names;
}

protocol::DeviceAddress parse_device(std::string_view text) {
  if (const auto device = protocol::parse_device_address(text)) return *device;
  const auto colon = text.find(':');
  const auto name = text.substr(0, colon);
  if (!protocol::find_interface(name) && !protocol::parse_decimal_u16(name)) {
    std::vector<std::string_view> names;
    for (const auto& info : protocol::all_interfaces()) names.push_back(info.name);
    throw UsageError("'" + std::string(text) + "' is not a device: unknown interface '" + std::string(name) + "'" +
                     suggestion(name, names));
  }
  throw UsageError("'" + std::string(text) + "' is not a device: the index after ':' must be a number 0..65535");
}

protocol::Message message_from_arguments(std::span<const std::string> words) {
  if (words.empty()) throw UsageError("missing DEVICE (like position:0); see --help");
  const auto device = parse_device(words.front());
  if (words.size() < 2) throw UsageError("expected 'cmd' or 'req' after " + words.front());
  const auto& verb = words[1];
  if (verb == "cmd") return command_message(device, words.subspan(2));
  if (verb == "req") return request_message(device, words.subspan(2));
  throw UsageError("expected 'cmd' or 'req' after " + words.front() + ", got '" + verb + "'");
}

}  // namespace playerkit::player_send
