// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H
#define FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

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

/// Runs f, which must throw std::invalid_argument with `part` in its message.
template <class F>
void expect_invalid_argument(F&& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning " << part;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}
}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_SAMPLING_SAMPLING_TEST_UTILITIES_H
