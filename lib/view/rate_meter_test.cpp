#include "view/rate_meter.hpp"

#include <gtest/gtest.h>

namespace playerkit::view {
namespace rate_meter_test {

TEST(RateMeter, MeasuresTheIntervalsBetweenMessages) {
  RateMeter meter;
  EXPECT_EQ(meter.rate(0.0), 0.0);
  for (int i = 0; i < 11; ++i) meter.record(10.0 + 0.2 * i);
  EXPECT_NEAR(meter.rate(12.0), 5.0, 1e-9);
  EXPECT_EQ(meter.total(), 11u);
}

TEST(RateMeter, ShowsZeroForADeviceGoneSilent) {
  RateMeter meter(5.0);
  meter.record(1.0);
  meter.record(1.1);
  EXPECT_NEAR(meter.rate(2.0), 10.0, 1e-9);
  EXPECT_EQ(meter.rate(7.0), 0.0);
}

TEST(RateMeter, FormatsWithOneDecimal) {
  EXPECT_EQ(format_rate(5.0), "5.0 Hz");
  EXPECT_EQ(format_rate(0.04), "0.0 Hz");
  EXPECT_EQ(format_rate(12.345), "12.3 Hz");
}

}  // namespace rate_meter_test
}  // namespace playerkit::view
