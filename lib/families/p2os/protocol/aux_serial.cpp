#include "families/p2os/protocol/aux_serial.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/packet_types.hpp"

#include <algorithm>
#include <string>
#include <string_view>

namespace playerkit::hardware::p2os {
namespace {

constexpr std::string_view kSerAuxName = "P2OS SERAUX packet";

bool is_aux_type(std::uint8_t type) {
  return type == packet_type::serial_aux || type == packet_type::serial_aux2;
}

template <std::size_t N>
void check_no_start_byte(const std::array<std::uint8_t, N>& message, std::string_view what) {
  if (std::find(message.begin() + 1, message.end(), kCmucamStart) != message.end()) {
    throw EncodeError("CMUcam " + std::string(what) +
                      " message: a value of 255 would be read as a start byte");
  }
}

}  // namespace

std::vector<std::uint8_t> encode_aux_serial(const AuxSerialPacket& packet) {
  if (!is_aux_type(packet.type)) {
    throw EncodeError(std::string(kSerAuxName) + ": type " + detail::hex_byte(packet.type) +
                      " is neither SERAUX 0xB0 nor SERAUX2 0xB8");
  }
  if (1 + packet.data.size() + kChecksumSize > kMaxLengthByteFromRobot) {
    throw EncodeError(std::string(kSerAuxName) + ": " + std::to_string(packet.data.size()) +
                      " data bytes do not fit one packet");
  }
  std::vector<std::uint8_t> out{packet.type};
  out.insert(out.end(), packet.data.begin(), packet.data.end());
  return out;
}

AuxSerialPacket decode_aux_serial(std::span<const std::uint8_t> payload) {
  detail::ByteCursor in(payload, kSerAuxName);
  const std::uint8_t type = in.u8("type");
  if (!is_aux_type(type)) {
    throw DecodeError(std::string(kSerAuxName) + ": packet type " + detail::hex_byte(type) +
                      " is neither SERAUX 0xB0 nor SERAUX2 0xB8");
  }
  const auto data = in.rest();
  return {type, {data.begin(), data.end()}};
}

std::uint32_t CmucamTracking::area() const {
  const int width = x2 - x1 + 1;
  const int height = y2 - y1 + 1;
  const long product = static_cast<long>(width) * height * confidence / 255;
  return product > 0 ? static_cast<std::uint32_t>(product) : 0u;
}

std::array<std::uint8_t, kCmucamTrackingSize> encode_cmucam_tracking(const CmucamTracking& blob) {
  const std::array<std::uint8_t, kCmucamTrackingSize> message{
      kCmucamStart, 'M', blob.mx, blob.my, blob.x1, blob.y1, blob.x2, blob.y2,
      blob.pixels, blob.confidence};
  check_no_start_byte(message, "tracking");
  return message;
}

std::array<std::uint8_t, kCmucamColorSize> encode_cmucam_color(const CmucamColor& color) {
  const std::array<std::uint8_t, kCmucamColorSize> message{
      kCmucamStart, 'S', color.red, color.green, color.blue,
      color.red_variance, color.green_variance, color.blue_variance};
  check_no_start_byte(message, "colour");
  return message;
}

std::optional<CmucamMessage> find_cmucam_message(std::span<const std::uint8_t> data) {
  const std::size_t length = data.size();
  if (length < kCmucamTrackingSize) return std::nullopt;
  const std::size_t last = length - kCmucamTrackingSize;
  const std::size_t first = length <= 18 ? 0 : length - 19;
  for (std::size_t i = first; i <= last; ++i) {
    if (data[i] != kCmucamStart) continue;
    const auto m = data.subspan(i);  // at least 10 bytes by the window's end
    if (m[1] == 'M') return CmucamTracking{m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9]};
    if (m[1] == 'S') return CmucamColor{m[2], m[3], m[4], m[5], m[6], m[7]};
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace playerkit::hardware::p2os
