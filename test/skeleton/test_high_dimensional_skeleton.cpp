// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Issue 3, section 5: skeletons of noisy samples of a random tree and of a figure-eight embedded in R^50. The
// skeleton must have the true branch nodes and loops, and lie within a stated Hausdorff distance of the true
// graph (both directions), measured in R^50 on the input-space polylines.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "high_dimensional_graphs.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

struct Topology {
  std::size_t loops = 0, components = 0, leaves = 0, branch_excess = 0;  // branch_excess: sum of (degree - 2)
  std::vector<std::size_t> branch_degrees;  // degrees of the branch nodes (>= 3), sorted
};

Topology topology(const Skeleton_graph& g) {
  Topology t;
  std::vector<int> comp(num_vertices(g));
  t.components = num_vertices(g) == 0 ? 0 : static_cast<std::size_t>(boost::connected_components(g, comp.data()));
  t.loops = num_edges(g) + t.components - num_vertices(g);
  for (auto v : boost::make_iterator_range(vertices(g))) {
    const std::size_t d = degree(v, g);
    if (d == 1) ++t.leaves;
    if (d >= 3) {
      t.branch_excess += d - 2;
      t.branch_degrees.push_back(d);
    }
  }
  std::sort(t.branch_degrees.begin(), t.branch_degrees.end());
  return t;
}

/// Largest distance from a skeleton vertex (input space) to the true graph, and from a dense sample of the true
/// graph to the skeleton's polylines: the two halves of the Hausdorff distance.
std::pair<double, double> hausdorff(const Skeleton_graph& g, const Segment_graph& truth) {
  const std::size_t d = truth.dimension;
  std::vector<std::vector<double>> lines;
  for (auto e : boost::make_iterator_range(edges(g))) lines.push_back(g[e].input_polyline);
  double to_truth = 0;  // along every polyline segment, at most 0.05 apart
  std::vector<double> p(d);
  for (const auto& line : lines)
    for (std::size_t i = 0; i + d <= line.size(); i += d) {
      to_truth = std::max(to_truth, truth.distance(&line[i]));
      if (i + 2 * d > line.size()) continue;
      const double length = FeatureRecon::skeleton::internal::point_distance(&line[i], &line[i + d], d);
      const int steps = static_cast<int>(std::ceil(length / 0.05));
      for (int k = 1; k < steps; ++k) {
        for (std::size_t c = 0; c < d; ++c) p[c] = line[i + c] + (line[i + d + c] - line[i + c]) * k / steps;
        to_truth = std::max(to_truth, truth.distance(p.data()));
      }
    }
  double to_skeleton = 0;
  for (const auto& p : truth.sample(0.05)) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& line : lines)
      for (std::size_t i = 0; i + 2 * d <= line.size(); i += d)
        best = std::min(best, point_segment_distance(p.data(), &line[i], &line[i + d], d));
    to_skeleton = std::max(to_skeleton, best);
  }
  return {to_truth, to_skeleton};
}

}  // namespace

// The stated bound: with per-coordinate noise 0.01 in R^50 (displacement about 0.07), sample spacing 0.25 and
// Rips radius r = 0.7, the Hausdorff distance between the skeleton and the true graph is at most 0.6 r (0.42),
// measured both ways along the polylines, not only at their vertices. What limits it: at a bend (two segments at
// about 90 degrees, as random directions in R^50 are) a level-set piece holds points of both legs up to about r
// from the corner, and its centroid cuts the corner (measured: up to 0.35 for the trees; 0.06 for the
// figure-eights, whose circles bend little and whose touching point is one node).
constexpr double rips_radius = 0.7;
constexpr double hausdorff_bound = 0.6 * rips_radius;

