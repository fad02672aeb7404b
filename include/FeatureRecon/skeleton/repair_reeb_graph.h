// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H
#define FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

namespace internal {
/// What a stopped trim_essential_stubs() or prune_reeb_graph_components() returns: the input graph, nothing
/// done, status interrupted.
template <class Result>
Result input_unchanged(const Reeb_graph& R) {
  Result stop;
  stop.graph = R;
  stop.status = Status::interrupted;
  return stop;
}

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

/// Checks what the repair functions rely on, naming the first offending node or arc: node values finite and
/// in strictly increasing (value, vertex) order, every arc going up between two nodes of the graph (lower <
/// upper). With `values`, every vertex the graph uses (nodes, members, arc vertices) indexes it, and arc
/// vertices (which can become nodes) have finite values.
inline void check_reeb_graph(const Reeb_graph& G, const char* fn,
                             const std::vector<double>* values = nullptr) {
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
      throw_invalid_argument(fn, what, " ", index, " has vertex ", v, " out of range [0, ", values->size(),
                             ")");
  };
  for (std::size_t i = 0; i < G.nodes.size(); ++i) {
    check(G.nodes[i].vertex, "node", i);
    for (const Vertex_index v : G.nodes[i].members) check(v, "node", i);
  }
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    for (const Vertex_index v : G.arcs[k].vertices) {
      check(v, "arc", k);
      if (!std::isfinite((*values)[v]))
        throw_invalid_argument(fn, "arc ", k, " has vertex ", v, " of value ", (*values)[v],
                               " (finite needed)");
    }
}

