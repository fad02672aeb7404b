// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Documented boundaries, tie-breaks and constants that no other test pinned (found by mutation testing: each
// test below fails when the behaviour it names is changed).
#include <FeatureRecon/skeleton/embed_reeb_graph.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/map_comparison.h>
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/road_map.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "reeb_graph_builders.h"
#include "skeleton_test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
Gps_trace_graph_options tolerance_of(double degrees) {
  Gps_trace_graph_options o;
  o.heading_tolerance = degrees;
  return o;
}
}  // namespace

// "Input vertices keep their place (node, node members, or arc vertices)": a member on its node's level (as a
// first simplification leaves where f ties) stays a member of that node, it does not become a node of its
// own.
TEST(DocumentedBoundaries, SimplificationKeepsLevelMembersWithTheirNode) {
  Reeb_graph R;  // a Y: minimum v0 (f 0) -> fork v1 (f 1, member v4 at f 1) -> maxima v2 (f 2) and v3 (f 3)
  R.nodes = {reeb_node(0, 0), reeb_node(1, 1, {4}), reeb_node(2, 2), reeb_node(3, 3)};
  R.arcs = {{0, 1, {}}, {1, 2, {}}, {1, 3, {}}};
  FeatureRecon::skeleton::internal::refresh_node_types(R);
  const std::vector<double> values{0, 1, 2, 3, 1};
  const Reeb_simplification_result S = simplify_by_persistence(R, values, 0.0);
  EXPECT_EQ(S.graph.nodes.size(), 4u);
  EXPECT_EQ(S.graph.arcs.size(), 3u);
  EXPECT_EQ(S.graph.components, 1u);
  const auto fork =
      std::find_if(S.graph.nodes.begin(), S.graph.nodes.end(), [](const auto& n) { return n.vertex == 1; });
  ASSERT_NE(fork, S.graph.nodes.end());
  EXPECT_EQ(fork->members, (std::vector<Vertex_index>{4}));
  EXPECT_TRUE(fork->type & up_fork);
}

// repair_reeb_graph(): when the two ends of an isolated segment are each other's closest free end, "the
// segment is left as it is ... and neither end joins anything farther".
TEST(DocumentedBoundaries, RepairAnIsolatedSegmentsEndsJoinNothingFarther) {
  Planar_points pts;  // segment 0-1 (x 0 and 1), segment 2-3 (x 3 and 13); f = x
  for (const double x : {0.0, 1.0, 3.0, 13.0}) pts.p.push_back({x, 0.0});
  const auto c = make(4, {{0, 1}, {2, 3}}, {}, {0, 1, 3, 13});
  const Reeb_graph R = reeb_graph_of(c);
  // Pairs within 2.5: (0, 1) at 1, the ends of one segment; (1, 2) at 2. Vertex 1 is no longer free.
  const Reeb_repair_result fixed = repair_reeb_graph(R, 2.5, pts);
  EXPECT_EQ(fixed.joined, 0u);
  EXPECT_EQ(fixed.graph.arcs.size(), R.arcs.size());
  EXPECT_EQ(fixed.graph.components, 2u);
}

// connect_dead_ends(): "the closest such point (ties: smallest vertex index)".
TEST(DocumentedBoundaries, ConnectDeadEndsBreaksDistanceTiesBySmallestVertex) {
  Planar_points pts;  // street 0..4 at (i, 0), f = i; dead end 5 at (1.5, 1) on the segment 5-6 going up
  std::vector<Edge> edges;
  for (int i = 0; i <= 4; ++i) {
    pts.p.push_back({double(i), 0.0});
    if (i > 0) edges.push_back({Vertex_index(i - 1), Vertex_index(i)});
  }
  pts.p.push_back({1.5, 1.0});
  pts.p.push_back({1.5, 10.0});
  edges.push_back({5, 6});
  const std::vector<double> f{0, 1, 2, 3, 4, 5, 6};
  const Reeb_graph R = reeb_graph_of(make(7, edges, {}, f));
  ASSERT_EQ(pts(5, 1), pts(5, 2));  // vertices 1 and 2 are equally close to the dead end
  const Reeb_dead_end_result r = connect_dead_ends(R, f, 1.2, pts);
  ASSERT_EQ(r.connected, 1u);
  auto has_node = [&](Vertex_index v) {
    return std::any_of(r.graph.nodes.begin(), r.graph.nodes.end(),
                       [v](const auto& n) { return n.vertex == v; });
  };
  EXPECT_TRUE(has_node(1));
  EXPECT_FALSE(has_node(2));
}

