// UTM against published points, against an independent formula (Snyder's
// series, USGS Professional Paper 1395 p. 61, written here from the book),
// both ways, in every zone and both hemispheres.

#include "families/garminnmea/protocol/utm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::hardware::garminnmea {
namespace utm_test {

// Snyder (8-9) to (8-10) for WGS-84: accurate to well under a millimetre
// within a few degrees of the central meridian, and nothing shared with utm.cpp.
struct Snyder {
  double easting;
  double northing;
};
Snyder snyder(double latitude, double longitude, int zone) {
  constexpr double a = 6378137.0, f = 1 / 298.257223563, k0 = 0.9996;
  const double e2 = f * (2 - f), ep2 = e2 / (1 - e2);
  const double phi = latitude * std::numbers::pi / 180;
  const double lambda0 = (zone * 6 - 183) * std::numbers::pi / 180;
  const double N = a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));
  const double T = std::tan(phi) * std::tan(phi);
  const double C = ep2 * std::cos(phi) * std::cos(phi);
  const double A = (longitude * std::numbers::pi / 180 - lambda0) * std::cos(phi);
  const double e4 = e2 * e2, e6 = e4 * e2;
  const double M = a * ((1 - e2 / 4 - 3 * e4 / 64 - 5 * e6 / 256) * phi -
                        (3 * e2 / 8 + 3 * e4 / 32 + 45 * e6 / 1024) * std::sin(2 * phi) +
                        (15 * e4 / 256 + 45 * e6 / 1024) * std::sin(4 * phi) - (35 * e6 / 3072) * std::sin(6 * phi));
  const double x = k0 * N *
                   (A + (1 - T + C) * std::pow(A, 3) / 6 + (5 - 18 * T + T * T + 72 * C - 58 * ep2) * std::pow(A, 5) / 120);
  const double y = k0 * (M + N * std::tan(phi) *
                                 (A * A / 2 + (5 - T + 9 * C + 4 * C * C) * std::pow(A, 4) / 24 +
                                  (61 - 58 * T + T * T + 600 * C - 330 * ep2) * std::pow(A, 6) / 720));
  return {500000 + x, latitude < 0 ? 10000000 + y : y};
}

TEST(Utm, PublishedPoints) {
  // GeographicLib's GeoConvert(1) manual: "33.3 44.4" -> "38n 444140.54 3684706.36".
  const Utm baghdad = to_utm(33.3, 44.4);
  EXPECT_EQ(baghdad.zone, 38);
  EXPECT_TRUE(baghdad.north);
  EXPECT_NEAR(baghdad.easting, 444140.54, 0.006);
  EXPECT_NEAR(baghdad.northing, 3684706.36, 0.006);
  // Palantir Foundry's "Create GeoPoint from coordinate system" example,
  // EPSG:32618: 322190.2234, 4306505.7039 is 38.88944258, -77.05014581.
  const Utm washington = to_utm(38.88944258, -77.05014581);
  EXPECT_EQ(washington.zone, 18);
  EXPECT_NEAR(washington.easting, 322190.2234, 0.002);
  EXPECT_NEAR(washington.northing, 4306505.7039, 0.002);
}

TEST(Utm, AgreesWithSnydersSeriesInEveryZoneAndBothHemispheres) {
  for (int zone = 1; zone <= 60; ++zone) {
    const double meridian = zone * 6 - 183;
    for (const double latitude : {-79.5, -45.4576, -10.0, -0.5, 0.0, 0.5, 33.8075, 60.1, 83.5}) {
      for (const double offset : {-2.9, -1.0, 0.0, 1.7, 2.9}) {
        const double longitude = meridian + offset;
        const Utm utm = to_utm_in_zone(latitude, longitude, zone);
        const Snyder reference = snyder(latitude, longitude, zone);
        EXPECT_NEAR(utm.easting, reference.easting, 0.003) << latitude << " " << longitude;
        EXPECT_NEAR(utm.northing, reference.northing, 0.003) << latitude << " " << longitude;
        EXPECT_EQ(utm.north, latitude >= 0);
      }
    }
  }
}

TEST(Utm, SouthIsTheMirrorOfNorth) {
  const Utm north = to_utm(45.4576333, 167.15275);
  const Utm south = to_utm(-45.4576333, 167.15275);
  EXPECT_NEAR(south.northing, 10000000 - north.northing, 1e-6);
  EXPECT_NEAR(south.easting, north.easting, 1e-6);
  // 1.5 put the equator itself 10,000 km north (garminnmea.md §3: false northing for lat > 0 only).
  EXPECT_NEAR(to_utm(0.0, 3.0).northing, 0.0, 1e-6);
}

TEST(Utm, ZonesWithTheirExceptions) {
  EXPECT_EQ(utm_zone(0, -180), 1);
  EXPECT_EQ(utm_zone(0, -177.0001), 1);
  EXPECT_EQ(utm_zone(0, -174), 2);
  EXPECT_EQ(utm_zone(0, 179.999), 60);
  EXPECT_EQ(utm_zone(0, 180), 60);
  EXPECT_EQ(utm_zone(-33.9, 18.4), 34);
  EXPECT_EQ(utm_zone(60.4, 5.3), 32);  // Bergen: Norway's wide zone
  EXPECT_EQ(utm_zone(78.2, 15.6), 33);  // Longyearbyen
  EXPECT_EQ(utm_zone(78.2, 8.0), 31);
  // 1.5 truncated toward zero: -0.5 degrees went to the zone of +0.5.
  EXPECT_EQ(utm_zone(51.5, -0.5), 30);
  EXPECT_EQ(utm_zone(51.5, 0.5), 31);
}

TEST(Utm, InverseReturnsThePosition) {
  for (const double latitude : {-80.0, -33.9, -0.001, 0.0, 21.3, 51.5, 84.0}) {
    for (const double longitude : {-179.9, -118.35, -0.5, 0.5, 44.4, 167.15}) {
      const LatLon back = from_utm(to_utm(latitude, longitude));
      EXPECT_NEAR(back.latitude, latitude, 1e-9) << latitude << " " << longitude;
      EXPECT_NEAR(back.longitude, longitude, 1e-9) << latitude << " " << longitude;
    }
  }
}

}  // namespace utm_test
}  // namespace playerkit::hardware::garminnmea
