// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H
#define FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/internal/Link_cut_tree.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// A point of a persistence diagram of a Reeb graph, with the nodes that create and destroy the feature.
struct Reeb_persistence_pair {
  double birth = 0;            ///< function value at which the feature appears
  double death = 0;            ///< function value at which it disappears
  std::size_t birth_node = 0;  ///< index into Reeb_graph::nodes
  std::size_t death_node = 0;  ///< index into Reeb_graph::nodes
  double persistence() const { return birth < death ? death - birth : birth - death; }  ///< |death - birth|
};

/// The features of a Reeb graph and their persistence (dissertation Ch. 5.1).
/// \note The diagrams correspond to the extended persistence of the lower-star filtration of f on the
/// complex: `sublevel_branches` = Ord0, `superlevel_branches` = Rel1, `essential` = Ext+0, `loops` = Ext-1.
struct Reeb_graph_persistence {
  /// 0-dim sublevel persistence: a minimum (birth) paired with the down-fork where its component merges into
  /// an older one (death); birth <= death (equal when f ties: a pair on the diagonal).
  std::vector<Reeb_persistence_pair> sublevel_branches;
  /// 0-dim superlevel persistence: a maximum (birth) paired with the up-fork where its component merges into
  /// one with a higher maximum (death); birth >= death (equal on ties).
  std::vector<Reeb_persistence_pair> superlevel_branches;
  /// 1-dim extended persistence: an essential down-fork (birth) paired with the essential up-fork at the
  /// bottom of the thinnest loop born there (death); birth >= death (equal on ties), persistence = height of
  /// that loop.
  std::vector<Reeb_persistence_pair> loops;
  /// One pair per connected component: its global minimum and maximum (birth <= death).
  std::vector<Reeb_persistence_pair> essential;
  /// success, or interrupted when the progress callback returned false (every diagram is then empty).
  Status status = Status::success;
};

namespace internal {
/// compute_reeb_graph_persistence(), optionally also giving for each loop (in the order of `loops`) the arcs
/// of its thin cycle (none after a stop); errors name `fn`; `progress` as Reeb_persistence_options::progress.
inline Reeb_graph_persistence reeb_graph_persistence(
    const Reeb_graph& R, std::vector<std::vector<std::size_t>>* loop_cycles,
    double cycle_limit = std::numeric_limits<double>::infinity(),
    const char* fn = "compute_reeb_graph_persistence", const Progress_callback& progress = {}) {
  const std::size_t n = R.nodes.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(R.nodes[i].value))
      FeatureRecon::internal::throw_invalid_argument(fn, "node ", i, " has value ", R.nodes[i].value);
  for (std::size_t i = 1; i < n; ++i) {
    const auto& a = R.nodes[i - 1];
    const auto& b = R.nodes[i];
    if (!(a.value < b.value || (a.value == b.value && a.vertex < b.vertex)))
      FeatureRecon::internal::throw_invalid_argument(fn, "nodes ", i - 1, " and ", i,
                                                     " are not in increasing (value, vertex) order");
  }
  for (std::size_t k = 0; k < R.arcs.size(); ++k)
    if (!(R.arcs[k].lower < R.arcs[k].upper && R.arcs[k].upper < n))
      FeatureRecon::internal::throw_invalid_argument(fn, "arc ", k, " does not go up between valid nodes");

  // Adjacency: for each node, (other end, arc) of its arcs below and above (multi-arcs repeated).
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> below(n), above(n);
  for (std::size_t k = 0; k < R.arcs.size(); ++k) {
    below[R.arcs[k].upper].push_back({R.arcs[k].lower, k});
    above[R.arcs[k].lower].push_back({R.arcs[k].upper, k});
  }
  for (std::size_t v = 0; v < n; ++v) {
    std::sort(below[v].begin(), below[v].end());
    std::sort(above[v].begin(), above[v].end());
  }
  Reeb_graph_persistence P;
  // A stop leaves empty diagrams (and no cycles); asked every 1024 nodes of each sweep.
  auto stopped = [&](double fraction) {
    if (FeatureRecon::internal::report_progress(progress, fraction)) return false;
    P = Reeb_graph_persistence{};
    P.status = Status::interrupted;
    if (loop_cycles != nullptr) loop_cycles->clear();
    return true;
  };
  auto stopped_in_sweep = [&](std::size_t done, double from, double to) {
    return (done & 1023) == 0 && done > 0 &&
           stopped(from + (to - from) * static_cast<double>(done) / static_cast<double>(n));
  };
  if (stopped(0.1)) return P;
  auto pair_of = [&](std::size_t b, std::size_t d) {
    return Reeb_persistence_pair{R.nodes[b].value, R.nodes[d].value, b, d};
  };

