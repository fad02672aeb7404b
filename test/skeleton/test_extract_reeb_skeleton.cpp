// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
std::size_t loops_of(const Skeleton_graph& g) {
  std::vector<int> comp(num_vertices(g));
  const std::size_t c =
      num_vertices(g) == 0 ? 0 : static_cast<std::size_t>(boost::connected_components(g, comp.data()));
  return num_edges(g) + c - num_vertices(g);
}
void expect_members_partition(const Skeleton_graph& g, std::size_t n) {
  std::vector<int> seen(n, 0);
  for (auto v : boost::make_iterator_range(vertices(g)))
    for (Vertex_index m : g[v].members) ++seen[m];
  for (auto e : boost::make_iterator_range(edges(g)))
    for (Vertex_index m : g[e].members) ++seen[m];
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1) << "point " << i;
}
/// n points evenly on the circle of radius 10 about the origin.
Point_matrix circle_points(int n) {
  Point_matrix m;
  m.dimension = 2;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    m.data.insert(m.data.end(), {10 * std::cos(a), 10 * std::sin(a)});
  }
  m.rows = static_cast<std::size_t>(n);
  return m;
}
}  // namespace

TEST(ExtractReebSkeleton, FigureEightAndTree) {
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton s = extract_reeb_skeleton(eight.points, 0.7, o);
  EXPECT_EQ(s.status, Status::success);
  EXPECT_EQ(loops_of(s.graph), 2u);
  EXPECT_EQ(s.dimension, 2u);
  EXPECT_GT(s.rips_triangles, 0u);
  expect_members_partition(s.graph, eight.points.size());
  // Every arc's polyline ends at its nodes.
  for (auto e : boost::make_iterator_range(edges(s.graph))) {
    const auto& line = s.graph[e].polyline;
    ASSERT_GE(line.size(), 2u);
    const auto a = s.graph[source(e, s.graph)].position, b = s.graph[target(e, s.graph)].position;
    EXPECT_TRUE((line.front() == a && line.back() == b) || (line.front() == b && line.back() == a));
    EXPECT_LE(s.graph[source(e, s.graph)].value, s.graph[target(e, s.graph)].value);  // from lower to upper
  }
  // Every node sits at the centroid of its points, the one where the two circles touch too (its two forks
  // merged into one node of degree 4).
  std::size_t degree_four = 0;
  for (auto v : boost::make_iterator_range(vertices(s.graph))) {
    double c[2] = {0, 0};
    for (const Vertex_index p : s.graph[v].members)
      for (int k = 0; k < 2; ++k) c[k] += eight.points[p][k] / static_cast<double>(s.graph[v].members.size());
    EXPECT_NEAR(s.graph[v].position[0], c[0], 1e-9);
    EXPECT_NEAR(s.graph[v].position[1], c[1], 1e-9);
    EXPECT_EQ(s.graph[v].position[2], 0.0);
    degree_four += degree(v, s.graph) == 4 ? 1 : 0;
  }
  EXPECT_EQ(degree_four, 1u);
  EXPECT_EQ(s.merged_branch_arcs, 1u);
  EXPECT_EQ(s.branch_merge_distance, 2 * s.level_width);  // the forks lie 0.66 apart, the level width is 0.42
  // A tree (tree_segments(): 6 segments, leaves at (0,0), (-7,6), (4,13) and (8,10)): no loop, four leaves.
  const auto tree = sample_segments(tree_segments(), 0.3, 0.05, 6);
  const Reeb_skeleton t = extract_reeb_skeleton(tree.points, 0.7, o);
  EXPECT_EQ(loops_of(t.graph), 0u);
  std::size_t leaves = 0;
  for (auto v : boost::make_iterator_range(vertices(t.graph))) leaves += degree(v, t.graph) == 1 ? 1 : 0;
  EXPECT_EQ(leaves, 4u);
  expect_members_partition(t.graph, tree.points.size());
}

TEST(ExtractReebSkeleton, StageByStageEqualsOneCall) {
  // The stages called one after another, with the pipeline's defaults, give the one call's skeleton exactly:
  // nodes (position, value, type, members) and arcs (ends, polyline, members), in the same order.
  const auto eight = sample_segments(figure_eight_segments(), 0.25, 0.15, 4);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton one = extract_reeb_skeleton(eight.points, 0.7, o);
  ASSERT_EQ(one.merged_branch_arcs, 1u);  // every stage does something here
  ASSERT_GT(one.removed_branches, 0u);
  ASSERT_GT(one.trimmed_stubs, 0u);
  const Point_matrix P = make_point_matrix(eight.points);
  const Simplicial_complex_2 K = build_flag_complex_2(build_rips_graph(P, 0.7));
  const Geodesic_result geo = compute_geodesic_function(K);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, geo.values);
  const Reeb_simplification_result S = simplify_by_persistence(A, o.delta.value());
  const Reeb_trim_result T = trim_essential_stubs(S.graph, o.delta.value());
  Embedding_options eo;
  eo.level_width = one.level_width;  // the median edge length of K
  const Reeb_graph_embedding E = embed_reeb_graph(T.graph, K, project_to_3d(P), A.values(), 2, eo);
  const Branch_node_merge_result M =
      merge_close_branch_nodes(make_skeleton_graph(T.graph, E), P, 2 * eo.level_width.value());
  EXPECT_EQ(S.removed_branches, one.removed_branches);
  EXPECT_EQ(T.trimmed, one.trimmed_stubs);
  EXPECT_EQ(M.merged, one.merged_branch_arcs);
  const Skeleton_graph &a = one.graph, &b = M.graph;
  ASSERT_EQ(num_vertices(a), num_vertices(b));
  ASSERT_EQ(num_edges(a), num_edges(b));
  for (std::size_t v = 0; v < num_vertices(a); ++v) {
    EXPECT_EQ(a[v].position, b[v].position) << v;
    EXPECT_EQ(a[v].value, b[v].value) << v;
    EXPECT_EQ(a[v].type, b[v].type) << v;
    EXPECT_EQ(a[v].members, b[v].members) << v;
  }
  auto ea = edges(a).first;
  for (auto eb : boost::make_iterator_range(edges(b))) {
    EXPECT_EQ(source(*ea, a), source(eb, b));
    EXPECT_EQ(target(*ea, a), target(eb, b));
    EXPECT_EQ(a[*ea].polyline, b[eb].polyline);
    EXPECT_EQ(a[*ea].members, b[eb].members);
    ++ea;
  }
}

namespace {
/// An X drawn as the Reeb graph draws a crossing: minima 0 and 1 join at the down-fork 2 (value 1), which an
/// arc of length 0.1 through point 6 joins to the up-fork 3 (value 1.1), which splits into the maxima 4
/// and 5.
struct Crossing {
  Point_matrix points;
  Skeleton_graph graph;
  Crossing() {
    points.dimension = 2;
    points.data = {-1, -1, 1, -1, 0, -0.05, 0, 0.05, -1, 1, 1, 1, 0, 0};
    points.rows = 7;
    const double values[6] = {0, 0, 1, 1.1, 2, 2};
    const unsigned types[6] = {minimum, minimum, down_fork, up_fork, maximum, maximum};
    graph = Skeleton_graph(6);
    for (std::size_t v = 0; v < 6; ++v) {
      graph[v].position = {points.row(v)[0], points.row(v)[1], 0};
      graph[v].value = values[v];
      graph[v].type = types[v];
      graph[v].members = {static_cast<Vertex_index>(v)};
    }
    auto arc = [&](std::size_t a, std::size_t b, std::vector<Vertex_index> members) {
      Skeleton_arc s;
      s.polyline.push_back(graph[a].position);
      for (const Vertex_index p : members) s.polyline.push_back({points.row(p)[0], points.row(p)[1], 0});
      s.polyline.push_back(graph[b].position);
      s.members = std::move(members);
      s.lower = a;
      s.upper = b;
      add_edge(a, b, std::move(s), graph);
    };
    arc(0, 2, {});
    arc(1, 2, {});
    arc(2, 3, {6});
    arc(3, 4, {});
    arc(3, 5, {});
  }
};
}  // namespace

