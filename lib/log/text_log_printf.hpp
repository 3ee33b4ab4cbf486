#pragma once
// printf into a string (internal to the text log writer), so every field keeps
// the exact pattern writelog used; the attribute keeps the compiler checking
// each pattern against its arguments.

#include <string>

namespace playerkit::log {

__attribute__((format(printf, 2, 3))) void append_printf(std::string& out, const char* pattern, ...);

}  // namespace playerkit::log
