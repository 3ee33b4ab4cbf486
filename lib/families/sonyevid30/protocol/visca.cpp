#include "families/sonyevid30/protocol/visca.hpp"

#include <algorithm>
#include <cstdio>

namespace playerkit::hardware::sonyevid30 {

framing::TerminatedPacketOptions reply_packet_options() { return {}; }

framing::TerminatedPacketOptions host_packet_options() {
  return {.header_mask = 0xF0, .header_value = 0x80, .terminator = kTerminator, .min_length = 3,
          .max_length = kLongestMessage + 2, .name = "visca"};
}

Bytes to_camera(std::span<const std::uint8_t> message) {
  Bytes packet{kToCamera1};
  packet.insert(packet.end(), message.begin(), message.end());
  packet.push_back(kTerminator);
  return packet;
}

void put_nibbles(Bytes& out, std::uint16_t value) {
  for (int shift = 12; shift >= 0; shift -= 4) out.push_back(static_cast<std::uint8_t>((value >> shift) & 0x0F));
}

std::optional<std::uint16_t> read_nibbles(std::span<const std::uint8_t> four) {
  if (four.size() != 4) return std::nullopt;
  std::uint16_t value = 0;
  for (const std::uint8_t byte : four) {
    if (byte > 0x0F) return std::nullopt;
    value = static_cast<std::uint16_t>((value << 4) | byte);
  }
  return value;
}

Bytes pan_tilt_inquiry() { return to_camera(std::array<std::uint8_t, 3>{0x09, 0x06, 0x12}); }
Bytes zoom_inquiry() { return to_camera(std::array<std::uint8_t, 3>{0x09, 0x04, 0x47}); }

Bytes absolute_pan_tilt(int pan_units, int tilt_units, int pan_speed, int tilt_speed) {
  Bytes message{0x01, 0x06, 0x02, static_cast<std::uint8_t>(pan_speed), static_cast<std::uint8_t>(tilt_speed)};
  // Two's complement in 16 bits: the camera's negative positions.
  put_nibbles(message, static_cast<std::uint16_t>(std::clamp(pan_units, kPanMinUnits, kPanMaxUnits)));
  put_nibbles(message, static_cast<std::uint16_t>(std::clamp(tilt_units, kTiltMinUnits, kTiltMaxUnits)));
  return to_camera(message);
}

Bytes drive_pan_tilt(Drive pan, Drive tilt, int pan_speed, int tilt_speed) {
  return to_camera(std::array<std::uint8_t, 7>{0x01, 0x06, 0x01, static_cast<std::uint8_t>(pan_speed),
                                               static_cast<std::uint8_t>(tilt_speed), static_cast<std::uint8_t>(pan),
                                               static_cast<std::uint8_t>(tilt)});
}

Bytes zoom_direct(int zoom_units) {
  Bytes message{0x01, 0x04, 0x47};
  put_nibbles(message, static_cast<std::uint16_t>(std::clamp(zoom_units, 0, kZoomMaxUnits)));
  return to_camera(message);
}

Bytes cancel(int socket) { return to_camera(std::array<std::uint8_t, 1>{static_cast<std::uint8_t>(0x20 | socket)}); }

Reply parse_reply(std::span<const std::uint8_t> packet) {
  Reply reply;
  if (packet.size() < 3 || packet.front() != kFromCamera1 || packet.back() != kTerminator) return reply;
  const std::uint8_t kind = packet[1] & 0xF0;
  const int socket = packet[1] & 0x0F;
  if (kind == 0x40 && packet.size() == 3) {
    reply.kind = Reply::Kind::ack;
  } else if (kind == 0x50 && socket == 0) {
    // Socket 0: an inquiry's answer (completion of socket 0), data or not.
    reply.kind = Reply::Kind::answer;
    reply.data.assign(packet.begin() + 2, packet.end() - 1);
  } else if (kind == 0x50 && packet.size() == 3) {
    reply.kind = Reply::Kind::completion;
  } else if (kind == 0x60 && packet.size() == 4) {
    reply.kind = Reply::Kind::error;
    reply.error_code = packet[2];
  } else {
    return reply;
  }
  reply.socket = socket;
  return reply;
}

std::string error_text(std::uint8_t code) {
  switch (code) {
    case kSyntaxError: return "syntax error";
    case kBufferFull: return "command buffer full";
    case kCancelled: return "command cancelled";
    case kNoSocket: return "no socket (nothing to cancel)";
    case kNotExecutable: return "command not executable";
    default: return "error " + hex(std::array<std::uint8_t, 1>{code});
  }
}

std::optional<PanTiltUnits> pan_tilt_answer(const Reply& reply) {
  if (reply.kind != Reply::Kind::answer || reply.data.size() != 8) return std::nullopt;
  const auto pan = read_nibbles(std::span(reply.data).first(4));
  const auto tilt = read_nibbles(std::span(reply.data).subspan(4));
  if (!pan || !tilt) return std::nullopt;
  return PanTiltUnits{static_cast<std::int16_t>(*pan), static_cast<std::int16_t>(*tilt)};
}

std::optional<int> zoom_answer(const Reply& reply) {
  if (reply.kind != Reply::Kind::answer || reply.data.size() != 4) return std::nullopt;
  const auto zoom = read_nibbles(reply.data);
  if (!zoom) return std::nullopt;
  return static_cast<int>(*zoom);
}

Bytes ack(int socket) { return {kFromCamera1, static_cast<std::uint8_t>(0x40 | socket), kTerminator}; }
Bytes completion(int socket) { return {kFromCamera1, static_cast<std::uint8_t>(0x50 | socket), kTerminator}; }
Bytes error_reply(int socket, std::uint8_t code) {
  return {kFromCamera1, static_cast<std::uint8_t>(0x60 | socket), code, kTerminator};
}

Bytes answer_reply(std::span<const std::uint8_t> data) {
  Bytes packet{kFromCamera1, 0x50};
  packet.insert(packet.end(), data.begin(), data.end());
  packet.push_back(kTerminator);
  return packet;
}

Bytes pan_tilt_reply(PanTiltUnits units) {
  Bytes data;
  put_nibbles(data, static_cast<std::uint16_t>(units.pan));
  put_nibbles(data, static_cast<std::uint16_t>(units.tilt));
  return answer_reply(data);
}

Bytes zoom_reply(int zoom_units) {
  Bytes data;
  put_nibbles(data, static_cast<std::uint16_t>(zoom_units));
  return answer_reply(data);
}

std::string hex(std::span<const std::uint8_t> bytes) {
  std::string text;
  for (const std::uint8_t byte : bytes) {
    char two[4];
    std::snprintf(two, sizeof two, "%02X", byte);
    if (!text.empty()) text.push_back(' ');
    text += two;
  }
  return text;
}

}  // namespace playerkit::hardware::sonyevid30
