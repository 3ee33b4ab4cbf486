#include "families/p2os/protocol/gyro_packet.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/packet_types.hpp"

#include <cmath>
#include <string>
#include <string_view>

namespace playerkit::hardware::p2os {
namespace {

constexpr std::string_view kGyroName = "P2OS GYROPAC";

}  // namespace

std::optional<int> GyroPacket::average_rate() const {
  if (readings.empty()) return std::nullopt;
  double sum = 0.0;
  for (const GyroReading& reading : readings) sum += reading.rate;
  return static_cast<int>(std::lround(sum / static_cast<double>(readings.size())));
}

std::vector<std::uint8_t> encode_gyro_packet(const GyroPacket& packet) {
  const std::size_t size = 2 + 3 * packet.readings.size();
  if (packet.readings.size() > 0xFF || size + kChecksumSize > kMaxLengthByteFromRobot) {
    throw EncodeError(std::string(kGyroName) + ": " + std::to_string(packet.readings.size()) +
                      " readings do not fit one packet");
  }
  std::vector<std::uint8_t> out{packet_type::gyro,
                                static_cast<std::uint8_t>(packet.readings.size())};
  out.reserve(size);
  for (const GyroReading& reading : packet.readings) {
    detail::append_u16(out, reading.rate);
    out.push_back(reading.temperature);
  }
  return out;
}

GyroPacket decode_gyro_packet(std::span<const std::uint8_t> payload) {
  detail::ByteCursor in(payload, kGyroName);
  detail::expect_type(in, packet_type::gyro, kGyroName);
  const std::uint8_t count = in.u8("count");
  if (in.remaining() != 3u * count) {
    throw DecodeError(std::string(kGyroName) + ": count " + std::to_string(count) + " needs " +
                      std::to_string(3u * count) + " bytes of readings, the payload has " +
                      std::to_string(in.remaining()));
  }
  GyroPacket packet;
  packet.readings.reserve(count);
  for (int i = 0; i < count; ++i) {
    GyroReading reading;
    reading.rate = in.u16("rate");
    reading.temperature = in.u8("temperature");
    packet.readings.push_back(reading);
  }
  return packet;
}

}  // namespace playerkit::hardware::p2os
