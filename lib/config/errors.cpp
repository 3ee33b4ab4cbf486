#include "config/errors.hpp"

#include <utility>

#include "text/printable.hpp"

namespace playerkit::config {

ConfigError::ConfigError(SourceLocation where, std::string message)
    : std::runtime_error(text::printable(to_string(where) + ": " + message)),
      where_(std::move(where)),
      message_(text::printable(message)) {}

}  // namespace playerkit::config
