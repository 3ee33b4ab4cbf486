#include "families/er1/protocol/er1_commands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace playerkit::hardware::er1 {

std::size_t command_length(std::uint8_t op) {
  switch (op) {
    case opcode::init:
    case opcode::reset_position:
    case opcode::execute:
    case opcode::read_position:
    case opcode::read_status:
      return 4;
    case opcode::mode_77:
    case opcode::mode_80:
    case opcode::mode_a0:
    case opcode::profile:
    case opcode::mode_d0:
    case opcode::voltage:
      return 6;
    case opcode::velocity:
    case opcode::acceleration:
    case opcode::deceleration:
      return 8;
    default:
      return 0;
  }
}

std::size_t reply_length(std::uint8_t op) {
  switch (op) {
    case opcode::init:
    case opcode::read_position:
      return 6;
    case opcode::read_status:
    case opcode::voltage:
      return 4;
    default:
      return 2;
  }
}

std::uint8_t balancing_byte(std::span<const std::uint8_t> bytes) {
  const unsigned sum = std::accumulate(bytes.begin(), bytes.end(), 0u);
  return static_cast<std::uint8_t>(0x100u - (sum & 0xFFu));
}

bool sums_to_zero(std::span<const std::uint8_t> bytes) {
  return (std::accumulate(bytes.begin(), bytes.end(), 0u) & 0xFFu) == 0;
}

Bytes command(Motor motor, std::uint8_t op, std::span<const std::uint8_t> argument) {
  Bytes bytes{static_cast<std::uint8_t>(motor), 0, 0, op};
  bytes.insert(bytes.end(), argument.begin(), argument.end());
  bytes[1] = balancing_byte(bytes);
  return bytes;
}

Bytes command16(Motor motor, std::uint8_t op, std::uint16_t argument) {
  const std::uint8_t big_endian[] = {static_cast<std::uint8_t>(argument >> 8), static_cast<std::uint8_t>(argument)};
  return command(motor, op, big_endian);
}

Bytes command32(Motor motor, std::uint8_t op, std::int32_t argument) {
  const auto value = static_cast<std::uint32_t>(argument);
  const std::uint8_t big_endian[] = {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
                                     static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
  return command(motor, op, big_endian);
}

Bytes init(Motor motor) { return command(motor, opcode::init); }
Bytes execute(Motor motor) { return command(motor, opcode::execute); }
Bytes read_position(Motor motor) { return command(motor, opcode::read_position); }
Bytes set_velocity(Motor motor, std::int32_t speed_register) {
  return command32(motor, opcode::velocity, speed_register);
}

std::vector<Bytes> reset_sequence(Motor motor) {
  return {command(motor, opcode::reset_position),    command16(motor, opcode::mode_77, 0),
          command16(motor, opcode::mode_80, 0),      command16(motor, opcode::mode_a0, 1),
          command32(motor, opcode::velocity, 0),     command32(motor, opcode::acceleration, 0),
          command32(motor, opcode::deceleration, 0), execute(motor)};
}

std::vector<Bytes> speed_sequence(Motor motor, std::int32_t speed_register, bool from_standstill) {
  std::vector<Bytes> sequence{command(motor, opcode::read_status)};
  if (from_standstill) {
    sequence.push_back(command16(motor, opcode::profile, 0x0300));
    sequence.push_back(command16(motor, opcode::mode_77, 0x6590));
    sequence.push_back(command16(motor, opcode::mode_a0, 1));
  } else {
    sequence.push_back(command16(motor, opcode::profile, 0x0700));
  }
  sequence.push_back(set_velocity(motor, speed_register));
  sequence.push_back(command32(motor, opcode::acceleration, 0x7E));
  return sequence;
}

std::vector<Bytes> acceleration_sequence(Motor motor) {
  return {command(motor, opcode::read_status), command16(motor, opcode::profile, 0x0700),
          command32(motor, opcode::acceleration, 0x7A)};
}

std::vector<Bytes> stop_sequence(Motor motor) {
  return {command16(motor, opcode::profile, 0),      command16(motor, opcode::mode_77, 0),
          command16(motor, opcode::mode_a0, 1),      command16(motor, opcode::mode_d0, 1),
          command32(motor, opcode::velocity, 0),     command32(motor, opcode::acceleration, 0),
          command32(motor, opcode::deceleration, 0), execute(motor),
          command(motor, opcode::reset_position)};
}

std::int32_t speed_register(double millimetres_per_second) {
  const double value = std::trunc(millimetres_per_second / 10.0 * kSpeedUnitsPerCentimetrePerSecond);
  constexpr double kLargest = std::numeric_limits<std::int32_t>::max();
  if (std::isnan(value)) return 0;
  return static_cast<std::int32_t>(std::clamp(value, -kLargest, kLargest));
}

double millimetres_per_second(std::int32_t speed_register) {
  return speed_register / kSpeedUnitsPerCentimetrePerSecond * 10.0;
}

Bytes reply(std::uint8_t status, std::span<const std::uint8_t> data) {
  Bytes bytes{status, 0};
  bytes.insert(bytes.end(), data.begin(), data.end());
  bytes[1] = balancing_byte(bytes);
  return bytes;
}

std::optional<std::int32_t> position_count(std::span<const std::uint8_t> reply) {
  if (reply.size() != 6) return std::nullopt;
  const std::uint32_t value = (std::uint32_t{reply[2]} << 24) | (std::uint32_t{reply[3]} << 16) |
                              (std::uint32_t{reply[4]} << 8) | std::uint32_t{reply[5]};
  return static_cast<std::int32_t>(value);
}

Bytes position_reply(std::int32_t count) {
  const auto value = static_cast<std::uint32_t>(count);
  const std::uint8_t data[] = {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
                               static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
  return reply(0, data);
}

Bytes init_reply() {
  const std::uint8_t data[] = {0x34, 0x10, 0x00, 0x13};
  return reply(0, data);
}

}  // namespace playerkit::hardware::er1
