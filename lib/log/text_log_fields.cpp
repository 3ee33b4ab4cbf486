#include "log/text_log_fields.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "text/decimal_number.hpp"
#include "text/printable.hpp"

namespace playerkit::log {
namespace {

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }


// "%.0f" without a locale or a minus zero: wire values in messages.
std::string whole(double value) {
  if (value == 0) return "0";
  char buffer[64];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 0);
  if (error != std::errc{}) return "?";
  return std::string(buffer, end);
}

}  // namespace

LineFields::LineFields(std::string_view text, std::string_view file, int line)
    : file_(file), line_(line) {
  if (!text.empty() && text.back() == '\n') text.remove_suffix(1);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  end_column_ = static_cast<int>(text.size()) + 1;
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (is_separator(text[pos])) {
      ++pos;
      continue;
    }
    const std::size_t start = pos;
    while (pos < text.size() && !is_separator(text[pos])) ++pos;
    fields_.push_back({text.substr(start, pos - start), static_cast<int>(start) + 1});
  }
}

void LineFields::fail(std::size_t i, const std::string& message) const {
  if (i >= fields_.size()) fail_at_end(message);
  throw LogParseError(file_, line_, fields_[i].column, message);
}

void LineFields::fail_at_end(const std::string& message) const {
  throw LogParseError(file_, line_, end_column_, message);
}

void LineFields::at(std::size_t i, std::string_view what) const {
  if (i >= fields_.size()) fail_at_end("line ends before " + std::string(what));
}

void LineFields::expect_end(std::size_t end, std::string_view after) const {
  if (fields_.size() > end) {
    fail(end, "unexpected field " + quoted_excerpt(fields_[end].text) + " after " + std::string(after));
  }
}

protocol::Timestamp LineFields::timestamp(std::size_t i, std::string_view what) const {
  at(i, what);
  const std::string_view text = fields_[i].text;
  const std::size_t dot = text.find('.');
  const std::string_view seconds = text.substr(0, dot);
  const std::string_view fraction = dot == std::string_view::npos ? "" : text.substr(dot + 1);
  auto all_digits = [](std::string_view s) {
    for (char c : s) {
      if (!is_digit(c)) return false;
    }
    return true;
  };
  if (seconds.empty() || !all_digits(seconds) || !all_digits(fraction) ||
      (dot != std::string_view::npos && fraction.empty())) {
    fail(i, std::string(what) + ": expected seconds like 1086000000.250, got " + quoted_excerpt(text));
  }
  std::uint64_t sec = 0;
  const auto parsed = std::from_chars(seconds.data(), seconds.data() + seconds.size(), sec);
  constexpr std::uint64_t kMaxSeconds = std::numeric_limits<std::uint32_t>::max();
  if (parsed.ec != std::errc{} || sec > kMaxSeconds) {
    fail(i, std::string(what) + ": " + std::string(text) +
                " s is beyond the 32-bit seconds of a Player header");
  }
  // Exact decimal arithmetic: six digits of microseconds, the seventh rounds.
  std::uint64_t usec = 0;
  for (std::size_t d = 0; d < 6; ++d) {
    usec = usec * 10 + (d < fraction.size() ? static_cast<std::uint64_t>(fraction[d] - '0') : 0);
  }
  if (fraction.size() > 6 && fraction[6] >= '5') ++usec;
  if (usec == 1000000) {
    usec = 0;
    if (++sec > kMaxSeconds) {
      fail(i, std::string(what) + ": " + std::string(text) +
                  " s is beyond the 32-bit seconds of a Player header");
    }
  }
  return {static_cast<std::uint32_t>(sec), static_cast<std::uint32_t>(usec)};
}

double LineFields::real(std::size_t i, std::string_view what) const { return number(i, what, false); }

double LineFields::scientific(std::size_t i, std::string_view what) const { return number(i, what, true); }

double LineFields::number(std::size_t i, std::string_view what, bool allow_exponent) const {
  at(i, what);
  std::string_view text = fields_[i].text;
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0;
  const auto parsed =
      text::decimal_from_chars(digits.data(), digits.data() + digits.size(), value,
                               allow_exponent ? std::chars_format::general : std::chars_format::fixed);
  if (parsed.ec != std::errc{} || parsed.ptr != digits.data() + digits.size() || !std::isfinite(value)) {
    fail(i, std::string(what) + ": expected a number, got " + quoted_excerpt(text));
  }
  return value;
}

long long LineFields::integer_in(std::size_t i, std::string_view what, long long min,
                                 long long max) const {
  at(i, what);
  const std::string_view text = fields_[i].text;
  long long value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec == std::errc::result_out_of_range ||
      (parsed.ec == std::errc{} && parsed.ptr == text.data() + text.size() &&
       (value < min || value > max))) {
    fail(i, std::string(what) + ": " + std::string(text) + " is out of range " +
                std::to_string(min) + ".." + std::to_string(max));
  }
  if (parsed.ec != std::errc{} || parsed.ptr != text.data() + text.size()) {
    fail(i, std::string(what) + ": expected a whole number, got " + quoted_excerpt(text));
  }
  return value;
}

double LineFields::rounded_in(std::size_t i, std::string_view what, double wire_per_file_unit,
                              std::string_view wire_unit, double min, double max) const {
  const double value = std::round(real(i, what) * wire_per_file_unit);
  if (value < min || value > max) {
    fail(i, std::string(what) + ": " + std::string(fields_[i].text) + " is " + whole(value) + " " +
                std::string(wire_unit) + ", outside the wire field's " + whole(min) + ".." +
                whole(max));
  }
  return value;
}

std::string quoted_excerpt(std::string_view text) { return "'" + text::excerpt(text) + "'"; }

}  // namespace playerkit::log
