#include "links/port_diagnosis.hpp"

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>
#include <tuple>

namespace playerkit::links {

namespace {

namespace fs = std::filesystem;

// Unix98 pseudo-terminal slaves (/dev/pts/N) have no sysfs entry.
constexpr unsigned kFirstPtySlaveMajor = 136;
constexpr unsigned kLastPtySlaveMajor = 143;
constexpr std::size_t kMostPortsListed = 8;

std::string_view strip_trailing_digits(std::string_view name) {
  while (!name.empty() && name.back() >= '0' && name.back() <= '9') name.remove_suffix(1);
  return name;
}

// ttyUSB2 before ttyUSB10.
auto natural_key(const std::string& path) {
  const std::string_view stem = strip_trailing_digits(path);
  const std::string_view digits = std::string_view(path).substr(stem.size());
  return std::make_tuple(std::string(stem), digits.size(), std::string(digits));
}

void add_entries(const fs::path& directory, std::string_view prefix, std::set<std::string>& found) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(prefix)) found.insert(entry.path().string());
  }
}

std::string list_of(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size() && i < kMostPortsListed; ++i) {
    if (i > 0) text += ", ";
    text += items[i];
  }
  if (items.size() > kMostPortsListed) text += " and " + std::to_string(items.size() - kMostPortsListed) + " more";
  return text;
}

std::string missing_text(const std::string& path, const std::vector<std::string>& similar, bool node_exists) {
  std::string text = node_exists ? path + " exists but no device answers behind it; is the adapter plugged in "
                                          "and its driver loaded?"
                                 : "no such port " + path + "; is the adapter plugged in?";
  if (similar.empty()) return text + " No similar ports exist here.";
  return text + " Similar ports here: " + list_of(similar) + ".";
}

std::string group_name(gid_t gid) {
  std::vector<char> buffer(4096);
  group entry{};
  group* result = nullptr;
  if (::getgrgid_r(gid, &entry, buffer.data(), buffer.size(), &result) == 0 && result != nullptr) {
    return result->gr_name;
  }
  return std::to_string(gid);
}

DeviceAccess access_of(const struct stat& device) {
  DeviceAccess access;
  access.mode = device.st_mode & 07777;
  access.type = S_ISCHR(device.st_mode)    ? 'c'
                : S_ISDIR(device.st_mode)  ? 'd'
                : S_ISBLK(device.st_mode)  ? 'b'
                : S_ISFIFO(device.st_mode) ? 'p'
                : S_ISSOCK(device.st_mode) ? 's'
                                           : '-';
  access.group = group_name(device.st_gid);
  std::vector<char> buffer(4096);
  passwd user{};
  passwd* user_found = nullptr;
  gid_t primary_group = static_cast<gid_t>(-1);
  if (::getpwuid_r(::geteuid(), &user, buffer.data(), buffer.size(), &user_found) == 0 && user_found != nullptr) {
    access.user = user_found->pw_name;
    primary_group = user_found->pw_gid;
  } else {
    access.user = std::to_string(::geteuid());
  }
  access.user_listed_in_group = primary_group == device.st_gid;
  std::vector<char> group_buffer(16384);
  group entry{};
  group* group_found = nullptr;
  if (::getgrgid_r(device.st_gid, &entry, group_buffer.data(), group_buffer.size(), &group_found) == 0 &&
      group_found != nullptr) {
    for (char** member = group_found->gr_mem; *member != nullptr; ++member) {
      if (access.user == *member) access.user_listed_in_group = true;
    }
  }
  access.process_has_group = ::getegid() == device.st_gid;
  const int count = ::getgroups(0, nullptr);
  if (count > 0) {
    std::vector<gid_t> groups(static_cast<std::size_t>(count));
    const int filled = ::getgroups(count, groups.data());
    for (int i = 0; i < filled; ++i) {
      if (groups[static_cast<std::size_t>(i)] == device.st_gid) access.process_has_group = true;
    }
  }
  return access;
}