  // Union-find whose root remembers the extreme node of its component.
  std::vector<std::size_t> parent(n), extreme(n);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };

  // Sweep up: minima paired with down-forks; essential down-forks give loops.
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::iota(extreme.begin(), extreme.end(), std::size_t(0));  // lowest node of the component
  struct Loop_birth {
    std::size_t fork, branch, arc;
    // the fork's earlier arcs: below[fork][0, earlier) (not copied: a fork of degree k would store O(k^2))
    std::size_t earlier;
  };
  std::vector<Loop_birth> loop_births;
  for (std::size_t v = 0; v < n; ++v) {
    if (stopped_in_sweep(v, 0.1, 0.3)) return P;
    std::size_t earlier = 0;
    for (const auto& [u, arc] : below[v]) {
      const std::size_t ru = find(u), rv = find(v);
      if (ru == rv) {
        loop_births.push_back({v, u, arc, earlier});
      } else if (earlier != 0) {
        // v already belongs to a component from below: the younger minimum dies here.
        const bool u_younger = extreme[ru] > extreme[rv];
        P.sublevel_branches.push_back(pair_of(u_younger ? extreme[ru] : extreme[rv], v));
        parent[u_younger ? ru : rv] = u_younger ? rv : ru;
      } else {
        parent[rv] = ru;  // v joins its first component below
      }
      ++earlier;
    }
  }
  // Essential pairs: per component, global minimum (the root's extreme) with its highest node.
  {
    std::vector<std::size_t> top(n, std::numeric_limits<std::size_t>::max());
    for (std::size_t v = 0; v < n; ++v) top[find(v)] = v;  // increasing v: the last one is the highest
    for (std::size_t v = 0; v < n; ++v)
      if (find(v) == v) P.essential.push_back(pair_of(extreme[v], top[v]));
  }

  // Sweep down: maxima paired with up-forks.
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::iota(extreme.begin(), extreme.end(), std::size_t(0));  // highest node of the component
  for (std::size_t k = n; k-- > 0;) {
    if (stopped_in_sweep(n - 1 - k, 0.3, 0.5)) return P;
    const std::size_t v = k;
    bool joined = false;
    for (auto it = above[v].rbegin(); it != above[v].rend(); ++it) {
      const std::size_t u = it->first;
      const std::size_t ru = find(u), rv = find(v);
      if (ru == rv) continue;  // an essential up-fork: paired from the loop side
      if (joined) {
        const bool u_younger = extreme[ru] < extreme[rv];
        P.superlevel_branches.push_back(pair_of(u_younger ? extreme[ru] : extreme[rv], v));
        parent[u_younger ? ru : rv] = u_younger ? rv : ru;
      } else {
        parent[rv] = ru;
        joined = true;
      }
    }
  }

  // Loops: the cycle born at fork s through its arc from `branch` has its best bottom at the maximin value
  // over paths from `branch` to s in the graph of the nodes below s and the fork's earlier arcs, the
  // bottleneck of a path being its lowest node: the lowest node on the path in a maximum spanning forest of
  // that graph, where an arc weighs its lower end. The forest is kept in a link-cut tree over the sweep (an
  // arc is a node of its own, keyed by its weight; graph nodes never are the minimum): an arc that closes a
  // cycle replaces the lightest arc on it when it is heavier. O((n + m) log n) in all; the thin cycle (the
  // arc and the forest path) costs its length, and only loops of persistence <= cycle_limit get one. Arcs
  // with the same lower end weigh more the later the sweep meets them (the key is the rank in (lower, upper,
  // index) order; the bottom is still the lowest lower end on the path, as for any maximum spanning forest).
  // Without that tie rule the arcs up from one node kept the oldest one in the forest, and the cycle of each
  // new loop ran back through all the older ones: a node joined to every node of a flat path gave cycles of
  // 2, 3, ..., n arcs (quadratic merging strips in simplify_by_persistence()); now each is a triangle.
  {
    Link_cut_tree forest(n + R.arcs.size());
    const auto arc_node = [n](std::size_t k) { return static_cast<std::int32_t>(n + k); };
    {
      std::vector<std::size_t> by_weight(R.arcs.size());
      std::iota(by_weight.begin(), by_weight.end(), std::size_t(0));
      std::sort(by_weight.begin(), by_weight.end(), [&R](std::size_t a, std::size_t b) {
        const auto& x = R.arcs[a];
        const auto& y = R.arcs[b];
        return x.lower != y.lower ? x.lower < y.lower : x.upper != y.upper ? x.upper < y.upper : a < b;
      });
      for (std::size_t r = 0; r < by_weight.size(); ++r)
        forest.set_key(arc_node(by_weight[r]), static_cast<Link_cut_tree::Key>(r));
    }
    std::vector<std::int32_t> on_path;
    std::size_t next_birth = 0;
    for (std::size_t v = 0; v < n; ++v) {
      if (stopped_in_sweep(v, 0.5, 1.0)) return P;
      for (const auto& [u, arc] : below[v]) {
        const std::int32_t e = arc_node(arc), x = static_cast<std::int32_t>(u),
                           y = static_cast<std::int32_t>(v);
        if (!forest.connected(x, y)) {
          forest.link(x, e);
          forest.link(e, y);
          continue;
        }
        // The loops are born in the order of the sweep above: same fork, same arcs.
        FEATURERECON_assertion(next_birth < loop_births.size() && loop_births[next_birth].fork == v &&
                               loop_births[next_birth].arc == arc);
        ++next_birth;
        const std::int32_t lightest = forest.path_min(x, y);
        const std::size_t bottom = R.arcs[static_cast<std::size_t>(lightest) - n].lower;
        P.loops.push_back(pair_of(v, bottom));
        if (loop_cycles != nullptr) {
          std::vector<std::size_t> cycle;
          if (P.loops.back().persistence() <= cycle_limit) {
            cycle.push_back(arc);
            forest.for_each_on_path(x, y, [&](std::int32_t z) {
              if (static_cast<std::size_t>(z) >= n) cycle.push_back(static_cast<std::size_t>(z) - n);
            });
          }
          loop_cycles->push_back(std::move(cycle));
        }
        if (forest.key(lightest) <
            forest.key(e)) {  // the new arc is heavier: it takes the lightest one's place
          // (on equal lower ends always: it is the latest arc)
          const std::size_t k = static_cast<std::size_t>(lightest) - n;
          forest.cut(static_cast<std::int32_t>(R.arcs[k].lower), lightest);
          forest.cut(lightest, static_cast<std::int32_t>(R.arcs[k].upper));
          forest.link(x, e);
          forest.link(e, y);
        }
      }
    }
    FEATURERECON_assertion(next_birth == loop_births.size());
  }
  (void)FeatureRecon::internal::report_progress(progress, 1.0);
  return P;
}
}  // namespace internal

