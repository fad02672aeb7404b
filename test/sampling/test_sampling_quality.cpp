// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Traits models, bilateral metrics and the spacing statistics of sample sets.
#include <FeatureRecon/sampling/sampling_quality.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include "sampling/sampling_test_utilities.h"
#include "test_utilities.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using namespace FeatureRecon::test;

TEST(BilateralMetric, GaussianAndExponentialForms) {
  const Gaussian_bilateral_metric g{2.0, 0.5};
  EXPECT_DOUBLE_EQ(g(4.0, 0.25), std::sqrt(2.0));  // sqrt(4/4 + 0.25/0.25)
  const Exponential_bilateral_metric e{2.0, 0.5};
  EXPECT_DOUBLE_EQ(e(4.0, 0.25), std::exp(1.0));  // 2/2 * exp(0.25/0.25)
  // sigma_feature = infinity is the scaled Euclidean distance, whatever the features.
  EXPECT_DOUBLE_EQ((Gaussian_bilateral_metric{2.0}(9.0, 100.0)), 1.5);
  EXPECT_DOUBLE_EQ((Exponential_bilateral_metric{2.0}(9.0, 100.0)), 1.5);
  // Identical positions are at distance 0 whatever the features, also where exp(f) overflows (0 * inf = NaN).
  EXPECT_EQ((Exponential_bilateral_metric{1.0, 0.05}(0.0, 4.0)), 0.0);
  EXPECT_EQ((Exponential_bilateral_metric{1.0, 0.05}(1e-300, 4.0)), std::numeric_limits<double>::infinity());
  // The documented lower bound xi >= |dp| / sigma_position, which the samplers' spatial searches rely on.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 10);
  for (int i = 0; i < 1000; ++i) {
    const double d2 = u(rng), f2 = u(rng), sp = 0.1 + u(rng), sf = 0.1 + u(rng);
    EXPECT_GE((Gaussian_bilateral_metric{sp, sf}(d2, f2)), std::sqrt(d2) / sp * (1 - 1e-15));
    EXPECT_GE((Exponential_bilateral_metric{sp, sf}(d2, f2)), std::sqrt(d2) / sp * (1 - 1e-15));
  }
}

TEST(FeaturePointTraits, ReadyModels) {
  static_assert(std::is_same<Default_traits_t<std::vector<Point_2>>, Point_traits<Point_2>>::value);
  static_assert(std::is_same<Default_traits_t<std::vector<std::pair<Point_3, Vector_3>>>,
                             Point_with_normal_traits<K>>::value);
  static_assert(FeatureRecon::internal::Is_feature_point_traits<Rgb_pixel_traits>::value);
  static_assert(!FeatureRecon::internal::Is_feature_point_traits<Point_2>::value);

  Point_with_normal_traits<K> oriented;
  const auto d = oriented.compute_feature_distance_object();
  EXPECT_NEAR(CGAL::to_double(d(Vector_3(0, 0, 2), Vector_3(0, 0, -1))), 4.0, 1e-12);  // two sides of a wall
  EXPECT_NEAR(CGAL::to_double(d(Vector_3(0, 0, 1), Vector_3(3, 0, 0))), 2.0, 1e-12);   // perpendicular
  EXPECT_NEAR(CGAL::to_double(d(Vector_3(1, 1, 0), Vector_3(2, 2, 0))), 0.0, 1e-12);  // lengths do not matter
  Point_with_normal_traits<K> unoriented{Normal_orientation::unoriented};
  const auto du = unoriented.compute_feature_distance_object();
  EXPECT_NEAR(CGAL::to_double(du(Vector_3(0, 0, 2), Vector_3(0, 0, -1))), 0.0, 1e-12);
  EXPECT_NEAR(CGAL::to_double(du(Vector_3(0, 0, 1), Vector_3(3, 0, 0))), 2.0, 1e-12);

  const Rgb_pixel black{4, 7, {0, 0, 0}}, white{5, 7, {255, 255, 255}}, red{0, 0, {255, 0, 0}};
  const Rgb_pixel_traits rgb;
  EXPECT_EQ(rgb.construct_point_object()(black), Point_2(4.5, 7.5));
  const auto fd = rgb.compute_feature_distance_object();
  const auto f = rgb.construct_feature_object();
  EXPECT_DOUBLE_EQ(CGAL::to_double(fd(f(black), f(white))), 1.0);
  EXPECT_DOUBLE_EQ(CGAL::to_double(fd(f(black), f(red))), 1.0 / 3.0);
  const Grey_pixel_traits grey;
  EXPECT_DOUBLE_EQ(CGAL::to_double(grey.compute_feature_distance_object()(
                       grey.construct_feature_object()(Grey_pixel{0, 0, 0}),
                       grey.construct_feature_object()(Grey_pixel{0, 0, 255}))),
                   1.0);

  // A user's struct through property maps.
  struct Sample {
    double x, y, temperature;
  };
  const auto traits = make_property_map_traits<K, 2, Sample>(
      [](const Sample& s) { return Point_2(s.x, s.y); }, [](const Sample& s) { return s.temperature; },
      [](double a, double b) { return (a - b) * (a - b); });
  const Sample a{1, 2, 10}, b{1, 2, 13};
  EXPECT_EQ(traits.construct_point_object()(a), Point_2(1, 2));
  EXPECT_DOUBLE_EQ(CGAL::to_double(traits.compute_feature_distance_object()(
                       traits.construct_feature_object()(a), traits.construct_feature_object()(b))),
                   9.0);
}

TEST(SamplingQuality, WhiteNoiseOnTheTorus) {
  // Reference (design notes, PSA tool, 4096 points, 10 sets): average minimum distance 0.466, rho 0.009.
  double amd = 0, rho = 0;
  for (unsigned s = 0; s < 10; ++s) {
    Sampling_quality_options o;
    o.periodic = true;
    const Sampling_quality q = sampling_quality(white_noise(4096, s), o);
    EXPECT_EQ(q.status, Status::success);
    amd += q.average_minimum_distance / 10;
    rho += q.relative_radius / 10;
  }
  EXPECT_NEAR(amd, 0.466, 0.006);
  EXPECT_LT(rho, 0.03);
}

TEST(SamplingQuality, TorusNeighboursAcrossTheSeamOfAClusteredSet) {
  // Two samples 0.4 apart across the seam x = 0 / 1 and 200 clustered far from both: d_hex is small, so the
  // nearest image of each lies beyond the first band of images; the result must still be the torus distance
  // (before: 0.6, the distance inside the cell). Euclidean and bilateral, against all pairs and shifts.
  std::vector<std::pair<Point_3, Vector_3>> p{{Point_3(0.2, 0.2, 0.5), Vector_3(0, 0, 1)},
                                              {Point_3(0.8, 0.2, 0.5), Vector_3(0, 0, 1)}};
  for (int i = 0; i < 200; ++i)
    p.push_back({Point_3(0.45 + 0.005 * (i % 20), 0.7 + 0.01 * (i / 20), 0.5 + 0.001 * (i % 7)),
                 Vector_3(0, 0, i % 2 ? 1 : -1)});
  for (const double sigma_feature : {std::numeric_limits<double>::infinity(), 0.5}) {
    Sampling_quality_options o;
    o.periodic = true;
    o.sigma_feature = sigma_feature;
    const Sampling_quality q = sampling_quality(p, o);
    double smallest = std::numeric_limits<double>::infinity(), mean = 0, seam = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < p.size(); ++j)
        for (int shift = 0; shift < 27 && j != i; ++shift) {
          const Vector_3 d =
              p[i].first - p[j].first - Vector_3(shift % 3 - 1, shift / 3 % 3 - 1, shift / 9 - 1);
          const double f =
              std::isinf(sigma_feature) ? 0 : (p[i].second - p[j].second).squared_length() / 0.25;
          nearest = std::min(nearest, std::sqrt(d.squared_length() + f));
        }
      smallest = std::min(smallest, nearest);
      mean += nearest / double(p.size());
      if (i < 2) seam += nearest / 2;
    }
    EXPECT_NEAR(seam, 0.4, 1e-12);
    EXPECT_NEAR(q.minimum_distance, smallest, 1e-12);
    EXPECT_NEAR(q.average_minimum_distance * q.hexagonal_distance, mean, 1e-12) << sigma_feature;
  }
}

