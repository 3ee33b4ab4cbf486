#include "log/log_parse_error.hpp"

#include <utility>

#include "text/printable.hpp"

namespace playerkit::log {

LogParseError::LogParseError(std::string file, int line, int column, std::string message)
    : std::runtime_error(text::printable(file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                         ": " + message)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(text::printable(message)) {}

}  // namespace playerkit::log
