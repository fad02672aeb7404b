// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Bilateral dart throwing on discrete domains: the Poisson-disk and maximality properties by brute force,
// adaptive radii, priorities, the target-count mode, thin walls, degenerate and bad input.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/continuous_dart_throwing.h>
#include <FeatureRecon/sampling/discrete_lloyd.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/internal/radius_search.h>
#include <FeatureRecon/sampling/kernel_relaxation.h>
#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include "sampling/sampling_test_utilities.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using namespace FeatureRecon::test;

template <class Range>
std::vector<std::size_t> darts(const Range& items, double r, const Dart_throwing_options& o = {}) {
  std::vector<std::size_t> kept;
  const auto res = bilateral_dart_throwing(items, r, std::back_inserter(kept), o);
  EXPECT_EQ(res.selected, kept.size());
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  return kept;
}

TEST(BilateralDartThrowing, PoissonDiskAndMaximalByBruteForce) {
  const std::vector<Point_2> p = white_noise(3000, 1);
  const double r = 0.04;
  const auto kept = darts(p, r);
  std::vector<bool> is_kept(p.size(), false);
  for (std::size_t i : kept) is_kept[i] = true;
  for (std::size_t a = 0; a < kept.size(); ++a)
    for (std::size_t b = a + 1; b < kept.size(); ++b)
      ASSERT_GE(std::sqrt(CGAL::squared_distance(p[kept[a]], p[kept[b]])), r);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (is_kept[i]) continue;
    bool covered = false;
    for (std::size_t k : kept) covered = covered || std::sqrt(CGAL::squared_distance(p[i], p[k])) < r;
    ASSERT_TRUE(covered) << "item " << i << " could have been kept: not maximal";
  }
}

// Dart throwing in a given order (decreasing priority, ties by index) by brute force: an item is kept when
// no kept item lies closer than r (Euclidean).
template <class P>
std::vector<std::size_t> darts_exactly(const std::vector<P>& p, double r,
                                       const std::vector<double>& priority) {
  std::vector<std::size_t> order(p.size()), kept;
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
  for (const std::size_t i : order) {
    bool conflict = false;
    for (const std::size_t j : kept) {
      double d2 = 0;
      for (int k = 0; k < p[i].dimension(); ++k) d2 += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
      conflict = conflict || std::sqrt(d2) < r;
    }
    if (!conflict) kept.push_back(i);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

TEST(BilateralDartThrowing, FarOutliersMatchTheBruteForce) {
  // Points in the unit square or cube beside far ones (one at 1e7 or 1e8, a cluster 0.01 wide, one just
  // beyond the bulk): the grid keeps the cells of a core box around the bulk in an array and the far ones in
  // a hash map (Uniform_grid.h). Thrown in a random order of priorities: the same items as the brute force.
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point_2> p = white_noise(3000, 43);
  p.emplace_back(1e7, 0);
  for (int i = 0; i < 30; ++i) p.emplace_back(5e6 + 0.01 * u(rng), -2e6 + 0.01 * u(rng));
  p.emplace_back(1.3, 0.5);
  std::vector<Point_3> s;
  for (int i = 0; i < 2000; ++i) s.emplace_back(u(rng), u(rng), u(rng));
  s.emplace_back(0, 0, 1e8);
  for (int i = 0; i < 30; ++i) s.emplace_back(-3e5 + 0.01 * u(rng), 0.01 * u(rng), 7e6);
  for (const double r : {0.004, 0.03}) {
    Dart_throwing_options o;
    o.priority.resize(p.size());
    for (double& x : o.priority) x = u(rng);
    EXPECT_EQ(darts(p, r, o), darts_exactly(p, r, o.priority)) << r;
    o.priority.resize(s.size());
    for (double& x : o.priority) x = u(rng);
    EXPECT_EQ(darts(s, 2 * r, o), darts_exactly(s, 2 * r, o.priority)) << r;
  }
}

TEST(BilateralDartThrowing, MaximalThrowReachesRelativeRadius) {
  // Maximal dart throwing: rho = r / d_hex(N) near 0.75 when the domain is densely sampled.
  const std::vector<Point_2> p = white_noise(100000, 2);
  const double r = 0.02;
  const auto kept = darts(p, r);
  const double d_hex = std::sqrt(2.0 / (std::sqrt(3.0) * double(kept.size())));
  EXPECT_GE(r / d_hex, 0.74) << kept.size() << " samples";
  std::vector<Point_2> s;
  for (std::size_t i : kept) s.push_back(p[i]);
  Sampling_quality_options q;
  q.domain_measure = 1;
  EXPECT_GE(sampling_quality(s, q).relative_radius, 0.74);
}

// Distance on the unit torus (nearest images), by brute force.
template <class P>
double torus_distance(const P& a, const P& b) {
  double sum = 0;
  for (int k = 0; k < a.dimension(); ++k) {
    double d = std::abs((a[k] - std::floor(a[k])) - (b[k] - std::floor(b[k])));
    d = std::min(d, 1 - d);
    sum += d * d;
  }
  return std::sqrt(sum);
}

TEST(BilateralDartThrowing, PeriodicThrowIsAMaximalPackingOfTheTorus) {
  // Positions modulo 1 (some candidates given one or two cells away), distances of the torus: no two kept
  // candidates closer than r across the seam, every rejected one within r of a kept one (brute force), in 2D
  // and 3D and at a radius above the torus's diameter sqrt(2) / 2 (every candidate conflicts with the first:
  // one kept). The
  // plain throw of the same candidates keeps pairs that the torus joins.
  for (const double r : {0.04, 0.75}) {
    std::vector<Point_2> p = white_noise(3000, 5);
    for (std::size_t i = 0; i < p.size(); i += 7) p[i] = Point_2(p[i].x() + 1, p[i].y() - 2);
    Dart_throwing_options o;
    o.periodic = true;
    const auto kept = darts(p, r, o);
    std::vector<bool> is_kept(p.size(), false);
    for (std::size_t i : kept) is_kept[i] = true;
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = a + 1; b < kept.size(); ++b) ASSERT_GE(torus_distance(p[kept[a]], p[kept[b]]), r);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (is_kept[i]) continue;
      bool covered = false;
      for (std::size_t k : kept) covered = covered || torus_distance(p[i], p[k]) < r;
      ASSERT_TRUE(covered) << "item " << i << " could have been kept: not maximal on the torus";
    }
    if (r > 0.5) {
      EXPECT_EQ(kept.size(), 1u);
      continue;
    }
    std::vector<Point_2> wrapped;
    for (const Point_2& q : white_noise(3000, 5)) wrapped.push_back(q);
    const auto plain = darts(wrapped, r);
    bool joined = false;
    for (std::size_t a = 0; a < plain.size() && !joined; ++a)
      for (std::size_t b = a + 1; b < plain.size() && !joined; ++b)
        joined = torus_distance(wrapped[plain[a]], wrapped[plain[b]]) < r;
    EXPECT_TRUE(joined) << "the plain throw kept no pair across the seam: the test would not tell";
  }
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point_3> q;
  for (int i = 0; i < 2000; ++i) q.emplace_back(u(rng), u(rng), u(rng) - 1);
  Dart_throwing_options o;
  o.periodic = true;
  const auto kept = darts(q, 0.12, o);
  for (std::size_t a = 0; a < kept.size(); ++a)
    for (std::size_t b = a + 1; b < kept.size(); ++b) ASSERT_GE(torus_distance(q[kept[a]], q[kept[b]]), 0.12);
  for (std::size_t i = 0; i < q.size(); ++i) {
    bool covered = std::binary_search(kept.begin(), kept.end(), i);
    for (std::size_t k : kept) covered = covered || torus_distance(q[i], q[k]) < 0.12;
    ASSERT_TRUE(covered) << "3D item " << i;
  }
}

