#pragma once
// For the tests: byte strings written as the sheets print them, "02 80 03 00".

#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace playerkit::hardware::sick::testing {

inline std::vector<std::uint8_t> bytes(std::string_view hex_text) {
  std::vector<std::uint8_t> out;
  int high = -1;
  for (const char c : hex_text) {
    if (c == ' ') continue;
    int digit = -1;
    if (c >= '0' && c <= '9') digit = c - '0';
    if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
    if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
    if (digit < 0) throw std::invalid_argument("not a hex digit in test bytes");
    if (high < 0) {
      high = digit;
    } else {
      out.push_back(static_cast<std::uint8_t>(high * 16 + digit));
      high = -1;
    }
  }
  if (high >= 0) throw std::invalid_argument("odd number of hex digits in test bytes");
  return out;
}

}  // namespace playerkit::hardware::sick::testing
