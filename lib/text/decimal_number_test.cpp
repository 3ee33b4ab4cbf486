#include "text/decimal_number.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>

namespace playerkit::text {
namespace decimal_number_test {

// Ours against std::from_chars: the same value bit for bit, the same end,
// the same error, and an untouched value on error.
void expect_as_from_chars(const std::string& text, std::chars_format format = std::chars_format::general) {
  constexpr double kUntouched = 12345.678;
  double ours = kUntouched, theirs = kUntouched;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto a = decimal_from_chars(first, last, ours, format);
  const auto b = std::from_chars(first, last, theirs, format);
  EXPECT_EQ(a.ec, b.ec) << '"' << text << '"';
  EXPECT_EQ(a.ptr - first, b.ptr - first) << '"' << text << '"';
  EXPECT_EQ(std::bit_cast<std::uint64_t>(ours), std::bit_cast<std::uint64_t>(theirs)) << '"' << text << '"';
}

TEST(DecimalFromChars, AgreesWithFromCharsOnHandPickedText) {
  for (const char* text :
       {"0", "-0", "0.0", "-0.000", "8.53", "-0.0412", "5.", ".5", "-.5", ".", "-", "", "+1", "1.2.3", "1e5",
        "1E-3", "2.5e", "1e+", "0x10", "inf", "-nan", "abc", "12abc", "9007199254740992", "9007199254740993",
        "9007199254740993.0", "0.1", "0.2", "0.3", "123456789012345678", "1234567890123456789",
        "0.0000000000000000000001", "0.00000000000000000000001", "1.7976931348623157", "4.9406564584124654",
        "00000000000000000000000001.5", "3.14159265358979323846", "1 2", "1,5"}) {
    expect_as_from_chars(text);
    expect_as_from_chars(text, std::chars_format::fixed);
    expect_as_from_chars(text, std::chars_format::scientific);
  }
}

TEST(DecimalFromChars, AgreesWithFromCharsOnRandomDecimals) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> length(1, 24), digit(0, 9), coin(0, 3), garbage(0, 30);
  for (int trial = 0; trial < 200000; ++trial) {
    std::string text;
    if (coin(random) == 0) text += '-';
    const int n = length(random);
    std::uniform_int_distribution<int> point_at(-1, n);
    const int point = point_at(random);
    for (int i = 0; i < n; ++i) {
      if (i == point) text += '.';
      text += static_cast<char>('0' + digit(random));
    }
    if (point == n) text += '.';
    if (garbage(random) == 0) text += "e-7";
    if (garbage(random) == 0) text += 'x';
    expect_as_from_chars(text);
  }
}

}  // namespace decimal_number_test
}  // namespace playerkit::text
