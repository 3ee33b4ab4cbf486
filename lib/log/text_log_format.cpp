#include "log/text_log_format.hpp"

namespace playerkit::log {

std::string_view to_string(LogFormatVersion version) {
  return version == LogFormatVersion::k0_2_0 ? "0.2.0" : "0.0.0";
}

std::optional<LogFormatVersion> parse_format_version(std::string_view text) {
  if (text == "0.0.0") return LogFormatVersion::k0_0_0;
  if (text == "0.2.0") return LogFormatVersion::k0_2_0;
  return std::nullopt;
}

}  // namespace playerkit::log
