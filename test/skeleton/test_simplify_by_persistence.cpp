// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "hera_bottleneck.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
/// Options whose progress callback refuses every fraction from `stop_at` on and counts in `later` the reports
/// after the first refusal (a stopped run must ask no more).
Simplification_options stopping_at(double stop_at, std::size_t& later) {
  Simplification_options stopping;
  // The state is shared: copies of the callback (stage wrappers) see one refusal.
  stopping.progress = [stop_at, &later, refused = std::make_shared<bool>(false)](double t) {
    if (*refused) ++later;
    *refused = *refused || t >= stop_at;
    return t < stop_at;
  };
  return stopping;
}
std::vector<std::pair<double, double>> diagram(const std::vector<Reeb_persistence_pair>& v) {
  std::vector<std::pair<double, double>> d;
  for (const auto& p : v)
    if (p.birth != p.death) d.emplace_back(p.birth, p.death);  // tied values give points on the diagonal
  return d;
}
std::size_t count_above(const std::vector<Reeb_persistence_pair>& v, double t) {
  return static_cast<std::size_t>(
      std::count_if(v.begin(), v.end(), [t](const auto& p) { return p.persistence() > t; }));
}

/// A random connected graph (a random tree plus extra edges) with a random function; integer values on odd
/// seeds (many ties).
Complex_with_function random_graph(std::mt19937& rng, bool ties, int max_n = 40) {
  const int n = std::uniform_int_distribution<int>(2, max_n)(rng);
  std::vector<Edge> edges;
  for (int v = 1; v < n; ++v)
    edges.push_back({static_cast<Vertex_index>(std::uniform_int_distribution<int>(0, v - 1)(rng)),
                     static_cast<Vertex_index>(v)});
  const int extra = std::uniform_int_distribution<int>(0, n / 2 + 1)(rng);
  for (int k = 0; k < extra; ++k) {
    const auto a = static_cast<Vertex_index>(std::uniform_int_distribution<int>(0, n - 1)(rng));
    const auto b = static_cast<Vertex_index>(std::uniform_int_distribution<int>(0, n - 1)(rng));
    if (a != b) edges.push_back({a, b});
  }
  std::vector<Triangle> triangles;
  if (n >= 3 && std::uniform_int_distribution<int>(0, 3)(rng) == 0) triangles.push_back({0, 1, 2});
  std::vector<double> f(static_cast<std::size_t>(n));
  for (double& x : f)
    x = ties ? std::uniform_int_distribution<int>(0, 6)(rng)
             : std::uniform_real_distribution<double>(0, 1)(rng);
  return make(static_cast<std::size_t>(n), edges, triangles, f);
}

/// Every input vertex is exactly once in the graph: a node's vertex or members, or an arc's vertices.
void expect_partition(const Reeb_graph& G, std::size_t n, const std::string& what) {
  std::vector<int> seen(n, 0);
  for (const auto& node : G.nodes) {
    ASSERT_LT(node.vertex, n) << what;
    ++seen[node.vertex];
    for (Vertex_index v : node.members) ++seen[v];
  }
  for (const auto& arc : G.arcs)
    for (Vertex_index v : arc.vertices) ++seen[v];
  for (std::size_t v = 0; v < n; ++v) EXPECT_EQ(seen[v], 1) << what << ": vertex " << v;
}
}  // namespace

