// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The Reeb-graph core (Augmented_reeb_graph.h, reeb_graph_persistence.h, simplify_by_persistence.h and the
// link-cut tree they use): documented orders, checks, tie rules and stops that no other test pinned (found by
// mutation testing: each test below fails when the behaviour it names is changed).
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/internal/Link_cut_tree.h>
#include <FeatureRecon/skeleton/reeb_graph_persistence.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "reeb_graph_builders.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

/// A path 0 - 1 - ... - n-1 with f = index.
Complex_with_function rising_path(std::size_t n) {
  std::vector<Edge> edges;
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = static_cast<double>(i);
    if (i + 1 < n) edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
  }
  return make(n, edges, {}, f);
}
}  // namespace

// Augmented_reeb_graph::arcs(): "Arcs sorted by (rank of lower, rank of upper)"; up_arcs(v) lists them in
// that order, and Reeb_graph::arcs out of one node go "by the (f, vertex index) order of the first vertex
// each reaches".
TEST(ReebCoreAudit, ArcsAreSortedByTheRanksOfTheirLowerThenUpperEnds) {
  // A star: vertex 0 (f 0) with arms to 1 (f 3), 2 (f 1), 3 (f 2), and 1 on to 4 (f 5).
  const auto star = make(5, {{0, 1}, {0, 2}, {0, 3}, {1, 4}}, {}, {0, 3, 1, 2, 5});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(star.complex, star.f);
  ASSERT_EQ(A.number_of_arcs(), 4u);
  const std::vector<std::pair<Vertex_index, Vertex_index>> expected{{0, 2}, {0, 3}, {0, 1}, {1, 4}};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(A.arcs()[k].lower, expected[k].first) << k;
    EXPECT_EQ(A.arcs()[k].upper, expected[k].second) << k;
  }
  EXPECT_EQ(A.up_arcs(0), (std::vector<std::size_t>{0, 1, 2}));
  const Reeb_graph R = A.reeb_graph();
  ASSERT_EQ(R.arcs.size(), 3u);  // vertex 1 is regular: the arm to 4 passes it
  EXPECT_EQ(R.nodes[R.arcs[0].upper].vertex, 2u);
  EXPECT_EQ(R.nodes[R.arcs[1].upper].vertex, 3u);
  EXPECT_EQ(R.nodes[R.arcs[2].upper].vertex, 4u);
  EXPECT_EQ(R.arcs[2].vertices, (std::vector<Vertex_index>{1}));
  // The same order on a torus, where many nodes have two arcs above.
  const auto t = upright_torus(12, 7);
  const Augmented_reeb_graph B = compute_augmented_reeb_graph(t.complex, t.f);
  const auto ranks = [&B](const Augmented_reeb_graph::Arc& a) {
    return std::make_pair(B.rank()[a.lower], B.rank()[a.upper]);
  };
  EXPECT_TRUE(std::is_sorted(B.arcs().begin(), B.arcs().end(),
                             [&](const auto& a, const auto& b) { return ranks(a) < ranks(b); }));
}

// Reeb_graph::count(flag): "number of nodes carrying flag" (a bit set: a node can carry several).
TEST(ReebCoreAudit, CountCountsNodesCarryingTheFlagAmongOthers) {
  // Theta graph: the bottom is a minimum and an up-fork, the top a maximum and a down-fork.
  const auto theta = make(5, {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {2, 4}, {3, 4}}, {}, {0, 1, 2, 3, 10});
  const Reeb_graph R = reeb_graph_of(theta);
  ASSERT_EQ(R.nodes.size(), 2u);
  EXPECT_EQ(R.nodes[0].type, unsigned(minimum | up_fork));
  EXPECT_EQ(R.count(minimum), 1u);
  EXPECT_EQ(R.count(up_fork), 1u);
  EXPECT_EQ(R.count(maximum), 1u);
  EXPECT_EQ(R.count(down_fork), 1u);
}

// Reeb_graph::loops(): "0 when components is too small for that to be one" (no unsigned wrap-around), and a
// hand-built graph with components 0 has them counted.
TEST(ReebCoreAudit, LoopsOfHandBuiltGraphs) {
  Reeb_graph G;  // four nodes, one arc, but components set to 1 (too small: there are three)
  G.nodes = {reeb_node(0, 0), reeb_node(1, 1), reeb_node(2, 2), reeb_node(3, 3)};
  G.arcs = {{0, 1, {}}};
  G.components = 1;
  EXPECT_EQ(G.loops(), 0u);
  Reeb_graph H;  // two nodes joined by two arcs: one loop, components left 0
  H.nodes = {reeb_node(0, 0), reeb_node(1, 1)};
  H.arcs = {{0, 1, {}}, {0, 1, {}}};
  EXPECT_EQ(H.loops(), 1u);
}