// Nearest distances on the torus of `period` by brute force: every other point at every shift by up to three
// periods along each axis (bilateral with sigma_feature 0.5 on the normals when `normals` is given).
template <class P>
std::vector<double> torus_nearest(const std::vector<P>& p, const std::vector<double>& period,
                                  const std::vector<Vector_3>& normals = {}) {
  const int d = p[0].dimension();
  std::vector<double> nearest(p.size(), std::numeric_limits<double>::infinity());
  int shifts = 1;
  for (int k = 0; k < d; ++k) shifts *= 7;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j)
      for (int s = 0; s < shifts && j != i; ++s) {
        double d2 = 0;
        for (int k = 0, c = s; k < d; ++k, c /= 7) {
          const double x = p[i][k] - p[j][k] - double(c % 7 - 3) * period[std::size_t(k)];
          d2 += x * x;
        }
        if (!normals.empty()) d2 += (normals[i] - normals[j]).squared_length() / 0.25;
        nearest[i] = std::min(nearest[i], std::sqrt(d2));
      }
  return nearest;
}

TEST(SamplingQuality, BoxTorusMatchesBruteForce) {
  // Tori of other periods (Sampling_quality_options::period): the measure is their product by default, and
  // the minimum and mean nearest distances are those of the nearest images of other points (brute force), for
  // spread samples (the first band of images), a few samples (every image at once), periods shorter than the
  // spacing (a point's own images, a period away, are not its neighbours: three points of [0, 4) x [0, 1) lie
  // 1.118 apart, not 1), very unequal periods, and in 3D, Euclidean and bilateral. The unit torus gives other
  // distances for the same samples.
  struct Case {
    std::vector<double> period;
    std::size_t n;
  };
  for (const Case& c :
       {Case{{2, 0.5}, 300}, Case{{2, 0.5}, 3}, Case{{4, 1}, 0}, Case{{3, 0.2}, 20}, Case{{100, 0.01}, 40}}) {
    std::vector<Point_2> p;
    if (c.n == 0)
      p = {Point_2(0.5, 0.25), Point_2(2.5, 0.25), Point_2(1.5, 0.75)};
    else
      for (const Point_2& q : white_noise(c.n, 40))
        p.emplace_back(c.period[0] * q.x() + 2 * c.period[0], c.period[1] * q.y() - c.period[1]);
    Sampling_quality_options o;
    o.periodic = true;
    o.period = c.period;
    const Sampling_quality q = sampling_quality(p, o);
    ASSERT_EQ(q.status, Status::success);
    EXPECT_EQ(q.domain_measure, c.period[0] * c.period[1]);
    const std::vector<double> nearest = torus_nearest(p, c.period);
    double mean = 0;
    for (const double d : nearest) mean += d / double(p.size());
    const std::string what = std::to_string(c.period[0]) + " x " + std::to_string(c.period[1]);
    EXPECT_NEAR(q.minimum_distance, *std::min_element(nearest.begin(), nearest.end()), 1e-12) << what;
    EXPECT_NEAR(q.average_minimum_distance * q.hexagonal_distance, mean, 1e-12) << what;
    if (c.n == 0) {
      EXPECT_NEAR(q.minimum_distance, std::sqrt(1.25), 1e-12);
    }
    Sampling_quality_options unit;
    unit.periodic = true;
    unit.domain_measure = q.domain_measure;
    EXPECT_GT(std::abs(sampling_quality(p, unit).average_minimum_distance - q.average_minimum_distance), 1e-3)
        << what;
  }
  // 3D: the box [0, 1) x [0, 2) x [0, 0.25), Euclidean and bilateral (normals up or down).
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<double> box{1, 2, 0.25};
  std::vector<Point_3> p3;
  std::vector<Vector_3> normals;
  std::vector<std::pair<Point_3, Vector_3>> pn;
  for (int i = 0; i < 60; ++i) {
    p3.emplace_back(u(rng) - 1, 2 * u(rng), 0.25 * u(rng) + 0.5);
    normals.emplace_back(0, 0, rng() % 2 ? 1 : -1);
    pn.push_back({p3.back(), normals.back()});
  }
  Sampling_quality_options o;
  o.periodic = true;
  o.period = box;
  const Sampling_quality q = sampling_quality(p3, o);
  EXPECT_EQ(q.domain_measure, 0.5);
  std::vector<double> nearest = torus_nearest(p3, box);
  EXPECT_NEAR(q.minimum_distance, *std::min_element(nearest.begin(), nearest.end()), 1e-12);
  o.sigma_feature = 0.5;
  const Sampling_quality b = sampling_quality(pn, o);
  nearest = torus_nearest(p3, box, normals);
  double mean = 0;
  for (const double d : nearest) mean += d / double(p3.size());
  EXPECT_NEAR(b.minimum_distance, *std::min_element(nearest.begin(), nearest.end()), 1e-12);
  EXPECT_NEAR(b.average_minimum_distance * b.hexagonal_distance, mean, 1e-12);
  Sampling_quality_options bad;
  bad.periodic = true;
  bad.period = {2};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { sampling_quality(white_noise(5, 1), bad); },
      "sampling_quality: period has 1 values for positions of dimension 2"));
  bad.period = {1e120, 1e120, 1e120};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { sampling_quality(p3, bad); },
      "the product of the periods (the torus's measure) must be a finite normal number"));
  bad.period = {1e-110, 1e-110, 1e-110};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_quality(p3, bad); }, "got 0"));
}

TEST(SamplingQuality, NearestNeighboursMatchBruteForceOnClusters) {
  // Half the points in a corner 0.01 wide, the rest spread out, some duplicates: the minimum and the mean of
  // the nearest-neighbour distances against a scan of all pairs, in 2-D and 3-D.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0, 1), c(0, 0.01);
  std::vector<Point_2> p2;
  std::vector<Point_3> p3;
  for (int i = 0; i < 600; ++i) {
    const bool corner = i % 2 == 0;
    p2.emplace_back(corner ? c(rng) : u(rng), corner ? c(rng) : u(rng));
    p3.emplace_back(corner ? c(rng) : u(rng), corner ? c(rng) : u(rng), corner ? c(rng) : u(rng));
  }
  p2.push_back(p2[7]);
  p2.push_back(p2[7]);  // three copies: the two nearest of one copy may be the other two
  p3.push_back(p3[8]);
  auto check = [](const auto& p, double hex_scale) {
    std::vector<double> nearest(p.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < p.size(); ++j)
        if (i != j)
          nearest[i] = std::min(nearest[i], std::sqrt(CGAL::to_double(CGAL::squared_distance(p[i], p[j]))));
    const Sampling_quality q = sampling_quality(p);
    ASSERT_EQ(q.status, Status::success);
    EXPECT_EQ(q.minimum_distance, *std::min_element(nearest.begin(), nearest.end()));
    double mean = 0;
    for (const double d : nearest) mean += d / double(p.size());
    EXPECT_NEAR(q.average_minimum_distance * q.hexagonal_distance, mean, 1e-12 * hex_scale);
  };
  check(p2, 1.0);
  check(p3, 1.0);
  // Bilateral (normals up or down at random, sigma_feature 0.05): the incremental search against all pairs.
  std::vector<std::pair<Point_3, Vector_3>> pn;
  for (std::size_t i = 0; i < p3.size(); ++i) pn.push_back({p3[i], Vector_3(0, 0, rng() % 2 ? 1 : -1)});
  Sampling_quality_options o;
  o.sigma_feature = 0.05;
  const Sampling_quality q = sampling_quality(pn, o);
  double smallest = std::numeric_limits<double>::infinity(), mean = 0;
  for (std::size_t i = 0; i < pn.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < pn.size(); ++j)
      if (i != j)
        nearest = std::min(
            nearest, std::sqrt(CGAL::to_double(CGAL::squared_distance(pn[i].first, pn[j].first)) +
                               CGAL::to_double((pn[i].second - pn[j].second).squared_length()) / 0.0025));
    smallest = std::min(smallest, nearest);
    mean += nearest / double(pn.size());
  }
  EXPECT_NEAR(q.minimum_distance, smallest, 1e-12);
  EXPECT_NEAR(q.average_minimum_distance * q.hexagonal_distance, mean, 1e-12);
  const Sampling_quality euclidean = sampling_quality(p3);
  EXPECT_GT(mean,
            1.05 * euclidean.average_minimum_distance * euclidean.hexagonal_distance);  // the features count
}

