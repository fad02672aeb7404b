// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H
#define FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H

#include <FeatureRecon/sampling/sampling_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_utilities.h"

namespace FeatureRecon {
namespace test {
using K = CGAL::Epick;
using Point_2 = K::Point_2;
using Point_3 = K::Point_3;
using Vector_3 = K::Vector_3;

/// n uniform random points in the unit square (a fixed generator: the same points on every platform).
inline std::vector<Point_2> white_noise(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Point_2> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = u();
    p.emplace_back(x, u());
  }
  return p;
}

/// rho of a 2D set on the unit torus (sampling_quality() with `periodic`).
inline double torus_relative_radius(const std::vector<Point_2>& s) {
  sampling::Sampling_quality_options q;
  q.periodic = true;
  return sampling::sampling_quality(s, q).relative_radius;
}

/// The periodogram of a 2D set on the unit torus up to |f_x|, |f_y| <= 200, as the averaged spectrum tests
/// take it.
inline sampling::Sampling_spectrum torus_spectrum(const std::vector<Point_2>& s) {
  sampling::Sampling_spectrum_options o;
  o.max_frequency = 200;
  return sampling::sampling_spectrum(s, o);
}

/// The energy stopping rule of the iterative samplers, checked on a history that stopped by it: the last
/// iteration's relative energy decrease is below `tolerance`, every earlier one after the first at least it.
template <class History>
void expect_energy_rule_holds_at_the_stop(const History& h, double tolerance) {
  ASSERT_GE(h.size(), 3u);
  auto relative_decrease = [&h](std::size_t k) { return (h[k - 1].energy - h[k].energy) / h[k - 1].energy; };
  EXPECT_LT(relative_decrease(h.size() - 1), tolerance);
  for (std::size_t k = 1; k + 1 < h.size(); ++k) EXPECT_GE(relative_decrease(k), tolerance) << k;
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H