// Distance on the torus of periods px x py (nearest images), by brute force on the positions reduced to the
// cell with fmod.
double box_torus_distance(const Point_2& a, const Point_2& b, double px, double py) {
  const auto wrap = [](double x, double p) { return x - p * std::floor(x / p); };
  double dx = std::abs(wrap(a.x(), px) - wrap(b.x(), px)), dy = std::abs(wrap(a.y(), py) - wrap(b.y(), py));
  dx = std::min(dx, px - dx);
  dy = std::min(dy, py - dy);
  return std::sqrt(dx * dx + dy * dy);
}

TEST(BilateralDartThrowing, PeriodicThrowIsAMaximalPackingOfABoxTorus) {
  // The torus [0, 2.5) x [0, 0.75) (Dart_throwing_options::period), some candidates given periods away from
  // the cell: no two kept closer than r (brute force with the box's nearest images, margin 1e-12), every
  // rejected one within r of a kept one; at r above half the short period (0.375) images across both seams
  // count; above the half diagonal (1.30) a single candidate is kept. The unit torus's throw of the same
  // candidates is no packing of this torus.
  for (const double r : {0.05, 0.3, 0.5, 1.4}) {
    std::vector<Point_2> p;
    for (const Point_2& q : white_noise(2000, 6)) p.emplace_back(2.5 * q.x(), 0.75 * q.y());
    for (std::size_t i = 0; i < p.size(); i += 7) p[i] = Point_2(p[i].x() - 5, p[i].y() + 1.5);
    Dart_throwing_options o;
    o.periodic = true;
    o.period = {2.5, 0.75};
    const auto kept = darts(p, r, o);
    std::vector<bool> is_kept(p.size(), false);
    for (std::size_t i : kept) is_kept[i] = true;
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = a + 1; b < kept.size(); ++b)
        ASSERT_GE(box_torus_distance(p[kept[a]], p[kept[b]], 2.5, 0.75), r - 1e-12) << r;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (is_kept[i]) continue;
      bool covered = false;
      for (std::size_t k : kept) covered = covered || box_torus_distance(p[i], p[k], 2.5, 0.75) < r + 1e-12;
      ASSERT_TRUE(covered) << "item " << i << " at r " << r << " could have been kept";
    }
    if (r > 1.31) {
      EXPECT_EQ(kept.size(), 1u);
    }
    if (r == 0.05) {
      Dart_throwing_options unit;
      unit.periodic = true;
      const auto other = darts(p, r, unit);
      bool joined = false;
      for (std::size_t a = 0; a < other.size() && !joined; ++a)
        for (std::size_t b = a + 1; b < other.size() && !joined; ++b)
          joined = box_torus_distance(p[other[a]], p[other[b]], 2.5, 0.75) < r - 1e-12;
      EXPECT_TRUE(joined) << "the unit torus's throw packs this torus too: the test would not tell";
    }
  }
}

TEST(BilateralDartThrowing, TargetCountOnABoxTorusIsAPackingAtItsRadius) {
  // The count search on the torus [0, 25) x [0, 8): random points, and a grid of unit spacing (the pixels of
  // a 25 x 8 picture, where the count jumps over the target at single distances and the search stops on the
  // nearest distances within its throws, taken on the torus): exactly `count` kept, no two closer than the
  // returned radius on the torus (brute force), and for random points the plain throw at that radius keeps
  // the same items.
  std::vector<Point_2> noise, grid;
  for (const Point_2& q : white_noise(2000, 12)) noise.emplace_back(25 * q.x(), 8 * q.y());
  for (int i = 0; i < 25; ++i)
    for (int j = 0; j < 8; ++j) grid.emplace_back(i + 0.5, j + 0.5);
  Dart_throwing_count_options c;
  c.darts.periodic = true;
  c.darts.period = {25, 8};
  for (const std::size_t count : {1, 3, 17, 40, 150}) {
    for (const auto* set : {&noise, &grid}) {
      std::vector<std::size_t> kept;
      const auto r = bilateral_dart_throwing_count(*set, count, std::back_inserter(kept), c);
      ASSERT_EQ(kept.size(), count);
      for (std::size_t a = 0; a < kept.size(); ++a)
        for (std::size_t b = a + 1; b < kept.size(); ++b)
          ASSERT_GE(box_torus_distance((*set)[kept[a]], (*set)[kept[b]], 25, 8), r.radius * (1 - 1e-12))
              << (set == &grid ? "grid " : "noise ") << count;
      if (set == &noise && count > 1) {
        EXPECT_EQ(darts(noise, r.radius, c.darts), kept) << count;
      }
    }
  }
}

TEST(BilateralDartThrowing, PeriodicThrowIsAMaximalPackingOfABoxTorusIn3D) {
  // The torus [0, 1) x [0, 2) x [0, 0.5), candidates a period away from the cell: a packing at r = 0.2 and
  // maximal (brute force over the 27 shifts).
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point_3> q;
  for (int i = 0; i < 1500; ++i) q.emplace_back(u(rng) + 1, 2 * u(rng), 0.5 * u(rng) - 0.5);
  const auto distance = [](const Point_3& a, const Point_3& b) {
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s < 27; ++s) {
      const double dx = a.x() - b.x() - double(s % 3 - 1);
      const double dy = a.y() - b.y() - 2.0 * (s / 3 % 3 - 1);
      const double dz = a.z() - b.z() - 0.5 * (s / 9 - 1);
      best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return best;
  };
  Dart_throwing_options o;
  o.periodic = true;
  o.period = {1, 2, 0.5};
  const auto kept = darts(q, 0.2, o);
  for (std::size_t a = 0; a < kept.size(); ++a)
    for (std::size_t b = a + 1; b < kept.size(); ++b)
      ASSERT_GE(distance(q[kept[a]], q[kept[b]]), 0.2 - 1e-12);
  for (std::size_t i = 0; i < q.size(); ++i) {
    bool covered = std::binary_search(kept.begin(), kept.end(), i);
    for (std::size_t k : kept) covered = covered || distance(q[i], q[k]) < 0.2 + 1e-12;
    ASSERT_TRUE(covered) << "3D item " << i;
  }
}

TEST(BilateralDartThrowing, PeriodsOfPowersOfTwoScaleTheUnitTorusExactly) {
  // Positions, periods and sigma_position 4 times a unit-torus run (exact in binary): the same items, by a
  // throw at a radius and by the count search (the same radius, bit for bit).
  std::vector<Point_2> unit = white_noise(3000, 9), scaled;
  for (std::size_t i = 0; i < unit.size(); i += 3) unit[i] = Point_2(unit[i].x() + 3, unit[i].y() - 1);
  for (const Point_2& q : unit) scaled.emplace_back(4 * q.x(), 4 * q.y());
  Dart_throwing_options a, b;
  a.periodic = b.periodic = true;
  b.period = {4, 4};
  b.sigma_position = 4;
  for (const double r : {0.03, 0.3, 0.6}) EXPECT_EQ(darts(unit, r, a), darts(scaled, r, b)) << r;
  for (const std::size_t count : {1, 17, 300}) {
    Dart_throwing_count_options ca, cb;
    ca.darts = a;
    cb.darts = b;
    std::vector<std::size_t> ka, kb;
    const auto ra = bilateral_dart_throwing_count(unit, count, std::back_inserter(ka), ca);
    const auto rb = bilateral_dart_throwing_count(scaled, count, std::back_inserter(kb), cb);
    EXPECT_EQ(ka, kb) << count;
    EXPECT_EQ(ra.radius, rb.radius) << count;
    EXPECT_EQ(ka.size(), count);
  }
}