namespace {
std::size_t count_between(const std::vector<Reeb_persistence_pair>& v, double lo, double hi) {  // in (lo, hi]
  return static_cast<std::size_t>(std::count_if(
      v.begin(), v.end(), [lo, hi](const auto& p) { return p.persistence() > lo && p.persistence() <= hi; }));
}
/// Runs random graphs and thresholds until `effective` trials both removed a feature and had one of
/// persistence above 2 delta to keep (at most 4 times as many trials in all), checking the guarantee on every
/// trial.
void check_guarantee_on_random_graphs(unsigned seed, std::size_t effective, int max_n,
                                      std::size_t min_removed, std::size_t min_loops_removed) {
  std::mt19937 rng(seed);
  std::size_t removed = 0, loops_removed = 0, counted = 0;
  for (std::size_t trial = 0; counted < effective && trial < 4 * effective; ++trial) {
    const bool ties = trial % 2 == 1;
    const auto c = random_graph(rng, ties, max_n);
    const double delta = std::uniform_real_distribution<double>(0, ties ? 3.0 : 0.5)(rng);
    const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
    const Reeb_graph_persistence before = compute_reeb_graph_persistence(A.reeb_graph());
    const Reeb_simplification_result S = simplify_by_persistence(A, delta);
    const std::string what = "trial " + std::to_string(trial) + " delta " + std::to_string(delta);
    expect_partition(S.graph, c.complex.number_of_vertices, what);
    const Reeb_graph_persistence after = compute_reeb_graph_persistence(S.graph);
    removed += S.removed_branches + S.removed_loops;
    loops_removed += S.removed_loops;
    // The diagrams move by at most 2 delta (branches), 6 delta (loops).
    EXPECT_LE(hera_bottleneck(diagram(before.sublevel_branches), diagram(after.sublevel_branches)),
              2 * delta + 1e-9)
        << what;
    EXPECT_LE(hera_bottleneck(diagram(before.superlevel_branches), diagram(after.superlevel_branches)),
              2 * delta + 1e-9)
        << what;
    EXPECT_LE(hera_bottleneck(diagram(before.loops), diagram(after.loops)), 6 * delta + 1e-9) << what;
    EXPECT_EQ(S.graph.components, A.reeb_graph().components) << what;
    const std::vector<Reeb_persistence_pair>* diagrams[3][2] = {
        {&before.sublevel_branches, &after.sublevel_branches},
        {&before.superlevel_branches, &after.superlevel_branches},
        {&before.loops, &after.loops}};
    for (const auto& [b, a] : diagrams) {
      // Features above 2 delta survive, and as more than noise: above delta.
      EXPECT_GE(count_above(*a, delta), count_above(*b, 2 * delta)) << what;
      // Every feature of persistence <= delta is merged away. A feature of at most delta left afterwards is
      // one of persistence in (delta, 2 delta] that a merge shortened, never an original small one: there are
      // at most as many, and none of them has an original small feature's birth and death (distinct values
      // only: with ties, two features can share them).
      EXPECT_LE(count_between(*a, 0, delta), count_between(*b, delta, 2 * delta)) << what;
      if (!ties)
        for (const auto& q : *a)
          for (const auto& p : *b)
            if (p.persistence() > 0 && p.persistence() <= delta) {
              EXPECT_FALSE(q.birth == p.birth && q.death == p.death)
                  << what << ": the feature (" << p.birth << ", " << p.death << ") survived";
            }
    }
    const bool keeps = count_above(before.sublevel_branches, 2 * delta) +
                           count_above(before.superlevel_branches, 2 * delta) +
                           count_above(before.loops, 2 * delta) >
                       0;
    if (S.removed_branches + S.removed_loops > 0 && keeps) ++counted;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GE(counted, effective);    // trials that both removed and kept something
  EXPECT_GT(removed, min_removed);  // the property was exercised
  EXPECT_GT(loops_removed, min_loops_removed);
}
}  // namespace

TEST(SimplifyByPersistence, GuaranteeOnRandomGraphs) {
  check_guarantee_on_random_graphs(2026, 1000, 40, 1000, 100);
}

// Larger graphs: nested branches, forks of sibling components with several parts beyond a spur's top level.
TEST(SimplifyByPersistence, GuaranteeOnLargerRandomGraphs) {
  check_guarantee_on_random_graphs(7, 150, 300, 3000, 100);
}

TEST(SimplifyByPersistence, TrimmingStubsMovesEveryDiagramByAtMostTheHeight) {
  // trim_essential_stubs() is f set to the fork's value on each stub (a change of at most max_height): every
  // diagram moves by at most max_height, on the Reeb graph itself and after a simplification (the pipeline's
  // order). Its documentation said that every feature but the essential pair stays as it is, which a stub
  // ending at a down-fork of two minima (or an up-fork of two maxima) breaks (here 219 of 374 trimmed
  // graphs).
  std::mt19937 rng(11);
  std::size_t trimmed = 0, others_changed = 0;
  auto sorted = [](std::vector<std::pair<double, double>> d) {
    std::sort(d.begin(), d.end());
    return d;
  };
  for (int trial = 0; trial < 3000; ++trial) {
    const bool ties = trial % 2 == 1;
    const auto c = random_graph(rng, ties, 40);
    const double h = std::uniform_real_distribution<double>(0, ties ? 3.0 : 0.5)(rng);
    const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
    const Reeb_graph R =
        trial % 4 < 2 ? A.reeb_graph() : simplify_by_persistence(A.reeb_graph(), A.values(), h).graph;
    const Reeb_trim_result T = trim_essential_stubs(R, h);
    const std::string what = "trial " + std::to_string(trial) + " height " + std::to_string(h);
    expect_partition(T.graph, c.complex.number_of_vertices, what);
    const Reeb_graph_persistence before = compute_reeb_graph_persistence(R);
    const Reeb_graph_persistence after = compute_reeb_graph_persistence(T.graph);
    EXPECT_LE(hera_bottleneck(diagram(before.sublevel_branches), diagram(after.sublevel_branches)), h + 1e-9)
        << what;
    EXPECT_LE(hera_bottleneck(diagram(before.superlevel_branches), diagram(after.superlevel_branches)),
              h + 1e-9)
        << what;
    EXPECT_LE(hera_bottleneck(diagram(before.loops), diagram(after.loops)), h + 1e-9) << what;
    // One essential pair per component, each moved by at most h at either end.
    ASSERT_EQ(after.essential.size(), before.essential.size()) << what;
    auto e0 = before.essential, e1 = after.essential;
    auto by_ends = [](const Reeb_persistence_pair& a, const Reeb_persistence_pair& b) {
      return std::make_pair(a.birth, a.death) < std::make_pair(b.birth, b.death);
    };
    std::sort(e0.begin(), e0.end(), by_ends);
    std::sort(e1.begin(), e1.end(), by_ends);
    EXPECT_EQ(T.graph.components, R.components) << what;
    if (before.essential.size() == 1) {
      EXPECT_LE(std::fabs(e0[0].birth - e1[0].birth), h + 1e-9) << what;
      EXPECT_LE(std::fabs(e0[0].death - e1[0].death), h + 1e-9) << what;
    }
    if (T.trimmed > 0) {
      ++trimmed;
      if (sorted(diagram(before.sublevel_branches)) != sorted(diagram(after.sublevel_branches)) ||
          sorted(diagram(before.superlevel_branches)) != sorted(diagram(after.superlevel_branches)))
        ++others_changed;
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(trimmed, 300u);         // the property was exercised
  EXPECT_GT(others_changed, 150u);  // including the stubs whose fork pairs another extreme
}

TEST(SimplifyByPersistence, RemovesSmallFeaturesOnly) {
  // A figure-eight-like graph with a short spur: delta between the spur and the loops removes the spur only.
  // Loop 0-1-3-2 (bottom 0, top 3, height 4), spur 1-5 (f 1 -> 1.5, persistence 0.5 as a superlevel branch).
  // "Persistence at most delta": the spur's persistence is exactly the delta below, and so is the loop's at
  // delta 4 (values exact in binary).
  const auto g = make(6, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}, {1, 5}}, {}, {0, 1, 2, 4, 6, 1.5});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_simplification_result S = simplify_by_persistence(A, 0.5);
  EXPECT_EQ(S.removed_branches, 1u);
  EXPECT_EQ(S.removed_loops, 0u);
  EXPECT_EQ(S.graph.loops(), 1u);
  EXPECT_EQ(S.graph.count(maximum), 1u);
  expect_partition(S.graph, 6, "spur");
  // The loop's persistence exactly delta: removed (counted, and merged away).
  const Reeb_simplification_result L = simplify_by_persistence(A, 4.0);
  EXPECT_EQ(L.removed_loops, 1u);
  EXPECT_EQ(L.graph.loops(), 0u);
  EXPECT_EQ(L.graph.nodes.size(), 2u);
  EXPECT_EQ(L.graph.arcs.size(), 1u);
  // A large delta removes the loop too: a single arc.
  const Reeb_simplification_result T = simplify_by_persistence(A, 10.0);
  EXPECT_EQ(T.graph.loops(), 0u);
  EXPECT_EQ(T.graph.nodes.size(), 2u);
  EXPECT_EQ(T.graph.arcs.size(), 1u);
  expect_partition(T.graph, 6, "all");
  // delta = 0 changes nothing.
  const Reeb_simplification_result Z = simplify_by_persistence(A, 0.0);
  EXPECT_EQ(Z.graph.nodes.size(), A.reeb_graph().nodes.size());
  EXPECT_EQ(Z.graph.arcs.size(), A.reeb_graph().arcs.size());
  EXPECT_THROW(simplify_by_persistence(A, -1.0), std::invalid_argument);
}

TEST(SimplifyByPersistence, UnusedValuesSubnormalsAndTrimmedStubs) {
  // An index the graph does not use may hold NaN or inf (the glued complex checked every value and the
  // message named compute_augmented_reeb_graph).
  const auto g = make(2, {{0, 1}}, {}, {0, 1});
  const Reeb_graph R = compute_augmented_reeb_graph(g.complex, g.f).reeb_graph();
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    const Reeb_simplification_result S = simplify_by_persistence(R, {0, 1, bad}, 0.0);
    ASSERT_EQ(S.graph.nodes.size(), 2u);
    EXPECT_EQ(S.graph.arcs.size(), 1u);
    EXPECT_TRUE(S.graph.nodes[0].members.empty() && S.graph.nodes[1].members.empty());
  }
  // Two parallel arcs between nodes of the smallest subnormal value: the helper midpoint rounded to 0, below
  // both (an assertion, or a node on a helper vertex). Level: one node with the other as a member.
  const double t = std::numeric_limits<double>::denorm_min();
  Reeb_graph P;
  P.nodes.resize(2);
  P.nodes[0].vertex = 0;
  P.nodes[0].value = t;
  P.nodes[1].vertex = 1;
  P.nodes[1].value = t;
  P.arcs = {{0, 1, {}}, {0, 1, {}}};
  P.components = 1;
  const Reeb_simplification_result Q = simplify_by_persistence(P, {t, t}, 0.0);
  ASSERT_EQ(Q.graph.nodes.size(), 1u);
  EXPECT_EQ(Q.graph.nodes[0].vertex, 0u);
  EXPECT_EQ(Q.graph.nodes[0].members, (std::vector<Vertex_index>{1}));
  // Trimming the stub 0 -> 2 leaves the fork 2 regular; simplifying then put vertex 0 (f 0) inside the arc
  // from vertex 1 (f 1) to vertex 3 (f 5), after vertex 2. It goes to the arc's lower node, on its side.
  const auto h = make(4, {{0, 2}, {1, 2}, {2, 3}}, {}, {0, 1, 2, 5});
  const Reeb_trim_result T =
      trim_essential_stubs(compute_augmented_reeb_graph(h.complex, h.f).reeb_graph(), 2.0);
  ASSERT_EQ(T.trimmed, 1u);
  const Reeb_simplification_result U = simplify_by_persistence(T.graph, h.f, 0.0);
  ASSERT_EQ(U.graph.nodes.size(), 2u);
  ASSERT_EQ(U.graph.arcs.size(), 1u);
  EXPECT_EQ(U.graph.arcs[0].vertices, (std::vector<Vertex_index>{2}));
  EXPECT_EQ(U.graph.nodes[0].vertex, 1u);
  EXPECT_EQ(U.graph.nodes[0].members, (std::vector<Vertex_index>{0}));
  expect_partition(U.graph, 4, "trimmed");
}

