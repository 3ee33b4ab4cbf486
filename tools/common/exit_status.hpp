#pragma once
// The exit statuses every playerkit tool documents in its --help, and the
// error that maps to "usage". A tool with more ways to fail (player-send)
// adds its own codes above these.

#include <stdexcept>

namespace playerkit::tools {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the work itself failed: unreadable input, cannot write, server problems
inline constexpr int kExitUsage = 2;    // the command line was wrong; nothing was done

// Thrown for bad flags or arguments; the tool prints its message and exits
// with kExitUsage.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace playerkit::tools
