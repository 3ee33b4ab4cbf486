#include "families/nomad/protocol/nclient_message.hpp"

#include <algorithm>

namespace playerkit::hardware::nomad {

namespace {

void put_u16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value & 0xFF));
}

std::uint16_t get_u16(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::uint16_t>((bytes[at] << 8) | bytes[at + 1]);
}

std::int32_t get_i32(std::span<const std::uint8_t> bytes, std::size_t at) {
  const std::uint32_t value = (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
                              (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
  return static_cast<std::int32_t>(value);
}

}  // namespace

std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> out;
  out.reserve(kHeaderSize + 4 * message.words.size());
  put_u16(out, static_cast<std::uint16_t>(message.type));
  put_u16(out, static_cast<std::uint16_t>(message.words.size()));
  for (const std::int32_t word : message.words) {
    const auto value = static_cast<std::uint32_t>(word);
    put_u16(out, static_cast<std::uint16_t>(value >> 16));
    put_u16(out, static_cast<std::uint16_t>(value & 0xFFFF));
  }
  return out;
}

std::optional<Message> decode(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kHeaderSize) return std::nullopt;
  const std::size_t count = get_u16(bytes, 2);
  if (bytes.size() != kHeaderSize + 4 * count) return std::nullopt;
  Message message{.type = static_cast<std::int16_t>(get_u16(bytes, 0)), .words = {}};
  message.words.reserve(count);
  for (std::size_t i = 0; i < count; ++i) message.words.push_back(get_i32(bytes, kHeaderSize + 4 * i));
  return message;
}

std::string_view type_name(std::int16_t type) {
  namespace t = message_type;
  switch (type) {
    case t::kAccelerations: return "AC";
    case t::kSpeeds: return "SP";
    case t::kVelocityMode: return "VM";
    case t::kGetState: return "GS";
    case t::kSensorMask: return "CT";
    case t::kZero: return "ZR";
    case t::kCommandTimeout: return "CONF_TM";
    case t::kState: return "STATE";
    case t::kError: return "ERROR";
    case t::kConnectRobot: return "CONNECT_ROBOT";
    default: return "unknown";
  }
}

framing::FrameScan NclientFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.size() < kHeaderSize) return framing::FrameScan::need(kHeaderSize);
  const std::size_t count = get_u16(buffered, 2);
  if (count > kMaxWords) return framing::FrameScan::noise(1);
  if (!expected_.empty()) {
    const auto type = static_cast<std::int16_t>(get_u16(buffered, 0));
    if (std::find(expected_.begin(), expected_.end(), type) == expected_.end()) return framing::FrameScan::noise(1);
  }
  const std::size_t size = kHeaderSize + 4 * count;
  if (buffered.size() < size) return framing::FrameScan::need(size);
  return framing::FrameScan::whole(size);
}

std::vector<std::int16_t> state_reply_types() {
  return {message_type::kState, message_type::kError, message_type::kFailure};
}

}  // namespace playerkit::hardware::nomad
