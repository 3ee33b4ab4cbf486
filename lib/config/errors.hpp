#pragma once
// The one exception type of the config layer. Its what() is the compiler-style
// "file:line:col: message" so a caller can print it as is.

#include <stdexcept>
#include <string>

#include "config/source_location.hpp"

namespace playerkit::config {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(SourceLocation where, std::string message);

  const SourceLocation& where() const { return where_; }
  // The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace playerkit::config