bool is_terminal_device(dev_t device) {
  const unsigned major_number = major(device);
  if (major_number >= kFirstPtySlaveMajor && major_number <= kLastPtySlaveMajor) return true;
  const fs::path sysfs =
      "/sys/dev/char/" + std::to_string(major_number) + ":" + std::to_string(minor(device)) + "/subsystem";
  std::error_code error;
  const fs::path subsystem = fs::read_symlink(sysfs, error);
  // Without sysfs we cannot tell; opening will.
  if (error) return true;
  return subsystem.filename() == "tty";
}

std::string file_kind(mode_t mode) {
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISBLK(mode)) return "a block device";
  return "not a device";
}

std::string busy_text(const std::string& path, const std::vector<PortHolder>& holders) {
  if (holders.empty()) {
    return path + " is busy: another process holds it (one we cannot inspect, perhaps another user's); stop it or "
                  "pick another port";
  }
  return path + " is busy: held by " + to_string(holders) + "; stop it or pick another port";
}

}  // namespace

std::vector<std::string> similar_ports(const std::string& path) {
  const fs::path given(path);
  fs::path directory = given.parent_path();
  if (directory.empty()) directory = ".";
  const std::string name = given.filename().string();
  std::set<std::string> found;
  const std::string_view stem = strip_trailing_digits(name);
  if (!stem.empty()) add_entries(directory, stem, found);
  if (directory.lexically_normal() == "/dev") {
    add_entries("/dev", "ttyUSB", found);
    add_entries("/dev", "ttyACM", found);
    add_entries("/dev/serial/by-id", "", found);
  }
  found.erase(path);
  std::vector<std::string> ports(found.begin(), found.end());
  std::sort(ports.begin(), ports.end(),
            [](const std::string& a, const std::string& b) { return natural_key(a) < natural_key(b); });
  return ports;
}

std::string mode_text(unsigned mode, char type) {
  std::string text(1, type);
  const char letters[] = {'r', 'w', 'x'};
  for (int bit = 8; bit >= 0; --bit) text += (mode & (1u << bit)) != 0 ? letters[(8 - bit) % 3] : '-';
  return text;
}

std::string permission_advice(const std::string& path, const DeviceAccess& access) {
  const std::string mode = mode_text(access.mode, access.type);
  const bool group_may_use = (access.mode & 060) == 060 && access.group != "root";
  if (!group_may_use) {
    const std::string name = fs::path(path).filename().string();
    return path + " may be opened read/write only by its owner (" + mode + ", group " + access.group +
           "): run as that user, or give it to a group with a udev rule such as KERNEL==\"" + name +
           "\", GROUP=\"dialout\", MODE=\"0660\"";
  }
  if (access.process_has_group) {
    return path + " belongs to group " + access.group + " (" + mode + ") and this process is in it, yet access is " +
           "denied: look for an ACL, a security module (AppArmor, SELinux) or a read-only mount";
  }
  if (access.user_listed_in_group) {
    return path + " belongs to group " + access.group + " (" + mode + "); " + access.user + " is in " +
           access.group + " but this session started before joining: log out and back in, or run `newgrp " +
           access.group + "`";
  }
  return path + " belongs to group " + access.group + " (" + mode + "), which " + access.user +
         " is not in: join it with `sudo usermod -aG " + access.group + " " + access.user +
         "`, then log out and back in";
}

