#pragma once
// GYROPAC, type 0x98 (p2os.md §2.6): `98 c {rate_lo rate_hi temperature}×c`.
// Rates run 0 ... 1023, 512 meaning no rotation and less than 512
// counter-clockwise. AROS sends one right before each SIP once GYRO 1 is on.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace playerkit::hardware::p2os {

inline constexpr std::uint16_t kGyroRateAtRest = 512;
inline constexpr std::uint16_t kGyroRateMax = 1023;

struct GyroReading {
  std::uint16_t rate = kGyroRateAtRest;
  std::uint8_t temperature = 0;
  friend bool operator==(const GyroReading&, const GyroReading&) = default;
};

struct GyroPacket {
  std::vector<GyroReading> readings;

  // The rounded mean rate, as 1.5 stores it; nothing for an empty packet.
  std::optional<int> average_rate() const;

  friend bool operator==(const GyroPacket&, const GyroPacket&) = default;
};

// Throws EncodeError for more than 255 readings or a packet too long to frame.
std::vector<std::uint8_t> encode_gyro_packet(const GyroPacket& packet);
// Throws DecodeError unless the payload is 98, c and exactly 3·c bytes (1.5
// drops a packet whose length disagrees with its count).
GyroPacket decode_gyro_packet(std::span<const std::uint8_t> payload);

}  // namespace playerkit::hardware::p2os
