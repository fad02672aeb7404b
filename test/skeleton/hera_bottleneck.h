// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Hera's exact bottleneck distance behind a plain interface (its own translation unit).
#ifndef FEATURERECON_TEST_SKELETON_HERA_BOTTLENECK_H
#define FEATURERECON_TEST_SKELETON_HERA_BOTTLENECK_H

#include <utility>
#include <vector>

namespace FeatureRecon {
namespace test {
/// Exact bottleneck distance between two diagrams (points on either side of the diagonal).
double hera_bottleneck(std::vector<std::pair<double, double>> a, std::vector<std::pair<double, double>> b);
}  // namespace test
}  // namespace FeatureRecon

#endif