TEST(MergeCloseBranchNodes, ACrossingBecomesOneNode) {
  const Crossing x;
  const Skeleton_graph before = x.graph;
  const Branch_node_merge_result r = merge_close_branch_nodes(x.graph, x.points, 0.2);
  EXPECT_EQ(r.merged, 1u);
  const Skeleton_graph& g = r.graph;
  ASSERT_EQ(num_vertices(g), 5u);
  ASSERT_EQ(num_edges(g), 4u);
  expect_members_partition(g, 7);
  // The merged node is 2 (the smallest of 2 and 3): value and members of the lower fork first, then the upper
  // fork's and the arc's; at the centroid of its three points; both forks at once.
  EXPECT_EQ(g[2].value, 1.0);
  EXPECT_EQ(g[2].members, (std::vector<Vertex_index>{2, 3, 6}));
  EXPECT_NEAR(g[2].position[0], 0.0, 1e-15);
  EXPECT_NEAR(g[2].position[1], 0.0, 1e-15);
  EXPECT_EQ(g[2].type, unsigned(down_fork | up_fork));
  EXPECT_EQ(degree(2, g), 4u);
  // The other nodes are copied; the maxima move down one index; every arc ends at the merged node's position.
  EXPECT_EQ(g[0].members, before[0].members);
  EXPECT_EQ(g[3].members, std::vector<Vertex_index>{4});
  EXPECT_EQ(g[4].position, before[5].position);
  for (auto e : boost::make_iterator_range(edges(g))) {
    const auto& line = g[e].polyline;
    EXPECT_EQ(line.front(), g[source(e, g)].position);
    EXPECT_EQ(line.back(), g[target(e, g)].position);
    EXPECT_LT(g[source(e, g)].value, g[target(e, g)].value);
  }
  // The input is untouched.
  EXPECT_EQ(num_vertices(x.graph), 6u);
  EXPECT_EQ(x.graph[2].members, std::vector<Vertex_index>{2});
  // Shorter than the arc (length 0.1) or 0: nothing changes.
  for (const double d : {0.0, 0.05, 0.0999}) {
    const Branch_node_merge_result same = merge_close_branch_nodes(x.graph, x.points, d);
    EXPECT_EQ(same.merged, 0u) << d;
    EXPECT_EQ(num_vertices(same.graph), 6u) << d;
    EXPECT_EQ(same.graph[3].position, before[3].position) << d;
  }
  EXPECT_EQ(merge_close_branch_nodes(x.graph, x.points, 0.1).merged, 1u);  // at most the distance: merged
  // A leaf is not a branch node: the arc from a fork to a close leaf stays.
  Crossing leafy;
  leafy.graph[0].position = {0, -0.1, 0};
  leafy.graph[0].value = 0.95;
  EXPECT_EQ(merge_close_branch_nodes(leafy.graph, leafy.points, 0.1).merged, 1u);  // only the fork-fork arc
  // A short loop stays a loop: a second arc between the forks keeps both.
  Crossing loop;
  add_edge(2, 3, Skeleton_arc{{{0, -0.05, 0}, {0.01, 0, 0}, {0, 0.05, 0}}, {}, {}, 2, 3}, loop.graph);
  const Branch_node_merge_result kept = merge_close_branch_nodes(loop.graph, loop.points, 0.2);
  EXPECT_EQ(kept.merged, 0u);
  EXPECT_EQ(num_edges(kept.graph), 6u);
  // Bad input is named.
  EXPECT_THROW(merge_close_branch_nodes(x.graph, x.points, -1), std::invalid_argument);
  EXPECT_THROW(merge_close_branch_nodes(x.graph, x.points, std::nan("")), std::invalid_argument);
  Point_matrix few = x.points;
  few.rows = 6;
  few.data.resize(12);
  const std::string few_message =
      invalid_argument_message([&] { merge_close_branch_nodes(x.graph, few, 0.2); });
  EXPECT_TRUE(contains(few_message, "arc 2 has member 6"));
  // Empty graph.
  EXPECT_EQ(num_vertices(merge_close_branch_nodes(Skeleton_graph(), x.points, 1).graph), 0u);
  // Nodes without points (a hand-made graph): the merged node at the mean of the two (it was NaN).
  Crossing bare;
  for (std::size_t v = 0; v < 6; ++v) bare.graph[v].members.clear();
  for (auto e : boost::make_iterator_range(edges(bare.graph))) bare.graph[e].members.clear();
  const Branch_node_merge_result mean = merge_close_branch_nodes(bare.graph, bare.points, 0.2);
  EXPECT_EQ(mean.graph[2].position, (std::array<double, 3>{0, 0, 0}));
  // An arc between two nodes of one value, nothing merged: copied as it is, not turned round by index.
  Skeleton_graph level(2);
  level[0].type = level[1].type = minimum | maximum;
  add_edge(1, 0, Skeleton_arc{{{1, 0, 0}, {0, 0, 0}}, {}, {}, 1, 0}, level);
  const Branch_node_merge_result kept_level = merge_close_branch_nodes(level, x.points, 1.0);
  const auto e = *edges(kept_level.graph).first;
  EXPECT_EQ(source(e, kept_level.graph), 1u);
  EXPECT_EQ(kept_level.graph[e].polyline.front(), (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(kept_level.graph[0].type, unsigned(minimum | maximum));
  // Above 3D, input positions of another dimension are named (they overflowed).
  Point_matrix four;
  four.dimension = 4;
  four.rows = 7;
  four.data.assign(28, 0.0);
  Crossing short_input = x;
  for (std::size_t v = 0; v < 6; ++v) short_input.graph[v].input_position = {0, 0};
  const std::string short_message =
      invalid_argument_message([&] { merge_close_branch_nodes(short_input.graph, four, 0.2); });
  EXPECT_TRUE(
      contains(short_message, "node 0 has an input position of 2 coordinates, the coordinates have 4"));
}

TEST(MergeCloseBranchNodes, ChainsAndReversedArcs) {
  // Three forks in a row, 0.1 apart: at distance 0.2 one node of degree 5 after two rounds; at 0.15 the first
  // two only (the third would lie 0.2 from the first: a cluster stays within the distance).
  Point_matrix p;
  p.dimension = 2;
  p.data = {-1, -1, 1, -1, 0, 0, 0, 0.1, 0, 0.2, -1, 1, 1, 1, 2, 1};
  p.rows = 8;
  Skeleton_graph g(8);
  const double values[8] = {0, 0, 1, 1.1, 1.2, 2, 2, 2};
  for (std::size_t v = 0; v < 8; ++v) {
    g[v].position = {p.row(v)[0], p.row(v)[1], 0};
    g[v].value = values[v];
    g[v].members = {static_cast<Vertex_index>(v)};
  }
  auto arc = [&](Skeleton_graph& h, std::size_t a, std::size_t b) {
    add_edge(a, b, Skeleton_arc{{h[a].position, h[b].position}, {}, {}, a, b}, h);
  };
  for (const auto& [a, b] :
       std::vector<std::pair<int, int>>{{0, 2}, {1, 2}, {2, 3}, {3, 5}, {3, 4}, {4, 6}, {4, 7}})
    arc(g, a, b);
  const Branch_node_merge_result r = merge_close_branch_nodes(g, p, 0.2);
  EXPECT_EQ(r.merged, 2u);
  ASSERT_EQ(num_vertices(r.graph), 6u);
  EXPECT_EQ(degree(2, r.graph), 5u);
  EXPECT_EQ(r.graph[2].members, (std::vector<Vertex_index>{2, 3, 4}));
  EXPECT_NEAR(r.graph[2].position[1], 0.1, 1e-15);
  expect_members_partition(r.graph, 8);
  const Branch_node_merge_result pair = merge_close_branch_nodes(g, p, 0.15);
  EXPECT_EQ(pair.merged, 1u);
  ASSERT_EQ(num_vertices(pair.graph), 7u);
  EXPECT_EQ(pair.graph[2].members, (std::vector<Vertex_index>{2, 3}));
  EXPECT_EQ(degree(2, pair.graph), 4u);
  EXPECT_EQ(pair.graph[3].members, std::vector<Vertex_index>{4});
  expect_members_partition(pair.graph, 8);
  // An up-fork below a down-fork: a's arc up to b is short; the leaf d (value 1.05) joins b from below.
  // Merged at a's value 1, the arc from d now runs up from the merged node to d, which becomes a maximum.
  Point_matrix q;
  q.dimension = 2;
  q.data = {0, -1, 0, 0, 0, 0.1, 1, 0.1, -1, 1, 0, 2};
  q.rows = 6;
  Skeleton_graph h(6);  // m, a, b, d, c, e
  const double hv[6] = {0, 1, 1.1, 1.05, 3, 3};
  const unsigned ht[6] = {minimum, up_fork, down_fork, minimum, maximum, maximum};
  for (std::size_t v = 0; v < 6; ++v) {
    h[v].position = {q.row(v)[0], q.row(v)[1], 0};
    h[v].value = hv[v];
    h[v].type = ht[v];
    h[v].members = {static_cast<Vertex_index>(v)};
  }
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {1, 4}, {3, 2}, {2, 5}})
    arc(h, a, b);
  const Branch_node_merge_result s = merge_close_branch_nodes(h, q, 0.2);
  EXPECT_EQ(s.merged, 1u);
  ASSERT_EQ(num_vertices(s.graph), 5u);
  EXPECT_EQ(s.graph[1].value, 1.0);
  EXPECT_EQ(s.graph[2].type, unsigned(maximum));  // d
  EXPECT_EQ(s.graph[1].type, unsigned(up_fork));  // one arc below (from m), three above
  for (auto e : boost::make_iterator_range(edges(s.graph))) {
    EXPECT_LT(s.graph[source(e, s.graph)].value, s.graph[target(e, s.graph)].value);
    EXPECT_EQ(s.graph[e].polyline.front(), s.graph[source(e, s.graph)].position);
    EXPECT_EQ(s.graph[e].polyline.back(), s.graph[target(e, s.graph)].position);
    // The reversed arc (d's) and the others name their new ends.
    EXPECT_EQ(s.graph[e].lower, source(e, s.graph));
    EXPECT_EQ(s.graph[e].upper, target(e, s.graph));
  }
}

TEST(ExtractReebSkeleton, ArcsSayWhichWayTheyRunFromEitherNode) {
  // Boost reports an undirected arc with either node as its source (out_edges(v, g): always v); the arc's
  // lower / upper say which way its polylines run, and arc_polyline_from() walks it from either node.
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  Skeleton_options o;
  o.delta = 1.0;
  const Skeleton_graph g = extract_reeb_skeleton(eight.points, 0.7, o).graph;
  ASSERT_GT(num_edges(g), 2u);
  std::size_t reversed = 0;
  for (auto v : boost::make_iterator_range(vertices(g)))
    for (auto e : boost::make_iterator_range(out_edges(v, g))) {
      const Skeleton_arc& a = g[e];
      ASSERT_TRUE(a.lower == v || a.upper == v);
      const std::size_t other = a.lower == v ? a.upper : a.lower;
      EXPECT_LE(g[a.lower].value, g[a.upper].value);
      EXPECT_EQ(a.polyline.front(), g[a.lower].position);
      EXPECT_EQ(a.polyline.back(), g[a.upper].position);
      const auto walked = arc_polyline_from(g, e, v);
      EXPECT_EQ(walked.front(), g[v].position);
      EXPECT_EQ(walked.back(), g[other].position);
      auto back = walked;
      std::reverse(back.begin(), back.end());
      EXPECT_EQ(v == a.lower ? walked : back, a.polyline);
      reversed += v != a.lower ? 1 : 0;
      for (std::size_t w = 0; w < num_vertices(g); ++w)
        if (w != a.lower && w != a.upper) {
          EXPECT_TRUE(
              contains(FeatureRecon::test::invalid_argument_message([&] { arc_polyline_from(g, e, w); }),
                       "node " + std::to_string(w) + " is not an end of the arc"));
          break;
        }
    }
  // Stored from lower to upper: edges(g) reports them that way; every arc but a loop arc (one node) is met
  // once from its upper node.
  std::size_t non_loops = 0;
  for (auto e : boost::make_iterator_range(edges(g))) {
    EXPECT_EQ(g[e].lower, source(e, g));
    EXPECT_EQ(g[e].upper, target(e, g));
    non_loops += g[e].lower != g[e].upper ? 1 : 0;
  }
  EXPECT_EQ(reversed, non_loops);
  EXPECT_GT(reversed, 0u);
  // Above 3D the input polylines too: the same figure-eight in R^4 (two zero coordinates).
  Point_matrix m4;
  m4.dimension = 4;
  for (const auto& p : eight.points) {
    m4.data.insert(m4.data.end(), {p[0], p[1], 0.0, 0.0});
    ++m4.rows;
  }
  const Skeleton_graph h = extract_reeb_skeleton(m4, 0.7, o).graph;
  ASSERT_EQ(num_edges(h), num_edges(g));
  for (auto e : boost::make_iterator_range(edges(h))) {
    const Skeleton_arc& a = h[e];
    ASSERT_FALSE(a.input_polyline.empty());
    EXPECT_EQ(arc_input_polyline_from(h, e, a.lower, 4), a.input_polyline);
    const std::vector<double> up = arc_input_polyline_from(h, e, a.upper, 4);
    const std::size_t count = a.input_polyline.size() / 4;
    ASSERT_EQ(up.size(), a.input_polyline.size());
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(up[4 * i + c], a.input_polyline[4 * (count - 1 - i) + c]);
    const std::size_t wrong = a.input_polyline.size() + 1;  // divides no positive size below it
    EXPECT_TRUE(contains(
        FeatureRecon::test::invalid_argument_message([&] { arc_input_polyline_from(h, e, a.lower, wrong); }),
        "not points of " + std::to_string(wrong) + " coordinates"));
  }
}

