// LogClock on synthetic time sequences: good logs untouched, each fault
// found and counted, the two repairs (interpolation, synthetic clock).

#include "log/log_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace playerkit::log {
namespace log_clock_test {

// n times from `start`, `step` apart.
std::vector<double> evenly(std::size_t n, double start = 100.0, double step = 0.25) {
  std::vector<double> times;
  for (std::size_t i = 0; i < n; ++i) times.push_back(start + static_cast<double>(i) * step);
  return times;
}

void expect_untouched(const LogClock& clock, std::size_t n) {
  EXPECT_EQ(clock.repair(), LogTimeRepair::kNone);
  EXPECT_EQ(clock.unusable(), 0u);
  EXPECT_EQ(clock.describe(), "");
  for (std::size_t i = 0; i < n + 2; ++i) EXPECT_FALSE(clock.replacement(i)) << i;
}

TEST(LogClockTest, GoodTimesAreUntouched) {
  expect_untouched(LogClock::audit(evenly(50)), 50);
  expect_untouched(LogClock::audit({}), 0);
  expect_untouched(LogClock::audit({5.0}), 1);
  expect_untouched(LogClock::audit({5.0, 5.0}), 2);  // too short to call "all equal"
  // Epoch times, pairs of records stamped alike (an ODOM and its FLASER).
  expect_untouched(LogClock::audit({1134863807.6, 1134863807.6, 1134863807.8, 1134863807.8, 1134863808.0,
                                    1134863808.0, 1134863808.2, 1134863808.2, 1134863808.4, 1134863808.4}),
                   10);
}

TEST(LogClockTest, StepsBackUnderASecondAreKept) {
  // Intel's scans stamped up to 0.9 s before the one above them stay as logged.
  auto times = evenly(40);
  times[10] = times[9] - 0.9;
  times[30] = times[29] - 0.5;
  expect_untouched(LogClock::audit(times), times.size());
}

TEST(LogClockTest, AllEqualGetsTheSyntheticClock) {
  const LogClock clock = LogClock::audit(std::vector<double>(20, 0.0));
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  EXPECT_TRUE(clock.synthetic());
  EXPECT_EQ(clock.unusable(), 20u);
  EXPECT_EQ(clock.faults().repeated, 20u);
  EXPECT_EQ(clock.describe(), "20 of 20 timestamps unusable (all 0); using file order with a synthetic 10 Hz clock");
  EXPECT_DOUBLE_EQ(*clock.replacement(0), 0.0);
  EXPECT_DOUBLE_EQ(*clock.replacement(7), 0.7);
  EXPECT_DOUBLE_EQ(*clock.replacement(25), 2.5);  // records the audit did not see continue the clock

  EXPECT_EQ(LogClock::audit(std::vector<double>(12, 42.5)).describe(),
            "12 of 12 timestamps unusable (all 42.5); using file order with a synthetic 10 Hz clock");
}

TEST(LogClockTest, ABackwardsJumpIsInterpolatedBetweenItsNeighbours) {
  auto times = evenly(100, 0.0, 1.0);
  times[60] = 20.0;
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kInterpolated);
  EXPECT_EQ(clock.unusable(), 1u);
  EXPECT_EQ(clock.faults().out_of_order, 1u);
  ASSERT_TRUE(clock.replacement(60));
  EXPECT_DOUBLE_EQ(*clock.replacement(60), 60.0);
  EXPECT_FALSE(clock.replacement(59));
  EXPECT_FALSE(clock.replacement(61));
  EXPECT_EQ(clock.describe(),
            "1 of 100 timestamps unusable (1 out of order by more than 1 s); each replaced by interpolating, in file "
            "order, between the usable times around it");
}

TEST(LogClockTest, NotFiniteAndNegativeTimesAreInterpolated) {
  auto times = evenly(20, 10.0, 1.0);
  times[4] = std::numeric_limits<double>::quiet_NaN();
  times[5] = std::numeric_limits<double>::infinity();
  times[12] = -3.0;
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kInterpolated);
  EXPECT_EQ(clock.faults().not_finite, 2u);
  EXPECT_EQ(clock.faults().negative, 1u);
  EXPECT_DOUBLE_EQ(*clock.replacement(4), 14.0);
  EXPECT_DOUBLE_EQ(*clock.replacement(5), 15.0);
  EXPECT_DOUBLE_EQ(*clock.replacement(12), 22.0);
  EXPECT_EQ(clock.describe().substr(0, 50), "3 of 20 timestamps unusable (2 not finite, 1 negat");
}

