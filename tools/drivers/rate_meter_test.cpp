#include "rate_meter.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace playerkit::player_drivers {
namespace rate_meter_test {

using namespace std::chrono_literals;

TEST(RateMeter, RateIntervalsAndJitterOfAWindow) {
  const StatsClock::time_point start{};
  RateMeter meter(start);
  // Gaps of 100, 200 and 300 ms: mean 200, standard deviation sqrt(20000/3) ms.
  meter.record(start + 100ms);
  meter.record(start + 200ms);
  meter.record(start + 400ms);
  meter.record(start + 700ms);
  const RateSummary summary = meter.take(start + 1s);
  EXPECT_EQ(summary.messages, 4u);
  EXPECT_EQ(summary.total, 4u);
  EXPECT_DOUBLE_EQ(summary.seconds, 1.0);
  EXPECT_DOUBLE_EQ(summary.rate_hz, 4.0);
  EXPECT_EQ(summary.intervals, 3u);
  EXPECT_NEAR(summary.min_interval_s, 0.1, 1e-12);
  EXPECT_NEAR(summary.max_interval_s, 0.3, 1e-12);
  EXPECT_NEAR(summary.jitter_s, std::sqrt(0.02 / 3.0), 1e-12);
  EXPECT_EQ(to_string(summary), "4.0 Hz (4 in 1.0 s), interval 100.0-300.0 ms, jitter 81.6 ms");
}

TEST(RateMeter, TheNextWindowCountsTheGapFromTheLastMessageBefore) {
  const StatsClock::time_point start{};
  RateMeter meter(start);
  meter.record(start + 900ms);
  EXPECT_EQ(to_string(meter.take(start + 1s)), "1.0 Hz (1 in 1.0 s)");
  meter.record(start + 1100ms);
  const RateSummary second = meter.take(start + 2s);
  EXPECT_EQ(second.messages, 1u);
  EXPECT_EQ(second.total, 2u);
  EXPECT_EQ(second.intervals, 1u);
  EXPECT_NEAR(second.min_interval_s, 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(second.jitter_s, 0.0);
}

TEST(RateMeter, NoData) {
  const StatsClock::time_point start{};
  RateMeter meter(start);
  EXPECT_EQ(to_string(meter.take(start + 1s)), "no data (0 in all)");
  meter.record(start + 1500ms);
  meter.take(start + 2s);
  EXPECT_EQ(to_string(meter.take(start + 3s)), "no data (1 in all)");
}

}  // namespace rate_meter_test
}  // namespace playerkit::player_drivers
