// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H
#define FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>

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
/// \note The diagrams correspond to the extended persistence of the lower-star filtration of f on the complex:
/// `sublevel_branches` = Ord0, `superlevel_branches` = Rel1, `essential` = Ext+0, `loops` = Ext-1.
struct Reeb_graph_persistence {
  /// 0-dim sublevel persistence: a minimum (birth) paired with the down-fork where its component merges into
  /// an older one (death); birth <= death (equal when f ties: a pair on the diagonal).
  std::vector<Reeb_persistence_pair> sublevel_branches;
  /// 0-dim superlevel persistence: a maximum (birth) paired with the up-fork where its component merges into
  /// one with a higher maximum (death); birth >= death (equal on ties).
  std::vector<Reeb_persistence_pair> superlevel_branches;
  /// 1-dim extended persistence: an essential down-fork (birth) paired with the essential up-fork at the
  /// bottom of the thinnest loop born there (death); birth >= death (equal on ties), persistence = height of that
  /// loop.
  std::vector<Reeb_persistence_pair> loops;
  /// One pair per connected component: its global minimum and maximum (birth <= death).
  std::vector<Reeb_persistence_pair> essential;
};

namespace internal {
/// compute_reeb_graph_persistence(), optionally also giving for each loop (in the order of `loops`) the arcs of
/// its thin cycle.
inline Reeb_graph_persistence reeb_graph_persistence(const Reeb_graph& R,
                                                     std::vector<std::vector<std::size_t>>* loop_cycles) {
  const char* fn = "compute_reeb_graph_persistence";
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
    std::size_t earlier;  // the fork's earlier arcs: below[fork][0, earlier) (not copied: a fork of degree k
                          // would store O(k^2))
  };
  std::vector<Loop_birth> loop_births;
  for (std::size_t v = 0; v < n; ++v) {
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

  // Loops: for the cycle born at fork s through its arc from `branch`, the best bottom is the maximin value
  // over paths from `branch` to one of the fork's earlier lower ends, inside the nodes below s.
  std::vector<std::size_t> best(n, 0), seen_stamp(n, 0), target_stamp(n, 0), via_arc(n, 0), target_arc(n, 0);
  std::size_t stamp = 0, fork_stamp = 0, current_fork = n, marked = 0;
  for (const Loop_birth& lb : loop_births) {
    ++stamp;
    // The targets are the lower ends of the fork's earlier arcs. The loops of one fork come in the order of its
    // arcs, so each fork marks its arcs once, incrementally: O(k) for a fork of degree k, not O(k^2).
    if (lb.fork != current_fork) {
      current_fork = lb.fork;
      ++fork_stamp;
      marked = 0;
    }
    for (; marked < lb.earlier; ++marked) {
      const auto& [t, arc] = below[lb.fork][marked];
      target_stamp[t] = fork_stamp;
      target_arc[t] = arc;  // with parallel arcs, the latest earlier one (as before)
    }
    // Widest path: pop the node with the largest bottleneck (the lowest node index on its path).
    std::priority_queue<std::pair<std::size_t, std::size_t>> heap;  // (bottleneck, node)
    heap.push({lb.branch, lb.branch});
    best[lb.branch] = lb.branch;
    seen_stamp[lb.branch] = stamp;
    std::size_t bottom = std::numeric_limits<std::size_t>::max(), reached = 0;
    while (!heap.empty()) {
      const auto [b, x] = heap.top();
      heap.pop();
      if (b != best[x]) continue;
      if (target_stamp[x] == fork_stamp) {
        bottom = b;
        reached = x;
        break;
      }
      for (const auto* nbrs : {&below[x], &above[x]})
        for (const auto& [y, arc] : *nbrs) {
          if (y >= lb.fork) continue;  // only the sublevel set strictly below the fork
          const std::size_t by = std::min(b, y);
          if (seen_stamp[y] != stamp || by > best[y]) {
            seen_stamp[y] = stamp;
            best[y] = by;
            via_arc[y] = arc;
            heap.push({by, y});
          }
        }
    }
    FEATURERECON_assertion(bottom != std::numeric_limits<std::size_t>::max());
    P.loops.push_back(pair_of(lb.fork, bottom));
    if (loop_cycles != nullptr) {
      // The thin cycle: the fork's arc from `branch`, the widest path back to `branch`, the earlier arc.
      std::vector<std::size_t> cycle{lb.arc, target_arc[reached]};
      for (std::size_t x = reached; x != lb.branch;) {
        const std::size_t arc = via_arc[x];
        cycle.push_back(arc);
        x = R.arcs[arc].lower == x ? R.arcs[arc].upper : R.arcs[arc].lower;
      }
      loop_cycles->push_back(std::move(cycle));
    }
  }
  return P;
}
}  // namespace internal

/// Persistence of the branch and loop features of a Reeb graph, computed on the graph itself.
///
/// Method: branches by two union-find sweeps (up for minima, down for maxima; elder rule), O(n log n) with
/// n nodes and arcs. A loop is born at a down-fork whose lower arcs are already connected below it; it is
/// paired with the highest up-fork s' such that the two branches are connected in the part of the graph
/// between f(s') and the fork: a maximin (widest) path search in the sublevel graph, O(n log n) per loop.
/// Nodes with several arcs below or above (degenerate forks) act as chains of binary forks, as in a
/// simulation of simplicity; node order is the graph's (f, vertex index) order.
/// \pre R's node values are finite and in increasing (value, vertex) order, as reeb_graph() returns them (checked;
/// throws).
inline Reeb_graph_persistence compute_reeb_graph_persistence(const Reeb_graph& R) {
  return internal::reeb_graph_persistence(R, nullptr);
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_REEB_GRAPH_PERSISTENCE_H
