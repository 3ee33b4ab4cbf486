#pragma once
// The Botrics "cerebellum" protocol of the O-Bot / Trogdor (trogdor.md §1):
// short host messages, each answered by one acknowledgement byte, GET_ODOM
// and GET_VOLTAGE followed by their data block. Integers are 32-bit
// little-endian; a message's last byte is the XOR of the bytes before it.
// Pure bytes: no I/O.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace playerkit::hardware::trogdor {

using Bytes = std::vector<std::uint8_t>;

inline constexpr std::uint8_t kAck = 6;
inline constexpr std::uint8_t kNack = 21;

// First bytes of the host's messages (trogdor.md §1.2).
namespace message {
inline constexpr std::uint8_t init[3] = {253, 252, 251};
inline constexpr std::uint8_t deinit = 250;
inline constexpr std::uint8_t set_velocities = 'v';
inline constexpr std::uint8_t set_accelerations = 'a';
inline constexpr std::uint8_t enable_velocity_control = 'e';
inline constexpr std::uint8_t disable_velocity_control = 'd';
inline constexpr std::uint8_t get_odometry = 'o';
inline constexpr std::uint8_t get_voltage = 'b';
inline constexpr std::uint8_t stop = 's';
inline constexpr std::uint8_t kill = 'k';
inline constexpr std::uint8_t heartbeat = 'h';
}  // namespace message

// A message with two wheel values: its byte, left, right and the XOR.
inline constexpr std::size_t kWheelPairMessageSize = 10;
// GET_ODOM's block after the ACK: two counts, two velocities, the error byte, the XOR.
inline constexpr std::size_t kOdometryBlockSize = 18;
// GET_VOLTAGE's block after the ACK: one int32 and the XOR.
inline constexpr std::size_t kVoltageBlockSize = 5;

[[nodiscard]] std::uint8_t xor_of(std::span<const std::uint8_t> bytes);
// Whether the last byte is the XOR of the others (false for an empty span).
[[nodiscard]] bool xor_checks(std::span<const std::uint8_t> bytes);

void put_int32(Bytes& out, std::int32_t value);
[[nodiscard]] std::int32_t get_int32(std::span<const std::uint8_t> bytes, std::size_t at);

struct WheelPair {
  std::int32_t left = 0;
  std::int32_t right = 0;
  friend bool operator==(const WheelPair&, const WheelPair&) = default;
};

[[nodiscard]] Bytes init();
[[nodiscard]] Bytes deinit();
// Velocities in ticks per PID period (trogdor_units.hpp).
[[nodiscard]] Bytes set_velocities(WheelPair units);
[[nodiscard]] Bytes set_accelerations(WheelPair units);
[[nodiscard]] Bytes enable_velocity_control();
[[nodiscard]] Bytes disable_velocity_control();
[[nodiscard]] Bytes get_odometry();
[[nodiscard]] Bytes get_voltage();

struct OdometryReading {
  std::int32_t left_count = 0;
  std::int32_t right_count = 0;
  std::int32_t left_velocity = 0;   // ticks per PID period
  std::int32_t right_velocity = 0;
  bool encoder_error = false;  // the error byte was 1
  friend bool operator==(const OdometryReading&, const OdometryReading&) = default;
};

// The 18-byte block as the robot sends it: note the velocities' order,
// right before left (trogdor.md §1.2).
[[nodiscard]] Bytes odometry_block(const OdometryReading& reading);
// Nothing when the block is not 18 bytes or its XOR fails.
[[nodiscard]] std::optional<OdometryReading> parse_odometry_block(std::span<const std::uint8_t> block);

[[nodiscard]] Bytes voltage_block(std::int32_t value);
[[nodiscard]] std::optional<std::int32_t> parse_voltage_block(std::span<const std::uint8_t> block);

// How long the host message starting with `first` is: 3 for INIT's first
// byte, 10 for 'v' and 'a', 1 for the other known bytes, 0 for a byte no
// message starts with.
[[nodiscard]] std::size_t host_message_size(std::uint8_t first);

}  // namespace playerkit::hardware::trogdor
