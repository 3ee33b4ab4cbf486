#pragma once
// The SICK CRC-16 of the LMS 2xx / PLS telegram protocol (sicklms200.md
// §1.4). Not a textbook CRC: each step XORs in the current byte paired with
// the previous one, so it must be computed over the telegram exactly as sent,
// from STX through the last data byte (a reply's status byte included).

#include <cstdint>
#include <span>

namespace playerkit::hardware::sick {

constexpr std::uint16_t crc16(std::span<const std::uint8_t> bytes) noexcept {
  std::uint16_t crc = 0;
  std::uint8_t previous = 0;
  for (const std::uint8_t byte : bytes) {
    if ((crc & 0x8000u) != 0) {
      crc = static_cast<std::uint16_t>(((crc & 0x7FFFu) << 1) ^ 0x8005u);
    } else {
      crc = static_cast<std::uint16_t>(crc << 1);
    }
    crc = static_cast<std::uint16_t>(crc ^ ((previous << 8) | byte));
    previous = byte;
  }
  return crc;
}

}  // namespace playerkit::hardware::sick