// count_components(): "arcs joining nodes out of range are not counted", also an arc to the node one past the
// last.
TEST(ReebCoreAudit, ComponentsIgnoreAnArcToTheNodeOnePastTheLast) {
  Reeb_graph G;
  G.nodes = {reeb_node(0, 0), reeb_node(1, 1)};
  G.arcs = {{0, 2, {}}, {2, 1, {}}};
  EXPECT_EQ(FeatureRecon::skeleton::internal::count_components(G), 2u);
}

// compute_augmented_reeb_graph(): "f has K.number_of_vertices finite values (checked; throws ...)": too many
// values are refused as too few are.
TEST(ReebCoreAudit, TooManyFunctionValuesAreRefused) {
  const auto c = circle(6);
  std::vector<double> f = c.f;
  f.push_back(0.5);
  EXPECT_TRUE(contains(invalid_argument_message([&] { compute_augmented_reeb_graph(c.complex, f); }),
                       "f has 7 values for 6 vertices"));
}

// Reeb_graph_options::progress: a stop during the sweep leaves "Status::interrupted; the arcs closed so far":
// the sweep ends there (no later report), and the arcs still open are not returned.
TEST(ReebCoreAudit, AStopDuringTheSweepEndsItAndKeepsOnlyClosedArcs) {
  const std::size_t n = 8192;
  const auto path = rising_path(n);
  std::size_t later = 0;
  bool refused = false;
  Reeb_graph_options options;
  options.progress = [&](double t) {
    if (refused) ++later;
    refused = refused || t > 0.4;  // the first report of the sweep
    return !refused;
  };
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(path.complex, path.f, options);
  EXPECT_EQ(A.status(), Status::interrupted);
  EXPECT_EQ(later, 0u);
  EXPECT_GT(A.number_of_arcs(), 0u);
  EXPECT_LT(A.number_of_arcs(), n - 1);
  for (const auto& a : A.arcs()) EXPECT_EQ(a.upper, a.lower + 1);  // arcs of the path, closed
}

// compute_reeb_graph_persistence(): the nodes must be "in increasing (value, vertex) order (checked;
// throws)": two nodes of one vertex are not; and an arc must go up between two nodes (not a loop at one
// node).
TEST(ReebCoreAudit, PersistenceRefusesARepeatedNodeAndAnArcFromANodeToItself) {
  Reeb_graph twice;
  twice.nodes = {reeb_node(0, 1), reeb_node(0, 1)};
  twice.arcs = {{0, 1, {}}};
  EXPECT_TRUE(contains(invalid_argument_message([&] { compute_reeb_graph_persistence(twice); }),
                       "nodes 0 and 1 are not in increasing (value, vertex) order"));
  Reeb_graph self;
  self.nodes = {reeb_node(0, 0), reeb_node(1, 1)};
  self.arcs = {{0, 1, {}}, {1, 1, {}}};
  EXPECT_TRUE(contains(invalid_argument_message([&] { compute_reeb_graph_persistence(self); }),
                       "arc 1 does not go up between valid nodes"));
}

// The thin cycle of a loop (reeb_graph_persistence.h): arcs weigh "the rank in (lower, upper, index) order",
// so of parallel arcs the one of the larger index weighs more and takes the forest's place: the thin cycle of
// each new parallel arc is the pair of it and the arc before it.
TEST(ReebCoreAudit, ParallelArcsTieByIndexInTheLoopForest) {
  Reeb_graph R;
  R.nodes = {reeb_node(0, 0), reeb_node(1, 1)};
  R.arcs = {{0, 1, {}}, {0, 1, {}}, {0, 1, {}}, {0, 1, {}}};
  std::vector<std::vector<std::size_t>> cycles;
  const Reeb_graph_persistence P = FeatureRecon::skeleton::internal::reeb_graph_persistence(R, &cycles);
  ASSERT_EQ(P.loops.size(), 3u);
  ASSERT_EQ(cycles.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    std::vector<std::size_t> c = cycles[i];
    std::sort(c.begin(), c.end());
    EXPECT_EQ(c, (std::vector<std::size_t>{i, i + 1})) << "loop " << i;
  }
}

