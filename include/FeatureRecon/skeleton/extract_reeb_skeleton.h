// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_EXTRACT_REEB_SKELETON_H
#define FEATURERECON_SKELETON_EXTRACT_REEB_SKELETON_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/embed_reeb_graph.h>
#include <FeatureRecon/skeleton/estimate_rips_radius.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Vertex bundle of a skeleton graph: a node of the Reeb graph.
struct Skeleton_node {
  std::array<double, 3> position{};  ///< centroid of its points (projected to 3D above 3D)
  double value = 0;                  ///< function value (geodesic distance)
  unsigned type = regular;           ///< Node_type flags
  /// Input points mapped to the node: first the node's own vertex of the Reeb graph (of a merged node, that
  /// of its lowest node), then the points of its level set.
  std::vector<Vertex_index> members;
  std::vector<double> input_position;  ///< above 3D: the centroid in input space (empty up to 3D: = position)
};

/// Edge bundle of a skeleton graph: an arc of the Reeb graph.
struct Skeleton_arc {
  std::vector<std::array<double, 3>> polyline;  ///< from node `lower` to node `upper`
  std::vector<Vertex_index> members;  ///< input points mapped into the arc, in increasing function value
  /// Above 3D: the polyline in input space, row-major (input dimension per vertex); its PCA projection is
  /// `polyline`, point for point (the same number of points, up to rounding; the gaps are bridged in input
  /// space). Empty up to 3D, where `polyline` is in input space.
  std::vector<double> input_polyline;
  /// The arc's lower and upper node (vertex indices of the Skeleton_graph; equal for a loop arc): its
  /// polylines run from `lower` to `upper`. The graph is undirected, so Boost reports an arc with either node
  /// as its source (`out_edges(v, g)` gives every arc with source v); these say which way the arc runs
  /// (arc_polyline_from() orients the polyline). Indices stay valid while no vertex is removed.
  std::size_t lower = 0;
  std::size_t upper = 0;  ///< see `lower`
};

/// The skeleton graph: nodes and arcs of the simplified Reeb graph with their embedding (parallel arcs
/// allowed).
using Skeleton_graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Skeleton_node, Skeleton_arc>;

/// Options of extract_reeb_skeleton().
struct Skeleton_options {
  /// Persistence threshold of the simplification (function unit); default 0 (no simplification).
  /// FeatureRecon::automatic: the suggested delta at the radius used, max(radius, 2.25 x the scale
  /// estimate_rips_radius() reads off the points or matrix; Rips_radius_estimate::delta), taken by the
  /// overloads of points and distance matrices (with a given radius the estimate's work, about 1,000 n
  /// distances, comes first and takes the first tenth of the progress range; a stop there returns status
  /// interrupted, rips_radius the given radius and delta NaN); the graph overload refuses it. Negative:
  /// refused (before FeatureRecon::automatic a negative delta asked for the suggested one).
  std::optional<double> delta = 0.0;
  /// join degree-1 nodes at most this far apart in input space, then simplify again; 0 (default): no repair
  double repair_distance = 0;
  /// With a repair distance: also join each remaining degree-1 node to the closest point of another arc
  /// within that distance, splitting the arc (connect_dead_ends(): T junctions with a gap). Default true.
  bool connect_dead_ends = true;
  /// Remove connected components of height (range of f) at most this after simplification and repair; their
  /// points then belong to no node or arc (Reeb_skeleton::pruned_points). 0 (default): keep all; infinity:
  /// remove all (an empty skeleton).
  double prune_height = 0;
  /// Contract each arc joining two branch nodes (degree >= 3) that is at most this long in input space into
  /// one node, each merged cluster at most this across (merge_close_branch_nodes()): where two curves cross
  /// or touch, the level sets merge and split at slightly different values, and the Reeb graph draws one
  /// point of degree 4 as two forks joined by a short arc. FeatureRecon::automatic (default): twice the level
  /// width of the embedding (Reeb_skeleton::level_width, by default the median edge length of the complex, so
  /// about the Rips radius: where two curves cross at a right angle the forks lie about that far apart, and
  /// closer features the complex does not resolve), in input units: for a graph whose edge lengths are not
  /// the coordinates' distances (unit weights, say), times the ratio of the median coordinate distance to the
  /// median length of its edges; off when the level width is infinite (one piece per arc, no scale); 0: off.
  /// For a distance matrix an arc is at least as long as the matrix's distance between its nodes' points
  /// (the MDS drawing may shorten it). Negative: refused (before FeatureRecon::automatic it asked for the
  /// automatic distance).
  std::optional<double> branch_merge_distance = FeatureRecon::automatic;
  /// Contract the spurs at the global minimum and maximum of each component when their height is at most
  /// delta (trim_essential_stubs()): on a loop the base point of the geodesic function otherwise stays a
  /// short spur. Default true.
  bool trim_stubs = true;
  Neighbor_search search = Neighbor_search::automatic;  ///< neighbour search of the Rips graph
  /// Refuse (std::invalid_argument, before storing any triangle) a Rips complex with more triangles than
  /// this: a radius too large for the data asks for billions, and the pipeline needs about 40 bytes per
  /// triangle. Default 2^27 (134,217,728 triangles, about 5.5 GB); 0: only the Reeb graph's own limit (2^31 -
  /// 1 edges and triangles together).
  std::size_t max_triangles = std::size_t(1) << 27;
  Embedding_options embedding;  ///< how arcs are drawn
  Progress_callback progress;   ///< called with the fraction done; returning false stops (status interrupted)
};

/// Result of extract_reeb_skeleton(): the skeleton and what the stages produced.
struct Reeb_skeleton {
  Skeleton_graph graph;       ///< the skeleton; its members partition the input points
  std::size_t dimension = 0;  ///< embedding dimension: min(input dimension, 3)
  /// The Rips radius of the complex (given or estimated); NaN for a proximity graph given as it is, and when
  /// the run was stopped before the radius was estimated.
  double rips_radius = std::numeric_limits<double>::quiet_NaN();
  /// the persistence threshold used (Skeleton_options::delta, or the suggested one; NaN when a run was
  /// stopped before the suggested delta was known)
  double delta = 0;
  /// Size of the complex (for points: the copies of a point are not joined to each other, see
  /// extract_reeb_skeleton()).
  std::size_t rips_edges = 0;
  std::size_t rips_triangles = 0;  ///< size of the complex, as rips_edges
  /// Input points with no neighbour at a positive distance in the complex (copies of a point do not count
  /// as its neighbours): each is a node of its own. Most of the points, with status success, means a radius
  /// below their spacing (give one above the distance to their nearest neighbours, or let
  /// estimate_rips_radius() choose).
  std::size_t isolated_points = 0;
  std::size_t removed_branches = 0;         ///< branches removed by the simplifications
  std::size_t removed_loops = 0;            ///< loops removed by the simplifications
  std::size_t repaired = 0;                 ///< arcs added by repair_reeb_graph()
  std::size_t connected_dead_ends = 0;      ///< arcs added by connect_dead_ends()
  std::size_t trimmed_stubs = 0;            ///< spurs at essential extrema contracted
  std::size_t pruned_components = 0;        ///< components removed (Skeleton_options::prune_height)
  std::vector<Vertex_index> pruned_points;  ///< their input points (sorted)
  std::size_t merged_branch_arcs = 0;  ///< arcs between close branch nodes contracted (branch_merge_distance)
  double branch_merge_distance = 0;    ///< the distance merge_close_branch_nodes() used (0: not run)
  double level_width = 0;              ///< level width the embedding used
  /// Gaps wider than this, in input units (above 3D measured in input space, where the gaps are bridged),
  /// were bridged through the complex (Reeb_graph_embedding::max_gap; infinity: none).
  double max_gap = std::numeric_limits<double>::infinity();
  /// degenerate_input for no points; interrupted if the callback stopped it
  Status status = Status::success;
};