// Embedding_options::level_width: "Automatic (default): 1/64 of the range of f over the graph".
TEST(DocumentedBoundaries, AutomaticLevelWidthIsOneSixtyFourthOfTheRange) {
  // one arc from f 0 to f 64 with a point at every f 0.5, 1.5, ..., 63.5: one per bin of width 1
  Reeb_graph G;
  G.nodes = {reeb_node(0, 0), reeb_node(1, 64)};
  Reeb_graph::Arc arc;
  arc.lower = 0;
  arc.upper = 1;
  std::vector<double> values{0, 64};
  std::vector<std::array<double, 3>> positions{{0, 0, 0}, {64, 0, 0}};
  for (int i = 0; i < 64; ++i) {
    arc.vertices.push_back(Vertex_index(2 + i));
    values.push_back(i + 0.5);
    positions.push_back({i + 0.5, 0, 0});
  }
  G.arcs.push_back(arc);
  FeatureRecon::skeleton::internal::refresh_node_types(G);
  const Reeb_graph_embedding E = embed_reeb_graph(G, positions, values, 3);
  ASSERT_EQ(E.arc_polylines.size(), 1u);
  EXPECT_EQ(E.arc_polylines[0].size(), 2u + 64u);  // the two nodes and 64 level-set pieces
}

// project_to_3d(): "Deterministic sign: the largest component of each axis is positive". Points spread along
// three orthonormal directions u0, u1, u2 of R^4 (variances 100, 9, 1, nothing along the fourth): coordinate
// c of a point is its coefficient along u_c, with the sign that makes u_c's largest component positive. The
// basis is tried with its coordinates shifted cyclically (the solver returns other signs for some).
TEST(DocumentedBoundaries, ProjectionAxesHaveTheDocumentedSigns) {
  const double basis[3][4] = {{0.36, 0.48, -0.8, 0}, {0.8, -0.6, 0, 0}, {-0.48, -0.64, -0.6, 0}};
  // Coefficients: orthogonal, centred columns (so the covariance has exactly these axes).
  const double a[8][3] = {{10, 3, 1},  {10, -3, -1}, {-10, 3, -1}, {-10, -3, 1},
                          {10, 3, -1}, {10, -3, 1},  {-10, 3, 1},  {-10, -3, -1}};
  for (int shift = 0; shift < 4; ++shift) {
    double u[3][4];
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 4; ++k) u[c][(k + shift) % 4] = basis[c][k];
    auto sign = [](const double* v) {
      int k = 0;
      for (int i = 1; i < 4; ++i)
        if (std::fabs(v[i]) > std::fabs(v[k])) k = i;
      return v[k] < 0 ? -1.0 : 1.0;
    };
    Point_matrix m;
    m.rows = 8;
    m.dimension = 4;
    for (const auto& row : a)
      for (int k = 0; k < 4; ++k) m.data.push_back(row[0] * u[0][k] + row[1] * u[1][k] + row[2] * u[2][k]);
    const std::vector<std::array<double, 3>> p = project_to_3d(m);
    for (int i = 0; i < 8; ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(p[i][c], sign(u[c]) * a[i][c], 1e-9)
            << "shift " << shift << " point " << i << " axis " << c;
  }
}

