#include "view/rate_meter.hpp"

#include <cstdio>

namespace playerkit::view {

void RateMeter::record(double now) {
  times_.push_back(now);
  ++total_;
  forget_before(now - window_);
}

void RateMeter::forget_before(double time) {
  while (!times_.empty() && times_.front() < time) times_.pop_front();
}

double RateMeter::rate(double now) const {
  std::size_t first = 0;
  while (first < times_.size() && times_[first] < now - window_) ++first;
  const std::size_t count = times_.size() - first;
  if (count < 2) return 0.0;
  // Intervals between the messages, not messages per window: a device that
  // just started shows its real rate at once.
  const double span = times_.back() - times_[first];
  if (span <= 0.0) return 0.0;
  return static_cast<double>(count - 1) / span;
}

std::string format_rate(double hz) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f Hz", hz);
  return text;
}

}  // namespace playerkit::view
