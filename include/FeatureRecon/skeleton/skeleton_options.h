// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SKELETON_OPTIONS_H
#define FEATURERECON_SKELETON_SKELETON_OPTIONS_H

// Options of the skeleton subsystem. Deliberately free of CGAL and Eigen (cheap to include).

#include <FeatureRecon/config.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// How neighbours are searched when building a proximity graph from points.
enum class Neighbor_search {
  automatic,   ///< kd-tree up to dimension 3, blocked brute force above
  kd_tree,     ///< CGAL kd-tree (dimension <= 3 only)
  brute_force  ///< blocked all-pairs distances with Eigen, any dimension
};

/// Options of build_rips_graph() and build_knn_graph().
struct Proximity_graph_options {
  Neighbor_search search = Neighbor_search::automatic;  ///< neighbour search strategy; default automatic
  /// called with the fraction done; returning false stops: the graph is partial (see each builder) and its
  /// status interrupted
  Progress_callback progress;
};

/// Options of compute_geodesic_function().
struct Geodesic_options {
  /// Base points (vertex indices), at most one per connected component (checked). Components without a base
  /// point use the automatic rule: the vertex farthest (ties: smallest index) from the smallest-index vertex
  /// of the component. Default: none.
  std::vector<std::size_t> base_points;
  Progress_callback progress;  ///< called with the fraction done; returning false stops
};

/// Options of compute_augmented_reeb_graph().
struct Reeb_graph_options {
  /// Called with the fraction done (the set-up passes up to 0.4, then the fraction of vertices swept);
  /// returning false stops (Status::interrupted; the arcs closed so far, none when the stop came before the
  /// sweep).
  Progress_callback progress;
};

/// Options of simplify_by_persistence().
struct Simplification_options {
  /// Called with the fraction done (persistence and merging paths up to 0.3, the Reeb graph of the glued
  /// complex up to 0.9, the quotient graph 1); returning false stops: status interrupted, empty graph.
  Progress_callback progress;
};

/// Options of compute_reeb_graph_persistence().
struct Reeb_persistence_options {
  /// Called with the fraction done (the checks and the adjacency up to 0.1, the upward sweep of branches to
  /// 0.3, the downward one to 0.5, the loops to 1); returning false stops: Status::interrupted and empty
  /// diagrams.
  Progress_callback progress;
};

/// Options of trim_essential_stubs().
struct Reeb_trim_options {
  /// Called with the fraction done; returning false stops: Status::interrupted, the input graph unchanged
  /// and nothing trimmed.
  Progress_callback progress;
};

/// Options of prune_reeb_graph_components().
struct Reeb_prune_options {
  /// Called with the fraction done; returning false stops: Status::interrupted, the input graph unchanged
  /// and nothing removed.
  Progress_callback progress;
};

/// Options of merge_close_branch_nodes().
struct Branch_node_merge_options {
  /// Called with the fraction done (the candidate arcs up to 0.1, each round of contractions by the share of
  /// candidates settled up to 0.9, the new graph 1); returning false stops: Status::interrupted, the input
  /// graph unchanged and nothing merged.
  Progress_callback progress;
};

/// Options of repair_reeb_graph() and connect_dead_ends().
struct Reeb_repair_options {
  /// Empty (default: every pair is measured), or a function of an input vertex that is 1-Lipschitz for the
  /// distance, |bound(a) - bound(b)| <= distance(a, b) (a coordinate of Euclidean points): only pairs whose
  /// bounds differ by at most the repair distance are measured. The result is the same; the work drops from
  /// quadratic. It must hold for the computed values (a coordinate plus a large offset rounds and can lose
  /// the pairs at the distance), and the values must be finite (a NaN or an infinity throws, naming the
  /// vertex).
  std::function<double(std::uint32_t)> bound;
  /// Empty (default), or a second such function (another coordinate); only with `bound` (set alone, it
  /// throws). With both, a pair is measured only when both bounds differ by at most the repair distance, and
  /// the candidates come from a grid of cells of that side instead of a strip of the first bound: points of
  /// even density in the plane cost O(1) candidates each instead of O(sqrt n). The result is the same.
  std::function<double(std::uint32_t)> second_bound;
  /// Called with the fraction done; returning false stops (status interrupted; the graph holds the arcs added
  /// before the stop, see each function).
  Progress_callback progress;
};

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SKELETON_OPTIONS_H