TEST(ExtractReebSkeleton, NamesOfStatusesAndNodeTypes) {
  EXPECT_STREQ(to_string(Status::success), "success");
  EXPECT_STREQ(to_string(Status::degenerate_input), "degenerate_input");
  EXPECT_STREQ(to_string(Status::interrupted), "interrupted");
  std::ostringstream os;
  os << Status::interrupted;
  EXPECT_EQ(os.str(), "interrupted");
  EXPECT_STREQ(node_type_name(regular), "regular");
  EXPECT_STREQ(node_type_name(minimum), "minimum");
  EXPECT_STREQ(node_type_name(maximum), "maximum");
  EXPECT_STREQ(node_type_name(minimum | maximum), "isolated");
  EXPECT_STREQ(node_type_name(up_fork), "up-fork");
  EXPECT_STREQ(node_type_name(down_fork), "down-fork");
  EXPECT_STREQ(node_type_name(up_fork | down_fork), "up-fork+down-fork");
  EXPECT_STREQ(node_type_name(minimum | up_fork), "minimum+up-fork");
  EXPECT_STREQ(node_type_name(maximum | down_fork), "maximum+down-fork");
}

TEST(MergeCloseBranchNodes, ALatticeIsNotChainedIntoALine) {
  // A 10 x 10 grid at radius 1.01 (no triangle: 81 cells, each a loop): nearly every node is a fork and every
  // arc about one level width (1), the default merge distance 2. Merging in rounds chained the forks into 15
  // nodes on a line with fans of coincident arcs; each cluster now stays at most 2 across, so a node's points
  // lie near it and the nodes still span the grid.
  std::vector<std::array<double, 2>> grid;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) grid.push_back({double(i), double(j)});
  Skeleton_options o;
  o.delta = 1.01;
  const Reeb_skeleton s = extract_reeb_skeleton(grid, 1.01, o);
  ASSERT_EQ(s.status, Status::success);
  EXPECT_EQ(s.branch_merge_distance, 2.0);
  EXPECT_GT(s.merged_branch_arcs, 0u);
  EXPECT_EQ(loops_of(s.graph), 81u);
  expect_members_partition(s.graph, grid.size());
  EXPECT_GE(num_vertices(s.graph), 20u);  // at most 5 grid nodes (a plus sign) lie within 2 of each other
  double x0 = 9, x1 = 0, y0 = 9, y1 = 0, farthest = 0;
  for (auto v : boost::make_iterator_range(vertices(s.graph))) {
    const auto& n = s.graph[v];
    x0 = std::min(x0, n.position[0]), x1 = std::max(x1, n.position[0]);
    y0 = std::min(y0, n.position[1]), y1 = std::max(y1, n.position[1]);
    for (const Vertex_index p : n.members)
      farthest = std::max(farthest, std::hypot(grid[p][0] - n.position[0], grid[p][1] - n.position[1]));
  }
  EXPECT_LE(farthest, 2.0);
  EXPECT_GE(x1 - x0, 8.0);
  EXPECT_GE(y1 - y0, 8.0);
}

TEST(ExtractReebSkeleton, RepairJoinsAGap) {
  // A line with a 1.5-unit gap: two components; repair at 2 joins them.
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i <= 40; ++i)
    if (i < 20 || i > 22) pts.push_back({0.5 * i, 0.0});
  Skeleton_options o;
  const Reeb_skeleton broken = extract_reeb_skeleton(pts, 0.6, o);
  std::vector<int> comp(num_vertices(broken.graph));
  EXPECT_EQ(boost::connected_components(broken.graph, comp.data()), 2);
  o.repair_distance = 2.0;
  const Reeb_skeleton fixed = extract_reeb_skeleton(pts, 0.6, o);
  EXPECT_EQ(fixed.repaired, 1u);
  comp.assign(num_vertices(fixed.graph), 0);
  EXPECT_EQ(boost::connected_components(fixed.graph, comp.data()), 1);
  expect_members_partition(fixed.graph, pts.size());
}

TEST(ExtractReebSkeleton, DegenerateAndBadInput) {
  EXPECT_EQ(extract_reeb_skeleton(std::vector<std::array<double, 2>>{}, 1.0).status,
            Status::degenerate_input);
  const Reeb_skeleton one = extract_reeb_skeleton(std::vector<std::array<double, 2>>{{1.0, 2.0}}, 1.0);
  EXPECT_EQ(one.status, Status::success);
  EXPECT_EQ(num_vertices(one.graph), 1u);
  EXPECT_EQ(num_edges(one.graph), 0u);
  EXPECT_EQ(one.graph[0].position, (std::array<double, 3>{1, 2, 0}));
  // Above 3D: one point, copies of one point, collinear points (rank 1 for the projection).
  Point_matrix high;
  high.dimension = 6;
  high.rows = 1;
  high.data = {1, 2, 3, 4, 5, 6};
  const Reeb_skeleton lone = extract_reeb_skeleton(high, 1.0);
  EXPECT_EQ(lone.status, Status::success);
  ASSERT_EQ(num_vertices(lone.graph), 1u);
  EXPECT_EQ(lone.graph[0].input_position, high.data);
  high.rows = 5;
  for (int k = 0; k < 4; ++k) high.data.insert(high.data.end(), {1, 2, 3, 4, 5, 6});
  const Reeb_skeleton copies = extract_reeb_skeleton(high, 1.0);
  EXPECT_EQ(copies.status, Status::success);
  ASSERT_EQ(num_vertices(copies.graph), 1u);  // one node holding all five copies
  EXPECT_EQ(copies.graph[0].members.size(), 5u);
  high.data.clear();
  high.rows = 21;
  for (int k = 0; k <= 20; ++k)
    for (int c = 0; c < 6; ++c)
      high.data.push_back(0.5 * k * (c + 1));  // along (1, ..., 6), 0.5 * sqrt(91) apart
  const Reeb_skeleton collinear = extract_reeb_skeleton(high, 5.0);
  EXPECT_EQ(collinear.status, Status::success);
  EXPECT_EQ(loops_of(collinear.graph), 0u);
  std::size_t leaves = 0;
  for (auto v : boost::make_iterator_range(vertices(collinear.graph)))
    leaves += degree(v, collinear.graph) == 1 ? 1 : 0;
  EXPECT_EQ(leaves, 2u);  // a segment
  expect_members_partition(collinear.graph, 21);
  // An automatic delta is the suggested one (one point: no scale, so the radius); NaN is refused, and each
  // bad field is named alone (one message listed three).
  Skeleton_options bad;
  bad.delta = FeatureRecon::automatic;
  EXPECT_EQ(extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad).delta, 1.0);
  bad.delta = std::nan("");
  EXPECT_THROW(extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad),
               std::invalid_argument);
  bad.delta = 0.0;
  bad.repair_distance = -2;
  EXPECT_TRUE(contains(invalid_argument_message([&] {
                         extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad);
                       }),
                       "repair_distance must be finite and >= 0 (0: no repair), got -2"));
  bad.repair_distance = 0;
  bad.prune_height = -3;
  EXPECT_TRUE(contains(invalid_argument_message([&] {
                         extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad);
                       }),
                       "prune_height must be >= 0 (0: keep all; infinity: prune all), got -3"));
  // A negative branch merge distance asked for the automatic one before FeatureRecon::automatic: refused.
  bad.prune_height = 0;
  bad.branch_merge_distance = -1;
  EXPECT_EQ(invalid_argument_message([&] {
              extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad);
            }),
            "extract_reeb_skeleton: branch_merge_distance must be finite and >= 0 (FeatureRecon::automatic: "
            "twice the level width; 0: off), got -1");
  bad.branch_merge_distance = std::numeric_limits<double>::infinity();
  EXPECT_THROW(extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad),
               std::invalid_argument);
  // Messages name the function called, not the stage that noticed (they began with build_rips_graph and
  // build_flag_complex_2), and say what is wrong.
  auto message = [](auto&& call) { return invalid_argument_message(call); };
  EXPECT_EQ(message([] {
              extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, std::nan(""));
            }).rfind("extract_reeb_skeleton: radius must be finite and >= 0", 0),
            0u);
  EXPECT_EQ(message([] {
              extract_reeb_skeleton_from_distance_matrix(Eigen::MatrixXd(Eigen::MatrixXd::Zero(2, 2)), -1.0);
            }).rfind("extract_reeb_skeleton_from_distance_matrix: radius must be finite and >= 0, got -1", 0),
            0u);
  Proximity_graph g;
  g.number_of_vertices = 2;
  g.edges = {{1, 0}};
  Point_matrix two;
  two.rows = 2;
  two.dimension = 2;
  two.data = {0, 0, 1, 0};
  EXPECT_EQ(
      message([&] {
        extract_reeb_skeleton(g, two);
      }).rfind("extract_reeb_skeleton: the graph is not canonical (see Proximity_graph): edge 0 (1, 0)", 0),
      0u);
  bad = {};
  bad.prune_height = -1;
  EXPECT_TRUE(contains(message([&] { extract_reeb_skeleton(g, two, bad); }),
                       "prune_height must be >= 0 (0: keep all; infinity: prune all), got -1"));
  // Embedding options are checked before the pipeline runs (they were refused by its last stage, naming
  // embed_reeb_graph and the automatic level width in place of the caller's), with the caller's values.
  bad = {};
  bad.embedding.smoothing_weight = 2;
  std::size_t calls = 0;
  bad.progress = [&calls](double) { return ++calls > 0; };
  const std::vector<std::array<double, 2>> pair{{0.0, 0.0}, {1.0, 0.0}};
  EXPECT_EQ(message([&] { extract_reeb_skeleton(pair, 2.0, bad); }),
            "extract_reeb_skeleton: embedding smoothing_weight must lie in [0, 2/3] for Taubin smoothing "
            "(Laplacian: "
            "[0, 1]), got 2");
  bad.embedding.smoothing = Embedding_options::Smoothing::laplacian;
  EXPECT_EQ(message([&] { extract_reeb_skeleton(pair, 2.0, bad); }),
            "extract_reeb_skeleton: embedding smoothing_weight must lie in [0, 1], got 2");
  bad.embedding.smoothing = static_cast<Embedding_options::Smoothing>(7);
  bad.embedding.smoothing_weight = 0.5;
  EXPECT_EQ(message([&] { extract_reeb_skeleton(pair, 2.0, bad); }),
            "extract_reeb_skeleton: embedding smoothing must be taubin or laplacian, got 7");
  bad.embedding.smoothing = Embedding_options::Smoothing::taubin;
  EXPECT_EQ(calls, 0u);
  bad.embedding.smoothing_weight = 0.5;
  bad.embedding.level_width = -1;
  EXPECT_TRUE(
      contains(message([&] { extract_reeb_skeleton(g, two, bad); }), "embedding level_width must be > 0"));
  // A geodesic distance beyond the largest double (20 points on a line 1e307 apart, about 2e308 end to end)
  // names the call and the stage (it named compute_geodesic_function alone).
  std::vector<std::array<double, 2>> far_apart;
  for (int i = 0; i < 20; ++i) far_apart.push_back({(i - 9.5) * 1e307, 0.0});
  EXPECT_EQ(message([&] { extract_reeb_skeleton(far_apart, 1.5e307); }),
            "extract_reeb_skeleton: the geodesic distance of vertex 18 overflows the largest double; scale "
            "the edge "
            "lengths down (in compute_geodesic_function)");
  // make_skeleton_graph() checks that the embedding is the graph's (it read out of bounds).
  Reeb_graph line;
  line.nodes.resize(2);
  line.nodes[1].vertex = 1;
  line.nodes[1].value = 1;
  line.arcs = {{0, 1, {}}};
  Reeb_graph_embedding wrong;
  wrong.node_positions.resize(1);
  EXPECT_EQ(message([&] { make_skeleton_graph(line, wrong); }),
            "make_skeleton_graph: the embedding has 1 node positions and 0 arc polylines for a graph of 2 "
            "nodes and 1 "
            "arcs (not its embedding)");
}

