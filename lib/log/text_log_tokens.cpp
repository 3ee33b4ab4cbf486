#include "log/text_log_tokens.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "text/printable.hpp"

namespace playerkit::log {

std::vector<LineToken> split_line_tokens(std::string_view line) {
  std::vector<LineToken> tokens;
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t\r\n", at);
    if (at == std::string_view::npos) break;
    std::size_t end = line.find_first_of(" \t\r\n", at);
    if (end == std::string_view::npos) end = line.size();
    tokens.push_back({at, line.substr(at, end - at)});
    at = end;
  }
  return tokens;
}

double token_number(const LineToken& token, std::string_view what) {
  std::string_view text = token.text;
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || parsed.ec != std::errc{} || parsed.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw std::runtime_error(std::string(what) + ": expected a number, got '" + text::excerpt(token.text) + "'");
  }
  return value;
}

std::string replace_tokens(std::string_view line, const std::vector<LineToken>& tokens, std::size_t first,
                           const std::vector<std::string>& replacements) {
  if (first + replacements.size() > tokens.size()) {
    throw std::logic_error("replace_tokens: tokens past the end of the line");
  }
  std::string result;
  result.reserve(line.size() + 16);
  std::size_t copied = 0;
  for (std::size_t i = 0; i < replacements.size(); ++i) {
    const LineToken& token = tokens[first + i];
    result.append(line.substr(copied, token.offset - copied));
    result.append(replacements[i]);
    copied = token.offset + token.text.size();
  }
  result.append(line.substr(copied));
  return result;
}

PoseColumns pose_columns(bool truth_0_2_0) {
  PoseColumns columns;
  if (truth_0_2_0) columns.yaw = kFirstFieldColumn + 5;
  return columns;
}

TextPose read_text_pose(const std::vector<LineToken>& tokens, bool truth_0_2_0) {
  const PoseColumns columns = pose_columns(truth_0_2_0);
  if (tokens.size() <= columns.yaw) throw std::runtime_error("pose line too short");
  return {token_number(tokens[columns.x], "x"), token_number(tokens[columns.y], "y"),
          token_number(tokens[columns.yaw], "yaw")};
}

std::string format_text(const char* format, double value) {
  char buffer[64];
  const int written = std::snprintf(buffer, sizeof buffer, format, value);
  if (written < 0 || static_cast<std::size_t>(written) >= sizeof buffer) {
    throw std::runtime_error("a number does not fit its field");
  }
  return std::string(buffer, static_cast<std::size_t>(written));
}

}  // namespace playerkit::log