TEST(SamplingQuality, ManyCopiesOfAPointAreOnePlaceOfTheTree) {
  // 50,000 copies of one point among 200: a kd-tree peels one copy per level (O(c^2) to build; 40,000 copies
  // overflowed the stack). The tree holds each place once; the statistics are those of all pairs: every copy
  // 0 from the next, the others their nearest distinct point. Bilateral: copies with normals up and down,
  // each 0 from a copy with its own normal. On a torus: copies and an image of another point at one place.
  std::vector<Point_2> p = white_noise(200, 65);
  const std::vector<Point_2> distinct = p;
  p.insert(p.end(), 50000, p[0]);
  const Sampling_quality q = sampling_quality(p);
  ASSERT_EQ(q.status, Status::success);
  EXPECT_EQ(q.minimum_distance, 0.0);
  double sum = 0;
  for (std::size_t i = 1; i < distinct.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < distinct.size(); ++j)
      if (j != i) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(distinct[i], distinct[j])));
    sum += nearest;
  }
  EXPECT_NEAR(q.average_minimum_distance * q.hexagonal_distance, sum / double(p.size()), 1e-15);

  std::mt19937_64 rng(65);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<Point_3, Vector_3>> pn;
  for (int i = 0; i < 100; ++i) pn.push_back({Point_3(u(rng), u(rng), u(rng)), Vector_3(0, 0, 1)});
  for (int i = 0; i < 20000; ++i) pn.push_back({pn[0].first, Vector_3(0, 0, i % 2 ? 1 : -1)});
  Sampling_quality_options o;
  o.sigma_feature = 0.05;
  const Sampling_quality b = sampling_quality(pn, o);
  ASSERT_EQ(b.status, Status::success);
  EXPECT_EQ(b.minimum_distance, 0.0);
  sum = 0;
  for (std::size_t i = 1; i < 100; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < 102; ++j)  // the 100 and both normals at the copies' place
      if (j != i)
        nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(pn[i].first, pn[j].first) +
                                              (pn[i].second - pn[j].second).squared_length() / 0.0025));
    sum += nearest;
  }
  EXPECT_NEAR(b.average_minimum_distance * b.hexagonal_distance, sum / double(pn.size()), 1e-15);

  std::vector<Point_2> t = white_noise(40, 66);
  t.push_back(t[3]);
  t.push_back(t[3]);
  t.push_back(Point_2(t[5].x() + 1, t[5].y()));  // an image of point 5 on the unit torus
  Sampling_quality_options torus;
  torus.periodic = true;
  torus.period = {1, 1};
  const Sampling_quality tq = sampling_quality(t, torus);
  const std::vector<double> nearest = torus_nearest(t, torus.period);
  double mean = 0;
  for (const double d : nearest) mean += d / double(t.size());
  EXPECT_EQ(tq.minimum_distance, 0.0);
  EXPECT_NEAR(tq.average_minimum_distance * tq.hexagonal_distance, mean, 1e-12);
}

TEST(SamplingQuality, HexagonalLatticeHasRelativeRadiusOne) {
  std::vector<Point_2> p;
  for (int r = 0; r < 30; ++r)
    for (int c = 0; c < 30; ++c) p.emplace_back(c + 0.5 * (r % 2), r * std::sqrt(3.0) / 2);
  Sampling_quality_options o;
  o.domain_measure = double(p.size()) * std::sqrt(3.0) / 2;  // a hexagonal cell per point
  const Sampling_quality q = sampling_quality(p, o);
  EXPECT_NEAR(q.hexagonal_distance, 1.0, 1e-12);
  EXPECT_NEAR(q.relative_radius, 1.0, 1e-9);
  EXPECT_NEAR(q.average_minimum_distance, 1.0, 1e-9);
  // Exact predicates kernels work the same way.
  std::vector<CGAL::Epeck::Point_2> e;
  for (const Point_2& x : p) e.emplace_back(x.x(), x.y());
  EXPECT_NEAR(sampling_quality(e, o).relative_radius, 1.0, 1e-9);
}

TEST(SamplingQuality, FccLatticeInThreeDimensions) {
  std::vector<Point_3> p;  // FCC with nearest distance 1: cubic cell of side sqrt(2) with 4 points
  const double a = std::sqrt(2.0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        p.emplace_back(i * a, j * a, k * a);
        p.emplace_back((i + 0.5) * a, (j + 0.5) * a, k * a);
        p.emplace_back((i + 0.5) * a, j * a, (k + 0.5) * a);
        p.emplace_back(i * a, (j + 0.5) * a, (k + 0.5) * a);
      }
  Sampling_quality_options o;
  o.domain_measure = double(p.size()) / std::sqrt(2.0);
  const Sampling_quality q = sampling_quality(p, o);
  EXPECT_NEAR(q.relative_radius, 1.0, 1e-9);
}

TEST(SamplingQuality, BilateralDistancesSeparateFeatures) {
  // Two interleaved grids with opposite normals: spatially 0.5 apart, bilaterally far.
  std::vector<std::pair<Point_3, Vector_3>> p;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      p.push_back({Point_3(i, j, 0), Vector_3(0, 0, 1)});
      p.push_back({Point_3(i + 0.5, j, 0), Vector_3(0, 0, -1)});
    }
  Sampling_quality_options o;
  o.domain_measure = 100;
  o.intrinsic_dimension = 2;
  EXPECT_NEAR(sampling_quality(p, o).minimum_distance, 0.5, 1e-12);
  o.sigma_feature = 0.1;  // feature term 4 / 0.01: the nearest neighbour has the same normal, at distance 1
  EXPECT_NEAR(sampling_quality(p, o).minimum_distance, 1.0, 1e-12);
}

TEST(SamplingQuality, ProgressReportsAndStops) {
  // 10000 samples: reports at 0, 4096, 8192 of them and 1, increasing; a stop at the second report leaves
  // every statistic 0 and says interrupted. On the torus a clustered set needs the second, wider pass (as in
  // the seam test above): its reports run on into the second half, and a stop there is honoured too.
  const std::vector<Point_2> p = white_noise(10000, 4);
  std::vector<double> seen;
  Sampling_quality_options o;
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const Sampling_quality full = sampling_quality(p, o);
  EXPECT_EQ(full.status, Status::success);
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(full.minimum_distance, sampling_quality(p).minimum_distance);
  int calls = 0;
  o.progress = [&](double) { return ++calls < 2; };
  const Sampling_quality stopped = sampling_quality(p, o);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(stopped.samples, 10000u);
  EXPECT_EQ(stopped.minimum_distance, 0.0);
  EXPECT_EQ(stopped.relative_radius, 0.0);
  EXPECT_EQ(stopped.average_minimum_distance, 0.0);

  std::vector<Point_2> clustered{Point_2(0.2, 0.2), Point_2(0.8, 0.2)};
  for (int i = 0; i < 200; ++i) clustered.emplace_back(0.45 + 0.005 * (i % 20), 0.7 + 0.01 * (i / 20));
  o.periodic = true;
  seen.clear();
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  EXPECT_EQ(sampling_quality(clustered, o).status, Status::success);
  EXPECT_EQ(seen, (std::vector<double>{0.0, 0.5, 1.0}));  // first pass from 0, the second from 0.5
  o.progress = [&](double f) { return f < 0.5; };
  EXPECT_EQ(sampling_quality(clustered, o).status, Status::interrupted);
}

