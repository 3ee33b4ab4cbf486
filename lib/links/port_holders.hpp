#pragma once
// Who has a device open, found the way `fuser` and `lslocks` do: /proc/locks
// for flock() holders and /proc/*/fd for open descriptors. Only processes we
// may inspect are seen (all of them as root, our own otherwise).

#include <string>
#include <vector>

namespace playerkit::links {

struct PortHolder {
  int pid = 0;
  std::string command;     // /proc/PID/comm, "" when unreadable
  bool holds_lock = false; // flock() on the device (what a playerkit link takes)

  friend bool operator==(const PortHolder&, const PortHolder&) = default;
};

// Processes that hold `device` (a path; symlinks are followed), by pid.
// Empty when it does not exist or nobody visible holds it.
std::vector<PortHolder> find_port_holders(const std::string& device);

// "pid 1234 (player-serve, holds the lock), pid 99 (minicom)"
std::string to_string(const std::vector<PortHolder>& holders);

}  // namespace playerkit::links
