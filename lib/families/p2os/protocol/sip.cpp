#include "families/p2os/protocol/sip.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"

#include <cmath>
#include <string>

namespace playerkit::hardware::p2os {
namespace {

constexpr std::string_view kSipName = "P2OS standard SIP";

}  // namespace

std::vector<std::uint8_t> encode_sip(const StandardSip& sip) {
  if (!is_standard_sip(sip.status)) {
    throw EncodeError(std::string(kSipName) + ": status " + detail::hex_byte(sip.status) +
                      " is not a SIP type (0x30 ... 0x34)");
  }
  if (sip.sonar.size() > 0xFF) {
    throw EncodeError(std::string(kSipName) + ": " + std::to_string(sip.sonar.size()) +
                      " sonar readings do not fit the count byte");
  }
  std::vector<std::uint8_t> out;
  out.reserve(kSipFixedSize + 3 * sip.sonar.size() + sip.trailing.size());
  out.push_back(sip.status);
  detail::append_u16(out, sip.x_position);
  detail::append_u16(out, sip.y_position);
  detail::append_i16(out, sip.heading);
  detail::append_i16(out, sip.left_velocity);
  detail::append_i16(out, sip.right_velocity);
  out.push_back(sip.battery);
  out.push_back(sip.stall_bumpers_low);
  out.push_back(sip.stall_bumpers_high);
  detail::append_u16(out, sip.control);
  detail::append_u16(out, sip.flags);
  out.push_back(sip.compass);
  out.push_back(static_cast<std::uint8_t>(sip.sonar.size()));
  for (const SonarReading& reading : sip.sonar) {
    out.push_back(reading.index);
    detail::append_u16(out, reading.range);
  }
  out.push_back(sip.analog_port);
  out.push_back(sip.gripper_state);
  out.push_back(sip.analog);
  out.push_back(sip.digital_in);
  out.push_back(sip.digital_out);
  out.insert(out.end(), sip.trailing.begin(), sip.trailing.end());
  if (out.size() + kChecksumSize > kMaxLengthByteFromRobot) {
    throw EncodeError(std::string(kSipName) + ": " + std::to_string(out.size()) +
                      " payload bytes do not fit a frame");
  }
  return out;
}

StandardSip decode_sip(std::span<const std::uint8_t> payload) {
  detail::ByteCursor in(payload, kSipName);
  StandardSip sip;
  sip.status = in.u8("STATUS");
  if (!is_standard_sip(sip.status)) {
    throw DecodeError(std::string(kSipName) + ": packet type " + detail::hex_byte(sip.status) +
                      " is not a SIP (0x30 ... 0x34)");
  }
  sip.x_position = in.u16("XPOS");
  sip.y_position = in.u16("YPOS");
  sip.heading = in.i16("THPOS");
  sip.left_velocity = in.i16("L VEL");
  sip.right_velocity = in.i16("R VEL");
  sip.battery = in.u8("BATTERY");
  sip.stall_bumpers_low = in.u8("STALL/BUMPERS low");
  sip.stall_bumpers_high = in.u8("STALL/BUMPERS high");
  sip.control = in.u16("CONTROL");
  sip.flags = in.u16("FLAGS");
  sip.compass = in.u8("COMPASS");
  const std::uint8_t count = in.u8("SONAR COUNT");
  if (in.remaining() < 3u * count) {  // one message for the whole block, not per reading
    in.take(3u * count, std::to_string(count) + " sonar readings");
  }
  sip.sonar.reserve(count);
  for (int i = 0; i < count; ++i) {
    SonarReading reading;
    reading.index = in.u8("sonar NUMBER");
    reading.range = in.u16("sonar RANGE");
    sip.sonar.push_back(reading);
  }
  sip.analog_port = in.u8("TIMER low");
  sip.gripper_state = in.u8("TIMER high");
  sip.analog = in.u8("ANALOG");
  sip.digital_in = in.u8("DIGIN");
  sip.digital_out = in.u8("DIGOUT");
  const auto rest = in.rest();
  sip.trailing.assign(rest.begin(), rest.end());
  return sip;
}

std::optional<int> compass_degrees(std::uint8_t compass) {
  if (compass == 0 || compass == 181 || compass == 255) return std::nullopt;
  return (compass - 1) * 2;
}

std::uint8_t compass_byte(double degrees) {
  if (!std::isfinite(degrees)) return 0;
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped < 0.0) wrapped += 360.0;
  const long units = std::lround(wrapped / 2.0) % 180;
  return static_cast<std::uint8_t>(units + 1);
}

}  // namespace playerkit::hardware::p2os
