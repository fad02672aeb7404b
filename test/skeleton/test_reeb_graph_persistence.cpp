// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// compute_reeb_graph_persistence() against GUDHI's extended persistence of the complex (lower-star
// filtration), design notes 1.2: sublevel branches = Ord0(K), superlevel branches = Rel1(K), loops =
// Ext-1(K), essential = Ext+0(K). Values are the simulation-of-simplicity ranks, so the comparison is exact.
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/reeb_graph_persistence.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gudhi_extended_persistence.h"
#include "reeb_graph_builders.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

std::vector<Point_pair> as_pairs(const std::vector<Reeb_persistence_pair>& v) {
  std::vector<Point_pair> out;
  for (const auto& p : v) out.emplace_back(std::lround(p.birth), std::lround(p.death));
  std::sort(out.begin(), out.end());
  return out;
}

/// Points compared so far (the tests assert that the comparisons were not vacuous).
std::size_t compared_points = 0, compared_loops = 0;

/// Compares the Reeb graph persistence of (K, f) with GUDHI's diagrams of K, in rank space.
void expect_matches_gudhi(const Simplicial_complex_2& K, const std::vector<double>& f,
                          const std::string& what) {
  const Augmented_reeb_graph A0 = compute_augmented_reeb_graph(K, f);
  std::vector<double> rank_f(K.number_of_vertices);
  std::vector<long> rank_l(K.number_of_vertices);
  for (std::size_t v = 0; v < K.number_of_vertices; ++v)
    rank_l[v] = static_cast<long>(rank_f[v] = A0.rank()[v]);
  const Reeb_graph R = compute_augmented_reeb_graph(K, rank_f).reeb_graph();
  const Reeb_graph_persistence P = compute_reeb_graph_persistence(R);
  std::vector<std::vector<int>> simplices;
  for (const Edge& e : K.edges) simplices.push_back({int(e[0]), int(e[1])});
  for (const Triangle& t : K.triangles) simplices.push_back({int(t[0]), int(t[1]), int(t[2])});
  const Extended_diagrams d = gudhi_extended_persistence(K.number_of_vertices, simplices, rank_l);
  EXPECT_EQ(as_pairs(P.sublevel_branches), d.ord[0]) << what << ": sublevel branches vs Ord0";
  EXPECT_EQ(as_pairs(P.superlevel_branches), d.rel[1]) << what << ": superlevel branches vs Rel1";
  EXPECT_EQ(as_pairs(P.loops), d.ext_minus[1]) << what << ": loops vs Ext-1";
  std::vector<Point_pair> essential = as_pairs(P.essential);
  essential.erase(std::remove_if(essential.begin(), essential.end(),
                                 [](const Point_pair& p) { return p.first == p.second; }),
                  essential.end());
  EXPECT_EQ(essential, d.ext_plus[0]) << what << ": essential vs Ext+0";
  EXPECT_EQ(P.loops.size(), R.loops()) << what;
  compared_points += d.ord[0].size() + d.rel[1].size() + d.ext_minus[1].size();
  compared_loops += d.ext_minus[1].size();
  for (const auto& p : P.sublevel_branches) EXPECT_LT(p.birth, p.death);
  for (const auto& p : P.superlevel_branches) EXPECT_GT(p.birth, p.death);
  for (const auto& p : P.loops) EXPECT_GT(p.birth, p.death);
}

}  // namespace

