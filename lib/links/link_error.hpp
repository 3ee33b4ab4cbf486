#pragma once
// The one exception type of lib/links. Every message names the port it is
// about ("/dev/ttyUSB0: ...", "tcp:robot:4001: ...") and says what to do,
// because it usually ends up verbatim in a driver's log line.

#include <stdexcept>
#include <string>
#include <string_view>

namespace playerkit::links {

enum class LinkErrorKind {
  bad_address,        // a `port` value that is neither a tty path nor tcp:HOST:PORT
  bad_settings,       // baud, data bits, parity or stop bits invalid, or refused by the port
  missing,            // no such device (file absent, or the adapter behind it unplugged)
  permission_denied,  // the device exists but we may not open it read/write
  busy,               // another process (or another link of ours) holds the port
  not_a_terminal,     // the path exists but is not a serial port
  connect_failed,     // TCP: name unknown, refused, unreachable or timed out
  disconnected,       // the device or peer went away while the link was open
  timed_out,          // a write could not finish by its deadline
  closed,             // the link was used after close()
  io_error,           // anything else the system reported
};

std::string_view to_string(LinkErrorKind kind);

class LinkError : public std::runtime_error {
 public:
  // `message` is complete on its own (it names the port); what() returns it.
  LinkError(LinkErrorKind kind, std::string port, const std::string& message);

  [[nodiscard]] LinkErrorKind kind() const { return kind_; }
  // The port as the user wrote it: "/dev/ttyUSB0", "tcp:127.0.0.1:4001".
  [[nodiscard]] const std::string& port() const { return port_; }

 private:
  LinkErrorKind kind_;
  std::string port_;
};

// "<port>: <what>: <strerror(error_number)>" as an io_error, or as
// `disconnected` for the errno values that mean the other end went away.
LinkError system_error(std::string_view port, std::string_view what, int error_number);

}  // namespace playerkit::links
