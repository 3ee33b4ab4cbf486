#include "config/errors.hpp"

#include <utility>

namespace playerkit::config {

ConfigError::ConfigError(SourceLocation where, std::string message)
    : std::runtime_error(to_string(where) + ": " + message),
      where_(std::move(where)),
      message_(std::move(message)) {}

}  // namespace playerkit::config
