#include "families/ptu46/protocol/ptu_replies.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace playerkit::hardware::ptu46 {

namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

// The number a reply ends with: terse "* 583", or verbose "... is 583".
std::optional<double> trailing_number(std::string_view text) {
  text = trim(text);
  const std::size_t space = text.rfind(' ');
  const std::string_view last = space == std::string_view::npos ? text : text.substr(space + 1);
  if (last.empty()) return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(last.data(), last.data() + last.size(), value);
  if (error != std::errc() || end != last.data() + last.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::optional<Reply> parse_reply(std::string_view line) {
  if (line.empty()) return std::nullopt;
  if (line == reset_line()) return Reply{.kind = Reply::Kind::reset, .number = std::nullopt, .text = {}};
  if (line.front() == '!') return Reply{.kind = Reply::Kind::refused, .number = std::nullopt, .text = std::string(trim(line.substr(1)))};
  if (line.front() != '*') return std::nullopt;
  if (const auto number = trailing_number(line.substr(1))) {
    return Reply{.kind = Reply::Kind::value, .number = number, .text = {}};
  }
  return Reply{.kind = Reply::Kind::done, .number = std::nullopt, .text = std::string(trim(line.substr(1)))};
}

std::string done_line() { return "*"; }

std::string value_line(double number) {
  // Whole numbers as integers ("* 583"), resolutions with four decimals as
  // the manual prints them ("* 185.1428").
  char text[48];
  if (number == std::floor(number) && std::fabs(number) < 1e15) {
    std::snprintf(text, sizeof text, "* %.0f", number);
  } else {
    std::snprintf(text, sizeof text, "* %.4f", number);
  }
  return text;
}

std::string refusal_line(std::string_view why) { return "! " + std::string(why); }

std::string reset_line() { return "!T!T!P!P*"; }

}  // namespace playerkit::hardware::ptu46
