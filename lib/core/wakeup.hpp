#pragma once
// Tells a driver's thread that work has arrived for it (a command, a
// request, a device added, a stop), so that the thread can sleep on its
// link until the link has bytes, the work arrives or its next timer is due,
// instead of waking every few milliseconds to look (which cost the p2os
// thread most of its command latency and its idle CPU).
//
//   core::Wakeup wakeup;
//   device.set_wakeup(...);                      // commands and requests notify it
//   const auto woke = wakeup.wait(next_timer, link.native_handle());
//   if (woke.readable) read_telegrams();
//   serve_commands_and_requests();               // after the wait: nothing is lost
//
// An eventfd, so one poll(2) covers it and the link. A notify() between two
// wait()s is remembered: the next wait() returns at once.

#include <chrono>

namespace playerkit::core {

class Wakeup {
 public:
  using Clock = std::chrono::steady_clock;

  // Throws std::system_error when the kernel refuses an eventfd.
  Wakeup();
  ~Wakeup();
  Wakeup(const Wakeup&) = delete;
  Wakeup& operator=(const Wakeup&) = delete;

  // From any thread; never blocks.
  void notify() noexcept;

  struct Woken {
    bool notified = false;  // notify() was called since the last wait
    bool readable = false;  // the other fd has input, hung up or failed
  };
  // Waits until notify(), `other_fd` becomes readable (ignored when < 0) or
  // `deadline` passes (both false then); a deadline in the past only looks.
  // Consumes the notification.
  Woken wait(Clock::time_point deadline, int other_fd = -1);

  [[nodiscard]] int native_handle() const { return fd_; }

 private:
  int fd_ = -1;
};

}  // namespace playerkit::core
