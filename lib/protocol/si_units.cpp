#include "protocol/si_units.hpp"

#include "protocol/message_json.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::protocol {

// Placeholder until the unit table lands: wire units unchanged.
nlohmann::json payload_to_si_json(std::uint16_t interface, MessageType type,
                                  std::span<const std::uint8_t> payload,
                                  std::optional<std::uint16_t> request_subtype) {
  return payload_to_json(interface, type, payload, request_subtype);
}

nlohmann::json message_to_si_json(const Message& message, std::optional<std::uint16_t> request_subtype) {
  return message_to_json(message, request_subtype);
}

}  // namespace playerkit::protocol
