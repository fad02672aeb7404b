// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H
#define FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

namespace internal {
/// Recomputes every node's type from its arcs and the number of components.
inline void refresh_node_types(Reeb_graph& G) {
  std::vector<std::size_t> down(G.nodes.size(), 0), up(G.nodes.size(), 0);
  for (const auto& a : G.arcs) {
    ++up[a.lower];
    ++down[a.upper];
  }
  for (std::size_t i = 0; i < G.nodes.size(); ++i) G.nodes[i].type = node_type_from_degrees(down[i], up[i]);
  G.components = count_components(G);
}

/// Checks what the repair functions rely on, naming the first offending node or arc: node values finite and in
/// strictly increasing (value, vertex) order, every arc going up between two nodes of the graph (lower < upper).
/// With `values`, every vertex the graph uses (nodes, members, arc vertices) indexes it, and arc vertices (which
/// can become nodes) have finite values.
inline void check_reeb_graph(const Reeb_graph& G, const char* fn, const std::vector<double>* values = nullptr) {
  using FeatureRecon::internal::throw_invalid_argument;
  for (std::size_t i = 0; i < G.nodes.size(); ++i) {
    const auto& node = G.nodes[i];
    if (!std::isfinite(node.value)) throw_invalid_argument(fn, "node ", i, " has value ", node.value);
    if (i > 0 && !(G.nodes[i - 1].value < node.value ||
                   (G.nodes[i - 1].value == node.value && G.nodes[i - 1].vertex < node.vertex)))
      throw_invalid_argument(fn, "nodes ", i - 1, " and ", i, " are not in increasing (value, vertex) order");
  }
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    if (!(G.arcs[k].lower < G.arcs[k].upper && G.arcs[k].upper < G.nodes.size()))
      throw_invalid_argument(fn, "arc ", k, " joins nodes ", G.arcs[k].lower, " and ", G.arcs[k].upper,
                             ": it must go up between nodes in [0, ", G.nodes.size(), ")");
  if (!values) return;
  auto check = [&](Vertex_index v, const char* what, std::size_t index) {
    if (v >= values->size())
      throw_invalid_argument(fn, what, " ", index, " has vertex ", v, " out of range [0, ", values->size(), ")");
  };
  for (std::size_t i = 0; i < G.nodes.size(); ++i) {
    check(G.nodes[i].vertex, "node", i);
    for (const Vertex_index v : G.nodes[i].members) check(v, "node", i);
  }
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    for (const Vertex_index v : G.arcs[k].vertices) {
      check(v, "arc", k);
      if (!std::isfinite((*values)[v]))
        throw_invalid_argument(fn, "arc ", k, " has vertex ", v, " of value ", (*values)[v], " (finite needed)");
    }
}

/// Component of each node: the smallest node index in it (union-find over the arcs).
inline std::vector<std::size_t> node_components(const Reeb_graph& G) {
  std::vector<std::size_t> parent(G.nodes.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&parent](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& a : G.arcs) {
    const std::size_t x = find(a.lower), y = find(a.upper);
    if (x != y) parent[std::max(x, y)] = std::min(x, y);
  }
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = find(i);
  return parent;
}
/// The nodes `ends` (indices into G.nodes) as (bound of their vertex, node), sorted.
template <class Bound>
std::vector<std::pair<double, std::size_t>> sorted_by_bound(const std::vector<std::size_t>& ends, const Bound& bound,
                                                            const Reeb_graph& G) {
  std::vector<std::pair<double, std::size_t>> swept;
  swept.reserve(ends.size());
  for (const std::size_t e : ends) swept.emplace_back(static_cast<double>(bound(G.nodes[e].vertex)), e);
  std::sort(swept.begin(), swept.end());
  return swept;
}
/// The bound difference up to which a pair is measured: max_distance with room for the rounding of a computed
/// distance (a Euclidean distance may come out an ulp below the difference of one coordinate).
inline double bound_window(double max_distance) {
  return max_distance * (1 + 1e-12) + std::numeric_limits<double>::denorm_min();
}
}  // namespace internal

/// Result of repair_reeb_graph().
struct Reeb_repair_result {
  Reeb_graph graph;         ///< the graph with the new arcs; may contain regular nodes (simplify next)
  std::size_t joined = 0;   ///< number of arcs added
  Status status = Status::success;  ///< interrupted when the progress callback returned false (no arc added)
};