TEST(BilateralDartThrowing, BadPeriodsAreNamed) {
  const std::vector<Point_2> p = white_noise(20, 10);
  Dart_throwing_options o;
  o.period = {1, 1};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { darts(p, 0.1, o); },
      "bilateral_dart_throwing: period is given (2 values) but periodic is false"));
  o.periodic = true;
  o.period = {1, 1, 1};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { darts(p, 0.1, o); },
                                                 "period has 3 values for positions of dimension 2"));
  o.period = {0.5, -1};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { darts(p, 0.1, o); },
                                                 "period[1] must be in [1e-150, 1e150], got -1"));
  Dart_throwing_count_options c;
  c.darts = o;
  std::vector<std::size_t> kept;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing_count(p, 5, std::back_inserter(kept), c); },
      "bilateral_dart_throwing_count: period[1] must be in"));
  c.darts.periodic = false;
  c.darts.period = {2, 2};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing_count(p, 5, std::back_inserter(kept), c); }, "but periodic is false"));
  EXPECT_TRUE(kept.empty());
}

TEST(BilateralDartThrowing, PeriodicThrowHasTheSpectrumOfMaximalPoissonDisk) {
  // The library's own darts on the torus, as the point-set analysis literature measures samplers: ten
  // maximal throws over 100,000 random candidates at r = 0.025 (about 1,000 samples, rho about 0.75), their
  // periodograms averaged: nu_eff and Omega in the ranges of continuous dart throwing on the torus
  // (test_sampling_quality.cpp: 0.58-0.66 and 1.1-1.6; PSA gives Bridson's sampler 0.616 and 1.20).
  std::vector<Sampling_spectrum> all;
  std::size_t n = 0;
  double rho = 0;
  for (unsigned seed = 0; seed < 10; ++seed) {
    const std::vector<Point_2> candidates = white_noise(100000, 100 + seed);
    Dart_throwing_options o;
    o.periodic = true;
    o.seed = seed;
    std::vector<Point_2> s;
    for (std::size_t i : darts(candidates, 0.025, o)) s.push_back(candidates[i]);
    rho += torus_relative_radius(s) / 10;
    Sampling_spectrum sp = torus_spectrum(s);
    if (n == 0) n = sp.samples;
    sp.samples = n;  // sets differ by a few samples; averaged on the first set's scale
    all.push_back(sp);
  }
  const Sampling_spectrum d = average_sampling_spectra(all);
  EXPECT_GT(rho, 0.74);  // measured 0.752, nu_eff 0.635, Omega 1.358 over [1.85, 11.90]
  EXPECT_GT(d.effective_nyquist, 0.58);
  EXPECT_LT(d.effective_nyquist, 0.66);
  EXPECT_GT(d.oscillation, 1.1);
  EXPECT_LT(d.oscillation, 1.6);
}

TEST(BilateralDartThrowing, SeedsPrioritiesAndAdaptiveRadii) {
  const std::vector<Point_2> p = white_noise(4000, 3);
  Dart_throwing_options o;
  o.seed = 5;
  EXPECT_EQ(darts(p, 0.05, o), darts(p, 0.05, o));
  o.seed = 6;
  const auto other = darts(p, 0.05, o);
  o.seed = 5;
  EXPECT_NE(darts(p, 0.05, o), other);
  // Priority: the highest-priority item is always kept, and the order no longer depends on the seed.
  o.priority.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) o.priority[i] = p[i].x();
  const auto by_priority = darts(p, 0.05, o);
  const std::size_t top = std::max_element(o.priority.begin(), o.priority.end()) - o.priority.begin();
  EXPECT_TRUE(std::binary_search(by_priority.begin(), by_priority.end(), top));
  o.seed = 99;
  EXPECT_EQ(darts(p, 0.05, o), by_priority);
  // Adaptive radii: a radius twice as large on the right half gives about four times fewer samples there.
  Dart_throwing_options a;
  for (const Point_2& q : p) a.radii.push_back(q.x() < 0.5 ? 0.03 : 0.06);
  std::size_t left = 0, right = 0;
  for (std::size_t i : darts(p, 1.0, a)) (p[i].x() < 0.5 ? left : right)++;
  EXPECT_GT(double(left), 2.5 * double(right)) << left << " vs " << right;
}

TEST(BilateralDartThrowing, TargetCount) {
  const std::vector<Point_2> p = white_noise(5000, 4);
  for (std::size_t count : {1u, 17u, 500u, 1200u}) {
    std::vector<std::size_t> kept;
    const auto r = bilateral_dart_throwing_count(p, count, std::back_inserter(kept));
    ASSERT_EQ(kept.size(), count);
    EXPECT_GT(r.radius, 0);
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = a + 1; b < kept.size(); ++b)
        ASSERT_GE(std::sqrt(CGAL::squared_distance(p[kept[a]], p[kept[b]])), r.radius);
  }
}

TEST(BilateralDartThrowing, TargetCountInterpolatesTheRadius) {
  // The count falls about as r^-2: interpolating log count against log r between the bracket's ends hits the
  // exact count in 6-11 throws on 5000 points (17, 500 and 1200 wanted), where a plain bisection took 10-20
  // (each throw is a progress call, plus the final one).
  // The progress rises as the bracket's log count ratio shrinks: before the final 1 it showed at most it /
  // 60, here below 0.2.
  const std::vector<Point_2> p = white_noise(5000, 4);
  for (const std::size_t count : {17u, 500u, 1200u}) {
    std::vector<double> shown;
    Dart_throwing_count_options o;
    o.darts.progress = [&shown](double f) {
      shown.push_back(f);
      return true;
    };
    std::vector<std::size_t> kept;
    const auto r = bilateral_dart_throwing_count(p, count, std::back_inserter(kept), o);
    EXPECT_EQ(r.status, Status::success);
    EXPECT_EQ(kept.size(), count);
    EXPECT_LE(shown.size(), 13u) << count;
    ASSERT_GE(shown.size(), 2u);
    EXPECT_TRUE(std::is_sorted(shown.begin(), shown.end())) << count;
    EXPECT_GE(shown.front(), 0.0);
    EXPECT_EQ(shown.back(), 1.0);
    EXPECT_LT(shown[shown.size() - 2], 1.0) << count;
    // (17 is kept by the first throw below the upper end: no bracket, no progress before the 1.)
    if (count != 17) {
      EXPECT_GT(shown[shown.size() - 2], 0.3) << count;
    }
  }
}

TEST(BilateralDartThrowing, TargetCountNearEveryItemFindsARadius) {
  // n - 1 of n: before a lower end is known the r^-2 guess from the upper end moved the radius by about 1 % a
  // throw, and 125 throws found no bracket: the first n - 1 items of the visiting order at radius 0, labelled
  // degenerate (a review: 30 of 30 seeds). Now each such step is at least a halving.
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const std::vector<Point_2> p = white_noise(2000, seed);
    for (const std::size_t count : {1999u, 1998u, 1995u, 1980u, 1900u}) {
      std::size_t calls = 0;
      Dart_throwing_count_options o;
      o.darts.progress = [&calls](double) { return ++calls > 0; };
      std::vector<std::size_t> kept;
      const auto r = bilateral_dart_throwing_count(p, count, std::back_inserter(kept), o);
      EXPECT_EQ(r.status, Status::success) << count;
      ASSERT_EQ(kept.size(), count);
      EXPECT_GT(r.radius, 0.0) << count;
      EXPECT_LE(calls, 60u) << count;
      double closest = std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < kept.size(); ++a)
        for (std::size_t b = a + 1; b < kept.size(); ++b)
          closest = std::min(closest, std::sqrt(CGAL::squared_distance(p[kept[a]], p[kept[b]])));
      EXPECT_GE(closest, r.radius * (1 - 1e-12)) << count;
    }
  }
}

