// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H
#define FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H

#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/traits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
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

/// 12 grey pixels (values 10, 20, ..., 120) whose extents, 9 x 6, read as a 4 x 3 lattice of spacing 3, so
/// that their box (widened by half a spacing) is [-1, 11] x [-1, 8]; the positions are not a lattice, so a
/// point near a face of that box often has its nearest pixel across the face on the torus.
inline std::vector<Grey_pixel> irregular_pixels() {
  const std::vector<std::array<int, 2>> at{{0, 0}, {9, 6}, {4, 3}, {2, 5}, {7, 1}, {5, 6},
                                           {1, 2}, {8, 4}, {3, 0}, {6, 3}, {9, 2}, {4, 1}};
  std::vector<Grey_pixel> px;
  for (std::size_t i = 0; i < at.size(); ++i) {
    Grey_pixel p;
    p.column = at[i][0];
    p.row = at[i][1];
    p.value = static_cast<std::uint8_t>(10 * (i + 1));
    px.push_back(p);
  }
  return px;
}

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
