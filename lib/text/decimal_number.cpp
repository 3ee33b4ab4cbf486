#include "text/decimal_number.hpp"

#include <array>
#include <cstdint>

namespace playerkit::text {
namespace {

constexpr std::uint64_t kExactMantissa = std::uint64_t{1} << 53;
constexpr int kExactPowers = 22;  // 10^22 is the largest power of ten a double holds exactly

constexpr std::array<double, kExactPowers + 1> kPowersOfTen = [] {
  std::array<double, kExactPowers + 1> powers{};
  double power = 1.0;
  for (double& p : powers) {
    p = power;
    power *= 10.0;
  }
  return powers;
}();

}  // namespace

std::from_chars_result decimal_from_chars(const char* first, const char* last, double& value,
                                          std::chars_format format) {
  const char* p = first;
  const bool negative = p != last && *p == '-';
  if (negative) ++p;
  std::uint64_t mantissa = 0;
  int digits = 0, fraction_digits = 0;
  bool point = false;
  for (; p != last; ++p) {
    const char c = *p;
    if (c >= '0' && c <= '9') {
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
      ++digits;
      if (point) ++fraction_digits;
      // 19 digits cannot overflow 64 bits; past 2^53 the quick way is inexact.
      if (digits > 18 || mantissa > kExactMantissa) return std::from_chars(first, last, value, format);
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  // An exponent, or no digit at all: the general way decides.
  const bool exponent_follows = p != last && (*p == 'e' || *p == 'E');
  if (digits == 0 || fraction_digits > kExactPowers || exponent_follows ||
      format == std::chars_format::scientific || format == std::chars_format::hex) {
    return std::from_chars(first, last, value, format);
  }
  const double magnitude = static_cast<double>(mantissa) / kPowersOfTen[static_cast<std::size_t>(fraction_digits)];
  value = negative ? -magnitude : magnitude;
  return {p, std::errc{}};
}

}  // namespace playerkit::text
