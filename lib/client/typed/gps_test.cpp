#include "client/typed/gps.hpp"

#include <gtest/gtest.h>

namespace playerkit::client {
namespace gps_test {

TEST(TypedGps, FixGolden) {
  protocol::GpsData d;
  d.time_sec = 1086000000;
  d.time_usec = 500000;
  d.latitude = 7776000;     // 36 degrees north
  d.longitude = -26352000;  // 122 degrees west
  d.altitude = 12345;
  d.utm_e = 58012345;
  d.utm_n = 398765432;
  d.quality = 2;
  d.num_sats = 7;
  d.hdop = 12;
  d.err_horz = 2500;
  d.err_vert = 4000;
  const GpsFix f = to_si(d);
  EXPECT_DOUBLE_EQ(f.time, 1086000000.5);
  EXPECT_DOUBLE_EQ(f.latitude, 36.0);
  EXPECT_DOUBLE_EQ(f.longitude, -122.0);
  EXPECT_DOUBLE_EQ(f.altitude, 12.345);
  EXPECT_DOUBLE_EQ(f.utm_easting, 580123.45);
  EXPECT_DOUBLE_EQ(f.utm_northing, 3987654.32);
  EXPECT_EQ(f.quality, 2);
  EXPECT_EQ(f.satellites, 7);
  EXPECT_DOUBLE_EQ(f.hdop, 1.2);
  EXPECT_DOUBLE_EQ(f.horizontal_error, 2.5);
  EXPECT_DOUBLE_EQ(f.vertical_error, 4.0);
}

TEST(TypedGps, FractionsOfADegree) {
  protocol::GpsData d;
  d.latitude = 1;  // 1/60 arc-second
  d.longitude = -108000;  // half a degree west
  const GpsFix f = to_si(d);
  EXPECT_DOUBLE_EQ(f.latitude, 1.0 / 216000);
  EXPECT_DOUBLE_EQ(f.longitude, -0.5);
}

}  // namespace gps_test
}  // namespace playerkit::client
