#include "links/fd_io.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <string>

#include "links/link_error.hpp"

namespace playerkit::links {

UniqueFd& UniqueFd::operator=(UniqueFd&& other) noexcept {
  if (this != &other) reset(other.release());
  return *this;
}

int UniqueFd::release() noexcept {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void UniqueFd::reset(int fd) noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
}

short wait_for_fd(int fd, short events, Deadline deadline) {
  pollfd entry{.fd = fd, .events = events, .revents = 0};
  while (true) {
    const auto remaining = deadline - LinkClock::now();
    timespec timeout{};
    if (remaining > LinkClock::duration::zero()) {
      const auto nanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(remaining).count();
      timeout.tv_sec = static_cast<time_t>(nanoseconds / 1'000'000'000);
      timeout.tv_nsec = static_cast<long>(nanoseconds % 1'000'000'000);
    }
    const int ready = ::ppoll(&entry, 1, &timeout, nullptr);
    if (ready > 0) return entry.revents;
    if (ready == 0) return 0;
    if (errno != EINTR) return POLLERR;  // let the following read or write report it
  }
}

std::size_t read_with_deadline(int fd, std::span<std::uint8_t> buffer, Deadline deadline, std::string_view port,
                               std::string_view end_of_file_meaning) {
  if (buffer.empty()) return 0;
  // A descriptor that polls ready yet reads EAGAIN must not spin past the
  // deadline: one more try after it, then give up.
  bool last_try = false;
  while (true) {
    const ssize_t count = ::read(fd, buffer.data(), buffer.size());
    if (count > 0) return static_cast<std::size_t>(count);
    if (count == 0) {
      throw LinkError(LinkErrorKind::disconnected, std::string(port),
                      std::string(port) + ": " + std::string(end_of_file_meaning));
    }
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) throw system_error(port, "read failed", errno);
    if (last_try) return 0;
    last_try = LinkClock::now() >= deadline;
    if (wait_for_fd(fd, POLLIN, deadline) == 0) return 0;
  }
}

std::size_t write_with_deadline(int fd, std::span<const std::uint8_t> bytes, Deadline deadline,
                                std::string_view port, bool is_socket) {
  std::size_t written = 0;
  bool last_try = false;
  while (written < bytes.size()) {
    const auto rest = bytes.subspan(written);
    const ssize_t count = is_socket ? ::send(fd, rest.data(), rest.size(), MSG_NOSIGNAL)
                                    : ::write(fd, rest.data(), rest.size());
    if (count > 0) {
      written += static_cast<std::size_t>(count);
      continue;
    }
    if (count < 0 && errno == EINTR) continue;
    if (count < 0 && errno != EAGAIN && errno != EWOULDBLOCK) throw system_error(port, "write failed", errno);
    if (last_try) break;
    last_try = LinkClock::now() >= deadline;
    if (wait_for_fd(fd, POLLOUT, deadline) == 0) break;
  }
  return written;
}

}  // namespace playerkit::links
