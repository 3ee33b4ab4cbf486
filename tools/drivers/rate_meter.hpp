#pragma once
// How regularly a device publishes, for `run --stats`: messages per second,
// the shortest and longest gap between two, and the jitter (the standard
// deviation of the gaps). Pure: the caller supplies the times and locks.

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace playerkit::player_drivers {

using StatsClock = std::chrono::steady_clock;

struct RateSummary {
  std::size_t messages = 0;       // in the window
  std::size_t total = 0;          // since the meter was made
  double seconds = 0.0;           // the window's length
  double rate_hz = 0.0;           // messages / seconds
  // Gaps ending in the window (the first one may start in the previous window).
  std::size_t intervals = 0;
  double min_interval_s = 0.0;
  double max_interval_s = 0.0;
  double jitter_s = 0.0;          // standard deviation of the gaps
};

class RateMeter {
 public:
  explicit RateMeter(StatsClock::time_point start) : window_start_(start) {}

  void record(StatsClock::time_point when);
  // The window from the previous take() (or the start) to `now`; starts the next one.
  RateSummary take(StatsClock::time_point now);

 private:
  StatsClock::time_point window_start_;
  std::optional<StatsClock::time_point> last_;
  std::vector<double> gaps_;
  std::size_t messages_ = 0;
  std::size_t total_ = 0;
};

// "5.0 Hz (10 in 2.0 s), interval 198.0-202.1 ms, jitter 1.1 ms", "no data (2 in all)".
std::string to_string(const RateSummary& summary);

}  // namespace playerkit::player_drivers
