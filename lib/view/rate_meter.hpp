#pragma once
// A device's message rate over the last few seconds, on the caller's clock
// (seconds as doubles), so tests feed it times instead of sleeping.

#include <cstddef>
#include <deque>
#include <string>

namespace playerkit::view {

class RateMeter {
 public:
  explicit RateMeter(double window_seconds = 5.0) : window_(window_seconds) {}

  void record(double now);
  // Messages per second over the window ending at `now`: 0 until two
  // messages arrived, and 0 again once none came for a whole window (a
  // device gone silent must not keep showing its old rate).
  [[nodiscard]] double rate(double now) const;
  [[nodiscard]] std::size_t total() const { return total_; }

 private:
  void forget_before(double time);

  double window_;
  std::deque<double> times_;
  std::size_t total_ = 0;
};

// "5.0 Hz"
std::string format_rate(double hz);

}  // namespace playerkit::view
