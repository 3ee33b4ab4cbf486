#include "drivers/logfile/replay_timer.hpp"

namespace playerkit::drivers {

std::chrono::nanoseconds SteadyReplayTimer::now() const {
  return std::chrono::steady_clock::now() - start_;
}

bool SteadyReplayTimer::wait_until(std::chrono::nanoseconds deadline, const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  // The predicate is only true on stop, so this returns at the deadline or on stop.
  wakeup_.wait_until(lock, stop, start_ + deadline, [] { return false; });
  return !stop.stop_requested();
}

}  // namespace playerkit::drivers
