#pragma once
// Data messages for the text log tests: a payload struct wrapped in a header.

#include <cstdint>
#include <vector>

#include "protocol/binary_codec.hpp"
#include "protocol/message.hpp"

namespace playerkit::log::test {

// Server time 1086000000.250 and data time 1086000000.125 unless told otherwise.
inline constexpr protocol::Timestamp kServerTime{1086000000, 250000};
inline constexpr protocol::Timestamp kDataTime{1086000000, 125000};

inline protocol::Message data_message(std::uint16_t interface, std::uint16_t index,
                                      std::vector<std::uint8_t> payload,
                                      protocol::Timestamp time = kServerTime,
                                      protocol::Timestamp timestamp = kDataTime) {
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, {interface, index}, time, timestamp);
  message.payload = std::move(payload);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

template <class Struct>
protocol::Message data_message(std::uint16_t interface, std::uint16_t index, const Struct& value,
                               protocol::Timestamp time = kServerTime,
                               protocol::Timestamp timestamp = kDataTime) {
  return data_message(interface, index, protocol::encode(value), time, timestamp);
}

}  // namespace playerkit::log::test