TEST(HighDimensionalSkeleton, RandomTreesInR50) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const Segment_graph tree = random_tree(50, 9, seed);
    const Point_matrix points = tree.noisy_sample(0.25, 0.01, seed);
    Skeleton_options o;
    o.delta = 1.0;
    const Reeb_skeleton s = extract_reeb_skeleton(points, rips_radius, o);
    ASSERT_EQ(s.status, Status::success);
    EXPECT_EQ(s.dimension, 3u);
    const Topology t = topology(s.graph);
    EXPECT_EQ(t.components, 1u) << "seed " << seed;
    EXPECT_EQ(t.loops, 0u) << "seed " << seed;
    EXPECT_EQ(t.leaves, tree.leaves()) << "seed " << seed;
    EXPECT_EQ(t.branch_excess, tree.branch_excess()) << "seed " << seed;
    EXPECT_EQ(t.branch_degrees, tree.branch_degrees()) << "seed " << seed;  // the true branch nodes, one each
    const auto [to_truth, to_skeleton] = hausdorff(s.graph, tree);
    EXPECT_LE(to_truth, hausdorff_bound) << "seed " << seed;
    EXPECT_LE(to_skeleton, hausdorff_bound) << "seed " << seed;
    for (auto v : boost::make_iterator_range(vertices(s.graph))) EXPECT_EQ(s.graph[v].input_position.size(), 50u);
  }
}

TEST(HighDimensionalSkeleton, FigureEightInR50) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const Segment_graph eight = figure_eight(50, 2.0, seed);
    const Point_matrix points = eight.noisy_sample(0.25, 0.01, seed);
    Skeleton_options o;
    o.delta = 1.0;
    const Reeb_skeleton s = extract_reeb_skeleton(points, rips_radius, o);
    ASSERT_EQ(s.status, Status::success);
    const Topology t = topology(s.graph);
    EXPECT_EQ(t.components, 1u) << "seed " << seed;
    EXPECT_EQ(t.loops, 2u) << "seed " << seed;
    EXPECT_EQ(t.leaves, 0u) << "seed " << seed;
    EXPECT_EQ(t.branch_excess, 2u) << "seed " << seed;
    // The touching point is one node of degree 4 (the Reeb graph's two forks there, merged).
    EXPECT_EQ(t.branch_degrees, std::vector<std::size_t>{4}) << "seed " << seed;
    for (auto v : boost::make_iterator_range(vertices(s.graph)))
      if (degree(v, s.graph) == 4) {  // at the touching point, the origin (measured: 0.02-0.05 away)
        ASSERT_EQ(s.graph[v].input_position.size(), 50u);
        EXPECT_LT(FeatureRecon::skeleton::internal::point_distance(s.graph[v].input_position.data(),
                                                                    eight.vertices[0].data(), 50),
                  0.1)
            << "seed " << seed;
      }
    const auto [to_truth, to_skeleton] = hausdorff(s.graph, eight);
    EXPECT_LE(to_truth, hausdorff_bound) << "seed " << seed;
    EXPECT_LE(to_skeleton, hausdorff_bound) << "seed " << seed;
  }
}

TEST(HighDimensionalSkeleton, MoreNoiseBreaksTheBound) {
  // The bound is not vacuous: ten times the noise (displacement about 0.7 = the Rips radius) violates it or
  // changes the topology; so does a figure-eight whose skeleton is compared with another figure-eight.
  const Segment_graph eight = figure_eight(50, 2.0, 1);
  const Point_matrix points = eight.noisy_sample(0.25, 0.1, 1);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton s = extract_reeb_skeleton(points, rips_radius, o);
  const Topology t = topology(s.graph);
  const auto [to_truth, to_skeleton] = hausdorff(s.graph, eight);
  EXPECT_TRUE(t.loops != 2 || to_truth > hausdorff_bound || to_skeleton > hausdorff_bound);
  const Reeb_skeleton clean = extract_reeb_skeleton(eight.noisy_sample(0.25, 0.01, 1), rips_radius, o);
  const auto [a, b] = hausdorff(clean.graph, figure_eight(50, 2.0, 2));
  EXPECT_GT(std::max(a, b), hausdorff_bound);
}
