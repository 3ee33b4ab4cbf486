#include "links/port_holders.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

namespace playerkit::links {

namespace {

namespace fs = std::filesystem;

std::optional<int> parse_pid(std::string_view text) {
  int pid = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), pid);
  if (error != std::errc() || end != text.data() + text.size() || pid <= 0) return std::nullopt;
  return pid;
}

std::string command_of(int pid) {
  std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
  std::string command;
  std::getline(comm, command);
  return command;
}

// /proc/locks: "1: FLOCK  ADVISORY  WRITE 1234 00:05:3 0 EOF", the device
// field being major:minor (hex) of the file system and the inode (decimal).
// Waiters appear as "1: -> FLOCK ..." and hold nothing.
void add_lock_holders(const struct stat& target, std::map<int, PortHolder>& holders) {
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string index, type, advisory, mode, pid_text, device;
    fields >> index >> type;
    if (type == "->") continue;
    fields >> advisory >> mode >> pid_text >> device;
    const auto pid = parse_pid(pid_text);
    if (!pid) continue;
    unsigned major_number = 0, minor_number = 0;
    unsigned long long inode = 0;
    if (std::sscanf(device.c_str(), "%x:%x:%llu", &major_number, &minor_number, &inode) != 3) continue;
    if (major_number != major(target.st_dev) || minor_number != minor(target.st_dev) || inode != target.st_ino) {
      continue;
    }
    auto& holder = holders[*pid];
    holder.pid = *pid;
    holder.holds_lock = true;
  }
}

bool same_file(const struct stat& a, const struct stat& b) {
  if (S_ISCHR(a.st_mode) && S_ISCHR(b.st_mode)) return a.st_rdev == b.st_rdev;
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

void add_open_holders(const struct stat& target, std::map<int, PortHolder>& holders) {
  std::error_code error;
  for (const auto& process : fs::directory_iterator("/proc", error)) {
    const auto pid = parse_pid(process.path().filename().native());
    if (!pid) continue;
    std::error_code fd_error;
    for (const auto& descriptor : fs::directory_iterator(process.path() / "fd", fd_error)) {
      struct stat opened {};
      if (::stat(descriptor.path().c_str(), &opened) != 0 || !same_file(opened, target)) continue;
      holders[*pid].pid = *pid;
      break;
    }
  }
}

}  // namespace

std::vector<PortHolder> find_port_holders(const std::string& device) {
  struct stat target {};
  if (::stat(device.c_str(), &target) != 0) return {};
  std::map<int, PortHolder> holders;
  add_lock_holders(target, holders);
  add_open_holders(target, holders);
  std::vector<PortHolder> found;
  for (auto& [pid, holder] : holders) {
    holder.command = command_of(pid);
    found.push_back(std::move(holder));
  }
  return found;
}

std::string to_string(const std::vector<PortHolder>& holders) {
  std::string text;
  for (const auto& holder : holders) {
    if (!text.empty()) text += ", ";
    text += "pid " + std::to_string(holder.pid);
    std::string detail = holder.command;
    if (holder.holds_lock) detail += detail.empty() ? "holds the lock" : ", holds the lock";
    if (!detail.empty()) text += " (" + detail + ")";
  }
  return text;
}

}  // namespace playerkit::links