/// Builds the skeleton graph from a Reeb graph and its embedding (the last stage).
/// \throws std::invalid_argument when E has another number of node positions or arc polylines than G has
/// nodes
///   and arcs, or an arc joins nodes out of range.
inline Skeleton_graph make_skeleton_graph(const Reeb_graph& G, const Reeb_graph_embedding& E) {
  const char* fn = "make_skeleton_graph";
  if (E.node_positions.size() != G.nodes.size() || E.arc_polylines.size() != G.arcs.size())
    FeatureRecon::internal::throw_invalid_argument(fn, "the embedding has ", E.node_positions.size(),
                                                   " node positions and ", E.arc_polylines.size(),
                                                   " arc polylines for a graph of ", G.nodes.size(),
                                                   " nodes and ", G.arcs.size(), " arcs (not its embedding)");
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    if (!(G.arcs[k].lower < G.nodes.size() && G.arcs[k].upper < G.nodes.size()))
      FeatureRecon::internal::throw_invalid_argument(fn, "arc ", k, " joins nodes out of range [0, ",
                                                     G.nodes.size(), ")");
  Skeleton_graph g(G.nodes.size());
  for (std::size_t i = 0; i < G.nodes.size(); ++i) {
    Skeleton_node& s = g[i];
    s.position = E.node_positions[i];
    s.value = G.nodes[i].value;
    s.type = G.nodes[i].type;
    s.members.push_back(G.nodes[i].vertex);
    s.members.insert(s.members.end(), G.nodes[i].members.begin(), G.nodes[i].members.end());
  }
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    add_edge(G.arcs[k].lower, G.arcs[k].upper,
             Skeleton_arc{E.arc_polylines[k], G.arcs[k].vertices, {}, G.arcs[k].lower, G.arcs[k].upper}, g);
  return g;
}

namespace internal {
/// Reverses the order of the points of a flattened polyline (`d` coordinates each; d = 0: nothing to do).
inline void reverse_points(std::vector<double>& flat, std::size_t d) {
  const std::size_t count = d > 0 ? flat.size() / d : 0;
  for (std::size_t i = 0; i < count / 2; ++i)
    std::swap_ranges(flat.begin() + static_cast<std::ptrdiff_t>(i * d),
                     flat.begin() + static_cast<std::ptrdiff_t>((i + 1) * d),
                     flat.begin() + static_cast<std::ptrdiff_t>((count - 1 - i) * d));
}
}  // namespace internal

/// The polyline of arc e walked from its node `from` (Skeleton_arc::lower or ::upper): the arc's polyline, or
/// the same reversed when `from` is its upper node. `input_dimension` > 0 orients
/// Skeleton_arc::input_polyline instead (points of that many coordinates; above 3D, the input dimension),
/// returned flattened as stored.
/// \throws std::invalid_argument when `from` is not a node of the arc, or the input polyline is not made of
/// points of `input_dimension` coordinates.
inline std::vector<double> arc_input_polyline_from(const Skeleton_graph& g,
                                                   const Skeleton_graph::edge_descriptor& e, std::size_t from,
                                                   std::size_t input_dimension) {
  const Skeleton_arc& a = g[e];
  const char* fn = "arc_input_polyline_from";
  if (from != a.lower && from != a.upper)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "node ", from, " is not an end of the arc (its ends are ", a.lower, " and ", a.upper, ")");
  if (input_dimension == 0 || a.input_polyline.size() % input_dimension != 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "the arc's input polyline has ",
                                                   a.input_polyline.size(), " numbers, not points of ",
                                                   input_dimension, " coordinates");
  std::vector<double> out = a.input_polyline;
  if (from != a.lower) internal::reverse_points(out, input_dimension);
  return out;
}

/// The polyline (3D) of arc e walked from its node `from`: Skeleton_arc::polyline, reversed when `from` is
/// the arc's upper node (a loop arc, lower == upper, keeps its stored direction). For walking a path of arcs
/// with `out_edges(v, g)`, whose source is always v.
/// \throws std::invalid_argument when `from` is not a node of the arc.
inline std::vector<std::array<double, 3>> arc_polyline_from(const Skeleton_graph& g,
                                                            const Skeleton_graph::edge_descriptor& e,
                                                            std::size_t from) {
  const Skeleton_arc& a = g[e];
  if (from != a.lower && from != a.upper)
    FeatureRecon::internal::throw_invalid_argument("arc_polyline_from", "node ", from,
                                                   " is not an end of the arc (its ends are ", a.lower,
                                                   " and ", a.upper, ")");
  std::vector<std::array<double, 3>> out = a.polyline;
  if (from != a.lower) std::reverse(out.begin(), out.end());
  return out;
}

/// Result of merge_close_branch_nodes().
struct Branch_node_merge_result {
  Skeleton_graph graph;    ///< the skeleton with close branch nodes merged
  std::size_t merged = 0;  ///< arcs contracted
  /// success, or interrupted when the progress callback returned false (the graph is then the input, nothing
  /// merged)
  Status status = Status::success;
};

