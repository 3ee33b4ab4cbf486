#pragma once
// A whole Player message: the 32-byte header and its payload.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/constants.hpp"
#include "protocol/device_address.hpp"
#include "protocol/messages/header.hpp"

namespace playerkit::protocol {

// Seconds and microseconds, as in the header's time and timestamp fields.
struct Timestamp {
  std::uint32_t sec = 0;
  std::uint32_t usec = 0;

  // The latest time the header's fields hold.
  static constexpr std::uint32_t kMaxSec = 0xFFFFFFFF;
  static constexpr double kMaxSeconds = 4294967295.999999;
  // Rounded to the microsecond. Below 0 (and NaN) gives 0; beyond kMaxSeconds
  // (infinity included) gives {kMaxSec, 999999}, never a wrapped-around time.
  static Timestamp from_seconds(double seconds);
  [[nodiscard]] double seconds() const { return sec + usec * 1e-6; }
  friend auto operator<=>(const Timestamp&, const Timestamp&) = default;
};

struct Message {
  MessageHeader header;
  std::vector<std::uint8_t> payload;

  [[nodiscard]] MessageType type() const { return static_cast<MessageType>(header.type); }
  [[nodiscard]] DeviceAddress device() const { return {header.device, header.device_index}; }
  [[nodiscard]] Timestamp time() const { return {header.time_sec, header.time_usec}; }
  [[nodiscard]] Timestamp timestamp() const { return {header.timestamp_sec, header.timestamp_usec}; }
  friend bool operator==(const Message&, const Message&) = default;
};

// A header with stx set, the given type and device, and size 0.
MessageHeader make_header(MessageType type, DeviceAddress device, Timestamp time,
                          Timestamp timestamp);

std::array<std::uint8_t, kHeaderSize> encode_header(const MessageHeader& header);
// Decodes the 32 bytes as they are; check header.stx == kStx before trusting them.
MessageHeader decode_header(std::span<const std::uint8_t, kHeaderSize> bytes);

// Header followed by payload, with header.size set to the payload's length.
std::vector<std::uint8_t> encode_message(MessageHeader header, std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encode_message(const Message& message);

// Splits one complete message off the front of bytes. nullopt when bytes do not yet
// hold a whole message. Throws DecodeError on a bad stx or a size above kMaxPayloadSize.
struct ParsedMessage {
  Message message;
  std::size_t consumed = 0;
};
std::optional<ParsedMessage> parse_message(std::span<const std::uint8_t> bytes);

}  // namespace playerkit::protocol
