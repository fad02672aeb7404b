// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/geographic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "test_utilities.h"

using FeatureRecon::test::contains;
using FeatureRecon::test::throws_with;

namespace {

using FeatureRecon::skeleton::local_transverse_mercator;
using FeatureRecon::skeleton::Transverse_mercator;

std::string message_of(const std::vector<std::array<double, 2>>& points) {
  return FeatureRecon::test::thrown_message<std::invalid_argument>(
      [&] { local_transverse_mercator(points); });
}

// UTM zone 16N (EPSG:32616) is this projection with central meridian -87, scale 0.9996 and false easting 500
// km. Reference positions from PROJ 9.1.1 (`cs2cs -f %.6f EPSG:4326 EPSG:32616`), among them a Chicago fix,
// points 1,100 km off the central meridian, in the southern hemisphere and next to the pole.
TEST(TransverseMercator, ForwardAgreesWithProjToAMillimetre) {
  struct Case {
    double lon, lat, easting, northing;
  };
  const Case cases[] = {
      {-87.6496270, 41.8791761, 446097.654553, 4636565.422789},
      {-87.0, 41.0, 500000.000000, 4538757.061913},
      {-84.0, 60.0, 667294.821124, 6655205.483635},
      {-80.0, 10.0, 1268980.132218, 1113599.929721},
      {-93.0, -45.0, 27108.208731, -5000491.005461},
      {-87.0, 89.9, 500000.000000, 9986800.012939},
      {-77.0, 0.5, 1618438.135590, 56123.425557},
  };
  const Transverse_mercator utm16{-87, 0};
  for (const Case& c : cases) {
    const auto xy = utm16.forward(c.lon, c.lat);
    EXPECT_NEAR(500000 + 0.9996 * xy[0], c.easting, 1e-3) << c.lon << " " << c.lat;
    EXPECT_NEAR(0.9996 * xy[1], c.northing, 1e-3) << c.lon << " " << c.lat;
  }
}

TEST(TransverseMercator, InverseUndoesForward) {
  const Transverse_mercator tm{-87, 30};
  double worst = 0;
  std::size_t checked = 0;
  for (double lat = -89.5; lat <= 89.5; lat += 4.75)
    for (double dlon = -60; dlon <= 60; dlon += 0.37) {
      const auto xy = tm.forward(-87 + dlon, lat);
      if (std::abs(xy[0]) > 1e6) continue;  // within 1,000 km of the central meridian
      const auto back = tm.inverse(xy[0], xy[1]);
      worst = std::max({worst, std::abs(back[0] - (-87 + dlon)), std::abs(back[1] - lat)});
      ++checked;
    }
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, 1e-8);  // degrees: about a millimetre
  // The poles and the equator on the central meridian.
  for (const double lat : {-90.0, 0.0, 90.0}) {
    const auto xy = tm.forward(-87, lat);
    EXPECT_NEAR(xy[0], 0, 1e-6);
    EXPECT_NEAR(tm.inverse(xy[0], xy[1])[1], lat, 1e-9);
  }
}

TEST(TransverseMercator, OriginLatitudeShiftsNorthingOnly) {
  const Transverse_mercator at_equator{-87, 0}, at_chicago{-87, 41.87};
  const auto origin = at_chicago.forward(-87, 41.87);
  EXPECT_NEAR(origin[0], 0, 1e-9);
  EXPECT_NEAR(origin[1], 0, 1e-6);
  const auto a = at_equator.forward(-87.65, 41.88), b = at_chicago.forward(-87.65, 41.88);
  EXPECT_NEAR(a[0], b[0], 1e-9);
  EXPECT_NEAR(a[1] - b[1], at_equator.forward(-87, 41.87)[1], 1e-6);
}

