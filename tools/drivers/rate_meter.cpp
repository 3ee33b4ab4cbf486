#include "rate_meter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace playerkit::player_drivers {

void RateMeter::record(StatsClock::time_point when) {
  if (last_) gaps_.push_back(std::chrono::duration<double>(when - *last_).count());
  last_ = when;
  ++messages_;
  ++total_;
}

RateSummary RateMeter::take(StatsClock::time_point now) {
  RateSummary summary;
  summary.messages = messages_;
  summary.total = total_;
  summary.seconds = std::max(0.0, std::chrono::duration<double>(now - window_start_).count());
  summary.rate_hz = summary.seconds > 0.0 ? static_cast<double>(messages_) / summary.seconds : 0.0;
  summary.intervals = gaps_.size();
  if (!gaps_.empty()) {
    const auto [shortest, longest] = std::minmax_element(gaps_.begin(), gaps_.end());
    summary.min_interval_s = *shortest;
    summary.max_interval_s = *longest;
    const double mean = std::accumulate(gaps_.begin(), gaps_.end(), 0.0) / static_cast<double>(gaps_.size());
    double squares = 0.0;
    for (const double gap : gaps_) squares += (gap - mean) * (gap - mean);
    summary.jitter_s = std::sqrt(squares / static_cast<double>(gaps_.size()));
  }
  window_start_ = now;
  messages_ = 0;
  gaps_.clear();
  return summary;
}

std::string to_string(const RateSummary& summary) {
  char text[160];
  if (summary.messages == 0) {
    std::snprintf(text, sizeof text, "no data (%zu in all)", summary.total);
    return text;
  }
  std::snprintf(text, sizeof text, "%.1f Hz (%zu in %.1f s)", summary.rate_hz, summary.messages, summary.seconds);
  std::string line = text;
  if (summary.intervals > 0) {
    std::snprintf(text, sizeof text, ", interval %.1f-%.1f ms, jitter %.1f ms", summary.min_interval_s * 1e3,
                  summary.max_interval_s * 1e3, summary.jitter_s * 1e3);
    line += text;
  }
  return line;
}

}  // namespace playerkit::player_drivers