TEST(ReebGraphPersistence, MatchesGudhiOnRandomRipsComplexes) {
  const std::vector<std::pair<std::string, std::vector<std::array<double, 4>>>> shapes{
      {"figure-eight", figure_eight_segments()}, {"tree", tree_segments()}, {"grid", grid_segments()}};
  std::mt19937 rng(77);
  for (int trial = 0; trial < 32; ++trial) {
    const auto& shape = shapes[trial % 3];
    Sampled_graph s;
    double radius = 0.7;
    if (trial % 4 == 3) {
      // A uniform cloud in a square near its connectivity radius: full of small holes, i.e. loops.
      std::uniform_real_distribution<double> u(0, 10);
      for (int i = 0; i < 300; ++i) s.points.push_back({u(rng), u(rng)});
      radius = 0.9;
    } else {
      s = sample_segments(shape.second, 0.35, 0.12, 900 + trial);
    }
    const Simplicial_complex_2 K = build_rips_complex_2(s.points, radius);
    std::vector<double> f;
    switch (trial % 3) {
      case 0:
        f = compute_geodesic_function(K).values;
        break;
      case 1: {
        const double a = std::uniform_real_distribution<double>(0, 6.3)(rng);
        for (const auto& p : s.points) f.push_back(std::cos(a) * p[0] + std::sin(a) * p[1]);
        break;
      }
      default:  // a rough random function: many branches and loops
        for (std::size_t i = 0; i < s.points.size(); ++i)
          f.push_back(std::uniform_real_distribution<double>()(rng));
    }
    expect_matches_gudhi(
        K, f, (trial % 4 == 3 ? std::string("cloud") : shape.first) + " trial " + std::to_string(trial));
  }
  // The comparisons covered many branches and loops (the random functions make hundreds).
  EXPECT_GT(compared_points, 200u) << compared_loops << " loops";
  EXPECT_GT(compared_loops, 100u);
  std::printf("compared %zu diagram points, %zu loops\n", compared_points, compared_loops);
}

TEST(ReebGraphPersistence, MatchesGudhiOnStreetGridsWithManyLoops) {
  // Street grids (the 1-skeleton of an m x m grid, no triangles) with random functions and with ties: every
  // block is a loop, and the loops' thin cycles cross each other. The loop pass keeps a maximum spanning
  // forest over the sweep; this checks its swaps on hundreds of loops at once.
  std::mt19937 rng(17);
  const std::size_t before = compared_loops;
  for (const int m : {12, 25}) {
    for (const bool ties : {false, true}) {
      std::vector<Edge> edges;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          const auto k = static_cast<Vertex_index>(i * m + j);
          if (i + 1 < m) edges.push_back({k, static_cast<Vertex_index>(k + m)});
          if (j + 1 < m) edges.push_back({k, static_cast<Vertex_index>(k + 1)});
        }
      std::vector<double> f(static_cast<std::size_t>(m * m));
      for (double& x : f)
        x = ties ? std::uniform_int_distribution<int>(0, 5)(rng)
                 : std::uniform_real_distribution<double>()(rng);
      const auto c = make(f.size(), edges, {}, f);
      expect_matches_gudhi(c.complex, c.f, "grid " + std::to_string(m) + (ties ? " with ties" : ""));
    }
  }
  EXPECT_EQ(compared_loops - before, 2u * (11 * 11 + 24 * 24));  // every block of each grid
}

TEST(ReebGraphPersistence, MatchesGudhiOnTorusCylinderAndNonManifoldMix) {
  const auto t = upright_torus(18, 9);
  expect_matches_gudhi(t.complex, t.f, "torus");
  const auto c = cylinder(12, 5);
  expect_matches_gudhi(c.complex, c.f, "cylinder");
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> f(16);
    for (double& x : f) x = std::uniform_int_distribution<int>(0, 4)(rng);  // many ties
    const auto m = make(16, {{4, 5}, {5, 6}, {14, 15}, {2, 11}},
                        {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {6, 7, 8}, {6, 9, 10}, {12, 13, 14}}, f);
    expect_matches_gudhi(m.complex, m.f, "mix trial " + std::to_string(trial));
  }
}

