// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <gtest/gtest.h>

#include "skeleton_test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
/// Points on the x axis (or a circle) with f = the first coordinate.
struct Line {
  std::vector<std::array<double, 2>> p;
  double operator()(Vertex_index a, Vertex_index b) const { return std::hypot(p[a][0] - p[b][0], p[a][1] - p[b][1]); }
};
}  // namespace

TEST(RepairReebGraph, JoinsABrokenPathAndSimplifies) {
  // Path 0..9 along x with the edge 4-5 missing: two components.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  for (int i = 0; i < 10; ++i) {
    pts.p.push_back({double(i), 0.0});
    f.push_back(double(i));
    if (i + 1 < 10 && i != 4) edges.push_back({Vertex_index(i), Vertex_index(i + 1)});
  }
  const auto c = make(10, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  const Reeb_graph R = A.reeb_graph();
  ASSERT_EQ(R.components, 2u);
  EXPECT_EQ(repair_reeb_graph(R, 0.5, pts).joined, 0u);  // too far
  const Reeb_repair_result fixed = repair_reeb_graph(R, 1.0, pts);  // inclusive
  EXPECT_EQ(fixed.joined, 1u);
  EXPECT_EQ(fixed.graph.components, 1u);
  // Simplifying (even with delta 0) absorbs the nodes that became regular: one arc through every vertex.
  const Reeb_simplification_result S = simplify_by_persistence(fixed.graph, A.values(), 0.0);
  EXPECT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.arcs[0].vertices.size(), 8u);
  EXPECT_EQ(S.graph.components, 1u);
}

TEST(RepairReebGraph, ClosesABrokenCircleIntoALoop) {
  // A 16-gon of radius 5 with one edge missing: a path; repair closes the loop, persistence keeps it.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  for (int i = 0; i < 16; ++i) {
    const double a = 2 * std::acos(-1.0) * i / 16;
    pts.p.push_back({5 * std::cos(a), 5 * std::sin(a)});
    f.push_back(5 * std::sin(a) + 0.01 * i);
    if (i < 15) edges.push_back({Vertex_index(i), Vertex_index(i + 1)});
  }
  const auto c = make(16, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  EXPECT_EQ(A.reeb_graph().loops(), 0u);
  const Reeb_repair_result fixed = repair_reeb_graph(A.reeb_graph(), 2.5, pts);
  EXPECT_EQ(fixed.joined, 1u);
  EXPECT_EQ(fixed.graph.loops(), 1u);
  const Reeb_simplification_result S = simplify_by_persistence(fixed.graph, A.values(), 1.0);
  EXPECT_EQ(S.graph.loops(), 1u);  // the loop is tall (about 10): it survives
  const Reeb_simplification_result T = simplify_by_persistence(fixed.graph, A.values(), 20.0);
  EXPECT_EQ(T.graph.loops(), 0u);
  EXPECT_THROW(repair_reeb_graph(A.reeb_graph(), -1.0, pts), std::invalid_argument);
}
