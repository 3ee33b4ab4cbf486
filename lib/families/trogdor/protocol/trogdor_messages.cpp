#include "families/trogdor/protocol/trogdor_messages.hpp"

namespace playerkit::hardware::trogdor {

namespace {

Bytes wheel_pair_message(std::uint8_t first, WheelPair units) {
  Bytes out{first};
  put_int32(out, units.left);
  put_int32(out, units.right);
  out.push_back(xor_of(out));
  return out;
}

}  // namespace

std::uint8_t xor_of(std::span<const std::uint8_t> bytes) {
  std::uint8_t sum = 0;
  for (const std::uint8_t byte : bytes) sum ^= byte;
  return sum;
}

bool xor_checks(std::span<const std::uint8_t> bytes) {
  return !bytes.empty() && xor_of(bytes.first(bytes.size() - 1)) == bytes.back();
}

void put_int32(Bytes& out, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value);
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(bits >> shift));
}

std::int32_t get_int32(std::span<const std::uint8_t> bytes, std::size_t at) {
  std::uint32_t bits = 0;
  for (std::size_t i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(bytes[at + i]) << (8 * i);
  return static_cast<std::int32_t>(bits);
}

Bytes init() { return Bytes(std::begin(message::init), std::end(message::init)); }
Bytes deinit() { return {message::deinit}; }
Bytes set_velocities(WheelPair units) { return wheel_pair_message(message::set_velocities, units); }
Bytes set_accelerations(WheelPair units) { return wheel_pair_message(message::set_accelerations, units); }
Bytes enable_velocity_control() { return {message::enable_velocity_control}; }
Bytes disable_velocity_control() { return {message::disable_velocity_control}; }
Bytes get_odometry() { return {message::get_odometry}; }
Bytes get_voltage() { return {message::get_voltage}; }

Bytes odometry_block(const OdometryReading& reading) {
  Bytes out;
  put_int32(out, reading.left_count);
  put_int32(out, reading.right_count);
  put_int32(out, reading.right_velocity);
  put_int32(out, reading.left_velocity);
  out.push_back(reading.encoder_error ? 1 : 0);
  out.push_back(xor_of(out));
  return out;
}

std::optional<OdometryReading> parse_odometry_block(std::span<const std::uint8_t> block) {
  if (block.size() != kOdometryBlockSize || !xor_checks(block)) return std::nullopt;
  return OdometryReading{.left_count = get_int32(block, 0),
                         .right_count = get_int32(block, 4),
                         .left_velocity = get_int32(block, 12),
                         .right_velocity = get_int32(block, 8),
                         .encoder_error = block[16] == 1};
}

Bytes voltage_block(std::int32_t value) {
  Bytes out;
  put_int32(out, value);
  out.push_back(xor_of(out));
  return out;
}

std::optional<std::int32_t> parse_voltage_block(std::span<const std::uint8_t> block) {
  if (block.size() != kVoltageBlockSize || !xor_checks(block)) return std::nullopt;
  return get_int32(block, 0);
}

std::size_t host_message_size(std::uint8_t first) {
  switch (first) {
    case message::init[0]:
      return sizeof message::init;
    case message::set_velocities:
    case message::set_accelerations:
      return kWheelPairMessageSize;
    case message::deinit:
    case message::enable_velocity_control:
    case message::disable_velocity_control:
    case message::get_odometry:
    case message::get_voltage:
    case message::stop:
    case message::kill:
    case message::heartbeat:
      return 1;
    default:
      return 0;
  }
}

}  // namespace playerkit::hardware::trogdor
