#pragma once
// Waiting on and moving bytes through one POSIX file descriptor with a
// deadline: poll (never a sleep loop), EINTR retried, errors turned into
// LinkErrors naming the port. Shared by the serial, TCP and pty code.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "links/deadline.hpp"

namespace playerkit::links {

// Owns a file descriptor; closes it once.
class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept;
  ~UniqueFd() { reset(); }

  [[nodiscard]] int get() const { return fd_; }
  [[nodiscard]] bool valid() const { return fd_ >= 0; }
  int release() noexcept;
  void reset(int fd = -1) noexcept;

 private:
  int fd_ = -1;
};

// Waits until `fd` reports one of `events` (POLLIN, POLLOUT), an error or a
// hang-up, or until the deadline; a deadline in the past checks once without
// waiting. Returns the revents seen, 0 on timeout.
short wait_for_fd(int fd, short events, Deadline deadline);

// Waits for input, then one read(). Returns the count read (>= 1 for a
// non-empty buffer), 0 when the deadline passed first. End of file throws
// LinkError(disconnected) with "<port>: <end_of_file_meaning>".
std::size_t read_with_deadline(int fd, std::span<std::uint8_t> buffer, Deadline deadline, std::string_view port,
                               std::string_view end_of_file_meaning);

// Writes as much as the deadline allows; returns the count written (less
// than bytes.size() only when the deadline passed). Sockets are written with
// MSG_NOSIGNAL so a vanished peer is an error, not a SIGPIPE.
std::size_t write_with_deadline(int fd, std::span<const std::uint8_t> bytes, Deadline deadline,
                                std::string_view port, bool is_socket);

}  // namespace playerkit::links