/// Graph fixing of dissertation Ch. 3.3.2: joins pairs of degree-1 nodes whose input points are at most
/// `max_distance` apart (the input distance, not the distance in the complex), closest pairs first, each node at
/// most once. A joined pair gets a new arc (no interior vertices) from the lower node to the higher one. The two
/// ends of one arc (an isolated segment) are never joined: when they are each other's closest free end, the
/// segment is left as it is (no loop of two arcs), and neither end joins anything farther. The new features are
/// not checked: simplify_by_persistence(graph, values, delta) afterwards removes the small ones and
/// absorbs nodes that became regular. O(k^2 log k) for k degree-1 nodes; with Reeb_repair_options::bound, only
/// pairs whose bounds differ by at most max_distance are measured (the same result). The progress callback is
/// asked after each end's pairs are measured; a stop adds no arc (the graph is R, status interrupted).
/// \tparam Distance callable `double(Vertex_index, Vertex_index)`, the distance between two input points.
/// \pre max_distance >= 0 and finite; R's node values finite and in increasing (value, vertex) order, its arcs
/// going up between its nodes, as reeb_graph() and simplify_by_persistence() return them (all checked; throws).
template <class Distance>
Reeb_repair_result repair_reeb_graph(const Reeb_graph& R, double max_distance, Distance distance,
                                     const Reeb_repair_options& options = {}) {
  const char* fn = "repair_reeb_graph";
  if (!(max_distance >= 0 && std::isfinite(max_distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_distance must be finite and >= 0, got ", max_distance);
  internal::check_reeb_graph(R, fn);
  Reeb_repair_result result;
  result.graph = R;
  Reeb_graph& G = result.graph;
  std::vector<std::size_t> degree(G.nodes.size(), 0), other_end(G.nodes.size(), G.nodes.size());
  for (const auto& a : G.arcs) {
    ++degree[a.lower];
    ++degree[a.upper];
    other_end[a.lower] = a.upper;
    other_end[a.upper] = a.lower;
  }
  std::vector<std::size_t> ends;
  for (std::size_t i = 0; i < G.nodes.size(); ++i)
    if (degree[i] == 1) ends.push_back(i);
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  auto measure = [&](std::size_t x, std::size_t y) {  // x < y, as node indices
    const double d = static_cast<double>(distance(G.nodes[x].vertex, G.nodes[y].vertex));
    if (d <= max_distance) candidates.emplace_back(d, x, y);
  };
  auto stopped_after = [&](std::size_t a) {  // the pairs of a + 1 ends are measured
    if (FeatureRecon::internal::report_progress(options.progress,
                                                0.9 * static_cast<double>(a + 1) / static_cast<double>(ends.size())))
      return false;
    result.status = Status::interrupted;
    return true;
  };
  if (!options.bound) {
    for (std::size_t a = 0; a < ends.size(); ++a) {
      for (std::size_t b = a + 1; b < ends.size(); ++b) measure(ends[a], ends[b]);
      if (stopped_after(a)) return result;
    }
  } else {
    // A sweep over the ends sorted by their bound: a pair farther apart in bound is farther apart in distance.
    const std::vector<std::pair<double, std::size_t>> swept = internal::sorted_by_bound(ends, options.bound, G);
    const double window = internal::bound_window(max_distance);
    for (std::size_t a = 0; a < swept.size(); ++a) {
      for (std::size_t b = a + 1; b < swept.size() && swept[b].first - swept[a].first <= window; ++b)
        measure(std::min(swept[a].second, swept[b].second), std::max(swept[a].second, swept[b].second));
      if (stopped_after(a)) return result;
    }
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [d, x, y] : candidates) {
    if (degree[x] != 1 || degree[y] != 1) continue;
    if (other_end[x] == y) {  // the two ends of an isolated arc: closest to each other, so left alone
      degree[x] = degree[y] = 2;
      continue;
    }
    Reeb_graph::Arc arc;
    arc.lower = std::min(x, y);  // nodes are in increasing (value, vertex) order
    arc.upper = std::max(x, y);
    G.arcs.push_back(std::move(arc));
    ++degree[x];
    ++degree[y];
    ++result.joined;
  }
  // Types and components of the new graph.
  internal::refresh_node_types(G);
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

/// Result of connect_dead_ends().
struct Reeb_dead_end_result {
  Reeb_graph graph;              ///< the graph with the new arcs (and nodes where arcs were split)
  std::size_t connected = 0;     ///< number of arcs added
  /// interrupted when the progress callback returned false: the graph holds the arcs of the dead ends taken before
  Status status = Status::success;
};

/// The other half of graph fixing: a degree-1 node whose input point is at most `max_distance` from a point of
/// another part of the graph (a node, or an interior vertex of an arc that does not end at this node) gets an arc
/// to the closest such point (ties: smallest vertex index), splitting that arc there: a street that stops short
/// of the street it meets (a T junction with a gap). An isolated arc whose two ends lie within `max_distance` of
/// each other is not connected (too short to be a street end). Dead ends are taken in node order and see the arcs added
/// before them. Simplify afterwards, as after repair_reeb_graph(). O(k * n) distance evaluations for k dead ends
/// and n input vertices in the graph (the bookkeeping is O(1) per dead end); the arcs come back in the order of
/// Reeb_graph::arcs. With Reeb_repair_options::bound, only the vertices whose bound lies within max_distance of
/// the dead end's are measured: O(n log n + k w) for w such vertices, the same result. The progress callback is
/// asked after each dead end; a stop keeps the arcs added so far (a valid graph, status interrupted).
/// \param values f of every input vertex (for the new nodes).
/// \tparam Distance callable `double(Vertex_index, Vertex_index)`, the input distance.
/// \pre max_distance >= 0 and finite; R as for repair_reeb_graph(), and every vertex it uses indexes `values`
/// (all checked; throws).
template <class Distance>
Reeb_dead_end_result connect_dead_ends(const Reeb_graph& R, const std::vector<double>& values, double max_distance,
                                       Distance distance, const Reeb_repair_options& options = {}) {
  const char* fn = "connect_dead_ends";
  if (!(max_distance >= 0 && std::isfinite(max_distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_distance must be finite and >= 0, got ", max_distance);
  internal::check_reeb_graph(R, fn, &values);
  Reeb_dead_end_result result;
  Reeb_graph G = R;
  // Degrees, the arcs at each node and the node of each vertex, kept up to date as arcs split and links appear.
  std::vector<std::size_t> degree(G.nodes.size(), 0);
  std::vector<std::vector<std::size_t>> incident(G.nodes.size());
  for (std::size_t a = 0; a < G.arcs.size(); ++a) {
    ++degree[G.arcs[a].lower], ++degree[G.arcs[a].upper];
    incident[G.arcs[a].lower].push_back(a);
    incident[G.arcs[a].upper].push_back(a);
  }
  std::unordered_map<Vertex_index, std::size_t> node_of;
  for (std::size_t i = 0; i < G.nodes.size(); ++i) node_of.emplace(G.nodes[i].vertex, i);
  std::vector<Vertex_index> ends;  // by input vertex: node indices change when arcs split
  for (std::size_t i = 0; i < G.nodes.size(); ++i)
    if (degree[i] == 1) ends.push_back(G.nodes[i].vertex);
  // With a bound: every vertex of the graph sorted by bound, and where it is now (a node, or an arc and the
  // position in it; updated when an arc splits). Splits only move vertices, so the sorted list stays valid.
  const auto& bound = options.bound;
  const bool bounded = static_cast<bool>(bound);
  const std::size_t no_node = static_cast<std::size_t>(-1);
  struct Place {
    std::size_t node, arc, position;  // node no_node: interior vertex `position` of `arc`
  };
  std::vector<std::pair<double, Vertex_index>> by_bound;
  std::unordered_map<Vertex_index, Place> place;
  if (bounded) {
    for (std::size_t i = 0; i < G.nodes.size(); ++i) {
      by_bound.emplace_back(static_cast<double>(bound(G.nodes[i].vertex)), G.nodes[i].vertex);
      place[G.nodes[i].vertex] = {i, 0, 0};
    }
    for (std::size_t a = 0; a < G.arcs.size(); ++a)
      for (std::size_t k = 0; k < G.arcs[a].vertices.size(); ++k) {
        by_bound.emplace_back(static_cast<double>(bound(G.arcs[a].vertices[k])), G.arcs[a].vertices[k]);
        place[G.arcs[a].vertices[k]] = {no_node, a, k};
      }
    std::sort(by_bound.begin(), by_bound.end());
  }
  for (std::size_t e = 0; e < ends.size(); ++e) {
    if (e > 0 && !FeatureRecon::internal::report_progress(
                     options.progress, 0.95 * static_cast<double>(e) / static_cast<double>(ends.size()))) {
      result.status = Status::interrupted;
      break;
    }
    const Vertex_index end_vertex = ends[e];
    const std::size_t u = node_of.at(end_vertex);
    if (degree[u] != 1) continue;
    // The arc at u and its other end are excluded (joining them would make a tiny loop).
    const std::size_t own = incident[u].front();
    const std::size_t neighbour = G.arcs[own].lower == u ? G.arcs[own].upper : G.arcs[own].lower;
    // An isolated segment whose ends lie within the distance is a blob, not a street that stops short: left
    // alone, as repair_reeb_graph() leaves it.
    if (degree[neighbour] == 1 &&
        static_cast<double>(distance(end_vertex, G.nodes[neighbour].vertex)) <= max_distance)
      continue;
    double best = max_distance;
    std::size_t best_node = G.nodes.size(), best_arc = G.arcs.size(), best_position = 0;
    Vertex_index best_vertex = 0;
    bool found = false;
    auto consider = [&](Vertex_index v, std::size_t node, std::size_t arc, std::size_t position) {
      const double d = static_cast<double>(distance(end_vertex, v));
      if (d < best || (d == best && found && v < best_vertex) || (d == best && !found)) {
        best = d;
        best_vertex = v;
        best_node = node;
        best_arc = arc;
        best_position = position;
        found = true;
      }
    };
    if (bounded) {
      // The candidates' order does not matter: the closest wins, ties by smallest vertex.
      const double b = static_cast<double>(bound(end_vertex)), window = internal::bound_window(max_distance);
      auto it = std::lower_bound(by_bound.begin(), by_bound.end(), std::make_pair(b - window, Vertex_index(0)));
      for (; it != by_bound.end() && it->first <= b + window; ++it) {
        const Place& at = place.at(it->second);
        if (at.node != no_node) {
          if (at.node != u && at.node != neighbour) consider(it->second, at.node, G.arcs.size(), 0);
        } else if (at.arc != own) {
          consider(it->second, G.nodes.size(), at.arc, at.position);
        }
      }
    } else {
      for (std::size_t i = 0; i < G.nodes.size(); ++i)
        if (i != u && i != neighbour) consider(G.nodes[i].vertex, i, G.arcs.size(), 0);
      for (std::size_t a = 0; a < G.arcs.size(); ++a)
        if (a != own)
          for (std::size_t k = 0; k < G.arcs[a].vertices.size(); ++k)
            consider(G.arcs[a].vertices[k], G.nodes.size(), a, k);
    }
    if (!found) continue;
    std::size_t target = best_node;
    if (best_arc < G.arcs.size()) {
      // Split the arc at its vertex: a new (regular, then fork) node.
      Reeb_graph::Node n;
      n.vertex = best_vertex;
      n.value = values[best_vertex];
      Reeb_graph::Arc upper_part;
      upper_part.lower = G.nodes.size();
      upper_part.upper = G.arcs[best_arc].upper;
      upper_part.vertices.assign(G.arcs[best_arc].vertices.begin() + static_cast<std::ptrdiff_t>(best_position) + 1,
                                 G.arcs[best_arc].vertices.end());
      G.arcs[best_arc].vertices.resize(best_position);
      const std::size_t old_upper = G.arcs[best_arc].upper;
      target = G.nodes.size();
      G.arcs[best_arc].upper = target;
      G.nodes.push_back(std::move(n));
      node_of.emplace(best_vertex, target);
      std::replace(incident[old_upper].begin(), incident[old_upper].end(), best_arc, G.arcs.size());
      incident.push_back({best_arc, G.arcs.size()});
      degree.push_back(2);
      if (bounded) {
        place[best_vertex] = {target, 0, 0};
        for (std::size_t k = 0; k < upper_part.vertices.size(); ++k)
          place[upper_part.vertices[k]] = {no_node, G.arcs.size(), k};
      }
      G.arcs.push_back(std::move(upper_part));
    }
    Reeb_graph::Arc link;
    link.lower = u;
    link.upper = target;
    incident[u].push_back(G.arcs.size());
    incident[target].push_back(G.arcs.size());
    ++degree[u], ++degree[target];
    G.arcs.push_back(std::move(link));
    ++result.connected;
  }
  // Nodes back in (value, vertex) order, arcs oriented upwards and sorted, types and components.
  std::vector<std::size_t> order(G.nodes.size()), index(G.nodes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&G](std::size_t a, std::size_t b) {
    return G.nodes[a].value < G.nodes[b].value || (G.nodes[a].value == G.nodes[b].value && G.nodes[a].vertex < G.nodes[b].vertex);
  });
  Reeb_graph& H = result.graph;
  for (std::size_t i = 0; i < order.size(); ++i) {
    index[order[i]] = i;
    H.nodes.push_back(std::move(G.nodes[order[i]]));
  }
  for (auto& a : G.arcs) {
    a.lower = index[a.lower];
    a.upper = index[a.upper];
    if (a.lower > a.upper) std::swap(a.lower, a.upper);  // only new links (no interior vertices) can be reversed
  }
  // Arcs by lower node, then by the (f, index) order of the first vertex each reaches (Reeb_graph::arcs).
  std::sort(G.arcs.begin(), G.arcs.end(), [&H, &values](const Reeb_graph::Arc& a, const Reeb_graph::Arc& b) {
    const Vertex_index fa = a.vertices.empty() ? H.nodes[a.upper].vertex : a.vertices.front();
    const Vertex_index fb = b.vertices.empty() ? H.nodes[b.upper].vertex : b.vertices.front();
    return std::make_tuple(a.lower, values[fa], fa, a.upper) < std::make_tuple(b.lower, values[fb], fb, b.upper);
  });
  H.arcs = std::move(G.arcs);
  internal::refresh_node_types(H);
  if (result.status == Status::success) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

/// Result of prune_reeb_graph_components().
struct Reeb_prune_result {
  Reeb_graph graph;                   ///< the graph without the pruned components
  std::size_t removed_components = 0;          ///< number of components removed
  std::vector<Vertex_index> removed_vertices;  ///< input vertices of the removed components (sorted)
};

/// Removes every connected component of height (maximum minus minimum of f over its nodes) at most
/// `max_height`: the essential 0-dimensional features of persistence <= max_height, which simplification keeps
/// (a component is never merged into another). Small isolated pieces of noise go; nodes keep their order.
/// \pre max_height >= 0; R as for repair_reeb_graph() (checked; throws).
inline Reeb_prune_result prune_reeb_graph_components(const Reeb_graph& R, double max_height) {
  if (!(max_height >= 0))
    FeatureRecon::internal::throw_invalid_argument("prune_reeb_graph_components", "max_height must be >= 0, got ",
                                                   max_height);
  internal::check_reeb_graph(R, "prune_reeb_graph_components");
  const std::vector<std::size_t> component = internal::node_components(R);
  auto find = [&component](std::size_t x) { return component[x]; };
  std::vector<double> low(R.nodes.size(), 0), high(R.nodes.size(), 0);
  std::vector<bool> seen(R.nodes.size(), false);
  for (std::size_t i = 0; i < R.nodes.size(); ++i) {
    const std::size_t c = find(i);
    if (!seen[c]) {
      seen[c] = true;
      low[c] = high[c] = R.nodes[i].value;
    }
    low[c] = std::min(low[c], R.nodes[i].value);
    high[c] = std::max(high[c], R.nodes[i].value);
  }
  Reeb_prune_result result;
  std::vector<std::size_t> index(R.nodes.size(), static_cast<std::size_t>(-1));
  for (std::size_t i = 0; i < R.nodes.size(); ++i) {
    const std::size_t c = find(i);
    if (high[c] - low[c] <= max_height) {
      if (c == i) ++result.removed_components;
      result.removed_vertices.push_back(R.nodes[i].vertex);
      result.removed_vertices.insert(result.removed_vertices.end(), R.nodes[i].members.begin(), R.nodes[i].members.end());
      continue;
    }
    if (c == i) ++result.graph.components;  // counted here: the input's field may be unset (a graph built by hand)
    index[i] = result.graph.nodes.size();
    result.graph.nodes.push_back(R.nodes[i]);
  }
  for (const auto& a : R.arcs) {
    if (index[a.lower] == static_cast<std::size_t>(-1)) {
      result.removed_vertices.insert(result.removed_vertices.end(), a.vertices.begin(), a.vertices.end());
      continue;
    }
    Reeb_graph::Arc b = a;
    b.lower = index[a.lower];
    b.upper = index[a.upper];
    result.graph.arcs.push_back(std::move(b));
  }
  std::sort(result.removed_vertices.begin(), result.removed_vertices.end());
  return result;
}

/// Result of trim_essential_stubs().
struct Reeb_trim_result {
  Reeb_graph graph;          ///< the graph with the stubs contracted into their forks
  std::size_t trimmed = 0;   ///< number of stubs contracted
};

/// Contracts, in every component, the arc from the global minimum (and the one to the global maximum) into the
/// fork at its other end when that arc is a stub: the extremum has degree 1, the fork degree >= 3 (counting only
/// arcs not contracted before: of a Y whose two ends are both stubs, one is contracted), and the arc's
/// height is at most `max_height`. Simplification never removes these arcs (the global extrema are an essential
/// pair), so on a loop the base point of the geodesic function and the farthest point stay as spurs of height
/// about half the Rips radius. Contracting them moves the essential pair by at most `max_height` and leaves every
/// other feature as it is; the stub's points join the fork node's members.
/// \pre max_height >= 0; R as for repair_reeb_graph() (checked; throws).
inline Reeb_trim_result trim_essential_stubs(const Reeb_graph& R, double max_height) {
  if (!(max_height >= 0))
    FeatureRecon::internal::throw_invalid_argument("trim_essential_stubs", "max_height must be >= 0, got ", max_height);
  internal::check_reeb_graph(R, "trim_essential_stubs");
  Reeb_trim_result result;
  const std::size_t n = R.nodes.size();
  std::vector<std::vector<std::size_t>> incident(n);
  for (std::size_t a = 0; a < R.arcs.size(); ++a) {
    incident[R.arcs[a].lower].push_back(a);
    incident[R.arcs[a].upper].push_back(a);
  }
  // Components (union-find on nodes), their lowest and highest node (nodes are sorted by (value, vertex)).
  const std::vector<std::size_t> component = internal::node_components(R);
  auto find = [&component](std::size_t x) { return component[x]; };
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> lowest(n, none), highest(n, none);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = find(i);
    if (lowest[c] == none) lowest[c] = i;
    highest[c] = i;
  }
  std::vector<bool> drop_node(n, false), drop_arc(R.arcs.size(), false);
  std::vector<std::size_t> degree(n);  // as stubs go: a fork left with two arcs is no fork (a Y keeps a branch)
  for (std::size_t i = 0; i < n; ++i) degree[i] = incident[i].size();
  std::vector<Reeb_graph::Node> nodes = R.nodes;
  for (std::size_t c = 0; c < n; ++c) {
    if (lowest[c] == none) continue;
    for (const std::size_t e : {lowest[c], highest[c]}) {
      if (incident[e].size() != 1 || lowest[c] == highest[c]) continue;
      const std::size_t a = incident[e][0];
      const std::size_t fork = R.arcs[a].lower == e ? R.arcs[a].upper : R.arcs[a].lower;
      if (drop_node[fork] || degree[fork] < 3) continue;
      if (std::fabs(R.nodes[fork].value - R.nodes[e].value) > max_height) continue;
      auto& m = nodes[fork].members;
      m.push_back(R.nodes[e].vertex);
      m.insert(m.end(), R.nodes[e].members.begin(), R.nodes[e].members.end());
      m.insert(m.end(), R.arcs[a].vertices.begin(), R.arcs[a].vertices.end());
      drop_node[e] = true;
      drop_arc[a] = true;
      --degree[fork];
      ++result.trimmed;
    }
  }
  std::vector<std::size_t> index(n, none);
  for (std::size_t i = 0; i < n; ++i)
    if (!drop_node[i]) {
      index[i] = result.graph.nodes.size();
      result.graph.nodes.push_back(std::move(nodes[i]));
    }
  for (std::size_t a = 0; a < R.arcs.size(); ++a)
    if (!drop_arc[a]) {
      Reeb_graph::Arc b = R.arcs[a];
      b.lower = index[b.lower];
      b.upper = index[b.upper];
      result.graph.arcs.push_back(std::move(b));
    }
  internal::refresh_node_types(result.graph);
  return result;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H