namespace internal {
/// merge_close_branch_nodes() given the coordinates of the input points in at most 3D (`positions`, as the
/// embedding used them: project_to_3d()) and in input space (`input`, used for input_position above 3D).
/// `metric` (optional): the input's own distance between two points when the coordinates only draw it (a
/// distance matrix embedded by classical MDS, where an arc along a direction of small variance is drawn
/// almost without length): an arc is then at least as long as the metric between its nodes' vertices, and a
/// merged group must also stay within `distance` by the metric. `progress` as
/// Branch_node_merge_options::progress.
inline Branch_node_merge_result merge_close_branch_nodes(
    const Skeleton_graph& g, const std::vector<std::array<double, 3>>& positions, const Point_matrix& input,
    double distance, const char* fn,
    const std::function<double(Vertex_index, Vertex_index)>& metric = nullptr,
    const Progress_callback& progress = {}) {
  if (!(distance >= 0 && std::isfinite(distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "distance must be finite and >= 0, got ", distance);
  const std::size_t n = num_vertices(g), none = std::numeric_limits<std::size_t>::max();
  const bool high = input.dimension > 3;
  std::vector<std::size_t> lower, upper;  // arc ends, in edges(g) order
  std::vector<const Skeleton_arc*> arc;
  for (auto e : boost::make_iterator_range(edges(g))) {
    lower.push_back(source(e, g));
    upper.push_back(target(e, g));
    arc.push_back(&g[e]);
  }
  const std::size_t m = arc.size();
  for (std::size_t v = 0; v < n; ++v)
    for (const Vertex_index p : g[v].members)
      if (p >= positions.size() || (high && p >= input.rows))
        FeatureRecon::internal::throw_invalid_argument(fn, "node ", v, " has member ", p,
                                                       " out of range [0, ", positions.size(), ")");
  for (std::size_t k = 0; k < m; ++k)
    for (const Vertex_index p : arc[k]->members)
      if (p >= positions.size() || (high && p >= input.rows))
        FeatureRecon::internal::throw_invalid_argument(fn, "arc ", k, " has member ", p, " out of range [0, ",
                                                       positions.size(), ")");
  for (std::size_t v = 0; v < n; ++v)
    if (!g[v].input_position.empty() && g[v].input_position.size() != input.dimension)
      FeatureRecon::internal::throw_invalid_argument(fn, "node ", v, " has an input position of ",
                                                     g[v].input_position.size(),
                                                     " coordinates, the coordinates have ", input.dimension);
  for (std::size_t k = 0; k < m; ++k)
    if (input.dimension == 0 ? !arc[k]->input_polyline.empty()
                             : arc[k]->input_polyline.size() % input.dimension != 0)
      FeatureRecon::internal::throw_invalid_argument(
          fn, "arc ", k, " has an input polyline of ", arc[k]->input_polyline.size(),
          " numbers, not a multiple of the ", "dimension ", input.dimension);
  // Arc lengths in input space (the input polyline above 3D), candidates shortest first (ties by arc index).
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t k = 0; k < m; ++k) {
    if (lower[k] == upper[k]) continue;
    double length = 0;
    if (arc[k]->input_polyline.empty()) {
      const auto& l = arc[k]->polyline;
      for (std::size_t i = 0; i + 1 < l.size(); ++i)
        length += point_distance(l[i].data(), l[i + 1].data(), 3);
    } else {
      const std::size_t d = input.dimension, count = arc[k]->input_polyline.size() / d;
      const double* c = arc[k]->input_polyline.data();
      for (std::size_t i = 0; i + 1 < count; ++i) length += point_distance(c + i * d, c + (i + 1) * d, d);
    }
    if (metric && !g[lower[k]].members.empty() && !g[upper[k]].members.empty())
      length = std::max(length, metric(g[lower[k]].members.front(), g[upper[k]].members.front()));
    if (length <= distance) candidates.push_back({length, k});
  }
  std::sort(candidates.begin(), candidates.end());
  auto stopped = [&g, &progress](double fraction, Branch_node_merge_result& result) {
    if (FeatureRecon::internal::report_progress(progress, fraction)) return false;
    result = Branch_node_merge_result{};
    result.graph = g;
    result.status = Status::interrupted;
    return true;
  };
  // Rounds: in each, over the arcs between groups of merged nodes, contract a matching of the candidates
  // whose groups have degree >= 3 and are joined by this arc alone (a short loop stays a loop: no arc becomes
  // a self-loop).
  FeatureRecon::internal::Union_find<std::size_t> groups(n);  // the smallest node the root
  auto find = [&groups](std::size_t x) { return groups.find(x); };
  // The nodes of each group (by its root), and whether two groups stay within `distance` of each other once
  // merged: every node of one within `distance` of every node of the other (input space above 3D). Without
  // this bound the rounds chained the forks of a lattice (every cell a loop, every arc about the level width)
  // into one line.
  std::vector<std::vector<std::size_t>> group_nodes(candidates.empty() ? 0 : n);
  for (std::size_t v = 0; v < group_nodes.size(); ++v) group_nodes[v] = {v};
  auto node_point = [&](std::size_t v) -> std::pair<const double*, std::size_t> {
    if (high && g[v].input_position.size() == input.dimension)
      return {g[v].input_position.data(), input.dimension};
    return {g[v].position.data(), 3};
  };
  auto close_groups = [&](std::size_t a, std::size_t b) {
    for (const std::size_t u : group_nodes[a])
      for (const std::size_t w : group_nodes[b]) {
        const auto [pu, du] = node_point(u);
        const auto [pw, dw] = node_point(w);
        if (du != dw || !(point_distance(pu, pw, du) <= distance)) return false;
        if (metric && !g[u].members.empty() && !g[w].members.empty() &&
            !(metric(g[u].members.front(), g[w].members.front()) <= distance))
          return false;
      }
    return true;
  };
  std::vector<char> contracted(m, 0), refused(m, 0);  // refused: too wide once merged (groups only grow)
  Branch_node_merge_result result;
  if (stopped(0.1, result)) return result;
  std::size_t settled = 0;  // candidates contracted or refused
  for (bool changed = !candidates.empty(); changed;) {
    if (settled > 0 &&
        stopped(0.1 + 0.8 * static_cast<double>(settled) / static_cast<double>(candidates.size()), result))
      return result;
    changed = false;
    std::vector<std::size_t> degree(n, 0);
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> joining;  // arcs between two groups
    for (std::size_t k = 0; k < m; ++k) {
      if (contracted[k]) continue;
      const std::size_t a = find(lower[k]), b = find(upper[k]);
      degree[a] += 1;
      degree[b] += 1;
      ++joining[{std::min(a, b), std::max(a, b)}];
    }
    std::vector<char> taken(n, 0);
    for (const auto& [length, k] : candidates) {
      if (contracted[k] || refused[k]) continue;
      const std::size_t a = find(lower[k]), b = find(upper[k]);
      if (a == b || taken[a] || taken[b] || degree[a] < 3 || degree[b] < 3 ||
          joining[{std::min(a, b), std::max(a, b)}] != 1)
        continue;
      if (!close_groups(a, b)) {
        refused[k] = 1;
        ++settled;
        continue;
      }
      taken[a] = taken[b] = 1;
      contracted[k] = 1;
      groups.unite(a, b);
      auto& into = group_nodes[std::min(a, b)];
      auto& from = group_nodes[std::max(a, b)];
      into.insert(into.end(), from.begin(), from.end());
      from.clear();
      ++result.merged;
      ++settled;
      changed = true;
    }
  }
  if (stopped(0.9, result)) return result;
  // The new nodes: one per group, in order of their smallest node; a merged node takes the value of its
  // lowest node (ties: smaller index), whose members come first, and sits at the centroid of all its points.
  std::vector<std::size_t> index(n, none), lowest(n, none);
  std::vector<std::vector<std::size_t>> nodes_of;
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t r = find(v);
    if (index[r] == none) {
      index[r] = nodes_of.size();
      nodes_of.emplace_back();
    }
    nodes_of[index[r]].push_back(v);
    std::size_t& low = lowest[index[r]];
    if (low == none || g[v].value < g[low].value) low = v;
  }
  std::vector<std::vector<std::size_t>> arcs_of(nodes_of.size());
  for (std::size_t k = 0; k < m; ++k)
    if (contracted[k]) arcs_of[index[find(lower[k])]].push_back(k);
  Skeleton_graph& h = result.graph;
  h = Skeleton_graph(nodes_of.size());
  for (std::size_t i = 0; i < nodes_of.size(); ++i) {
    if (nodes_of[i].size() == 1) {
      h[i] = g[nodes_of[i].front()];
      continue;
    }
    Skeleton_node& node = h[i];
    node = g[lowest[i]];
    for (const std::size_t v : nodes_of[i])
      if (v != lowest[i]) node.members.insert(node.members.end(), g[v].members.begin(), g[v].members.end());
    for (const std::size_t k : arcs_of[i])
      node.members.insert(node.members.end(), arc[k]->members.begin(), arc[k]->members.end());
    using internal::mean_of;
    const auto& merged = nodes_of[i];
    if (!node.input_position.empty()) std::fill(node.input_position.begin(), node.input_position.end(), 0.0);
    if (node.members.empty()) {  // no points (a hand-made graph): the mean of the merged nodes
      for (int c = 0; c < 3; ++c)
        node.position[c] = mean_of(merged.size(), [&](std::size_t q) { return g[merged[q]].position[c]; });
      for (std::size_t c = 0; c < node.input_position.size(); ++c)
        node.input_position[c] = mean_of(merged.size(), [&](std::size_t q) {
          return c < g[merged[q]].input_position.size() ? g[merged[q]].input_position[c] : 0.0;
        });
      continue;
    }
    const auto& points = node.members;
    for (int c = 0; c < 3; ++c)
      node.position[c] = mean_of(points.size(), [&](std::size_t q) { return positions[points[q]][c]; });
    if (high && !node.input_position.empty())
      for (std::size_t c = 0; c < input.dimension; ++c)
        node.input_position[c] =
            mean_of(points.size(), [&](std::size_t q) { return input.row(points[q])[c]; });
  }
  // The other arcs, their ends moved to the merged nodes; an arc whose lower end moved above its upper end is
  // reversed (its members stay in increasing function value).
  std::vector<std::size_t> down(nodes_of.size(), 0), up(nodes_of.size(), 0);
  std::vector<char> retype(nodes_of.size(), 0);  // merged nodes and the ends of reversed arcs
  for (std::size_t k = 0; k < m; ++k) {
    if (contracted[k]) continue;
    std::size_t a = index[find(lower[k])], b = index[find(upper[k])];
    Skeleton_arc copy = *arc[k];
    if (a != b && (nodes_of[a].size() > 1 || nodes_of[b].size() > 1) && h[a].value > h[b].value) {
      std::swap(a, b);
      retype[a] = retype[b] = 1;
      std::reverse(copy.polyline.begin(), copy.polyline.end());
      reverse_points(copy.input_polyline, input.dimension);
    }
    const bool moved_a = nodes_of[a].size() > 1, moved_b = nodes_of[b].size() > 1;  // the ends that moved
    if (!copy.polyline.empty()) {
      if (moved_a) copy.polyline.front() = h[a].position;
      if (moved_b) copy.polyline.back() = h[b].position;
    }
    const std::size_t d = h[a].input_position.size();
    if (d > 0 && copy.input_polyline.size() >= d && h[b].input_position.size() == d) {
      if (moved_a)
        std::copy(h[a].input_position.begin(), h[a].input_position.end(), copy.input_polyline.begin());
      if (moved_b)
        std::copy(h[b].input_position.begin(), h[b].input_position.end(),
                  copy.input_polyline.end() - static_cast<std::ptrdiff_t>(d));
    }
    ++up[a];
    ++down[b];
    copy.lower = a;
    copy.upper = b;
    add_edge(a, b, std::move(copy), h);
  }
  for (std::size_t i = 0; i < nodes_of.size(); ++i)
    if (nodes_of[i].size() > 1 || retype[i]) h[i].type = node_type_from_degrees(down[i], up[i]);
  (void)FeatureRecon::internal::report_progress(progress, 1.0);
  return result;
}
}  // namespace internal