TEST(SamplingQuality, DegenerateAndBadInput) {
  EXPECT_EQ(sampling_quality(std::vector<Point_2>{}).status, Status::degenerate_input);
  EXPECT_EQ(sampling_quality(std::vector<Point_2>{Point_2(1, 1)}).status, Status::degenerate_input);
  EXPECT_EQ(sampling_quality(std::vector<Point_2>{Point_2(0, 0), Point_2(1, 1), Point_2(2, 2)}).status,
            Status::degenerate_input);  // collinear: zero area
  std::vector<Point_2> p = white_noise(10, 1);
  p[3] = Point_2(std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_quality(p); }, "item 3"));
  Sampling_quality_options o;
  o.sigma_position = 0;
  EXPECT_THROW(sampling_quality(white_noise(10, 1), o), std::invalid_argument);
}
}  // namespace

namespace {
// Continuous dart throwing on the unit torus (a test-only reference set): candidates until `fails` in a row
// are rejected.
std::vector<Point_2> torus_darts(double r, int fails, unsigned seed) {
  std::mt19937_64 rng(seed);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  const int g = int(1 / r);
  std::vector<std::vector<int>> grid(std::size_t(g * g));
  std::vector<Point_2> s;
  for (int f = 0; f < fails;) {
    const double x = u(), y = u();
    const int cx = int(x * g) % g, cy = int(y * g) % g;
    bool ok = true;
    for (int a = -2; a <= 2 && ok; ++a)
      for (int b = -2; b <= 2 && ok; ++b)
        for (int j : grid[std::size_t(((cx + a + g) % g) * g + (cy + b + g) % g)]) {
          double dx = std::abs(s[std::size_t(j)].x() - x), dy = std::abs(s[std::size_t(j)].y() - y);
          dx = std::min(dx, 1 - dx);
          dy = std::min(dy, 1 - dy);
          if (dx * dx + dy * dy < r * r) ok = false;
        }
    if (!ok) {
      ++f;
      continue;
    }
    f = 0;
    grid[std::size_t(cx * g + cy)].push_back(int(s.size()));
    s.emplace_back(x, y);
  }
  return s;
}

TEST(SamplingSpectrum, WhiteNoiseIsFlatAndIsotropic) {
  std::vector<Sampling_spectrum> all;
  for (unsigned seed = 0; seed < 10; ++seed) all.push_back(sampling_spectrum(white_noise(1024, seed + 20)));
  const Sampling_spectrum s = average_sampling_spectra(all);
  ASSERT_EQ(s.radial_power.size(), 193u);  // F = 6 sqrt(1024): 12 units of sqrt(N)/2
  ASSERT_EQ(s.annulus_size.size(), 193u);
  EXPECT_EQ(s.annulus_size[0], 1u);  // DC alone
  EXPECT_EQ(s.annulus_size[1], 8u);  // |f| in {1, sqrt 2}
  double mean = 0, aniso = 0;
  for (std::size_t b = 8; b < s.radial_power.size(); ++b) {
    mean += s.radial_power[b] / double(s.radial_power.size() - 8);
    aniso += s.anisotropy[b] / double(s.radial_power.size() - 8);
  }
  EXPECT_NEAR(mean, 1.0, 0.02);
  EXPECT_NEAR(aniso, 0.0, 0.5);         // an exponential distribution per frequency: variance = mean^2
  EXPECT_EQ(s.effective_nyquist, 0.0);  // no zero region: the mean power of the first disc is already ~1
  EXPECT_LT(s.oscillation, 0.5);        // flat: only the noise of ten averaged periodograms
  EXPECT_LT(s.oscillation_from, 0.2);   // the power reaches 0.98 almost at once
  EXPECT_NEAR(s.oscillation_to - s.oscillation_from, 10.0, 1.0 / 16);  // a whole band of 10 units
  EXPECT_NEAR(s.radial_power[0], 1024.0, 1e-6);                        // the DC term is N
  EXPECT_THROW(average_sampling_spectra(all, 0.5), std::invalid_argument);
  Sampling_spectrum_options bad;
  bad.threshold = 0;
  EXPECT_THROW(sampling_spectrum(white_noise(16, 1), bad), std::invalid_argument);
  bad = {};
  bad.max_frequency = std::numeric_limits<std::size_t>::max();  // became -1: an Eigen assertion or worse
  EXPECT_THROW(sampling_spectrum(white_noise(16, 1), bad), std::invalid_argument);
  bad.max_frequency = 16385;
  EXPECT_THROW(sampling_spectrum(white_noise(16, 1), bad), std::invalid_argument);
}

TEST(SamplingSpectrum, SquareLatticeAndDartThrowing) {
  // A 32 x 32 lattice on the torus: zero power except at multiples of 32 (2 units of sqrt(N)/2), so the
  // quiet disc has radius 2 and nu_eff = 1 (to half an annulus), with huge oscillation.
  std::vector<Point_2> lattice;
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j) lattice.emplace_back((i + 0.5) / 32, (j + 0.5) / 32);
  const Sampling_spectrum l = sampling_spectrum(lattice);
  EXPECT_NEAR(l.effective_nyquist, 1.0, 1.0 / 32);
  EXPECT_NEAR(l.radial_power[1], 0.0, 1e-9);
  EXPECT_GT(l.anisotropy[32], 5.0);  // four spikes in the annulus: strongly anisotropic
  EXPECT_GT(l.oscillation, 20.0);
  // Maximal dart throwing at rho ~ 0.75, ten periodograms averaged: nu_eff ~ 0.62 and Omega ~ 1.35 over the
  // band from 1.87 to 11.9 units. The point-set analysis tool gives Bridson's sampler (rho 0.73) 0.616 and
  // 1.20 on 4096 points (design notes), the same definitions.
  std::vector<Sampling_spectrum> all;
  std::size_t n = 0;
  for (unsigned seed = 0; seed < 10; ++seed) {
    const std::vector<Point_2> s = torus_darts(0.025, 5000, seed);
    Sampling_spectrum_options o;
    o.max_frequency = 200;
    Sampling_spectrum sp = sampling_spectrum(s, o);
    if (n == 0) n = sp.samples;
    sp.samples = n;  // sets differ by a few points; average them on the first set's scale
    all.push_back(sp);
  }
  const Sampling_spectrum d = average_sampling_spectra(all);
  EXPECT_GT(d.effective_nyquist, 0.58);
  EXPECT_LT(d.effective_nyquist, 0.66);
  EXPECT_GT(d.oscillation, 1.1);
  EXPECT_LT(d.oscillation, 1.6);
  EXPECT_GT(d.oscillation_from, 1.7);
  EXPECT_LT(d.oscillation_from, 2.0);
  // A band cut short by the frequency range shows in oscillation_to, and Omega then overstates.
  std::vector<Sampling_spectrum> short_band;
  for (unsigned seed = 0; seed < 10; ++seed) {
    Sampling_spectrum_options o;
    o.max_frequency = 64;
    Sampling_spectrum sp = sampling_spectrum(torus_darts(0.025, 5000, seed), o);
    sp.samples = n;
    short_band.push_back(sp);
  }
  const Sampling_spectrum t = average_sampling_spectra(short_band);
  EXPECT_NEAR(t.effective_nyquist, d.effective_nyquist, 1e-12);  // the zero region lies inside both
  EXPECT_LT(t.oscillation_to, 4.1);
  EXPECT_GT(t.oscillation, d.oscillation);
  EXPECT_THROW(average_sampling_spectra({}), std::invalid_argument);
}
}  // namespace

// Boundaries pinned by a mutation audit of the sampling headers (session 45): each test fails when the
// comparison or constant it names is moved.
namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using namespace FeatureRecon::test;

