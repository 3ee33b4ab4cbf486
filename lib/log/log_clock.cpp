#include "log/log_clock.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>

namespace playerkit::log {
namespace {

// Counts the fault a single value has on its own; true when it has one.
bool count_value_fault(double time, LogTimeFaults& faults) {
  if (!std::isfinite(time)) {
    ++faults.not_finite;
  } else if (time < 0) {
    ++faults.negative;
  } else if (time > LogClock::kFarFutureS) {
    ++faults.far_future;
  } else if (time > 0 && time < LogClock::kMinClockReadingS) {
    ++faults.below_microsecond;
  } else {
    return false;
  }
  return true;
}

// Which of `candidates` (indices into `times`, ascending) make up the longest
// non-decreasing run of their times (patience sorting, O(n log n)).
std::vector<bool> longest_non_decreasing(const std::vector<double>& times, const std::vector<std::size_t>& candidates) {
  std::vector<double> tail_times;        // smallest last time of a run of each length
  std::vector<std::size_t> tail_at;      // the candidate that ends it
  std::vector<std::ptrdiff_t> previous(candidates.size(), -1);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const double time = times[candidates[k]];
    const auto length = static_cast<std::size_t>(
        std::upper_bound(tail_times.begin(), tail_times.end(), time) - tail_times.begin());
    if (length > 0) previous[k] = static_cast<std::ptrdiff_t>(tail_at[length - 1]);
    if (length == tail_times.size()) {
      tail_times.push_back(time);
      tail_at.push_back(k);
    } else {
      tail_times[length] = time;
      tail_at[length] = k;
    }
  }
  std::vector<bool> on_run(times.size(), false);
  if (tail_at.empty()) return on_run;
  for (auto k = static_cast<std::ptrdiff_t>(tail_at.back()); k >= 0; k = previous[static_cast<std::size_t>(k)]) {
    on_run[candidates[static_cast<std::size_t>(k)]] = true;
  }
  return on_run;
}

// Marks candidates more than the tolerance off the run around them.
void mark_out_of_order(const std::vector<double>& times, const std::vector<bool>& on_run, std::vector<bool>& usable,
                       LogTimeFaults& faults) {
  const std::size_t n = times.size();
  std::vector<std::optional<double>> next_on_run(n);
  std::optional<double> next;
  for (std::size_t i = n; i-- > 0;) {
    next_on_run[i] = next;
    if (on_run[i]) next = times[i];
  }
  std::optional<double> previous;
  for (std::size_t i = 0; i < n; ++i) {
    if (on_run[i]) {
      previous = times[i];
      continue;
    }
    if (!usable[i]) continue;
    const bool too_early = previous && times[i] < *previous - LogClock::kBackwardsToleranceS;
    const bool too_late = next_on_run[i] && times[i] > *next_on_run[i] + LogClock::kBackwardsToleranceS;
    if (too_early || too_late) {
      usable[i] = false;
      ++faults.out_of_order;
    }
  }
}

struct MostCommon {
  std::size_t count = 0;
  double value = 0;
};

MostCommon most_common(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  MostCommon best;
  for (std::size_t first = 0; first < values.size();) {
    std::size_t last = first;
    while (last < values.size() && values[last] == values[first]) ++last;
    if (last - first > best.count) best = {last - first, values[first]};
    first = last;
  }
  return best;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace

LogClock LogClock::audit(const std::vector<double>& logged_times) {
  LogClock clock;
  const std::size_t n = logged_times.size();
  clock.records_ = n;
  std::vector<bool> usable(n, true);
  std::vector<std::size_t> candidates;
  candidates.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (count_value_fault(logged_times[i], clock.faults_)) {
      usable[i] = false;
    } else {
      candidates.push_back(i);
    }
  }
  mark_out_of_order(logged_times, longest_non_decreasing(logged_times, candidates), usable, clock.faults_);

  std::vector<double> usable_times;
  usable_times.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (usable[i]) usable_times.push_back(logged_times[i]);
  }
  const std::size_t bad = n - usable_times.size();
  if (bad == 0 && n < kMinRecordsToJudge) return clock;

