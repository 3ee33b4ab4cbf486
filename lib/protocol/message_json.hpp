#pragma once
// One message as one JSON object, the form tools print and read:
//   {"type":"data","device":"laser","index":0,"time":1086000000.25,
//    "timestamp":1086000000.2,"data":{"min_angle":-9000,...}}
// Requests and replies also carry "request":"get-geom" when the kind is known.

#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "protocol/message.hpp"

namespace playerkit::protocol {

// Throws DecodeError when the payload does not fit its struct.
nlohmann::json message_to_json(const Message& message,
                               std::optional<std::uint16_t> request_subtype = std::nullopt);

// Throws JsonError for a missing or unknown type or device, or bad data.
Message message_from_json(const nlohmann::json& j);

}  // namespace playerkit::protocol
