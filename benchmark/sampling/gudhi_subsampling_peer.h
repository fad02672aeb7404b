// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// GUDHI's subsampling, in its own translation unit (GUDHI 3.7 headers are compiled apart from ours).
#ifndef FEATURERECON_BENCHMARK_SAMPLING_GUDHI_SUBSAMPLING_PEER_H
#define FEATURERECON_BENCHMARK_SAMPLING_GUDHI_SUBSAMPLING_PEER_H

#include <array>
#include <cstddef>
#include <vector>

namespace FeatureRecon {
namespace bench {
/// Gudhi::subsampling::choose_n_farthest_points (exact count, farthest-point order) from point 0.
std::vector<std::array<double, 2>> gudhi_choose_n_farthest_points(const std::vector<std::array<double, 2>>& p,
                                                                  std::size_t count);
/// Gudhi::subsampling::sparsify_point_set: no two output points closer than min_distance.
std::vector<std::array<double, 2>> gudhi_sparsify_point_set(const std::vector<std::array<double, 2>>& p,
                                                            double min_distance);
}  // namespace bench
}  // namespace FeatureRecon

#endif  // FEATURERECON_BENCHMARK_SAMPLING_GUDHI_SUBSAMPLING_PEER_H
