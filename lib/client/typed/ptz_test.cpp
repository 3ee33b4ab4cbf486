#include "client/typed/ptz.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"

namespace playerkit::client {
namespace ptz_test {

constexpr double kOneDegree = 0.017453292519943295;

TEST(TypedPtz, StateGolden) {
  protocol::PtzData d;
  d.pan = -30;
  d.tilt = 10;
  d.zoom = 60;
  d.panspeed = 15;
  d.tiltspeed = -5;
  const PtzState s = to_si(d);
  EXPECT_DOUBLE_EQ(s.pan, -0.5235987755982988);
  EXPECT_DOUBLE_EQ(s.tilt, 0.17453292519943295);
  EXPECT_DOUBLE_EQ(s.zoom, 1.0471975511965976);
  EXPECT_DOUBLE_EQ(s.pan_speed, 0.2617993877991494);
  EXPECT_DOUBLE_EQ(s.tilt_speed, -0.08726646259971647);
}

TEST(TypedPtz, CommandRoundsToWholeDegreesAndRoundTrips) {
  const PtzCommand c{0.5, -0.25, 1.0, 0.1, -0.1};
  const protocol::PtzCommand w = to_wire(c);
  EXPECT_EQ(w.pan, 29);    // 28.65 degrees
  EXPECT_EQ(w.tilt, -14);  // -14.32
  EXPECT_EQ(w.zoom, 57);   // 57.30
  EXPECT_EQ(w.panspeed, 6);
  EXPECT_EQ(w.tiltspeed, -6);
  const PtzState back = to_si(protocol::decode<protocol::PtzCommand>(protocol::encode(w)));
  EXPECT_NEAR(back.pan, c.pan, kOneDegree / 2);
  EXPECT_NEAR(back.tilt, c.tilt, kOneDegree / 2);
  EXPECT_NEAR(back.zoom, c.zoom, kOneDegree / 2);
  EXPECT_NEAR(back.pan_speed, c.pan_speed, kOneDegree / 2);
  EXPECT_NEAR(back.tilt_speed, c.tilt_speed, kOneDegree / 2);
}

TEST(TypedPtz, CommandClampsToInt16AndRefusesNaN) {
  EXPECT_EQ(to_wire(PtzCommand{1e6, -1e6, 0, 0, 0}).pan, 32767);
  EXPECT_EQ(to_wire(PtzCommand{1e6, -1e6, 0, 0, 0}).tilt, -32768);
  EXPECT_THROW((void)to_wire(PtzCommand{0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0}),
               std::invalid_argument);
}

}  // namespace ptz_test
}  // namespace playerkit::client