TEST(ReebGraphPersistence, HandExamples) {
  // Y: stem 0-1-2 up to the fork 2, arms to maxima 4 (f = 4) and 6 (f = 5): the lower maximum's branch
  // dies at the fork: superlevel pair (4, 2).
  const auto y = make(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {2, 5}, {5, 6}}, {}, {0, 1, 2, 3, 4, 3.5, 5});
  const Reeb_graph_persistence Py = compute_reeb_graph_persistence(reeb_graph_of(y));
  ASSERT_EQ(Py.superlevel_branches.size(), 1u);
  EXPECT_EQ(Py.superlevel_branches[0].birth, 4.0);
  EXPECT_EQ(Py.superlevel_branches[0].death, 2.0);
  EXPECT_TRUE(Py.sublevel_branches.empty());
  EXPECT_TRUE(Py.loops.empty());
  ASSERT_EQ(Py.essential.size(), 1u);
  EXPECT_EQ(Py.essential[0].birth, 0.0);
  EXPECT_EQ(Py.essential[0].death, 5.0);
  // Theta graph: bottom 0 (f = 0), three paths through 1, 2, 3 (f = 1, 2, 3) to top 4 (f = 10): two loops,
  // both born at the top; the thinnest pairs of paths have bottoms... both at node 0, the only up-fork.
  const auto theta = make(5, {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {2, 4}, {3, 4}}, {}, {0, 1, 2, 3, 10});
  const Reeb_graph_persistence Pt = compute_reeb_graph_persistence(reeb_graph_of(theta));
  ASSERT_EQ(Pt.loops.size(), 2u);
  for (const auto& p : Pt.loops) {
    EXPECT_EQ(p.birth, 10.0);
    EXPECT_EQ(p.death, 0.0);
    EXPECT_EQ(p.persistence(), 10.0);
  }
  // Two stacked loops: the thin upper loop (bottom 5, top 6) and the tall lower one (bottom 0, top 4).
  const auto eight =
      make(7, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}, {4, 5}, {4, 6}, {5, 6}}, {}, {0, 1, 2, 4, 5, 5.5, 6});
  const Reeb_graph_persistence Pe = compute_reeb_graph_persistence(reeb_graph_of(eight));
  ASSERT_EQ(Pe.loops.size(), 2u);
  EXPECT_DOUBLE_EQ(Pe.loops[0].persistence(), 4.0);  // born at 3 (f = 4), dies at 0
  EXPECT_DOUBLE_EQ(Pe.loops[1].persistence(), 1.0);  // born at 6, dies at 4 (f = 5)
}

TEST(ReebGraphPersistence, TiedValuesGivePairsOnTheDiagonal) {
  // A constant f on a path 0-2-1 with a square 2-3-5-4 at vertex 2: ties are broken by vertex index, so the
  // Reeb graph still has its minima, forks and loop, and their pairs lie on the diagonal (persistence 0). The
  // same pairs as with values ranked by (f, index), only flattened.
  const auto flat = make(6, {{0, 2}, {1, 2}, {2, 3}, {2, 4}, {3, 5}, {4, 5}}, {}, {0, 0, 0, 0, 0, 0});
  const Reeb_graph_persistence P = compute_reeb_graph_persistence(reeb_graph_of(flat));
  const auto ranked = make(6, {{0, 2}, {1, 2}, {2, 3}, {2, 4}, {3, 5}, {4, 5}}, {}, {0, 1, 2, 3, 4, 5});
  const Reeb_graph_persistence Q = compute_reeb_graph_persistence(reeb_graph_of(ranked));
  ASSERT_EQ(P.loops.size(), 1u);
  ASSERT_EQ(P.sublevel_branches.size(), Q.sublevel_branches.size());
  ASSERT_EQ(P.superlevel_branches.size(), Q.superlevel_branches.size());
  ASSERT_EQ(P.loops.size(), Q.loops.size());
  for (const auto* list : {&P.sublevel_branches, &P.superlevel_branches, &P.loops, &P.essential})
    for (const auto& p : *list) {
      EXPECT_EQ(p.birth, 0.0);
      EXPECT_EQ(p.death, 0.0);
      EXPECT_EQ(p.persistence(), 0.0);
    }
  EXPECT_EQ(P.sublevel_branches.size(), 1u);  // minima 0 and 1 meet at the down-fork 2
  EXPECT_EQ(P.loops[0].birth_node, Q.loops[0].birth_node);
  EXPECT_EQ(P.loops[0].death_node, Q.loops[0].death_node);
}

TEST(ReebGraphPersistence, EmptyAndBadInput) {
  const Reeb_graph_persistence P = compute_reeb_graph_persistence(Reeb_graph{});
  EXPECT_TRUE(P.loops.empty() && P.essential.empty() && P.sublevel_branches.empty());
  Reeb_graph bad;
  bad.nodes = {{0, 2.0, minimum, {}}, {1, 1.0, maximum, {}}};  // not sorted by value
  EXPECT_THROW(compute_reeb_graph_persistence(bad), std::invalid_argument);
  Reeb_graph down;
  down.nodes = {{0, 1.0, minimum, {}}, {1, 2.0, maximum, {}}};
  down.arcs = {{1, 0, {}}};  // an arc going down
  EXPECT_THROW(compute_reeb_graph_persistence(down), std::invalid_argument);
  Reeb_graph nan_node;  // one node: no order to break, so the value itself is checked
  nan_node.nodes = {{0, std::nan(""), minimum | maximum, {}}};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { compute_reeb_graph_persistence(nan_node); },
                                                 "node 0 has value nan"));
}