/// Persistence of the branch and loop features of a Reeb graph, computed on the graph itself.
///
/// Method: branches by two union-find sweeps (up for minima, down for maxima; elder rule), O(n log n) with
/// n nodes and arcs. A loop is born at a down-fork whose lower arcs are already connected below it; it is
/// paired with the highest up-fork s' such that the two branches are connected in the part of the graph
/// between f(s') and the fork: the lowest node on the path between them in a maximum spanning forest of the
/// sublevel graph (an arc weighs its lower node; among arcs with the same lower node the later in the sweep
/// weighs more), kept in a link-cut tree over the sweep. O(n log n) for all loops together. Nodes with
/// several arcs below or above (degenerate forks) act as chains of binary forks, as in a simulation of
/// simplicity; node order is the graph's (f, vertex index) order.
/// \pre R's node values are finite and in increasing (value, vertex) order, as reeb_graph() returns them
///   (checked; throws).
/// \param options progress callback (return false to stop: Status::interrupted, empty diagrams).
inline Reeb_graph_persistence compute_reeb_graph_persistence(const Reeb_graph& R,
                                                             const Reeb_persistence_options& options = {}) {
  return internal::reeb_graph_persistence(R, nullptr, std::numeric_limits<double>::infinity(),
                                          "compute_reeb_graph_persistence", options.progress);
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H