/// Merges branch nodes that lie close together: contracts every arc that joins two nodes of degree >= 3 and
/// is at most `distance` long in input space (its input_polyline above 3D, else its polyline) into one node,
/// unless another arc joins the same two nodes (a short loop is kept). Where two curves cross or touch (a
/// figure-eight, a road crossing) the level sets merge and split at slightly different values, so the Reeb
/// graph draws one point of degree 4 as two forks joined by a short arc; this draws it as one node.
/// Contractions go in rounds until no such arc is left, each round a greedy matching of the candidate arcs,
/// shortest first (ties by arc index), so a cluster of forks joined by short arcs becomes one node, as long
/// as its nodes stay within `distance` of each other (node positions, input space above 3D): the forks of a
/// lattice whose cells are about `distance` wide are not chained into one line. A merged node takes the value
/// of its lowest node (ties: the smaller index), whose members come first, then the other nodes' and the
/// contracted arcs' members (the members still partition the points); it sits at the centroid of its points
/// (above 3D its input_position is the centroid in `coordinates`, its position the centroid's projection,
/// project_to_3d(); without points, at the mean of the merged nodes). The arcs' polylines end at the new
/// positions; an arc whose lower end moved above its upper end is reversed (its polylines; its members stay
/// in increasing function value), and the types of the merged nodes and of the ends of reversed arcs follow
/// from the arcs below and above them. Nodes and arcs that take no part are copied unchanged; the new nodes
/// are ordered by the smallest original node of each.
/// A stop through the progress callback leaves Status::interrupted and the input graph unchanged.
/// \pre distance >= 0 and finite; the members index `coordinates`; above 3D input positions and polylines
///   have its dimension (all checked; throws naming the node or arc).
inline Branch_node_merge_result merge_close_branch_nodes(const Skeleton_graph& g,
                                                         const Point_matrix& coordinates, double distance,
                                                         const Branch_node_merge_options& options = {}) {
  internal::check_point_matrix(coordinates, "merge_close_branch_nodes", "coordinates");
  return internal::merge_close_branch_nodes(g, project_to_3d(coordinates), coordinates, distance,
                                            "merge_close_branch_nodes", nullptr, options.progress);
}

namespace internal {

/// The median length of the edges between first copies (first[v] == v; every vertex when `first` is empty):
/// copies of points add edges of length 0 and repeat some lengths (their edges to the first copy's
/// neighbours), so over all edges the median moved with the number of copies (an X of points 0.4 apart: 0.754
/// once, 0.4 with every point twice). 0 without such edges. The same median of another length of the edges:
/// `length(e)` for edge index e.
template <class Length>
double median_edge_length(const Proximity_graph& g, const std::vector<Vertex_index>& first, Length&& length) {
  std::vector<double> l;
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (first.empty() || (first[g.edges[e][0]] == g.edges[e][0] && first[g.edges[e][1]] == g.edges[e][1]))
      l.push_back(length(e));
  if (l.empty()) return 0;  // no edges, or every edge has a copy at an end: all points are copies of one
  std::nth_element(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(l.size() / 2), l.end());
  return l[l.size() / 2];
}
inline double median_edge_length(const Proximity_graph& g, const std::vector<Vertex_index>& first = {}) {
  return median_edge_length(g, first, [&g](std::size_t e) { return g.length(e); });
}

inline void check_skeleton_options(const Skeleton_options& options, const char* fn) {
  if (!options.delta)
    FeatureRecon::internal::throw_invalid_argument(
        fn,
        "delta is automatic (the suggested delta), which needs points or a distance matrix: give a value");
  FeatureRecon::internal::check_optional_length(fn, options.delta, "delta",
                                                "the suggested delta, with points or a distance matrix",
                                                "no simplification");
  if (!(options.repair_distance >= 0 && std::isfinite(options.repair_distance)))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "repair_distance must be finite and >= 0 (0: no repair), got ", options.repair_distance);
  if (!(options.prune_height >= 0))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "prune_height must be >= 0 (0: keep all; infinity: prune all), got ", options.prune_height);
  FeatureRecon::internal::check_optional_length(fn, options.branch_merge_distance, "branch_merge_distance",
                                                "twice the level width", "off");
  check_embedding_options(options.embedding, fn);  // before the pipeline runs, with the caller's values
}