// Skeleton_options::max_triangles: a complex of exactly that many triangles is built as without a limit, one
// more is refused while counting, naming the option; 0 leaves only the Reeb graph's own limit.
TEST(ExtractReebSkeleton, TriangleLimitIsCheckedWhileCounting) {
  const Point_matrix m = circle_points(300);
  Skeleton_options o;
  o.delta = 1;
  o.max_triangles = 0;
  const Reeb_skeleton all = extract_reeb_skeleton(m, 1.0, o);
  ASSERT_EQ(all.status, Status::success);
  ASSERT_GT(all.rips_triangles, 100u);
  EXPECT_EQ(Skeleton_options().max_triangles, std::size_t(1) << 27);
  o.max_triangles = all.rips_triangles;
  const Reeb_skeleton exact = extract_reeb_skeleton(m, 1.0, o);
  EXPECT_EQ(exact.rips_triangles, all.rips_triangles);
  EXPECT_EQ(num_edges(exact.graph), num_edges(all.graph));
  o.max_triangles = all.rips_triangles - 1;
  const std::string what = invalid_argument_message([&] { extract_reeb_skeleton(m, 1.0, o); });
  EXPECT_EQ(
      what.rfind("extract_reeb_skeleton: the flag complex has more than " +
                     std::to_string(all.rips_triangles - 1) + " triangles (max_triangles of the options",
                 0),
      0u)
      << what;
}

TEST(ExtractReebSkeleton, AStopDuringTheRipsStageEndsTheRun) {
  // The callback says stop once, inside the Rips stage, and go on afterwards: the run still ends,
  // interrupted.
  const Point_matrix m = circle_points(2000);
  int calls = 0;
  Skeleton_options o;
  o.delta = 1;
  o.progress = [&calls](double) { return ++calls != 2; };
  const Reeb_skeleton s = extract_reeb_skeleton(m, 1.0, o);
  EXPECT_EQ(s.status, Status::interrupted);
  EXPECT_EQ(num_vertices(s.graph), 0u);
  o.progress = nullptr;
  EXPECT_EQ(extract_reeb_skeleton(m, 1.0, o).status, Status::success);
}

TEST(ExtractReebSkeleton, TheSimplificationsReportAndStop) {
  // The two simplifications, the repair, the dead-end connection and the embedding report in their stages
  // (the simplifications reported nothing: a long one looked hung) and a stop in any of them ends the run.
  const Point_matrix m = circle_points(2000);
  Skeleton_options o;
  o.delta = 1;
  o.repair_distance = 0.5;
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  ASSERT_EQ(extract_reeb_skeleton(m, 1.0, o).status, Status::success);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  auto at = [](double x) { return 0.3 + 0.7 * x; };  // from points, the stages after the Rips graph: 0.3 to 1
  auto reports = [&seen](double from, double to) {
    return std::count_if(seen.begin(), seen.end(), [from, to](double t) { return t > from && t < to; });
  };
  EXPECT_GE(reports(at(0.8), at(0.87)), 3);    // the first simplification
  EXPECT_GE(reports(at(0.87), at(0.91)), 2);   // repair and dead ends
  EXPECT_GE(reports(at(0.91), at(0.95)), 3);   // the second simplification
  EXPECT_GE(reports(at(0.95), at(0.995)), 1);  // the embedding (it reported nothing until session 37)
  for (const double stop_at : {at(0.83), at(0.88), at(0.9), at(0.93), at(0.96)}) {
    std::size_t later = 0;
    bool refused = false;
    o.progress = [&](double t) {
      if (refused) ++later;
      refused = refused || t >= stop_at;
      return t < stop_at;
    };
    const Reeb_skeleton s = extract_reeb_skeleton(m, 1.0, o);
    EXPECT_EQ(s.status, Status::interrupted) << stop_at;
    EXPECT_EQ(num_vertices(s.graph), 0u) << stop_at;
    EXPECT_EQ(later, 0u) << stop_at;
  }
}

TEST(ExtractReebSkeleton, TheStagesAfterTheEmbeddingReportAndStop) {
  // Trimming (0.95 to 0.955 of the stages after the Rips graph), pruning (to 0.96) and the branch-node merge
  // (0.99 to 1) report in their stages; a stop at any of their reports ends the run with an empty graph and
  // no later report (they reported nothing, and a stop during them was seen only at the end).
  const Point_matrix m = circle_points(2000);
  Skeleton_options o;
  o.delta = 1;
  o.prune_height = 0.5;
  ASSERT_TRUE(o.trim_stubs);
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  const Reeb_skeleton full = extract_reeb_skeleton(m, 1.0, o);
  ASSERT_EQ(full.status, Status::success);
  ASSERT_GT(full.branch_merge_distance, 0.0);
  ASSERT_GT(num_vertices(full.graph), 0u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  auto at = [](double x) { return 0.3 + 0.7 * x; };  // from points, the stages after the Rips graph: 0.3 to 1
  auto reports_at = [&seen](double x) {
    return std::count_if(seen.begin(), seen.end(), [x](double t) { return std::fabs(t - x) < 1e-12; });
  };
  EXPECT_EQ(reports_at(at(0.95)), 1);   // trimming's start (no repair: no second simplification)
  EXPECT_EQ(reports_at(at(0.955)), 2);  // trimming's end, pruning's start
  EXPECT_GE(reports_at(at(0.96)), 1);   // pruning's end
  // the merge: after its candidates and before its new graph (its end is 1)
  EXPECT_EQ(std::count_if(seen.begin(), seen.end(), [&](double t) { return t > at(0.99) && t < 1; }), 2);
  std::size_t checked = 0;
  for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
    if (seen[i] < at(0.95) || (seen[i] > at(0.96) && seen[i] < at(0.99))) continue;
    std::size_t calls = 0;
    o.progress = [&calls, i](double) { return calls++ != i; };
    const Reeb_skeleton s = extract_reeb_skeleton(m, 1.0, o);
    EXPECT_EQ(s.status, Status::interrupted) << "stopped at " << seen[i];
    EXPECT_EQ(num_vertices(s.graph), 0u) << "stopped at " << seen[i];
    EXPECT_EQ(calls, i + 1) << "stopped at " << seen[i];
    ++checked;
  }
  EXPECT_GE(checked, 6u);
}

TEST(ExtractReebSkeleton, LevelWidthReportsTheWidthUsed) {
  // Most points are copies of one point: the median edge length over all edges is 0 (the embedding fell back
  // to 1/64 of the range of f); over the edges between distinct points it is the spacing, 1, as without the
  // copies. The result reports that width, and giving it explicitly draws the same skeleton.
  Point_matrix m;
  m.dimension = 2;
  for (int i = 0; i < 20; ++i) m.data.insert(m.data.end(), {double(i), 0.0});
  for (int c = 0; c < 30; ++c) m.data.insert(m.data.end(), {0.0, 0.0});
  m.rows = m.data.size() / 2;
  Skeleton_options o;
  o.trim_stubs = false;
  const Reeb_skeleton s = extract_reeb_skeleton(m, 1.0, o);
  EXPECT_EQ(s.level_width, 1.0);
  o.embedding.level_width = s.level_width;
  const Reeb_skeleton t = extract_reeb_skeleton(m, 1.0, o);
  ASSERT_EQ(num_edges(s.graph), num_edges(t.graph));
  auto e = edges(s.graph).first;
  auto f = edges(t.graph).first;
  for (; e != edges(s.graph).second; ++e, ++f) EXPECT_EQ(s.graph[*e].polyline, t.graph[*f].polyline);
}

