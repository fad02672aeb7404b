// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The GUDHI peer of the end-to-end benchmark, in its own translation unit (GUDHI 3.7 and CGAL's Boost.Graph
// headers do not mix in one).
#ifndef FEATURERECON_BENCHMARK_GUDHI_EXTENDED_PERSISTENCE_PEER_H
#define FEATURERECON_BENCHMARK_GUDHI_EXTENDED_PERSISTENCE_PEER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace FeatureRecon {
namespace bench {

struct Gudhi_result {
  std::size_t simplices = 0;  ///< of the 2-complex
  std::size_t pairs = 0;      ///< extended persistence pairs (all types, finite)
};

/// GUDHI: Rips_complex of `points` at `radius` expanded to dimension 2, lower-star filtration of `values`,
/// extend_filtration(), persistent cohomology over Z/2, the extended pairs decoded.
Gudhi_result gudhi_rips_extended_persistence(const std::vector<std::vector<double>>& points, double radius,
                                             const std::vector<double>& values);

/// The same on the flag 2-complex of a graph given by its edges.
Gudhi_result gudhi_flag_extended_persistence(std::size_t n,
                                             const std::vector<std::array<std::uint32_t, 2>>& edges,
                                             const std::vector<double>& values);

}  // namespace bench
}  // namespace FeatureRecon

#endif