/// `run` := `options` with an automatic delta replaced by the suggested delta at `radius`: max(radius,
/// delta_factor * scale) for the scale `estimate(o)` finds (estimate_rips_radius() with Rips_radius_options
/// o, default but for the progress), as Rips_radius_estimate::delta is at the estimated radius. Checked with
/// the replacement standing in. The estimate takes the first tenth of the progress range of
/// `options.progress` and `run.progress` the rest. \returns false when the callback stopped the estimate.
template <class Estimate>
bool with_suggested_delta(const Skeleton_options& options, double radius, const char* fn, Estimate&& estimate,
                          Skeleton_options& run) {
  run = options;
  if (!options.delta) run.delta = 0.0;  // checked with the suggestion standing in
  check_skeleton_options(run, fn);
  if (options.delta) return true;
  Rips_radius_options ro;
  if (options.progress) {
    ro.progress = [&options](double t) { return options.progress(0.1 * t); };
    run.progress = [progress = options.progress](double t) { return progress(0.1 + 0.9 * t); };
  }
  const Rips_radius_estimate e = estimate(ro);
  if (e.status == Status::interrupted) return false;
  run.delta = std::min(std::numeric_limits<double>::max(), std::max(radius, ro.delta_factor * e.scale));
  return true;
}

/// The result of a run stopped before any skeleton: the caller's delta (NaN if automatic), the radius (NaN
/// if not known yet).
inline Reeb_skeleton interrupted_skeleton(std::size_t dimension, double rips_radius,
                                          const std::optional<double>& delta) {
  Reeb_skeleton s;
  s.dimension = dimension;
  s.rips_radius = rips_radius;
  s.delta = delta.value_or(std::numeric_limits<double>::quiet_NaN());
  s.status = Status::interrupted;
  return s;
}

/// The stages after the proximity graph; `distance` measures input space for the repair, `bounds` is nullptr
/// or an Axis_bounds, 1-Lipschitz for it (Reeb_repair_options); `first`: the first copy of each vertex, or
/// empty (no copies).
template <class Distance, class Bounds>
Reeb_skeleton skeleton_from_graph(const Proximity_graph& graph, const Point_matrix& coordinates,
                                  const Distance& distance, const Skeleton_options& options,
                                  double progress_start, const Bounds& bounds,
                                  const char* fn = "extract_reeb_skeleton",
                                  const std::vector<Vertex_index>& first = {},
                                  bool coordinates_are_metric = true) {
  const std::size_t dimension = coordinates.dimension;
  Reeb_skeleton result;
  result.dimension = std::min<std::size_t>(dimension, 3);
  result.delta = *options.delta;  // checked: set
  if (graph.number_of_vertices == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  // Once the callback has said stop, every later stage sees a stop too, and the run ends after the stage.
  bool stopped = false;
  auto stage = [&](double a, double b) -> Progress_callback {
    if (!options.progress) return {};
    a = progress_start + (1 - progress_start) * a;
    b = progress_start + (1 - progress_start) * b;
    return [&options, &stopped, a, b](double t) {
      return !(stopped = stopped || !options.progress(a + (b - a) * t));
    };
  };
  // The Reeb graph takes fewer than 2^31 - 1 edges and triangles together, and fewer than 2^30 edges.
  const std::size_t capacity = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) - 1;
  const std::size_t room =
      graph.edges.size() < capacity && 2 * graph.edges.size() < capacity ? capacity - graph.edges.size() : 0;
  const std::size_t max_triangles = options.max_triangles > 0 ? std::min(options.max_triangles, room) : room;
  const Simplicial_complex_2 K = internal::flag_complex_2(
      graph, max_triangles, stage(0.0, 0.2), fn,
      max_triangles == options.max_triangles && max_triangles > 0
          ? "max_triangles of the options"
          : "the Reeb graph's limit: 2^31 - 1 edges and triangles together, 2^30 edges");
  // A stage ended by the callback (its own status, or a stop the stage wrapper saw) ends the run.
  auto ended = [&stopped, &result](Status stage_status) {
    if (stopped || stage_status == Status::interrupted) result.status = Status::interrupted;
    return result.status == Status::interrupted;
  };
  if (ended(Status::success)) return result;
  result.rips_edges = K.number_of_edges();
  result.rips_triangles = K.number_of_triangles();
  {
    std::vector<bool> joined(graph.number_of_vertices, false);
    for (std::size_t e = 0; e < graph.edges.size(); ++e)
      if (graph.length(e) > 0) joined[graph.edges[e][0]] = joined[graph.edges[e][1]] = true;
    result.isolated_points = static_cast<std::size_t>(std::count(joined.begin(), joined.end(), false));
  }
  Geodesic_options go;
  go.progress = stage(0.2, 0.35);
  Geodesic_result geo;
  try {
    geo = compute_geodesic_function(K, go);
  } catch (
      const std::invalid_argument& e) {  // the complex is ours: only a distance beyond the largest double
    const std::string what = e.what(), stage_name = "compute_geodesic_function: ";
    FeatureRecon::internal::throw_invalid_argument(
        fn, what.compare(0, stage_name.size(), stage_name) == 0 ? what.substr(stage_name.size()) : what,
        " (in compute_geodesic_function)");
  }
  if (ended(geo.status)) return result;
  Reeb_graph_options ro;
  ro.progress = stage(0.35, 0.8);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, geo.values, ro);
  if (ended(A.status())) return result;
  Simplification_options so;
  so.progress = stage(0.8, 0.87);
  Reeb_simplification_result S = simplify_by_persistence(A, *options.delta, so);
  if (ended(S.status)) return result;
  result.removed_branches = S.removed_branches;
  result.removed_loops = S.removed_loops;
  if (options.repair_distance > 0) {
    Reeb_repair_options repair;
    if constexpr (!std::is_same<Bounds, std::nullptr_t>::value) {
      repair.bound = bounds.first;
      repair.second_bound = bounds.second;
    }
    repair.progress = stage(0.87, 0.89);
    Reeb_repair_result fixed = repair_reeb_graph(S.graph, options.repair_distance, distance, repair);
    if (ended(fixed.status)) return result;
    result.repaired = fixed.joined;
    Reeb_graph joined = std::move(fixed.graph);
    if (options.connect_dead_ends) {
      repair.progress = stage(0.89, 0.91);
      Reeb_dead_end_result ends =
          connect_dead_ends(joined, A.values(), options.repair_distance, distance, repair);
      if (ended(ends.status)) return result;
      result.connected_dead_ends = ends.connected;
      joined = std::move(ends.graph);
    }
    so.progress = stage(0.91, 0.95);
    S = simplify_by_persistence(joined, A.values(), *options.delta, so);
    if (ended(S.status)) return result;
    result.removed_branches += S.removed_branches;
    result.removed_loops += S.removed_loops;
  }
  if (options.trim_stubs) {
    Reeb_trim_options to;
    to.progress = stage(0.95, 0.955);
    Reeb_trim_result trimmed = trim_essential_stubs(S.graph, *options.delta, to);
    if (ended(trimmed.status)) return result;
    S.graph = std::move(trimmed.graph);
    result.trimmed_stubs = trimmed.trimmed;
  }
  if (options.prune_height > 0) {
    Reeb_prune_options po;
    po.progress = stage(0.955, 0.96);
    Reeb_prune_result pruned = prune_reeb_graph_components(S.graph, options.prune_height, po);
    if (ended(pruned.status)) return result;
    S.graph = std::move(pruned.graph);
    result.pruned_components = pruned.removed_components;
    result.pruned_points = std::move(pruned.removed_vertices);
  }
  Embedding_options eo = options.embedding;
  if (!eo.level_width) {
    const double median = median_edge_length(K, first);
    eo.level_width = median > 0 ? median : automatic_level_width(S.graph);  // 0: mostly duplicate points
  }
  result.level_width = *eo.level_width;
  const std::vector<std::array<double, 3>> projected = project_to_3d(coordinates);
  if (!eo.max_gap && !first.empty()) {
    // The automatic max_gap (twice the median edge length in the space where gaps are measured: the input
    // space, which is the embedding's up to 3D) over the edges between first copies, as the level width: with
    // every point given twice (edges of length 0 and repeated lengths) it moved from 1.065 to 1.018 and one
    // more node stayed; 300 copies of one point made it 0 (nothing bridged).
    const double median = median_edge_length(K, first, [&](std::size_t e) {
      return point_distance(coordinates.row(K.edges[e][0]), coordinates.row(K.edges[e][1]), dimension);
    });
    // none (all points copies of one): straight segments, as before
    eo.max_gap = median > 0 ? 2 * median : 0.0;
  }
  eo.progress = stage(0.96, 0.99);
  if (dimension > 3) {
    // Drawn in input space and projected point for point: each arc's `polyline` is the projection of its
    // `input_polyline` (two separate drawings bridged gaps measured in their own spaces, and their point
    // counts differed on 42 arcs of 150 noisy trees in R^7).
    auto [E, I] =
        internal::embed_reeb_graph_with_projection(S.graph, K, coordinates, projected, A.values(), eo);
    if (ended(E.status)) return result;
    result.graph = make_skeleton_graph(S.graph, E);
    result.max_gap = E.max_gap;
    for (std::size_t i = 0; i < I.node_positions.size(); ++i)
      result.graph[i].input_position = std::move(I.node_positions[i]);
    std::size_t k = 0;
    for (auto e : boost::make_iterator_range(edges(result.graph)))
      result.graph[e].input_polyline = std::move(I.arc_polylines[k++]);
  } else {
    const Reeb_graph_embedding E = embed_reeb_graph(S.graph, K, projected, A.values(), dimension, eo);
    if (ended(E.status)) return result;
    result.graph = make_skeleton_graph(S.graph, E);
    result.max_gap = E.max_gap;
  }
  if (!options.branch_merge_distance) {
    // Twice the level width, from function units (the edge lengths) to input units (`distance`) by the ratio
    // of their medians: 1 for points and distance matrices, whose edge lengths are the distances; a graph
    // with unit weights (or any other) on coordinates 0.01 apart merged forks 2 coordinate units apart, 200
    // edges.
    double ratio = 1;
    {
      const double input =
          median_edge_length(K, first, [&](std::size_t e) { return distance(K.edges[e][0], K.edges[e][1]); });
      const double weight = median_edge_length(K, first);
      if (input > 0 && weight > 0) ratio = input / weight;
    }
    // Saturates (edges near DBL_MAX). An infinite level width (one piece per arc) has no scale: off.
    result.branch_merge_distance = std::isinf(*eo.level_width) ? 0.0
                                                               : std::min(2 * *eo.level_width * ratio,
                                                                          std::numeric_limits<double>::max());
  } else {
    result.branch_merge_distance = *options.branch_merge_distance;
  }
  if (result.branch_merge_distance > 0) {
    std::function<double(Vertex_index, Vertex_index)> metric;
    if (!coordinates_are_metric)
      metric = [&distance](Vertex_index a, Vertex_index b) { return distance(a, b); };
    Branch_node_merge_result merged = internal::merge_close_branch_nodes(
        result.graph, projected, coordinates, result.branch_merge_distance, fn, metric, stage(0.99, 1.0));
    if (ended(merged.status)) {
      result.graph = Skeleton_graph();  // what every other stop leaves
      return result;
    }
    result.graph = std::move(merged.graph);
    result.merged_branch_arcs = merged.merged;
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

/// The graph of all points from the graph h of the first copies (h's vertex k is original[k], increasing;
/// first[i]: the first copy of point i): each further copy joined to its first copy, the first copy's
/// neighbours (at their distances) and the previous copy.
inline Proximity_graph join_copies(const Proximity_graph& h, const std::vector<Vertex_index>& first,
                                   const std::vector<Vertex_index>& original) {
  const std::size_t n = first.size();
  // Neighbours of each first copy in h (compressed rows over the original indices), and the copies in order.
  std::vector<std::size_t> start(n + 1, 0);
  for (const Edge& e : h.edges) {
    ++start[original[e[0]] + 1];
    ++start[original[e[1]] + 1];
  }
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::pair<Vertex_index, double>> around(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < h.edges.size(); ++e) {
    const Vertex_index a = original[h.edges[e][0]], b = original[h.edges[e][1]];
    around[fill[a]++] = {b, h.length(e)};
    around[fill[b]++] = {a, h.length(e)};
  }
  Proximity_graph g;
  g.number_of_vertices = n;
  g.edges.reserve(h.edges.size());
  g.edge_lengths.reserve(h.edges.size());
  auto join = [&g](Vertex_index a, Vertex_index b, double length) {
    g.edges.push_back({std::min(a, b), std::max(a, b)});
    g.edge_lengths.push_back(length);
  };
  for (std::size_t e = 0; e < h.edges.size(); ++e)
    join(original[h.edges[e][0]], original[h.edges[e][1]], h.length(e));
  std::vector<Vertex_index> previous(n);  // the last copy seen of each first copy
  for (std::size_t i = 0; i < n; ++i) previous[i] = static_cast<Vertex_index>(i);
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex_index r = first[i], c = static_cast<Vertex_index>(i);
    if (r == c) continue;
    join(r, c, 0.0);
    if (previous[r] != r) join(previous[r], c, 0.0);
    previous[r] = c;
    for (std::size_t k = start[r]; k < start[r + 1]; ++k) join(around[k].first, c, around[k].second);
  }
  sort_unique_edges(g.edges, &g.edge_lengths);
  return g;
}

