#include "families/flockofbirds/protocol/bird_commands.hpp"

#include <algorithm>

namespace playerkit::hardware::flockofbirds {

namespace {

// Value bytes CHANGE VALUE carries for a parameter: one word each.
constexpr std::size_t kValueBytes = 2;

bool unmarked(std::uint8_t byte) { return (byte & kPhasingBit) == 0; }

}  // namespace

std::vector<std::uint8_t> command(CommandByte byte) { return {static_cast<std::uint8_t>(byte)}; }

std::vector<std::uint8_t> examine_position_scaling() {
  return {static_cast<std::uint8_t>(CommandByte::examine_value), kPositionScalingParameter};
}

std::vector<std::uint8_t> change_position_scaling(PositionScaling scaling) {
  const auto value = scaling_reply(scaling);
  return {static_cast<std::uint8_t>(CommandByte::change_value), kPositionScalingParameter, value[0], value[1]};
}

std::array<std::uint8_t, kScalingReplySize> scaling_reply(PositionScaling scaling) {
  return {static_cast<std::uint8_t>(scaling == PositionScaling::inches_36 ? 0 : 1), 0};
}

std::optional<PositionScaling> scaling_from_reply(std::span<const std::uint8_t> reply) {
  if (reply.size() != kScalingReplySize || reply[1] != 0) return std::nullopt;
  if (reply[0] == 0) return PositionScaling::inches_36;
  if (reply[0] == 1) return PositionScaling::inches_72;
  return std::nullopt;
}

framing::FixedLengthOptions scaling_reply_format_options() {
  return {.size = kScalingReplySize,
          .sync = {},
          .check = [](std::span<const std::uint8_t> reply) { return std::all_of(reply.begin(), reply.end(), unmarked); },
          .name = "flockofbirds-value"};
}

std::vector<BirdCommand> CommandReader::feed(std::span<const std::uint8_t> bytes) {
  std::vector<BirdCommand> done;
  for (const std::uint8_t byte : bytes) {
    if (!pending_) {
      BirdCommand next{.byte = static_cast<CommandByte>(byte), .raw = byte, .parameter = 0, .value = {}};
      if (next.byte == CommandByte::examine_value || next.byte == CommandByte::change_value) {
        pending_ = std::move(next);
        have_parameter_ = false;
      } else {
        done.push_back(std::move(next));
      }
      continue;
    }
    if (!have_parameter_) {
      pending_->parameter = byte;
      have_parameter_ = true;
    } else {
      pending_->value.push_back(byte);
    }
    const std::size_t wanted = pending_->byte == CommandByte::change_value ? kValueBytes : 0;
    if (have_parameter_ && pending_->value.size() == wanted) {
      done.push_back(std::move(*pending_));
      pending_.reset();
    }
  }
  return done;
}

void CommandReader::reset() {
  pending_.reset();
  have_parameter_ = false;
}

}  // namespace playerkit::hardware::flockofbirds