TEST(TransverseMercator, ForwardRefusesPointsOffTheSphere) {
  const Transverse_mercator p{-87, 0};
  for (const auto& [lon, lat] : {std::pair{10.0, 95.0}, std::pair{10.0, -90.5}, std::pair{10.0, std::nan("")},
                                 std::pair{HUGE_VAL, 10.0}, std::pair{std::nan(""), 10.0}}) {
    EXPECT_TRUE(throws_with<std::invalid_argument>([&] { (void)p.forward(lon, lat); },
                                                   "Transverse_mercator::forward: longitude"))
        << lon << " " << lat;
  }
  // Settings out of range are named as settings, by forward() and inverse().
  for (const Transverse_mercator& bad : {Transverse_mercator{10, 95}, Transverse_mercator{std::nan(""), 0}}) {
    for (int direction = 0; direction < 2; ++direction) try {
        (void)(direction == 0 ? bad.forward(10, 45) : bad.inverse(0, 0));
        ADD_FAILURE() << "projected with bad settings";
      } catch (const std::invalid_argument& e) {
        EXPECT_TRUE(contains(e.what(), "Transverse_mercator: central_meridian"));
      }
  }
  // inverse() of a non-finite or far-out position: an error, not the south pole (a NaN passed for -90
  // degrees).
  for (const auto& [x, y] : {std::pair{std::nan(""), 0.0}, std::pair{0.0, std::nan("")},
                             std::pair{HUGE_VAL, 0.0}, std::pair{1e9, 1e9}}) {
    EXPECT_TRUE(throws_with<std::invalid_argument>([&] { (void)p.inverse(x, y); },
                                                   "Transverse_mercator::inverse: x "))
        << x << " " << y;
  }
  EXPECT_TRUE(std::isfinite(p.forward(-87, 90)[1]));  // the poles are on it
  EXPECT_TRUE(std::isfinite(p.forward(-87, -90)[1]));
}

// Scale 1 on the central meridian: a short step north there is the meridian arc M(phi) d(phi).
TEST(TransverseMercator, LengthsOnTheCentralMeridianAreTrue) {
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f), degree = std::acos(-1.0) / 180;
  const Transverse_mercator tm{10, 0};
  for (const double lat : {-60.0, 0.0, 41.87, 75.0}) {
    const double s = std::sin(lat * degree);
    const double M = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
    const double step = 1e-4;  // degrees: about 11 m
    const double dy = tm.forward(10, lat + step)[1] - tm.forward(10, lat)[1];
    EXPECT_NEAR(dy / (M * step * degree), 1.0, 1e-7) << lat;
  }
}

TEST(LocalTransverseMercator, CentresOnThePoints) {
  const std::vector<std::array<double, 2>> chicago = {{-87.70, 41.80}, {-87.60, 41.95}, {-87.62, 41.85}};
  const Transverse_mercator tm = local_transverse_mercator(chicago);
  EXPECT_NEAR(tm.central_meridian, -87.64, 1e-3);
  EXPECT_DOUBLE_EQ(tm.origin_latitude, (41.80 + 41.95) / 2);
  // No points: the projection at (0, 0).
  const Transverse_mercator none = local_transverse_mercator({});
  EXPECT_EQ(none.central_meridian, 0);
  EXPECT_EQ(none.origin_latitude, 0);
}

// Points on both sides of the antimeridian: the circular mean puts the central meridian at 180 degrees, the
// points 11 km either side of it, and the inverse gives their longitudes back in (-180, 180].
TEST(LocalTransverseMercator, PointsAcrossTheAntimeridianStayTogether) {
  const std::vector<std::array<double, 2>> fiji = {{179.9, -17.0}, {-179.9, -17.0}};
  const Transverse_mercator tm = local_transverse_mercator(fiji);
  EXPECT_NEAR(std::abs(tm.central_meridian), 180, 1e-9);
  const auto west = tm.forward(179.9, -17.0), east = tm.forward(-179.9, -17.0);
  EXPECT_NEAR(west[0], -east[0], 1e-6);
  EXPECT_NEAR(east[0] - west[0], 21300, 100);  // 0.2 degrees of longitude at 17 degrees south
  EXPECT_NEAR(tm.inverse(west[0], west[1])[0], 179.9, 1e-9);
  EXPECT_NEAR(tm.inverse(east[0], east[1])[0], -179.9, 1e-9);
}

