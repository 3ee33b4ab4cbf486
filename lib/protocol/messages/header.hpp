#pragma once
// Player 1.5 `header` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"

namespace playerkit::protocol {

struct MessageHeader {
  static constexpr std::string_view kWireName = "player_msghdr_t";
  static constexpr std::size_t kWireSize = 32;

  std::uint16_t stx = 0;  // start marker, always 0x5878 (bytes 0x58 0x78, "Xx" in wire order)
  std::uint16_t type = 0;  // message type (PLAYER_MSGTYPE_*)
  std::uint16_t device = 0;  // interface code of the device concerned
  std::uint16_t device_index = 0;  // index of that device
  std::uint32_t time_sec = 0;  // server clock when the message was sent, seconds
  std::uint32_t time_usec = 0;  // server clock, microsecond part
  std::uint32_t timestamp_sec = 0;  // time the data/reply was produced, seconds
  std::uint32_t timestamp_usec = 0;  // production time, microsecond part
  std::uint32_t reserved = 0;  // TCP: server always sends 0. UDP: header bytes 26-27 (second half of this field) hold the client id as big-endian uint16
  std::uint32_t size = 0;  // number of payload bytes that follow the header

  static constexpr auto fields() {
    return std::tuple{field("stx", &MessageHeader::stx),
                      field("type", &MessageHeader::type),
                      field("device", &MessageHeader::device),
                      field("device_index", &MessageHeader::device_index),
                      field("time_sec", &MessageHeader::time_sec),
                      field("time_usec", &MessageHeader::time_usec),
                      field("timestamp_sec", &MessageHeader::timestamp_sec),
                      field("timestamp_usec", &MessageHeader::timestamp_usec),
                      field("reserved", &MessageHeader::reserved),
                      field("size", &MessageHeader::size)};
  }
  friend bool operator==(const MessageHeader&, const MessageHeader&) = default;
};

}  // namespace playerkit::protocol
