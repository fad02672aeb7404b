// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Issue 3, section 5: skeletons of noisy samples of a random tree and of a figure-eight embedded in R^50. The
// skeleton must have the true branch nodes and loops, and lie within a stated Hausdorff distance of the true
// graph (both directions), measured in R^50 on the input-space polylines.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "high_dimensional_graphs.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

/// Largest distance from a skeleton vertex (input space) to the true graph, and from a dense sample of the
/// true graph to the skeleton's polylines: the two halves of the Hausdorff distance.
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
// Rips radius r = 0.7, the Hausdorff distance between the skeleton and the true graph is at most 0.7 r
// (0.49), measured both ways along the polylines, not only at their vertices. What limits it: at a bend a
// level-set piece holds points of both legs up to about r from the corner, and its centroid cuts the corner,
// the more the sharper the bend. Random directions in R^50 meet at 90 +- 8 degrees; over 1000 random trees
// the worst distance was 0.442 (0.63 r, seed 9, a bend of 62 degrees; mean 0.25 at bends of 90-95 degrees,
// 0.38 at 65-70); 0.6 r failed 7 of them, all at bends of 58-70 degrees. The figure-eights stay under 0.15:
// their circles bend little.
constexpr double rips_radius = 0.7;
constexpr double hausdorff_bound = 0.7 * rips_radius;
// The figure-eight's touching point is one node of degree 4 within one sample spacing of it: its position
// comes from the few samples around it (measured: 0.02-0.10 with these samples, which take each vertex of the
// 64-gons twice, their edges being shorter than the spacing; 0.10-0.15 with one sample every 0.25 along the
// circles, where the node's three members lie on one side of the point).
constexpr double sample_spacing = 0.25;

TEST(HighDimensionalSkeleton, RandomTreesInR50) {
  for (const std::uint32_t seed :
       {1u, 2u, 3u, 4u, 5u, 9u}) {  // 9: the sharpest bend of 1000 seeds, the worst
    const Segment_graph tree = random_tree(50, 9, seed);
    const Point_matrix points = tree.noisy_sample(sample_spacing, 0.01, seed);
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
    for (auto v : boost::make_iterator_range(vertices(s.graph)))
      EXPECT_EQ(s.graph[v].input_position.size(), 50u);
  }
}

// Both samplings of the figure-eight: the fixture's (every 64-gon vertex twice) and one sample every 0.25
// along the circles, where the touching point's node lies 0.10-0.15 away (0.1 was stated before: it failed
// there).
class HighDimensionalFigureEight : public ::testing::TestWithParam<bool> {};

TEST_P(HighDimensionalFigureEight, InR50) {
  const bool along = GetParam();
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const Segment_graph eight = figure_eight(50, 2.0, seed);
    const Point_matrix points = eight.noisy_sample(sample_spacing, 0.01, seed, along);
    EXPECT_EQ(points.rows, along ? 101u : 256u);
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
      if (degree(v, s.graph) == 4) {  // at the touching point, the origin
        ASSERT_EQ(s.graph[v].input_position.size(), 50u);
        EXPECT_LT(FeatureRecon::skeleton::internal::point_distance(s.graph[v].input_position.data(),
                                                                   eight.vertices[0].data(), 50),
                  sample_spacing)
            << "seed " << seed;
      }
    const auto [to_truth, to_skeleton] = hausdorff(s.graph, eight);
    EXPECT_LE(to_truth, hausdorff_bound) << "seed " << seed;
    EXPECT_LE(to_skeleton, hausdorff_bound) << "seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Samplings, HighDimensionalFigureEight, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? std::string("OnceAlongTheCircles") : std::string("PerSegment");
                         });