namespace {
std::string error_of(const Reeb_graph& R, const std::vector<double>& f) {
  return invalid_argument_message([&] { simplify_by_persistence(R, f, 0.5); });
}
}  // namespace

TEST(SimplifyByPersistence, BadGraphsAreNamed) {
  // Path 0 - 1 - 2 with f = 0, 1, 2: one arc from node 0 (vertex 0) to node 1 (vertex 2) through vertex 1.
  const auto g = make(3, {{0, 1}, {1, 2}}, {}, {0, 1, 2});
  const Reeb_graph R = compute_augmented_reeb_graph(g.complex, g.f).reeb_graph();
  ASSERT_EQ(R.arcs.size(), 1u);
  ASSERT_EQ(R.arcs[0].vertices, (std::vector<Vertex_index>{1}));
  Reeb_graph bad = R;
  bad.arcs[0].vertices = {40};
  EXPECT_TRUE(contains(error_of(bad, g.f), "arc 0 has vertex 40 out of range [0, 3): values has 3 entries"));
  // Too few values for the graph: named as such, not only as a vertex out of range.
  EXPECT_TRUE(contains(error_of(R, {0, 1}),
                       "node 1 has vertex 2 out of range [0, 2): values has 2 entries, one per "
                       "vertex"));
  bad = R;
  bad.arcs[0].vertices = {0};
  EXPECT_TRUE(contains(error_of(bad, g.f), "vertex 0 appears twice in the graph (arc 0)"));
  bad = R;
  bad.nodes[1].members = {7};
  EXPECT_TRUE(contains(error_of(bad, g.f), "node 1 has vertex 7 out of range"));
  EXPECT_TRUE(contains(error_of(R, {0, std::nan(""), 2}), "the value of vertex 1 (arc 0) is nan"));
  EXPECT_TRUE(contains(error_of(R, {0, 1, -5}), "node 1 has value 2 but its vertex 2 has -5"));
  bad = R;
  bad.arcs[0].upper = 9;
  EXPECT_TRUE(contains(error_of(bad, g.f), "arc 0 joins nodes out of range"));
  // Nodes out of (value, vertex) order: the message names this function, not the persistence it calls.
  bad = R;
  std::swap(bad.nodes[0], bad.nodes[1]);
  std::swap(bad.arcs[0].lower, bad.arcs[0].upper);
  EXPECT_EQ(
      error_of(bad, g.f).rfind("simplify_by_persistence: nodes 0 and 1 are not in increasing (value, vertex) "
                               "order",
                               0),
      0u)
      << error_of(bad, g.f);
}