// A spectrum given by its radial power and annulus sizes; average_sampling_spectra() of it alone recomputes
// the effective Nyquist frequency and the oscillation (finish_spectrum) from exactly these numbers.
Sampling_spectrum hand_made_spectrum(std::size_t samples, const std::vector<double>& power,
                                     const std::vector<std::size_t>& sizes) {
  Sampling_spectrum s;
  s.samples = samples;
  s.radial_power = power;
  s.annulus_size = sizes;
  s.anisotropy.assign(power.size(), 0.0);
  s.frequency.assign(power.size(), 0.0);
  return s;
}

TEST(SamplingSpectrum, ZeroRegionSearchStartsAtTheDiscOfRadiusExactlyOneUnit) {
  // N = 25: nu_N = 2.5 integer frequencies, so annulus 2 (disc radius 2 + 1/2) is the first disc of at least
  // one unit, inclusive (b + 1/2 >= nu). Its mean power 1 > 0.5 ends the search there; disc 1 (mean 0) lies
  // below the threshold 0.1, so nu* is interpolated between 1.5 and 2.5: 1.5 + (0.1 - 0) / (1 - 0) = 1.6,
  // nu_eff = 1.6 / 2.5 / 2 = 0.32. Starting one annulus later (b + 1/2 > nu) finds disc 4 and gives about
  // 0.73; dropping the half annulus of the interpolation gives 0.22.
  const Sampling_spectrum s =
      average_sampling_spectra({hand_made_spectrum(25, {25, 0, 2, 0, 1}, {1, 1, 1, 100, 1000})});
  EXPECT_DOUBLE_EQ(s.effective_nyquist, 0.32);
}

TEST(SamplingSpectrum, ADiscMeanOfExactlyOneHalfDoesNotEndTheZeroRegion) {
  // N = 4 (nu_N = 1). Disc 1 has mean power exactly 0.5: the search needs a mean above 0.5, so it goes on to
  // disc 3 (mean 100.5 / 111) and interpolates below it from disc 2 (mean 0.5 / 11): nu* = 2.5 + t. A
  // search that stopped at 0.5 would step down from disc 1 and report nu_eff 0.
  const Sampling_spectrum s =
      average_sampling_spectra({hand_made_spectrum(4, {4, 0.5, 0, 1}, {1, 1, 10, 100})});
  EXPECT_DOUBLE_EQ(s.effective_nyquist, 1.2817142857142858);  // (2.5 + t) / 1 / 2, measured
}

TEST(SamplingSpectrum, ADiscMeanOfExactlyTheThresholdIsNotQuiet) {
  // N = 4, threshold 0.1: disc 1 has mean exactly 0.1, which is not below the threshold, so the zero region
  // is empty (nu_eff 0). Counting it as quiet would give nu* = 1.5 + 0, nu_eff 0.75.
  const Sampling_spectrum s = average_sampling_spectra({hand_made_spectrum(4, {4, 0.1, 1}, {1, 1, 1})}, 0.1);
  EXPECT_EQ(s.effective_nyquist, 0.0);
}

TEST(SamplingSpectrum, AQuietSpectrumReportsItsLastHalfAnnulus) {
  // No disc reaches 0.5: nu* is the lower bound bins - 1/2 = 3.5 (N = 4, nu_N = 1): nu_eff = 1.75, and no
  // annulus reaches 0.98, so there is no oscillation band.
  const Sampling_spectrum s = average_sampling_spectra({hand_made_spectrum(4, {4, 0, 0, 0}, {1, 8, 12, 16})});
  EXPECT_DOUBLE_EQ(s.effective_nyquist, 1.75);
  EXPECT_EQ(s.oscillation, 0.0);
}

TEST(SamplingSpectrum, OscillationBandStartsAtExactlyPointNineEightAndEndsInclusively) {
  // N = 2: nu_N = sqrt(2) / 2, so the band is ceil(10 nu_N) = ceil(7.07) = 8 annuli long. Annulus 2 has power
  // exactly 0.98 and starts the band (>= 0.98); the band ends at annulus 2 + 8 = 10, included, whose power 3
  // dominates Omega. Pinned: oscillation_from = 2 / nu_N, oscillation_to = 10 / nu_N, and Omega itself.
  const std::vector<double> power{2, 0.5, 0.98, 1, 1, 1, 1, 1, 1, 1, 3, 1};
  const std::vector<std::size_t> sizes{1, 8, 12, 16, 32, 28, 40, 40, 48, 56, 68, 56};
  const Sampling_spectrum s = average_sampling_spectra({hand_made_spectrum(2, power, sizes)});
  const double nu = std::sqrt(2.0) / 2;
  EXPECT_DOUBLE_EQ(s.oscillation_from, 2 / nu);
  EXPECT_DOUBLE_EQ(s.oscillation_to, 10 / nu);
  EXPECT_DOUBLE_EQ(s.oscillation, 8.9443508296972496);  // measured: 10 sqrt(sum d^2 a / sum a)
}

TEST(SamplingQuality, PeriodicDefaultMeasureIsTheUnitCell) {
  // On the torus the default
  // domain measure is the unit square, not the bounding box of the samples (here 0.5 x 0.5): d_hex for
  // N = 4 is sqrt(2 / (sqrt(3) 4)).
  const std::vector<Point_2> p{Point_2(0.1, 0.1), Point_2(0.6, 0.1), Point_2(0.1, 0.6), Point_2(0.6, 0.6)};
  Sampling_quality_options o;
  o.periodic = true;
  const Sampling_quality q = sampling_quality(p, o);
  EXPECT_EQ(q.status, Status::success);
  EXPECT_EQ(q.domain_measure, 1.0);
  EXPECT_DOUBLE_EQ(q.hexagonal_distance, std::sqrt(2 / (std::sqrt(3.0) * 4)));
  EXPECT_DOUBLE_EQ(q.minimum_distance, 0.5);  // the lattice of spacing 0.5, also across the seam
}

TEST(SamplingSpectrum, FrequencyRangeBoundsAndDefault) {
  // max_frequency 16384 is the largest allowed (only 16385 was tried); with a single sample nothing is
  // allocated, the result is degenerate_input.
  Sampling_spectrum_options o;
  o.max_frequency = 16384;
  Sampling_spectrum s;
  EXPECT_NO_THROW(s = sampling_spectrum(white_noise(1, 3), o));
  EXPECT_EQ(s.status, Status::degenerate_input);
  // The default F is 6 sqrt(N) rounded up: 6 sqrt(10) = 18.97 gives F = 19, annuli 0..19.
  const Sampling_spectrum t = sampling_spectrum(white_noise(10, 3));
  EXPECT_EQ(t.radial_power.size(), 20u);
}

TEST(SamplingSpectrum, AveragingRefusesSpectraOfOtherSampleCounts) {
  // Spectra of 64 and
  // 65 samples with the same frequency range (F = 48) differ in their unit sqrt(N) / 2: refused.
  Sampling_spectrum_options o;
  o.max_frequency = 48;
  const Sampling_spectrum a = sampling_spectrum(white_noise(64, 1), o);
  const Sampling_spectrum b = sampling_spectrum(white_noise(65, 2), o);
  ASSERT_EQ(a.radial_power.size(), b.radial_power.size());
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        average_sampling_spectra({a, b});
      },
      "spectrum 1 has 65 samples"));
}

TEST(SamplingSpectrum, AnisotropyUsesTheSampleVarianceOfTheAnnulus) {
  // Two samples at
  // (0, 0) and (0.5, 0): P(f) = 1 + cos(pi f_x), 2 for even f_x and 0 for odd. Annulus 1 holds the 8
  // frequencies (+-1, 0), (0, +-1), (+-1, +-1) with powers 0, 0, 2, 2, 0, 0, 0, 0: mean 0.5, sample variance
  // (8 - 8 * 0.25) / 7 = 6 / 7, anisotropy 10 log10((6 / 7) / 0.25) = 10 log10(24 / 7).
  const std::vector<Point_2> p{Point_2(0, 0), Point_2(0.5, 0)};
  Sampling_spectrum_options o;
  o.max_frequency = 4;
  const Sampling_spectrum s = sampling_spectrum(p, o);
  ASSERT_EQ(s.annulus_size.size(), 5u);
  EXPECT_EQ(s.annulus_size[1], 8u);
  EXPECT_NEAR(s.radial_power[1], 0.5, 1e-12);
  EXPECT_NEAR(s.anisotropy[1], 10 * std::log10(24.0 / 7.0), 1e-9);
}
}  // namespace

