#pragma once
// JSON of any payload, with the struct chosen by interface, message type and
// (for requests and replies) subtype, through the catalog.
//
// Payloads without a known struct (an unknown subtype, an interface that defines
// none) convert to {"raw": [byte, ...]}, and {"raw": [...]} converts back to those
// bytes for any message, so nothing is ever lost or refused for lack of a struct.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/catalog.hpp"
#include "protocol/constants.hpp"

namespace playerkit::protocol {

// True for {"raw": [bytes]}: a payload given as bytes rather than fields.
bool is_raw_payload_json(const nlohmann::json& j);

// The request kind a request payload belongs to, read from its leading subtype.
const RequestKind* request_kind_of(std::uint16_t interface, std::span<const std::uint8_t> payload);

// Throws DecodeError when the payload does not fit the struct its message calls for.
// For replies, pass the subtype of the request being answered when it is known:
// some replies (power) do not start with the subtype.
nlohmann::json payload_to_json(std::uint16_t interface, MessageType type,
                               std::span<const std::uint8_t> payload,
                               std::optional<std::uint16_t> request_subtype = std::nullopt);

// The inverse. Requests and replies need the subtype (the request's name decides
// it); JSON for a request may carry it as "subtype". Throws JsonError.
std::vector<std::uint8_t> payload_from_json(std::uint16_t interface, MessageType type,
                                            const nlohmann::json& j,
                                            std::optional<std::uint16_t> request_subtype = std::nullopt);

// A request's payload from its kind and fields: a query is only the subtype; a
// struct request gets its subtype from the kind. Throws JsonError.
std::vector<std::uint8_t> request_payload(const InterfaceMessages& messages, const RequestKind& kind,
                                          const nlohmann::json& fields);

}  // namespace playerkit::protocol