TEST(SimplifyByPersistence, OnlyTheGraphsVerticesComeBack) {
  // Two components; pruning the lower one leaves vertices 0-2 out of the graph: they must not come back as
  // isolated nodes.
  const auto g = make(6, {{0, 1}, {1, 2}, {3, 4}, {4, 5}}, {}, {0, 1, 2, 10, 20, 30});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_prune_result P = prune_reeb_graph_components(A.reeb_graph(), 5);
  ASSERT_EQ(P.graph.components, 1u);
  const Reeb_simplification_result S = simplify_by_persistence(P.graph, A.values(), 0.0);
  EXPECT_EQ(S.graph.nodes.size(), 2u);
  EXPECT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.components, 1u);
  std::vector<int> seen(6, 0);
  for (const auto& node : S.graph.nodes) {
    ++seen[node.vertex];
    for (Vertex_index v : node.members) ++seen[v];
  }
  for (const auto& arc : S.graph.arcs)
    for (Vertex_index v : arc.vertices) ++seen[v];
  EXPECT_EQ(seen, (std::vector<int>{0, 0, 0, 1, 1, 1}));
}

TEST(SimplifyByPersistence, TrimmedStubsStayTrimmed) {
  // Lollipop: stub 0 (f 0) - 1 (f 1) up to the fork 2 (f 2), loop 2-3-5 / 2-4-5 (f 3, 3.5, 6). Trimming puts
  // vertices 0 and 1 into the fork's members, off its level; simplifying again keeps them there (an edge to
  // the fork would not be level and brought the stub back as two minima).
  const auto g = make(6, {{0, 1}, {1, 2}, {2, 3}, {2, 4}, {3, 5}, {4, 5}}, {}, {0, 1, 2, 3, 3.5, 6});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_trim_result T = trim_essential_stubs(A.reeb_graph(), 2.5);
  ASSERT_EQ(T.trimmed, 1u);
  const Reeb_simplification_result S = simplify_by_persistence(T.graph, A.values(), 0.0);
  ASSERT_EQ(S.graph.nodes.size(), 2u);
  EXPECT_EQ(S.graph.nodes[0].vertex, 2u);
  std::vector<Vertex_index> members = S.graph.nodes[0].members;
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<Vertex_index>{0, 1}));
  EXPECT_EQ(S.graph.loops(), 1u);
}

TEST(SimplifyByPersistence, ValuesNearTheLargestDouble) {
  // Two parallel arcs without interior vertices get a helper midpoint: halves first, no overflow to infinity.
  const double big = 1.3e308;
  Reeb_graph R;
  R.nodes.resize(2);
  R.nodes[0].vertex = 0;
  R.nodes[0].value = big;
  R.nodes[0].type = minimum | up_fork;
  R.nodes[1].vertex = 1;
  R.nodes[1].value = 1.7e308;
  R.nodes[1].type = maximum | down_fork;
  R.arcs.resize(2);
  R.arcs[0].lower = R.arcs[1].lower = 0;
  R.arcs[0].upper = R.arcs[1].upper = 1;
  R.components = 1;
  const Reeb_simplification_result S = simplify_by_persistence(R, {big, 1.7e308}, 0.0);
  EXPECT_EQ(S.graph.nodes.size(), 2u);
  EXPECT_EQ(S.graph.arcs.size(), 2u);
}

