#include "client/typed/power.hpp"

#include <gtest/gtest.h>

namespace playerkit::client {
namespace power_test {

TEST(TypedPower, DecivoltsToVolts) {
  EXPECT_DOUBLE_EQ(to_si(protocol::PowerData{125}).volts, 12.5);
  EXPECT_DOUBLE_EQ(to_si(protocol::PowerData{131}).volts, 13.1);
  EXPECT_DOUBLE_EQ(to_si(protocol::PowerData{0}).volts, 0.0);
}

}  // namespace power_test
}  // namespace playerkit::client
