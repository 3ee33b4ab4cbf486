#include "sim/worldfile/worldfile_error.hpp"

#include <utility>

#include "text/printable.hpp"

namespace playerkit::sim::worldfile {

std::string located(const SourceLocation& where, const std::string& message) {
  return text::printable(to_string(where) + ": " + message);
}

WorldFileError::WorldFileError(SourceLocation where, std::string message)
    : std::runtime_error(located(where, message)),
      where_(std::move(where)),
      message_(text::printable(message)) {}

}  // namespace playerkit::sim::worldfile
