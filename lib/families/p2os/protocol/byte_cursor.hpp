#pragma once
// Internal to lib/families/p2os/protocol: bounds-checked little-endian reading and
// writing of packet payloads. Every read names its field, so a truncated
// packet is reported as "<packet>: truncated in field '<field>' ...".

#include "families/p2os/protocol/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::hardware::p2os::detail {

class ByteCursor {
 public:
  ByteCursor(std::span<const std::uint8_t> bytes, std::string_view packet)
      : bytes_(bytes), packet_(packet) {}

  std::uint8_t u8(std::string_view field) { return take(1, field)[0]; }

  std::uint16_t u16(std::string_view field) {
    const auto b = take(2, field);
    return static_cast<std::uint16_t>(b[0] | (b[1] << 8));
  }

  std::int16_t i16(std::string_view field) { return static_cast<std::int16_t>(u16(field)); }

  std::span<const std::uint8_t> take(std::size_t count, std::string_view field) {
    if (count > remaining()) {
      throw DecodeError(std::string(packet_) + ": truncated in field '" + std::string(field) +
                        "': needs " + std::to_string(count) + " more bytes at offset " +
                        std::to_string(offset_) + ", the payload has " +
                        std::to_string(bytes_.size()));
    }
    const auto part = bytes_.subspan(offset_, count);
    offset_ += count;
    return part;
  }

  std::span<const std::uint8_t> rest() {
    const auto part = bytes_.subspan(offset_);
    offset_ = bytes_.size();
    return part;
  }

  std::size_t remaining() const { return bytes_.size() - offset_; }
  std::size_t offset() const { return offset_; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::string_view packet_;
  std::size_t offset_ = 0;
};

inline void append_u16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xFF));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

inline void append_i16(std::vector<std::uint8_t>& out, std::int16_t value) {
  append_u16(out, static_cast<std::uint16_t>(value));
}

// "0x3B": for error messages about type bytes.
inline std::string hex_byte(std::uint8_t value) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  return {'0', 'x', kDigits[value >> 4], kDigits[value & 0x0F]};
}

// Reads payload byte 0 and checks it is `expected`.
inline void expect_type(ByteCursor& cursor, std::uint8_t expected, std::string_view packet) {
  const std::uint8_t type = cursor.u8("type");
  if (type != expected) {
    throw DecodeError(std::string(packet) + ": packet type " + hex_byte(type) + " is not " +
                      hex_byte(expected));
  }
}

}  // namespace playerkit::hardware::p2os::detail
