#pragma once
// RFLEX packets (rflex.md §1.1), both directions:
//
//   1B 02 | port | id | opcode | n | data (n bytes) | XOR(port..data) | 1B 03
//
// No byte stuffing: a receiver goes by the length byte alone, so 0x1B may
// appear inside the data. Integers in the data are big-endian.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::hardware::rflex {

inline constexpr std::uint8_t kEscape = 0x1B;
inline constexpr std::uint8_t kStart = 0x02;
inline constexpr std::uint8_t kEnd = 0x03;
// Everything but the data: 1B 02 port id op n ... xor 1B 03.
inline constexpr std::size_t kPacketOverhead = 9;
inline constexpr std::size_t kLongestPacket = kPacketOverhead + 255;

struct Packet {
  std::uint8_t port = 0;
  std::uint8_t id = 0;
  std::uint8_t opcode = 0;
  std::vector<std::uint8_t> data;
  friend bool operator==(const Packet&, const Packet&) = default;
};

// XOR of port, id, opcode, length and the data.
[[nodiscard]] std::uint8_t packet_checksum(std::span<const std::uint8_t> port_to_data);

// Throws std::length_error for more than 255 data bytes.
[[nodiscard]] std::vector<std::uint8_t> encode_packet(const Packet& packet);

// A whole packet as RflexFrameFormat cut it; nullopt when it is not one.
[[nodiscard]] std::optional<Packet> decode_packet(std::span<const std::uint8_t> bytes);

// Cuts RFLEX packets out of a byte stream by their length byte, with the
// trailer and the XOR checked.
class RflexFrameFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "rflex"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override;
};

// Big-endian fields, as every RFLEX packet carries them.
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value);
void put_u16(std::vector<std::uint8_t>& out, std::uint16_t value);
[[nodiscard]] std::uint32_t get_u32(std::span<const std::uint8_t> data, std::size_t offset);
[[nodiscard]] std::uint16_t get_u16(std::span<const std::uint8_t> data, std::size_t offset);

}  // namespace playerkit::hardware::rflex