TEST(BilateralDartThrowing, TargetCountStopsWhereTheCountJumpsOverIt) {
  // On a grid many pairs lie at one distance, and the count jumps over the goal there: no radius keeps
  // exactly 5000 or 1234 of these 60,000 points. The search used to shrink the bracket around the jump until
  // no double was left between its ends (all 60 steps, 54-64 throws); it now stops once the throws at its two
  // ends are known to be the only ones between (6-12 throws). Scaled by 0.1, or by 1/3 and shifted far from
  // the origin, the grid's equal distances differ in their last bits: the same items are kept. (With the
  // grid's coordinate range in place of the coordinates' magnitude in the rounding tolerance, the centimetre
  // grid in UTM coordinates took 32-39 throws and kept other items.)
  for (const std::size_t count : {5000u, 1234u}) {
    std::vector<std::size_t> first;
    // {spacing, x and y of the first point}: the last a centimetre grid in UTM coordinates (metres).
    for (const std::array<double, 3> grid :
         {std::array<double, 3>{1.0, 0, 0}, {0.1, 0, 0}, {1 / 3.0, 1000, -1000}, {0.01, 4.6e6, 4.4e6}}) {
      const double scale = grid[0];
      std::vector<Point_2> p;
      for (int i = 0; i < 300; ++i)
        for (int j = 0; j < 200; ++j) p.emplace_back(i * scale + grid[1], j * scale + grid[2]);
      std::size_t calls = 0;
      Dart_throwing_count_options o;
      o.darts.progress = [&calls](double) { return ++calls > 0; };
      std::vector<std::size_t> kept;
      const auto r = bilateral_dart_throwing_count(p, count, std::back_inserter(kept), o);
      EXPECT_EQ(r.status, Status::success);
      ASSERT_EQ(kept.size(), count);
      EXPECT_LE(calls, 15u) << count << " " << scale;
      // The radius is where the count jumps: its throw keeps more and holds the result, a radius just above
      // keeps fewer.
      const std::vector<std::size_t> at = darts(p, r.radius, o.darts);
      EXPECT_GT(at.size(), count);
      EXPECT_TRUE(std::includes(at.begin(), at.end(), kept.begin(), kept.end()));
      EXPECT_LT(darts(p, r.radius * (1 + 1e-6), o.darts).size(), count) << count << " " << scale;
      double closest = std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < kept.size(); ++a)
        for (std::size_t b = a + 1; b < kept.size(); ++b)
          closest = std::min(closest, CGAL::squared_distance(p[kept[a]], p[kept[b]]));
      EXPECT_GE(std::sqrt(closest), r.radius) << count << " " << scale;
      if (first.empty())
        first = kept;
      else
        EXPECT_EQ(kept, first) << count << " " << scale;
    }
  }
  // On the unit torus and on a grey picture (bilateral distance) as well.
  std::vector<Point_2> torus;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 120; ++j) torus.emplace_back(i / 120.0, j / 120.0);
  std::vector<std::uint8_t> values(160 * 120);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = (k % 160) / 40 % 2 != 0 ? 200 : 30;
  const auto pixels = image_pixels<Grey_pixel>(160, 120, values);
  for (const bool picture : {false, true}) {
    std::size_t calls = 0;
    Dart_throwing_count_options o;
    o.darts.periodic = !picture;
    if (picture) o.darts.sigma_feature = 0.2;
    o.darts.progress = [&calls](double) { return ++calls > 0; };
    std::vector<std::size_t> kept;
    const auto r =
        picture ? bilateral_dart_throwing_count(pixels, 700, std::back_inserter(kept), o, Grey_pixel_traits())
                : bilateral_dart_throwing_count(torus, 700, std::back_inserter(kept), o);
    ASSERT_EQ(kept.size(), 700u);
    EXPECT_LE(calls, 15u) << picture;
    const auto throw_at = [&](double radius) {
      std::vector<std::size_t> out;
      if (picture)
        bilateral_dart_throwing(pixels, radius, std::back_inserter(out), o.darts, Grey_pixel_traits());
      else
        bilateral_dart_throwing(torus, radius, std::back_inserter(out), o.darts);
      return out;
    };
    const std::vector<std::size_t> at = throw_at(r.radius);
    EXPECT_GT(at.size(), 700u) << picture;
    EXPECT_TRUE(std::includes(at.begin(), at.end(), kept.begin(), kept.end())) << picture;
    EXPECT_LT(throw_at(r.radius * (1 + 1e-9)).size(), 700u) << picture;
  }
}