/// The Rips graph of the distinct points, where each further copy of a point is joined to its first copy, to
/// the first copy's neighbours (at their distances) and to the next copy (index order), but not to the other
/// copies. Every copy's closed neighbourhood lies in its first copy's, and has its value under any geodesic
/// function, so the copies collapse onto it: the flag complex keeps the homotopy type, the level sets and the
/// critical points of the full Rips complex, where the copies also form a clique; k copies of a point with d
/// neighbours cost about k (d + 2) edges and k (d + t) triangles (t: the first copy's) instead of about k^2/2
/// edges and k^3/6 triangles.
inline Proximity_graph rips_graph_of_distinct_points(const Point_matrix& points, double radius,
                                                     const Proximity_graph_options& options,
                                                     std::vector<Vertex_index>& first) {
  if (!first_copies(points, first)) return build_rips_graph(points, radius, options);
  Point_matrix distinct;
  distinct.dimension = points.dimension;
  std::vector<Vertex_index> original;  // increasing, so an edge (a, b), a < b, stays ordered
  for (std::size_t i = 0; i < points.rows; ++i)
    if (first[i] == i) {
      original.push_back(static_cast<Vertex_index>(i));
      distinct.data.insert(distinct.data.end(), points.row(i), points.row(i) + points.dimension);
    }
  distinct.rows = original.size();
  return join_copies(build_rips_graph(distinct, radius, options), first, original);
}

