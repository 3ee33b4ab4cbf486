#pragma once
// The pace of a replay: readlog waits on one of these between log lines, so
// that tests can hold the replay at any point (a manual timer) while the
// server uses real time (SteadyReplayTimer).

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stop_token>

namespace playerkit::drivers {

class ReplayTimer {
 public:
  virtual ~ReplayTimer() = default;
  // Time since a fixed start; never goes back.
  [[nodiscard]] virtual std::chrono::nanoseconds now() const = 0;
  // Returns true once now() >= deadline, false as soon as stop is requested.
  virtual bool wait_until(std::chrono::nanoseconds deadline, const std::stop_token& stop) = 0;
};

// std::chrono::steady_clock, immune to wall-clock jumps.
class SteadyReplayTimer final : public ReplayTimer {
 public:
  [[nodiscard]] std::chrono::nanoseconds now() const override;
  bool wait_until(std::chrono::nanoseconds deadline, const std::stop_token& stop) override;

 private:
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable_any wakeup_;  // only ever woken by a stop request
};

}  // namespace playerkit::drivers