TEST(BilateralDartThrowing, CountSearchScalesPerItemRadii) {
  // Per-item radii with a target count: the search is on their factor t (radii t r(s)), and finds the jumps
  // of the count as with a uniform radius. On a picture of one grey (the radii all alike, as stippling gives
  // them) the count jumps over the goal on the pixel lattice: the command line's own search, which did not
  // know the jumps, threw 30 times (26 s on a 1024 x 1024 grey picture). Also adaptive radii (1 on the dark
  // stripes, 1.5 on the bright ones), one radius of 1e-12 among them (a tolerance and start bounds divided by
  // the least radius took false jumps and wasted throws), in the plane and on the torus of the picture; the
  // factor returned throws the set (a ratio rounded an ulp above a pair's distance over its radius lost the
  // pair: 900 dots at radii 1.5); a count tolerance, the whole throw (no cut) and a first guess.
  std::vector<std::uint8_t> stripes(160 * 120), grey(160 * 120, 128);
  for (std::size_t k = 0; k < stripes.size(); ++k) stripes[k] = (k % 160) / 40 % 2 != 0 ? 200 : 30;
  std::size_t window_hits = 0;
  for (const int shape : {0, 1, 2})  // 0: all 1.5; 1: stripes 1 and 1.5; 2: as 1 with radii[0] = 1e-12
    for (const bool periodic : {false, true})
      for (const std::size_t count : {std::size_t(500), std::size_t(900)}) {
        const auto pixels = image_pixels<Grey_pixel>(160, 120, shape == 0 ? grey : stripes);
        std::size_t calls = 0;
        Dart_throwing_count_options o;
        o.darts.sigma_feature = 0.2;
        o.darts.sigma_position = 4;
        o.darts.periodic = periodic;
        if (periodic) o.darts.period = {160, 120};
        for (const auto& p : pixels) o.darts.radii.push_back(shape != 0 && p.value == 30 ? 1.0 : 1.5);
        if (shape == 2) o.darts.radii[0] = 1e-12;
        o.darts.progress = [&calls](double) { return ++calls > 0; };
        std::vector<std::size_t> kept;
        const auto r =
            bilateral_dart_throwing_count(pixels, count, std::back_inserter(kept), o, Grey_pixel_traits());
        const std::string what = "shape " + std::to_string(shape) + (periodic ? ", torus, " : ", ") +
                                 std::to_string(count) + " items";
        EXPECT_EQ(r.status, Status::success) << what;
        ASSERT_EQ(kept.size(), count) << what;
        EXPECT_LE(calls, 15u) << what;
        // The set is (a part of) the throw at radii t r(s), the factor where the count jumps: just above,
        // fewer.
        const auto throw_at = [&](double t) {
          Dart_throwing_options d = o.darts;
          d.progress = nullptr;
          for (double& radius : d.radii) radius *= t;
          std::vector<std::size_t> out;
          bilateral_dart_throwing(pixels, 1.0, std::back_inserter(out), d, Grey_pixel_traits());
          return out;
        };
        const std::vector<std::size_t> at = throw_at(r.radius);
        EXPECT_GE(at.size(), count) << what;
        EXPECT_TRUE(std::includes(at.begin(), at.end(), kept.begin(), kept.end())) << what;
        if (at.size() > count) {
          EXPECT_LT(throw_at(r.radius * (1 + 1e-9)).size(), count) << what;
        }
        // With a tolerance of 5 % the search may end at a throw of up to 5 % more, cut to `count`; without
        // the cut, the whole of that throw.
        o.count_tolerance = 0.05;
        std::vector<std::size_t> loose, whole;
        const auto l =
            bilateral_dart_throwing_count(pixels, count, std::back_inserter(loose), o, Grey_pixel_traits());
        ASSERT_EQ(loose.size(), count) << what;
        const std::vector<std::size_t> loose_at = throw_at(l.radius);
        EXPECT_TRUE(std::includes(loose_at.begin(), loose_at.end(), loose.begin(), loose.end())) << what;
        if (loose_at.size() > count + count / 20) {
          EXPECT_LT(throw_at(l.radius * (1 + 1e-9)).size(), count) << what;
        }
        o.cut = false;
        bilateral_dart_throwing_count(pixels, count, std::back_inserter(whole), o, Grey_pixel_traits());
        EXPECT_EQ(whole, loose_at) << what;
        o.cut = true;
        // A first guess that lands in the window ends the search at its first throw (one report before it,
        // one at the end), with the same dots.
        if (loose_at.size() <= count + count / 20) {
          ++window_hits;
          o.initial_radius = l.radius;
          calls = 0;
          std::vector<std::size_t> guessed;
          bilateral_dart_throwing_count(pixels, count, std::back_inserter(guessed), o, Grey_pixel_traits());
          EXPECT_EQ(calls, 2u) << what;
          EXPECT_EQ(guessed, loose) << what;
        }
        o.initial_radius = -1;
        EXPECT_TRUE(test::throws_with<std::invalid_argument>(
            [&] {
              bilateral_dart_throwing_count(pixels, count, std::back_inserter(loose), o, Grey_pixel_traits());
            },
            "initial_radius must be finite and >= 0, got -1"))
            << what;
        o.initial_radius = 0;
        o.count_tolerance = 1.5;
        EXPECT_TRUE(test::throws_with<std::invalid_argument>(
            [&] {
              bilateral_dart_throwing_count(pixels, count, std::back_inserter(loose), o, Grey_pixel_traits());
            },
            "bilateral_dart_throwing_count: count_tolerance must be in [0, 1], got 1.5"))
            << what;
      }
  EXPECT_GT(window_hits, 0u);
}

TEST(BilateralDartThrowing, TheBoundsOfAThrowAreItsNearestConflictsAndItsClosestPair) {
  // The two bounds that end the count search, on small inputs by hand. Visiting order by priority: x = 0.1
  // and x = 1 are accepted first; at radius 0.6, x = 0.45 conflicts with both (0.35 and 0.55 away: its
  // nearest conflict is 0.35) and x = 0.3 with x = 0.1 only (0.2): the largest nearest conflict is 0.35. The
  // mirror image lists the two accepted items the other way round in the grid.
  using Traits = Default_traits_t<std::vector<Point_2>>;
  for (const bool mirror : {false, true}) {
    std::vector<Point_2> p;
    for (const double x : {0.1, 1.0, 0.45, 0.3}) p.emplace_back(mirror ? 1.1 - x : x, 0);
    const sampling::internal::Sample_set<Traits> S(p, Traits(), "test");
    Dart_throwing_options o;
    o.priority = {4, 3, 2, 1};
    bool interrupted = true;
    double largest = 0;
    const std::vector<std::uint32_t> kept = sampling::internal::throw_darts(
        S, 0.6, o, sampling::internal::dart_order(4, o), interrupted, &largest);
    EXPECT_FALSE(interrupted);
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_NEAR(largest, 0.35, 1e-12) << mirror;
    // Nothing rejected: -infinity. And the closest pair of the kept set (0.9 apart), or the cap.
    const std::vector<std::uint32_t> all = sampling::internal::throw_darts(
        S, 0.1, o, sampling::internal::dart_order(4, o), interrupted, &largest);
    EXPECT_EQ(all.size(), 4u);
    EXPECT_EQ(largest, -std::numeric_limits<double>::infinity());
    EXPECT_NEAR(sampling::internal::throw_separation(S, kept, 2.0, o, 0.0), 0.9, 1e-12);
    EXPECT_DOUBLE_EQ(sampling::internal::throw_separation(S, kept, 0.7, o, 0.0), 0.7);
    EXPECT_NEAR(sampling::internal::throw_separation(S, all, 2.0, o, 0.0), 0.15, 1e-12);
  }
  // On the unit torus the closest pair may lie across the seam: 0.02 and 0.95 are 0.07 apart there, 0.93 in
  // the plane.
  const std::vector<Point_2> t{{0.02, 0.5}, {0.95, 0.5}, {0.5, 0.5}};
  const sampling::internal::Sample_set<Traits> T(t, Traits(), "test");
  Dart_throwing_options o;
  o.periodic = true;
  EXPECT_NEAR(sampling::internal::throw_separation(T, {0, 1, 2}, 1.0, o, 0.0), 0.07, 1e-12);
  o.periodic = false;
  EXPECT_NEAR(sampling::internal::throw_separation(T, {0, 1, 2}, 1.0, o, 0.0), 0.45, 1e-12);
}

TEST(BilateralDartThrowing, ACapKeepsTheFirstInTheVisitingOrder) {
  // Points stored left to right: a cap of 40 keeps the first 40 accepted in the seeded order, spread over the
  // whole square (not the first 40 of the file), and they are the prefix of the uncapped throw's acceptances.
  std::vector<Point_2> p;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) p.emplace_back(i / 60.0, j / 60.0);
  Dart_throwing_options o;
  o.seed = 3;
  o.max_accepted = 40;
  std::vector<std::size_t> capped;
  const auto r = bilateral_dart_throwing(p, 0.05, std::back_inserter(capped), o);
  ASSERT_EQ(capped.size(), 40u);
  EXPECT_EQ(r.selected, 40u);
  std::size_t right_half = 0;
  for (const std::size_t i : capped) right_half += p[i].x() >= 0.5;
  EXPECT_GT(right_half, 10u);
  EXPECT_LT(right_half, 30u);
  o.max_accepted = 0;
  const std::vector<std::size_t> all = darts(p, 0.05, o);
  EXPECT_GT(all.size(), 40u);
  for (const std::size_t i : capped) EXPECT_TRUE(std::binary_search(all.begin(), all.end(), i)) << i;
  o.max_accepted = 5;
  Dart_throwing_count_options co;
  co.darts = o;
  std::vector<std::size_t> unused;
  EXPECT_THROW(bilateral_dart_throwing_count(p, 10, std::back_inserter(unused), co), std::invalid_argument);
}