// Link_cut_tree::for_each_on_path(x, y): "Calls f(node) for every node of the tree path x..y, in order from x
// to y", whatever root and splay shape earlier operations left: a random tree (fixed seed), random roots and
// queries, each walk checked against the path found by a parent walk.
TEST(ReebCoreAudit, LinkCutTreeWalksAPathInOrder) {
  using FeatureRecon::skeleton::internal::Link_cut_tree;
  const std::int32_t n = 60;
  std::mt19937 rng(11);
  Link_cut_tree T(static_cast<std::size_t>(n));
  std::vector<std::int32_t> parent(static_cast<std::size_t>(n), -1);  // the tree rooted at 0
  for (std::int32_t i = 1; i < n; ++i) {
    parent[static_cast<std::size_t>(i)] = std::uniform_int_distribution<std::int32_t>(0, i - 1)(rng);
    T.link(i, parent[static_cast<std::size_t>(i)]);
  }
  auto to_root = [&parent](std::int32_t x) {
    std::vector<std::int32_t> p{x};
    while (parent[static_cast<std::size_t>(p.back())] != -1)
      p.push_back(parent[static_cast<std::size_t>(p.back())]);
    return p;
  };
  std::uniform_int_distribution<std::int32_t> any(0, n - 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::int32_t x = any(rng), y = any(rng);
    if (trial % 3 == 0) T.evert(any(rng));
    if (trial % 5 == 0) (void)T.find_root(any(rng));
    std::vector<std::int32_t> px = to_root(x), py = to_root(y);
    while (px.size() > 1 && py.size() > 1 && px[px.size() - 2] == py[py.size() - 2]) {
      px.pop_back();
      py.pop_back();
    }
    std::vector<std::int32_t> expected = px;  // x up to the meeting node, then down to y
    expected.insert(expected.end(), py.rbegin() + 1, py.rend());
    std::vector<std::int32_t> seen;
    T.for_each_on_path(x, y, [&seen](std::int32_t z) { seen.push_back(z); });
    ASSERT_EQ(seen, expected) << "trial " << trial << ": " << x << " .. " << y;
  }
}

// simplify_by_persistence(): "\pre delta >= 0 and finite ... (all checked; throws)": infinity is refused, as a
// negative delta is.
TEST(ReebCoreAudit, SimplificationRefusesAnInfiniteDelta) {
  const auto c = rising_path(3);
  const Reeb_graph R = reeb_graph_of(c);
  EXPECT_TRUE(contains(invalid_argument_message(
                           [&] { simplify_by_persistence(R, c.f, std::numeric_limits<double>::infinity()); }),
                       "delta must be finite and >= 0, got inf"));
}

// simplify_by_persistence(): an arc whose lower node is out of range is named as such (as one whose upper
// node is), before the persistence looks at it.
TEST(ReebCoreAudit, SimplificationNamesAnArcWithItsLowerNodeOutOfRange) {
  const auto c = rising_path(3);
  Reeb_graph bad = reeb_graph_of(c);
  bad.arcs[0].lower = 9;
  EXPECT_TRUE(contains(invalid_argument_message([&] { simplify_by_persistence(bad, c.f, 0.5); }),
                       "arc 0 joins nodes out of range [0, 2)"));
}

// simplify_by_persistence(): "Members of a node with another value than the node's ... are not level with it:
// they take no part in the merges and stay with the node of their node's vertex", members above the node's
// level as those below.
TEST(ReebCoreAudit, MembersAboveTheirNodesLevelStayWithTheNode) {
  Reeb_graph R;  // one arc from vertex 0 (f 0) to vertex 1 (f 1), whose node holds vertex 2 (f 5)
  R.nodes = {reeb_node(0, 0), reeb_node(1, 1, {2})};
  R.arcs = {{0, 1, {}}};
  R.nodes[0].type = minimum;
  R.nodes[1].type = maximum;
  R.components = 1;
  const Reeb_simplification_result S = simplify_by_persistence(R, {0, 1, 5}, 0.0);
  ASSERT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.nodes[1].vertex, 1u);
  EXPECT_EQ(S.graph.nodes[1].members, (std::vector<Vertex_index>{2}));
  EXPECT_TRUE(S.graph.arcs[0].vertices.empty());
}

// Simplification_options::progress: "returning false stops: status interrupted, empty graph", at any report
// before the last (1, the work done), even when the callback would go on afterwards: a callback that refuses
// once, at its i-th report, for every i.
TEST(ReebCoreAudit, SimplificationStopsOnAnyRefusalEvenIfTheCallbackChangesItsMind) {
  // A loop 0-1-3-2 with a spur 1-5 (persistence 0.5): both merged at delta 4.
  const auto g = make(6, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}, {1, 5}}, {}, {0, 1, 2, 4, 6, 1.5});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  std::vector<double> seen;
  Simplification_options watching;
  watching.progress = test::recording_progress(seen);
  ASSERT_EQ(simplify_by_persistence(A, 4.0, watching).status, Status::success);
  ASSERT_GE(seen.size(), 3u);
  ASSERT_EQ(seen.back(), 1.0);
  for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
    std::size_t calls = 0;
    Simplification_options once;
    once.progress = [&calls, i](double) { return calls++ != i; };
    const Reeb_simplification_result S = simplify_by_persistence(A, 4.0, once);
    EXPECT_EQ(S.status, Status::interrupted) << "refused at report " << i << " (" << seen[i] << ")";
    EXPECT_TRUE(S.graph.nodes.empty()) << i;
    EXPECT_EQ(S.removed_loops, 0u) << i;
  }
}