// merge_close_branch_nodes(): "A merged node takes the value of its lowest node (ties: the smaller index),
// whose members come first".
TEST(DocumentedBoundaries, MergedBranchNodesOfEqualValueTakeTheSmallerIndexFirst) {
  Point_matrix coordinates;  // 0, 1: the two forks 0.1 apart; 2..5: the leaves
  coordinates.rows = 6;
  coordinates.dimension = 2;
  coordinates.data = {0, 0, 0.1, 0, -1, -1, -1, 1, 1.1, -1, 1.1, 1};
  Skeleton_graph g(6);
  const double value[6] = {5, 5, 0, 0, 10, 10};
  for (std::size_t v = 0; v < 6; ++v) {
    g[v].value = value[v];
    g[v].members = {Vertex_index(v)};
    g[v].position = {coordinates.row(v)[0], coordinates.row(v)[1], 0};
  }
  auto arc = [&](std::size_t a, std::size_t b) {
    add_edge(a, b, Skeleton_arc{{g[a].position, g[b].position}, {}, {}, a, b}, g);
  };
  arc(0, 1);
  arc(2, 0);
  arc(3, 0);
  arc(1, 4);
  arc(1, 5);
  const Branch_node_merge_result r = merge_close_branch_nodes(g, coordinates, 0.5);
  ASSERT_EQ(r.merged, 1u);
  ASSERT_EQ(num_vertices(r.graph), 5u);
  const Skeleton_node& merged = r.graph[0];
  EXPECT_EQ(merged.value, 5);
  ASSERT_EQ(merged.members.size(), 2u);
  EXPECT_EQ(merged.members.front(), 0u);
}

// The greedy matching of the map comparison: "at most match_distance apart", bearings that "differ by less
// than" the limit, and "proposals are accepted by increasing distance (ties: smaller h)".
TEST(DocumentedBoundaries, GreedyMatchingBoundariesAndTies) {
  const Map_comparison_options o;                                              // 15 m, 45 degrees
  EXPECT_EQ(match_map_samples({{{0, 0}, 0}}, {{{15, 0}, 0}}, o).matched, 1u);  // exactly 15 m apart
  EXPECT_EQ(match_map_samples({{{0, 0}, 0}}, {{{16, 0}, 0}}, o).matched, 0u);
  EXPECT_EQ(match_map_samples({{{0, 0}, 0}}, {{{1, 0}, 45}}, o).matched, 0u);  // exactly 45 degrees: not less
  EXPECT_EQ(match_map_samples({{{0, 0}, 0}}, {{{1, 0}, 44}}, o).matched, 1u);
  // Two ground-truth samples 1 m on either side of one reconstruction sample: the smaller index takes it.
  const Map_sample_matching M = match_map_samples({{{-1, 0}, 0}, {{1, 0}, 0}}, {{{0, 0}, 0}}, o);
  EXPECT_EQ(M.matched, 1u);
  EXPECT_EQ(M.ground_truth_partner, (std::vector<std::int64_t>{0, -1}));
}

// build_gps_trace_graph(): Rips edges "between samples whose headings differ by at most heading_tolerance".
TEST(DocumentedBoundaries, TraceGraphHeadingToleranceIsInclusive) {
  Gps_trace_sample S;
  S.points.rows = 2;
  S.points.dimension = 2;
  S.points.data = {0, 0, 1, 0};
  S.headings = {0, 30};
  S.directed = true;
  EXPECT_EQ(build_gps_trace_graph(S, 5.0, tolerance_of(30)).edges.size(), 1u);
  EXPECT_EQ(build_gps_trace_graph(S, 5.0, tolerance_of(29.5)).edges.size(), 0u);
}

// explain_unmatched_samples(): taken = an aligned sample "within the threshold"; offset = the nearest aligned
// one "between 1 and 2 thresholds away"; crossing = samples within 2 thresholds, none aligned; absent =
// nothing there.
TEST(DocumentedBoundaries, UnmatchedSampleClassesAtTheirBoundaries) {
  // every sample unmatched; distances exact: 15 (= threshold) and 27 (1.8 thresholds)
  Map_comparison_result r;
  r.ground_truth_sample_list = {{{0, 0}, 0}, {{0, 100}, 0}, {{0, 200}, 0}, {{0, 500}, 0}};
  r.reconstruction_sample_list = {{{15, 0}, 0}, {{27, 100}, 0}, {{10, 200}, 90}};
  r.ground_truth_samples = 4;
  r.reconstruction_samples = 3;
  r.ground_truth_partner.assign(4, -1);
  r.reconstruction_partner.assign(3, -1);
  const Unmatched_samples_breakdown b = explain_unmatched_samples(r);
  EXPECT_EQ(b.missed.taken, 1u);
  EXPECT_EQ(b.missed.offset, 1u);
  EXPECT_EQ(b.missed.crossing, 1u);
  EXPECT_EQ(b.missed.absent, 1u);
  EXPECT_EQ(b.spurious.taken, 1u);
  EXPECT_EQ(b.spurious.offset, 1u);
  EXPECT_EQ(b.spurious.crossing, 1u);
  EXPECT_EQ(b.spurious.absent, 0u);
}

