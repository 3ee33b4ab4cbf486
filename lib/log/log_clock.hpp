#pragma once
// The times to read a log by, when the logged ones cannot be trusted.
//
// Some logs carry no usable clock: Radish's Örebro log stamps every scan 0 and
// its odometry with uninitialised memory (4.85e-86, -2.2, ...); csail's are
// rounded to 10^4 s; the corrected logs stamp one ODOM line per scan 0. A
// LogClock audits the times of a log's timed records (file order) and says
// what to use instead. Pure: callers collect the times (log_clock_reader.hpp
// reads them from a file) and apply the replacements (the readers do, given
// the clock in their options).
//
// A record's time is unusable when it is
//   * not finite, negative, or after 2100-01-01 (4102444800 s);
//   * positive but under 1 microsecond: no logger writes such a time (they
//     print %f or sec.usec), uninitialised memory printed with %g does;
//   * out of order: more than 1 s before or after the log's clock around it
//     (a time going backwards, or a jump the records after it do not follow).
//     The log's clock is the longest non-decreasing run of the remaining
//     times, so one huge value does not condemn every record after it; a
//     record off that run by up to 1 s is kept (four Intel scans are stamped
//     up to 0.9 s before the scan above them, as the laser delivered them).
// Then, for the whole log:
//   * nothing unusable: no replacement, the log is read exactly as before;
//   * the log is degenerate: fewer than 2 usable times, more than half of the
//     records unusable, more than half of the usable times one and the same
//     value (all 0, csail's 10^4 s steps; judged from kMinRecordsToJudge
//     records on), or a rate above kMaxRateHz: every record gets a synthetic
//     clock, record n (0-based, file order) at n / kSyntheticRateHz seconds;
//   * otherwise each unusable time is interpolated, in file order, between
//     the usable times before and after it (held at the first/last usable
//     time at the ends); usable times are kept as logged.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace playerkit::log {

// How many records had each fault (a record counts once, under its first).
struct LogTimeFaults {
  std::size_t not_finite = 0;
  std::size_t negative = 0;
  std::size_t far_future = 0;
  std::size_t below_microsecond = 0;
  std::size_t out_of_order = 0;
  // Degenerate logs only: usable times that share the most common value.
  std::size_t repeated = 0;
  std::optional<double> repeated_value;
  // Degenerate logs only: the usable times' rate when above kMaxRateHz.
  std::optional<double> absurd_rate_hz;

  friend bool operator==(const LogTimeFaults&, const LogTimeFaults&) = default;
};

enum class LogTimeRepair {
  kNone,          // every time usable: read as logged
  kInterpolated,  // the unusable ones interpolated between usable neighbours
  kSynthetic,     // file order with a synthetic clock for every record
};

class LogClock {
 public:
  static constexpr double kSyntheticRateHz = 10.0;
  static constexpr double kBackwardsToleranceS = 1.0;
  static constexpr double kFarFutureS = 4102444800.0;  // 2100-01-01T00:00:00Z
  static constexpr double kMinClockReadingS = 1e-6;
  static constexpr double kMaxRateHz = 1e6;  // a record every microsecond, the finest any log format writes
  static constexpr std::size_t kMinRecordsToJudge = 10;

  // A clock that replaces nothing (a log not audited).
  LogClock() = default;
  // Audits the times of a log's timed records, in file order.
  static LogClock audit(const std::vector<double>& logged_times);

  [[nodiscard]] LogTimeRepair repair() const { return repair_; }
  [[nodiscard]] bool synthetic() const { return repair_ == LogTimeRepair::kSynthetic; }
  [[nodiscard]] std::size_t records() const { return records_; }
  // Records whose time is replaced (all of them when synthetic).
  [[nodiscard]] std::size_t unusable() const { return unusable_; }
  [[nodiscard]] const LogTimeFaults& faults() const { return faults_; }

  // The time to use for the record at `ordinal` (0-based among the timed
  // records, file order), or nullopt to keep the logged one. Ordinals past
  // the audited records (a file that grew) keep theirs, or continue the
  // synthetic clock.
  [[nodiscard]] std::optional<double> replacement(std::size_t ordinal) const;
  // replacement(ordinal), or `logged` when there is none.
  [[nodiscard]] double time_of(std::size_t ordinal, double logged) const {
    return replacement(ordinal).value_or(logged);
  }

  // "N of M timestamps unusable (255 at 0, 60 negative, ...); using file
  // order with a synthetic 10 Hz clock", or "" when nothing is replaced.
  [[nodiscard]] std::string describe() const;

 private:
  LogTimeRepair repair_ = LogTimeRepair::kNone;
  std::size_t records_ = 0;
  std::size_t unusable_ = 0;
  LogTimeFaults faults_;
  // Interpolated: the time of every record (usable ones as logged), and
  // which ones are replacements.
  std::vector<double> times_;
  std::vector<bool> replaced_;
};

}  // namespace playerkit::log