// The periodogram's two evaluations: the non-uniform FFT (gridded) against the direct sums and against closed
// forms.
namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using namespace FeatureRecon::test;

double largest_difference(const sampling::internal::Periodogram_sums& a,
                          const sampling::internal::Periodogram_sums& b) {
  EXPECT_EQ(a.rows(), b.rows());
  EXPECT_EQ(a.cols(), b.cols());
  return (a - b).cwiseAbs().maxCoeff();
}

TEST(SamplingSpectrum, GriddedSumsAgreeWithTheDirectSums) {
  // Awkward positions (in [0, 1), as sampling_spectrum() hands them over): both ends of the unit interval,
  // points on the grid's lines (k / G), duplicates, and a cluster; every range of F, from grids smaller than
  // the spreading Gaussian (F = 1: 8 cells, the Gaussian spans 24, so it wraps onto itself) to F = 150.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  sampling::internal::Torus_points p;
  for (int i = 0; i < 400; ++i) p.push_back({u(rng), u(rng)});
  for (int i = 0; i < 100; ++i) p.push_back({0.3 + 0.001 * u(rng), 0.7 + 0.001 * u(rng)});  // a cluster
  p.push_back({0.0, 0.0});
  p.push_back({0.0, 0.0});
  p.push_back({std::nextafter(1.0, 0.0), 0.5});
  p.push_back({0.5, std::nextafter(1.0, 0.0)});
  for (const long F : {1L, 2L, 7L, 40L, 150L}) {
    const double G = double(sampling::internal::periodogram_grid_size(F));
    sampling::internal::Torus_points q = p;
    for (int k = 0; k < 8; ++k) q.push_back({double(k) / G, double((3 * k + 1) % 8) / G});
    sampling::internal::Periodogram_sums direct, gridded;
    ASSERT_TRUE(sampling::internal::direct_periodogram_sums(q, F, direct, {}, 0, 1));
    ASSERT_TRUE(sampling::internal::gridded_periodogram_sums(q, F, gridded, {}, 0, 1));
    EXPECT_EQ(direct.rows(), 2 * F + 1);
    EXPECT_EQ(gridded.rows(), long(G));  // the sums in its first 2F + 1 rows
    EXPECT_EQ(gridded.cols(), F + 1);
    EXPECT_LT(largest_difference(gridded.topRows(2 * F + 1), direct), 2e-11 * double(q.size()))
        << "F = " << F;
    EXPECT_NEAR(gridded(F, 0).real(), double(q.size()), 2e-11 * double(q.size()));  // DC: N
  }
}

TEST(SamplingSpectrum, GriddedSumsOfTwoSamplesHaveTheirClosedForm) {
  // Samples at (0, 0) and (0.5, 0.25): S(f) = 1 + exp(-i pi (f_x + f_y / 2)), so P(f) = |S|^2 / 2 = 1 +
  // cos(pi (f_x + f_y / 2)), at every frequency of both methods.
  const sampling::internal::Torus_points p{{0.0, 0.0}, {0.5, 0.25}};
  const long F = 30;
  for (const bool gridded : {false, true}) {
    sampling::internal::Periodogram_sums sums;
    ASSERT_TRUE(gridded ? sampling::internal::gridded_periodogram_sums(p, F, sums, {}, 0, 1)
                        : sampling::internal::direct_periodogram_sums(p, F, sums, {}, 0, 1));
    const double pi = 3.141592653589793238463;
    for (long fx = -F; fx <= F; ++fx)
      for (long fy = 0; fy <= F; ++fy)
        ASSERT_NEAR(std::norm(sums(fx + F, fy)) / 2, 1 + std::cos(pi * (double(fx) + double(fy) / 2)), 1e-10)
            << (gridded ? "gridded" : "direct") << " at (" << fx << ", " << fy << ")";
  }
}

TEST(SamplingSpectrum, GriddedSumsOfOneClusteredPointAtHighFrequencies) {
  // 50 samples at one point: S(f) = 50 exp(-2 pi i f . p) exactly, the gridded method's worst case (every
  // sample's spreading error adds up); at F = 400 within 3e-11 N of it everywhere, corners included.
  const sampling::internal::Torus_points p(50, {0.3183098861837907, 0.7071067811865476});
  const long F = 400;
  sampling::internal::Periodogram_sums sums;
  ASSERT_TRUE(sampling::internal::gridded_periodogram_sums(p, F, sums, {}, 0, 1));
  const double two_pi = 6.283185307179586476925;
  double worst = 0;
  for (long fx = -F; fx <= F; ++fx)
    for (long fy = 0; fy <= F; ++fy) {
      const std::complex<double> exact =
          50.0 * std::polar(1.0, -two_pi * (double(fx) * p[0][0] + double(fy) * p[0][1]));
      worst = std::max(worst, std::abs(sums(fx + F, fy) - exact));
    }
  EXPECT_LT(worst, 3e-11 * 50);
  EXPECT_GT(worst, 0.0);  // not the direct sums by mistake: those are exact to rounding, ~1e-13 here
}

