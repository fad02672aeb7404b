// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Hand-built Reeb graphs for tests that give a graph directly (not from a complex).
#ifndef FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H
#define FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/repair_reeb_graph.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace test {

/// A node of a hand-built Reeb graph: its vertex, its value and its members (no type set).
inline skeleton::Reeb_graph::Node reeb_node(skeleton::Vertex_index v, double f,
                                            std::vector<skeleton::Vertex_index> members = {}) {
  skeleton::Reeb_graph::Node n;
  n.vertex = v;
  n.value = f;
  n.members = std::move(members);
  return n;
}

/// A Reeb graph with one component per entry of `spines`, component c a comb of spines[c] spine nodes
/// (f = 0, 1, 2, ...): spine node i carries a spur up to a maximum at f = i + 0.5 when i is even and
/// positive, and when i is odd a side node at f = i + 0.5 joined to it and to spine node i + 1 (a loop of
/// height 1; none after the last spine node). Spine node 0 is a stub of height 1 below a fork when the
/// spine has at least three nodes. Vertices are numbered in order of construction; nodes are in (value,
/// vertex) order with their types and the count of components, as reeb_graph() leaves them.
inline skeleton::Reeb_graph reeb_combs(const std::vector<std::size_t>& spines) {
  using skeleton::Vertex_index;
  std::vector<std::pair<double, Vertex_index>> nodes;  // (value, vertex)
  std::vector<std::array<Vertex_index, 2>> arcs;       // (lower, upper) vertices
  for (const std::size_t n : spines) {
    const auto first = static_cast<Vertex_index>(nodes.size());
    for (std::size_t i = 0; i < n; ++i) nodes.push_back({double(i), static_cast<Vertex_index>(nodes.size())});
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const auto a = static_cast<Vertex_index>(first + i);
      arcs.push_back({a, static_cast<Vertex_index>(a + 1)});
      const auto extra = static_cast<Vertex_index>(nodes.size());
      if (i % 2 == 1) {
        nodes.push_back({i + 0.5, extra});
        arcs.push_back({a, extra});
        arcs.push_back({extra, static_cast<Vertex_index>(a + 1)});
      } else if (i > 0) {
        nodes.push_back({i + 0.5, extra});
        arcs.push_back({a, extra});
      }
    }
  }
  std::vector<std::size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&nodes](std::size_t a, std::size_t b) { return nodes[a] < nodes[b]; });
  std::vector<std::size_t> index(nodes.size());
  skeleton::Reeb_graph R;
  for (std::size_t k = 0; k < order.size(); ++k) {
    index[order[k]] = k;
    R.nodes.push_back(reeb_node(nodes[order[k]].second, nodes[order[k]].first));
  }
  for (const auto& [a, b] : arcs) R.arcs.push_back({index[a], index[b], {}});
  skeleton::internal::refresh_node_types(R);
  R.components = static_cast<std::size_t>(
      std::count_if(spines.begin(), spines.end(), [](std::size_t n) { return n > 0; }));
  return R;
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H