TEST(BilateralDartThrowing, TargetCountWithTheExponentialForm) {
  // A 64 x 64 picture, black left half, white right half: with sigma_feature 0.03 the exponential form's
  // exp(|deta|^2 / sigma^2) overflows across the edge, so the largest distance from item 0 is infinite. The
  // count search must still bracket a radius (it used to return the first `count` items of the visiting order
  // as degenerate input).
  std::vector<std::uint8_t> values(64 * 64);
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) values[static_cast<std::size_t>(r * 64 + c)] = c < 32 ? 0 : 255;
  const auto pixels = image_pixels<Grey_pixel>(64, 64, values);
  for (const std::size_t count : {1u, 50u, 200u}) {
    Dart_throwing_count_options o;
    o.darts.form = Bilateral_form::exponential;
    o.darts.sigma_feature = 0.03;
    std::vector<std::size_t> kept;
    const auto r =
        bilateral_dart_throwing_count(pixels, count, std::back_inserter(kept), o, Grey_pixel_traits());
    EXPECT_EQ(r.status, Status::success) << count;
    ASSERT_EQ(kept.size(), count);
    EXPECT_GT(r.radius, 0) << count;
    EXPECT_TRUE(std::isfinite(r.radius)) << count;
    // Pixels of one colour are r.radius * sigma_position apart at least (xi = |dp| / sigma_position there).
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = a + 1; b < kept.size(); ++b) {
        const Grey_pixel &x = pixels[kept[a]], &y = pixels[kept[b]];
        if (x.value == y.value) {
          ASSERT_GE(std::hypot(x.column - y.column, x.row - y.row) / o.darts.sigma_position,
                    r.radius * (1 - 1e-12));
        }
      }
  }
  // The radius doubling before the bisection asks the callback at every throw (about 1000 throws here, none
  // of which could be stopped: 44 s on a 512 x 512 picture), and a stop there ends the run.
  Dart_throwing_count_options o;
  o.darts.form = Bilateral_form::exponential;
  o.darts.sigma_feature = 0.03;
  std::size_t calls = 0;
  o.darts.progress = [&calls](double) { return ++calls > 0; };
  std::vector<std::size_t> kept;
  EXPECT_EQ(bilateral_dart_throwing_count(pixels, 1, std::back_inserter(kept), o, Grey_pixel_traits()).status,
            Status::success);
  EXPECT_GT(calls, 100u);
  kept.clear();
  calls = 0;
  o.darts.progress = [&calls](double) { return ++calls < 10; };
  EXPECT_EQ(bilateral_dart_throwing_count(pixels, 1, std::back_inserter(kept), o, Grey_pixel_traits()).status,
            Status::interrupted);
  EXPECT_EQ(calls, 10u);
  EXPECT_TRUE(kept.empty());
}

TEST(BilateralDartThrowing, ThinWallKeepsBothSheets) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<Point_3, Vector_3>> wall;
  for (int i = 0; i < 6000; ++i) {
    const bool top = i % 2 == 1;
    wall.push_back({Point_3(u(rng), u(rng), top ? 0.01 : 0.0), Vector_3(0, 0, top ? 1 : -1)});
  }
  auto sheets = [&](const std::vector<std::size_t>& kept) {
    std::size_t top = 0;
    for (std::size_t i : kept) top += wall[i].second.z() > 0;
    return std::make_pair(kept.size() - top, top);
  };
  Dart_throwing_options o;
  o.sigma_feature = 0.1;
  const auto [b0, b1] = sheets(darts(wall, 0.05, o));
  o.sigma_feature = std::numeric_limits<double>::infinity();
  const auto [e0, e1] = sheets(darts(wall, 0.05, o));
  // Bilateral: each sheet is a maximal set on its own, as large as the Euclidean set of both sheets together.
  EXPECT_GT(double(std::min(b0, b1)), 0.8 * double(e0 + e1));
  // Euclidean: the sheets share one set, so each keeps only about half of what it needs.
  EXPECT_LT(double(std::max(e0, e1)), 0.7 * double(b0 + b1) / 2);
}

TEST(BilateralDartThrowing, PositionsTooWideForSigmaArePinnedAndRefused) {
  // Positions and sigma_position within their own limits but whose ratio squares past the doubles (white
  // noise scaled by 2^330 with sigma_position 2^-490: every bilateral distance became infinite, dart
  // throwing's bisection ran to radius 9e307 and returned an arbitrary set with status success) are refused
  // by every sampler, naming sigma_position. Up to 2^400 the samplers are scale invariant: the same indices
  // as at scale 1.
  const std::vector<Point_2> unit = white_noise(2000, 1);
  auto scaled = [&](int e) {
    std::vector<Point_2> p;
    for (const Point_2& q : unit) p.emplace_back(std::ldexp(q.x(), e), std::ldexp(q.y(), e));
    return p;
  };
  auto count = [](const std::vector<Point_2>& p, double sigma) {
    Dart_throwing_count_options o;
    o.darts.sigma_position = sigma;
    std::vector<std::size_t> kept;
    bilateral_dart_throwing_count(p, 200, std::back_inserter(kept), o);
    return kept;
  };
  auto eliminate = [](const std::vector<Point_2>& p, double sigma) {
    Elimination_options o;
    o.sigma_position = sigma;
    std::vector<std::size_t> kept;
    weighted_sample_elimination(p, 200, std::back_inserter(kept), o);
    return kept;
  };
  const auto wide = scaled(300);                                   // extent just below 2^300
  EXPECT_EQ(count(wide, std::ldexp(1.0, -99)), count(unit, 1.0));  // span / sigma just below 2^399
  EXPECT_EQ(eliminate(wide, std::ldexp(1.0, -99)), eliminate(unit, 1.0));
  const double too_small = std::ldexp(1.0, -101);  // span / sigma just below 2^401
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { count(wide, too_small); }, "sigma_position"));
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { eliminate(wide, too_small); }, "sigma_position"));
  std::vector<std::size_t> kept;
  Dart_throwing_options d;
  d.sigma_position = too_small;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing(wide, 1.0, std::back_inserter(kept), d); }, "sigma_position"));
  Sampling_quality_options q;
  q.sigma_position = too_small;
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { sampling_quality(wide, q); }, "sigma_position"));
  Continuous_dart_throwing_options c;
  c.sigma_position = too_small;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        continuous_bilateral_dart_throwing(
            {0, 0, std::ldexp(1.0, 300), 1}, 1.0, [](double, double) { return 0.0; },
            [](double, double) { return 0.0; }, c);
      },
      "sigma_position"));
  Kernel_relaxation_options<2> k;
  k.sigma_position = too_small;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        kernel_relaxation(wide, std::vector<std::size_t>{0, 5}, k);
      },
      "sigma_position"));
  Discrete_lloyd_options<2> l;
  l.sigma_position = too_small;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        discrete_bilateral_lloyd(wide, std::vector<std::size_t>{0, 5}, l);
      },
      "sigma_position"));
  // The sites count too: items in the unit square, sigma_position 1e-110, a site at 1e100 (a site far outside
  // was infinitely far from every item and tied with a nearer one: all items went to the farther site).
  Discrete_lloyd_options<2> s;
  s.sigma_position = 1e-110;
  using Site2 = Bilateral_site<Default_traits_t<std::vector<Point_2>>>;
  std::vector<Site2> sites(2);
  sites[0].position = {1e100, 0};
  sites[1].position = {0.9e100, 0};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { bilateral_voronoi_assignment(unit, sites, s); },
                                                 "sigma_position"));
  sites[0].position = {0.5, 0.5};
  sites[1].position = {0.25, 0.25};
  EXPECT_EQ(bilateral_voronoi_assignment(unit, sites, s).site.size(), unit.size());  // near sites: fine
}