/// The bounds of repair_reeb_graph() and connect_dead_ends() for Euclidean points: the coordinates of the two
/// axes along which the points spread the most (ties: the smaller axis), each 1-Lipschitz for the distance;
/// the second empty in dimension 1. Two bounds make the repair's search a grid instead of a strip.
using Axis_bounds = std::pair<std::function<double(std::uint32_t)>, std::function<double(std::uint32_t)>>;
inline Axis_bounds widest_axis_bounds(const Point_matrix& points) {
  std::vector<std::pair<double, std::size_t>> spread;  // (-extent, axis)
  for (std::size_t c = 0; c < points.dimension; ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < points.rows; ++i) {
      lo = std::min(lo, points.row(i)[c]);
      hi = std::max(hi, points.row(i)[c]);
    }
    spread.emplace_back(-(hi - lo), c);  // no points: +inf for every axis, equal
  }
  std::stable_sort(spread.begin(), spread.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Axis_bounds bounds;
  auto axis_of = [&points](std::size_t axis) {
    return [&points, axis](std::uint32_t v) { return points.row(v)[axis]; };
  };
  if (!spread.empty()) bounds.first = axis_of(spread[0].second);
  if (spread.size() > 1) bounds.second = axis_of(spread[1].second);
  return bounds;
}

inline double euclidean_distance(const Point_matrix& points, Vertex_index a, Vertex_index b) {
  return point_distance(points.row(a), points.row(b), points.dimension);  // squares of 1e160 overflowed
}

}  // namespace internal

/// One call from points to a skeleton graph (dissertation Ch. 3): Rips 2-complex at `radius`, geodesic
/// function, augmented Reeb graph, simplification of features of persistence <= delta, optional repair and a
/// second simplification, embedding. Each stage is also callable alone (see doc/skeleton.md).
/// The automatic level width of the embedding is the median edge length of the complex, copies of
/// points left out (internal::median_edge_length()). Further copies of a point
/// (equal coordinates) are not joined to each other, only to their first copy, its neighbours and the next
/// copy (internal::rips_graph_of_distinct_points(): same homotopy type, level sets and critical points as the
/// full Rips complex without the copies' cliques); every copy is a member of its first copy's node or arc.
/// `options.delta = FeatureRecon::automatic` asks for the suggested delta at this radius
/// (Skeleton_options::delta).
/// \pre radius >= 0 and finite; repair_distance >= 0 (checked; throws). Points as build_rips_graph().
/// \tparam Radius an arithmetic type: `extract_reeb_skeleton(points, {})` is not radius 0 but the overload
///   that estimates the radius (default options).
template <class Radius, std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton(const Point_matrix& points, Radius radius,
                                    const Skeleton_options& given_options = {}) {
  const double rips_radius = static_cast<double>(radius);
  internal::check_point_matrix(points, "extract_reeb_skeleton");
  if (!(std::isfinite(rips_radius) && rips_radius >= 0))
    FeatureRecon::internal::throw_invalid_argument("extract_reeb_skeleton",
                                                   "radius must be finite and >= 0, got ", rips_radius);
  const std::size_t dimension = std::min<std::size_t>(points.dimension, 3);
  Skeleton_options options;
  if (!internal::with_suggested_delta(
          given_options, rips_radius, "extract_reeb_skeleton",
          [&points](const Rips_radius_options& o) { return estimate_rips_radius(points, o); }, options))
    return internal::interrupted_skeleton(dimension, rips_radius, given_options.delta);
  Proximity_graph_options po;
  po.search = options.search;
  // a stop inside the Rips stage ends the run even if the callback answers true afterwards
  bool stopped = false;
  if (options.progress)
    po.progress = [&options, &stopped](double t) {
      return !(stopped = stopped || !options.progress(0.3 * t));
    };
  std::vector<Vertex_index> first;  // empty: no copies
  const Proximity_graph g = internal::rips_graph_of_distinct_points(points, rips_radius, po, first);
  if (stopped) return internal::interrupted_skeleton(dimension, rips_radius, options.delta);
  Reeb_skeleton s = internal::skeleton_from_graph(
      g, points,
      [&points](Vertex_index a, Vertex_index b) { return internal::euclidean_distance(points, a, b); },
      options, 0.3, internal::widest_axis_bounds(points), "extract_reeb_skeleton", first);
  s.rips_radius = rips_radius;
  return s;
}

/// extract_reeb_skeleton(points, {r}[, options]): a braced radius is a radius (a template radius cannot be
/// deduced from {r}, and the estimating overload would take {r} for options with delta r).
template <class Radius, std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton(const Point_matrix& points, const Radius (&radius)[1],
                                    const Skeleton_options& options = {}) {
  return extract_reeb_skeleton(points, radius[0], options);
}

namespace internal {
/// Runs `run(radius, options)` at the radius `estimate()` gives, the estimate taking the first tenth of the
/// progress range; interrupted (no skeleton) when it was stopped.
template <class Estimate, class Run>
Reeb_skeleton with_estimated_radius(const Skeleton_options& options, Rips_radius_options radius_options,
                                    std::size_t dimension, const char* fn, Estimate&& estimate, Run&& run) {
  Skeleton_options rest = options;
  if (!options.delta) rest.delta = 0.0;  // checked with the estimate's delta standing in
  check_skeleton_options(rest, fn);
  // both callbacks hear the estimate (its own fraction, and the first tenth of the run's)
  if (options.progress) {
    radius_options.progress = [&options, own = radius_options.progress](double t) {
      const bool go_on = !own || own(t);
      return options.progress(0.1 * t) && go_on;
    };
  }
  const Rips_radius_estimate r = estimate(radius_options);
  if (r.status == Status::interrupted)
    return interrupted_skeleton(dimension, std::numeric_limits<double>::quiet_NaN(), options.delta);
  if (!options.delta) rest.delta = r.delta;
  if (options.progress) rest.progress = [&options](double t) { return options.progress(0.1 + 0.9 * t); };
  Reeb_skeleton s = run(r.radius, rest);
  s.rips_radius = r.radius;
  return s;
}
}  // namespace internal

/// extract_reeb_skeleton() at the radius estimate_rips_radius() derives from the points (with
/// `radius_options`; the radius used is Reeb_skeleton::rips_radius, the delta used Reeb_skeleton::delta).
/// `options.delta = FeatureRecon::automatic` stands for the estimate's suggested delta
/// (Rips_radius_estimate::delta; the default 0 means no simplification, as in every overload); every other
/// value is taken from `options` as given. The estimate takes the first tenth of the progress range of
/// `options.progress`; `radius_options.progress`, when set, hears it too (with the estimate's own fraction),
/// and either can stop it: an empty skeleton, status interrupted, rips_radius NaN. Stage by stage:
/// estimate_rips_radius(), then extract_reeb_skeleton(points, estimate.radius, options with delta =
/// estimate.delta).
inline Reeb_skeleton extract_reeb_skeleton(const Point_matrix& points, const Skeleton_options& options,
                                           const Rips_radius_options& radius_options = {}) {
  internal::check_point_matrix(points, "extract_reeb_skeleton");
  return internal::with_estimated_radius(
      options, radius_options, std::min<std::size_t>(points.dimension, 3), "extract_reeb_skeleton",
      [&points](const Rips_radius_options& o) { return estimate_rips_radius(points, o); },
      [&points](double radius, const Skeleton_options& o) {
        return extract_reeb_skeleton(points, radius, o);
      });
}