namespace {
// Nodes as (type, sorted members) and arcs as sorted members, in sorted order: skeletons compared without
// their numbering.
std::pair<std::vector<std::pair<unsigned, std::vector<Vertex_index>>>, std::vector<std::vector<Vertex_index>>>
skeleton_signature(const Skeleton_graph& g) {
  std::vector<std::pair<unsigned, std::vector<Vertex_index>>> nodes;
  for (auto v : boost::make_iterator_range(vertices(g))) {
    nodes.push_back({g[v].type, g[v].members});
    std::sort(nodes.back().second.begin(), nodes.back().second.end());
  }
  std::vector<std::vector<Vertex_index>> arcs;
  for (auto e : boost::make_iterator_range(edges(g))) {
    arcs.push_back(g[e].members);
    std::sort(arcs.back().begin(), arcs.back().end());
  }
  std::sort(nodes.begin(), nodes.end());
  std::sort(arcs.begin(), arcs.end());
  return {nodes, arcs};
}
}  // namespace

TEST(ExtractReebSkeleton, CopiesLeaveTheAutomaticLevelWidthAlone) {
  // An X of two lines of points 0.4 apart crossing at 1.2 rad, r = 1: the median edge length (the automatic
  // level width, and twice it the branch-merge distance) was taken over all edges, so copies of the points,
  // with their edges of length 0, moved it (0.754 once, 0.4 twice) and the crossing became two forks instead
  // of one node of degree 4.
  auto x_of = [](int copies) {
    std::vector<std::array<double, 2>> p;
    for (int i = -30; i <= 30; ++i) {
      for (int c = 0; c < copies; ++c) p.push_back({0.4 * i, 0.0});
      if (i != 0)
        for (int c = 0; c < copies; ++c) p.push_back({0.4 * i * std::cos(1.2), 0.4 * i * std::sin(1.2)});
    }
    return p;
  };
  Skeleton_options o;
  o.delta = 0.5;
  const Reeb_skeleton once = extract_reeb_skeleton(x_of(1), 1.0, o);
  ASSERT_EQ(once.status, Status::success);
  auto degree_4 = [](const Reeb_skeleton& s) {
    std::size_t count = 0;
    for (auto v : boost::make_iterator_range(vertices(s.graph))) count += degree(v, s.graph) == 4 ? 1 : 0;
    return count;
  };
  EXPECT_EQ(degree_4(once), 1u);
  for (const int copies : {2, 3}) {
    const auto points = x_of(copies);
    const Reeb_skeleton s = extract_reeb_skeleton(points, 1.0, o);
    EXPECT_EQ(s.level_width, once.level_width) << copies;
    EXPECT_EQ(s.branch_merge_distance, once.branch_merge_distance) << copies;
    EXPECT_EQ(s.max_gap, once.max_gap) << copies;  // the embedding's automatic one, likewise (session 42)
    EXPECT_EQ(num_vertices(s.graph), num_vertices(once.graph)) << copies;
    EXPECT_EQ(num_edges(s.graph), num_edges(once.graph)) << copies;
    EXPECT_EQ(degree_4(s), 1u) << copies;
    expect_members_partition(s.graph, points.size());
  }
}

TEST(ExtractReebSkeleton, CopiesOfOneFarPointLeaveTheMaxGapAlone) {
  // An L of points 0.5 apart and 300 copies of one point far from it: over all edges the median edge length
  // was 0, so the automatic max_gap (twice it) turned bridging off for the whole skeleton.
  std::vector<std::array<double, 2>> l;
  for (int i = 0; i <= 25; ++i) l.push_back({0.5 * i, 0.0});
  for (int i = 1; i <= 25; ++i) l.push_back({0.0, 0.5 * i});
  Skeleton_options o;
  o.delta = 0.5;
  const Reeb_skeleton alone = extract_reeb_skeleton(l, 0.5, o);
  ASSERT_EQ(alone.status, Status::success);
  EXPECT_DOUBLE_EQ(alone.max_gap, 1.0);
  std::vector<std::array<double, 2>> with = l;
  for (int c = 0; c < 300; ++c) with.push_back({100.0, 100.0});
  const Reeb_skeleton s = extract_reeb_skeleton(with, 0.5, o);
  ASSERT_EQ(s.status, Status::success);
  EXPECT_EQ(s.max_gap, alone.max_gap);
  EXPECT_EQ(num_vertices(s.graph), num_vertices(alone.graph) + 1);  // the far point's node
  // Only copies: no edge between distinct points, straight segments (nothing to bridge through).
  const Reeb_skeleton copies =
      extract_reeb_skeleton(std::vector<std::array<double, 2>>(5, {1.0, 2.0}), 0.5, o);
  EXPECT_EQ(copies.status, Status::success);
  EXPECT_EQ(copies.max_gap, std::numeric_limits<double>::infinity());
}

TEST(ExtractReebSkeleton, CopiesOfAPointAreNotJoinedToEachOther) {
  // A noisy figure-eight with copies: 40 more of its point 7 (a regular point), 40 of point 0 (the smallest
  // index, where the geodesic base search starts), two more copies of every point (maxima included). The
  // skeleton is exactly the one of the full Rips complex, where the copies form cliques: same nodes with
  // their types and members, same arcs, same counts of removed features.
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  const std::size_t n = eight.points.size();
  auto with_copies_of = [&](std::size_t copies) {
    std::vector<std::array<double, 2>> p = eight.points;
    for (std::size_t k = 0; k < copies; ++k) p.push_back(eight.points[7]);
    for (std::size_t k = 0; k < 40; ++k) p.push_back(eight.points[0]);
    for (int twice = 0; twice < 2; ++twice)
      for (std::size_t i = 0; i < n; ++i) p.push_back(eight.points[i]);
    return p;
  };
  Skeleton_options o;
  o.delta = 1.0;
  o.embedding.level_width = 0.3;  // the copies' zero-length edges would otherwise set the median edge length
  const auto some = with_copies_of(40);
  const Point_matrix m = make_point_matrix(some);
  const Reeb_skeleton full = extract_reeb_skeleton(build_rips_graph(m, 0.7), m, o);
  const Reeb_skeleton s = extract_reeb_skeleton(m, 0.7, o);
  ASSERT_EQ(s.status, Status::success);
  EXPECT_EQ(loops_of(s.graph), 2u);
  EXPECT_EQ(s.removed_branches, full.removed_branches);
  EXPECT_EQ(s.removed_loops, full.removed_loops);
  EXPECT_EQ(skeleton_signature(s.graph), skeleton_signature(full.graph));
  EXPECT_LT(s.rips_triangles, full.rips_triangles / 3);
  expect_members_partition(s.graph, some.size());
  // 400 copies: the full complex has 11.4 million triangles; here the copies add about 400 stars of point 7.
  const auto many = with_copies_of(400);
  const Reeb_skeleton t = extract_reeb_skeleton(many, 0.7, o);
  const Reeb_skeleton distinct = extract_reeb_skeleton(eight.points, 0.7, o);
  EXPECT_LT(t.rips_triangles, distinct.rips_triangles + 500 * 100);
  EXPECT_EQ(t.removed_branches, distinct.removed_branches);
  EXPECT_EQ(num_vertices(t.graph), num_vertices(distinct.graph));
  EXPECT_EQ(num_edges(t.graph), num_edges(distinct.graph));
  expect_members_partition(t.graph, many.size());

  // The rule itself: first copies by exact coordinates (-0.0 equals 0.0), smallest index first; each copy
  // joined to its first copy, the first copy's neighbours and the next copy.
  Point_matrix q;
  q.dimension = 2;
  q.data = {1, 2, 0.0, 5, 1, 2, -0.0, 5, 1.5, 2, 1, 2};
  q.rows = 6;
  std::vector<Vertex_index> first;
  ASSERT_TRUE(skeleton::internal::first_copies(q, first));
  EXPECT_EQ(first, (std::vector<Vertex_index>{0, 1, 0, 1, 4, 0}));
  std::vector<Vertex_index> found;
  const Proximity_graph g = skeleton::internal::rips_graph_of_distinct_points(q, 1.0, {}, found);
  EXPECT_EQ(found, first);
  EXPECT_EQ(g.edges, (std::vector<Edge>{{0, 2}, {0, 4}, {0, 5}, {1, 3}, {2, 4}, {2, 5}, {4, 5}}));
  EXPECT_EQ(g.edge_lengths, (std::vector<double>{0, 0.5, 0, 0, 0.5, 0, 0.5}));
  q.data = {1, 2, 1, 3, 2, 2};
  q.rows = 3;
  EXPECT_FALSE(skeleton::internal::first_copies(q, first));
  EXPECT_TRUE(first.empty());
  EXPECT_EQ(skeleton::internal::rips_graph_of_distinct_points(q, 1.0, {}, found).edges,
            build_rips_graph(q, 1.0).edges);
  EXPECT_TRUE(found.empty());
}

namespace {

/// Two noisy half circles of radius 10 (300 points on the circle, seed 3) with gaps of about 1.5 at angles 0,
/// pi.
std::vector<std::array<double, 2>> half_circles_with_gaps() {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.1);
  std::vector<std::array<double, 2>> unit;
  for (int i = 0; i < 300; ++i) {
    const double a = 2 * M_PI * i / 300, r = 10 + noise(rng);
    if (std::fabs(std::remainder(a, M_PI)) >= 0.075) unit.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return unit;
}

}  // namespace

TEST(ExtractReebSkeleton, RepairGivesTheSameGraphAtEveryScale) {
  // Two noisy half circles with gaps of about 1.5 radii: repair at 2.5 joins them into a loop. The repair's
  // distances squared their differences: at 1e160 they overflowed (no repair), at 1e-200 underflowed (all 0).
  const std::vector<std::array<double, 2>> unit = half_circles_with_gaps();
  auto run = [&](double s) {
    std::vector<std::array<double, 2>> p;
    for (const auto& q : unit) p.push_back({s * q[0], s * q[1]});
    Skeleton_options o;
    o.delta = 2 * s;
    o.repair_distance = 2.5 * s;
    return extract_reeb_skeleton(p, s, o);
  };
  const Reeb_skeleton one = run(1);
  ASSERT_EQ(one.repaired, 2u);
  ASSERT_EQ(loops_of(one.graph), 1u);
  for (const double s : {1e160, 1e-160, 1e-200}) {
    const Reeb_skeleton scaled = run(s);
    EXPECT_EQ(scaled.repaired, one.repaired) << "scale " << s;
    EXPECT_EQ(num_vertices(scaled.graph), num_vertices(one.graph)) << "scale " << s;
    EXPECT_EQ(num_edges(scaled.graph), num_edges(one.graph)) << "scale " << s;
  }
}