// The documented constants of the road-map option sets.
TEST(DocumentedBoundaries, RoadMapOptionSetsHaveTheDocumentedValues) {
  const Gps_trace_options t = road_map_trace_options();  // heading tolerance 30, 5 % and 30 % density rules
  EXPECT_EQ(t.heading_tolerance, 30);
  EXPECT_EQ(t.min_relative_density, 0.05);
  EXPECT_EQ(t.min_lateral_density, 0.3);
  const Embedding_options e = road_map_embedding_options();  // 2 Laplacian rounds
  EXPECT_EQ(e.smoothing, Embedding_options::Smoothing::laplacian);
  EXPECT_EQ(e.smoothing_iterations, 2u);
  const Embedding_options m = road_merge_embedding_options();  // 20 Laplacian rounds
  EXPECT_EQ(m.smoothing, Embedding_options::Smoothing::laplacian);
  EXPECT_EQ(m.smoothing_iterations, 20u);
}

// Embedding_options::smoothing_iterations rounds are made (a Laplacian round at weight 0.5 moves a point
// halfway to its neighbours' mean), and an automatic max_gap is "twice the median edge length of the graph",
// reported back.
TEST(DocumentedBoundaries, EmbeddingSmoothingRoundsAndAutomaticMaxGap) {
  Reeb_graph G;  // one arc from vertex 0 to vertex 3 through vertex 1; vertex 2 is only in the graph
  G.nodes = {reeb_node(0, 0), reeb_node(3, 3)};
  G.arcs.push_back({0, 1, {1}});
  FeatureRecon::skeleton::internal::refresh_node_types(G);
  const std::vector<std::array<double, 3>> positions{{0, 0, 0}, {1, 1, 0}, {3, 0, 0}, {7, 0, 0}};
  const std::vector<double> values{0, 1, 2, 3};
  Embedding_options o;
  o.smoothing = Embedding_options::Smoothing::laplacian;
  o.smoothing_iterations = 1;
  o.level_width = 100;  // one piece (no graph: straight between pieces, max_gap unused)
  const Reeb_graph_embedding E = embed_reeb_graph(G, positions, values, 2, o);
  ASSERT_EQ(E.arc_polylines[0].size(), 3u);
  EXPECT_EQ(E.arc_polylines[0][1][0], 2.25);  // 0.5 * (1, 1) + 0.5 * mean of (0, 0) and (7, 0)
  EXPECT_EQ(E.arc_polylines[0][1][1], 0.5);
  // Edges of lengths sqrt(2), sqrt(5) and 4: median sqrt(5), max_gap 2 sqrt(5).
  Proximity_graph graph;
  graph.number_of_vertices = 4;
  graph.edges = {{0, 1}, {1, 2}, {2, 3}};
  graph.edge_lengths = {std::sqrt(2.0), std::sqrt(5.0), 4};
  o.max_gap = FeatureRecon::automatic;
  const Reeb_graph_embedding F = embed_reeb_graph(G, graph, positions, values, 2, o);
  EXPECT_DOUBLE_EQ(F.max_gap, 2 * std::sqrt(5.0));
}

