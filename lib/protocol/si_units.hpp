#pragma once
// The JSON of a payload in SI units instead of wire units: lengths in metres,
// angles in radians, speeds in m/s and rad/s (player-cat --si, typed helpers).
// Same shape and field names as payload_to_json / message_to_json; only the
// values of fields that carry a unit change (to floating point). Laser ranges
// are multiplied by range_res on the way. Fields without a unit stay as they are.

#include <cstdint>
#include <optional>
#include <span>

#include <nlohmann/json.hpp>

#include "protocol/constants.hpp"
#include "protocol/message.hpp"

namespace playerkit::protocol {

// Throws DecodeError like payload_to_json.
nlohmann::json payload_to_si_json(std::uint16_t interface, MessageType type,
                                  std::span<const std::uint8_t> payload,
                                  std::optional<std::uint16_t> request_subtype = std::nullopt);

// message_to_json with "data" in SI units.
nlohmann::json message_to_si_json(const Message& message,
                                  std::optional<std::uint16_t> request_subtype = std::nullopt);

}  // namespace playerkit::protocol