/// Component of each node: the smallest node index in it (union-find over the arcs).
inline std::vector<std::size_t> node_components(const Reeb_graph& G) {
  FeatureRecon::internal::Union_find<std::size_t> sets(G.nodes.size());
  for (const auto& a : G.arcs) sets.unite(a.lower, a.upper);
  return sets.labels();
}
/// The bound of input vertex v, checked: a NaN or an infinity throws, naming the bound and the vertex (no
/// order to sort by, and no difference to compare with the distance).
template <class Bound>
double checked_bound(const Bound& bound, Vertex_index v, const char* fn, const char* name = "bound") {
  const double b = static_cast<double>(bound(v));
  if (!std::isfinite(b))
    FeatureRecon::internal::throw_invalid_argument(fn, "Reeb_repair_options::", name, " of vertex ", v,
                                                   " is ", b, " (a finite number needed)");
  return b;
}
/// The user's distance between input points a and b, checked: NaN or negative is not a distance (a NaN joined
/// nothing and a negative one joined any pair, silently).
template <class Distance>
double checked_distance(Distance& distance, Vertex_index a, Vertex_index b, const char* fn) {
  const double d = static_cast<double>(distance(a, b));
  if (!(d >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "the distance between vertices ", a, " and ", b,
                                                   " is ", d,
                                                   " (the distance callable must return a number >= 0)");
  return d;
}
/// The bound difference up to which a pair is measured: max_distance with room for the rounding of a computed
/// distance (a Euclidean distance may come out an ulp below the difference of one coordinate).
inline double bound_window(double max_distance) {
  return max_distance * (1 + 1e-12) + std::numeric_limits<double>::denorm_min();
}

/// A slot (a node, or a vertex of an arc) and the values of Reeb_repair_options' bounds at its vertex (the
/// second equal to the first without a second bound).
struct Bounded_slot {
  double first, second;
  std::size_t slot;
};

/// The candidates of a search within a distance, from Reeb_repair_options' bounds. With one bound: the slots
/// sorted by it, a query visits those within the window of its bound (a strip; O(sqrt n) of n points of even
/// density in the plane). With two: columns of the first bound about a window wide, each sorted by the second
/// bound, a query visits the slots within the window in both bounds (O(1) cells of the window's side).
/// Differences are compared with the window, never shifted bounds: rounding is monotone, so a slot whose
/// bounds truly differ by at most the window is visited whatever the bounds' magnitude. The sorted keys,
/// slots and (with two bounds) first bounds lie in separate arrays: a strip's scan reads 8 bytes a slot.
class Bound_index {
 public:
  /// `two`: whether `slots` carry a second bound. \pre the bounds finite, window > 0.
  Bound_index(std::vector<Bounded_slot> slots, double window, bool two) : window_(window), two_(two) {
    auto by = [](auto key) {
      return [key](const Bounded_slot& a, const Bounded_slot& b) {
        return key(a) < key(b) || (!(key(b) < key(a)) && a.slot < b.slot);
      };
    };
    std::sort(slots.begin(), slots.end(), by([](const Bounded_slot& s) { return s.first; }));
    // Columns: runs of the sorted slots whose first bounds lie within the window of the run's first one (all
    // slots with one bound). Run starts are more than a window apart, so a query meets at most 3 columns,
    // whatever the spread of the bound (floor((first - least) / window) capped at 2^62 put every slot past a
    // far outlier, or every slot at max_distance 0, into one column: a strip of the second bound).
    for (std::size_t b = 0; b < slots.size();) {
      std::size_t e = b + 1;
      while (e < slots.size() && (!two_ || slots[e].first - slots[b].first <= window_)) ++e;
      columns_.push_back({slots[b].first, slots[e - 1].first, b, e});
      if (two_)
        std::sort(slots.begin() + static_cast<std::ptrdiff_t>(b),
                  slots.begin() + static_cast<std::ptrdiff_t>(e),
                  by([](const Bounded_slot& s) { return s.second; }));
      b = e;
    }
    keys_.reserve(slots.size());
    slots_.reserve(slots.size());
    if (two_) firsts_.reserve(slots.size());
    for (const Bounded_slot& s : slots) {
      keys_.push_back(two_ ? s.second : s.first);
      slots_.push_back(s.slot);
      if (two_) firsts_.push_back(s.first);
    }
  }
  /// Calls visit(slot) for every slot whose bounds differ from (first, second) by at most the window (each
  /// once; in no particular order).
  template <class Visit>
  void visit(double first, double second, Visit&& visit) const {
    const double key = two_ ? second : first;
    const auto c0 = std::partition_point(columns_.begin(), columns_.end(),
                                         [&](const Column& c) { return first - c.last > window_; });
    for (auto c = c0; c != columns_.end() && c->first - first <= window_; ++c)
      for (std::size_t i = lowest_within(*c, key); i < c->end && keys_[i] - key <= window_; ++i)
        if (near_first(i, first)) visit(slots_[i]);
  }
  /// The number of columns (tests: each spans at most the window in the first bound, none with one bound).
  std::size_t number_of_columns() const { return columns_.size(); }
  /// Calls pair(s, t) once for every two slots whose bounds differ by at most the window, s before t in the
  /// sorted order, and after(k) once the pairs of the k-th slot in that order are visited (k = 0, 1, ...);
  /// after() returning true stops the sweep (then false is returned).
  template <class Pair, class After>
  bool for_each_pair(Pair&& pair, After&& after) const {
    for (std::size_t c = 0; c < columns_.size(); ++c)
      for (std::size_t i = columns_[c].begin; i < columns_[c].end; ++i) {
        const double key = keys_[i], first = two_ ? firsts_[i] : key;
        // The rest of its own column, by key; then the later columns within the window (none with one
        // bound), where the keys lie on both sides.
        for (std::size_t j = i + 1; j < columns_[c].end && keys_[j] - key <= window_; ++j)
          if (near_first(j, first)) pair(slots_[i], slots_[j]);
        for (std::size_t d = c + 1; d < columns_.size() && columns_[d].first - first <= window_; ++d)
          for (std::size_t j = lowest_within(columns_[d], key);
               j < columns_[d].end && keys_[j] - key <= window_; ++j)
            if (near_first(j, first)) pair(slots_[i], slots_[j]);
        if (after(i)) return false;
      }
    return true;
  }

 private:
  struct Column {
    double first, last;  // the least and the largest first bound of its slots
    std::size_t begin, end;
  };
  /// The first index of column c whose key lies at most the window below `key` (the column's end if none).
  std::size_t lowest_within(const Column& c, double key) const {
    return static_cast<std::size_t>(std::partition_point(keys_.begin() + static_cast<std::ptrdiff_t>(c.begin),
                                                         keys_.begin() + static_cast<std::ptrdiff_t>(c.end),
                                                         [&](double k) { return key - k > window_; }) -
                                    keys_.begin());
  }
  /// Whether sorted slot i's first bound is within the window of `first` (always, with one bound: the key).
  bool near_first(std::size_t i, double first) const {
    return !two_ || (first - firsts_[i] <= window_ && firsts_[i] - first <= window_);
  }
  // By column, then by (key, slot); the key is the second bound (the first with one bound).
  std::vector<double> keys_, firsts_;
  std::vector<std::size_t> slots_;
  std::vector<Column> columns_;
  double window_;
  bool two_;
};

/// Whether the options ask for a bounded search at all (a second bound without a first throws).
inline bool bounded_search(const Reeb_repair_options& options, const char* fn) {
  if (options.second_bound && !options.bound)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "Reeb_repair_options::second_bound is set without bound (the first bound is needed)");
  return static_cast<bool>(options.bound);
}
/// The bounds of input vertex v as a Bounded_slot (checked).
inline Bounded_slot bounded_slot(const Reeb_repair_options& options, Vertex_index v, std::size_t slot,
                                 const char* fn) {
  const double first = checked_bound(options.bound, v, fn);
  return {first, options.second_bound ? checked_bound(options.second_bound, v, fn, "second_bound") : first,
          slot};
}
}  // namespace internal

