#include "core/wakeup.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <system_error>

namespace playerkit::core {

Wakeup::Wakeup() : fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "eventfd");
}

Wakeup::~Wakeup() { ::close(fd_); }

void Wakeup::notify() noexcept {
  const std::uint64_t one = 1;
  // EAGAIN only when the counter is at its maximum: it is notified anyway.
  while (::write(fd_, &one, sizeof one) < 0 && errno == EINTR) {
  }
}

Wakeup::Woken Wakeup::wait(Clock::time_point deadline, int other_fd) {
  pollfd watched[2] = {{fd_, POLLIN, 0}, {other_fd, POLLIN, 0}};
  const nfds_t count = other_fd >= 0 ? 2 : 1;
  for (;;) {
    const auto left = std::max(deadline - Clock::now(), Clock::duration::zero());
    const auto whole = std::chrono::duration_cast<std::chrono::seconds>(left);
    const timespec timeout{static_cast<time_t>(whole.count()),
                           static_cast<long>(std::chrono::nanoseconds(left - whole).count())};
    const int ready = ::ppoll(watched, count, &timeout, nullptr);
    if (ready >= 0) break;
    if (errno != EINTR) {
      // A poll that cannot wait (out of memory for its table) must not
      // turn the caller's loop into a spin: say the link wants looking at,
      // whose read reports the real trouble.
      return {.notified = true, .readable = count == 2};
    }
  }
  Woken woken;
  if (watched[0].revents != 0) {
    std::uint64_t value = 0;
    while (::read(fd_, &value, sizeof value) < 0 && errno == EINTR) {
    }
    woken.notified = true;
  }
  woken.readable = count == 2 && watched[1].revents != 0;
  return woken;
}

}  // namespace playerkit::core
