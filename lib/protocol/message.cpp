#include "protocol/message.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"

namespace playerkit::protocol {

Timestamp Timestamp::from_seconds(double seconds) {
  if (!(seconds > 0)) return {};
  constexpr Timestamp kLatest{kMaxSec, 999999};
  // Casting a double of 2^32 or more to 32 bits is undefined (a fuzzed JSON
  // time, or a header whose usec field is over a million, reached it).
  if (!(seconds < 4294967296.0)) return kLatest;
  auto sec = static_cast<std::uint32_t>(std::floor(seconds));
  auto usec = static_cast<std::uint32_t>(std::llround((seconds - sec) * 1e6));
  if (usec >= 1000000) {
    if (sec == kMaxSec) return kLatest;
    ++sec;
    usec -= 1000000;
  }
  return {sec, usec};
}

MessageHeader make_header(MessageType type, DeviceAddress device, Timestamp time,
                          Timestamp timestamp) {
  MessageHeader header;
  header.stx = kStx;
  header.type = static_cast<std::uint16_t>(type);
  header.device = device.interface;
  header.device_index = device.index;
  header.time_sec = time.sec;
  header.time_usec = time.usec;
  header.timestamp_sec = timestamp.sec;
  header.timestamp_usec = timestamp.usec;
  return header;
}

std::array<std::uint8_t, kHeaderSize> encode_header(const MessageHeader& header) {
  std::array<std::uint8_t, kHeaderSize> out{};
  std::uint8_t* cursor = out.data();
  detail::write_value(cursor, header);
  return out;
}

MessageHeader decode_header(std::span<const std::uint8_t, kHeaderSize> bytes) {
  MessageHeader header;
  const std::uint8_t* cursor = bytes.data();
  detail::read_value(cursor, header);
  return header;
}

std::vector<std::uint8_t> encode_message(MessageHeader header,
                                         std::span<const std::uint8_t> payload) {
  header.size = static_cast<std::uint32_t>(payload.size());
  std::vector<std::uint8_t> out(kHeaderSize + payload.size());
  const auto head = encode_header(header);
  std::copy(head.begin(), head.end(), out.begin());
  std::copy(payload.begin(), payload.end(), out.begin() + kHeaderSize);
  return out;
}

std::vector<std::uint8_t> encode_message(const Message& message) {
  return encode_message(message.header, message.payload);
}

std::optional<ParsedMessage> parse_message(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kHeaderSize) return std::nullopt;
  const MessageHeader header = decode_header(bytes.first<kHeaderSize>());
  if (header.stx != kStx) {
    throw DecodeError(MessageHeader::kWireName, "stx", kStx, header.stx,
                      "player_msghdr_t: bad start marker 0x" + [&] {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "%04X", header.stx);
                        return std::string(buf);
                      }() + " (expected 0x5878, \"Xx\")");
  }
  if (header.size > kMaxPayloadSize) {
    throw DecodeError(MessageHeader::kWireName, "size", kMaxPayloadSize, header.size,
                      "player_msghdr_t: payload size " + std::to_string(header.size) +
                          " exceeds the " + std::to_string(kMaxPayloadSize) + "-byte limit");
  }
  if (bytes.size() < kHeaderSize + header.size) return std::nullopt;
  ParsedMessage parsed;
  parsed.message.header = header;
  parsed.message.payload.assign(bytes.begin() + kHeaderSize,
                                bytes.begin() + kHeaderSize + header.size);
  parsed.consumed = kHeaderSize + header.size;
  return parsed;
}

}  // namespace playerkit::protocol
