#pragma once
// std::from_chars for double, with a quicker way for the numbers logs are
// made of. A CARMEN or Player log is mostly short plain decimals ("8.53",
// "-0.0412"); for those the value is the whole number of their digits
// divided by a power of ten, and when both are exact in a double (at most
// 2^53, and 10^22) one division rounds it correctly, so the result is bit
// for bit what from_chars gives. Anything else (exponents, long digit
// strings, "inf", garbage) goes to std::from_chars itself.
//
//   double value;
//   const auto parsed = text::decimal_from_chars(field.data(), field.data() + field.size(), value);
//   if (parsed.ec != std::errc{} || parsed.ptr != field.data() + field.size()) reject(field);

#include <charconv>

namespace playerkit::text {

// The contract of std::from_chars(first, last, value, format).
std::from_chars_result decimal_from_chars(const char* first, const char* last, double& value,
                                          std::chars_format format = std::chars_format::general);

}  // namespace playerkit::text
