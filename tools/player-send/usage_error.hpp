#pragma once

#include <stdexcept>

namespace playerkit::player_send {

// Bad arguments or input lines: exit 2, the message says what and what is allowed.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace playerkit::player_send
