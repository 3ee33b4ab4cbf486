#include "links/serial_link.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

#include "links/link_error.hpp"
#include "links/port_diagnosis.hpp"

namespace playerkit::links {

std::unique_ptr<SerialLink> SerialLink::open(const std::string& path, const SerialSettings& settings) {
  validate(settings, path);
  std::unique_ptr<SerialLink> link(new SerialLink(path, settings));
  link->open_device();
  return link;
}

SerialLink::SerialLink(std::string path, const SerialSettings& settings)
    : path_(std::move(path)), settings_(settings) {}

SerialLink::~SerialLink() { close(); }

void SerialLink::open_device() {
  // Non-blocking: open() must not wait for a carrier, and every read and
  // write below waits in poll() with a deadline instead.
  UniqueFd fd(::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd.valid()) throw open_failure(path_, errno);
  struct stat device {};
  if (::fstat(fd.get(), &device) != 0) throw system_error(path_, "cannot stat", errno);
  if (!S_ISCHR(device.st_mode) || ::isatty(fd.get()) == 0) {
    throw LinkError(LinkErrorKind::not_a_terminal, path_,
                    path_ + " is not a serial port (not a terminal device); give the tty path, e.g. /dev/ttyUSB0");
  }
  if (settings_.exclusive) {
    if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
      const int error_number = errno;
      fd.reset();  // so the holders listed are the others, not this descriptor
      if (error_number == EWOULDBLOCK) throw busy_failure(path_);
      throw system_error(path_, "cannot lock", error_number);
    }
    // Keeps out programs that do not flock (minicom, Player 1.5). Root is
    // exempt, which is why the lock above comes first.
    (void)::ioctl(fd.get(), TIOCEXCL);
  }
  try {
    configure_terminal(fd.get(), settings_, path_);
  } catch (...) {
    if (settings_.exclusive) (void)::ioctl(fd.get(), TIOCNXCL);
    throw;
  }
  if (settings_.flush_on_open) (void)::tcflush(fd.get(), TCIOFLUSH);
  fd_ = std::move(fd);
}

int SerialLink::checked_fd() const {
  if (!fd_.valid()) throw LinkError(LinkErrorKind::closed, path_, path_ + " is closed");
  return fd_.get();
}

std::size_t SerialLink::read_available(std::span<std::uint8_t> buffer, Deadline deadline) {
  return read_with_deadline(checked_fd(), buffer, deadline, path_, "the device hung up (unplugged?)");
}

std::size_t SerialLink::write_available(std::span<const std::uint8_t> bytes, Deadline deadline) {
  return write_with_deadline(checked_fd(), bytes, deadline, path_, false);
}

void SerialLink::flush_input() {
  if (::tcflush(checked_fd(), TCIFLUSH) != 0) throw system_error(path_, "flushing input failed", errno);
}

void SerialLink::drain() {
  while (::tcdrain(checked_fd()) != 0) {
    if (errno != EINTR) throw system_error(path_, "draining output failed", errno);
  }
}

void SerialLink::close() noexcept {
  if (!fd_.valid()) return;
  // A pty's exclusive flag outlives our descriptor (the tty lives as long as
  // its master), so it must be cleared by hand or the next opener is refused.
  if (settings_.exclusive) (void)::ioctl(fd_.get(), TIOCNXCL);
  fd_.reset();
}

void SerialLink::reopen(Deadline /*deadline*/) {
  close();
  open_device();
  counters().reconnects.add();
}

bool SerialLink::set_baud(int baud) {
  set_terminal_speed(checked_fd(), baud, path_);
  settings_.baud = baud;
  return true;
}

std::string SerialLink::describe() const { return path_ + " at " + to_string(settings_); }

TerminalLine SerialLink::line() const { return read_terminal_line(checked_fd(), path_); }

bool SerialLink::set_modem_lines(bool dtr, bool rts) {
  int lines = 0;
  if (::ioctl(checked_fd(), TIOCMGET, &lines) != 0) return false;
  lines = dtr ? (lines | TIOCM_DTR) : (lines & ~TIOCM_DTR);
  lines = rts ? (lines | TIOCM_RTS) : (lines & ~TIOCM_RTS);
  return ::ioctl(fd_.get(), TIOCMSET, &lines) == 0;
}

}  // namespace playerkit::links