TEST(ReebGraphPersistence, ForkOfHighDegree) {
  // Two nodes joined by k parallel arcs: k - 1 loops, each of persistence 1. The fork's earlier arcs are
  // marked once per fork (a copy per loop took O(k^2) memory: 3 GB at k = 20000).
  const std::size_t k = 5000;
  Reeb_graph R;
  R.nodes.resize(2);
  R.nodes[0].vertex = 0;
  R.nodes[0].value = 0;
  R.nodes[0].type = minimum | up_fork;
  R.nodes[1].vertex = 1;
  R.nodes[1].value = 1;
  R.nodes[1].type = maximum | down_fork;
  R.arcs.resize(k);
  for (auto& a : R.arcs) a.upper = 1;
  R.components = 1;
  const Reeb_graph_persistence P = compute_reeb_graph_persistence(R);
  ASSERT_EQ(P.loops.size(), k - 1);
  for (const auto& p : P.loops) {
    EXPECT_EQ(p.birth_node, 1u);
    EXPECT_EQ(p.death_node, 0u);
    EXPECT_EQ(p.persistence(), 1.0);
  }
  EXPECT_TRUE(P.sublevel_branches.empty());
  EXPECT_TRUE(P.superlevel_branches.empty());
}

TEST(ReebGraphPersistence, ReportsProgressAndAStopLeavesEmptyDiagrams) {
  // Two combs of 3,000 spine nodes and one of 5: about 12,000 nodes, so each of the three sweeps reports
  // several times (every 1,024 nodes).
  const Reeb_graph R = reeb_combs({3000, 3000, 5});
  const Reeb_graph_persistence full = compute_reeb_graph_persistence(R);
  ASSERT_EQ(full.status, Status::success);
  // Spurs at the even spine nodes 2..2998 (1,499 per long comb) and at node 2 of the short one; loops at the
  // odd nodes 1..2997 and 1, 3; one minimum per comb.
  EXPECT_EQ(full.superlevel_branches.size(), 2 * 1499u + 1);
  EXPECT_EQ(full.loops.size(), 2 * 1499u + 2);
  EXPECT_EQ(full.sublevel_branches.size(), 0u);
  EXPECT_EQ(full.essential.size(), 3u);
  std::vector<double> seen;
  Reeb_persistence_options o;
  o.progress = recording_progress(seen);
  const Reeb_graph_persistence P = compute_reeb_graph_persistence(R, o);
  ASSERT_EQ(P.status, Status::success);
  auto same = [](const std::vector<Reeb_persistence_pair>& a, const std::vector<Reeb_persistence_pair>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].birth_node != b[i].birth_node || a[i].death_node != b[i].death_node) return false;
    return true;
  };
  EXPECT_TRUE(same(P.superlevel_branches, full.superlevel_branches));
  EXPECT_TRUE(same(P.loops, full.loops));
  EXPECT_TRUE(same(P.essential, full.essential));
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.1);
  EXPECT_EQ(seen.back(), 1.0);
  auto reports = [&seen](double from, double to) {
    return std::count_if(seen.begin(), seen.end(), [from, to](double t) { return t > from && t < to; });
  };
  EXPECT_GE(reports(0.1, 0.3), 10);  // the upward sweep
  EXPECT_GE(reports(0.3, 0.5), 10);  // the downward sweep
  EXPECT_GE(reports(0.5, 1.0), 10);  // the loops
  // A stop at any report but the last: interrupted, every diagram empty, no report after the refusal.
  for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
    std::size_t calls = 0;
    o.progress = [&calls, i](double) { return calls++ != i; };
    const Reeb_graph_persistence S = compute_reeb_graph_persistence(R, o);
    EXPECT_EQ(S.status, Status::interrupted) << "stopped at " << seen[i];
    EXPECT_TRUE(S.superlevel_branches.empty() && S.sublevel_branches.empty() && S.loops.empty() &&
                S.essential.empty())
        << "stopped at " << seen[i];
    EXPECT_EQ(calls, i + 1) << "stopped at " << seen[i];
  }
  // The empty graph reports its start and its end.
  seen.clear();
  o.progress = recording_progress(seen);
  EXPECT_EQ(compute_reeb_graph_persistence(Reeb_graph{}, o).status, Status::success);
  EXPECT_EQ(seen, (std::vector<double>{0.1, 1.0}));
}
