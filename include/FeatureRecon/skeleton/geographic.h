// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_GEOGRAPHIC_H
#define FEATURERECON_SKELETON_GEOGRAPHIC_H

// Longitude / latitude to metres and back, for GPS traces given in degrees (WGS84): the road-map pipeline
// works in metres (its radii, gaps and thresholds are lengths), so traces in degrees are projected to a plane
// first and the map is projected back. The projection is transverse Mercator on the WGS84 ellipsoid (the
// projection of UTM, Krüger's series to third order in the third flattening n, as in the UTM formulas),
// centred on the data: scale 1 on the central meridian, so that lengths near it are true lengths; the scale
// grows as 1 + x^2 / (2 R^2) away from it (1.0003 at 100 km, 1.003 at 350 km). local_transverse_mercator()
// picks the centre and refuses data farther than a bound from it.
//
//   // lonlat: {longitude, latitude} in degrees
//   const Transverse_mercator tm = local_transverse_mercator(lonlat);
//   const std::array<double, 2> xy = tm.forward(lon, lat);          // metres east and north of the centre
//   const std::array<double, 2> back = tm.inverse(xy[0], xy[1]);    // {longitude, latitude} again

#include <FeatureRecon/assertions.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Transverse Mercator on the WGS84 ellipsoid (a = 6378137 m, f = 1 / 298.257223563) with scale 1 on the
/// central meridian: forward() maps {longitude, latitude} in degrees to {x, y} in metres, x east of the
/// central meridian and y north of the origin latitude (on the central meridian); inverse() maps back.
/// Krüger's series to third order in n (the inverse finishes the latitude by Newton's method): within 1,000
/// km of the central meridian the round trip is exact to 2e-9 degrees (0.2 mm), and the positions agree with
/// PROJ's (EPSG:32616, UTM zone 16N, after its scale 0.9996 and false easting) to a millimetre
/// (test_geographic.cpp).
struct Transverse_mercator {
  double central_meridian = 0;  ///< longitude of the central meridian (degrees)
  double origin_latitude = 0;   ///< latitude where y = 0 on the central meridian (degrees)

  /// {x, y} in metres of {longitude, latitude} in degrees. The longitude is taken modulo 360 about the
  /// central meridian (a map crossing the antimeridian stays in one piece). Beyond 90 degrees of longitude
  /// the map goes on over the poles: near a pole the points on the far side of it from the central meridian
  /// lie a few metres from it too (the round trip holds there to 4 mm, test_geographic.cpp).
  /// \pre the point is not 90 degrees of longitude from the central meridian on the equator (x infinite
  ///   there).
  /// \throws std::invalid_argument for a latitude outside [-90, 90] or a longitude that is not finite, or
  ///   settings out of range (origin_latitude outside [-90, 90], central_meridian not finite; inverse() too).
  std::array<double, 2> forward(double longitude, double latitude) const {
    if (!(latitude >= -90 && latitude <= 90) || !std::isfinite(longitude))
      FeatureRecon::internal::throw_invalid_argument("Transverse_mercator::forward", "longitude ", longitude,
                                                     ", latitude ", latitude,
                                                     ": the latitude must be in [-90, 90] "
                                                     "and the longitude finite");
    const Constants& c = constants();
    const double phi = latitude * degree;
    const double lambda = wrap(longitude - central_meridian) * degree;
    const double s = std::sin(phi);
    const double t = std::sinh(std::atanh(s) - c.e * std::atanh(c.e * s));
    const double xi = std::atan2(t, std::cos(lambda));
    const double eta = std::atanh(std::sin(lambda) / std::sqrt(1 + t * t));
    double x = eta, y = xi;
    for (int j = 1; j <= 3; ++j) {
      x += c.alpha[j - 1] * std::cos(2 * j * xi) * std::sinh(2 * j * eta);
      y += c.alpha[j - 1] * std::sin(2 * j * xi) * std::cosh(2 * j * eta);
    }
    return {c.A * x, c.A * y - northing_of_origin()};
  }

