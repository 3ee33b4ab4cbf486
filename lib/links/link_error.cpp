#include "links/link_error.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

namespace playerkit::links {

std::string_view to_string(LinkErrorKind kind) {
  switch (kind) {
    case LinkErrorKind::bad_address: return "bad address";
    case LinkErrorKind::bad_settings: return "bad settings";
    case LinkErrorKind::missing: return "missing";
    case LinkErrorKind::permission_denied: return "permission denied";
    case LinkErrorKind::busy: return "busy";
    case LinkErrorKind::not_a_terminal: return "not a terminal";
    case LinkErrorKind::connect_failed: return "connect failed";
    case LinkErrorKind::disconnected: return "disconnected";
    case LinkErrorKind::timed_out: return "timed out";
    case LinkErrorKind::closed: return "closed";
    case LinkErrorKind::io_error: return "i/o error";
  }
  return "unknown";
}

LinkError::LinkError(LinkErrorKind kind, std::string port, const std::string& message)
    : std::runtime_error(message), kind_(kind), port_(std::move(port)) {}

LinkError system_error(std::string_view port, std::string_view what, int error_number) {
  // EIO is what a tty returns once its hardware is gone (USB adapter pulled,
  // pty master closed); the others are a TCP peer resetting or vanishing.
  const bool gone = error_number == EIO || error_number == ENXIO || error_number == ENODEV ||
                    error_number == ECONNRESET || error_number == EPIPE ||
                    error_number == ETIMEDOUT || error_number == EHOSTUNREACH ||
                    error_number == ENETUNREACH || error_number == ECONNABORTED;
  std::string message = std::string(port) + ": " + std::string(what) + ": " + std::strerror(error_number);
  return LinkError(gone ? LinkErrorKind::disconnected : LinkErrorKind::io_error, std::string(port), message);
}

}  // namespace playerkit::links
