#pragma once
// Robot-to-host packet types: payload byte 0 (p2os.md §2.2).

#include <cstdint>

namespace playerkit::hardware::p2os {

namespace packet_type {
inline constexpr std::uint8_t sync0 = 0x00;
inline constexpr std::uint8_t sync1 = 0x01;
inline constexpr std::uint8_t sync2 = 0x02;
inline constexpr std::uint8_t config = 0x20;        // CONFIGpac (ignored by 1.5)
inline constexpr std::uint8_t sip_first = 0x30;     // standard SIPs are 0x30 ... 0x34
inline constexpr std::uint8_t sip_stopped = 0x32;
inline constexpr std::uint8_t sip_moving = 0x33;
inline constexpr std::uint8_t sip_last = 0x34;
inline constexpr std::uint8_t encoder = 0x90;       // ENCODERpac (unknown to 1.5)
inline constexpr std::uint8_t gyro = 0x98;          // GYROPAC
inline constexpr std::uint8_t serial_aux = 0xB0;    // SERAUX: AUX1 serial bytes (ignored by 1.5)
inline constexpr std::uint8_t serial_aux2 = 0xB8;   // SERAUX2: AUX2 serial bytes (CMUcam)
inline constexpr std::uint8_t io = 0xF0;            // IOpac (unknown to 1.5)
}  // namespace packet_type

constexpr bool is_standard_sip(std::uint8_t type) {
  return type >= packet_type::sip_first && type <= packet_type::sip_last;
}

constexpr bool is_sync_echo(std::uint8_t type) { return type <= packet_type::sync2; }

// Old Cognachrome vision packets, which 1.5 skips silently.
constexpr bool is_old_vision_packet(std::uint8_t type) {
  return type == 0x50 || type == 0x80 || type == 0xC0 || type == 0xD0 || type == 0xE0;
}

}  // namespace playerkit::hardware::p2os
