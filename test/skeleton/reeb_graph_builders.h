// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Hand-built Reeb graphs for tests that give a graph directly (not from a complex).
#ifndef FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H
#define FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>

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

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_REEB_GRAPH_BUILDERS_H