namespace {
/// The arc holding input vertex v (or none).
std::size_t arc_of(const Reeb_graph& G, Vertex_index v) {
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    if (std::find(G.arcs[k].vertices.begin(), G.arcs[k].vertices.end(), v) != G.arcs[k].vertices.end())
      return k;
  return G.arcs.size();
}
}  // namespace

TEST(SimplifyByPersistence, ASpurIsMergedOnTheWayToTheElder) {
  // Fork s = vertex 1 (f 0) above the minimum 0 (f -1). Spur 1 - 2 - 3 (f 0.75, 1): the maximum 3 dies at s,
  // persistence 1. The sibling goes up to the fork a = 4 (f 0.5), which splits into a short branch 4 - 5 - 6
  // (f 0.6, 3; persistence 2.5, kept at delta 1.5) and the way to the elder 4 - 7 - 8 - 9 - 10 (f 0.7, 0.9,
  // 2, 10). Both branches leave a by one arc and cross the spur's top level, the short one first in arc
  // order; the dissertation's path runs towards the elder, so the spur lies on that arc afterwards.
  const auto g = make(11, {{0, 1}, {1, 2}, {2, 3}, {1, 4}, {4, 5}, {5, 6}, {4, 7}, {7, 8}, {8, 9}, {9, 10}},
                      {}, {-1, 0, 0.75, 1, 0.5, 0.6, 3, 0.7, 0.9, 2, 10});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  ASSERT_EQ(A.reeb_graph().count(maximum), 3u);
  const Reeb_simplification_result S = simplify_by_persistence(A, 1.5);
  EXPECT_EQ(S.removed_branches, 1u);
  expect_partition(S.graph, 11, "spur");
  ASSERT_EQ(S.graph.nodes.size(), 4u);  // the minimum, a, and the two maxima
  ASSERT_EQ(S.graph.arcs.size(), 3u);
  const std::size_t to_elder = arc_of(S.graph, 9), to_short = arc_of(S.graph, 5);
  ASSERT_LT(to_elder, 3u);
  ASSERT_LT(to_short, 3u);
  EXPECT_EQ(S.graph.nodes[S.graph.arcs[to_elder].upper].vertex, 10u);
  EXPECT_EQ(arc_of(S.graph, 2), to_elder);
  EXPECT_EQ(arc_of(S.graph, 3), to_elder);
  const std::size_t below_a = arc_of(S.graph, 1);  // s became regular: on the arc from the minimum to a
  ASSERT_LT(below_a, 3u);
  EXPECT_EQ(S.graph.nodes[S.graph.arcs[below_a].lower].vertex, 0u);
  EXPECT_EQ(S.graph.nodes[S.graph.arcs[below_a].upper].vertex, 4u);
  EXPECT_EQ(S.graph.nodes[S.graph.arcs[to_short].upper].vertex, 6u);
}

TEST(SimplifyByPersistence, ManySpursAtOneForkGoTowardsTheElder) {
  // Fork s = vertex 1 (f 0) above the minimum 0 (f -1), with k one-vertex spurs (f up to 0.1), a kept branch
  // to the maximum 2 (f 5) and the elder branch to the maximum 3 (f 10), the spurs' arcs before, between and
  // after the two. Every spur dies at s; each is merged along the arc towards the elder. The sibling
  // components of a fork are found once per fork (they were searched for each pair: quadratic in the fork's
  // degree).
  const std::size_t k = 300, n = 4 + k;
  std::vector<Edge> edges{{0, 1}};
  std::vector<double> f{-1, 0, 5, 10};
  for (std::size_t j = 0; j < k; ++j) {
    if (j == k / 3) edges.push_back({1, 2});
    if (j == 2 * k / 3) edges.push_back({1, 3});
    f.push_back(0.1 * static_cast<double>(j + 1) / static_cast<double>(k));
    edges.push_back({1, static_cast<Vertex_index>(4 + j)});
  }
  const auto g = make(n, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  ASSERT_EQ(A.reeb_graph().count(maximum), k + 2);
  const Reeb_simplification_result S = simplify_by_persistence(A, 1.0);
  EXPECT_EQ(S.removed_branches, k);
  expect_partition(S.graph, n, "fork");
  ASSERT_EQ(S.graph.nodes.size(), 4u);  // the minimum, s and the two maxima
  ASSERT_EQ(S.graph.arcs.size(), 3u);
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t a = arc_of(S.graph, static_cast<Vertex_index>(4 + j));
    ASSERT_LT(a, 3u) << "spur " << j;
    EXPECT_EQ(S.graph.nodes[S.graph.arcs[a].upper].vertex, 3u) << "spur " << j;
  }
}

