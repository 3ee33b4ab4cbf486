#pragma once
// Little-endian words and hex bytes as the SICK telegrams carry them: one
// copy for every file of this folder (they compile in one unity batch, so
// file-local copies would collide).

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace playerkit::hardware::sick::detail {

inline void append_le16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xFFu));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

// The word at byte `at`; the caller has checked that two bytes are there.
inline std::uint16_t load_le16(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::uint16_t>(bytes[at] | (bytes[at + 1] << 8));
}

// "0A": one byte in the form the sheet's tables use.
inline std::string byte_hex(std::uint8_t byte) {
  char digits[4];
  std::snprintf(digits, sizeof digits, "%02X", byte);
  return digits;
}

}  // namespace playerkit::hardware::sick::detail
