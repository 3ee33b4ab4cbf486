#include "families/segwayrmp/protocol/rmp_frames.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::hardware::segwayrmp {

namespace {

framing::CanFrame frame_of(std::uint32_t id, std::array<std::uint16_t, 4> slots) {
  framing::CanFrame frame{.id = id, .extended = false, .remote = false, .dlc = 8, .data = {}};
  for (std::size_t slot = 0; slot < slots.size(); ++slot) {
    frame.data[slot * 2] = static_cast<std::uint8_t>(slots[slot] >> 8);
    frame.data[slot * 2 + 1] = static_cast<std::uint8_t>(slots[slot] & 0xFF);
  }
  return frame;
}

std::uint16_t slot(const framing::CanFrame& frame, std::size_t index) {
  return static_cast<std::uint16_t>((frame.data[index * 2] << 8) | frame.data[index * 2 + 1]);
}

std::int16_t signed_slot(const framing::CanFrame& frame, std::size_t index) {
  return static_cast<std::int16_t>(slot(frame, index));
}

std::uint32_t wide(const framing::CanFrame& frame, std::size_t first) {
  return (static_cast<std::uint32_t>(slot(frame, first + 1)) << 16) | slot(frame, first);
}

std::uint16_t low(std::uint32_t value) { return static_cast<std::uint16_t>(value & 0xFFFF); }
std::uint16_t high(std::uint32_t value) { return static_cast<std::uint16_t>(value >> 16); }
std::uint16_t bits(std::int16_t value) { return static_cast<std::uint16_t>(value); }

std::int16_t rounded_within(double counts, std::int16_t limit) {
  const double clamped = std::clamp(std::rint(counts), -static_cast<double>(limit), static_cast<double>(limit));
  return static_cast<std::int16_t>(clamped);
}

}  // namespace

framing::CanFrame command_frame(const Command& command) {
  const auto value = static_cast<std::uint16_t>(command.status_value);
  // Segway's demo code put the value's low byte in both of the last bytes.
  return frame_of(kCommandId, {bits(command.trans), bits(command.rot), static_cast<std::uint16_t>(command.status),
                               static_cast<std::uint16_t>((value << 8) | value)});
}

framing::CanFrame shutdown_frame() { return frame_of(kShutdownId, {0, 0, 0, 0}); }

std::optional<Command> parse_command(const framing::CanFrame& frame) {
  if (frame.id != kCommandId || frame.extended || frame.remote) return std::nullopt;
  return Command{.trans = signed_slot(frame, 0),
                 .rot = signed_slot(frame, 1),
                 .status = static_cast<StatusCommand>(slot(frame, 2)),
                 .status_value = frame.data[7]};
}

std::int16_t trans_counts(double millimetres_per_second) {
  return rounded_within(millimetres_per_second * kTransCountsPerMillimetrePerSecond, kMaxTransCounts);
}

std::int16_t rot_counts(double degrees_per_second) {
  return rounded_within(degrees_per_second * kAngleCountsPerDegree, kMaxRotCounts);
}

std::array<framing::CanFrame, 5> status_frames(const Status& status) {
  return {
      frame_of(kBatteryId, {0, 0, status.battery, 0}),
      frame_of(kAttitudeId, {bits(status.pitch), bits(status.pitch_rate), bits(status.roll), bits(status.roll_rate)}),
      frame_of(kVelocityId, {bits(status.left_wheel_velocity), bits(status.right_wheel_velocity),
                             bits(status.yaw_rate), status.frame_counter}),
      frame_of(kWheelDisplacementId, {low(status.left_wheel_displacement), high(status.left_wheel_displacement),
                                      low(status.right_wheel_displacement), high(status.right_wheel_displacement)}),
      frame_of(kBodyDisplacementId, {low(status.fore_aft_displacement), high(status.fore_aft_displacement),
                                     low(status.yaw_displacement), high(status.yaw_displacement)}),
  };
}

bool StatusAssembler::add(const framing::CanFrame& frame) {
  if (frame.extended || frame.remote || frame.dlc < 8 || frame.id < kBatteryId || frame.id > kBodyDisplacementId) {
    return false;
  }
  switch (frame.id) {
    case kBatteryId:
      status_.battery = slot(frame, 2);
      break;
    case kAttitudeId:
      status_.pitch = signed_slot(frame, 0);
      status_.pitch_rate = signed_slot(frame, 1);
      status_.roll = signed_slot(frame, 2);
      status_.roll_rate = signed_slot(frame, 3);
      break;
    case kVelocityId:
      status_.left_wheel_velocity = signed_slot(frame, 0);
      status_.right_wheel_velocity = signed_slot(frame, 1);
      status_.yaw_rate = signed_slot(frame, 2);
      status_.frame_counter = slot(frame, 3);
      break;
    case kWheelDisplacementId:
      status_.left_wheel_displacement = wide(frame, 0);
      status_.right_wheel_displacement = wide(frame, 2);
      break;
    default:
      status_.fore_aft_displacement = wide(frame, 0);
      status_.yaw_displacement = wide(frame, 2);
      break;
  }
  seen_ |= static_cast<std::uint8_t>(1u << (frame.id & 0xF));
  if (seen_ != 0x1F) return false;
  seen_ = 0;
  return true;
}

}  // namespace playerkit::hardware::segwayrmp
