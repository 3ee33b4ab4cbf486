// Golden bytes are written from wire-format.md §5 "ptz" by hand.
#include "interfaces/ptz_limits.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "interfaces/wire_units.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {
namespace ptz_limits_test {

// Stage 1.3's head: pan ±100°, tilt fixed, field of view 5°..60°.
const PtzLimits kStageHead{radians(-100), radians(100), 0.0, 0.0, radians(5), radians(60)};

protocol::PtzCommand command(std::int16_t pan, std::int16_t tilt, std::int16_t zoom) {
  protocol::PtzCommand c;
  c.pan = pan;
  c.tilt = tilt;
  c.zoom = zoom;
  return c;
}

TEST(PtzLimits, ACommandWithinReachIsTakenInRadians) {
  const PtzPose target = ptz_target(command(30, 0, 40), kStageHead);
  EXPECT_DOUBLE_EQ(target.pan, radians(30));
  EXPECT_DOUBLE_EQ(target.tilt, 0.0);
  EXPECT_DOUBLE_EQ(target.fov, radians(40));
}

TEST(PtzLimits, ACommandOutOfReachIsClampedToTheLimits) {
  const PtzPose target = ptz_target(command(150, 20, 1), kStageHead);
  EXPECT_DOUBLE_EQ(target.pan, radians(100));
  EXPECT_DOUBLE_EQ(target.tilt, 0.0);
  EXPECT_DOUBLE_EQ(target.fov, radians(5));
  EXPECT_DOUBLE_EQ(ptz_target(command(-32768, -5, 32767), kStageHead).pan, radians(-100));
}

TEST(PtzLimits, LimitsGivenBackwardsAreTheSameRange) {
  const PtzLimits backwards{radians(100), radians(-100), radians(25), radians(-25), radians(60), radians(5)};
  EXPECT_EQ(ptz_target(command(150, -30, 90), backwards), (PtzPose{radians(100), radians(-25), radians(60)}));
}

TEST(PtzLimits, DataIsInWholeDegreesWithTheTableLayout) {
  const protocol::PtzData data =
      ptz_data({radians(-30.4), radians(10.6), std::numbers::pi / 3}, radians(-2), radians(260));
  // pan @0, tilt @2, zoom @4, panspeed @6, tiltspeed @8: int16 degrees.
  const std::vector<std::uint8_t> golden = {0xFF, 0xE2, 0x00, 0x0B, 0x00, 0x3C, 0xFF, 0xFE, 0x01, 0x04};
  EXPECT_EQ(protocol::encode(data), golden);
  EXPECT_EQ(protocol::decode<protocol::PtzData>(golden), data);
}

}  // namespace ptz_limits_test
}  // namespace playerkit::interfaces
