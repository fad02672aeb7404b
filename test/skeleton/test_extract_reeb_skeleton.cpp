// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include "skeleton_test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
std::size_t loops_of(const Skeleton_graph& g) {
  std::vector<int> comp(num_vertices(g));
  const std::size_t c = num_vertices(g) == 0 ? 0 : static_cast<std::size_t>(boost::connected_components(g, comp.data()));
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
  }
  // A tree (tree_segments(): 6 segments, leaves at (0,0), (-7,6), (4,13) and (8,10)): no loop, four leaves.
  const auto tree = sample_segments(tree_segments(), 0.3, 0.05, 6);
  const Reeb_skeleton t = extract_reeb_skeleton(tree.points, 0.7, o);
  EXPECT_EQ(loops_of(t.graph), 0u);
  std::size_t leaves = 0;
  for (auto v : boost::make_iterator_range(vertices(t.graph))) leaves += degree(v, t.graph) == 1 ? 1 : 0;
  EXPECT_EQ(leaves, 4u);
  expect_members_partition(t.graph, tree.points.size());
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
  EXPECT_EQ(extract_reeb_skeleton(std::vector<std::array<double, 2>>{}, 1.0).status, Status::degenerate_input);
  const Reeb_skeleton one = extract_reeb_skeleton(std::vector<std::array<double, 2>>{{1.0, 2.0}}, 1.0);
  EXPECT_EQ(num_vertices(one.graph), 1u);
  EXPECT_EQ(num_edges(one.graph), 0u);
  Skeleton_options bad;
  bad.delta = -1;
  EXPECT_THROW(extract_reeb_skeleton(std::vector<std::array<double, 2>>{{0.0, 0.0}}, 1.0, bad), std::invalid_argument);
}
