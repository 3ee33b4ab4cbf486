#include "families/rflex/protocol/rflex_packet.hpp"

#include <algorithm>
#include <stdexcept>

namespace playerkit::hardware::rflex {

std::uint8_t packet_checksum(std::span<const std::uint8_t> port_to_data) {
  std::uint8_t sum = 0;
  for (const std::uint8_t byte : port_to_data) sum ^= byte;
  return sum;
}

std::vector<std::uint8_t> encode_packet(const Packet& packet) {
  if (packet.data.size() > 255) throw std::length_error("rflex: a packet carries at most 255 data bytes");
  std::vector<std::uint8_t> bytes{kEscape, kStart, packet.port, packet.id, packet.opcode,
                                  static_cast<std::uint8_t>(packet.data.size())};
  bytes.insert(bytes.end(), packet.data.begin(), packet.data.end());
  bytes.push_back(packet_checksum(std::span(bytes).subspan(2)));
  bytes.push_back(kEscape);
  bytes.push_back(kEnd);
  return bytes;
}

std::optional<Packet> decode_packet(std::span<const std::uint8_t> bytes) {
  const RflexFrameFormat format;
  const framing::FrameScan scan = format.scan(bytes);
  if (scan.kind != framing::FrameScan::Kind::frame || scan.length != bytes.size()) return std::nullopt;
  return Packet{bytes[2], bytes[3], bytes[4], {bytes.begin() + 6, bytes.end() - 3}};
}

framing::FrameScan RflexFrameFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return framing::FrameScan::need();
  if (buffered[0] != kEscape) {
    const auto next = std::find(buffered.begin() + 1, buffered.end(), kEscape);
    return framing::FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  if (buffered.size() < 2) return framing::FrameScan::need(2);
  if (buffered[1] != kStart) return framing::FrameScan::noise(1);
  if (buffered.size() < 6) return framing::FrameScan::need(6);
  const std::size_t total = kPacketOverhead + buffered[5];
  if (buffered.size() < total) return framing::FrameScan::need(total);
  // A wrong trailer means the length byte was not one (a lost byte, noise
  // that looked like a start): hunt again from the next byte.
  if (buffered[total - 2] != kEscape || buffered[total - 1] != kEnd) return framing::FrameScan::noise(1);
  const std::uint8_t sum = packet_checksum(buffered.subspan(2, total - 5));
  return sum == buffered[total - 3] ? framing::FrameScan::whole(total) : framing::FrameScan::corrupt(total);
}

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void put_u16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value));
}

std::uint32_t get_u32(std::span<const std::uint8_t> data, std::size_t offset) {
  if (offset + 4 > data.size()) throw std::out_of_range("rflex: a packet too short for its field");
  return (std::uint32_t{data[offset]} << 24) | (std::uint32_t{data[offset + 1]} << 16) |
         (std::uint32_t{data[offset + 2]} << 8) | std::uint32_t{data[offset + 3]};
}

std::uint16_t get_u16(std::span<const std::uint8_t> data, std::size_t offset) {
  if (offset + 2 > data.size()) throw std::out_of_range("rflex: a packet too short for its field");
  return static_cast<std::uint16_t>((data[offset] << 8) | data[offset + 1]);
}

}  // namespace playerkit::hardware::rflex
