#include "families/sonyevid30/protocol/camera_commands.hpp"

namespace playerkit::hardware::sonyevid30 {

namespace {

bool starts_with(std::span<const std::uint8_t> message, std::initializer_list<std::uint8_t> prefix) {
  if (message.size() < prefix.size()) return false;
  std::size_t i = 0;
  for (const std::uint8_t byte : prefix) {
    if (message[i++] != byte) return false;
  }
  return true;
}

bool is_drive(std::uint8_t byte) { return byte >= 1 && byte <= 3; }

HostMessage pan_tilt_command(std::span<const std::uint8_t> m) {
  HostMessage out;
  if (m.size() < 5) return out;
  out.pan_speed = m[3];
  out.tilt_speed = m[4];
  // Speeds outside 01..18 / 01..14 are not the camera's: a syntax error.
  if (out.pan_speed < 1 || out.pan_speed > kPanSpeedMax || out.tilt_speed < 1 || out.tilt_speed > kTiltSpeedMax) {
    return out;
  }
  if (m[2] == 0x02 && m.size() == 13) {
    const auto pan = read_nibbles(m.subspan(5, 4));
    const auto tilt = read_nibbles(m.subspan(9, 4));
    if (!pan || !tilt) return out;
    out.kind = HostMessage::Kind::absolute_pan_tilt;
    out.pan = static_cast<std::int16_t>(*pan);
    out.tilt = static_cast<std::int16_t>(*tilt);
  } else if (m[2] == 0x01 && m.size() == 7 && is_drive(m[5]) && is_drive(m[6])) {
    out.kind = HostMessage::Kind::drive_pan_tilt;
    out.drive_pan = static_cast<Drive>(m[5]);
    out.drive_tilt = static_cast<Drive>(m[6]);
  }
  return out;
}

HostMessage command(std::span<const std::uint8_t> m) {
  HostMessage out;
  if (starts_with(m, {0x01, 0x06}) && m.size() >= 3 && (m[2] == 0x01 || m[2] == 0x02)) return pan_tilt_command(m);
  if (starts_with(m, {0x01, 0x04, 0x47})) {
    const auto zoom = m.size() == 7 ? read_nibbles(m.subspan(3, 4)) : std::nullopt;
    if (zoom) {
      out.kind = HostMessage::Kind::zoom_direct;
      out.zoom = *zoom;
    }
    return out;
  }
  if (starts_with(m, {0x01, 0x04, 0x07}) && m.size() == 4) {
    const std::uint8_t how = m[3];
    if (how == 0x00 || how == 0x02 || how == 0x03) {
      // Standard speed: tele 02, wide 03.
      out.kind = HostMessage::Kind::zoom_drive;
      out.zoom_speed = how == 0x00 ? 0 : how == 0x02 ? 4 : -4;
    } else if ((how & 0xF0) == 0x20 || (how & 0xF0) == 0x30) {
      const int speed = (how & 0x0F) + 1;
      out.kind = HostMessage::Kind::zoom_drive;
      out.zoom_speed = (how & 0xF0) == 0x20 ? speed : -speed;
    }
    return out;
  }
  if (m.size() >= 2) out.kind = HostMessage::Kind::other_command;
  return out;
}

}  // namespace

HostMessage parse_host_message(std::span<const std::uint8_t> packet) {
  HostMessage out;
  if (packet.size() < 3 || packet.back() != kTerminator) return out;
  const auto m = packet.subspan(1, packet.size() - 2);
  if (packet.front() == kBroadcast) {
    if (m.size() == 2 && m[0] == 0x30 && m[1] == 0x01) out.kind = HostMessage::Kind::address_set;
    if (m.size() == 3 && m[0] == 0x01 && m[1] == 0x00 && m[2] == 0x01) out.kind = HostMessage::Kind::if_clear;
    return out;
  }
  if (packet.front() != kToCamera1 || m.size() > kLongestMessage) return out;
  if (m.size() == 1 && (m[0] == 0x21 || m[0] == 0x22)) {
    out.kind = HostMessage::Kind::cancel;
    out.socket = m[0] & 0x0F;
    return out;
  }
  if (m.empty()) return out;
  if (m[0] == 0x01) return command(m);
  if (m[0] == 0x09 && m.size() >= 2) {
    out.kind = starts_with(m, {0x09, 0x06, 0x12}) && m.size() == 3   ? HostMessage::Kind::pan_tilt_inquiry
               : starts_with(m, {0x09, 0x04, 0x47}) && m.size() == 3 ? HostMessage::Kind::zoom_inquiry
                                                                     : HostMessage::Kind::other_inquiry;
  }
  return out;
}

}  // namespace playerkit::hardware::sonyevid30
