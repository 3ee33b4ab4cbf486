#pragma once
// Universal Transverse Mercator on the WGS-84 ellipsoid, both ways, with
// Krüger's series in the third flattening to n^6 (Karney, "Transverse
// Mercator with an accuracy of a few nanometers", J. Geodesy 85, 2011): well
// under a millimetre anywhere in a zone, where 1.5's Snyder series drifted
// and mishandled the southern hemisphere's edge and the zones' boundaries
// (garminnmea.md §3). The zone is the standard one, with the Norway and
// Svalbard exceptions; the southern hemisphere's false northing is 10,000 km.

namespace playerkit::hardware::garminnmea {

struct Utm {
  int zone = 0;        // 1..60
  bool north = true;   // latitude >= 0
  double easting = 0;  // metres, false easting 500 km included
  double northing = 0; // metres, false northing 10,000 km in the south
};

// The standard zone of a position (longitude in -180..180).
[[nodiscard]] int utm_zone(double latitude, double longitude);

// In the position's own zone.
[[nodiscard]] Utm to_utm(double latitude, double longitude);
// In a given zone (a position near a boundary projected in its neighbour's).
[[nodiscard]] Utm to_utm_in_zone(double latitude, double longitude, int zone);

struct LatLon {
  double latitude = 0;
  double longitude = 0;
};
[[nodiscard]] LatLon from_utm(const Utm& utm);

}  // namespace playerkit::hardware::garminnmea