/// The skeleton of a proximity graph whose vertices have coordinates (any dimension; projected to 3D by PCA
/// for the embedding above 3D): the stages of extract_reeb_skeleton() after the Rips graph. The graph's edge
/// lengths drive the geodesic function; the coordinates, the repair distance and the embedding.
/// \pre coordinates.rows == graph.number_of_vertices (checked; throws).
inline Reeb_skeleton extract_reeb_skeleton(const Proximity_graph& graph, const Point_matrix& coordinates,
                                           const Skeleton_options& options = {}) {
  internal::check_skeleton_options(options, "extract_reeb_skeleton");
  if (coordinates.rows != graph.number_of_vertices)
    FeatureRecon::internal::throw_invalid_argument("extract_reeb_skeleton", "the graph has ",
                                                   graph.number_of_vertices, " vertices but coordinates has ",
                                                   coordinates.rows, " rows");
  internal::check_point_matrix(coordinates, "extract_reeb_skeleton", "coordinates");
  if (const std::string problem = internal::canonical_form_problem(graph); !problem.empty())
    FeatureRecon::internal::throw_invalid_argument(
        "extract_reeb_skeleton", "the graph is not canonical (see Proximity_graph): ", problem);
  return internal::skeleton_from_graph(
      graph, coordinates,
      [&coordinates](Vertex_index a, Vertex_index b) {
        return internal::euclidean_distance(coordinates, a, b);
      },
      options, 0.0, internal::widest_axis_bounds(coordinates));
}

/// extract_reeb_skeleton(graph, coordinates, options) with the coordinates as a range of points (one per
/// vertex of the graph) through a PointCoordinateTraits model, as the points overloads take them.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Reeb_skeleton extract_reeb_skeleton(const Proximity_graph& graph, const PointRange& coordinates,
                                    const Skeleton_options& options = {}, const Traits& traits = Traits()) {
  return extract_reeb_skeleton(graph, make_point_matrix(coordinates, traits, "extract_reeb_skeleton"),
                               options);
}

/// The skeleton of a dense distance matrix: Rips graph at `radius` (an arithmetic type) on the matrix, then
/// the stages of extract_reeb_skeleton(). Repair distances are read from the matrix; the embedding uses
/// classical MDS into 3D (classical_mds_3d(); it takes the first 30 % of the progress range and can be
/// stopped between its steps). Copies (a row at distance 0 from an earlier one, with the same distances to
/// all) are joined as extract_reeb_skeleton() joins copies of points (internal::first_copies_of_rows(),
/// internal::join_copies()).
/// \tparam Matrix as build_rips_graph_from_distance_matrix() (checked the same way; throws).
template <class Matrix, class Radius, std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton_from_distance_matrix(const Matrix& D, Radius radius,
                                                         const Skeleton_options& given_options = {}) {
  const double rips_radius = static_cast<double>(radius);
  const char* fn = "extract_reeb_skeleton_from_distance_matrix";
  std::size_t n = 0;
  const std::vector<double> a = internal::checked_distance_matrix(D, n, fn);
  if (!(std::isfinite(rips_radius) && rips_radius >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and >= 0, got ", rips_radius);
  Skeleton_options options;
  if (!internal::with_suggested_delta(
          given_options, rips_radius, fn,
          [&D](const Rips_radius_options& o) { return estimate_rips_radius_from_distance_matrix(D, o); },
          options))
    return internal::interrupted_skeleton(3, rips_radius, given_options.delta);
  // Copies (rows at distance 0 with equal rows) are joined as extract_reeb_skeleton() joins copies of points:
  // n copies of one point formed a clique of n^3 / 6 triangles.
  std::vector<Vertex_index> first;
  Proximity_graph g;
  if (internal::first_copies_of_rows(a, n, first)) {
    std::vector<Vertex_index> original;
    for (std::size_t i = 0; i < n; ++i)
      if (first[i] == i) original.push_back(static_cast<Vertex_index>(i));
    const std::size_t m = original.size();
    std::vector<double> distinct(m * m);
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t c = 0; c < m; ++c) distinct[r * m + c] = a[original[r] * n + original[c]];
    g = internal::join_copies(internal::rips_graph_of_distance_matrix(distinct, m, rips_radius), first,
                              original);
  } else {  // from the checked copy: a second copy of the matrix would double the memory
    g = internal::rips_graph_of_distance_matrix(a, n, rips_radius);
  }
  bool stopped = false;
  Progress_callback scaled;
  if (options.progress) scaled = [&options](double f) { return options.progress(0.3 * f); };
  Point_matrix mds;
  mds.rows = n;
  mds.dimension = 3;
  for (const auto& p : internal::classical_mds_3d(a, n, scaled, stopped))
    mds.data.insert(mds.data.end(), p.begin(), p.end());
  if (stopped || !FeatureRecon::internal::report_progress(options.progress, 0.3))
    return internal::interrupted_skeleton(3, rips_radius, options.delta);
  Reeb_skeleton s = internal::skeleton_from_graph(
      g, mds, [&a, n](Vertex_index i, Vertex_index j) { return a[static_cast<std::size_t>(i) * n + j]; },
      options, 0.3, nullptr, fn, first, false);
  s.rips_radius = rips_radius;
  return s;
}

/// extract_reeb_skeleton_from_distance_matrix(D, {r}[, options]): a braced radius is a radius.
template <class Matrix, class Radius, std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton_from_distance_matrix(const Matrix& D, const Radius (&radius)[1],
                                                         const Skeleton_options& options = {}) {
  return extract_reeb_skeleton_from_distance_matrix(D, radius[0], options);
}

/// extract_reeb_skeleton_from_distance_matrix() at the radius estimate_rips_radius_from_distance_matrix()
/// derives from the matrix, as extract_reeb_skeleton(points, options, radius_options) does for points.
template <class Matrix>
Reeb_skeleton extract_reeb_skeleton_from_distance_matrix(const Matrix& D, const Skeleton_options& options,
                                                         const Rips_radius_options& radius_options = {}) {
  return internal::with_estimated_radius(
      options, radius_options, 3, "extract_reeb_skeleton_from_distance_matrix",
      [&D](const Rips_radius_options& o) { return estimate_rips_radius_from_distance_matrix(D, o); },
      [&D](double radius, const Skeleton_options& o) {
        return extract_reeb_skeleton_from_distance_matrix(D, radius, o);
      });
}

/// extract_reeb_skeleton() on a range of points through a PointCoordinateTraits model.
template <class PointRange, class Radius,
          class Traits = Point_coordinate_traits<typename std::iterator_traits<
              decltype(std::begin(std::declval<const PointRange&>()))>::value_type>,
          std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton(const PointRange& points, Radius radius,
                                    const Skeleton_options& options = {}, const Traits& traits = Traits()) {
  return extract_reeb_skeleton(make_point_matrix(points, traits, "extract_reeb_skeleton"),
                               static_cast<double>(radius), options);
}

/// extract_reeb_skeleton(points, {r}[, options, traits]) on a range: a braced radius is a radius.
template <class PointRange, class Radius,
          class Traits = Point_coordinate_traits<typename std::iterator_traits<
              decltype(std::begin(std::declval<const PointRange&>()))>::value_type>,
          std::enable_if_t<std::is_arithmetic<Radius>::value, int> = 0>
Reeb_skeleton extract_reeb_skeleton(const PointRange& points, const Radius (&radius)[1],
                                    const Skeleton_options& options = {}, const Traits& traits = Traits()) {
  return extract_reeb_skeleton(points, radius[0], options, traits);
}

/// extract_reeb_skeleton(points, options, radius_options) on a range of points through a
/// PointCoordinateTraits model: the radius derived from the data.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Reeb_skeleton extract_reeb_skeleton(const PointRange& points, const Skeleton_options& options,
                                    const Rips_radius_options& radius_options = {},
                                    const Traits& traits = Traits()) {
  return extract_reeb_skeleton(make_point_matrix(points, traits, "extract_reeb_skeleton"), options,
                               radius_options);
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_EXTRACT_REEB_SKELETON_H