TEST(LogClockTest, AHugeValueDoesNotCondemnTheRecordsAfterIt) {
  auto times = evenly(30, 1000.0, 0.5);
  times[3] = 1e300;         // past 2100
  times[8] = 2000000000.0;  // a plausible epoch time, but the log is at 1000 s
  times[0] = 3e-86;         // uninitialised memory near 0
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kInterpolated);
  EXPECT_EQ(clock.faults().far_future, 1u);
  EXPECT_EQ(clock.faults().out_of_order, 1u);
  EXPECT_EQ(clock.faults().below_microsecond, 1u);
  EXPECT_EQ(clock.unusable(), 3u);
  EXPECT_DOUBLE_EQ(*clock.replacement(3), 1001.5);
  EXPECT_DOUBLE_EQ(*clock.replacement(8), 1004.0);
  EXPECT_DOUBLE_EQ(*clock.replacement(0), 1000.5);  // before the first usable time: held at it
  EXPECT_FALSE(clock.replacement(9));
}

TEST(LogClockTest, TheCorrectedLogsZeroTimeLinesAreInterpolated) {
  // Freiburg 079: each scan's pair, then an ODOM stamped 0.
  std::vector<double> times;
  for (int i = 0; i < 20; ++i) {
    times.insert(times.end(), {10.0 + i, 10.0 + i, 0.0});
  }
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kInterpolated);
  EXPECT_EQ(clock.unusable(), 20u);
  EXPECT_EQ(clock.faults().out_of_order, 20u);
  EXPECT_DOUBLE_EQ(*clock.replacement(2), 10.5);
  EXPECT_DOUBLE_EQ(*clock.replacement(59), 29.0);  // after the last usable time: held at it
}

TEST(LogClockTest, GarbageLikeOrebrosGetsTheSyntheticClock) {
  // Scans at 0, odometry from uninitialised memory.
  const std::vector<double> odometry{0, 6.979, 1.961, 3.44e-86, 1.3e-76, 4.4e-38, 0, 4.65e-86, 1.58e-153,
                                     1.8e-153, 4.4e-38, 4.6e-72, 4.747, 5.927, -0.0588, -2.219, 0.0806, -0.0594};
  std::vector<double> times;
  for (double t : odometry) times.insert(times.end(), {t, 0.0});
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  EXPECT_EQ(clock.unusable(), times.size());
  EXPECT_EQ(clock.faults().negative, 3u);
  EXPECT_EQ(clock.faults().below_microsecond, 8u);
  EXPECT_GE(clock.faults().repeated, 20u);
  EXPECT_EQ(clock.faults().repeated_value, 0.0);
  EXPECT_NE(clock.describe().find("using file order with a synthetic 10 Hz clock"), std::string::npos);
  EXPECT_DOUBLE_EQ(*clock.replacement(35), 3.5);
}

TEST(LogClockTest, TimesRoundedToOneValueGetTheSyntheticClock) {
  // csail: 6 significant digits of an epoch time, and a 0 per scan.
  std::vector<double> times;
  for (int i = 0; i < 30; ++i) times.insert(times.end(), {1.13486e9, 1.13486e9, i < 25 ? 1.13486e9 : 1.13487e9, 0.0});
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  EXPECT_EQ(clock.faults().repeated, 85u);
  EXPECT_GE(clock.faults().out_of_order, 29u);  // the zeros (but one that may start the run) and stray 1.13487e9s
}

TEST(LogClockTest, MostlyUnusableGetsTheSyntheticClock) {
  auto times = evenly(10, 5.0, 1.0);
  for (std::size_t i = 0; i < 6; ++i) times[i] = -1.0;
  const LogClock clock = LogClock::audit(times);
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  EXPECT_EQ(clock.faults().negative, 6u);
}

TEST(LogClockTest, AnAbsurdRateGetsTheSyntheticClock) {
  const LogClock clock = LogClock::audit(evenly(20, 1.0, 1e-9));
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  ASSERT_TRUE(clock.faults().absurd_rate_hz);
  EXPECT_GT(*clock.faults().absurd_rate_hz, LogClock::kMaxRateHz);
  EXPECT_NE(clock.describe().find("a rate of"), std::string::npos);
}

TEST(LogClockTest, ASingleBadRecordGetsTheSyntheticClock) {
  const LogClock clock = LogClock::audit({std::numeric_limits<double>::quiet_NaN()});
  EXPECT_EQ(clock.repair(), LogTimeRepair::kSynthetic);
  EXPECT_DOUBLE_EQ(*clock.replacement(0), 0.0);
}

}  // namespace log_clock_test
}  // namespace playerkit::log
