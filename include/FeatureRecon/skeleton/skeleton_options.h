// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SKELETON_OPTIONS_H
#define FEATURERECON_SKELETON_SKELETON_OPTIONS_H

// Options of the skeleton subsystem. Deliberately free of CGAL and Eigen (cheap to include).

#include <FeatureRecon/config.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// How neighbours are searched when building a proximity graph from points.
enum class Neighbor_search {
  automatic,    ///< kd-tree up to dimension 3, blocked brute force above
  kd_tree,      ///< CGAL kd-tree (dimension <= 3 only)
  brute_force   ///< blocked all-pairs distances with Eigen, any dimension
};

/// Options of build_rips_graph() and build_knn_graph().
struct Proximity_graph_options {
  Neighbor_search search = Neighbor_search::automatic;  ///< neighbour search strategy; default automatic
  Progress_callback progress;  ///< called with the fraction done; returning false stops (result is partial)
};

/// Options of compute_geodesic_function().
struct Geodesic_options {
  /// Base points (vertex indices), at most one per connected component (checked). Components without a base
  /// point use the automatic rule: the vertex farthest (ties: smallest index) from the smallest-index vertex of
  /// the component. Default: none.
  std::vector<std::size_t> base_points;
  Progress_callback progress;  ///< called with the fraction done; returning false stops
};

/// Options of compute_augmented_reeb_graph().
struct Reeb_graph_options {
  Progress_callback progress;  ///< called with the fraction of vertices swept; returning false stops
};

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SKELETON_OPTIONS_H