TEST(SimplifyByPersistence, LongStemWithManySpursBecomesOneArc) {
  // Stem 0..n-1 (f = index); at every inner stem vertex a spur up (f + 0.5) and one down (f - 0.5): each dies
  // at its stem vertex with persistence 0.5. Every sibling component is the rest of the stem: a search of it
  // per spur made this quadratic (session 14: 64,000 spurs took 45 s).
  const std::size_t n = 4000;
  std::vector<Edge> edges;
  std::vector<double> f(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = static_cast<double>(i);
    f[n + i] = i + 0.5;
    f[2 * n + i] = i - 0.5;
    if (i + 1 < n) edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
    if (i > 0 && i + 1 < n) {
      edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(n + i)});
      edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(2 * n + i)});
    }
  }
  const auto g = make(3 * n, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_graph_persistence before = compute_reeb_graph_persistence(A.reeb_graph());
  ASSERT_EQ(before.superlevel_branches.size(), n - 2);
  ASSERT_EQ(before.sublevel_branches.size(), n - 2);
  const Reeb_simplification_result S = simplify_by_persistence(A, 1.0);
  EXPECT_EQ(S.removed_branches, 2 * (n - 2));
  // The spur vertices of the stem's ends (n, 2n - 1, 2n, 3n - 1) are isolated: a component each.
  const Reeb_graph& G = S.graph;
  EXPECT_EQ(G.components, 5u);
  EXPECT_EQ(G.loops(), 0u);
  std::size_t stem_arc = G.arcs.size();
  for (std::size_t k = 0; k < G.arcs.size(); ++k)
    if (G.nodes[G.arcs[k].lower].vertex == 0 && G.nodes[G.arcs[k].upper].vertex == n - 1) stem_arc = k;
  ASSERT_LT(stem_arc, G.arcs.size());
  EXPECT_EQ(G.arcs.size(), 1u);
  EXPECT_EQ(G.arcs[stem_arc].vertices.size(), 3 * (n - 2));
  expect_partition(G, 3 * n, "stem");
}

TEST(SimplifyByPersistence, ProgressIsReportedAndAStopEndsIt) {
  // The spurs at one fork of the test above: reports from 0 to 1 in order, the same graph as without a
  // callback; a stop at the start, after the persistence or during the glued complex's Reeb graph gives
  // interrupted and no graph, and no later report; the last report (1, the work done) does not undo the
  // result.
  const std::size_t k = 300, n = 4 + k;
  std::vector<Edge> edges{{0, 1}, {1, 2}, {1, 3}};
  std::vector<double> f{-1, 0, 5, 10};
  for (std::size_t j = 0; j < k; ++j) {
    f.push_back(0.1 * static_cast<double>(j + 1) / static_cast<double>(k));
    edges.push_back({1, static_cast<Vertex_index>(4 + j)});
  }
  const auto g = make(n, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_simplification_result plain = simplify_by_persistence(A, 1.0);
  std::vector<double> seen;
  Simplification_options watching;
  watching.progress = test::recording_progress(seen);
  const Reeb_simplification_result watched = simplify_by_persistence(A, 1.0, watching);
  EXPECT_EQ(watched.status, Status::success);
  EXPECT_EQ(watched.removed_branches, k);
  ASSERT_EQ(watched.graph.nodes.size(), plain.graph.nodes.size());
  for (std::size_t i = 0; i < plain.graph.nodes.size(); ++i)
    EXPECT_EQ(watched.graph.nodes[i].vertex, plain.graph.nodes[i].vertex);
  ASSERT_GE(seen.size(), 6u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  // glued sweep
  EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double t) { return t > 0.3 && t < 0.9; }));
  for (const double stop_at : {0.0, 0.15, 0.5, 0.95}) {
    std::size_t later = 0;
    const Reeb_simplification_result S = simplify_by_persistence(A, 1.0, stopping_at(stop_at, later));
    EXPECT_EQ(S.status, stop_at < 0.95 ? Status::interrupted : Status::success)
        << stop_at;  // 1.0 is not asked
    if (stop_at < 0.95) {
      EXPECT_TRUE(S.graph.nodes.empty()) << stop_at;
      EXPECT_EQ(S.removed_branches, 0u) << stop_at;
      EXPECT_EQ(later, 0u) << stop_at;
    }
  }
}

TEST(SimplifyByPersistence, RefusesAnInterruptedAugmentedGraph) {
  // A path stopped half way has half its arcs: simplifying that partial graph would report success on a graph
  // of thousands of components. Refused, naming the argument; the complete graph simplifies to one arc.
  const std::size_t n = 8192;
  std::vector<Edge> edges;
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = static_cast<double>(i);
    if (i + 1 < n) edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
  }
  const auto g = make(n, edges, {}, f);
  Reeb_graph_options stop;
  stop.progress = [](double t) { return t < 0.4; };
  const Augmented_reeb_graph partial = compute_augmented_reeb_graph(g.complex, g.f, stop);
  ASSERT_EQ(partial.status(), Status::interrupted);
  ASSERT_LT(partial.number_of_arcs(), n - 1);
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { (void)simplify_by_persistence(partial, 1.0); },
                                                 "augmented Reeb graph A is incomplete"));
  const Reeb_simplification_result S =
      simplify_by_persistence(compute_augmented_reeb_graph(g.complex, g.f), 1.0);
  EXPECT_EQ(S.status, Status::success);
  EXPECT_EQ(S.graph.nodes.size(), 2u);
  EXPECT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.components, 1u);
}

namespace {
/// A stem 0..n-1 with f = stem(i) and a tooth at every stem vertex, vertex n + i, up to stem(i) + tooth(i).
template <class Stem, class Tooth>
Complex_with_function toothed_stem(std::size_t n, Stem stem, Tooth tooth) {
  std::vector<Edge> edges;
  std::vector<double> f(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = stem(i);
    f[n + i] = f[i] + tooth(i);
    if (i + 1 < n) edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
    edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(n + i)});
  }
  return make(2 * n, edges, {}, f);
}

