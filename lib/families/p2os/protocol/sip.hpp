#pragma once
// The standard Server Information Packet, types 0x30 ... 0x34, as the 1.5
// driver parses it (p2os.md §2.3). Fields hold raw units; converting them
// needs the robot's parameter row (robot_params.hpp): mm = XPOS ×
// DistConvFactor, rad = THPOS × AngleConvFactor, mm/s = VEL × VelConvFactor,
// sonar mm = range × RangeConvFactor.

#include "families/p2os/protocol/packet_types.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace playerkit::hardware::p2os {

// Payload size without sonar readings: 25 + 3 per reading (N = 27 + 3n).
inline constexpr std::size_t kSipFixedSize = 25;

// FLAGS bit 0; bits 1-4 are the sonar arrays' status.
inline constexpr std::uint16_t kSipFlagMotorsEnabled = 0x0001;

struct SonarReading {
  std::uint8_t index = 0;   // transducer number, 0 = front left, clockwise
  std::uint16_t range = 0;  // raw: mm = range × RangeConvFactor
  friend bool operator==(const SonarReading&, const SonarReading&) = default;
};

struct StandardSip {
  std::uint8_t status = packet_type::sip_stopped;  // 0x32 stopped, 0x33 moving
  std::uint16_t x_position = 0;  // XPOS; the driver keeps only its low 12 bits
  std::uint16_t y_position = 0;  // YPOS
  std::int16_t heading = 0;      // THPOS (P2/P3: 4096 per turn)
  std::int16_t left_velocity = 0;
  std::int16_t right_velocity = 0;
  std::uint8_t battery = 0;      // decivolts
  // Bit 0: the wheel is stalled (low byte left, high byte right); bits 1-5:
  // bumper switches (low byte rear, high byte front).
  std::uint8_t stall_bumpers_low = 0;
  std::uint8_t stall_bumpers_high = 0;
  std::uint16_t control = 0;     // angular servo setpoint
  std::uint16_t flags = 0;
  std::uint8_t compass = 0;      // 2-degree units + 1; 0, 181, 255: no reading
  std::vector<SonarReading> sonar;
  std::uint8_t analog_port = 0;    // TIMER low byte: the selected analog port (1-5)
  std::uint8_t gripper_state = 0;  // TIMER high byte (gripper.hpp gripper_state)
  std::uint8_t analog = 0;
  std::uint8_t digital_in = 0;     // also the gripper beams (gripper.hpp gripper_beam)
  std::uint8_t digital_out = 0;
  std::vector<std::uint8_t> trailing;  // fields newer firmware appends

  bool left_stalled() const { return (stall_bumpers_low & 0x01) != 0; }
  bool right_stalled() const { return (stall_bumpers_high & 0x01) != 0; }
  // Five switches each, bit k = switch k+1 (SIP bit k+1).
  std::uint8_t rear_bumpers() const { return (stall_bumpers_low >> 1) & 0x1F; }
  std::uint8_t front_bumpers() const { return (stall_bumpers_high >> 1) & 0x1F; }
  bool motors_enabled() const { return (flags & kSipFlagMotorsEnabled) != 0; }

  friend bool operator==(const StandardSip&, const StandardSip&) = default;
};

// A stall/bumper byte from its parts (`switches`: five bits, bit 0 = switch 1).
constexpr std::uint8_t stall_bumper_byte(bool stalled, std::uint8_t switches) {
  return static_cast<std::uint8_t>((stalled ? 0x01 : 0x00) | ((switches & 0x1F) << 1));
}

// Payload of a SIP. Throws EncodeError when `status` is not 0x30 ... 0x34 or
// the packet would not fit a frame.
std::vector<std::uint8_t> encode_sip(const StandardSip& sip);
// Throws DecodeError when the payload is not a SIP or is cut short.
StandardSip decode_sip(std::span<const std::uint8_t> payload);

// Compass degrees as 1.5 reads the byte: (b - 1) × 2, or nothing for 0, 181
// and 255, where 1.5 keeps its previous value.
std::optional<int> compass_degrees(std::uint8_t compass);
// The byte for a heading in degrees (any value; wrapped into 0 ... 358).
std::uint8_t compass_byte(double degrees);

}  // namespace playerkit::hardware::p2os