/// Result of repair_reeb_graph().
struct Reeb_repair_result {
  Reeb_graph graph;        ///< the graph with the new arcs; may contain regular nodes (simplify next)
  std::size_t joined = 0;  ///< number of arcs added
  Status status = Status::success;  ///< interrupted when the progress callback returned false (no arc added)
};

/// Graph fixing of dissertation Ch. 3.3.2: joins pairs of degree-1 nodes whose input points are at most
/// `max_distance` apart (the input distance, not the distance in the complex), closest pairs first (equal
/// distances: the pair of smaller node indices, compared lexicographically, first), each node at most once. A
/// joined pair gets a new arc (no interior vertices) from the lower node to the higher one. The two ends of
/// one arc (an isolated segment) are never joined: when they are each other's closest free end, the segment
/// is left as it is (no loop of two arcs), and neither end joins anything farther. The new features are not
/// checked: simplify_by_persistence(graph, values, delta) afterwards removes the small ones and absorbs nodes
/// that became regular. O(k^2 log k) for k degree-1 nodes; with Reeb_repair_options::bound, only pairs whose
/// bounds differ by at most max_distance are measured (the same result; with second_bound too, pairs within
/// it in both, found in a grid: O(k log k + p) for p such pairs). The progress callback is asked after each
/// end's pairs are measured; a stop adds no arc (the graph is R, status interrupted).
/// \tparam Distance callable `double(Vertex_index, Vertex_index)`, the distance between two input points (>= 0;
///   NaN or a negative value throws std::invalid_argument naming the two vertices).
/// \pre max_distance >= 0 and finite; R's node values finite and in increasing (value, vertex) order, its
///   arcs going up between its nodes, as reeb_graph() and simplify_by_persistence() return them;
///   Reeb_repair_options::bound (and second_bound) finite at every degree-1 node, second_bound only with
///   bound (all checked; throws).
template <class Distance>
Reeb_repair_result repair_reeb_graph(const Reeb_graph& R, double max_distance, Distance distance,
                                     const Reeb_repair_options& options = {}) {
  const char* fn = "repair_reeb_graph";
  if (!(max_distance >= 0 && std::isfinite(max_distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_distance must be finite and >= 0, got ",
                                                   max_distance);
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
    const double d = internal::checked_distance(distance, G.nodes[x].vertex, G.nodes[y].vertex, fn);
    if (d <= max_distance) candidates.emplace_back(d, x, y);
  };
  auto stopped_after = [&](std::size_t a) {  // the pairs of a + 1 ends are measured
    if (FeatureRecon::internal::report_progress(
            options.progress, 0.9 * static_cast<double>(a + 1) / static_cast<double>(ends.size())))
      return false;
    result.status = Status::interrupted;
    return true;
  };
  if (!internal::bounded_search(options, fn)) {
    for (std::size_t a = 0; a < ends.size(); ++a) {
      for (std::size_t b = a + 1; b < ends.size(); ++b) measure(ends[a], ends[b]);
      if (stopped_after(a)) return result;
    }
  } else {
    // Only the ends within the window of each other's bounds: a pair farther apart in a bound is farther
    // apart in distance. Each pair is measured once.
    std::vector<internal::Bounded_slot> at;
    at.reserve(ends.size());
    for (const std::size_t e : ends) at.push_back(internal::bounded_slot(options, G.nodes[e].vertex, e, fn));
    const internal::Bound_index index(std::move(at), internal::bound_window(max_distance),
                                      static_cast<bool>(options.second_bound));
    if (!index.for_each_pair([&](std::size_t x, std::size_t y) { measure(std::min(x, y), std::max(x, y)); },
                             stopped_after))
      return result;
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
  Reeb_graph graph;           ///< the graph with the new arcs (and nodes where arcs were split)
  std::size_t connected = 0;  ///< number of arcs added
  /// interrupted when the progress callback returned false: the graph holds the arcs of the dead ends taken
  /// before
  Status status = Status::success;
};

namespace internal {
/// connect_dead_ends(), adding to `moved` the number of arc vertices that splits moved into a new arc (a test
/// checks that it stays O(n log n): a split that copied the rest of a long arc made the function quadratic).
template <class Distance>
Reeb_dead_end_result connect_dead_ends_counting(const Reeb_graph& R, const std::vector<double>& values,
                                                double max_distance, Distance distance,
                                                const Reeb_repair_options& options, std::size_t& moved) {
  const char* fn = "connect_dead_ends";
  if (!(max_distance >= 0 && std::isfinite(max_distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_distance must be finite and >= 0, got ",
                                                   max_distance);
  check_reeb_graph(R, fn, &values);
  Reeb_dead_end_result result;
  const std::size_t none = static_cast<std::size_t>(-1), n0 = R.nodes.size();
  // The arcs as they split: pieces of R's arcs, each the range [begin, end) of the vertices of its input arc
  // (input none: a new link, no vertices). A split cuts a range without copying it; the vertices are copied
  // once, at the end, into vectors of their exact size.
  struct Piece {
    std::size_t lower, upper, input, begin, end;
  };
  std::vector<Piece> pieces;
  pieces.reserve(R.arcs.size());
  std::vector<Reeb_graph::Node> nodes;  // R's, then the new ones appended: indices stay valid until the end
  // Degrees, the input arc at each degree-1 node, the input arc each split node was a vertex of, and the
  // pieces at the lower and the upper end of each input arc (a dead end's piece changes when its arc splits).
  std::vector<std::size_t> degree(n0, 0), arc_at(n0, none), origin(n0, none), lower_piece, upper_piece;
  lower_piece.reserve(R.arcs.size());
  upper_piece.reserve(R.arcs.size());
  for (std::size_t a = 0; a < R.arcs.size(); ++a) {
    const Reeb_graph::Arc& arc = R.arcs[a];
    ++degree[arc.lower], ++degree[arc.upper];
    arc_at[arc.lower] = arc_at[arc.upper] = a;
    pieces.push_back({arc.lower, arc.upper, a, 0, arc.vertices.size()});
    lower_piece.push_back(a);
    upper_piece.push_back(a);
  }
  std::vector<std::size_t> ends;
  for (std::size_t i = 0; i < n0; ++i)
    if (degree[i] == 1) ends.push_back(i);
  // Each dead end adds at most one node (a split) and two pieces: room for all, so that nothing is copied to
  // grow.
  nodes.reserve(n0 + ends.size());
  nodes.assign(R.nodes.begin(), R.nodes.end());
  degree.reserve(n0 + ends.size());
  origin.reserve(n0 + ends.size());
  pieces.reserve(R.arcs.size() + 2 * ends.size());
  // With a bound: every vertex of the graph as a slot (node i is slot i, vertex k of input arc a is slot
  // first_slot[a] + k) sorted by bound, and where each slot is now: a node, or the piece that holds it.
  // Splits only move vertices between pieces and into new nodes, so the sorted list stays valid.
  const bool bounded = bounded_search(options, fn);
  struct Place {
    std::size_t node, piece;  // node none: an interior vertex of `piece`
  };
  std::vector<std::size_t> first_slot;
  std::vector<Vertex_index> vertex_of;
  std::vector<Place> place;
  Bound_index by_bound({}, 1.0, false);
  if (bounded) {
    std::size_t slots = n0;
    first_slot.reserve(R.arcs.size());
    for (const Reeb_graph::Arc& arc : R.arcs) {
      first_slot.push_back(slots);
      slots += arc.vertices.size();
    }
    vertex_of.reserve(slots);
    place.reserve(slots);
    for (std::size_t i = 0; i < n0; ++i) {
      vertex_of.push_back(R.nodes[i].vertex);
      place.push_back({i, none});
    }
    for (std::size_t a = 0; a < R.arcs.size(); ++a)
      for (const Vertex_index v : R.arcs[a].vertices) {
        vertex_of.push_back(v);
        place.push_back({none, a});
      }
    std::vector<Bounded_slot> at;
    at.reserve(slots);
    for (std::size_t s = 0; s < slots; ++s) at.push_back(bounded_slot(options, vertex_of[s], s, fn));
    by_bound =
        Bound_index(std::move(at), bound_window(max_distance), static_cast<bool>(options.second_bound));
  }
  for (std::size_t e = 0; e < ends.size(); ++e) {
    if (e > 0 && !FeatureRecon::internal::report_progress(
                     options.progress, 0.95 * static_cast<double>(e) / static_cast<double>(ends.size()))) {
      result.status = Status::interrupted;
      break;
    }
    const std::size_t u = ends[e];
    if (degree[u] != 1) continue;
    const Vertex_index end_vertex = nodes[u].vertex;
    // u's input arc, the piece of it at u, and the node at that piece's other end.
    const std::size_t input = arc_at[u];
    const std::size_t own = R.arcs[input].lower == u ? lower_piece[input] : upper_piece[input];
    const std::size_t neighbour = pieces[own].lower == u ? pieces[own].upper : pieces[own].lower;
    // An isolated segment whose ends lie within the distance is a blob, not a street that stops short: left
    // alone, as repair_reeb_graph() leaves it.
    if (degree[neighbour] == 1 &&
        internal::checked_distance(distance, end_vertex, nodes[neighbour].vertex, fn) <= max_distance)
      continue;
    // Excluded: every point of u's input arc and its far end, split or not (joining them would close a loop
    // of the street itself). Excluding only the piece at u let a dead end whose arc was split for an earlier
    // one reach the far part of its own street (a U-shaped street): the result depended on the order of the
    // dead ends.
    const std::size_t far = R.arcs[input].lower == u ? R.arcs[input].upper : R.arcs[input].lower;
    auto excluded_node = [&](std::size_t i) { return i == u || i == far || origin[i] == input; };
    auto excluded_piece = [&](std::size_t p) { return pieces[p].input == input; };
    double best = max_distance;
    std::size_t best_node = none, best_piece = none, best_position = 0;
    Vertex_index best_vertex = 0;
    bool found = false;
    auto consider = [&](Vertex_index v, std::size_t node, std::size_t piece, std::size_t position) {
      const double d = internal::checked_distance(distance, end_vertex, v, fn);
      if (d < best || (d == best && found && v < best_vertex) || (d == best && !found)) {
        best = d;
        best_vertex = v;
        best_node = node;
        best_piece = piece;
        best_position = position;
        found = true;
      }
    };
    if (bounded) {
      // The candidates' order does not matter: the closest wins, ties by smallest vertex.
      const Bounded_slot b = bounded_slot(options, end_vertex, 0, fn);
      by_bound.visit(b.first, b.second, [&](std::size_t s) {
        const Place& at = place[s];
        if (at.node != none) {
          if (!excluded_node(at.node)) consider(vertex_of[s], at.node, none, 0);
        } else if (!excluded_piece(at.piece)) {
          consider(vertex_of[s], none, at.piece, s - first_slot[pieces[at.piece].input]);
        }
      });
    } else {
      for (std::size_t i = 0; i < nodes.size(); ++i)
        if (!excluded_node(i)) consider(nodes[i].vertex, i, none, 0);
      for (std::size_t p = 0; p < pieces.size(); ++p)
        if (pieces[p].input != none && !excluded_piece(p)) {
          const std::vector<Vertex_index>& vertices = R.arcs[pieces[p].input].vertices;
          for (std::size_t k = pieces[p].begin; k < pieces[p].end; ++k) consider(vertices[k], none, p, k);
        }
    }
    if (!found) continue;
    std::size_t target = best_node;
    if (best_piece != none) {
      // Split the piece at its vertex: a new (regular, then fork) node. The shorter side moves into a new
      // piece, the longer one stays: a vertex only moves into a piece at most half as long, O(log n) times.
      const std::size_t a = pieces[best_piece].input, q = pieces.size();
      target = nodes.size();
      Reeb_graph::Node node;
      node.vertex = best_vertex;
      node.value = values[best_vertex];
      nodes.push_back(std::move(node));
      degree.push_back(2);
      origin.push_back(a);
      Piece& p = pieces[best_piece];
      Piece side;
      if (best_position - p.begin <= p.end - best_position - 1) {
        side = {p.lower, target, a, p.begin, best_position};
        p.lower = target;
        p.begin = best_position + 1;
        if (lower_piece[a] == best_piece) lower_piece[a] = q;
      } else {
        side = {target, p.upper, a, best_position + 1, p.end};
        p.upper = target;
        p.end = best_position;
        if (upper_piece[a] == best_piece) upper_piece[a] = q;
      }
      moved += side.end - side.begin;
      if (bounded) {
        place[first_slot[a] + best_position] = {target, none};
        for (std::size_t k = side.begin; k < side.end; ++k) place[first_slot[a] + k].piece = q;
      }
      pieces.push_back(side);
    }
    pieces.push_back({u, target, none, 0, 0});
    ++degree[u], ++degree[target];
    ++result.connected;
  }
  // Nodes back in (value, vertex) order, arcs oriented upwards and sorted, types and components.
  std::vector<std::size_t> order(nodes.size()), index(nodes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&nodes](std::size_t a, std::size_t b) {
    return nodes[a].value < nodes[b].value ||
           (nodes[a].value == nodes[b].value && nodes[a].vertex < nodes[b].vertex);
  });
  Reeb_graph& H = result.graph;
  H.nodes.reserve(nodes.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    index[order[i]] = i;
    H.nodes.push_back(std::move(nodes[order[i]]));
  }
  H.arcs.reserve(pieces.size());
  for (const Piece& p : pieces) {
    Reeb_graph::Arc arc;
    arc.lower = index[p.lower];
    arc.upper = index[p.upper];
    if (arc.lower > arc.upper)
      std::swap(arc.lower, arc.upper);  // only links (no interior vertices) can be reversed
    if (p.input != none) {
      const std::vector<Vertex_index>& vertices = R.arcs[p.input].vertices;
      arc.vertices.assign(vertices.begin() + static_cast<std::ptrdiff_t>(p.begin),
                          vertices.begin() + static_cast<std::ptrdiff_t>(p.end));
    }
    H.arcs.push_back(std::move(arc));
  }
  // Arcs by lower node, then by the (f, index) order of the first vertex each reaches (Reeb_graph::arcs).
  // Arcs that compare equal have the same ends and no vertices, so the result does not depend on the pieces'
  // order.
  std::sort(H.arcs.begin(), H.arcs.end(), [&H, &values](const Reeb_graph::Arc& a, const Reeb_graph::Arc& b) {
    const Vertex_index fa = a.vertices.empty() ? H.nodes[a.upper].vertex : a.vertices.front();
    const Vertex_index fb = b.vertices.empty() ? H.nodes[b.upper].vertex : b.vertices.front();
    return std::make_tuple(a.lower, values[fa], fa, a.upper) <
           std::make_tuple(b.lower, values[fb], fb, b.upper);
  });
  refresh_node_types(H);
  if (result.status == Status::success) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}
}  // namespace internal

/// The other half of graph fixing: a degree-1 node whose input point is at most `max_distance` from a point
/// of another part of the graph (a node, or an interior vertex of an arc) gets an arc to the closest such
/// point (ties: smallest vertex index), splitting that arc there: a street that stops short of the street it
/// meets (a T junction with a gap). Not another part: the node's own arc in R, its vertices and its other
/// end, also once the arc was split for an earlier dead end (a U-shaped street is not closed on itself,
/// whatever the order of the dead ends). Dead ends are taken in node order and see the arcs added before
/// them: an arc that is still isolated when its dead end's turn comes (no arc added before split it or ends
/// on it) and whose two ends lie within `max_distance` of each other is not connected (too short to be a
/// street end); one that an earlier dead end split is part of a larger piece, and its ends connect like
/// any other. Simplify afterwards, as after repair_reeb_graph(). O(k * n) distance evaluations for k
/// dead ends and n input vertices in the graph, and O(n log n) for all splits (each moves the shorter side of
/// its arc); the arcs come back in the order of Reeb_graph::arcs, their vertex vectors no larger than they
/// need. With Reeb_repair_options::bound, only the vertices whose bound lies within max_distance of the dead
/// end's are measured: O(n log n + k w) for w such vertices, the same result; with second_bound too, those
/// within it in both bounds (a grid; w then O(1) for points of even density in the plane). The progress
/// callback is asked after each dead end; a stop keeps the arcs added so far (a valid graph, status
/// interrupted).
/// \param values f of every input vertex (for the new nodes).
/// \tparam Distance callable `double(Vertex_index, Vertex_index)`, the input distance (>= 0; NaN or a negative
///   value throws std::invalid_argument naming the two vertices).
/// \pre max_distance >= 0 and finite; R as for repair_reeb_graph(), and every vertex it uses indexes
///   `values`; Reeb_repair_options::bound (and second_bound) finite at every vertex of R, second_bound only
///   with bound (all checked; throws).
template <class Distance>
Reeb_dead_end_result connect_dead_ends(const Reeb_graph& R, const std::vector<double>& values,
                                       double max_distance, Distance distance,
                                       const Reeb_repair_options& options = {}) {
  std::size_t moved = 0;
  return internal::connect_dead_ends_counting(R, values, max_distance, distance, options, moved);
}

/// Result of prune_reeb_graph_components().
struct Reeb_prune_result {
  Reeb_graph graph;                            ///< the graph without the pruned components
  std::size_t removed_components = 0;          ///< number of components removed
  std::vector<Vertex_index> removed_vertices;  ///< input vertices of the removed components (sorted)
  /// success, or interrupted when the progress callback returned false (the graph is then the input, nothing
  /// removed)
  Status status = Status::success;
};

/// Removes every connected component of height (maximum minus minimum of f over its nodes) at most
/// `max_height`: the essential 0-dimensional features of persistence <= max_height, which simplification
/// keeps (a component is never merged into another). Small isolated pieces of noise go; nodes keep their
/// order. A stop through the progress callback leaves Status::interrupted and the input graph unchanged.
/// \pre max_height >= 0; R as for repair_reeb_graph() (checked; throws).
inline Reeb_prune_result prune_reeb_graph_components(const Reeb_graph& R, double max_height,
                                                     const Reeb_prune_options& options = {}) {
  if (!(max_height >= 0))
    FeatureRecon::internal::throw_invalid_argument("prune_reeb_graph_components",
                                                   "max_height must be >= 0, got ", max_height);
  internal::check_reeb_graph(R, "prune_reeb_graph_components");
  auto interrupted = [&R] { return internal::input_unchanged<Reeb_prune_result>(R); };
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) return interrupted();
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
    if ((i & 1023) == 0 && i > 0 &&
        !FeatureRecon::internal::report_progress(
            options.progress, 0.2 + 0.6 * static_cast<double>(i) / static_cast<double>(R.nodes.size())))
      return interrupted();
    const std::size_t c = find(i);
    if (high[c] - low[c] <= max_height) {
      if (c == i) ++result.removed_components;
      result.removed_vertices.push_back(R.nodes[i].vertex);
      result.removed_vertices.insert(result.removed_vertices.end(), R.nodes[i].members.begin(),
                                     R.nodes[i].members.end());
      continue;
    }
    if (c == i)
      ++result.graph.components;  // counted here: the input's field may be unset (a graph built by hand)
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
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

/// Result of trim_essential_stubs().
struct Reeb_trim_result {
  Reeb_graph graph;         ///< the graph with the stubs contracted into their forks
  std::size_t trimmed = 0;  ///< number of stubs contracted
  /// success, or interrupted when the progress callback returned false (the graph is then the input, nothing
  /// trimmed)
  Status status = Status::success;
};

/// Contracts, in every component, the arc from the global minimum (and the one to the global maximum) into
/// the fork at its other end when that arc is a stub: the extremum has degree 1, the fork degree >= 3
/// (counting only arcs not contracted before: of a Y whose two ends are both stubs, one is contracted), and
/// the arc's height is at most `max_height`. Simplification never removes these arcs (the global extrema are
/// an essential pair), so on a loop the base point of the geodesic function and the farthest point stay as
/// spurs of height about half the Rips radius. Contracting a stub is the same as giving its points the fork's
/// value (a change of f by at most `max_height`), so by stability every diagram (branches, loops, essential
/// pairs) moves by at most `max_height` in bottleneck distance. The essential pair moves by at most that; a
/// feature whose extreme lies within the stub's levels may shrink or go with it (where the global minimum's
/// stub meets a second minimum at a down-fork, that minimum becomes the global one and its own pair goes);
/// the stub's points join the fork node's members. A stop through the progress callback leaves
/// Status::interrupted and the input graph unchanged.
/// \pre max_height >= 0; R as for repair_reeb_graph() (checked; throws).
inline Reeb_trim_result trim_essential_stubs(const Reeb_graph& R, double max_height,
                                             const Reeb_trim_options& options = {}) {
  if (!(max_height >= 0))
    FeatureRecon::internal::throw_invalid_argument("trim_essential_stubs", "max_height must be >= 0, got ",
                                                   max_height);
  internal::check_reeb_graph(R, "trim_essential_stubs");
  auto interrupted = [&R] { return internal::input_unchanged<Reeb_trim_result>(R); };
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) return interrupted();
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
  // as stubs go: a fork left with two arcs is no fork (a Y keeps a branch)
  std::vector<std::size_t> degree(n);
  for (std::size_t i = 0; i < n; ++i) degree[i] = incident[i].size();
  std::vector<Reeb_graph::Node> nodes = R.nodes;
  for (std::size_t c = 0; c < n; ++c) {
    if ((c & 1023) == 0 && c > 0 &&
        !FeatureRecon::internal::report_progress(options.progress,
                                                 0.2 + 0.6 * static_cast<double>(c) / static_cast<double>(n)))
      return interrupted();
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
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_REPAIR_REEB_GRAPH_H
