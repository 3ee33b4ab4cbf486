#pragma once
// Host-to-robot commands (p2os.md §1.2, §2.1): a command number, then
// optionally an argument introduced by a type byte. Numbers are reused: 0 is
// SYNC0 before the connection and PULSE after it, 1 SYNC1/OPEN, 2 SYNC2/CLOSE.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::hardware::p2os {

namespace command {
inline constexpr std::uint8_t sync0 = 0;
inline constexpr std::uint8_t pulse = 0;
inline constexpr std::uint8_t sync1 = 1;
inline constexpr std::uint8_t open = 1;
inline constexpr std::uint8_t sync2 = 2;
inline constexpr std::uint8_t close = 2;
inline constexpr std::uint8_t enable = 4;
inline constexpr std::uint8_t setv = 6;
inline constexpr std::uint8_t seto = 7;
inline constexpr std::uint8_t vel = 11;
inline constexpr std::uint8_t config = 18;
inline constexpr std::uint8_t rvel = 21;
inline constexpr std::uint8_t sonar = 28;
inline constexpr std::uint8_t stop = 29;
inline constexpr std::uint8_t vel2 = 32;
inline constexpr std::uint8_t gripper = 33;
inline constexpr std::uint8_t gripper_value = 36;
inline constexpr std::uint8_t gripper_request = 37;
inline constexpr std::uint8_t io_request = 40;
inline constexpr std::uint8_t tty2 = 42;
inline constexpr std::uint8_t getaux = 43;
inline constexpr std::uint8_t joydrive = 47;
inline constexpr std::uint8_t gyro = 58;
inline constexpr std::uint8_t tty3 = 66;
inline constexpr std::uint8_t getaux2 = 67;
inline constexpr std::uint8_t sound = 90;
inline constexpr std::uint8_t playlist = 91;
}  // namespace command

// The type byte before an argument.
namespace argument_type {
inline constexpr std::uint8_t integer = 0x3B;           // ARGINT: 2 bytes, LSB first, value >= 0
inline constexpr std::uint8_t negative_integer = 0x1B;  // ARGNINT: 2 bytes, the negative of them
inline constexpr std::uint8_t string = 0x2B;            // ARGSTR: length byte, then the characters
}  // namespace argument_type

enum class ArgumentForm {
  none,       // a single payload byte
  integer,    // ARGINT or ARGNINT with its two value bytes
  type_only,  // an integer type byte and no value: how the reference sends SETO
  string,     // ARGSTR
};

struct Command {
  std::uint8_t number = 0;
  ArgumentForm form = ArgumentForm::none;
  std::uint16_t magnitude = 0;  // integer: the two value bytes as sent
  bool negative = false;        // integer: sent as ARGNINT
  std::string text;             // string

  // integer: the signed value (-65535 ... 65535); 0 for the other forms.
  int value() const { return negative ? -static_cast<int>(magnitude) : magnitude; }

  static Command plain(std::uint8_t number);
  // ARGINT for value >= 0, ARGNINT below. Throws EncodeError when |value| > 65535.
  static Command with_integer(std::uint8_t number, int value);
  // SETO as the reference sends it: ARGINT's type byte and nothing else.
  static Command type_only(std::uint8_t number);
  static Command with_string(std::uint8_t number, std::string text);

  friend bool operator==(const Command&, const Command&) = default;
};

// The payload of a command. Throws EncodeError when a string argument is
// longer than 255 characters or the frame would exceed N = 200.
std::vector<std::uint8_t> encode_command(const Command& command);
// The whole frame (FA FB N ... checksum) of a command.
std::vector<std::uint8_t> command_frame(const Command& command);

// Parses a command payload. Throws DecodeError for an empty payload, an
// unknown type byte, or an argument cut short. Bytes after a complete
// argument are ignored, as a controller would.
Command decode_command(std::span<const std::uint8_t> payload);

// VEL2's argument: left wheel in the high byte, right in the low, each a
// signed byte in units of the robot's Vel2Divisor mm/s.
struct Vel2Wheels {
  std::int8_t left = 0;
  std::int8_t right = 0;
  friend bool operator==(const Vel2Wheels&, const Vel2Wheels&) = default;
};
std::uint16_t encode_vel2(Vel2Wheels wheels);
Vel2Wheels decode_vel2(std::uint16_t magnitude);

// "ENABLE", "VEL2", "SYNC0" or "PULSE" (depending on `connected`), or
// "command 99" for a number the sheet does not name.
std::string command_name(std::uint8_t number, bool connected);

}  // namespace playerkit::hardware::p2os