TEST(BilateralDartThrowing, DegenerateInputs) {
  std::vector<std::size_t> kept;
  EXPECT_EQ(bilateral_dart_throwing(std::vector<Point_2>{}, 1.0, std::back_inserter(kept)).status,
            Status::degenerate_input);
  EXPECT_EQ(darts(std::vector<Point_2>{Point_2(0, 0)}, 1.0), (std::vector<std::size_t>{0}));
  // Duplicates conflict at any radius: one item per position.
  std::vector<Point_2> dup;
  for (int c = 0; c < 5; ++c)
    for (int i = 0; i < 4; ++i) dup.emplace_back(i, 0);
  EXPECT_EQ(darts(dup, 0.5).size(), 4u);
  const auto r =
      bilateral_dart_throwing_count(std::vector<Point_2>(6, Point_2(1, 1)), 3, std::back_inserter(kept));
  EXPECT_EQ(r.status, Status::degenerate_input);
  EXPECT_EQ(r.selected, 3u);
  // A grid: exact distances equal to the radius do not conflict (strict test), so r = 1 keeps every pixel.
  std::vector<Point_2> grid;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) grid.emplace_back(i, j);
  EXPECT_EQ(darts(grid, 1.0).size(), 100u);
  EXPECT_LT(darts(grid, 1.5).size(), 60u);
  // A radius whose square underflows: copies still conflict (the prefilter |dp|^2 < r^2 let none through).
  const std::vector<Point_2> two_and_one{Point_2(0, 0), Point_2(0, 0), Point_2(1, 0)};
  EXPECT_EQ(darts(two_and_one, 1e-150).size(), 2u);
  EXPECT_EQ(darts(two_and_one, 1e-170).size(), 2u);
  // ... and the status says that such a radius cannot be trusted: white noise scaled by 2^-540 kept 220 items
  // at r = 0.03 (scaled) instead of 566, not maximal, with status success.
  const std::vector<Point_2> unit = white_noise(3000, 1);
  std::vector<Point_2> tiny;
  for (const Point_2& q : unit) tiny.emplace_back(std::ldexp(q.x(), -540), std::ldexp(q.y(), -540));
  EXPECT_EQ(bilateral_dart_throwing(unit, 0.03, std::back_inserter(kept)).status, Status::success);
  EXPECT_EQ(bilateral_dart_throwing(tiny, std::ldexp(0.03, -540), std::back_inserter(kept)).status,
            Status::degenerate_input);
  EXPECT_EQ(bilateral_dart_throwing(two_and_one, 1e-170, std::back_inserter(kept)).status,
            Status::degenerate_input);
  EXPECT_EQ(bilateral_dart_throwing(two_and_one, 1e-140, std::back_inserter(kept)).status, Status::success);
  // Per-item radii: the result reports the largest (it echoed the ignored radius argument).
  Dart_throwing_options o;
  o.radii = {0.5, 2.0, 1.0};
  EXPECT_EQ(bilateral_dart_throwing(two_and_one, std::nan(""), std::back_inserter(kept), o).radius, 2.0);
}

TEST(BilateralDartThrowing, BadInputNamesTheProblem) {
  const std::vector<Point_2> p = white_noise(10, 1);
  std::vector<std::size_t> kept;
  EXPECT_THROW(bilateral_dart_throwing(p, 0.0, std::back_inserter(kept)), std::invalid_argument);
  Dart_throwing_options o;
  o.radii.assign(9, 1.0);
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing(p, 1.0, std::back_inserter(kept), o); },
      "radii has 9 values for 10 items"));
  o.radii.assign(10, 1.0);
  o.radii[4] = -1;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing(p, 1.0, std::back_inserter(kept), o); }, "radii[4]"));
  o = {};
  o.priority.assign(10, 0.0);
  o.priority[2] = std::nan("");
  EXPECT_THROW(bilateral_dart_throwing(p, 1.0, std::back_inserter(kept), o), std::invalid_argument);
  EXPECT_THROW(bilateral_dart_throwing_count(p, 11, std::back_inserter(kept)), std::invalid_argument);
  Dart_throwing_count_options no_steps;
  // returned the first 5 items of the order with radius 0, as "degenerate input"
  no_steps.max_iterations = 0;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing_count(p, 5, std::back_inserter(kept), no_steps); },
      "max_iterations must be >= 1"));
  // Scales whose square is not a normal double (1e-160 squared is 0: the count search never ended).
  for (const double sigma : {1e-160, 1e160, 0.0, -1.0, std::nan("")}) {
    Dart_throwing_count_options c;
    c.darts.sigma_feature = sigma;
    EXPECT_TRUE(throws_with<std::invalid_argument>(
        [&] { bilateral_dart_throwing_count(p, 5, std::back_inserter(kept), c); },
        "sigma_feature must be in [1e-150, 1e150]"));
    o = {};
    o.sigma_position = sigma;
    EXPECT_TRUE(throws_with<std::invalid_argument>(
        [&] { bilateral_dart_throwing(p, 0.1, std::back_inserter(kept), o); },
        "sigma_position must be in [1e-150, 1e150]"));
  }
  o = {};
  o.sigma_feature = 1e-150;  // the bound itself is accepted
  EXPECT_NO_THROW(bilateral_dart_throwing(p, 0.1, std::back_inserter(kept), o));
  kept.clear();
  EXPECT_TRUE(kept.empty());
}
}  // namespace

TEST(BilateralDartThrowing, FewBisectionStepsStillBracketTheRadius) {
  // 5000 points, 200 wanted, 3 bisection steps: the halving that finds the bracket used the steps up, and the
  // result was the first 200 items of the visiting order at radius 0, labelled degenerate input (rho 0.035).
  // The halving is not counted now: a radius is bracketed and the samples are spread.
  const std::vector<Point_2> p = white_noise(5000, 21);
  for (const std::size_t steps : {1u, 3u, 60u}) {
    Dart_throwing_count_options o;
    o.max_iterations = steps;
    std::vector<std::size_t> kept;
    const auto r = bilateral_dart_throwing_count(p, 200, std::back_inserter(kept), o);
    EXPECT_EQ(r.status, Status::success) << steps;
    ASSERT_EQ(kept.size(), 200u);
    EXPECT_GT(r.radius, 0.0) << steps;
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = a + 1; b < kept.size(); ++b)
        closest = std::min(closest, std::sqrt(CGAL::squared_distance(p[kept[a]], p[kept[b]])));
    EXPECT_GE(closest, r.radius * (1 - 1e-12)) << steps;  // Poisson disk at the radius reported
  }
  // Two distinct positions and 10 wanted: no radius above 0 keeps enough. The uncounted halving is bounded
  // (it went down to 0: about 1078 throws instead of 61).
  std::vector<Point_2> two;
  for (int i = 0; i < 2000; ++i) two.emplace_back(i % 2, 0);
  std::size_t calls = 0;
  Dart_throwing_count_options o;
  o.darts.progress = [&calls](double) { return ++calls > 0; };
  std::vector<std::size_t> kept;
  EXPECT_EQ(bilateral_dart_throwing_count(two, 10, std::back_inserter(kept), o).status,
            Status::degenerate_input);
  EXPECT_EQ(kept.size(), 10u);
  EXPECT_LE(calls, 60u + 64u + 2u);
}

// Boundaries pinned by a mutation audit of the sampling headers (session 45): each test fails when the
// comparison or constant it names is moved.
namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using namespace FeatureRecon::test;