TEST(HighDimensionalSkeleton, EachPolylineIsTheProjectionOfItsInputPolyline) {
  // Skeleton_arc::polyline is the PCA projection of Skeleton_arc::input_polyline, point for point. The two
  // were drawn separately, each bridging the gaps wider than max_gap measured in its own space: with copies
  // among the points (the automatic max_gap then came from the projection) the input polylines got extra
  // bridge points (a review: 42 arcs of 150 noisy random walks in R^7). The projection is affine, so an
  // affine map fitted to the input points and their projection must carry every input polyline onto its
  // polyline.
  std::size_t arcs = 0, long_arcs = 0;
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    Portable_gaussian g(seed);
    const std::size_t d = 7;
    std::vector<std::vector<double>> walk;
    std::vector<double> at(d, 0.0);
    const std::size_t n = 20 + g.next() % 150;
    for (std::size_t i = 0; i < n; ++i) {
      if (g.next() % 15 == 0 && !walk.empty()) at = walk[g.next() % walk.size()];  // a branch
      for (double& c : at) c += 0.3 * (static_cast<int>(g.next() % 3) - 1);
      std::vector<double> x = at;
      for (double& c : x) c += 0.05 * g();
      walk.push_back(x);
      if (g.next() % 10 == 0) walk.push_back(x);  // a copy
    }
    Skeleton_options o;
    o.delta = 0.5 * (seed % 3);
    o.repair_distance = seed % 2 == 1 ? 1.0 : 0.0;
    const Reeb_skeleton s = extract_reeb_skeleton(walk, 0.6, o);
    ASSERT_EQ(s.status, Status::success);
    const Point_matrix points = make_point_matrix(walk);
    const std::vector<std::array<double, 3>> projected = project_to_3d(points);
    // The affine map x -> A^T [x, 1] with the least squared error over the points (exact up to rounding).
    Eigen::MatrixXd X(points.rows, d + 1), Y(points.rows, 3);
    for (std::size_t i = 0; i < points.rows; ++i) {
      for (std::size_t c = 0; c < d; ++c) X(Eigen::Index(i), Eigen::Index(c)) = points.row(i)[c];
      X(Eigen::Index(i), Eigen::Index(d)) = 1;
      for (std::size_t c = 0; c < 3; ++c) Y(Eigen::Index(i), Eigen::Index(c)) = projected[i][c];
    }
    const Eigen::MatrixXd A = X.colPivHouseholderQr().solve(Y);
    auto expect_projection = [&](const double* x, const std::array<double, 3>& y, const std::string& what) {
      Eigen::VectorXd v(d + 1);
      for (std::size_t c = 0; c < d; ++c) v[Eigen::Index(c)] = x[c];
      v[Eigen::Index(d)] = 1;
      const Eigen::VectorXd z = A.transpose() * v;
      for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(z[Eigen::Index(c)], y[c], 1e-9) << what;
    };
    for (auto v : boost::make_iterator_range(vertices(s.graph))) {
      ASSERT_EQ(s.graph[v].input_position.size(), d);
      expect_projection(s.graph[v].input_position.data(), s.graph[v].position,
                        "seed " + std::to_string(seed) + " node " + std::to_string(v));
    }
    for (auto e : boost::make_iterator_range(edges(s.graph))) {
      const Skeleton_arc& a = s.graph[e];
      const std::string what =
          "seed " + std::to_string(seed) + " arc " + std::to_string(a.lower) + "-" + std::to_string(a.upper);
      ASSERT_EQ(a.input_polyline.size(), d * a.polyline.size()) << what;
      for (std::size_t i = 0; i < a.polyline.size(); ++i)
        expect_projection(a.input_polyline.data() + d * i, a.polyline[i],
                          what + " point " + std::to_string(i));
      ++arcs;
      if (a.polyline.size() > 2) ++long_arcs;
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(arcs, 200u);
  EXPECT_GT(long_arcs, 100u);
}

TEST(HighDimensionalSkeleton, MoreNoiseBreaksTheBound) {
  // The bound is not vacuous: ten times the noise (displacement about 0.7 = the Rips radius) violates it or
  // changes the topology; so does a figure-eight whose skeleton is compared with another figure-eight.
  const Segment_graph eight = figure_eight(50, 2.0, 1);
  const Point_matrix points = eight.noisy_sample(sample_spacing, 0.1, 1);
  Skeleton_options o;
  o.delta = 1.0;
  const Reeb_skeleton s = extract_reeb_skeleton(points, rips_radius, o);
  const Topology t = topology(s.graph);
  const auto [to_truth, to_skeleton] = hausdorff(s.graph, eight);
  EXPECT_TRUE(t.loops != 2 || to_truth > hausdorff_bound || to_skeleton > hausdorff_bound);
  const Reeb_skeleton clean =
      extract_reeb_skeleton(eight.noisy_sample(sample_spacing, 0.01, 1), rips_radius, o);
  const auto [a, b] = hausdorff(clean.graph, figure_eight(50, 2.0, 2));
  EXPECT_GT(std::max(a, b), hausdorff_bound);
}