// Around a pole: fixes 1.1 m from it at longitudes 0, 90, 180 and -120 (the circular mean is 8 degrees), on
// all sides of it. They lie metres apart in the projection, as on the ground, and the round trip holds (they
// were refused: "inf km" from the central meridian, beyond 89 degrees of longitude).
TEST(LocalTransverseMercator, PointsAroundAPole) {
  const double lat = 89.99999;  // 1.1 m from the pole
  const std::vector<std::array<double, 2>> pole = {{0, lat}, {90, lat}, {180, lat}, {-120, lat}};
  const Transverse_mercator tm = local_transverse_mercator(pole);
  std::vector<std::array<double, 2>> xy;
  for (const auto& p : pole) xy.push_back(tm.forward(p[0], p[1]));
  EXPECT_NEAR(std::hypot(xy[2][0] - xy[0][0], xy[2][1] - xy[0][1]), 2.23, 0.01);  // across the pole
  EXPECT_NEAR(std::hypot(xy[1][0] - xy[0][0], xy[1][1] - xy[0][1]), 2.23 / std::sqrt(2.0), 0.01);
  for (std::size_t i = 0; i < pole.size(); ++i) {
    const auto back = tm.inverse(xy[i][0], xy[i][1]);
    EXPECT_NEAR(back[1], lat,
                1e-7);  // 1 cm (3.4e-8 degrees, 4 mm, measured: asin near 90 degrees loses digits)
    EXPECT_NEAR(std::remainder(back[0] - pole[i][0], 360.0), 0, 1e-5);  // 2e-7 m at 1.1 m from the pole
  }
}

TEST(LocalTransverseMercator, BadPointsAreNamed) {
  EXPECT_EQ(message_of({{-87.6, 41.8}, {-87.6, 95}}),
            "local_transverse_mercator: point 1 has latitude 95, not in [-90, 90]");
  EXPECT_EQ(message_of({{200, 41.8}}),
            "local_transverse_mercator: point 0 has longitude 200, not in [-180, 180]");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of({{-87.6, 41.8}, {-87.6, 41.8}, {nan, 41.8}}),
            "local_transverse_mercator: point 2 has longitude nan, not in [-180, 180]");
  // 27 degrees of longitude at 42 degrees north: each end lies about 1,100 km from the middle.
  const std::string wide = message_of({{-87.6, 41.8}, {-60, 41.8}});
  EXPECT_TRUE(contains(wide, "point 0 (longitude -87.6, latitude 41.8) lies 1"));
  EXPECT_TRUE(contains(wide, "span too much for one projection"));
  // Half the globe apart: 100 degrees from the central meridian on the equator lie 15,000 km away, 90 degrees
  // infinitely far.
  EXPECT_TRUE(
      contains(message_of({{0, 0}, {100, 0}, {-100, 0}}), "point 1 (longitude 100, latitude 0) lies 15"));
  EXPECT_EQ(
      message_of({{0, 0}, {90, 0}, {-90, 0}}),
      "local_transverse_mercator: point 1 (longitude 90, latitude 0) lies on the equator 90 degrees of "
      "longitude "
      "from the central meridian 0 of the points, where the projection is infinite: the points span too much "
      "for one projection");
  // Within the bound it is accepted.
  EXPECT_EQ(message_of({{-87.6, 41.8}, {-84, 41.8}}), "no exception");
}

// The longitude is taken modulo 360 about the central meridian: whole turns added to it, even 2^30 of them
// (the sum still exact in a double), leave the position where it was.
TEST(TransverseMercator, LongitudeIsTakenModulo360) {
  const Transverse_mercator tm{7, 30};
  const double turns = double(1u << 30);
  for (const double lon : {10.0, -170.0, 7.5}) {
    const auto xy = tm.forward(lon, 45);
    for (const double k : {-turns, -1.0, 1.0, turns}) {
      const auto again = tm.forward(lon + 360 * k, 45);
      EXPECT_NEAR(again[0], xy[0], 1e-6) << lon << " + 360 x " << k;
      EXPECT_NEAR(again[1], xy[1], 1e-6) << lon << " + 360 x " << k;
    }
  }
}

