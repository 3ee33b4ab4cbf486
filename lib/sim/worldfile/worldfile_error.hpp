#pragma once
// The one exception of the world-file reader. what() is the compiler-style
// "file:line:col: message", printable as is (input quoted in it is escaped).

#include <stdexcept>
#include <string>

#include "sim/worldfile/worldfile_location.hpp"

namespace playerkit::sim::worldfile {

class WorldFileError : public std::runtime_error {
 public:
  WorldFileError(SourceLocation where, std::string message);

  [[nodiscard]] const SourceLocation& where() const { return where_; }
  // The message without the location.
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// "file:line:col: message", escaped: the form of errors and of warnings.
std::string located(const SourceLocation& where, const std::string& message);

}  // namespace playerkit::sim::worldfile
