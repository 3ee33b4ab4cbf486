#include "log/log_line.hpp"

#include "text/line_reader.hpp"

namespace playerkit::log {

bool read_log_line(std::istream& in, std::string& line, bool& too_long) {
  too_long = false;
  try {
    return text::read_line(in, line, "", 0);
  } catch (const text::LineTooLongError&) {
    too_long = true;
    return true;
  }
}

LogParseError too_long_line_error(const std::string& file, int line) {
  return LogParseError(file, line, static_cast<int>(text::kMaxLineBytes) + 1,
                       "line longer than " + std::to_string(text::kMaxLineBytes) + " bytes");
}

}  // namespace playerkit::log