TEST(ExtractReebSkeleton, NodesAndArcsNearTheLargestDouble) {
  // The two half circles of the test above, 1e305 times larger and moved to 1.5e308 (a coordinate's double is
  // about 1.7e308 at most): the skeleton is the same, nodes and polylines at the same places. Node and
  // level-set centroids summed their points (inf for two of them) and smoothing summed two neighbours.
  const std::vector<std::array<double, 2>> unit = half_circles_with_gaps();
  const double s = 1e305, offset = 1.5e308;
  auto run = [&](double scale, double shift) {
    std::vector<std::array<double, 2>> p;
    for (const auto& q : unit) p.push_back({shift + scale * q[0], shift + scale * q[1]});
    Skeleton_options o;
    o.delta = 2 * scale;
    o.repair_distance = 2.5 * scale;
    return extract_reeb_skeleton(p, scale, o);
  };
  const Reeb_skeleton one = run(1, 0), far = run(s, offset);
  ASSERT_EQ(num_vertices(far.graph), num_vertices(one.graph));
  ASSERT_EQ(num_edges(far.graph), num_edges(one.graph));
  EXPECT_EQ(loops_of(far.graph), 1u);
  const double tolerance = 1e-6 * s;  // of a circle of radius 10 s
  for (std::size_t v = 0; v < num_vertices(one.graph); ++v)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(far.graph[v].position[c], offset + s * one.graph[v].position[c], tolerance) << "node " << v;
  auto e = edges(one.graph).first;
  auto f = edges(far.graph).first;
  for (; e != edges(one.graph).second; ++e, ++f) {
    const auto& a = one.graph[*e].polyline;
    const auto& b = far.graph[*f].polyline;
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t t = 0; t < a.size(); ++t)
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(b[t][c], offset + s * a[t][c], tolerance) << "polyline vertex " << t;
  }
}

namespace {

/// The planar distance matrix of points.
Eigen::MatrixXd planar_distance_matrix(const std::vector<std::array<double, 2>>& p) {
  Eigen::MatrixXd D(p.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) D(i, j) = std::hypot(p[i][0] - p[j][0], p[i][1] - p[j][1]);
  return D;
}

/// The skeleton of a figure-eight from its points and from their distance matrix D: the same complex and
/// skeleton (two loops; every point a member once).
void expect_matrix_skeleton_as_points(const std::vector<std::array<double, 2>>& p, const Eigen::MatrixXd& D) {
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton from_points = extract_reeb_skeleton(p, 0.7, o);
  const Reeb_skeleton from_matrix = extract_reeb_skeleton_from_distance_matrix(D, 0.7, o);
  EXPECT_EQ(from_matrix.rips_edges, from_points.rips_edges);
  EXPECT_EQ(from_matrix.rips_triangles, from_points.rips_triangles);
  EXPECT_EQ(from_matrix.level_width, from_points.level_width);
  EXPECT_EQ(num_vertices(from_matrix.graph), num_vertices(from_points.graph));
  EXPECT_EQ(num_edges(from_matrix.graph), num_edges(from_points.graph));
  EXPECT_EQ(loops_of(from_matrix.graph), 2u);
  expect_members_partition(from_matrix.graph, p.size());
}

}  // namespace

TEST(ExtractReebSkeleton, CopiesInADistanceMatrixAreJoinedAsCopiesOfPoints) {
  // Rows at distance 0 with equal rows are copies: joined as copies of points are (first copy, its
  // neighbours, the previous copy), not as a clique. 1000 copies of one point were 1.7 * 10^8 triangles,
  // refused by the limit.
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(1000, 1000);
  const Reeb_skeleton one_place = extract_reeb_skeleton_from_distance_matrix(zero, 1.0);
  ASSERT_EQ(one_place.status, Status::success);
  EXPECT_EQ(num_vertices(one_place.graph), 1u);
  EXPECT_LT(one_place.rips_triangles, 1000u);
  expect_members_partition(one_place.graph, 1000);
  // A figure-eight with copies, as points and as their distance matrix: the same complex and skeleton.
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  std::vector<std::array<double, 2>> p = eight.points;
  for (std::size_t k = 0; k < 30; ++k) p.push_back(eight.points[7]);
  for (std::size_t i = 0; i < eight.points.size(); i += 3) p.push_back(eight.points[i]);
  expect_matrix_skeleton_as_points(p, planar_distance_matrix(p));
  // Rows at distance 0 whose other distances differ are not copies (a matrix that is not a metric): they
  // count for the level width like any other (40 points on a line, 2i and 2i + 1 at distance 0: median 1, not
  // 2).
  Eigen::MatrixXd pairs(40, 40);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) pairs(i, j) = i / 2 == j / 2 && i != j ? 0.0 : std::abs(i - j);
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(pairs, 2.5).level_width, 1.0);
}

TEST(ExtractReebSkeleton, DistanceMatrixAndGraphInputsAgreeWithPoints) {
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  const std::size_t n = eight.points.size();
  const Eigen::MatrixXd D = planar_distance_matrix(eight.points);
  expect_matrix_skeleton_as_points(eight.points, D);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton from_points = extract_reeb_skeleton(eight.points, 0.7, o);
  // Classical MDS of planar distances recovers them (up to rounding).
  std::vector<double> flat(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) flat[i * n + j] = D(i, j);
  const auto mds = classical_mds_3d(flat, n);
  for (std::size_t i = 0; i < n; i += 7)
    for (std::size_t j = 0; j < n; j += 5)
      EXPECT_NEAR(std::hypot(mds[i][0] - mds[j][0], mds[i][1] - mds[j][1]) + std::fabs(mds[i][2] - mds[j][2]),
                  D(i, j), 1e-6);
  // The same Rips graph handed over as a graph with coordinates.
  const Point_matrix m = make_point_matrix(eight.points);
  const Reeb_skeleton from_graph = extract_reeb_skeleton(build_rips_graph(m, 0.7), m, o);
  EXPECT_EQ(num_edges(from_graph.graph), num_edges(from_points.graph));
  EXPECT_EQ(loops_of(from_graph.graph), 2u);
  // The coordinates as a range of points, as the points overloads take them: the same skeleton.
  const Reeb_skeleton from_range = extract_reeb_skeleton(build_rips_graph(m, 0.7), eight.points, o);
  ASSERT_EQ(num_edges(from_range.graph), num_edges(from_graph.graph));
  for (auto v : boost::make_iterator_range(vertices(from_graph.graph))) {
    EXPECT_EQ(from_range.graph[v].position, from_graph.graph[v].position);
    EXPECT_EQ(from_range.graph[v].members, from_graph.graph[v].members);
  }
  auto shorter = eight.points;
  shorter.pop_back();
  EXPECT_TRUE(contains(FeatureRecon::test::invalid_argument_message(
                           [&] { extract_reeb_skeleton(build_rips_graph(m, 0.7), shorter, o); }),
                       "vertices but coordinates has"));
  // Bad input: a matrix that is not symmetric, coordinates that do not match the graph.
  Eigen::MatrixXd bad = D;
  bad(0, 1) += 1;
  EXPECT_THROW(extract_reeb_skeleton_from_distance_matrix(bad, 0.7, o), std::invalid_argument);
  Point_matrix short_m = m;
  short_m.rows -= 1;
  EXPECT_THROW(extract_reeb_skeleton(build_rips_graph(m, 0.7), short_m, o), std::invalid_argument);
}

TEST(ExtractReebSkeleton, IsolatedPointsAreCounted) {
  // Reeb_skeleton::isolated_points: points without a neighbour at a positive distance in the complex. 20
  // points 1 apart on a line, a pair of copies at (50, 0) and a point at (60, 0).
  std::vector<std::array<double, 2>> p;
  for (int i = 0; i < 20; ++i) p.push_back({double(i), 0.0});
  p.push_back({50.0, 0.0});
  p.push_back({50.0, 0.0});
  p.push_back({60.0, 0.0});
  // Below the spacing every point is alone (the copies are joined, at distance 0: alone too), and each
  // place is a node of its own; the status stays success.
  const Reeb_skeleton below = extract_reeb_skeleton(p, 0.9);
  ASSERT_EQ(below.status, Status::success);
  EXPECT_EQ(below.isolated_points, 23u);
  EXPECT_EQ(num_vertices(below.graph), 22u);
  // At the spacing (inclusive) the line joins up: the copies and the far point stay alone.
  EXPECT_EQ(extract_reeb_skeleton(p, 1.0).isolated_points, 3u);
  EXPECT_EQ(extract_reeb_skeleton(p, 10.0).isolated_points, 0u);
  // The same counts from the distance matrix and from a graph (a vertex without edges).
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(planar_distance_matrix(p), 1.0).isolated_points, 3u);
  const Point_matrix m = make_point_matrix(p);
  EXPECT_EQ(extract_reeb_skeleton(build_rips_graph(m, 1.0), m).isolated_points, 3u);
  // The estimated radius joins them.
  EXPECT_EQ(extract_reeb_skeleton(p, Skeleton_options{}).isolated_points, 0u);
}

TEST(ExtractReebSkeleton, StubsAtTheBasePointAreTrimmedOnLoops) {
  // A noisy circle: with trimming (default) the skeleton is one cycle without spurs; without it, the global
  // minimum and maximum each hang off the cycle on a short spur.
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i < 200; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 200;
    pts.push_back({5 * std::cos(a) + 0.02 * std::sin(7.0 * i), 5 * std::sin(a) + 0.02 * std::cos(5.0 * i)});
  }
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton trimmed = extract_reeb_skeleton(pts, 0.7, o);
  EXPECT_EQ(loops_of(trimmed.graph), 1u);
  for (auto v : boost::make_iterator_range(vertices(trimmed.graph))) EXPECT_EQ(degree(v, trimmed.graph), 2u);
  expect_members_partition(trimmed.graph, pts.size());
  o.trim_stubs = false;
  const Reeb_skeleton raw = extract_reeb_skeleton(pts, 0.7, o);
  std::size_t leaves = 0;
  for (auto v : boost::make_iterator_range(vertices(raw.graph))) leaves += degree(v, raw.graph) == 1 ? 1 : 0;
  EXPECT_EQ(leaves, 2u);
  EXPECT_EQ(trimmed.trimmed_stubs, 2u);
}

// The pipeline through every kernel's points: the same skeleton as from std::array points.
template <class Point>
class ExtractReebSkeletonKernels : public ::testing::Test {};
using Skeleton_kernel_points =
    ::testing::Types<CGAL::Simple_cartesian<double>::Point_2, CGAL::Epick::Point_2, CGAL::Epeck::Point_2>;
TYPED_TEST_SUITE(ExtractReebSkeletonKernels, Skeleton_kernel_points);

