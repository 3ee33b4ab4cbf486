#include "message_source.hpp"

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "log/carmen_log_reader.hpp"
#include "log/log_clock_reader.hpp"
#include "log/log_conversion.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"

namespace playerkit::plog {

namespace {
constexpr std::size_t kKeptUnconvertible = 10;
}  // namespace

SourceStats for_each_message(const std::filesystem::path& path, bool strict,
                             const std::function<void(const SourceMessage&)>& visit) {
  SourceStats stats;
  stats.format = detect_log_format(path);
  // Unusable times are replaced (and said so on stderr once) before they become messages.
  const auto clock = log::audit_log_times(path);
  auto in = log::open_log_input(path);
  if (stats.format == LogFormat::kPlayer) {
    log::TextLogReader reader(*in, path.string(), {.strict = strict, .clock = clock});
    while (auto line = reader.next()) {
      const auto* data = std::get_if<log::DataLine>(&*line);
      if (!data) continue;
      if (!data->device) {
        ++stats.skipped;
        continue;
      }
      visit({data->message, data->host, data->port});
    }
    stats.version = reader.format_version();
    stats.malformed = reader.malformed_count();
    stats.malformed_texts = reader.malformed_lines();
  } else {
    log::CarmenLogReader reader(*in, path.string(), {.strict = strict, .clock = clock});
    // Records CARMEN reads but Player cannot hold (a negative time, as one
    // ODOM line of Freiburg 079 has) count as malformed, like a bad line.
    std::size_t unconvertible = 0;
    std::vector<std::string> unconvertible_texts;
    while (auto record = reader.next()) {
      log::PlayerMessages converted;
      try {
        converted = log::carmen_to_player(*record);
      } catch (const std::invalid_argument& e) {
        log::LogParseError error(path.string(), reader.line_number(), 1, e.what());
        if (strict) throw error;
        if (unconvertible_texts.size() < kKeptUnconvertible) unconvertible_texts.emplace_back(error.what());
        ++unconvertible;
        continue;
      }
      if (converted.messages.empty()) ++stats.skipped;
      for (const auto& message : converted.messages) visit({message, converted.host, 6665});
    }
    stats.malformed = reader.malformed_lines() + unconvertible;
    stats.malformed_texts = reader.malformed_messages();
    stats.malformed_texts.insert(stats.malformed_texts.end(), unconvertible_texts.begin(), unconvertible_texts.end());
    stats.skipped += reader.unknown_lines();
  }
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  return stats;
}

}  // namespace playerkit::plog
