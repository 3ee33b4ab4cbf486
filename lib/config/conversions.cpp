#include "config/conversions.hpp"

#include <charconv>
#include <cstdlib>
#include <limits>
#include <string>

namespace playerkit::config {
namespace {

bool is_c_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

std::string_view skip_leading_space(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size() && is_c_space(text[start])) ++start;
  return text.substr(start);
}

}  // namespace

int c_atoi(std::string_view text) {
  text = skip_leading_space(text);
  bool negative = false;
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  long long magnitude = 0;
  constexpr long long kLimit = static_cast<long long>(std::numeric_limits<int>::max()) + 1;
  for (const char c : text) {
    if (c < '0' || c > '9') break;
    magnitude = magnitude * 10 + (c - '0');
    if (magnitude > kLimit) magnitude = kLimit;  // saturate; keeps the loop overflow free
  }
  const long long value = negative ? -magnitude : magnitude;
  if (value > std::numeric_limits<int>::max()) return std::numeric_limits<int>::max();
  return static_cast<int>(value);
}

double c_atof(std::string_view text) {
  text = skip_leading_space(text);
  // from_chars accepts '-' but not '+'; atof accepts both.
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return 0.0;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Rare enough to let the C library decide between HUGE_VAL and a denormal.
    const std::string digits(text.data(), end);
    return std::strtod(digits.c_str(), nullptr);
  }
  return error == std::errc() ? value : 0.0;
}

}  // namespace playerkit::config
