#pragma once
// Why a serial port would not open, in words a user can act on. SerialLink
// builds its open errors from these, and `player-drivers probe` calls
// describe_open_problem() before opening anything (it never opens the
// device: opening a port raises DTR, which resets some boards).

#include <optional>
#include <string>
#include <vector>

#include "links/link_error.hpp"
#include "links/port_holders.hpp"

namespace playerkit::links {

// Other ports a user may have meant: entries beside `path` with the same
// name stem (ttyUSB0 -> ttyUSB1, ttyUSB2), and for /dev also the USB serial
// adapters (ttyUSB*, ttyACM*) and /dev/serial/by-id/*. Sorted, numbers in
// numeric order, `path` itself excluded.
std::vector<std::string> similar_ports(const std::string& path);

// What decides whether we may open a device read/write.
struct DeviceAccess {
  std::string user;                 // our effective user name
  std::string group;                // the group owning the device
  unsigned mode = 0;                // permission bits (07777)
  char type = 'c';                  // as ls shows it: 'c' character device, '-' file, 'd' directory
  bool user_listed_in_group = false;  // in /etc/group (or primary group)
  bool process_has_group = false;     // in this process's groups right now
};

// The advice for a permission problem on `path`: which group to join and
// how, or that this session predates joining, or that only root may open it.
std::string permission_advice(const std::string& path, const DeviceAccess& access);

// "crw-rw----" for a character device with mode 0660.
std::string mode_text(unsigned mode, char type = 'c');

struct PortDiagnosis {
  std::string path;
  bool exists = false;
  bool character_device = false;
  bool terminal_device = false;  // a character device of the tty class (or a pty)
  bool readable = false;         // by us, as the kernel would check at open
  bool writable = false;
  std::optional<DeviceAccess> access;  // when it exists
  std::vector<PortHolder> holders;
  std::vector<std::string> similar;  // when it is missing
  // What opening it would most likely fail with; nullopt: it looks fine.
  std::optional<LinkErrorKind> problem;
  std::string summary;  // one or two sentences, naming the port
};

PortDiagnosis describe_open_problem(const std::string& path);

// Multi-line report: the summary, then what was checked.
std::string to_string(const PortDiagnosis& diagnosis);

// The error for an open() of `path` that failed with `error_number`:
// missing (with similar ports), permission_denied (with advice), busy (with
// holders) or io_error.
LinkError open_failure(const std::string& path, int error_number);

// The error for a port someone else holds (flock refused, or EBUSY).
LinkError busy_failure(const std::string& path);

}  // namespace playerkit::links