  /// {longitude, latitude} in degrees of {x, y} in metres; the longitude in (-180, 180].
  /// \throws std::invalid_argument for x or y not finite, or so far out that the series overflow (x beyond
  ///   about 700 semi-major axes: no point of the ellipsoid maps there).
  std::array<double, 2> inverse(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y))
      FeatureRecon::internal::throw_invalid_argument("Transverse_mercator::inverse", "x ", x, ", y ", y,
                                                     ": both must be finite");
    const Constants& c = constants();
    const double xi = (y + northing_of_origin()) / c.A, eta = x / c.A;
    double xi1 = xi, eta1 = eta;
    for (int j = 1; j <= 3; ++j) {
      xi1 -= c.beta[j - 1] * std::sin(2 * j * xi) * std::cosh(2 * j * eta);
      eta1 -= c.beta[j - 1] * std::cos(2 * j * xi) * std::sinh(2 * j * eta);
    }
    const double chi = std::asin(std::sin(xi1) / std::cosh(eta1));  // conformal latitude
    // Geographic latitude from the conformal one: Newton on tan(phi) (exact, unlike a series in n).
    const double tau1 = std::tan(chi);
    double tau = tau1;
    for (int k = 0; k < 8 && std::isfinite(tau); ++k) {
      const double s = tau / std::sqrt(1 + tau * tau);
      const double sigma = std::sinh(c.e * std::atanh(c.e * s));
      const double tau_of = tau * std::sqrt(1 + sigma * sigma) - sigma * std::sqrt(1 + tau * tau);
      const double derivative = (1 - c.e * c.e) * std::sqrt((1 + tau_of * tau_of) * (1 + tau * tau)) /
                                (1 + (1 - c.e * c.e) * tau * tau);
      const double step = (tau1 - tau_of) / derivative;
      tau += step;
      if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(tau))) break;
    }
    const double latitude = std::isfinite(tau) ? std::atan(tau) / degree : (chi > 0 ? 90.0 : -90.0);
    const double longitude = wrap(central_meridian + std::atan2(std::sinh(eta1), std::cos(xi1)) / degree);
    if (std::isnan(chi) || std::isnan(longitude))  // (a NaN chi made the south pole)
      FeatureRecon::internal::throw_invalid_argument("Transverse_mercator::inverse", "x ", x, ", y ", y,
                                                     ": outside the range of the projection");
    return {longitude, latitude};
  }

 private:
  static constexpr double degree = 3.14159265358979323846 / 180;
  struct Constants {
    double e, A;
    double alpha[3], beta[3];
  };
  static const Constants& constants() {
    static const Constants c = [] {
      const double a = 6378137.0, f = 1 / 298.257223563;
      const double n = f / (2 - f), n2 = n * n, n3 = n2 * n;
      Constants k;
      k.e = std::sqrt(f * (2 - f));
      k.A = a / (1 + n) * (1 + n2 / 4 + n2 * n2 / 64);
      k.alpha[0] = n / 2 - 2 * n2 / 3 + 5 * n3 / 16;
      k.alpha[1] = 13 * n2 / 48 - 3 * n3 / 5;
      k.alpha[2] = 61 * n3 / 240;
      k.beta[0] = n / 2 - 2 * n2 / 3 + 37 * n3 / 96;
      k.beta[1] = n2 / 48 + n3 / 15;
      k.beta[2] = 17 * n3 / 480;
      return k;
    }();
    return c;
  }
  /// Longitude difference in (-180, 180].
  static double wrap(double d) {
    d = std::fmod(d, 360.0);
    if (d > 180) d -= 360;
    if (d <= -180) d += 360;
    return d;
  }
  double northing_of_origin()
      const {  // (forward() and inverse() both call it: the settings are checked here)
    if (!(origin_latitude >= -90 && origin_latitude <= 90) || !std::isfinite(central_meridian))
      FeatureRecon::internal::throw_invalid_argument("Transverse_mercator", "central_meridian ",
                                                     central_meridian, ", origin_latitude ", origin_latitude,
                                                     ": the origin latitude "
                                                     "must be in [-90, 90] and the central meridian finite");
    if (origin_latitude == 0) return 0;
    Transverse_mercator at_equator{central_meridian, 0};
    return at_equator.forward(central_meridian, origin_latitude)[1];
  }
};

/// The transverse Mercator centred on some points given as {longitude, latitude} in degrees: the central
/// meridian is their mean longitude (a circular mean, so that points on both sides of the antimeridian are
/// centred right), the origin latitude the middle of their latitudes; no points: the projection at (0, 0).
/// \throws std::invalid_argument naming the first point whose longitude is not in [-180, 180] or latitude not
///   in [-90, 90] (or not finite), and the first point farther than `max_offset` metres (default 500 km:
///   scale 1.003) east or west of the central meridian: such data span too much for one projection (project
///   them yourself, e.g. to their UTM zones).
inline Transverse_mercator local_transverse_mercator(const std::vector<std::array<double, 2>>& lonlat,
                                                     double max_offset = 500e3) {
  const char* fn = "local_transverse_mercator";
  if (!(max_offset > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_offset must be positive, got ", max_offset);
  Transverse_mercator tm;
  if (lonlat.empty()) return tm;
  constexpr double degree = 3.14159265358979323846 / 180;
  double sx = 0, sy = 0, low = 90, high = -90;
  for (std::size_t i = 0; i < lonlat.size(); ++i) {
    const double lon = lonlat[i][0], lat = lonlat[i][1];
    if (!(lon >= -180 && lon <= 180))
      FeatureRecon::internal::throw_invalid_argument(fn, "point ", i, " has longitude ", lon,
                                                     ", not in [-180, 180]");
    if (!(lat >= -90 && lat <= 90))
      FeatureRecon::internal::throw_invalid_argument(fn, "point ", i, " has latitude ", lat,
                                                     ", not in [-90, 90]");
    sx += std::cos(lon * degree);
    sy += std::sin(lon * degree);
    low = std::min(low, lat);
    high = std::max(high, lat);
  }
  tm.central_meridian = (sx == 0 && sy == 0) ? lonlat.front()[0] : std::atan2(sy, sx) / degree;
  tm.origin_latitude = (low + high) / 2;
  for (std::size_t i = 0; i < lonlat.size(); ++i) {
    // Beyond max_offset too distorted (infinite 90 degrees from the central meridian on the equator). Near a
    // pole, points at any longitude lie close to the central meridian (they used to be refused beyond 89
    // degrees of longitude: two fixes 2 m apart on either side of the pole, "inf km" away).
    const double x = std::abs(tm.forward(lonlat[i][0], lonlat[i][1])[0]);
    if (!(x <= max_offset)) {
      if (std::isfinite(x))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "point ", i, " (longitude ", lonlat[i][0], ", latitude ", lonlat[i][1], ") lies ", x / 1000,
            " km from the central meridian ", tm.central_meridian, " of the points (at most ",
            max_offset / 1000, " km): the points span too much for one projection");
      FeatureRecon::internal::throw_invalid_argument(
          fn, "point ", i, " (longitude ", lonlat[i][0], ", latitude ", lonlat[i][1],
          ") lies on the equator 90 ", "degrees of longitude from the central meridian ", tm.central_meridian,
          " of the points, where the ",
          "projection is infinite: the points span too much for one projection");
    }
  }
  return tm;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_GEOGRAPHIC_H