TYPED_TEST(ExtractReebSkeletonKernels, SameSkeletonAsPlainArrays) {
  const auto eight = sample_segments(figure_eight_segments(), 0.3, 0.05, 4);
  std::vector<TypeParam> points;
  for (const auto& p : eight.points) points.emplace_back(p[0], p[1]);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton a = extract_reeb_skeleton(eight.points, 0.7, o);
  const Reeb_skeleton b = extract_reeb_skeleton(points, 0.7, o);
  EXPECT_EQ(b.rips_edges, a.rips_edges);
  EXPECT_EQ(b.rips_triangles, a.rips_triangles);
  ASSERT_EQ(num_vertices(b.graph), num_vertices(a.graph));
  ASSERT_EQ(num_edges(b.graph), num_edges(a.graph));
  for (std::size_t v = 0; v < num_vertices(a.graph); ++v) EXPECT_EQ(b.graph[v].position, a.graph[v].position);
  EXPECT_EQ(loops_of(b.graph), 2u);
}

namespace {
// Degrees of a skeleton's nodes: {number of degree 3, number of degree 4}.
std::pair<int, int> fork_degrees(const Skeleton_graph& g) {
  int three = 0, four = 0;
  for (auto v : boost::make_iterator_range(vertices(g))) {
    three += degree(v, g) == 3;
    four += degree(v, g) == 4;
  }
  return {three, four};
}
}  // namespace

TEST(ExtractReebSkeleton, AutomaticBranchMergeDistanceIsInCoordinateUnitsForGraphs) {
  // An H drawn as a graph: two bars of 101 vertices 50 steps apart, joined at their middles by 49 vertices,
  // the steps s apart in coordinates. With unit edge weights the level width is 1 whatever s; the automatic
  // merge distance was 2 of those read as coordinates, so at s = 0.01 the crossbar (0.5 long) was contracted
  // and the H became an X. Now it is 2 s, as with Euclidean weights: two forks, five arcs, nothing merged at
  // every scale.
  for (const double s : {1.0, 0.01}) {
    for (const bool unit_weights : {true, false}) {
      Point_matrix m;
      m.dimension = 2;
      auto add = [&](double x, double y) {
        m.data.push_back(x * s);
        m.data.push_back(y * s);
        return static_cast<Vertex_index>(m.rows++);
      };
      std::vector<Vertex_index> left, right, middle;
      for (int y = 0; y <= 100; ++y) left.push_back(add(0, y));
      for (int y = 0; y <= 100; ++y) right.push_back(add(50, y));
      for (int x = 1; x < 50; ++x) middle.push_back(add(x, 50));
      std::vector<Edge> e;
      for (int y = 0; y < 100; ++y) {
        e.push_back({left[y], left[y + 1]});
        e.push_back({right[y], right[y + 1]});
      }
      e.push_back({left[50], middle.front()});
      for (std::size_t k = 0; k + 1 < middle.size(); ++k) e.push_back({middle[k], middle[k + 1]});
      e.push_back({middle.back(), right[50]});
      const Simplicial_complex_2 c = make_simplicial_complex_2(m.rows, e, {});
      Proximity_graph g;
      g.number_of_vertices = c.number_of_vertices;
      g.edges = c.edges;
      if (!unit_weights)
        for (const Edge& ed : g.edges)
          g.edge_lengths.push_back(skeleton::internal::euclidean_distance(m, ed[0], ed[1]));
      const Reeb_skeleton r = extract_reeb_skeleton(g, m);
      EXPECT_NEAR(r.branch_merge_distance, 2 * s, 1e-12 * s) << s << " " << unit_weights;
      EXPECT_EQ(r.merged_branch_arcs, 0u) << s << " " << unit_weights;
      EXPECT_EQ(num_vertices(r.graph), 6u) << s << " " << unit_weights;
      EXPECT_EQ(num_edges(r.graph), 5u) << s << " " << unit_weights;
      EXPECT_EQ(fork_degrees(r.graph), std::make_pair(2, 0)) << s << " " << unit_weights;
    }
  }
}

TEST(ExtractReebSkeleton, BranchMergeOfADistanceMatrixMeasuresTheMatrix) {
  // An H in R^5: two spirals (large extent in e1..e3) joined at their middles by a crossbar 2 long along e5,
  // a direction of little variance, so classical MDS draws the crossbar with no length (the forks 3e-14
  // apart) and the merge contracted it: from points 2 forks, from their exact distance matrix one node of
  // degree 4. The matrix's own distance between the nodes' points now bounds the arc's length from below: the
  // same H.
  const double h = 0.1, bar = 2;
  Point_matrix m;
  m.dimension = 5;
  auto add = [&](std::array<double, 5> p) {
    m.data.insert(m.data.end(), p.begin(), p.end());
    ++m.rows;
  };
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 300; ++i) {
      const double t = i * h;
      add({5 * std::cos(t / 5), 5 * std::sin(t / 5), 0.6 * t, 0, side * bar});
    }
  for (int i = 1; i < 20; ++i) add({5 * std::cos(3.0), 5 * std::sin(3.0), 9.0, 0, i * h});
  const double radius = 0.25;
  const Reeb_skeleton points = extract_reeb_skeleton(m, radius);
  std::vector<std::vector<double>> D(m.rows, std::vector<double>(m.rows));
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t j = i + 1; j < m.rows; ++j)
      D[i][j] = D[j][i] = skeleton::internal::point_distance(m.row(i), m.row(j), 5);
  const Reeb_skeleton matrix = extract_reeb_skeleton_from_distance_matrix(D, radius);
  for (const Reeb_skeleton* r : {&points, &matrix}) {
    EXPECT_EQ(r->merged_branch_arcs, 0u);
    EXPECT_EQ(num_vertices(r->graph), 6u);
    EXPECT_EQ(num_edges(r->graph), 5u);
    EXPECT_EQ(fork_degrees(r->graph), std::make_pair(2, 0));
  }
  EXPECT_EQ(points.branch_merge_distance, matrix.branch_merge_distance);
}

// A triangle of forks joined by short arcs: a round contracts a matching (the shortest arc), and the two arcs
// then joining the merged node to the third fork are a short loop, which stays; no arc becomes a self-loop.
TEST(MergeCloseBranchNodes, ATriangleOfForksKeepsItsLoop) {
  Point_matrix p;
  p.dimension = 2;
  p.data = {0, 0, 0.1, 0, 0, 0.12, -1, -1, 1, -1, 0, 2};
  p.rows = 6;
  Skeleton_graph g(6);  // forks 0, 1, 2 (arcs 0.1, 0.12 and 0.156 long), each with a leaf 3, 4, 5
  const double values[6] = {1, 1.1, 1.2, 0, 0, 3};
  for (std::size_t v = 0; v < 6; ++v) {
    g[v].position = {p.row(v)[0], p.row(v)[1], 0};
    g[v].value = values[v];
    g[v].members = {static_cast<Vertex_index>(v)};
  }
  for (const auto& [a, b] :
       std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}, {0, 2}, {1, 2}, {3, 0}, {4, 1}, {2, 5}})
    add_edge(a, b, Skeleton_arc{{g[a].position, g[b].position}, {}, {}, a, b}, g);
  const Branch_node_merge_result r = merge_close_branch_nodes(g, p, 0.2);
  EXPECT_EQ(r.merged, 1u);
  ASSERT_EQ(num_vertices(r.graph), 5u);
  EXPECT_EQ(num_edges(r.graph), 5u);
  std::size_t between = 0;
  for (auto e : boost::make_iterator_range(edges(r.graph))) {
    EXPECT_NE(source(e, r.graph), target(e, r.graph));
    between += (source(e, r.graph) == 0 && target(e, r.graph) == 1) ? 1 : 0;
  }
  EXPECT_EQ(between, 2u);  // the merged node 0 and the third fork (now 1): the loop
  EXPECT_EQ(r.graph[0].members, (std::vector<Vertex_index>{0, 1}));
  expect_members_partition(r.graph, 6);
}

// A merged node takes the value and leading members of its lowest node, the smaller index on a tie, and sits
// at the centroid of all its points (here off the mean of the two forks).
TEST(MergeCloseBranchNodes, TiesGoToTheSmallerIndexAndTheNodeSitsAtTheCentroid) {
  Crossing x;
  x.graph[3].value = 1.0;  // the forks at one value
  const Branch_node_merge_result tie = merge_close_branch_nodes(x.graph, x.points, 0.2);
  ASSERT_EQ(tie.merged, 1u);
  EXPECT_EQ(tie.graph[2].value, 1.0);
  EXPECT_EQ(tie.graph[2].members, (std::vector<Vertex_index>{2, 3, 6}));
  // The arc's point moved off the line between the forks: the centroid moves a third of the way.
  Crossing off;
  off.points.data[12] = 0.03;
  for (auto e : boost::make_iterator_range(edges(off.graph)))
    if (off.graph[e].members == std::vector<Vertex_index>{6}) off.graph[e].polyline[1] = {0.03, 0, 0};
  const Branch_node_merge_result c = merge_close_branch_nodes(off.graph, off.points, 0.2);
  ASSERT_EQ(c.merged, 1u);
  EXPECT_NEAR(c.graph[2].position[0], 0.01, 1e-15);
  EXPECT_NEAR(c.graph[2].position[1], 0.0, 1e-15);
}

// Each node's first member is its own vertex of the Reeb graph (of a merged node, its lowest node's), whose
// function value is the node's value.
TEST(ExtractReebSkeleton, ANodesFirstMemberIsItsVertex) {
  const auto eight = sample_segments(figure_eight_segments(), 0.25, 0.15, 4);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton one = extract_reeb_skeleton(eight.points, 0.7, o);
  ASSERT_EQ(one.merged_branch_arcs, 1u);
  const Point_matrix P = make_point_matrix(eight.points);
  const Geodesic_result geo = compute_geodesic_function(build_flag_complex_2(build_rips_graph(P, 0.7)));
  std::size_t with_level_sets = 0;
  for (auto v : boost::make_iterator_range(vertices(one.graph))) {
    ASSERT_FALSE(one.graph[v].members.empty());
    with_level_sets += one.graph[v].members.size() > 1 ? 1 : 0;
    EXPECT_EQ(one.graph[v].value, geo.values[one.graph[v].members.front()]) << v;
  }
  EXPECT_GT(with_level_sets, 2u);
}

