#include "protocol/message_json.hpp"

#include <string>

#include "protocol/catalog.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::protocol {
namespace {

const RequestKind* kind_for(const Message& message, std::optional<std::uint16_t> request_subtype) {
  const auto* messages = find_messages(message.header.device);
  if (!messages) return nullptr;
  if (request_subtype) return messages->find_request(*request_subtype);
  if (message.type() == MessageType::kRequest || is_reply(message.type())) {
    return request_kind_of(message.header.device, message.payload);
  }
  return nullptr;
}

Timestamp read_time(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return {};
  if (!it->is_number()) throw JsonError(std::string(key) + ": expected seconds, got " + it->dump());
  const double seconds = it->get<double>();
  if (seconds > Timestamp::kMaxSeconds) {
    throw JsonError(std::string(key) + ": " + it->dump() + " s is past the latest time a header holds (" +
                    "4294967295.999999 s)");
  }
  return Timestamp::from_seconds(seconds);
}

}  // namespace

nlohmann::json message_to_json(const Message& message, std::optional<std::uint16_t> request_subtype) {
  const auto type = message.type();
  nlohmann::json j;
  j["type"] = std::string(to_string(type));
  // An interface 1.5 does not define keeps its code, as a number, so that
  // the line can be sent back (player-send takes codes; "interface 73" no).
  if (find_interface(message.header.device) != nullptr) {
    j["device"] = interface_name(message.header.device);
  } else {
    j["device"] = message.header.device;
  }
  j["index"] = message.header.device_index;
  j["time"] = message.time().seconds();
  j["timestamp"] = message.timestamp().seconds();
  if (const auto* kind = kind_for(message, request_subtype)) j["request"] = std::string(kind->name);
  j["data"] = payload_to_json(message.header.device, type, message.payload, request_subtype);
  return j;
}

Message message_from_json(const nlohmann::json& j) {
  if (!j.is_object()) throw JsonError("message: expected an object, got " + j.dump());
  const auto type_it = j.find("type");
  if (type_it == j.end() || !type_it->is_string()) throw JsonError("message: \"type\" is missing");
  const auto type = parse_message_type(type_it->get<std::string>());
  if (!type) throw JsonError("message: unknown type '" + type_it->get<std::string>() + "'");

  const auto device_it = j.find("device");
  if (device_it == j.end()) throw JsonError("message: \"device\" is missing");
  std::uint16_t interface = 0;
  if (device_it->is_string()) {
    const auto* info = find_interface(device_it->get<std::string>());
    if (!info) throw JsonError("message: unknown device '" + device_it->get<std::string>() + "'");
    interface = info->code;
  } else if (device_it->is_number_unsigned() && device_it->get<std::uint64_t>() <= 0xFFFF) {
    interface = device_it->get<std::uint16_t>();
  } else {
    throw JsonError("message: \"device\" must be an interface name or code, got " + device_it->dump());
  }
  std::uint16_t index = 0;
  if (const auto index_it = j.find("index"); index_it != j.end()) {
    // Checked here rather than by the JSON library, which would wrap 70000
    // or cut 1.5 without a word.
    if (!index_it->is_number_unsigned() || index_it->get<std::uint64_t>() > 0xFFFF) {
      throw JsonError("message: \"index\" must be a whole number from 0 to 65535, got " + index_it->dump());
    }
    index = index_it->get<std::uint16_t>();
  }

  std::optional<std::uint16_t> subtype;
  if (const auto request = j.find("request"); request != j.end()) {
    if (!request->is_string()) {
      throw JsonError("message: \"request\" must be a request's name, got " + request->dump());
    }
    const auto* messages = find_messages(interface);
    const RequestKind* kind = messages ? messages->find_request(request->get<std::string>()) : nullptr;
    if (!kind) {
      throw JsonError("message: " + interface_name(interface) + " has no request '" +
                      request->get<std::string>() + "'");
    }
    subtype = kind->subtype;
  }

  Message message;
  message.header = make_header(*type, {interface, index}, read_time(j, "time"), read_time(j, "timestamp"));
  const nlohmann::json data = j.value("data", nlohmann::json::object());
  message.payload = payload_from_json(interface, *type, data, subtype);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

}  // namespace playerkit::protocol
