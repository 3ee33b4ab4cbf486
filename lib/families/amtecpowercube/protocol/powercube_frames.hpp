#pragma once
// The Amtec PowerCube's serial telegrams as pure bytes (amtecpowercube.md
// §1, §2): STX, a header D1 D2 naming the module and the data length, the
// data and a check byte stuffed with DLE, ETX. The same frame carries a
// command to a module and the module's reply.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "framing/dle_stuffed_format.hpp"

namespace playerkit::hardware::powercube {

// The wrist of Player 1.5's driver: two modules on one line.
enum class Module : std::uint8_t { tilt = 11, pan = 12 };

enum class CommandCode : std::uint8_t {
  reset = 0x00,
  home = 0x01,
  halt = 0x02,
  set_extended = 0x08,
  get_extended = 0x0A,
  set_motion = 0x0B,
};

enum class Parameter : std::uint8_t {
  state = 0x27,           // uint32, ModuleState bits
  min_position = 0x45,    // float rad
  max_position = 0x46,    // float rad
  position = 0x3C,        // float rad, the actual position
  velocity = 0x41,        // float rad/s, the actual velocity
};

enum class MotionMode : std::uint8_t { step = 0x10, velocity = 0x11 };  // FSTEP_ACK, FVEL_ACK

namespace state_bit {
inline constexpr std::uint32_t error = 0x01;
inline constexpr std::uint32_t homed = 0x02;
inline constexpr std::uint32_t halted = 0x04;
}  // namespace state_bit

// Data of one frame is at most 31 bytes (5 bits of D2).
inline constexpr std::size_t kMaxDataLength = 31;
// A frame as sent: STX, D1, D2, every data byte and the check escaped, ETX.
inline constexpr std::size_t kLongestFrame = 3 + 2 * (kMaxDataLength + 1) + 1;

struct Frame {
  std::uint8_t module = 0;  // 0..31
  std::vector<std::uint8_t> data;
  std::uint8_t check = 0;   // as received (stuffed frames carry it last)
};

// (module id + Σ data) mod 256: the host's check byte.
[[nodiscard]] std::uint8_t check_byte(std::uint8_t module, std::span<const std::uint8_t> data);

// The header: D1 = 0x04 | id >> 3, D2 = (id & 7) << 5 | length.
[[nodiscard]] std::uint8_t header_d1(std::uint8_t module);
[[nodiscard]] std::uint8_t header_d2(std::uint8_t module, std::size_t length);

// The whole frame as it goes on the line, with the check byte computed.
[[nodiscard]] std::vector<std::uint8_t> encode(std::uint8_t module, std::span<const std::uint8_t> data);
[[nodiscard]] std::vector<std::uint8_t> encode(Module module, std::span<const std::uint8_t> data);

// A stuffed frame read back: module from the header, the data (as long as
// the bytes between header and check, whatever D2 claims), the check byte.
// nullopt when it is no well-formed frame.
[[nodiscard]] std::optional<Frame> decode(std::span<const std::uint8_t> telegram);
[[nodiscard]] bool check_holds(const Frame& frame);

// The format cutting frames out of a byte stream; no check (the reply's
// check byte is not documented, amtecpowercube.md §1).
[[nodiscard]] framing::DleOptions frame_options();

// --- command data (before stuffing)
[[nodiscard]] std::vector<std::uint8_t> reset_data();
[[nodiscard]] std::vector<std::uint8_t> home_data();
[[nodiscard]] std::vector<std::uint8_t> halt_data();
[[nodiscard]] std::vector<std::uint8_t> get_data(Parameter parameter);
[[nodiscard]] std::vector<std::uint8_t> set_float_data(Parameter parameter, float value);
// A move to `radians`, arriving after `milliseconds`.
[[nodiscard]] std::vector<std::uint8_t> step_data(float radians, std::uint16_t milliseconds);
[[nodiscard]] std::vector<std::uint8_t> velocity_data(float radians_per_second);
// A GET_EXTENDED reply: 0A pp v0 v1 v2 v3.
[[nodiscard]] std::vector<std::uint8_t> value_reply_data(Parameter parameter, std::uint32_t raw);

// --- values, little-endian as an x86 host copied them
[[nodiscard]] std::uint32_t float_bits(float value);
[[nodiscard]] float float_from_bits(std::uint32_t bits);
[[nodiscard]] std::uint32_t read_u32(std::span<const std::uint8_t> four);
void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value);

// The value of a GET_EXTENDED reply to `parameter`, nullopt for any other frame.
[[nodiscard]] std::optional<std::uint32_t> reply_value(const Frame& reply, Parameter parameter);

}  // namespace playerkit::hardware::powercube