/// A flat stem 0..n-1 (f = i * 1e-6) with a tooth at every stem vertex, n + i, up to f(i) + 0.5, or, when
/// `falling`, up to f(i) + 0.5 - 2e-6 i with the last tooth the tallest (0.9): every tooth but the tallest
/// dies at its stem vertex, persistence about 0.5.
Complex_with_function flat_comb(std::size_t n, bool falling) {
  return toothed_stem(
      n, [](std::size_t i) { return 1e-6 * static_cast<double>(i); },
      [&](std::size_t i) {
        return falling ? (i + 1 == n ? 0.9 : 0.5 - 2e-6 * static_cast<double>(i)) : 0.5;
      });
}
}  // namespace

TEST(SimplifyByPersistence, FlatStemWithTallTeethGluesEachToothOnce) {
  // Each tooth's level is reached again only at the tallest tooth, at the far end of the stem: the path it
  // was glued onto ran along the rest of the stem, n^2 / 2 merging edges whose strips spanned O(n) levels
  // each (n 2000: 6 million triangles, 17 s and 1.4 GB; n 4000: 131 s, 5.5 GB). Each path now goes on as the
  // next tooth's at the next stem vertex: a few triangles per tooth. Rising and falling teeth (the next tooth
  // higher, or lower).
  const std::size_t n = 2000;
  for (const bool falling : {false, true}) {
    const auto g = flat_comb(n, falling);
    const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
    const Reeb_graph_persistence before = compute_reeb_graph_persistence(A.reeb_graph());
    ASSERT_EQ(count_above(before.superlevel_branches, 0.4), n - 1);
    const Reeb_simplification_result S = simplify_by_persistence(A, 1.0);
    const std::string what = falling ? "falling" : "rising";
    EXPECT_EQ(S.removed_branches, n - 1) << what;
    EXPECT_LE(S.glued_triangles, 16 * n) << what;
    // Every tooth merged into the tallest one's arc: one arc from the stem's bottom to the tallest tooth.
    ASSERT_EQ(S.graph.nodes.size(), 2u) << what;
    ASSERT_EQ(S.graph.arcs.size(), 1u) << what;
    EXPECT_EQ(S.graph.nodes[0].vertex, 0u) << what;
    EXPECT_EQ(S.graph.nodes[1].vertex, 2 * n - 1) << what;
    EXPECT_EQ(S.graph.arcs[0].vertices.size(), 2 * n - 2) << what;
    expect_partition(S.graph, 2 * n, what);
    const Reeb_graph_persistence after = compute_reeb_graph_persistence(S.graph);
    EXPECT_TRUE(after.superlevel_branches.empty() && after.sublevel_branches.empty()) << what;
    ASSERT_EQ(after.essential.size(), 1u) << what;
    EXPECT_EQ(after.essential[0].death, before.essential[0].death) << what;
  }
}

TEST(SimplifyByPersistence, NoisyFlatPathGluesEachEdgeToLogManySpineSegments) {
  // A path of n vertices with values drawn in [0, 0.001): its merging edges span about n / 3 spine levels
  // each. A fan of triangles over every spine edge they span made O(n^2) of them (n 2,500: 2.4 million, 3.2
  // s); a segment tree over the spine covers each edge's span with O(log n) segments (145,000 triangles, 0.2
  // s). The result is the same (compared with the fans on 4,000 random complexes at six deltas when the tree
  // came in): one arc from the lowest vertex to the highest, every vertex on it.
  const std::size_t n = 2500;
  std::mt19937_64 rng(5);
  std::vector<double> f(n);
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < n; ++i) f[i] = 0.001 * std::uniform_real_distribution<double>(0, 1)(rng);
  for (std::size_t i = 0; i + 1 < n; ++i)
    edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
  const auto g = make(n, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_simplification_result S = simplify_by_persistence(A, 1.0);
  EXPECT_GT(S.removed_branches, n / 4);
  EXPECT_LE(static_cast<double>(S.glued_triangles), 8 * n * std::log2(static_cast<double>(n)));
  ASSERT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  const auto lowest = static_cast<Vertex_index>(std::min_element(f.begin(), f.end()) - f.begin());
  const auto highest = static_cast<Vertex_index>(std::max_element(f.begin(), f.end()) - f.begin());
  EXPECT_EQ(S.graph.nodes[0].vertex, lowest);
  EXPECT_EQ(S.graph.nodes[1].vertex, highest);
  EXPECT_EQ(S.graph.arcs[0].vertices.size(), n - 2);
  expect_partition(S.graph, n, "noisy flat path");
  // The gluing reports progress between 0.2 and 0.3 and stops there: no graph and no later report.
  std::vector<double> seen;
  Simplification_options watching;
  watching.progress = test::recording_progress(seen);
  EXPECT_EQ(simplify_by_persistence(A, 1.0, watching).glued_triangles, S.glued_triangles);
  const auto gluing = std::find_if(seen.begin(), seen.end(), [](double t) { return t > 0.2 && t < 0.3; });
  ASSERT_NE(gluing, seen.end());
  EXPECT_GE(std::count_if(seen.begin(), seen.end(), [](double t) { return t > 0.2 && t < 0.3; }), 4);
  const double stop_at = *gluing;
  std::size_t later = 0;
  const Reeb_simplification_result stopped = simplify_by_persistence(A, 1.0, stopping_at(stop_at, later));
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_TRUE(stopped.graph.nodes.empty());
  EXPECT_EQ(stopped.glued_triangles, 0u);
  EXPECT_EQ(later, 0u);
}

