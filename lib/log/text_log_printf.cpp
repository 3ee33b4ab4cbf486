#include "log/text_log_printf.hpp"

#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace playerkit::log {

void append_printf(std::string& out, const char* pattern, ...) {
  char buffer[128];
  std::va_list args;
  va_start(args, pattern);
  const int length = std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  if (length < 0) throw std::runtime_error("text log: cannot format a field");
  if (static_cast<std::size_t>(length) < sizeof buffer) {
    out.append(buffer, static_cast<std::size_t>(length));
    return;
  }
  // Only a huge number gets here; format again with room for it.
  std::string wide(static_cast<std::size_t>(length) + 1, '\0');
  va_start(args, pattern);
  std::vsnprintf(wide.data(), wide.size(), pattern, args);
  va_end(args);
  wide.resize(static_cast<std::size_t>(length));
  out += wide;
}

}  // namespace playerkit::log
