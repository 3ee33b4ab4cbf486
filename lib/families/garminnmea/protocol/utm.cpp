#include "families/garminnmea/protocol/utm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace playerkit::hardware::garminnmea {

namespace {

constexpr double kSemiMajorAxis = 6378137.0;
constexpr double kFlattening = 1.0 / 298.257223563;
constexpr double kScale = 0.9996;
constexpr double kFalseEasting = 500000.0;
constexpr double kSouthFalseNorthing = 10000000.0;
constexpr double kDegree = std::numbers::pi / 180.0;

struct Series {
  double rectifying_radius;  // A
  double eccentricity;
  std::array<double, 6> alpha;
  std::array<double, 6> beta;
};

const Series& series() {
  static const Series s = [] {
    const double n = kFlattening / (2 - kFlattening);
    const double n2 = n * n, n3 = n2 * n, n4 = n3 * n, n5 = n4 * n, n6 = n5 * n;
    Series out{};
    out.rectifying_radius = kSemiMajorAxis / (1 + n) * (1 + n2 / 4 + n4 / 64 + n6 / 256);
    out.eccentricity = std::sqrt(kFlattening * (2 - kFlattening));
    out.alpha = {n / 2 - 2 * n2 / 3 + 5 * n3 / 16 + 41 * n4 / 180 - 127 * n5 / 288 + 7891 * n6 / 37800,
                 13 * n2 / 48 - 3 * n3 / 5 + 557 * n4 / 1440 + 281 * n5 / 630 - 1983433 * n6 / 1935360,
                 61 * n3 / 240 - 103 * n4 / 140 + 15061 * n5 / 26880 + 167603 * n6 / 181440,
                 49561 * n4 / 161280 - 179 * n5 / 168 + 6601661 * n6 / 7257600,
                 34729 * n5 / 80640 - 3418889 * n6 / 1995840,
                 212378941 * n6 / 319334400};
    out.beta = {n / 2 - 2 * n2 / 3 + 37 * n3 / 96 - n4 / 360 - 81 * n5 / 512 + 96199 * n6 / 604800,
                n2 / 48 + n3 / 15 - 437 * n4 / 1440 + 46 * n5 / 105 - 1118711 * n6 / 3870720,
                17 * n3 / 480 - 37 * n4 / 840 - 209 * n5 / 4480 + 5569 * n6 / 90720,
                4397 * n4 / 161280 - 11 * n5 / 504 - 830251 * n6 / 7257600,
                4583 * n5 / 161280 - 108847 * n6 / 3991680,
                20648693 * n6 / 638668800};
    return out;
  }();
  return s;
}

double central_meridian(int zone) { return (zone * 6 - 183) * kDegree; }

// The tangent of the conformal latitude from the tangent of the latitude.
double conformal_tangent(double tau, double e) {
  const double sigma = std::sinh(e * std::atanh(e * tau / std::hypot(1.0, tau)));
  return tau * std::hypot(1.0, sigma) - sigma * std::hypot(1.0, tau);
}

}  // namespace

int utm_zone(double latitude, double longitude) {
  int zone = static_cast<int>(std::floor((longitude + 180.0) / 6.0)) + 1;
  // 180 degrees is zone 60's eastern edge, not zone 1's western one.
  zone = std::clamp(zone, 1, 60);
  if (latitude >= 56 && latitude < 64 && longitude >= 3 && longitude < 12) return 32;
  if (latitude >= 72 && latitude <= 84 && longitude >= 0 && longitude < 42) {
    if (longitude < 9) return 31;
    if (longitude < 21) return 33;
    if (longitude < 33) return 35;
    return 37;
  }
  return zone;
}

Utm to_utm(double latitude, double longitude) {
  return to_utm_in_zone(latitude, longitude, utm_zone(latitude, longitude));
}

Utm to_utm_in_zone(double latitude, double longitude, int zone) {
  const Series& s = series();
  const double phi = latitude * kDegree;
  const double lambda = std::remainder(longitude * kDegree - central_meridian(zone), 2 * std::numbers::pi);
  const double tau_prime = conformal_tangent(std::tan(phi), s.eccentricity);
  const double xi_prime = std::atan2(tau_prime, std::cos(lambda));
  const double eta_prime = std::asinh(std::sin(lambda) / std::hypot(tau_prime, std::cos(lambda)));
  double xi = xi_prime, eta = eta_prime;
  for (int j = 1; j <= 6; ++j) {
    xi += s.alpha[j - 1] * std::sin(2 * j * xi_prime) * std::cosh(2 * j * eta_prime);
    eta += s.alpha[j - 1] * std::cos(2 * j * xi_prime) * std::sinh(2 * j * eta_prime);
  }
  const bool north = latitude >= 0;
  return {.zone = zone,
          .north = north,
          .easting = kFalseEasting + kScale * s.rectifying_radius * eta,
          .northing = (north ? 0.0 : kSouthFalseNorthing) + kScale * s.rectifying_radius * xi};
}

LatLon from_utm(const Utm& utm) {
  const Series& s = series();
  const double xi = (utm.northing - (utm.north ? 0.0 : kSouthFalseNorthing)) / (kScale * s.rectifying_radius);
  const double eta = (utm.easting - kFalseEasting) / (kScale * s.rectifying_radius);
  double xi_prime = xi, eta_prime = eta;
  for (int j = 1; j <= 6; ++j) {
    xi_prime -= s.beta[j - 1] * std::sin(2 * j * xi) * std::cosh(2 * j * eta);
    eta_prime -= s.beta[j - 1] * std::cos(2 * j * xi) * std::sinh(2 * j * eta);
  }
  const double tau_prime = std::sin(xi_prime) / std::hypot(std::sinh(eta_prime), std::cos(xi_prime));
  const double lambda = std::atan2(std::sinh(eta_prime), std::cos(xi_prime));
  // Newton's method on the conformal latitude (Karney 2011, eq. 19-21).
  const double e = s.eccentricity, one_minus_e2 = 1 - e * e;
  double tau = tau_prime;
  for (int i = 0; i < 6; ++i) {
    const double tau_i_prime = conformal_tangent(tau, e);
    tau += (tau_prime - tau_i_prime) / std::hypot(1.0, tau_i_prime) * (1 + one_minus_e2 * tau * tau) /
           (one_minus_e2 * std::hypot(1.0, tau));
  }
  return {std::atan(tau) / kDegree, std::remainder(lambda / kDegree + central_meridian(utm.zone) / kDegree, 360.0)};
}

}  // namespace playerkit::hardware::garminnmea