  const MostCommon common = most_common(usable_times);
  const bool repeated = n >= kMinRecordsToJudge && common.count * 2 > usable_times.size();
  std::optional<double> absurd_rate;
  if (usable_times.size() >= 2) {
    const auto [lowest, highest] = std::minmax_element(usable_times.begin(), usable_times.end());
    const double span = *highest - *lowest;
    const double rate = static_cast<double>(usable_times.size() - 1) / span;
    if (span > 0 && rate > kMaxRateHz) absurd_rate = rate;
  }
  if (usable_times.size() < 2 || bad * 2 > n || repeated || absurd_rate) {
    clock.repair_ = LogTimeRepair::kSynthetic;
    clock.unusable_ = n;
    if (repeated) {
      clock.faults_.repeated = common.count;
      clock.faults_.repeated_value = common.value;
    }
    clock.faults_.absurd_rate_hz = absurd_rate;
    return clock;
  }
  if (bad == 0) return clock;

  clock.repair_ = LogTimeRepair::kInterpolated;
  clock.unusable_ = bad;
  clock.times_ = logged_times;
  clock.replaced_.assign(n, false);
  std::vector<std::optional<std::size_t>> next_usable(n);
  std::optional<std::size_t> next;
  for (std::size_t i = n; i-- > 0;) {
    next_usable[i] = next;
    if (usable[i]) next = i;
  }
  std::optional<std::size_t> previous;
  for (std::size_t i = 0; i < n; ++i) {
    if (usable[i]) {
      previous = i;
      continue;
    }
    clock.replaced_[i] = true;
    const auto after = next_usable[i];
    if (previous && after) {
      const double fraction = static_cast<double>(i - *previous) / static_cast<double>(*after - *previous);
      clock.times_[i] = logged_times[*previous] + fraction * (logged_times[*after] - logged_times[*previous]);
    } else {
      clock.times_[i] = logged_times[previous ? *previous : *after];  // held at the ends
    }
  }
  return clock;
}

std::optional<double> LogClock::replacement(std::size_t ordinal) const {
  switch (repair_) {
    case LogTimeRepair::kNone:
      return std::nullopt;
    case LogTimeRepair::kSynthetic:
      return static_cast<double>(ordinal) / kSyntheticRateHz;
    case LogTimeRepair::kInterpolated:
      if (ordinal < replaced_.size() && replaced_[ordinal]) return times_[ordinal];
      return std::nullopt;
  }
  return std::nullopt;
}

std::string LogClock::describe() const {
  if (repair_ == LogTimeRepair::kNone) return "";
  std::vector<std::string> reasons;
  const auto add = [&](std::size_t count, const std::string& what) {
    if (count > 0) reasons.push_back(std::to_string(count) + " " + what);
  };
  if (faults_.repeated_value) {
    if (faults_.repeated == records_) {
      reasons.push_back(*faults_.repeated_value == 0 ? "all 0" : "all " + number_text(*faults_.repeated_value));
    } else {
      add(faults_.repeated, "at " + number_text(*faults_.repeated_value));
    }
  }
  add(faults_.not_finite, "not finite");
  add(faults_.negative, "negative");
  add(faults_.far_future, "after the year 2100");
  add(faults_.below_microsecond, "below 1 us");
  add(faults_.out_of_order, "out of order by more than 1 s");
  if (faults_.absurd_rate_hz) reasons.push_back("a rate of " + number_text(*faults_.absurd_rate_hz) + " Hz");
  std::string text = std::to_string(unusable_) + " of " + std::to_string(records_) + " timestamps unusable (";
  for (std::size_t i = 0; i < reasons.size(); ++i) text += (i > 0 ? ", " : "") + reasons[i];
  text += "); ";
  if (repair_ == LogTimeRepair::kSynthetic) {
    text += "using file order with a synthetic " + number_text(kSyntheticRateHz) + " Hz clock";
  } else {
    text += "each replaced by interpolating, in file order, between the usable times around it";
  }
  return text;
}

}  // namespace playerkit::log