TEST(SamplingSpectrum, BothMethodsReportProgressOftenWhereOneStepIsLong) {
  // Direct sums at F = 1000 take 2 million multiply-adds a sample: blocks of 49 samples, not 256 (one report
  // for 100 samples); the gridded method at F = 2 has a grid of 24 rows, one report by rows, and reports
  // every 65,536 samples spread as well (100,000 samples reach 24 rows each: 36 reports).
  std::vector<double> seen;
  sampling::internal::Torus_points few;
  for (int i = 0; i < 100; ++i) few.push_back({0.01 * i, 0.5});
  sampling::internal::Periodogram_sums sums;
  ASSERT_TRUE(sampling::internal::direct_periodogram_sums(few, 1000, sums, recording_progress(seen), 0, 1));
  EXPECT_EQ(seen.size(), 3u);  // at samples 0, 49, 98
  seen.clear();
  sampling::internal::Torus_points many(100000, {0.25, 0.75});
  ASSERT_TRUE(sampling::internal::gridded_periodogram_sums(many, 2, sums, recording_progress(seen), 0, 1));
  EXPECT_GE(seen.size(), 36u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

// From a mutation audit of periodogram.h: a progress callback that returns false stops either method at that
// report: the sums return false and the callback is not called again (the direct sums at their second block,
// the gridded method in its spreading by rows, before the columns' transforms).
TEST(SamplingSpectrum, BothMethodsStopAtTheFirstReportThatAsksTo) {
  std::size_t after_stop = 0;
  bool stopped = false;
  const FeatureRecon::Progress_callback stop_from_0_3 = [&](double t) {
    if (stopped) ++after_stop;
    stopped = stopped || t >= 0.3;
    return !stopped;
  };
  sampling::internal::Torus_points few;
  for (int i = 0; i < 100; ++i) few.push_back({0.01 * i, 0.5});
  sampling::internal::Periodogram_sums sums;
  EXPECT_FALSE(sampling::internal::direct_periodogram_sums(few, 1000, sums, stop_from_0_3, 0, 1));
  EXPECT_TRUE(stopped);
  EXPECT_EQ(after_stop, 0u);
  stopped = false;
  EXPECT_FALSE(sampling::internal::gridded_periodogram_sums(few, 100, sums, stop_from_0_3, 0, 1));
  EXPECT_TRUE(stopped);
  EXPECT_EQ(after_stop, 0u);
}

TEST(SamplingSpectrum, TorusCoordinatesLieInTheUnitInterval) {
  // Shared by the spectrum, the periodic quality measures and periodic dart throwing: -1e-20 - floor(-1e-20)
  // is 1.0 in floating point, which is the torus's 0.
  EXPECT_EQ(-1e-20 - std::floor(-1e-20), 1.0);
  EXPECT_EQ(sampling::internal::torus_coordinate(-1e-20), 0.0);
  EXPECT_EQ(sampling::internal::torus_coordinate(1.0), 0.0);
  EXPECT_EQ(sampling::internal::torus_coordinate(-0.25), 0.75);
  EXPECT_EQ(sampling::internal::torus_coordinate(3.5), 0.5);
  EXPECT_EQ(sampling::internal::torus_coordinate(0.0), 0.0);
  // Other periods (fmod, exact, moved up by a period when negative): in [0, period), -1e-20 again 0.
  using sampling::internal::torus_coordinate;
  EXPECT_EQ(torus_coordinate(-1e-20, 3), 0.0);
  EXPECT_EQ(torus_coordinate(3.0, 3), 0.0);
  EXPECT_EQ(torus_coordinate(-3.0, 3), 0.0);
  EXPECT_FALSE(std::signbit(torus_coordinate(-3.0, 3)));  // fmod gives -0: the torus's 0 is +0
  EXPECT_FALSE(std::signbit(torus_coordinate(-0.0, 3)));
  EXPECT_FALSE(std::signbit(torus_coordinate(-0.0)));
  EXPECT_EQ(torus_coordinate(-0.5, 3), 2.5);
  EXPECT_EQ(torus_coordinate(7.25, 3), 1.25);
  EXPECT_EQ(torus_coordinate(0.3, 0.1), std::fmod(0.3, 0.1));  // 0.09999999999999998: 0.3 is below 3 x 0.1
  EXPECT_LT(torus_coordinate(0.3, 0.1), 0.1);
  for (const double x : {-1e300, -12345.678, -1e-300, 1e-300, 98765.4321, 1e300}) {
    const double t = torus_coordinate(x, 0.7);
    EXPECT_TRUE(t >= 0 && t < 0.7) << x << " -> " << t;
  }
}

TEST(SamplingSpectrum, DefaultFrequencyIsRefusedAboveTheLimit) {
  // 6 sqrt(N) rounded up reaches 16384 at N = 7,456,540 and passes it one sample later: refused, naming the
  // option to give; a given max_frequency is taken as it is.
  EXPECT_EQ(sampling::internal::spectrum_frequency(7456540, 0, "f"), 16384);
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [] { sampling::internal::spectrum_frequency(7456541, 0, "f"); },
      "f: the default max_frequency 6 sqrt(N) is 16385 for 7456541 samples, above the limit "
      "16384: give max_frequency"));
  EXPECT_EQ(sampling::internal::spectrum_frequency(7456541, 100, "f"), 100);
  EXPECT_EQ(sampling::internal::spectrum_frequency(10, 0, "f"), 19);
}

TEST(SamplingSpectrum, MethodsAgreeOnTheStatisticsAndTheChoiceIsReported) {
  // 3000 samples at F = 60, and a lattice with its spikes: the radial power, anisotropy, nu_eff and Omega of
  // both methods agree; the automatic method is direct for 10 samples (F = 19) and gridded for 1000 (F =
  // 190).
  std::vector<std::vector<Point_2>> sets{white_noise(3000, 5), {}};
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) sets[1].emplace_back((i + 0.25) / 24, (j + 0.5) / 24 - 1);  // wraps
  for (const auto& s : sets) {
    Sampling_spectrum_options o;
    o.max_frequency = 60;
    o.method = Spectrum_method::direct;
    const Sampling_spectrum d = sampling_spectrum(s, o);
    o.method = Spectrum_method::gridded;
    const Sampling_spectrum g = sampling_spectrum(s, o);
    EXPECT_EQ(d.method, Spectrum_method::direct);
    EXPECT_EQ(g.method, Spectrum_method::gridded);
    ASSERT_EQ(g.radial_power.size(), d.radial_power.size());
    for (std::size_t b = 0; b < d.radial_power.size(); ++b) {
      EXPECT_NEAR(g.radial_power[b], d.radial_power[b], 1e-9 * (1 + d.radial_power[b])) << b;
      if (d.radial_power[b] > 1e-6) {  // the lattice's empty annuli have anisotropy from rounding alone
        EXPECT_NEAR(g.anisotropy[b], d.anisotropy[b], 1e-6) << b;
      }
    }
    EXPECT_NEAR(g.effective_nyquist, d.effective_nyquist, 1e-9);
    EXPECT_NEAR(g.oscillation, d.oscillation, 1e-9 * (1 + d.oscillation));
  }
  EXPECT_NEAR(sampling_spectrum(sets[1]).effective_nyquist, 1.0, 1.0 / 24);  // 576 samples: gridded
  EXPECT_EQ(sampling_spectrum(white_noise(10, 1)).method, Spectrum_method::direct);
  EXPECT_EQ(sampling_spectrum(white_noise(1000, 1)).method, Spectrum_method::gridded);
  EXPECT_EQ(sampling_spectrum(white_noise(1, 1)).method, Spectrum_method::automatic);  // nothing evaluated
}