TEST(SimplifyByPersistence, FanOfLoopsGluesEachLoopOnce) {
  // A bottom vertex 0 joined to every vertex of a nearly flat path 1..n (f = 0.5 + 1e-6 i): n - 1 loops of
  // height about 0.5. The arcs up from vertex 0 weigh the same in the maximum spanning forest of the loop
  // pass, which kept the oldest, so loop i's thin cycle ran back along the whole path instead of the triangle
  // 0, i - 1, i: n^2 / 2 arcs (n 2000: 2 million, strips of 6 million triangles, 22 s and 1.4 GB). Now each
  // cycle is a triangle.
  const std::size_t n = 2000;
  std::vector<Edge> edges;
  std::vector<double> f(n + 1, 0.0);
  for (std::size_t i = 1; i <= n; ++i) {
    f[i] = 0.5 + 1e-6 * static_cast<double>(i);
    edges.push_back({0, static_cast<Vertex_index>(i)});
    if (i < n) edges.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(i + 1)});
  }
  const auto g = make(n + 1, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  std::vector<std::vector<std::size_t>> cycles;
  const Reeb_graph_persistence before =
      FeatureRecon::skeleton::internal::reeb_graph_persistence(A.reeb_graph(), &cycles, 1.0);
  ASSERT_EQ(before.loops.size(), n - 1);
  std::size_t cycle_arcs = 0, longest = 0, other_bottom = 0;
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    cycle_arcs += cycles[i].size();
    longest = std::max(longest, cycles[i].size());
    if (before.loops[i].death_node != 0) ++other_bottom;  // the bottom stays vertex 0's node
  }
  EXPECT_LE(cycle_arcs, 3 * n);
  EXPECT_LE(longest, 3u);
  EXPECT_EQ(other_bottom, 0u);
  const Reeb_simplification_result S = simplify_by_persistence(A, 1.0);
  EXPECT_EQ(S.removed_loops, n - 1);
  EXPECT_LE(S.glued_triangles, 8 * n);
  // All loops merged: one arc from vertex 0 to the path's top.
  ASSERT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.nodes[1].vertex, n);
  EXPECT_EQ(S.graph.arcs[0].vertices.size(), n - 1);
  EXPECT_EQ(S.graph.loops(), 0u);
  expect_partition(S.graph, n + 1, "fan");
}

TEST(SimplifyByPersistence, ATallToothsPathGoesOnFromWhereShorterOnesStop) {
  // Rising stem 0..19 (f = i) with a tooth i + 0.5 at each vertex, but 5.5 at vertex 0 and 22 at vertex 19.
  // Each short tooth's path stops at the next stem vertex; the tall tooth's goes on as theirs, from where
  // each stopped, up to 5.5. Delta 0.6 keeps the tall tooth, 6 merges it too: one arc.
  const std::size_t n = 20;
  const auto g = toothed_stem(
      n, [](std::size_t i) { return static_cast<double>(i); },
      [&](std::size_t i) { return i == 0       ? 5.5
                                  : i + 1 == n ? 3
                                               : 0.5; });
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(g.complex, g.f);
  const Reeb_simplification_result K = simplify_by_persistence(A, 0.6);
  EXPECT_EQ(K.removed_branches, n - 2);
  ASSERT_EQ(K.graph.arcs.size(), 2u);
  EXPECT_EQ(K.graph.count(maximum), 2u);
  expect_partition(K.graph, 2 * n, "kept");
  const Reeb_simplification_result S = simplify_by_persistence(A, 6.0);
  EXPECT_EQ(S.removed_branches, n - 1);
  ASSERT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.nodes[1].vertex, 2 * n - 1);
  expect_partition(S.graph, 2 * n, "merged");
}

// Vertices of equal value are one class (compared with ==, so -0 and +0 are equal); the class's node takes
// the value of its representative, the smallest input vertex, which is also the node's vertex: the node's
// value is bit for bit values[node.vertex] (-0 here, as the input's minimum; the class's root was once its
// upper vertex, +0).
TEST(SimplifyByPersistence, AClassOfEqualValuesTakesItsRepresentativesValue) {
  Reeb_graph R;
  const std::vector<double> values{-0.0, 0.0, 1.0};
  Reeb_graph::Node a, b;
  a.vertex = 0;
  a.value = -0.0;
  a.type = minimum;
  b.vertex = 2;
  b.value = 1.0;
  b.type = maximum;
  R.nodes = {a, b};
  Reeb_graph::Arc arc;
  arc.lower = 0;
  arc.upper = 1;
  arc.vertices = {1};
  R.arcs = {arc};
  R.components = 1;
  const auto simplified = simplify_by_persistence(R, values, 0.0);
  ASSERT_EQ(simplified.graph.nodes.size(), 2u);
  for (const auto& node : simplified.graph.nodes) {
    EXPECT_EQ(std::signbit(node.value), std::signbit(values[node.vertex])) << node.vertex;
    EXPECT_EQ(node.value, values[node.vertex]);
  }
  EXPECT_EQ(simplified.graph.nodes[0].vertex, 0u);
  EXPECT_TRUE(std::signbit(simplified.graph.nodes[0].value));
}
