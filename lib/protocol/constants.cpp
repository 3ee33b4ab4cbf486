#include "protocol/constants.hpp"

#include <array>
#include <utility>

namespace playerkit::protocol {
namespace {

constexpr std::array<std::pair<MessageType, std::string_view>, 7> kMessageTypeNames{{
    {MessageType::kData, "data"},
    {MessageType::kCommand, "cmd"},
    {MessageType::kRequest, "req"},
    {MessageType::kAck, "ack"},
    {MessageType::kSynch, "synch"},
    {MessageType::kNack, "nack"},
    {MessageType::kError, "err"},
}};

constexpr std::array<std::pair<DataMode, std::string_view>, 4> kDataModeNames{{
    {DataMode::kPushAll, "push-all"},
    {DataMode::kPullAll, "pull-all"},
    {DataMode::kPushNew, "push-new"},
    {DataMode::kPullNew, "pull-new"},
}};

}  // namespace

std::string_view to_string(MessageType type) {
  for (const auto& [value, name] : kMessageTypeNames) {
    if (value == type) return name;
  }
  return "unknown";
}

std::optional<MessageType> parse_message_type(std::string_view name) {
  for (const auto& [value, text] : kMessageTypeNames) {
    if (text == name) return value;
  }
  return std::nullopt;
}

bool is_reply(MessageType type) {
  return type == MessageType::kAck || type == MessageType::kNack || type == MessageType::kError;
}

std::string_view to_string(DataMode mode) {
  for (const auto& [value, name] : kDataModeNames) {
    if (value == mode) return name;
  }
  return "unknown";
}

std::optional<DataMode> parse_data_mode(std::string_view name) {
  for (const auto& [value, text] : kDataModeNames) {
    if (text == name) return value;
  }
  return std::nullopt;
}

}  // namespace playerkit::protocol
