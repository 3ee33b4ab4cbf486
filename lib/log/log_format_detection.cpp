#include "log/log_format_detection.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>
#include <string>
#include <vector>

#include "log/log_input.hpp"
#include "log/log_line.hpp"
#include "text/printable.hpp"

namespace playerkit::log {
namespace {

std::vector<std::string_view> split_fields(std::string_view line, std::size_t at_most) {
  std::vector<std::string_view> fields;
  std::size_t at = 0;
  while (fields.size() < at_most) {
    at = line.find_first_not_of(" \t\r\n", at);
    if (at == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r\n", at), line.size());
    fields.push_back(line.substr(at, end - at));
    at = end;
  }
  return fields;
}

bool is_unsigned_decimal(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

bool is_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && parsed.ec == std::errc{} && parsed.ptr == text.data() + text.size();
}

bool is_interface_name(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) != 0 ||
           std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

// CARMEN's record names: FLASER, ROBOTLASER1, VERTEX2, GPS_GPGGA, ...
bool is_carmen_keyword(std::string_view text) {
  return !text.empty() && std::isupper(static_cast<unsigned char>(text.front())) != 0 &&
         std::all_of(text.begin(), text.end(), [](char c) {
           return std::isupper(static_cast<unsigned char>(c)) != 0 ||
                  std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '_';
         });
}

// Player's prefix: time host port interface index time.
bool is_player_data_line(const std::vector<std::string_view>& fields) {
  return fields.size() >= 6 && is_number(fields[0]) && !fields[1].empty() &&
         is_unsigned_decimal(fields[2]) && is_interface_name(fields[3]) &&
         is_unsigned_decimal(fields[4]) && is_number(fields[5]);
}


}  // namespace

std::string_view to_string(LogFormat format) {
  return format == LogFormat::kPlayer ? "player" : "carmen";
}

std::optional<LogFormat> classify_log_line(std::string_view line) {
  if (line.starts_with("## ")) return LogFormat::kPlayer;  // Player's header lines
  const auto fields = split_fields(line, 6);
  if (fields.empty() || fields.front().starts_with('#')) return std::nullopt;
  if (is_player_data_line(fields)) return LogFormat::kPlayer;
  if (is_carmen_keyword(fields.front())) return LogFormat::kCarmen;
  if (std::any_of(line.begin(), line.end(), [](char c) {
        return c == '\0' || (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r' && c != '\n');
      })) {
    throw std::runtime_error("binary data, not a text log");
  }
  throw std::runtime_error(std::string("neither a Player log line (\"<time> <host> <port> <interface> "
                                       "<index> <time> ...\") nor a CARMEN record (an upper-case keyword "
                                       "such as FLASER): '") +
                           text::excerpt(line) + "'");
}

LogFormat detect_log_format(std::istream& in, std::string_view name) {
  std::string line;
  std::size_t number = 0;
  bool too_long = false;
  while (number < kMaxDetectionLines && read_log_line(in, line, too_long)) {
    ++number;
    if (too_long) throw too_long_line_error(std::string(name), static_cast<int>(number));
    try {
      if (const auto format = classify_log_line(line)) return *format;
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(std::string(name) + ":" + std::to_string(number) + ": " + error.what());
    }
  }
  if (number == 0) throw std::runtime_error(std::string(name) + ": empty file, not a log");
  throw std::runtime_error(std::string(name) + ": no Player or CARMEN line in its first " +
                           std::to_string(number) + " lines (only blank lines and comments)");
}

LogFormat detect_log_format(const std::filesystem::path& path) {
  auto in = open_log_input(path);
  try {
    return detect_log_format(*in, path.string());
  } catch (const std::runtime_error&) {
    if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
    throw;
  }
}

}  // namespace playerkit::log
