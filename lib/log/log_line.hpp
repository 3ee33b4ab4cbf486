#pragma once
// One line of a log, read with text::read_line's cap (text::kMaxLineBytes). A
// line over the cap is not kept: the reader gets `too_long` and reports it
// like any malformed line, as too_long_line_error() says, quoting none of it.
//
//   bool too_long = false;
//   while (read_log_line(in, text, too_long)) {
//     ++number;
//     try {
//       if (too_long) throw too_long_line_error(file, number);
//       ... parse text ...
//     } catch (const LogParseError& error) { ... }
//   }

#include <istream>
#include <string>

#include "log/log_parse_error.hpp"

namespace playerkit::log {

// std::getline with the cap: false at the end of the stream. A line over the
// cap sets too_long (and `line` to its start); the next call reads the line
// after it.
bool read_log_line(std::istream& in, std::string& line, bool& too_long);

// "file:line:1048577: line longer than 1048576 bytes": the column is the
// first byte over the cap.
LogParseError too_long_line_error(const std::string& file, int line);

}  // namespace playerkit::log
