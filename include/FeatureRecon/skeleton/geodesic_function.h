// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_GEODESIC_FUNCTION_H
#define FEATURERECON_SKELETON_GEODESIC_FUNCTION_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Result of compute_geodesic_function().
struct Geodesic_result {
  std::vector<double> values;  ///< shortest-path distance of each vertex to its component's base point
  std::vector<std::size_t> base_points;  ///< the base point of each connected component, by component number
  std::vector<std::uint32_t> component;  ///< connected component of each vertex (numbered by smallest vertex)
  Status status = Status::success;       ///< degenerate_input for an empty graph; interrupted if stopped
};

namespace internal {
/// \cond
struct Csr_edge_weight {
  double weight = 0;
};
using Csr_graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Csr_edge_weight>;

/// Multi-source Dijkstra on the (symmetrised) graph; distances of unreachable vertices stay infinite.
inline std::vector<double> multi_source_dijkstra(const Csr_graph& csr,
                                                 const std::vector<std::size_t>& sources) {
  const std::size_t n = num_vertices(csr);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> pred(n);
  if (sources.empty()) return dist;
  boost::dijkstra_shortest_paths(
      csr, sources.begin(), sources.end(),
      boost::make_iterator_property_map(pred.begin(), get(boost::vertex_index, csr)),
      boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, csr)),
      get(&Csr_edge_weight::weight, csr), get(boost::vertex_index, csr), std::less<double>(),
      boost::closed_plus<double>(), std::numeric_limits<double>::infinity(), 0.0,
      boost::default_dijkstra_visitor(),
      boost::make_iterator_property_map(std::vector<boost::default_color_type>(n).begin(),
                                        get(boost::vertex_index, csr)));
  return dist;
}

inline Csr_graph make_csr_graph(const Proximity_graph& g) {
  std::vector<std::pair<std::size_t, std::size_t>> arcs;
  std::vector<Csr_edge_weight> w;
  arcs.reserve(2 * g.edges.size());
  w.reserve(2 * g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    arcs.emplace_back(g.edges[e][0], g.edges[e][1]);
    arcs.emplace_back(g.edges[e][1], g.edges[e][0]);
    w.push_back({g.length(e)});
    w.push_back({g.length(e)});
  }
  return Csr_graph(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), w.begin(),
                   g.number_of_vertices);
}
/// \endcond
}  // namespace internal

/// Geodesic function of dissertation Ch. 3.3: the shortest-path distance in the graph (edge lengths as
/// weights) to a base point, separately in every connected component.
///
/// Method: Dijkstra on a Boost compressed-sparse-row graph. Unless the options name a base point in a
/// component, its base point is the vertex farthest from the component's smallest-index vertex (ties: the
/// smallest index), an extreme point of the component. Two multi-source Dijkstra runs in all:
/// O((n + m) log n).
/// \pre every base point in options is < number_of_vertices, and no two lie in one component (checked; throws
///      naming them); g canonical (checked); no shortest path longer than the largest double (checked: throws
///      naming a vertex whose distance overflows).
/// \returns per-vertex values, per-component base points; `degenerate_input` for an empty graph.
inline Geodesic_result compute_geodesic_function(const Proximity_graph& g,
                                                 const Geodesic_options& options = {}) {
  const char* fn = "compute_geodesic_function";
  if (const std::string problem = internal::canonical_form_problem(g); !problem.empty())
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the graph is not canonical (see Proximity_graph): ", problem);
  const std::size_t n = g.number_of_vertices;
  for (std::size_t i = 0; i < options.base_points.size(); ++i)
    if (options.base_points[i] >= n)
      FeatureRecon::internal::throw_invalid_argument(fn, "base point ", i, " is vertex ",
                                                     options.base_points[i], ", out of range [0, ", n, ")");
  Geodesic_result result;
  if (n == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  const Connected_components cc = connected_components(g);
  result.component = cc.label;
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> chosen(cc.count, none), start(cc.count, none);
  std::vector<std::size_t> given_as(cc.count, none);  // index in options.base_points
  for (std::size_t i = 0; i < options.base_points.size(); ++i) {
    const std::size_t b = options.base_points[i], c = cc.label[b];
    if (given_as[c] != none)
      FeatureRecon::internal::throw_invalid_argument(
          fn, "base points ", given_as[c], " and ", i, " (vertices ", options.base_points[given_as[c]],
          " and ", b,
          ") lie in the same connected component; give at most one "
          "per component");
    given_as[c] = i;
    chosen[c] = b;
  }
  for (std::size_t v = 0; v < n; ++v)
    if (start[cc.label[v]] == none) start[cc.label[v]] = v;
  const internal::Csr_graph csr = internal::make_csr_graph(g);
  // Every vertex of a component with a source is reached: an infinite distance there is a sum of lengths that
  // overflowed.
  auto check_finite = [&](const std::vector<double>& d, bool every_component) {
    for (std::size_t v = 0; v < n; ++v)
      if ((every_component || chosen[cc.label[v]] == none) &&
          !(d[v] < std::numeric_limits<double>::infinity()))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "the geodesic distance of vertex ", v,
            " overflows the largest double; scale the edge lengths down");
  };
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) {
    result.status = Status::interrupted;
    return result;
  }
  // First pass: distances from the start vertex of each component that has no given base point.
  std::vector<std::size_t> sources;
  for (std::size_t c = 0; c < cc.count; ++c)
    if (chosen[c] == none) sources.push_back(start[c]);
  if (!sources.empty()) {
    const std::vector<double> d = internal::multi_source_dijkstra(csr, sources);
    check_finite(d, false);  // the components that had no base point
    // Farthest vertex per component; strict comparison: the smallest index wins ties.
    std::vector<std::size_t> far(cc.count, none);
    std::vector<double> far_d(cc.count, -1.0);
    for (std::size_t v = 0; v < n; ++v) {
      const std::uint32_t c = cc.label[v];
      if (chosen[c] != none) continue;
      if (d[v] > far_d[c]) {
        far_d[c] = d[v];
        far[c] = v;
      }
    }
    for (std::size_t c = 0; c < cc.count; ++c)
      if (chosen[c] == none) chosen[c] = far[c];
  }
  if (!FeatureRecon::internal::report_progress(options.progress, 0.5)) {
    result.status = Status::interrupted;
    return result;
  }
  result.base_points = chosen;
  result.values = internal::multi_source_dijkstra(csr, chosen);
  check_finite(result.values, true);
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_GEODESIC_FUNCTION_H