TEST(SamplingSpectrum, GriddedMethodReportsProgressStopsAndRepeatsItself) {
  const std::vector<Point_2> p = white_noise(2000, 9);
  Sampling_spectrum_options o;
  o.method = Spectrum_method::gridded;
  std::vector<double> seen;
  o.progress = recording_progress(seen);
  const Sampling_spectrum a = sampling_spectrum(p, o);
  ASSERT_GT(seen.size(), 10u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  o.progress = {};
  const Sampling_spectrum b = sampling_spectrum(p, o);  // bit for bit the same
  EXPECT_EQ(a.radial_power, b.radial_power);
  EXPECT_EQ(a.anisotropy, b.anisotropy);
  for (const double stop_at : {0.5, 0.9}) {  // in the spreading, in the columns' transforms
    o.progress = [stop_at](double t) { return t < stop_at; };
    const Sampling_spectrum c = sampling_spectrum(p, o);
    EXPECT_EQ(c.status, Status::interrupted) << stop_at;
    EXPECT_TRUE(c.radial_power.empty());
  }
}

// From a mutation audit of sample_set.h: the surface area of 3D samples of a surface.
TEST(SamplingQuality, SurfaceAreaOfUniformSamplesIsEstimatedWithoutBias) {
  // 3D samples with intrinsic_dimension 2 are measured by the area estimate: over the points, the area of
  // the disc reaching each one's 8th nearest other point, divided by 8 ("unbiased for uniform samples").
  // 6000 uniform samples of the unit sphere (no border) give 4 pi within 3 % (a 7th neighbour, or the point
  // itself counted as its first neighbour, gives 7/8 of it; a division by 7, 8/7).
  std::mt19937_64 rng(21);
  std::normal_distribution<double> g;
  std::vector<Point_3> sphere;
  for (int i = 0; i < 6000; ++i) {
    const Vector_3 v(g(rng), g(rng), g(rng));
    sphere.push_back(CGAL::ORIGIN + v / std::sqrt(v.squared_length()));
  }
  Sampling_quality_options o;
  o.intrinsic_dimension = 2;
  const Sampling_quality q = sampling_quality(sphere, o);
  EXPECT_EQ(q.status, Status::success);
  EXPECT_NEAR(q.domain_measure, 4 * M_PI, 0.03 * 4 * M_PI);
}

TEST(SamplingQuality, ASingleSampleOffTheLineOrPlaneOfTheOthersRaisesTheAffineDimension) {
  // Samples of lower affine dimension are degenerate; one sample off the line (2D) or the plane (3D) of all
  // the others is enough to make the set full-dimensional, whichever index it has: here the first one the
  // test can see (the third sample in 2D, the fourth in 3D) and a later one.
  for (std::size_t off = 2; off < 5; ++off) {
    std::vector<Point_2> p{{0, 0}, {1, 0}, {0.25, 0}, {0.5, 0}, {0.75, 0}};
    p[off] = Point_2(0.5, 1);
    EXPECT_EQ(sampling_quality(p).status, Status::success) << off;
    p[off] = Point_2(0.5, 0);
    EXPECT_EQ(sampling_quality(p).status, Status::degenerate_input) << off;
  }
  for (std::size_t off = 3; off < 6; ++off) {
    std::vector<Point_3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0.25, 0.5, 0}, {1, 1, 0}};
    p[off] = Point_3(0.5, 0.5, 1);
    EXPECT_EQ(sampling_quality(p).status, Status::success) << off;
    p[off] = Point_3(0.5, 0.25, 0);
    EXPECT_EQ(sampling_quality(p).status, Status::degenerate_input) << off;
  }
}
TEST(SamplingSpectrum, RectangularTorusIsMeasuredAsScaledToAreaOne) {
  // 60 random points, some outside the torus, against a brute-force periodogram in the torus's own
  // coordinates: the integer frequencies (k_x / W, k_y / H) at g = sqrt(W H) (k_x / W, k_y / H), binned by
  // round(|g|) up to annulus F (complete), DC alone in annulus 0; both methods. On the torus 3 x 1.2 and on
  // the strip 16 x 1 (aspect ratio 16: k_x = +-1 lie at |g| = 1/4, counted in annulus 1).
  std::mt19937_64 rng(12);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Point_2> points;
  for (int i = 0; i < 60; ++i) points.emplace_back(-3 + 9 * u(), -1 + 3 * u());
  const double pi = 3.141592653589793238463;
  const long F = 10;
  for (const std::array<double, 2> torus : {std::array<double, 2>{3, 1.2}, std::array<double, 2>{16, 1}}) {
    const double W = torus[0], H = torus[1];
    std::vector<double> sum(F + 1, 0.0);
    std::vector<std::size_t> size(F + 1, 0);
    for (long kx = -200; kx <= 200; ++kx)
      for (long ky = -200; ky <= 200; ++ky) {
        const double gx = std::sqrt(W * H) * double(kx) / W, gy = std::sqrt(W * H) * double(ky) / H;
        long b = std::lround(std::hypot(gx, gy));
        if (b > F) continue;
        if (b == 0 && (kx != 0 || ky != 0)) b = 1;
        std::complex<double> z = 0;
        for (const Point_2& p : points)
          z += std::polar(1.0, -2 * pi * (double(kx) * p.x() / W + double(ky) * p.y() / H));
        sum[std::size_t(b)] += std::norm(z) / 60;
        ++size[std::size_t(b)];
      }
    EXPECT_GT(size[std::size_t(F)], 45u);  // about 2 pi F = 63 frequencies: the brute force reaches them all
    for (const Spectrum_method method : {Spectrum_method::direct, Spectrum_method::gridded}) {
      Sampling_spectrum_options o;
      o.period = {W, H};
      o.max_frequency = F;
      o.method = method;
      const Sampling_spectrum s = sampling_spectrum(points, o);
      ASSERT_EQ(s.radial_power.size(), std::size_t(F + 1));
      EXPECT_EQ(s.annulus_size, size) << W << " x " << H;
      EXPECT_EQ(s.annulus_size[0], 1u);
      EXPECT_NEAR(s.radial_power[0], 60.0, 1e-9);
      for (long b = 0; b <= F; ++b)
        EXPECT_NEAR(s.radial_power[std::size_t(b)], sum[std::size_t(b)] / double(size[std::size_t(b)]), 1e-8)
            << W << " x " << H << ", annulus " << b
            << (method == Spectrum_method::direct ? " direct" : " gridded");
    }
  }
  // A set scaled with its square torus keeps its spectrum; the unit period is the unit torus, bit for bit.
  const std::vector<Point_2> noise = white_noise(300, 4);
  std::vector<Point_2> scaled;
  for (const Point_2& p : noise) scaled.emplace_back(2.5 * p.x(), 2.5 * p.y());
  Sampling_spectrum_options unit, wide;
  unit.period = {1, 1};
  wide.period = {2.5, 2.5};
  const Sampling_spectrum plain = sampling_spectrum(noise), one = sampling_spectrum(noise, unit),
                          big = sampling_spectrum(scaled, wide);
  EXPECT_EQ(one.radial_power, plain.radial_power);
  EXPECT_EQ(one.effective_nyquist, plain.effective_nyquist);
  ASSERT_EQ(big.radial_power.size(), plain.radial_power.size());
  for (std::size_t b = 0; b < plain.radial_power.size(); ++b)
    EXPECT_NEAR(big.radial_power[b], plain.radial_power[b], 1e-9 * (1 + plain.radial_power[b])) << b;
  // A square lattice 1/16 apart on the torus 1 x 2 (16 x 32 points) has nu_eff 1, as on the unit torus:
  // its spikes at |k_x| = 16 and |k_y| = 32 both lie at |g| = 16 sqrt(2), 2 units of sqrt(512)/2.
  std::vector<Point_2> lattice;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 32; ++j) lattice.emplace_back((i + 0.5) / 16, (j + 0.5) / 16);
  Sampling_spectrum_options tall;
  tall.period = {1, 2};
  const Sampling_spectrum l = sampling_spectrum(lattice, tall);
  EXPECT_NEAR(l.effective_nyquist, 1.0, 1.0 / 32);
  EXPECT_NEAR(l.radial_power[1], 0.0, 1e-9);
  EXPECT_GT(l.anisotropy[23], 5.0);  // the four spikes, in annulus round(22.6) = 23
  EXPECT_GT(l.radial_power[23], 10.0);
  // Refused: a period of another length, out of range, or too long and thin for the frequency range.
  Sampling_spectrum_options bad;
  bad.period = {1};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_spectrum(noise, bad); },
                                                 "period has 1 values for positions of dimension 2"));
  bad.period = {1, 0};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_spectrum(white_noise(1, 1), bad); },
                                                 "period[1] must be in [1e-150, 1e150], got 0"));
  bad.period = {1, 1e6};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { sampling_spectrum(noise, bad); },
      "period 1 x 1e+06 needs integer frequencies up to 104500 for max_frequency 104, above 16384 (the "
      "periodogram holds (2 K + 1)(K + 1) complex sums); max_frequency at most 15 on this torus"));
  bad.max_frequency = 16;  // (16.5) 1000 > 16384 (15 would be allowed: 7.7 GB of sums, not run here)
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_spectrum(white_noise(3, 1), bad); },
                                                 "up to 16500 for max_frequency 16"));
  bad.max_frequency = 0;
  bad.period = {1e-20, 1e20};  // a valid torus whose frequencies overflow a long: refused, not cast
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_spectrum(noise, bad); },
                                                 "max_frequency at most 0 on this torus"));
  // Spectra of tori of other shapes have other annuli: not averaged.
  Sampling_spectrum_options square, wide_torus;
  square.period = {1, 1};
  wide_torus.period = {2, 1};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        average_sampling_spectra({sampling_spectrum(noise, square), sampling_spectrum(noise, wide_torus)});
      },
      "spectrum 1 has other annuli than spectrum 0 (a torus of another aspect ratio)"));
}

}  // namespace

TEST(SamplingOptions, NamesOfTheStoppingReasons) {
  const std::pair<FeatureRecon::sampling::Lloyd_stop, const char*> names[] = {
      {FeatureRecon::sampling::Lloyd_stop::iteration_cap, "iteration_cap"},
      {FeatureRecon::sampling::Lloyd_stop::energy_tolerance, "energy_tolerance"},
      {FeatureRecon::sampling::Lloyd_stop::move_tolerance, "move_tolerance"},
      {FeatureRecon::sampling::Lloyd_stop::callback, "callback"},
      {FeatureRecon::sampling::Lloyd_stop::interrupted, "interrupted"},
      {FeatureRecon::sampling::Lloyd_stop::no_descent, "no_descent"}};
  for (const auto& [stop, name] : names) {
    EXPECT_STREQ(FeatureRecon::sampling::to_string(stop), name);
    std::ostringstream os;
    os << stop;
    EXPECT_EQ(os.str(), name);
  }
}