PortDiagnosis describe_open_problem(const std::string& path) {
  PortDiagnosis diagnosis;
  diagnosis.path = path;
  struct stat device {};
  if (::stat(path.c_str(), &device) != 0) {
    const int error_number = errno;
    diagnosis.similar = similar_ports(path);
    if (error_number == ENOENT || error_number == ENOTDIR) {
      diagnosis.problem = LinkErrorKind::missing;
      struct stat link {};
      diagnosis.summary = missing_text(path, diagnosis.similar, false);
      if (::lstat(path.c_str(), &link) == 0) {
        std::error_code ignored;
        diagnosis.summary += " (" + path + " is a symlink to " + fs::read_symlink(path, ignored).string() +
                             ", which does not exist)";
      }
    } else if (error_number == EACCES) {
      diagnosis.problem = LinkErrorKind::permission_denied;
      diagnosis.summary = "cannot look at " + path + ": a directory on its path denies access";
    } else {
      diagnosis.problem = LinkErrorKind::io_error;
      diagnosis.summary = "cannot look at " + path + ": " + std::strerror(error_number);
    }
    return diagnosis;
  }
  diagnosis.exists = true;
  diagnosis.character_device = S_ISCHR(device.st_mode);
  diagnosis.terminal_device = diagnosis.character_device && is_terminal_device(device.st_rdev);
  diagnosis.readable = ::faccessat(AT_FDCWD, path.c_str(), R_OK, AT_EACCESS) == 0;
  diagnosis.writable = ::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) == 0;
  diagnosis.access = access_of(device);
  diagnosis.holders = find_port_holders(path);
  const bool locked = std::any_of(diagnosis.holders.begin(), diagnosis.holders.end(),
                                  [](const PortHolder& holder) { return holder.holds_lock; });
  if (!diagnosis.character_device) {
    diagnosis.problem = LinkErrorKind::not_a_terminal;
    diagnosis.summary = path + " is " + file_kind(device.st_mode) + ", not a serial port";
  } else if (!diagnosis.terminal_device) {
    diagnosis.problem = LinkErrorKind::not_a_terminal;
    diagnosis.summary = path + " is a character device but not a terminal, so not a serial port";
  } else if (!diagnosis.readable || !diagnosis.writable) {
    diagnosis.problem = LinkErrorKind::permission_denied;
    diagnosis.summary = "permission denied: " + permission_advice(path, *diagnosis.access);
  } else if (locked) {
    diagnosis.problem = LinkErrorKind::busy;
    diagnosis.summary = busy_text(path, diagnosis.holders);
  } else {
    diagnosis.summary = path + " looks usable: a terminal device we may read and write";
    if (!diagnosis.holders.empty()) diagnosis.summary += "; already open in " + to_string(diagnosis.holders);
  }
  return diagnosis;
}

std::string to_string(const PortDiagnosis& diagnosis) {
  const auto yes_no = [](bool value) { return value ? "yes" : "no"; };
  std::string text = diagnosis.summary + "\n";
  text += "  exists: " + std::string(yes_no(diagnosis.exists)) + "\n";
  if (!diagnosis.exists) {
    if (!diagnosis.similar.empty()) text += "  similar ports: " + list_of(diagnosis.similar) + "\n";
    return text;
  }
  text += "  character device: " + std::string(yes_no(diagnosis.character_device)) + "\n";
  text += "  terminal: " + std::string(yes_no(diagnosis.terminal_device)) + "\n";
  text += "  readable: " + std::string(yes_no(diagnosis.readable)) + ", writable: " + yes_no(diagnosis.writable);
  if (diagnosis.access) {
    text += " (" + mode_text(diagnosis.access->mode, diagnosis.access->type) + ", group " + diagnosis.access->group + ", we are " +
            diagnosis.access->user + ")";
  }
  text += "\n  held by: " + (diagnosis.holders.empty() ? std::string("nobody we can see") : to_string(diagnosis.holders)) +
          "\n";
  return text;
}

LinkError open_failure(const std::string& path, int error_number) {
  switch (error_number) {
    case ENOENT:
    case ENOTDIR:
      return LinkError(LinkErrorKind::missing, path, missing_text(path, similar_ports(path), false));
    case ENXIO:
    case ENODEV:
      return LinkError(LinkErrorKind::missing, path, missing_text(path, similar_ports(path), true));
    case EACCES:
    case EPERM:
    case EROFS: {
      struct stat device {};
      if (::stat(path.c_str(), &device) != 0) {
        return LinkError(LinkErrorKind::permission_denied, path,
                         "permission denied opening " + path + ": a directory on its path denies access");
      }
      return LinkError(LinkErrorKind::permission_denied, path,
                       "permission denied opening " + path + ": " + permission_advice(path, access_of(device)));
    }
    case EBUSY:
      return busy_failure(path);
    case EISDIR:
      return LinkError(LinkErrorKind::not_a_terminal, path, path + " is a directory, not a serial port");
    default:
      return system_error(path, "cannot open", error_number);
  }
}

LinkError busy_failure(const std::string& path) {
  return LinkError(LinkErrorKind::busy, path, busy_text(path, find_port_holders(path)));
}

}  // namespace playerkit::links
