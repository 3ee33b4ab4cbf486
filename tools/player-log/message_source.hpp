#pragma once
// A log of either format as Player data messages, in file order: Player logs
// as they are, CARMEN logs through log::carmen_to_player. Malformed lines are
// skipped and counted (their first texts kept) unless strict, when the
// LogParseError propagates.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "log/text_log_format.hpp"
#include "log_tool.hpp"
#include "protocol/message.hpp"

namespace playerkit::plog {

struct SourceMessage {
  const protocol::Message& message;
  const std::string& host;
  std::uint16_t port;
};

struct SourceStats {
  LogFormat format = LogFormat::kPlayer;
  log::LogFormatVersion version = log::LogFormatVersion::k0_0_0;
  std::size_t malformed = 0;
  std::vector<std::string> malformed_texts;
  std::size_t skipped = 0;  // CARMEN records Player has no place for (PARAM, TRUEPOS), unknown names
};

SourceStats for_each_message(const std::filesystem::path& path, bool strict,
                             const std::function<void(const SourceMessage&)>& visit);

}  // namespace playerkit::plog