namespace {
/// Three forks in a row, a (node 0), b (1) and c (2) at the given x, joined by the arcs a-b (added first) and
/// b-c; a and c have two leaves each, b one, so that every fork has degree 3. Point i is node i's member.
struct Three_forks {
  Point_matrix points;
  Skeleton_graph graph;
  explicit Three_forks(const std::array<double, 3>& x) {
    points.dimension = 2;
    points.data = {x[0], 0, x[1], 0, x[2], 0, -1, -1, -1, 1, 0.05, 1, 1, 1, 1, -1};
    points.rows = 8;
    const double values[8] = {1, 1.1, 1.2, 0, 0, 2, 3, 3};
    graph = Skeleton_graph(8);
    for (std::size_t v = 0; v < 8; ++v) {
      graph[v].position = {points.row(v)[0], points.row(v)[1], 0};
      graph[v].value = values[v];
      graph[v].members = {static_cast<Vertex_index>(v)};
    }
    for (const auto& [a, b] : std::vector<std::pair<std::size_t, std::size_t>>{
             {0, 1}, {1, 2}, {3, 0}, {4, 0}, {1, 5}, {2, 6}, {2, 7}})
      add_edge(a, b, Skeleton_arc{{graph[a].position, graph[b].position}, {}, {}, a, b}, graph);
  }
};
}  // namespace

// Shortest first: the arc b-c (0.08) is contracted before a-b (0.12, the earlier arc), and a cannot join
// afterwards (a and c lie 0.2 apart, beyond the distance 0.15).
TEST(MergeCloseBranchNodes, TheShortestArcIsContractedFirst) {
  const Three_forks t({0, 0.12, 0.2});
  const Branch_node_merge_result r = merge_close_branch_nodes(t.graph, t.points, 0.15);
  EXPECT_EQ(r.merged, 1u);
  ASSERT_EQ(num_vertices(r.graph), 7u);
  EXPECT_EQ(r.graph[0].members, std::vector<Vertex_index>{0});
  EXPECT_EQ(r.graph[1].members, (std::vector<Vertex_index>{1, 2}));
}

// With a metric (a distance matrix drawn by MDS): an arc is as long as the metric between its nodes when the
// drawing is shorter, so b-c (0.1) goes before a-b (drawn 0.01, metric 0.15); and a merged group stays within
// the distance by the metric too: a, 0.11 from c in the drawing but 0.3 by the metric, does not join.
TEST(MergeCloseBranchNodes, TheMetricLengthensArcsAndBoundsGroups) {
  const Three_forks t({0, 0.01, 0.11});
  std::vector<std::array<double, 3>> positions;
  for (std::size_t i = 0; i < t.points.rows; ++i)
    positions.push_back({t.points.row(i)[0], t.points.row(i)[1], 0});
  const std::function<double(Vertex_index, Vertex_index)> metric = [&](Vertex_index i, Vertex_index j) {
    const Vertex_index lo = std::min(i, j), hi = std::max(i, j);
    if (lo == 0 && hi == 1) return 0.15;
    if (lo == 1 && hi == 2) return 0.1;
    if (lo == 0 && hi == 2) return 0.3;
    return skeleton::internal::euclidean_distance(t.points, i, j);
  };
  const Branch_node_merge_result r =
      skeleton::internal::merge_close_branch_nodes(t.graph, positions, t.points, 0.2, "test", metric);
  EXPECT_EQ(r.merged, 1u);
  ASSERT_EQ(num_vertices(r.graph), 7u);
  EXPECT_EQ(r.graph[0].members, std::vector<Vertex_index>{0});
  EXPECT_EQ(r.graph[1].members, (std::vector<Vertex_index>{1, 2}));
  // Without the metric the drawing alone decides: a-b first, then c joins (0.11 from a).
  const Branch_node_merge_result drawn = merge_close_branch_nodes(t.graph, t.points, 0.2);
  EXPECT_EQ(drawn.merged, 2u);
  EXPECT_EQ(num_vertices(drawn.graph), 6u);
}

// With a repair distance the pipeline simplifies again after repair_reeb_graph() and connect_dead_ends(), and
// its counts are those of the stages called one after another: a street with a spur below it (height 1.5)
// and a short stem above it across a gap of 1, which connect_dead_ends() joins. At delta 1 only the second
// simplification removes a branch, at delta 2 only the first.
TEST(ExtractReebSkeleton, TheSecondSimplificationCountsAsTheStagesDo) {
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i <= 40; ++i) pts.push_back({0.5 * i, 0.0});  // the street, x 0..20
  for (int i = 3; i <= 6; ++i) pts.push_back({10.0, 0.5 * i});  // the stem, y 1.5..3
  for (int i = 1; i <= 3; ++i) pts.push_back({5.0, -0.5 * i});  // the spur
  const Point_matrix P = make_point_matrix(pts);
  const auto distance = [&P](Vertex_index a, Vertex_index b) {
    return skeleton::internal::euclidean_distance(P, a, b);
  };
  const Simplicial_complex_2 K = build_flag_complex_2(build_rips_graph(P, 0.6));
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, compute_geodesic_function(K).values);
  for (const double delta : {1.0, 2.0}) {
    Skeleton_options o;
    o.delta = delta;
    o.repair_distance = 2.0;
    o.branch_merge_distance = 0.0;
    const Reeb_skeleton one = extract_reeb_skeleton(pts, 0.6, o);
    const Reeb_simplification_result S1 = simplify_by_persistence(A, delta);
    const Reeb_repair_result fixed = repair_reeb_graph(S1.graph, 2.0, distance);
    const Reeb_dead_end_result ends = connect_dead_ends(fixed.graph, A.values(), 2.0, distance);
    const Reeb_simplification_result S2 = simplify_by_persistence(ends.graph, A.values(), delta);
    const Reeb_trim_result T = trim_essential_stubs(S2.graph, delta);
    EXPECT_EQ(one.repaired, fixed.joined) << delta;
    EXPECT_EQ(one.connected_dead_ends, ends.connected) << delta;
    EXPECT_EQ(one.removed_branches, S1.removed_branches + S2.removed_branches) << delta;
    EXPECT_EQ(one.removed_loops, S1.removed_loops + S2.removed_loops) << delta;
    EXPECT_EQ(num_vertices(one.graph), T.graph.nodes.size()) << delta;
    EXPECT_EQ(num_edges(one.graph), T.graph.arcs.size()) << delta;
    // Each simplification has something to do at one of the two deltas.
    EXPECT_GT(delta == 1.0 ? S2.removed_branches : S1.removed_branches, 0u) << delta;
  }
}

namespace {
/// A caterpillar: a spine of `k` forks 0.01 apart on the x axis (f = x) with a leg up to (x, 1) at each (two
/// at the ends), every node its own point; the spine arcs are the merge's candidates.
struct Caterpillar {
  Point_matrix points;
  Skeleton_graph graph;
  explicit Caterpillar(std::size_t k) {
    points.dimension = 2;
    std::vector<std::array<double, 2>> p;
    for (std::size_t i = 0; i < k; ++i) p.push_back({0.01 * double(i), 0.0});
    std::vector<std::pair<std::size_t, std::size_t>> legs;
    for (std::size_t i = 0; i < k; ++i)
      for (int twice = 0; twice < (i == 0 || i + 1 == k ? 2 : 1); ++twice) {
        legs.push_back({i, p.size()});
        p.push_back({0.01 * double(i) + 0.001 * twice, 1.0});
      }
    for (const auto& q : p) points.data.insert(points.data.end(), {q[0], q[1]});
    points.rows = p.size();
    graph = Skeleton_graph(p.size());
    for (std::size_t v = 0; v < p.size(); ++v) {
      graph[v].position = {p[v][0], p[v][1], 0};
      graph[v].value = v < k ? p[v][0] : 1 + p[v][0];
      graph[v].members = {static_cast<Vertex_index>(v)};
    }
    auto arc = [&](std::size_t a, std::size_t b) {
      Skeleton_arc s;
      s.polyline = {graph[a].position, graph[b].position};
      s.lower = a;
      s.upper = b;
      add_edge(a, b, std::move(s), graph);
    };
    for (std::size_t i = 0; i + 1 < k; ++i) arc(i, i + 1);
    for (const auto& [a, b] : legs) arc(a, b);
  }
};
}  // namespace

TEST(MergeCloseBranchNodes, ReportsEachRoundAndAStopLeavesTheInput) {
  // 16 forks in a row merge into one node in rounds of matchings (8, 4, 2, 1 contractions): a report after
  // the candidates (0.1), at each later round by the share of candidates settled, before the new graph (0.9)
  // and at the end.
  const Caterpillar c(16);
  const Branch_node_merge_result plain = merge_close_branch_nodes(c.graph, c.points, 1.0);
  ASSERT_EQ(plain.status, Status::success);
  EXPECT_EQ(plain.merged, 15u);
  EXPECT_EQ(num_vertices(plain.graph), num_vertices(c.graph) - 15);
  std::vector<double> seen;
  Branch_node_merge_options o;
  o.progress = test::recording_progress(seen);
  const Branch_node_merge_result watched = merge_close_branch_nodes(c.graph, c.points, 1.0, o);
  EXPECT_EQ(watched.merged, 15u);
  EXPECT_EQ(skeleton_signature(watched.graph), skeleton_signature(plain.graph));
  ASSERT_GE(seen.size(), 6u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.1);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_GE(std::count_if(seen.begin(), seen.end(), [](double t) { return t > 0.1 && t < 0.9; }), 3);
  for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
    std::size_t calls = 0;
    o.progress = [&calls, i](double) { return calls++ != i; };
    const Branch_node_merge_result s = merge_close_branch_nodes(c.graph, c.points, 1.0, o);
    EXPECT_EQ(s.status, Status::interrupted) << "stopped at " << seen[i];
    EXPECT_EQ(s.merged, 0u) << "stopped at " << seen[i];
    EXPECT_EQ(skeleton_signature(s.graph), skeleton_signature(c.graph)) << "stopped at " << seen[i];
    EXPECT_EQ(num_vertices(s.graph), num_vertices(c.graph)) << "stopped at " << seen[i];
    EXPECT_EQ(calls, i + 1) << "stopped at " << seen[i];
  }
  // Without candidates: the start, the end of the (no) rounds and the end.
  seen.clear();
  o.progress = test::recording_progress(seen);
  EXPECT_EQ(merge_close_branch_nodes(c.graph, c.points, 0.001, o).merged, 0u);
  EXPECT_EQ(seen, (std::vector<double>{0.1, 0.9, 1.0}));
}
