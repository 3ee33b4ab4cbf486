#include "core/clock.hpp"

#include <gtest/gtest.h>

#include <ctime>

namespace playerkit::core {
namespace clock_test {

TEST(ClockTest, MicrosecondConversionsRoundTrip) {
  EXPECT_EQ(to_microseconds({3, 250'000}), 3'250'000u);
  EXPECT_EQ(from_microseconds(3'250'000u), (Timestamp{3, 250'000}));
}

TEST(ClockTest, ManualClockMovesOnlyWhenTold) {
  ManualClock clock({10, 999'999});
  EXPECT_EQ(clock.now(), (Timestamp{10, 999'999}));
  clock.advance_microseconds(2);
  EXPECT_EQ(clock.now(), (Timestamp{11, 1}));
  clock.set({0, 0});
  EXPECT_EQ(clock.now(), (Timestamp{0, 0}));
}

TEST(ClockTest, WallClockIsUnixTime) {
  const auto before = static_cast<std::uint32_t>(std::time(nullptr));
  const Timestamp now = WallClock().now();
  EXPECT_GE(now.sec, before);
  EXPECT_LE(now.sec, before + 2);
  EXPECT_LT(now.usec, 1'000'000u);
}

}  // namespace clock_test
}  // namespace playerkit::core