// repair_reeb_graph(): "each node at most once": of three dead ends within the distance of one another only
// the closest pair is joined.
TEST(DocumentedBoundaries, RepairJoinsEachNodeAtMostOnce) {
  Planar_points pts;  // segments 0-1, 2-3, 4-5 whose ends 1, 3, 5 lie close together; f = index
  pts.p = {{-10, 0}, {0, 0}, {10, 0}, {1, 0}, {0, 10}, {0, 1.5}};
  const Reeb_graph R = reeb_graph_of(make(6, {{0, 1}, {2, 3}, {4, 5}}, {}, {0, 1, 2, 3, 4, 5}));
  const Reeb_repair_result fixed = repair_reeb_graph(R, 2.0, pts);
  ASSERT_EQ(fixed.joined, 1u);
  const auto& a = fixed.graph.arcs.back();
  EXPECT_EQ(fixed.graph.nodes[a.lower].vertex, 1u);
  EXPECT_EQ(fixed.graph.nodes[a.upper].vertex, 3u);
  EXPECT_EQ(fixed.graph.components, 2u);
}

// extract_reeb_skeleton() with a repair distance: repair, connect_dead_ends, "then simplify again", and
// prune_height; a T junction whose stem stops 1.5 short of the street, and a short far-away piece.
TEST(DocumentedBoundaries, PipelineConnectsDeadEndsSimplifiesAgainAndPrunes) {
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i <= 40; ++i) pts.push_back({0.5 * i, 0.0});   // the street, x 0..20
  for (int i = 3; i <= 20; ++i) pts.push_back({10.0, 0.5 * i});  // the stem, y 1.5..10
  pts.push_back({50.0, 50.0});                                   // a piece of height 0.5
  pts.push_back({50.5, 50.0});
  Skeleton_options o;
  o.repair_distance = 2.0;
  o.prune_height = 1.0;
  const Reeb_skeleton s = extract_reeb_skeleton(pts, 0.6, o);
  EXPECT_EQ(s.repaired, 0u);
  EXPECT_EQ(s.connected_dead_ends, 1u);
  EXPECT_EQ(s.pruned_components, 1u);
  EXPECT_EQ(s.pruned_points, (std::vector<Vertex_index>{59, 60}));
  std::vector<int> comp(num_vertices(s.graph));
  EXPECT_EQ(boost::connected_components(s.graph, comp.data()), 1);
  std::size_t forks = 0;
  for (auto v : boost::make_iterator_range(vertices(s.graph))) {
    EXPECT_NE(s.graph[v].type, regular) << "node " << v << " of degree " << degree(v, s.graph);  // absorbed
    if (degree(v, s.graph) == 3) ++forks;
  }
  EXPECT_EQ(forks, 1u);
  EXPECT_EQ(num_vertices(s.graph), 4u);
  EXPECT_EQ(num_edges(s.graph), 3u);
}

// Loop persistence (doc/skeleton.md): "an arc that closes a cycle replaces the lightest arc on it when it is
// heavier" (strictly; of two arcs with the same lower node the later in the sweep weighs more, so it replaces
// the earlier, reeb_graph_persistence.h). Which thin cycle a
// loop gets then decides the simplification where several loops share a bottom: here the loop that survives
// delta 3 keeps its bottom at the up-fork of value 2 (replacing on ties moved it to value 1). A pinned
// regression result.
TEST(DocumentedBoundaries, ThinCyclesOnTiedBottomsArePinned) {
  const auto c = make(
      8, {{0, 1}, {1, 2}, {0, 3}, {1, 4}, {4, 5}, {0, 6}, {0, 7}, {2, 6}, {5, 7}, {1, 6}, {3, 4}, {0, 5}}, {},
      {1, 0, 2, 5, 3, 0, 2, 3});
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  const Reeb_simplification_result S = simplify_by_persistence(A, 3.0);
  EXPECT_EQ(S.removed_branches, 3u);
  EXPECT_EQ(S.removed_loops, 4u);
  ASSERT_EQ(S.graph.nodes.size(), 3u);
  EXPECT_EQ(S.graph.nodes[1].vertex, 2u);
  EXPECT_EQ(S.graph.nodes[1].value, 2);
  EXPECT_EQ(S.graph.nodes[1].members, (std::vector<Vertex_index>{6}));
  EXPECT_EQ(S.graph.loops(), 1u);
}
