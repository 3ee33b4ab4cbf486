#include "protocol/payload_json.hpp"

#include <string>

#include "protocol/byte_order.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::protocol {
namespace {

nlohmann::json raw_json(std::span<const std::uint8_t> payload) {
  return {{"raw", std::vector<std::uint8_t>(payload.begin(), payload.end())}};
}

std::vector<std::uint8_t> raw_bytes(const nlohmann::json& j) {
  std::vector<std::uint8_t> bytes;
  const auto& array = j.at("raw");
  if (!array.is_array()) throw JsonError("raw: expected an array of bytes");
  for (std::size_t i = 0; i < array.size(); ++i) {
    const auto& b = array[i];
    if (!b.is_number_integer() || b.get<std::int64_t>() < 0 || b.get<std::int64_t>() > 255) {
      throw JsonError("raw[" + std::to_string(i) + "]: expected a byte (0..255), got " + b.dump());
    }
    bytes.push_back(b.get<std::uint8_t>());
  }
  return bytes;
}

std::optional<std::uint16_t> leading_subtype(const InterfaceMessages& messages,
                                             std::span<const std::uint8_t> payload) {
  if (payload.size() < messages.subtype_size) return std::nullopt;
  return messages.subtype_size == 2 ? load_be<std::uint16_t>(payload.data()) : payload[0];
}

void write_subtype(const InterfaceMessages& messages, std::uint16_t subtype,
                   std::vector<std::uint8_t>& payload) {
  if (payload.size() < messages.subtype_size) payload.resize(messages.subtype_size);
  if (messages.subtype_size == 2) {
    store_be(payload.data(), subtype);
  } else {
    payload[0] = static_cast<std::uint8_t>(subtype);
  }
}

const PayloadCodec* fixed_codec(const InterfaceMessages& messages, MessageType type) {
  switch (type) {
    case MessageType::kData: return messages.data;
    case MessageType::kCommand: return messages.command;
    default: return nullptr;
  }
}

}  // namespace

const RequestKind* request_kind_of(std::uint16_t interface, std::span<const std::uint8_t> payload) {
  const auto* messages = find_messages(interface);
  if (!messages) return nullptr;
  const auto subtype = leading_subtype(*messages, payload);
  return subtype ? messages->find_request(*subtype) : nullptr;
}

nlohmann::json payload_to_json(std::uint16_t interface, MessageType type,
                               std::span<const std::uint8_t> payload,
                               std::optional<std::uint16_t> request_subtype) {
  const auto* messages = find_messages(interface);
  if (!messages) return raw_json(payload);
  if (type == MessageType::kSynch) return nlohmann::json::object();

  if (type == MessageType::kRequest) {
    const RequestKind* kind = request_kind_of(interface, payload);
    if (!kind) return raw_json(payload);
    if (payload.size() == messages->subtype_size || !kind->request) {
      if (payload.size() != messages->subtype_size) return raw_json(payload);
      return {{"subtype", kind->subtype}};
    }
    return kind->request->to_json(payload);
  }

  if (is_reply(type)) {
    if (payload.empty()) return nlohmann::json::object();
    const RequestKind* kind = request_subtype ? messages->find_request(*request_subtype)
                                              : request_kind_of(interface, payload);
    if (!kind || !kind->reply) return raw_json(payload);
    return kind->reply->to_json(payload);
  }

  const PayloadCodec* codec = fixed_codec(*messages, type);
  if (!codec) return raw_json(payload);
  return codec->to_json(payload);
}

std::vector<std::uint8_t> request_payload(const InterfaceMessages& messages, const RequestKind& kind,
                                          const nlohmann::json& fields) {
  if (is_raw_payload_json(fields)) return raw_bytes(fields);
  // {"subtype": n} alone is the subtype and nothing else, whatever the kind:
  // payload_to_json prints a request cut short after its subtype that way.
  const bool just_subtype = fields.is_object() && fields.size() == 1 && fields.contains("subtype");
  if (kind.form == RequestForm::kQuery || !kind.request || just_subtype) {
    const bool no_fields = fields.is_null() || (fields.is_object() && fields.empty()) || just_subtype;
    if (!no_fields) {
      throw JsonError(std::string(kind.name) + ": this request takes no fields, got " + fields.dump());
    }
    std::vector<std::uint8_t> payload;
    write_subtype(messages, kind.subtype, payload);
    return payload;
  }
  auto payload = kind.request->from_json(fields.is_null() ? nlohmann::json::object() : fields);
  write_subtype(messages, kind.subtype, payload);
  return payload;
}

std::vector<std::uint8_t> payload_from_json(std::uint16_t interface, MessageType type,
                                            const nlohmann::json& j,
                                            std::optional<std::uint16_t> request_subtype) {
  if (is_raw_payload_json(j)) return raw_bytes(j);
  if (type == MessageType::kSynch) return {};
  const auto* messages = find_messages(interface);
  if (!messages) {
    throw JsonError(interface_name(interface) + ": no structs are known; give {\"raw\": [...]}");
  }
  if (type == MessageType::kRequest || is_reply(type)) {
    std::optional<std::uint16_t> subtype = request_subtype;
    if (!subtype && j.is_object() && j.contains("subtype") && j["subtype"].is_number_unsigned()) {
      subtype = j["subtype"].get<std::uint16_t>();
    }
    if (!subtype) throw JsonError("a request or reply needs its subtype");
    const RequestKind* kind = messages->find_request(*subtype);
    if (!kind) {
      throw JsonError(interface_name(interface) + ": no request has subtype " + std::to_string(*subtype));
    }
    if (type == MessageType::kRequest) return request_payload(*messages, *kind, j);
    if (j.is_object() && j.empty()) return {};
    if (!kind->reply) throw JsonError(std::string(kind->name) + ": the reply carries no payload");
    return kind->reply->from_json(j);
  }
  const PayloadCodec* codec = fixed_codec(*messages, type);
  if (!codec) {
    throw JsonError(interface_name(interface) + " has no " + std::string(to_string(type)) +
                    " struct; give {\"raw\": [...]}");
  }
  return codec->from_json(j);
}

bool is_raw_payload_json(const nlohmann::json& j) {
  return j.is_object() && j.size() == 1 && j.contains("raw");
}

}  // namespace playerkit::protocol