TEST(BilateralDartThrowing, ItemsAtExactlyTheRadiusDoNotConflict) {
  // Conflicts are strict (xi < r). Two neighbouring
  // pixels, black and white: with sigma_position = sigma_feature = 1 their bilateral distance is
  // sqrt(1 + 255^2 / 255^2) = sqrt(2), computed exactly as std::sqrt(2.0), while their spatial distance 1
  // lies inside the spatial prefilter, so only the strict test decides: both are kept at r = sqrt(2), one at
  // the next radius up.
  const std::vector<Grey_pixel> px{Grey_pixel{0, 0, 0}, Grey_pixel{1, 0, 255}};
  Dart_throwing_options g;
  g.sigma_feature = 1;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    g.seed = seed;
    std::vector<std::size_t> kept;
    bilateral_dart_throwing(px, std::sqrt(2.0), std::back_inserter(kept), g);
    EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1})) << "seed " << seed;
  }
  std::vector<std::size_t> one;
  bilateral_dart_throwing(px, std::nextafter(std::sqrt(2.0), 2.0), std::back_inserter(one), g);
  EXPECT_EQ(one.size(), 1u);
  const std::vector<Point_2> p{Point_2(0, 0), Point_2(1, 0), Point_2(2, 0)};
  // Per-item radii: the pair conflicts at the larger of the two radii, so radius 1 beside radius 1.5
  // conflicts.
  Dart_throwing_options o;
  o.radii = {1.0, 1.5, 1.0};
  o.priority = {3, 2, 1};  // item 0 first, then 1 (conflicts with 0 at max(1, 1.5)), then 2 (at 2 from 0)
  std::vector<std::size_t> kept;
  bilateral_dart_throwing(p, 1.0, std::back_inserter(kept), o);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 2}));
}

TEST(BilateralDartThrowing, ARadiusWhoseSquareIsExactly2ToTheMinus960IsNotTiny) {
  // The status is
  // degenerate_input only for a radius whose square lies below 2^-960: r = 2^-480 (square exactly 2^-960)
  // is success; the next double below is degenerate.
  const std::vector<Point_2> p{Point_2(0, 0), Point_2(1, 0)};
  std::vector<std::size_t> kept;
  EXPECT_EQ(bilateral_dart_throwing(p, 0x1p-480, std::back_inserter(kept)).status, Status::success);
  EXPECT_EQ(bilateral_dart_throwing(p, std::nextafter(0x1p-480, 0.0), std::back_inserter(kept)).status,
            Status::degenerate_input);
}

TEST(BilateralDartThrowing, ConsecutiveFailuresStopAtTheLimitAndRestartAfterAnAcceptance) {
  // Visiting order fixed by priority (item 0 first), r = 1, max_consecutive_failures = 2.
  Dart_throwing_options o;
  o.max_consecutive_failures = 2;
  // Items 1 and 2 conflict with item 0: the second failure in a row is the limit itself and stops the
  // throw before item 3 (far away) is visited.
  const std::vector<Point_2> a{Point_2(0, 0), Point_2(0.1, 0), Point_2(0.2, 0), Point_2(5, 0)};
  o.priority = {4, 3, 2, 1};
  std::vector<std::size_t> kept;
  bilateral_dart_throwing(a, 1.0, std::back_inserter(kept), o);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0}));
  // Failures alternate with acceptances: the count restarts at every acceptance, so two failures that are
  // not consecutive never stop the throw and item 4 is kept.
  const std::vector<Point_2> b{Point_2(0, 0), Point_2(0.1, 0), Point_2(5, 0), Point_2(5.1, 0),
                               Point_2(10, 0)};
  o.priority = {5, 4, 3, 2, 1};
  kept.clear();
  bilateral_dart_throwing(b, 1.0, std::back_inserter(kept), o);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 2, 4}));
}

TEST(BilateralDartThrowing, APerItemRadiusOfZeroIsRefused) {
  // Per-item radii
  // must be > 0: 0 itself is refused, naming the index (only -1 was tried).
  const std::vector<Point_2> p{Point_2(0, 0), Point_2(1, 0), Point_2(2, 0)};
  Dart_throwing_options o;
  o.radii = {1.0, 0.0, 1.0};
  std::vector<std::size_t> kept;
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { bilateral_dart_throwing(p, 1.0, std::back_inserter(kept), o); }, "radii[1]"));
}

TEST(BilateralDartThrowing, TargetCountBracketStartsAtTwiceTheLargestDistance) {
  // Two points 1 apart, count 1:
  // the bracket starts at twice the largest distance from item 0 (2), whose midpoint 1 still keeps both
  // (conflicts are strict) and the next one, 1.5, keeps exactly one: an exact hit at radius 1.5. A bracket
  // starting at the largest distance itself never reaches a radius that keeps one item (the set returned is
  // then the first item of a throw below radius 1, no longer a maximal throw).
  const std::vector<Point_2> p{Point_2(0, 0), Point_2(1, 0)};
  std::vector<std::size_t> kept;
  const auto r = bilateral_dart_throwing_count(p, 1, std::back_inserter(kept));
  EXPECT_EQ(r.status, Status::success);
  EXPECT_EQ(kept.size(), 1u);
  EXPECT_EQ(r.radius, 1.5);
}

TEST(BilateralDartThrowing, ExponentialDoublingStopsAtAThrowOfExactlyTheCount) {
  // Two black pixels 1 apart and two white ones far away, exponential form with sigma_feature 0.03: black and
  // white never conflict (their distance overflows), so the search doubles from twice the largest finite
  // distance from item 0 (2). The throw at 2 keeps exactly count = 2 items (one per colour), which ends the
  // doubling (at most `count`, inclusive); the search then hits 2 items at a radius in (1, 2] (at 1 the black
  // pair does not conflict: strict; 2 sqrt(2 / 3) = 1.633, the r^-2 guess from the throw at 2). Doubling on
  // past a throw of exactly `count` items never stops before the radius overflows and returns a radius near
  // 1e308.
  const std::vector<Grey_pixel> px{Grey_pixel{0, 0, 0}, Grey_pixel{1, 0, 0}, Grey_pixel{10, 0, 255},
                                   Grey_pixel{11, 0, 255}};
  Dart_throwing_count_options o;
  o.darts.form = Bilateral_form::exponential;
  o.darts.sigma_feature = 0.03;
  std::vector<std::size_t> kept;
  const auto r = bilateral_dart_throwing_count(px, 2, std::back_inserter(kept), o);
  EXPECT_EQ(r.status, Status::success);
  EXPECT_EQ(kept.size(), 2u);
  EXPECT_GT(r.radius, 1.0);
  EXPECT_LE(r.radius, 2.0);
}

// From a mutation audit of radius_search.h: the steps of the target count's search, as documented. While no
// lower end is known the step is the law count ~ r^-2 from the upper end; with both ends, log count is
// interpolated in log r, within the middle 90 % of the bracket.
TEST(BilateralDartThrowing, BracketedRadiusSearchStepsAsDocumented) {
  FeatureRecon::sampling::internal::Bracketed_radius_search s;
  s.hi = 2;
  s.kept_hi = 25;
  EXPECT_DOUBLE_EQ(s.next(100.5), 2 * std::sqrt(25 / 100.5));
  s.lo = 1;
  s.kept_lo = 1000;
  s.kept_hi = 10;
  // the interpolation gives 1 * (1000 / 999.5)^(1 / log2(100)), next to the lower end: moved to 1.05
  EXPECT_DOUBLE_EQ(s.next(999.5), 1.05);
  EXPECT_DOUBLE_EQ(s.next(10.001), 1.95);  // next to the upper end: moved to 1.95
  s.kept_lo = 400;
  s.kept_hi = 100;  // count ~ r^-2 between the ends: the goal 200 at sqrt(2)
  EXPECT_NEAR(s.next(200), std::sqrt(2.0), 1e-12);
}
}  // namespace
