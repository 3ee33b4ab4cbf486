#pragma once
// The error of a text log line that cannot be read. Its what() is the
// compiler-style "file:line:col: message", so a tool can print it as is.

#include <stdexcept>
#include <string>

namespace playerkit::log {

class LogParseError : public std::runtime_error {
 public:
  // line and column are 1-based; column counts bytes from the start of the line.
  LogParseError(std::string file, int line, int column, std::string message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  // The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string message_;
};

}  // namespace playerkit::log