// The documented ranges are closed where they say so: origin latitudes -90 and 90 are settings in range
// (the pole is then the origin), and inverse() gives longitudes in (-180, 180]: 180, never -180.
TEST(TransverseMercator, ClosedRangesAndTheLongitudeOfInverse) {
  for (const double meridian : {180.0, -180.0}) {
    const Transverse_mercator tm{meridian, 0};
    for (const double y : {0.0, 1e6, -2e6}) EXPECT_EQ(tm.inverse(0, y)[0], 180.0) << meridian << " " << y;
  }
  for (const double pole : {-90.0, 90.0}) {
    const Transverse_mercator at_pole{10, pole};
    const auto xy = at_pole.forward(10, pole);
    EXPECT_NEAR(xy[0], 0, 1e-9) << pole;
    EXPECT_NEAR(xy[1], 0, 1e-6) << pole;
    EXPECT_NEAR(at_pole.inverse(0, 0)[1], pole, 1e-9) << pole;
  }
  // Points at longitudes -180 and 180 (one meridian) are in range for local_transverse_mercator().
  EXPECT_EQ(message_of({{-180, -17}, {180, -17.01}, {-179.99, -17}}), "no exception");
}

// The documented accuracy of inverse(): within 1,000 km of the central meridian the round trip is exact to
// 2e-9 degrees, and the PROJ positions of ForwardAgreesWithProjToAMillimetre go back to their longitude and
// latitude to 1e-9 degrees (0.1 mm).
TEST(TransverseMercator, InverseMeetsTheDocumentedAccuracy) {
  const Transverse_mercator tm{-87, 30};
  double worst = 0;
  for (double lat = -84.5; lat <= 84.5; lat += 6.5)
    for (double dlon = -13; dlon <= 13; dlon += 0.65) {
      const auto xy = tm.forward(-87 + dlon, lat);
      if (std::abs(xy[0]) > 1e6) continue;
      const auto back = tm.inverse(xy[0], xy[1]);
      worst = std::max({worst, std::abs(back[0] - (-87 + dlon)), std::abs(back[1] - lat)});
    }
  EXPECT_LT(worst, 2e-9);
  const Transverse_mercator utm16{-87, 0};
  const double proj[][4] = {{-87.6496270, 41.8791761, 446097.654553, 4636565.422789},
                            {-84.0, 60.0, 667294.821124, 6655205.483635},
                            {-80.0, 10.0, 1268980.132218, 1113599.929721},
                            {-93.0, -45.0, 27108.208731, -5000491.005461}};
  for (const auto& c : proj) {
    const auto back = utm16.inverse((c[2] - 500000) / 0.9996, c[3] / 0.9996);
    EXPECT_NEAR(back[0], c[0], 1e-9) << c[0] << " " << c[1];
    EXPECT_NEAR(back[1], c[1], 1e-9) << c[0] << " " << c[1];
  }
}

// max_offset bounds the distance from the central meridian inclusively (a point exactly at it is accepted,
// one a hair beyond refused); by default 500 km (5.4 degrees of longitude on the equator, about 601 km, are
// refused; 3.6 degrees, about 401 km, accepted); zero, negative or NaN bounds are refused by name.
TEST(LocalTransverseMercator, MaxOffsetIsAPositiveInclusiveBound) {
  const std::string far = message_of({{0, 0}, {10.8, 0}});
  EXPECT_TRUE(contains(far, "point 0 (longitude 0, latitude 0) lies 60"));
  EXPECT_EQ(message_of({{0, 0}, {7.2, 0}}), "no exception");
  const std::vector<std::array<double, 2>> points = {{0, 0}, {7.2, 0}, {3, 1}};
  const Transverse_mercator tm = local_transverse_mercator(points);
  double x = 0;
  for (const auto& p : points) x = std::max(x, std::abs(tm.forward(p[0], p[1])[0]));
  EXPECT_NO_THROW(local_transverse_mercator(points, x));
  EXPECT_THROW(local_transverse_mercator(points, std::nextafter(x, 0.0)), std::invalid_argument);
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_TRUE(throws_with<std::invalid_argument>(
        [&] {
          local_transverse_mercator({{0, 0}, {1, 0}}, bad);
        },
        "local_transverse_mercator: max_offset must be positive"))
        << bad;
  }
}

}  // namespace
