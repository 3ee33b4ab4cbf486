#pragma once
// One CARMEN log line into a record (carmen_log.hpp); the line-level half of
// CarmenLogReader.
//
//   auto line = log::parse_carmen_line(text, "intel.log", 42);
//   if (auto* laser = std::get_if<log::CarmenLaser>(&line.record)) ...
//
// Numbers are strict (CARMEN's atof read "abc" as 0; here it is an error naming
// the field) and may be written in exponent form ("1.13486e+09", as some Radish
// logs have them). Counts must match the fields that follow.

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "log/carmen_log.hpp"
#include "log/log_parse_error.hpp"

namespace playerkit::log {

// A blank line or a comment (first character '#': CARMEN's header lines, and
// flirtlib's "#SEQUENTIAL" markers).
struct CarmenBlankLine {};

// A line whose first word names no record this reader knows (NEFF, VERTEX2,
// EDGE2, SYNC, GLOBALPOS, ...).
struct CarmenUnknownLine {
  std::string keyword;
};

using CarmenLine = std::variant<CarmenBlankLine, CarmenUnknownLine, CarmenRecord>;

// The keywords parse_carmen_line reads: PARAM ODOM TRUEPOS and the laser ones.
bool is_carmen_record_keyword(std::string_view keyword);

// Parses one line (a trailing "\n" or "\r\n" is allowed). `file` and
// `line_number` only go into errors. Throws LogParseError ("file:line:col:
// message") when a known record is malformed.
CarmenLine parse_carmen_line(std::string_view text, std::string_view file, int line_number);

}  // namespace playerkit::log
