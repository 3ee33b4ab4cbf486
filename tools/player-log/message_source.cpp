#include "message_source.hpp"

#include <stdexcept>
#include <variant>

#include "log/carmen_log_reader.hpp"
#include "log/log_conversion.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"

namespace playerkit::plog {

SourceStats for_each_message(const std::filesystem::path& path, bool strict,
                             const std::function<void(const SourceMessage&)>& visit) {
  SourceStats stats;
  stats.format = detect_log_format(path);
  auto in = log::open_log_input(path);
  if (stats.format == LogFormat::kPlayer) {
    log::TextLogReader reader(*in, path.string(), {.strict = strict});
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
    log::CarmenLogReader reader(*in, path.string(), {.strict = strict});
    while (auto record = reader.next()) {
      log::PlayerMessages converted;
      try {
        converted = log::carmen_to_player(*record);
      } catch (const std::invalid_argument& e) {
        throw log::LogParseError(path.string(), reader.line_number(), 1, e.what());
      }
      if (converted.messages.empty()) ++stats.skipped;
      for (const auto& message : converted.messages) visit({message, converted.host, 6665});
    }
    stats.malformed = reader.malformed_lines();
    stats.malformed_texts = reader.malformed_messages();
    stats.skipped += reader.unknown_lines();
  }
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  return stats;
}

}  // namespace playerkit::plog
