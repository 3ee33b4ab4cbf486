#pragma once
// The exit statuses of every playerkit tool and of the daemon, one table
// (each tool's --help says which it uses), and the error that maps to
// "usage".
//
//   0  done
//   1  the work itself failed: unreadable input, cannot write, cannot connect,
//      the server or a device failed
//   2  the command line or the configuration was wrong; nothing was done
//   3  player-send: the device refused the request (NACK)
//   4  player-send: the server answered ERR, or could not open the device for it

#include <stdexcept>

namespace playerkit::tools {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitNack = 3;
inline constexpr int kExitError = 4;

// Thrown for bad flags or arguments; the tool prints its message and exits
// with kExitUsage.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace playerkit::tools
