// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SIMPLIFY_BY_PERSISTENCE_H
#define FEATURERECON_SKELETON_SIMPLIFY_BY_PERSISTENCE_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Compressed_lists.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/reeb_graph_persistence.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Result of simplify_by_persistence().
struct Reeb_simplification_result {
  /// The simplified Reeb graph. Every vertex of the input graph is in exactly one place: a node's `vertex`, a
  /// node's `members`, or an arc's `vertices` (indices of `values` that the input graph does not use stay
  /// out).
  Reeb_graph graph;
  std::size_t removed_branches = 0;  ///< branch features of persistence <= delta that were merged away
  std::size_t removed_loops = 0;     ///< loop features of persistence <= delta that were merged away
  /// Triangles of the glued complex whose Reeb graph is the result (the strips that glue each merging path to
  /// its spine): the measure of the work beyond the graph's size; a statistic, as tests read it.
  std::size_t glued_triangles = 0;
  /// success, or interrupted when the progress callback returned false (the graph is then empty).
  Status status = Status::success;
};

namespace internal {
/// \cond
struct Simplification_complex {
  std::vector<double> values;  // originals first, then helper vertices
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
};
/// \endcond
}  // namespace internal

/// Removes every branch and loop feature of persistence at most `delta` from a Reeb graph, by the
/// merges of dissertation Ch. 5.3.1: a branch's monotone path is glued by function value onto a path into
/// its sibling component; the two sides of a thin loop are glued into one monotone arc. All merges are
/// applied together (the transitive closure of the identifications), so features of persistence above 2 delta
/// survive and the diagrams move by at most 2 delta (branches) and 6 delta (loops).
///
/// Method: the quotient is computed as a Reeb graph. Each merging path gets a spine, a path with one vertex
/// per function value on it, and every edge of the merging path a strip of triangles to the spine segment of
/// its values (a fan over the O(log L) segments of a segment tree over the spine's L levels, each glued to
/// the spine below it); the level set of the resulting 2-complex at any height joins all points of the
/// merging path at that height, so its Reeb graph, with arcs of zero height contracted, is the quotient.
/// A branch (extreme e, fork s) is glued onto a path from s into the sibling component that holds the elder
/// extreme, up to e's level: the fewest arcs to a node beyond e's level that lies, beyond that level, in the
/// elder's part (else to the nearest node beyond it). The search stays between the two levels, and one
/// union-find sweep finds every fork's sibling, so a long stem with n short spurs, or one fork with n, costs
/// O(n log n), not O(n^2). When the search meets, strictly nearer than such a node and coming from the fork's
/// near side, the fork of another merged branch with the same elder whose path it could have taken, the path
/// goes on as that branch's path (resolved first: forks from the far end on), held in the merging set by one
/// summary edge. On a tree the result is that of the path through that fork; a flat stem with n tall teeth
/// costs O(n), not n strips of O(n) levels. A loop's merging path is its thin cycle: the arc that closes it
/// and the path in a maximum spanning forest below it (reeb_graph_persistence.h; among arcs from one node the
/// latest weighs most, so that the cycles of a node joined to every node of a flat path stay triangles). This
/// overload takes a Reeb graph and the function value of every input vertex; the graph may also contain
/// regular nodes (e.g. after repair_reeb_graph()), which the result absorbs into arcs.
/// Members of a node with another value than the node's (trim_essential_stubs() puts a trimmed stub's
/// vertices there) are not level with it: they take no part in the merges and stay with the node of their
/// node's vertex (when that vertex ends up inside an arc: with the arc's lower or upper node, on their side
/// of the vertex). Indices of `values` the graph does not use stay out of the result, whatever their value.
/// \pre delta >= 0 and finite; every vertex of R (nodes, members, arc vertices) indexes `values` and is used
/// once; the values R uses are finite and each node's value is `values[vertex]`; the nodes are in increasing
/// (value, vertex) order, as every function returning a Reeb_graph leaves them (all checked; throws naming
/// the node or arc). A stop through Simplification_options::progress leaves status interrupted and an empty
/// graph.
inline Reeb_simplification_result simplify_by_persistence(const Reeb_graph& R,
                                                          const std::vector<double>& values, double delta,
                                                          const Simplification_options& options = {}) {
  const char* fn = "simplify_by_persistence";
  const Progress_callback& progress = options.progress;
  using FeatureRecon::internal::Compressed_lists;
  using FeatureRecon::internal::release;
  using FeatureRecon::internal::throw_invalid_argument;
  if (!(delta >= 0 && std::isfinite(delta)))
    throw_invalid_argument(fn, "delta must be finite and >= 0, got ", delta);
  // Which vertices the graph uses, each once: 1 = in the complex, 2 = a member off its node's level.
  std::vector<char> used(values.size(), 0);
  auto use = [&](Vertex_index v, const char* what, std::size_t index, char how) {
    if (v >= values.size())
      throw_invalid_argument(fn, what, " ", index, " has vertex ", v, " out of range [0, ", values.size(),
                             "): values has ", values.size(), " entries, one per vertex");
    if (!std::isfinite(values[v]))
      throw_invalid_argument(fn, "the value of vertex ", v, " (", what, " ", index, ") is ", values[v]);
    if (used[v])
      throw_invalid_argument(fn, "vertex ", v, " appears twice in the graph (", what, " ", index, ")");
    used[v] = how;
  };
  for (std::size_t i = 0; i < R.nodes.size(); ++i) {
    const auto& node = R.nodes[i];
    use(node.vertex, "node", i, 1);
    if (!(values[node.vertex] == node.value))
      throw_invalid_argument(fn, "node ", i, " has value ", node.value, " but its vertex ", node.vertex,
                             " has ", values[node.vertex]);
  }
  for (std::size_t i = 0; i < R.nodes.size(); ++i)
    for (const Vertex_index v : R.nodes[i].members) {
      use(v, "node", i, 1);
      if (values[v] != R.nodes[i].value) used[v] = 2;
    }
  for (std::size_t k = 0; k < R.arcs.size(); ++k) {
    if (!(R.arcs[k].lower < R.nodes.size() && R.arcs[k].upper < R.nodes.size()))
      throw_invalid_argument(fn, "arc ", k, " joins nodes out of range [0, ", R.nodes.size(), ")");
    for (const Vertex_index v : R.arcs[k].vertices) use(v, "arc", k, 1);
  }
  Reeb_simplification_result result;
  auto interrupted = [&result] {  // what a stop leaves: no graph
    result = Reeb_simplification_result{};
    result.status = Status::interrupted;
    return true;
  };
  auto stopped = [&](double t) {
    return !FeatureRecon::internal::report_progress(progress, t) && interrupted();
  };
  if (stopped(0.0)) return result;
  std::vector<std::vector<std::size_t>> cycles;
  // The persistence reports up to 0.1; a refusal of any of its reports stops (its last one included).
  bool refused = false;
  Progress_callback persistence_progress;
  if (progress)
    persistence_progress = [&progress, &refused](double t) {
      return !(refused = refused || !progress(0.1 * t));
    };
  const Reeb_graph_persistence P =
      internal::reeb_graph_persistence(R, &cycles, delta, fn, persistence_progress);
  if (refused && interrupted()) return result;
  const std::size_t n = values.size();
  internal::Simplification_complex Y;
  Y.values = values;
  std::vector<double>& val = Y.values;
  for (std::size_t v = 0; v < n;
       ++v)  // indices the graph does not use stay out, whatever their value (NaN too)
    if (used[v] == 0) val[v] = 0;
  auto less = [&](std::size_t a, std::size_t b) { return val[a] < val[b] || (val[a] == val[b] && a < b); };

  // The graph of R as a 1-complex on the input vertices: each arc a chain through its vertices. Parallel arcs
  // without interior vertices get a helper midpoint (but the first). Only such arcs can repeat an edge: every
  // other edge has an interior vertex of its arc, used once. Chain k is chain_items[chain_start[k],
  // chain_start[k + 1]), from the lower node's vertex to the upper's.
  std::vector<std::size_t> chain_start{0};
  std::vector<Vertex_index> chain_items;
  std::set<Edge> present;  // the edges of arcs without interior vertices
  auto key = [](Vertex_index a, Vertex_index b) { return a < b ? Edge{a, b} : Edge{b, a}; };
  for (std::size_t k = 0; k < R.arcs.size(); ++k) {
    const Vertex_index a = R.nodes[R.arcs[k].lower].vertex, b = R.nodes[R.arcs[k].upper].vertex;
    chain_items.push_back(a);
    if (R.arcs[k].vertices.empty() && !present.insert(key(a, b)).second) {
      chain_items.push_back(static_cast<Vertex_index>(val.size()));
      // Halves first: no overflow near the largest doubles; clamped, as halves of subnormals round.
      val.push_back(
          std::clamp(0.5 * val[a] + 0.5 * val[b], std::min(val[a], val[b]), std::max(val[a], val[b])));
    }
    chain_items.insert(chain_items.end(), R.arcs[k].vertices.begin(), R.arcs[k].vertices.end());
    chain_items.push_back(b);
    chain_start.push_back(chain_items.size());
    for (std::size_t i = chain_start[k]; i + 1 < chain_items.size(); ++i)
      Y.edges.push_back(key(chain_items[i], chain_items[i + 1]));
  }
  release(present);

  // Members of a node (input vertices identified with it) stay with it: a horizontal edge to the node's
  // vertex. Members off the node's level are attached after the quotient (an edge would not be level).
  for (const auto& node : R.nodes)
    for (const Vertex_index v : node.members)
      if (used[v] == 1) Y.edges.push_back(key(node.vertex, v));

  // Node adjacency of R with arcs.
  const std::size_t nn = R.nodes.size();
  Compressed_lists<std::pair<std::size_t, std::size_t>> adj;  // (other node, arc)
  adj.build(nn, [&](auto emit) {
    for (std::size_t k = 0; k < R.arcs.size(); ++k) {
      emit(R.arcs[k].lower, {R.arcs[k].upper, k});
      emit(R.arcs[k].upper, {R.arcs[k].lower, k});
    }
  });
  // Breadth-first search from `start` inside the nodes accepted by `inside`, not going on from the nodes
  // accepted by `stop` (the search ends at the first one, returned last); records the predecessor arcs in
  // `pred_arc` (valid for the nodes reached). Stamped arrays: a search costs the nodes it reaches, not nn.
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> seen_stamp(nn, 0);
  std::size_t stamp = 0;
  // The start of a search (both below): a new stamp, `start` reached with no predecessor; the order of
  // reaching.
  auto start_search = [&](std::size_t start, std::vector<std::size_t>& pred_arc) {
    if (pred_arc.size() != nn) pred_arc.assign(nn, none);
    ++stamp;
    seen_stamp[start] = stamp;
    pred_arc[start] = none;
    return std::vector<std::size_t>{start};
  };
  // Reaches node y over `arc` if it is new to this search and accepted by `inside`; says whether it did.
  auto reach = [&](std::size_t y, std::size_t arc, auto inside, std::vector<std::size_t>& pred_arc,
                   std::vector<std::size_t>& order) {
    if (seen_stamp[y] == stamp || !inside(y)) return false;
    seen_stamp[y] = stamp;
    pred_arc[y] = arc;
    order.push_back(y);
    return true;
  };
  auto bfs = [&](std::size_t start, auto inside, auto stop, std::vector<std::size_t>& pred_arc) {
    std::vector<std::size_t> order = start_search(start, pred_arc);
    if (stop(start)) return order;
    for (std::size_t i = 0; i < order.size(); ++i)
      for (const auto& [y, arc] : adj[order[i]])
        if (reach(y, arc, inside, pred_arc, order) && stop(y)) return order;
    return order;  // the nodes reached
  };
  // The search of pi1 (below): as bfs() with stop `target`, but a node accepted by `fork` ends it when it is
  // strictly nearer (in arcs) than every node accepted by `target`. Returns the node it ended at, or none.
  auto search = [&](std::size_t start, auto inside, auto target, auto fork,
                    std::vector<std::size_t>& pred_arc) {
    std::vector<std::size_t> order = start_search(start, pred_arc);
    if (target(start)) return start;
    std::size_t found = fork(start) ? start : none;
    for (std::size_t i = 0, layer_end = 0; i < order.size(); ++i) {
      if (i == layer_end) {  // every node as near as order[i] is found: the rest are farther than `found`
        if (found != none) return found;
        layer_end = order.size();
      }
      for (const auto& [y, arc] : adj[order[i]])
        if (reach(y, arc, inside, pred_arc, order)) {
          if (target(y)) return y;
          if (found == none && fork(y)) found = y;
        }
    }
    return found;
  };
  auto other_end = [&](std::size_t arc, std::size_t node) {
    return R.arcs[arc].lower == node ? R.arcs[arc].upper : R.arcs[arc].lower;
  };
  // Where a walk stopped: at vertex `index` of the chain of `arc` walked from node `from`; arc none: it did
  // not stop, and ended at node `from`.
  struct Walk_end {
    std::size_t arc, from, index;
  };
  // Appends to `edges` the input-vertex edges of a node path given as a sequence of arcs walked from `from`,
  // starting at vertex `first_index` of the first arc's chain, stopping after the first vertex v with
  // stop(v).
  auto walk = [&](std::size_t from, const std::vector<std::size_t>& arcs, std::size_t first_index, auto stop,
                  std::vector<Edge>& edges) {
    std::size_t node = from;
    for (const std::size_t arc : arcs) {
      const std::size_t first = chain_start[arc], length = chain_start[arc + 1] - first;
      const bool forward = R.arcs[arc].lower == node;
      auto at = [&](std::size_t i) { return chain_items[first + (forward ? i : length - 1 - i)]; };
      for (std::size_t i = first_index; i + 1 < length; ++i) {
        edges.push_back(key(at(i), at(i + 1)));
        if (stop(at(i + 1))) return Walk_end{arc, node, i + 1};
      }
      first_index = 0;
      node = other_end(arc, node);
    }
    return Walk_end{none, node, 0};
  };
  auto walk_end_vertex = [&](const Walk_end& w) {
    const std::size_t first = chain_start[w.arc], length = chain_start[w.arc + 1] - first;
    return chain_items[first + (R.arcs[w.arc].lower == w.from ? w.index : length - 1 - w.index)];
  };
  auto path_arcs = [&](std::size_t target,
                       const std::vector<std::size_t>& pred_arc) {  // pred_arc[start] == none
    std::vector<std::size_t> arcs;                                  // from the BFS start to target
    for (std::size_t x = target; pred_arc[x] != none; x = other_end(pred_arc[x], x))
      arcs.push_back(pred_arc[x]);
    std::reverse(arcs.begin(), arcs.end());
    return arcs;
  };

  // Merging set j: merging_edges[merging_start[j], merging_start[j + 1]).
  std::vector<Edge> merging_edges;
  std::vector<std::size_t> merging_start{0};
  // Branches: (extreme node e, fork s); `down` for minima (paths go below the fork). At the fork, the arc
  // alpha goes into C2, the component of e beyond the fork, and beta into the sibling component that reaches
  // farthest (its extreme is the elder; the first such arc of the fork). Both are found for all pairs by one
  // union-find sweep from the far end towards the forks, asked at each fork before it joins its components:
  // O(n log n) in all, where a search of each sibling component would cost O(n) per branch (a long stem with
  // many spurs). The union-find keeps its history (union by size, no path compression, each link stamped with
  // the step of the sweep that made it), so that the path into the sibling can later ask which nodes beyond e
  // were joined with the elder when the sweep reached e.
  struct Branch_choice {
    std::size_t alpha, beta, elder;
  };
  struct Sweep {
    std::vector<std::size_t> parent, size, linked_at, extreme,
        step;  // step: when the sweep reached each node
    std::size_t find(std::size_t x, std::size_t t = std::numeric_limits<std::size_t>::max()) const {
      while (parent[x] != x && linked_at[x] <= t) x = parent[x];
      return x;
    }
  };
  auto sweep = [&](const std::vector<Reeb_persistence_pair>& pairs, bool down,
                   std::vector<Branch_choice>& choice) {
    choice.assign(pairs.size(), Branch_choice{none, none, none});
    Compressed_lists<std::size_t> at_fork;  // the pairs to simplify, by fork
    at_fork.build(nn, [&](auto emit) {
      for (std::size_t i = 0; i < pairs.size(); ++i)
        if (pairs[i].persistence() <= delta) emit(pairs[i].death_node, i);
    });
    Sweep W;
    W.parent.resize(nn);
    std::iota(W.parent.begin(), W.parent.end(), std::size_t(0));
    W.extreme = W.parent;
    W.size.assign(nn, 1);
    W.linked_at.assign(nn, none);
    W.step.assign(nn, none);
    auto farther = [&](std::size_t x, std::size_t y) { return down ? x < y : x > y; };
    // The components beyond a fork, each with its first arc (in adjacency order): once per fork, so that a
    // fork with k short branches costs O(k log k), not k times its degree.
    struct Part {
      std::size_t root, first_arc;
    };
    std::vector<Part> parts;
    for (std::size_t k = 0; k < nn; ++k) {
      const std::size_t s = down ? k : nn - 1 - k;
      W.step[s] = k;
      if (!at_fork[s].empty()) {
        parts.clear();
        for (const auto& [y, arc] : adj[s])
          if (farther(y, s)) parts.push_back({W.find(y), arc});
        std::stable_sort(parts.begin(), parts.end(),
                         [](const Part& a, const Part& b) { return a.root < b.root; });
        parts.erase(std::unique(parts.begin(), parts.end(),
                                [](const Part& a, const Part& b) { return a.root == b.root; }),
                    parts.end());  // the first arc of each component stays
        // The two components that reach farthest (extremes of distinct components differ); ties cannot occur.
        std::size_t best = none, second = none;
        for (std::size_t j = 0; j < parts.size(); ++j) {
          if (best == none || farther(W.extreme[parts[j].root], W.extreme[parts[best].root])) {
            second = best;
            best = j;
          } else if (second == none || farther(W.extreme[parts[j].root], W.extreme[parts[second].root])) {
            second = j;
          }
        }
        for (const std::size_t i : at_fork[s]) {
          const std::size_t ce = W.find(pairs[i].birth_node);
          Branch_choice& c = choice[i];
          const auto own = std::lower_bound(parts.begin(), parts.end(), ce,
                                            [](const Part& a, std::size_t r) { return a.root < r; });
          if (own != parts.end() && own->root == ce) c.alpha = own->first_arc;
          const std::size_t sibling = best != none && parts[best].root != ce ? best : second;
          if (sibling != none && parts[sibling].root != ce) {
            c.elder = W.extreme[parts[sibling].root];
            c.beta = parts[sibling].first_arc;
          }
        }
      }
      for (const auto& [y, arc] : adj[s]) {  // s joins the components beyond it
        if (!farther(y, s)) continue;
        std::size_t a = W.find(y), b = W.find(s);
        if (a == b) continue;
        if (W.size[a] > W.size[b]) std::swap(a, b);
        W.parent[a] = b;
        W.linked_at[a] = k;
        W.size[b] += W.size[a];
        if (farther(W.extreme[a], W.extreme[b])) W.extreme[b] = W.extreme[a];
      }
    }
    return W;
  };
  std::vector<std::size_t> pred;  // reused: allocated once
  // A branch's pi1: where it stopped (its last vertex, at or beyond e's level, and the arc it is on), the
  // farthest node it passed before that arc's end (none: only the fork), whether every search on it reached
  // the elder's part (no fallback), and the helper vertices of its summary edge once made.
  const Vertex_index no_vertex = std::numeric_limits<Vertex_index>::max();
  struct Route {
    Vertex_index top, low, high;
    Walk_end end;
    std::size_t peak;
    bool to_elder;
  };
  std::vector<std::size_t> used_stamp(nn, 0);  // forks a route went on from (stamped per route)
  std::size_t route_stamp = 0;
  auto merge_branches = [&](const std::vector<Reeb_persistence_pair>& pairs, bool down) {
    std::vector<Branch_choice> choice;
    const Sweep W = sweep(pairs, down, choice);
    auto farther = [&](std::size_t x, std::size_t y) { return down ? x < y : x > y; };
    // Merged pairs, their forks from the far end towards the near one: a branch's pi1 can then go on as the
    // pi1 of a branch merged at a fork it meets (all farther than its own fork).
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (pairs[i].persistence() <= delta && choice[i].alpha != none && choice[i].beta != none)
        order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return farther(pairs[a].death_node, pairs[b].death_node);
    });
    // At each fork the merged branch that reaches farthest: the branches merged at one fork share sibling and
    // elder, so its pi1 covers the others'.
    std::vector<std::size_t> reaching(nn, none);
    for (const std::size_t i : order) {
      std::size_t& r = reaching[pairs[i].death_node];
      if (r == none || farther(pairs[i].birth_node, pairs[r].birth_node)) r = i;
    }
    // Forks where a kept loop ends (its bottom for maxima, its top for minima): two arcs there lead on into
    // the elder's part, round the loop, and the route of another branch from there need not be this branch's.
    std::vector<char> kept_loop_end(nn, 0);
    for (const auto& loop : P.loops)
      if (loop.persistence() > delta) kept_loop_end[down ? loop.birth_node : loop.death_node] = 1;
    std::vector<std::vector<Edge>> sets(pairs.size());
    std::vector<Route> routes(pairs.size(),
                              Route{no_vertex, no_vertex, no_vertex, Walk_end{none, none, 0}, none, true});
    auto farthest = [&](std::size_t x, std::size_t y) {
      return x == none || (y != none && farther(y, x)) ? y : x;
    };
    // The summary edge of branch r's merge: an edge of two helper vertices from the level of r's fork to that
    // of its route's top, in r's merging set. It adds nothing to the quotient (r's set has a point at each of
    // these levels, all one class there, and its classes form a monotone path), but stands in for r's whole
    // merging path in the sets of the branches that go on through r's fork.
    auto summary = [&](std::size_t r) {
      Route& q = routes[r];
      if (q.high == no_vertex) {
        q.low = static_cast<Vertex_index>(val.size());
        val.push_back(val[R.nodes[pairs[r].death_node].vertex]);
        q.high = static_cast<Vertex_index>(val.size());
        val.push_back(val[q.top]);
        sets[r].push_back({q.low, q.high});
      }
      return Edge{q.low, q.high};
    };
    for (const std::size_t i : order) {
      const std::size_t e = pairs[i].birth_node, s = pairs[i].death_node;
      const Branch_choice& c = choice[i];
      auto side = [&](std::size_t y) { return farther(y, s); };
      auto beyond_e = [&](std::size_t y) { return farther(y, e); };
      const Vertex_index ev = R.nodes[e].vertex;
      auto reached_e = [&](Vertex_index v) { return down ? !less(ev, v) : !less(v, ev); };
      std::vector<Edge>& edges = sets[i];
      {
        // pi2: from the fork through alpha into C2, then to the extreme e (C2 lies between the two levels).
        std::vector<std::size_t> arcs{c.alpha};
        const std::size_t u = other_end(c.alpha, s);
        bfs(
            u, side, [&](std::size_t x) { return x == e; }, pred);
        const std::vector<std::size_t> rest = path_arcs(e, pred);
        arcs.insert(arcs.end(), rest.begin(), rest.end());
        walk(
            s, arcs, 0, [](Vertex_index) { return false; }, edges);
      }
      // pi1: from the fork through beta towards the elder, walked until the level of e is reached: a shortest
      // path (in arcs) between the two levels to the nearest node beyond e that is joined with the elder
      // beyond e (when the sweep reached e); if every such path first crosses into another part of the
      // sibling beyond e, the nearest node beyond e. Either search stays between the two levels. Or, when the
      // search meets, strictly nearer than such a node, the fork x of a merged branch r with the same elder
      // whose pi1 it could have taken (see joinable), coming to x from x's near side: pi1 goes on as r's pi1,
      // held in the set by r's summary edge, and on from where r's pi1 stopped if that is short of e's level.
      // On a tree that is the same path (the merges together glue the same points); with loops it may pass a
      // loop on its other side. But the set is short: a flat stem with n tall teeth gave each tooth a pi1
      // along the rest of the stem, n^2 / 2 merging edges with strips of O(n) levels.
      const std::size_t elder_root = W.find(c.elder, W.step[e]);
      auto with_elder = [&](std::size_t x) { return W.find(x, W.step[e]) == elder_root; };
      ++route_stamp;
      auto joinable = [&](std::size_t x, std::size_t prev) {
        const std::size_t r = reaching[x];
        if (r == none || beyond_e(x) || kept_loop_end[x] || choice[r].elder != c.elder) return none;
        if (used_stamp[x] == route_stamp || farther(prev, x)) return none;  // from beyond x: need not pass x
        const Route& q = routes[r];
        FEATURERECON_assertion(q.top != no_vertex);  // its fork is farther: resolved before
        // r's pi1 must be one this search could take: towards the elder, between e's level and the fork's up
        // to its last arc, which ends beyond e's level only in the elder's part.
        const std::size_t z = other_end(q.end.arc, q.end.from);
        if (!q.to_elder || (q.peak != none && beyond_e(q.peak)) || (beyond_e(z) && !with_elder(z)))
          return none;
        return r;
      };
      // The nodes a walk passed before the end of the arc it stopped on (all of them if it did not stop).
      auto passed = [&](std::size_t node, const std::vector<std::size_t>& path, const Walk_end& end) {
        std::size_t peak = none;
        for (const std::size_t arc : path) {
          if (arc == end.arc && node == end.from) break;
          node = other_end(arc, node);
          peak = farthest(peak, node);
        }
        return peak;
      };
      Route& route = routes[i];
      const std::size_t y = other_end(c.beta, s), pi1_begin = edges.size();
      std::size_t from = s, start = y, start_prev = s;
      std::vector<std::size_t> arcs{c.beta}, joined;
      for (;;) {
        auto prev = [&](std::size_t x) { return x == start ? start_prev : other_end(pred[x], x); };
        std::size_t target = search(
            start, [&](std::size_t x) { return side(x) && (!beyond_e(x) || with_elder(x)); }, beyond_e,
            [&](std::size_t x) { return joinable(x, prev(x)) != none; }, pred);
        const std::size_t r = target == none || beyond_e(target) ? none : joinable(target, prev(target));
        if (target == none) {
          // No way on to the elder's part: the nearest node beyond e, from the start (as if nothing had been
          // joined: on a tree the first search would have failed too).
          edges.resize(pi1_begin);
          joined.clear();
          route.peak = none;
          route.to_elder = false;
          from = s;
          arcs.assign(1, c.beta);
          target = bfs(y, side, beyond_e, pred).back();
          FEATURERECON_assertion(beyond_e(target));
        }
        const std::vector<std::size_t> rest = path_arcs(target, pred);
        arcs.insert(arcs.end(), rest.begin(), rest.end());
        Walk_end end = walk(from, arcs, 0, reached_e, edges);
        route.peak = farthest(route.peak, passed(from, arcs, end));
        if (end.arc == none) {  // at the fork x = target of r (a node beyond e's level stops the walk)
          FEATURERECON_assertion(r != none && end.from == target);
          used_stamp[target] = route_stamp;
          joined.push_back(r);
          const Route& q = routes[r];
          route.peak = farthest(route.peak, q.peak);
          if (reached_e(q.top)) {
            route.top = q.top;
            route.end = q.end;
            break;
          }
          end = walk(q.end.from, {q.end.arc}, q.end.index, reached_e, edges);
          if (end.arc == none) {  // on from the node at the end of r's last arc
            route.peak = farthest(route.peak, end.from);
            start_prev = q.end.from;
            from = start = end.from;
            arcs.clear();
            continue;
          }
        }
        route.top = walk_end_vertex(end);
        route.end = end;
        break;
      }
      for (const std::size_t r : joined) edges.push_back(summary(r));
    }
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      if (pairs[i].persistence() > delta || choice[i].alpha == none || choice[i].beta == none) continue;
      merging_edges.insert(merging_edges.end(), sets[i].begin(), sets[i].end());
      merging_start.push_back(merging_edges.size());
      ++result.removed_branches;
    }
  };
  for (const bool down : {true, false})
    merge_branches(down ? P.sublevel_branches : P.superlevel_branches, down);
  for (std::size_t i = 0; i < P.loops.size(); ++i) {
    if (P.loops[i].persistence() > delta) continue;
    for (const std::size_t arc : cycles[i])
      for (std::size_t j = chain_start[arc]; j + 1 < chain_start[arc + 1]; ++j)
        merging_edges.push_back(key(chain_items[j], chain_items[j + 1]));
    merging_start.push_back(merging_edges.size());
    ++result.removed_loops;
  }

  // What the glued complex does not need goes before it is built.
  release(chain_items);
  release(chain_start);
  release(adj);
  release(seen_stamp);
  release(pred);
  release(used_stamp);
  release(cycles);
  if (stopped(0.2)) return result;
  // Spines and strips.
  std::vector<double> levels;
  std::vector<char> tree_built;  // per segment-tree node of the current spine (root 1, children 2i, 2i + 1)
  // Progress by merging edges glued (0.2 to 0.3), asked once per 1,024 of them: a nearly flat noisy path of
  // 40,000 spends seconds here.
  const double merging_total = static_cast<double>(merging_start.back());
  std::size_t next_report = 1024;
  for (std::size_t j = 0; j + 1 < merging_start.size(); ++j) {
    if (merging_start[j] >= next_report) {
      next_report = merging_start[j] + 1024;
      if (stopped(0.2 + 0.1 * static_cast<double>(merging_start[j]) / merging_total)) return result;
    }
    const auto edges_begin = merging_edges.begin() + static_cast<std::ptrdiff_t>(merging_start[j]);
    auto edges_end = merging_edges.begin() + static_cast<std::ptrdiff_t>(merging_start[j + 1]);
    std::sort(edges_begin, edges_end);
    edges_end = std::unique(edges_begin, edges_end);
    levels.clear();
    for (auto e = edges_begin; e != edges_end; ++e) {
      levels.push_back(val[(*e)[0]]);
      levels.push_back(val[(*e)[1]]);
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    const Vertex_index first = static_cast<Vertex_index>(val.size());
    for (const double l : levels) val.push_back(l);
    for (std::size_t i = 0; i + 1 < levels.size(); ++i)
      Y.edges.push_back({static_cast<Vertex_index>(first + i), static_cast<Vertex_index>(first + i + 1)});
    auto spine = [&](double l) {
      return static_cast<Vertex_index>(first +
                                       (std::lower_bound(levels.begin(), levels.end(), l) - levels.begin()));
    };
    // A merging edge a-b (f(a) <= f(b)) is glued to the spine at every level between its ends: a fan of
    // triangles from a over the spine from a's level to b's, then (a, b, top). A fan over each spine edge
    // made O(L^2) triangles for L merging edges spanning L levels each (a path of 5,000 nearly flat noisy
    // values: 4.5 million triangles, 6.4 s). The fan now covers the levels with the O(log L) segments of a
    // segment tree over the spine, whose node [l, r] (r - l >= 2) is an edge l-r glued to its halves by the
    // triangle (l, m, r), built when first used. Every level set joins the same points as before: a's fan
    // meets each segment's edge, which reaches the spine through the triangles below it, so the Reeb graph
    // is the same.
    const std::size_t K = levels.size();
    tree_built.assign(K > 1 ? 4 * K : 0, 0);
    // Builds tree node `id` spanning [l, r] and the nodes below it (spine edges are the leaves). Plain
    // recursive lambdas (passed to themselves): a std::function allocates, and there is a merging set per
    // removed feature.
    auto build = [&](auto& self, std::size_t id, std::size_t l, std::size_t r) -> void {
      if (r - l < 2 || tree_built[id]) return;
      tree_built[id] = 1;
      const std::size_t m = (l + r) / 2;
      Y.triangles.push_back({static_cast<Vertex_index>(first + l), static_cast<Vertex_index>(first + m),
                             static_cast<Vertex_index>(first + r)});
      self(self, 2 * id, l, m);
      self(self, 2 * id + 1, m, r);
    };
    // Glues a to the canonical segments of [lo, hi] within node `id` spanning [l, r], lowest first.
    auto glue = [&](auto& self, Vertex_index a, std::size_t id, std::size_t l, std::size_t r, std::size_t lo,
                    std::size_t hi) -> void {
      if (lo == l && hi == r) {
        build(build, id, l, r);
        Y.triangles.push_back(
            {a, static_cast<Vertex_index>(first + l), static_cast<Vertex_index>(first + r)});
        return;
      }
      const std::size_t m = (l + r) / 2;
      if (hi <= m) {
        self(self, a, 2 * id, l, m, lo, hi);
      } else if (lo >= m) {
        self(self, a, 2 * id + 1, m, r, lo, hi);
      } else {
        self(self, a, 2 * id, l, m, lo, m);
        self(self, a, 2 * id + 1, m, r, m, hi);
      }
    };
    for (auto e = edges_begin; e != edges_end; ++e) {
      Vertex_index a = (*e)[0], b = (*e)[1];
      if (less(b, a)) std::swap(a, b);
      const Vertex_index lo = spine(val[a]), hi = spine(val[b]);
      if (lo < hi) glue(glue, a, 1, 0, K - 1, lo - first, hi - first);
      Y.triangles.push_back({a, b, hi});
    }
  }
  release(tree_built);

  release(merging_edges);
  release(merging_start);
  result.glued_triangles = Y.triangles.size();

  // The Reeb graph of the glued complex, with zero-height arcs contracted.
  Simplicial_complex_2 K = make_simplicial_complex_2(val.size(), std::move(Y.edges), std::move(Y.triangles));
  if (stopped(0.3)) return result;
  Reeb_graph_options glued_options;
  // sticky: the sweep's last report (all swept) does not stop it, but counts here
  bool asked_to_stop = false;
  if (progress)
    glued_options.progress = [&progress, &asked_to_stop](double t) {
      return !(asked_to_stop = asked_to_stop || !progress(0.3 + 0.6 * t));
    };
  const Augmented_reeb_graph AY = compute_augmented_reeb_graph(K, val, glued_options);
  release(K);
  if (((asked_to_stop || AY.status() == Status::interrupted) && interrupted()) || stopped(0.9)) return result;
  const std::size_t m = val.size();
  FeatureRecon::internal::Union_find<std::size_t> sets(m);
  for (const auto& a : AY.arcs())
    if (val[a.lower] == val[a.upper]) sets.unite(a.lower, a.upper);
  const auto find = [&sets](std::size_t x) { return sets.find(x); };
  // Classes, their representative (smallest input vertex, else smallest helper) and members.
  std::vector<std::size_t> rep(m, none);
  for (std::size_t v = 0; v < m; ++v) {
    const std::size_t r = find(v);
    if (rep[r] == none || v < rep[r]) rep[r] = v;  // inputs (< n) come first
  }
  std::vector<std::size_t> classes;
  for (std::size_t v = 0; v < m; ++v)
    if (find(v) == v) classes.push_back(v);
  std::sort(classes.begin(), classes.end(), [&](std::size_t a, std::size_t b) {
    return val[a] < val[b] || (val[a] == val[b] && rep[a] < rep[b]);
  });
  const std::size_t nc = classes.size();
  std::vector<Vertex_index> class_of(m);  // the index in `classes` of each vertex's class
  {
    std::vector<Vertex_index> class_index(m);
    for (std::size_t i = 0; i < nc; ++i) class_index[classes[i]] = static_cast<Vertex_index>(i);
    for (std::size_t v = 0; v < m; ++v) class_of[v] = class_index[find(v)];
  }
  sets.release();
  Compressed_lists<Vertex_index> up;  // the classes an arc of the glued graph reaches above, by class
  up.build(nc, [&](auto emit) {
    for (const auto& a : AY.arcs())
      if (val[a.lower] != val[a.upper]) emit(class_of[a.lower], class_of[a.upper]);
  });
  std::vector<std::size_t> down_degree(nc, 0);
  for (const Vertex_index c : up.items) ++down_degree[c];
  Compressed_lists<Vertex_index> inputs_of, off_level_of;
  inputs_of.build(nc, [&](auto emit) {
    for (std::size_t v = 0; v < n; ++v)
      if (used[v] == 1) emit(class_of[v], static_cast<Vertex_index>(v));
  });
  // Members off their node's level go where the node's vertex went: to its node, or, when that became
  // regular, to the lower or upper node of its arc by their value (an arc's vertices stay in increasing
  // order).
  off_level_of.build(nc, [&](auto emit) {
    for (const auto& node : R.nodes)
      for (const Vertex_index v : node.members)
        if (used[v] == 2) emit(class_of[node.vertex], v);
  });
  // Indices of `values` the graph does not use (and members placed above) are isolated, single classes: no
  // part of the result as such.
  auto unused_class = [&](std::size_t c) { return rep[classes[c]] < n && used[rep[classes[c]]] != 1; };
  Reeb_graph& G = result.graph;
  std::vector<std::size_t> node_of(nc, none);
  for (std::size_t c = 0; c < nc; ++c) {
    const unsigned t = node_type_from_degrees(down_degree[c], up[c].size());
    if (t == regular || unused_class(c)) continue;
    node_of[c] = G.nodes.size();
    Reeb_graph::Node node;
    node.vertex = static_cast<Vertex_index>(rep[classes[c]]);
    node.value = val[classes[c]];
    node.type = t;
    for (const Vertex_index v : inputs_of[c])
      if (v != node.vertex) node.members.push_back(v);
    node.members.insert(node.members.end(), off_level_of[c].begin(), off_level_of[c].end());
    FEATURERECON_assertion(node.vertex < n);
    G.nodes.push_back(std::move(node));
  }
  for (std::size_t c = 0; c < nc; ++c) {
    if (node_of[c] == none) continue;
    for (std::size_t next : up[c]) {
      Reeb_graph::Arc arc;
      arc.lower = node_of[c];
      std::vector<Vertex_index> below, above;  // off-level members of regular classes on the arc
      while (node_of[next] == none) {
        arc.vertices.insert(arc.vertices.end(), inputs_of[next].begin(), inputs_of[next].end());
        for (const Vertex_index v : off_level_of[next])
          (values[v] < val[classes[next]] ? below : above).push_back(v);
        next = up[next].front();
      }
      arc.upper = node_of[next];
      G.nodes[arc.lower].members.insert(G.nodes[arc.lower].members.end(), below.begin(), below.end());
      G.nodes[arc.upper].members.insert(G.nodes[arc.upper].members.end(), above.begin(), above.end());
      G.arcs.push_back(std::move(arc));
    }
  }
  G.components = internal::count_components(G);
  (void)FeatureRecon::internal::report_progress(progress, 1.0);
  return result;
}

/// simplify_by_persistence() of the Reeb graph of A.
/// \throws std::invalid_argument when A's computation was interrupted (its graph lacks the arcs still open
/// then).
inline Reeb_simplification_result simplify_by_persistence(const Augmented_reeb_graph& A, double delta,
                                                          const Simplification_options& options = {}) {
  if (A.status() == Status::interrupted)
    FeatureRecon::internal::throw_invalid_argument("simplify_by_persistence",
                                                   "the augmented Reeb graph A is "
                                                   "incomplete: its computation was interrupted");
  return simplify_by_persistence(A.reeb_graph(), A.values(), delta, options);
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SIMPLIFY_BY_PERSISTENCE_H
