#pragma once
// P2OS packet framing, both directions (p2os.md §1.1):
//   FA FB N payload chk_hi chk_lo
// N counts the payload and the two checksum bytes. The checksum adds the
// payload as big-endian 16-bit words and XORs a left-over odd byte into the
// low byte; it is the only big-endian field (payload integers are
// little-endian).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace playerkit::hardware::p2os {

inline constexpr std::uint8_t kHeader1 = 0xFA;
inline constexpr std::uint8_t kHeader2 = 0xFB;
inline constexpr std::size_t kHeaderSize = 3;    // FA FB N
inline constexpr std::size_t kChecksumSize = 2;
// A frame carries at least one payload byte (the command or packet type).
inline constexpr std::uint8_t kMinLengthByte = 3;
// Towards the robot N is at most 200 (the reference never builds more than
// 198 bytes in all).
inline constexpr std::uint8_t kMaxLengthByteToRobot = 200;
// The reference's receive buffer holds 256 bytes: 3 header bytes + N.
inline constexpr std::uint8_t kMaxLengthByteFromRobot = 253;

// Checksum of §1.1 over the payload bytes only.
std::uint16_t checksum(std::span<const std::uint8_t> payload);

// Whole frame for `payload`. Throws EncodeError for an empty payload or one
// whose N would exceed kMaxLengthByteFromRobot.
std::vector<std::uint8_t> build_frame(std::span<const std::uint8_t> payload);

// The payload inside one whole frame. Throws DecodeError when `frame` is not
// exactly one well-formed frame (header, length, checksum).
std::span<const std::uint8_t> frame_payload(std::span<const std::uint8_t> frame);

}  // namespace playerkit::hardware::p2os
