#pragma once
// The C conversions 1.5 applied to property values (server-behaviour.md §9.3),
// so that "12abc" still reads as 12 and "abc" as 0. Locale independent.

#include <string_view>

namespace playerkit::config {

// atoi: optional leading whitespace and sign, then as many digits as there are;
// 0 when there are none. Out-of-range values saturate instead of being undefined.
int c_atoi(std::string_view text);

// atof: optional leading whitespace, then the longest prefix that reads as a
// decimal floating-point number ("1e-3", ".5", "-2.", "inf"); 0 when there is
// none. Hexadecimal floats ("0x1p3") are not recognised.
double c_atof(std::string_view text);

}  // namespace playerkit::config
