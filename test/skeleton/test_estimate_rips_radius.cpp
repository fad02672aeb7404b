// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// estimate_rips_radius(): the profile against brute-force counts, exact bins, scale invariance, copies,
// degenerate input, and the end-to-end property it is for: noisy samples of graphs in R^2, R^3 and R^50 give
// their true topology at the estimated radius and delta, and a fixed radius from the other samples would not.
#include <FeatureRecon/skeleton/estimate_rips_radius.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <Eigen/Core>

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "high_dimensional_graphs.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

constexpr double pi = 3.14159265358979323846;

using Row_major_matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The Euclidean distance matrix of the points.
Row_major_matrix distance_matrix_of(const Point_matrix& m) {
  Row_major_matrix D(static_cast<Eigen::Index>(m.rows), static_cast<Eigen::Index>(m.rows));
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t j = 0; j < m.rows; ++j)
      D(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          skeleton::internal::point_distance(m.row(i), m.row(j), m.dimension);
  return D;
}

void add_point(Point_matrix& m, std::initializer_list<double> p) {
  m.dimension = p.size();
  m.data.insert(m.data.end(), p.begin(), p.end());
  ++m.rows;
}

/// A circle of radius 10 in the plane, points at uniform random angles, Gaussian noise `noise` per
/// coordinate.
Point_matrix noisy_circle(std::size_t n, double noise, std::uint32_t seed) {
  Portable_gaussian g(seed);
  Point_matrix m;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * pi * g.uniform();
    add_point(m, {10 * std::cos(t) + noise * g(), 10 * std::sin(t) + noise * g()});
  }
  return m;
}

/// A Y: three arms of length 5 from the origin at 120 degrees, Gaussian noise per coordinate.
Point_matrix noisy_y(std::size_t n, double noise, std::uint32_t seed) {
  Portable_gaussian g(seed);
  Point_matrix m;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = pi / 2 + static_cast<double>(g.next() % 3) * 2 * pi / 3, t = 5 * g.uniform();
    add_point(m, {t * std::cos(a) + noise * g(), t * std::sin(a) + noise * g()});
  }
  return m;
}

/// A trefoil knot in R^3 (one loop), Gaussian noise per coordinate.
Point_matrix noisy_trefoil(std::size_t n, double noise, std::uint32_t seed) {
  Portable_gaussian g(seed);
  Point_matrix m;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * pi * g.uniform();
    add_point(m, {std::sin(t) + 2 * std::sin(2 * t) + noise * g(),
                  std::cos(t) - 2 * std::cos(2 * t) + noise * g(), -std::sin(3 * t) + noise * g()});
  }
  return m;
}

/// The skeleton's topology at `radius` with `delta` (unset: delta = radius).
Topology skeleton_shape(const Point_matrix& m, double radius, std::optional<double> delta = std::nullopt) {
  Skeleton_options o;
  o.delta = delta.value_or(radius);
  const Reeb_skeleton s = extract_reeb_skeleton(m, radius, o);
  EXPECT_EQ(s.status, Status::success);
  return topology(s.graph);
}

}  // namespace

TEST(EstimateRipsRadius, QuarterOctaveBinsAreExact) {
  for (int b = -4080; b <= 4090; ++b) {  // normal numbers (the subnormal powers round)
    const double p = skeleton::internal::quarter_octave_power(b);
    ASSERT_EQ(skeleton::internal::quarter_octave_bin(p), b) << b;
    ASSERT_EQ(skeleton::internal::quarter_octave_bin(std::nextafter(p, 0.0)), b - 1) << b;
    // Within rounding of the power itself.
    ASSERT_NEAR(p / std::exp2(b / 4.0), 1.0, 4e-16) << b;
  }
  EXPECT_EQ(skeleton::internal::quarter_octave_bin(std::numeric_limits<double>::denorm_min()), -4296);
  EXPECT_EQ(skeleton::internal::quarter_octave_bin(std::numeric_limits<double>::max()), 4095);
}

TEST(EstimateRipsRadius, ProfileCountsEqualBruteForce) {
  // 60 points in R^3 with copies and a far point; every reference point (m = n) and 7 of them (i = t * n /
  // 7).
  Portable_gaussian g(5);
  Point_matrix m;
  for (int i = 0; i < 57; ++i) add_point(m, {g(), g(), 0.1 * g()});
  add_point(m, {m.data[0], m.data[1], m.data[2]});  // a copy of point 0
  add_point(m, {m.data[0], m.data[1], m.data[2]});
  add_point(m, {1e3, 0, 0});
  // The copies of point 0 (57 and 58) are one point with it: 58 distinct points, 57 the reference ones at
  // most.
  std::vector<std::size_t> distinct;
  for (std::size_t i = 0; i < 60; ++i)
    if (i != 57 && i != 58) distinct.push_back(i);
  for (const std::size_t references : {std::size_t(58), std::size_t(7)}) {
    Rips_radius_options o;
    o.reference_points = references;
    const Rips_radius_estimate e = estimate_rips_radius(m, o);
    ASSERT_EQ(e.status, Status::success);
    ASSERT_EQ(e.reference_points, references);
    ASSERT_EQ(e.distinct_points, 58u);
    ASSERT_EQ(e.radii.size(), e.mean_neighbours_within.size());
    ASSERT_GT(e.radii.size(), 20u);
    for (std::size_t k = 0; k < e.radii.size(); ++k) {
      if (k > 0) {  // consecutive quarter octaves
        ASSERT_EQ(skeleton::internal::quarter_octave_bin(e.radii[k]),
                  skeleton::internal::quarter_octave_bin(e.radii[k - 1]) + 1)
            << k;
      }
      std::size_t within = 0;
      for (std::size_t t = 0; t < references; ++t) {
        const std::size_t i = distinct[t * distinct.size() / references];
        for (const std::size_t j : distinct)
          if (j != i && skeleton::internal::point_distance(m.row(i), m.row(j), 3) < e.radii[k]) ++within;
      }
      EXPECT_DOUBLE_EQ(e.mean_neighbours_within[k],
                       static_cast<double>(within) / static_cast<double>(references))
          << "references " << references << ", r " << e.radii[k];
    }
    // The smallest positive distance lies in the first bin, the largest in the last.
    EXPECT_EQ(e.mean_neighbours_within.back(), 57.0);
    // The chosen scale is a profile radius with at least min_neighbours neighbours, and the radius 1.5 times
    // it.
    EXPECT_NE(std::find(e.radii.begin(), e.radii.end(), e.scale), e.radii.end());
    EXPECT_GE(e.mean_neighbours, 8.0);
    EXPECT_EQ(e.radius, std::max(1.5 * e.scale, e.gap_radius));
  }
}

TEST(EstimateRipsRadius, NoisySamplesOfGraphsGiveTheirTopology) {
  // Each sample, its true loops / leaves / branch excess, and the window of radii that gives them (measured
  // by a sweep of fixed radii 1.19 apart from 0.2, delta = radius): the estimate must land inside, and its
  // delta give them too. The windows differ: 0.2-0.96 for the trefoil, 0.96 and more for the circle.
  struct Case {
    const char* name;
    Point_matrix points;
    std::array<std::size_t, 4> truth;  // loops, components, leaves, branch excess
    double low, high;
  };
  std::vector<Case> cases;
  cases.push_back({"circle, 1000 points, noise 0.3", noisy_circle(1000, 0.3, 1), {{1, 1, 0, 0}}, 0.95, 4.5});
  cases.push_back({"Y, 1500 points, noise 0.2", noisy_y(1500, 0.2, 2), {{0, 1, 3, 1}}, 0.34, 1.9});
  cases.push_back(
      {"trefoil, 1500 points, noise 0.05", noisy_trefoil(1500, 0.05, 3), {{1, 1, 0, 0}}, 0.2, 0.95});
  const Segment_graph eight = figure_eight(50, 2.0, 1);
  cases.push_back(
      {"figure-eight in R^50, noise 0.01", eight.noisy_sample(0.25, 0.01, 1), {{2, 1, 0, 2}}, 0.28, 2.7});
  const Segment_graph tree = random_tree(50, 9, 2);
  cases.push_back({"random tree in R^50, noise 0.01",
                   tree.noisy_sample(0.25, 0.01, 2),
                   {{0, 1, tree.leaves(), tree.branch_excess()}},
                   0.34,
                   2.28});
  for (const Case& c : cases) {
    const Rips_radius_estimate e = estimate_rips_radius(c.points);
    ASSERT_EQ(e.status, Status::success) << c.name;
    EXPECT_NEAR(e.intrinsic_dimension, 1.0, 0.3) << c.name;
    EXPECT_GE(e.radius, c.low) << c.name;
    EXPECT_LE(e.radius, c.high) << c.name;
    EXPECT_EQ(e.delta, std::max(e.radius, 2.25 * e.scale)) << c.name;
    const Topology s = skeleton_shape(c.points, e.radius, e.delta);
    EXPECT_EQ(s.loops, c.truth[0]) << c.name << " at radius " << e.radius;
    EXPECT_EQ(s.components, c.truth[1]) << c.name << " at radius " << e.radius;
    EXPECT_EQ(s.leaves, c.truth[2]) << c.name << " at radius " << e.radius;
    EXPECT_EQ(s.branch_excess, c.truth[3]) << c.name << " at radius " << e.radius;
  }
  // The windows' ends are real: the circle at 0.5 and the trefoil's radius on the circle fall apart.
  EXPECT_NE(skeleton_shape(cases[0].points, 0.5).components, 1u);
  EXPECT_NE(skeleton_shape(cases[0].points, estimate_rips_radius(cases[2].points).radius).components, 1u);
}

TEST(EstimateRipsRadius, TheSuggestedDeltaRemovesTheSpursOfADenseBand) {
  // 3,000 points around a circle with noise 0.3: the band's outliers make branches of persistence above the
  // radius (delta = radius kept a spur on 7 of 20 seeds, this is one), the suggested delta removes them.
  const Point_matrix m = noisy_circle(3000, 0.3, 1);
  const Rips_radius_estimate e = estimate_rips_radius(m);
  EXPECT_GT(e.delta, e.radius);
  const Topology at_radius = skeleton_shape(m, e.radius, e.radius);
  EXPECT_EQ(at_radius.loops, 1u);
  EXPECT_EQ(at_radius.leaves, 1u);  // the spur
  const Topology at_delta = skeleton_shape(m, e.radius, e.delta);
  EXPECT_EQ(at_delta.loops, 1u);
  EXPECT_EQ(at_delta.leaves, 0u);
  EXPECT_EQ(at_delta.branch_excess, 0u);
}

TEST(EstimateRipsRadius, SparseSamplesGetARadiusAcrossTheirGaps) {
  // 400 points at random along a trefoil about 29 long (noise 0.05; 14 points per unit length): at 1.5 times
  // the scale (0.45-0.53) random gaps split the loop on 7 of these 10 seeds; the gap rule (2 ln(400 / 0.05) =
  // 18 neighbours) takes the radius to 0.71, and every seed gives the loop.
  std::size_t split = 0;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    const Point_matrix m = noisy_trefoil(400, 0.05, seed);
    const Rips_radius_estimate e = estimate_rips_radius(m);
    EXPECT_GT(e.gap_radius, 1.5 * e.scale) << seed;
    EXPECT_EQ(e.radius, e.gap_radius) << seed;
    const Topology at_scale = skeleton_shape(m, 1.5 * e.scale);
    split += at_scale.loops != 1 || at_scale.components != 1 || at_scale.leaves != 0;
    const Topology s = skeleton_shape(m, e.radius, e.delta);
    EXPECT_EQ(s.loops, 1u) << seed;
    EXPECT_EQ(s.components, 1u) << seed;
    EXPECT_EQ(s.leaves, 0u) << seed;
  }
  EXPECT_EQ(split, 7u);
}

TEST(EstimateRipsRadius, ScalingThePointsByAPowerOfTwoScalesTheRadiusExactly) {
  const Point_matrix m = noisy_circle(400, 0.3, 4);
  const Rips_radius_estimate e = estimate_rips_radius(m);
  for (const int k : {-600, -7, 3, 600}) {
    Point_matrix scaled = m;
    for (double& x : scaled.data) x = std::ldexp(x, k);
    const Rips_radius_estimate f = estimate_rips_radius(scaled);
    EXPECT_EQ(f.radius, std::ldexp(e.radius, k)) << k;
    EXPECT_EQ(f.scale, std::ldexp(e.scale, k)) << k;
    EXPECT_EQ(f.mean_neighbours_within, e.mean_neighbours_within) << k;
    EXPECT_EQ(f.intrinsic_dimension, e.intrinsic_dimension) << k;
  }
}

TEST(EstimateRipsRadius, DegenerateInputs) {
  Point_matrix empty;
  empty.dimension = 2;
  Rips_radius_estimate e = estimate_rips_radius(empty);
  EXPECT_EQ(e.status, Status::degenerate_input);
  EXPECT_EQ(e.radius, 0.0);
  EXPECT_EQ(e.reference_points, 0u);

  Point_matrix one;
  add_point(one, {1, 2});
  e = estimate_rips_radius(one);
  EXPECT_EQ(e.status, Status::degenerate_input);
  EXPECT_EQ(e.radius, 0.0);

  Point_matrix copies;
  for (int i = 0; i < 5; ++i) add_point(copies, {1, 2, 3});
  e = estimate_rips_radius(copies);
  EXPECT_EQ(e.status, Status::degenerate_input);
  EXPECT_EQ(e.radius, 0.0);
  EXPECT_EQ(e.distinct_points, 1u);

  // Two points 5 apart: 5 lies in [2^(9/4), 2^(10/4)); with one neighbour each, the scale is that bin's top.
  Point_matrix two;
  add_point(two, {0, 0});
  add_point(two, {3, 4});
  e = estimate_rips_radius(two);
  EXPECT_EQ(e.status, Status::success);
  EXPECT_TRUE(std::isnan(e.intrinsic_dimension));
  EXPECT_EQ(e.scale, std::exp2(2.5));
  EXPECT_EQ(e.radius,
            1.5 * std::exp2(2.5));  // the gap rule asks for (n - 1) / 2 = 0.5 neighbours: the same bin
  EXPECT_EQ(e.gap_radius, std::exp2(2.5));

  // 100 collinear points 1 apart: dimension 1, and 8 neighbours on average first within 2^(10/4) = 5.66 (5 on
  // each side inside, fewer at the ends: 9.7 on average); 2 ln(100 / 0.05) = 15.2 neighbours first within
  // 2^(13/4) = 9.51 (15.28 on average), which is above 1.5 * 5.66: the radius. The line's skeleton is one
  // arc.
  Point_matrix line;
  for (int i = 0; i < 100; ++i) add_point(line, {static_cast<double>(i), 0});
  e = estimate_rips_radius(line);
  EXPECT_NEAR(e.intrinsic_dimension, 1.0, 0.05);
  EXPECT_EQ(e.scale, std::exp2(2.5));
  EXPECT_DOUBLE_EQ(e.mean_neighbours, 9.7);
  EXPECT_EQ(e.gap_radius, std::exp2(3.25));
  EXPECT_EQ(e.radius, std::exp2(3.25));
  const Topology s = skeleton_shape(line, e.radius);
  EXPECT_EQ(s.components, 1u);
  EXPECT_EQ(s.leaves, 2u);

  // A 30 x 30 grid (every distance repeats, every square cocircular) reads as two-dimensional, not as a
  // curve.
  Point_matrix grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) add_point(grid, {static_cast<double>(i), static_cast<double>(j)});
  e = estimate_rips_radius(grid);
  EXPECT_GT(e.intrinsic_dimension, 1.5);
  EXPECT_GE(e.mean_neighbours, 8.0);
  EXPECT_GT(e.radius, std::sqrt(2.0));  // joins each grid point to its 8 neighbours

  // Distances from 2^1023.75 on: the top bin's edge, 2^1024, is not a double; the largest one stands for it
  // and the radius stays finite (it was infinite, with status success).
  Point_matrix far;
  add_point(far, {0});
  add_point(far, {1.6e308});
  e = estimate_rips_radius(far);
  EXPECT_EQ(e.status, Status::success);
  EXPECT_EQ(e.scale, std::numeric_limits<double>::max());
  EXPECT_EQ(e.radius, std::numeric_limits<double>::max());
  EXPECT_EQ(e.delta, std::numeric_limits<double>::max());
}

TEST(EstimateRipsRadius, TheRulesBoundariesArePinned) {
  // Each case sits on one boundary of the rules (>= against >, a range's last bin, the fallback's count), so
  // that moving it changes the estimate. Collinear points 1 apart: a point has 2 neighbours within (1, 2], 4
  // within (2, 3], ... (fewer at the ends).
  auto line = [](int n) {
    Point_matrix m;
    for (int i = 0; i < n; ++i) add_point(m, {static_cast<double>(i), 0});
    return m;
  };
  const Point_matrix line100 = line(100), line8 = line(8);
  Rips_radius_options o;
  // min_neighbours 1: the first bin with a dimension read is bin 2 (radius 2^(3/4) = 1.68), the first whose
  // octave below has a count.
  o.min_neighbours = 1;
  Rips_radius_estimate e = estimate_rips_radius(line100, o);
  EXPECT_EQ(e.scale, std::exp2(0.75));
  // The count at 2^(3/4) is (98 * 2 + 2) / 100 = 1.98: exactly min_neighbours is enough.
  o.min_neighbours = 1.98;
  e = estimate_rips_radius(line100, o);
  EXPECT_EQ(e.scale, std::exp2(0.75));
  EXPECT_DOUBLE_EQ(e.mean_neighbours, 1.98);
  // Eight points: (n - 1) / 4 = 1.75 neighbours is exactly the count at 2^(3/4) (14 / 8), the top of the
  // range where the dimension is read: log2(26 / 14) over the octave to 2^(7/4).
  o.min_neighbours = 1;
  e = estimate_rips_radius(line8, o);
  EXPECT_DOUBLE_EQ(e.intrinsic_dimension, std::log2(13.0 / 7.0));
  EXPECT_EQ(e.scale, std::exp2(0.75));
  // A slope exactly at the smallest plus a margin of 0 is taken.
  o.dimension_margin = 0;
  e = estimate_rips_radius(line8, o);
  EXPECT_EQ(e.scale, std::exp2(0.75));
  // With the default 8 neighbours no bin of the eight points is in range: the scale is the first bin with
  // min(8, (n - 1) / 2 = 3.5) neighbours (2^(7/4): 36 / 8 = 4.5), and the gap rule asks for 3.5 too.
  e = estimate_rips_radius(line8);
  EXPECT_TRUE(std::isnan(e.intrinsic_dimension));
  EXPECT_EQ(e.scale, std::exp2(1.75));
  EXPECT_DOUBLE_EQ(e.mean_neighbours, 4.5);
  EXPECT_EQ(e.gap_radius, std::exp2(1.75));
  // A regular pentagon: 2 neighbours at the side (1.18, below 2^(1/4)) are exactly the (n - 1) / 2 both the
  // fallback and the gap rule ask for.
  Point_matrix pentagon;
  for (int k = 0; k < 5; ++k) add_point(pentagon, {std::cos(2 * pi * k / 5), std::sin(2 * pi * k / 5)});
  e = estimate_rips_radius(pentagon);
  EXPECT_EQ(e.scale, std::exp2(0.25));
  EXPECT_EQ(e.gap_radius, std::exp2(0.25));
  EXPECT_DOUBLE_EQ(e.mean_neighbours, 2.0);
  EXPECT_EQ(e.radius, 1.5 * std::exp2(0.25));
  // Nine points on a cycle 1 apart, every other pair 2.2 apart (a matrix): the profile has bins 0 to 4 (1 and
  // 2.2), with 2, 2, 2, 2 and 8 neighbours; a dimension is read where the octave above is in the profile, up
  // to the last bin but two: at bin 2 only, log2(8 / 2) = 2.
  std::vector<std::vector<double>> cycle(9, std::vector<double>(9, 2.2));
  for (int i = 0; i < 9; ++i) {
    cycle[i][i] = 0;
    cycle[i][(i + 1) % 9] = cycle[(i + 1) % 9][i] = 1;
  }
  o = {};
  o.min_neighbours = 1;
  e = estimate_rips_radius_from_distance_matrix(cycle, o);
  EXPECT_NEAR(e.intrinsic_dimension, 2.0, 1e-12);
  EXPECT_EQ(e.scale, std::exp2(0.75));
  EXPECT_EQ(e.radius, 1.5 * std::exp2(0.75));
  // The suggested delta is at least the radius (delta_factor 0: the radius, 2^(13/4) for the line).
  o = {};
  o.delta_factor = 0;
  e = estimate_rips_radius(line100, o);
  EXPECT_EQ(e.radius, std::exp2(3.25));
  EXPECT_EQ(e.delta, e.radius);
  // Rows of a matrix 0 apart that are not copies count at every radius, below the first bin: the profile
  // starts at the smallest positive distance (1, bin 0) and ends at 2 (bin 4).
  e = estimate_rips_radius_from_distance_matrix(
      std::vector<std::vector<double>>{{0, 0, 1}, {0, 0, 2}, {1, 2, 0}});
  ASSERT_EQ(e.radii.size(), 5u);
  EXPECT_EQ(e.radii[0], std::exp2(0.25));
  EXPECT_DOUBLE_EQ(e.mean_neighbours_within[0], 4.0 / 3);
  // A distance beyond the largest double (2e308) falls in the bin after 2^1023.75: five bins from 1e308's.
  Point_matrix huge;
  add_point(huge, {0});
  add_point(huge, {1e308});
  add_point(huge, {-1e308});
  e = estimate_rips_radius(huge);
  ASSERT_EQ(e.radii.size(), 5u);
  EXPECT_EQ(e.radii[3], std::numeric_limits<double>::max());
  EXPECT_EQ(e.radii[4], std::numeric_limits<double>::max());
  EXPECT_DOUBLE_EQ(e.mean_neighbours_within[3], 4.0 / 3);
  EXPECT_DOUBLE_EQ(e.mean_neighbours_within.back(), 2.0);
}

TEST(EstimateRipsRadius, CopiesOfThePointsLeaveTheEstimateAsItWas) {
  // The Rips stage joins copies, so the estimate counts each point once: 4 copies of every point of a noisy
  // circle shrank the radius and broke the skeleton (copies counted as neighbours at every radius).
  const Point_matrix once = noisy_circle(500, 0.3, 11);
  Point_matrix four;
  four.dimension = 2;
  for (int c = 0; c < 4; ++c) four.data.insert(four.data.end(), once.data.begin(), once.data.end());
  four.rows = 4 * once.rows;
  const Rips_radius_estimate a = estimate_rips_radius(once), b = estimate_rips_radius(four);
  EXPECT_EQ(b.distinct_points, 500u);
  EXPECT_EQ(b.radius, a.radius);
  EXPECT_EQ(b.delta, a.delta);
  EXPECT_EQ(b.mean_neighbours_within, a.mean_neighbours_within);
  Skeleton_options o;
  o.delta = FeatureRecon::automatic;
  const Topology t = topology(extract_reeb_skeleton(four, o).graph);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.loops, 1u);
  // The matrix of the copies: the same.
  EXPECT_EQ(estimate_rips_radius_from_distance_matrix(distance_matrix_of(four)).radius, a.radius);
}

TEST(EstimateRipsRadius, BracesSelectTheEstimateNotRadiusZero) {
  // extract_reeb_skeleton(points, {}) took {} for radius 0 (an exact conversion beating the options'
  // aggregate): 200 points on a line gave 200 single nodes. The radius is any arithmetic type, so {} now
  // means default options and the radius is estimated.
  Point_matrix line;
  for (int i = 0; i < 200; ++i) add_point(line, {static_cast<double>(i), 0});
  const Reeb_skeleton a = extract_reeb_skeleton(line, {});
  EXPECT_EQ(a.rips_radius, estimate_rips_radius(line).radius);
  EXPECT_EQ(num_vertices(a.graph), 2u);
  std::vector<std::array<double, 3>> range;
  for (int i = 0; i < 200; ++i) range.push_back({static_cast<double>(i), 0, 0});
  EXPECT_EQ(extract_reeb_skeleton(range, {}).rips_radius, a.rips_radius);
  EXPECT_EQ(extract_reeb_skeleton(line, {}, {}).rips_radius, a.rips_radius);
  // A braced radius is a radius (not options with that delta), alone or with options.
  Skeleton_options o;
  EXPECT_EQ(extract_reeb_skeleton(line, {2.0}).rips_radius, 2.0);
  EXPECT_EQ(extract_reeb_skeleton(line, {2.0}).delta, 0.0);
  EXPECT_EQ(extract_reeb_skeleton(line, {2}, o).rips_radius, 2.0);
  EXPECT_EQ(extract_reeb_skeleton(range, {2.5}).rips_radius, 2.5);
  std::vector<double> D(200 * 200);
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) D[std::size_t(i) * 200 + std::size_t(j)] = std::abs(i - j);
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> matrix(D.data(),
                                                                                                  200, 200);
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(matrix, {3.0}).rips_radius, 3.0);
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(matrix, {}).rips_radius,
            estimate_rips_radius_from_distance_matrix(matrix).radius);
  // A radius of any arithmetic type is a radius.
  EXPECT_EQ(extract_reeb_skeleton(line, 2).rips_radius, 2.0);
  EXPECT_EQ(extract_reeb_skeleton(line, 1.5f).rips_radius, 1.5);
  EXPECT_EQ(extract_reeb_skeleton(range, 3u).rips_radius, 3.0);
}

TEST(EstimateRipsRadius, DistanceMatrixGivesTheSameEstimate) {
  const Point_matrix m = noisy_trefoil(400, 0.05, 6);
  Row_major_matrix matrix = distance_matrix_of(m);
  const Rips_radius_estimate a = estimate_rips_radius(m),
                             b = estimate_rips_radius_from_distance_matrix(matrix);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.mean_neighbours_within, b.mean_neighbours_within);
  Skeleton_options o;
  o.delta = FeatureRecon::automatic;  // the estimate's
  const Reeb_skeleton s = extract_reeb_skeleton_from_distance_matrix(matrix, o);
  EXPECT_EQ(s.rips_radius, a.radius);
  EXPECT_EQ(s.delta, a.delta);
  EXPECT_EQ(topology(s.graph).loops, 1u);
  // With a given radius, an automatic delta is the suggested one at that radius.
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(matrix, a.radius, o).delta, a.delta);
  EXPECT_EQ(extract_reeb_skeleton_from_distance_matrix(matrix, 4 * a.scale, o).delta, 4 * a.scale);
  matrix(0, 1) = -1;  // refused as the other distance-matrix functions refuse it
  EXPECT_THROW(estimate_rips_radius_from_distance_matrix(matrix), std::invalid_argument);
}

TEST(EstimateRipsRadius, OneCallSkeletonUsesTheEstimate) {
  const Point_matrix m = noisy_circle(600, 0.3, 7);
  const Rips_radius_estimate e = estimate_rips_radius(m);
  Skeleton_options o;
  o.delta = e.radius;  // as given (FeatureRecon::automatic stands for e.delta)
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  const Reeb_skeleton one_call = extract_reeb_skeleton(m, o);
  o.progress = nullptr;
  const Reeb_skeleton staged = extract_reeb_skeleton(m, e.radius, o);
  EXPECT_EQ(one_call.rips_radius, e.radius);
  EXPECT_EQ(one_call.delta, e.radius);
  EXPECT_EQ(staged.rips_radius, e.radius);
  EXPECT_EQ(one_call.rips_edges, staged.rips_edges);
  EXPECT_EQ(one_call.rips_triangles, staged.rips_triangles);
  EXPECT_EQ(num_vertices(one_call.graph), num_vertices(staged.graph));
  EXPECT_EQ(num_edges(one_call.graph), num_edges(staged.graph));
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_GT(std::count_if(seen.begin(), seen.end(), [](double t) { return t <= 0.1; }), 100);

  // A range of points through the traits gives the same.
  std::vector<std::array<double, 2>> range;
  for (std::size_t i = 0; i < m.rows; ++i) range.push_back({m.row(i)[0], m.row(i)[1]});
  EXPECT_EQ(estimate_rips_radius(range).radius, e.radius);
  o.progress = nullptr;
  EXPECT_EQ(num_edges(extract_reeb_skeleton(range, o).graph), num_edges(staged.graph));

  // An automatic delta: the estimate's; with a given radius, max(radius, 2.25 x the estimated scale) (it was
  // refused); the graph overload, without points to estimate from, refuses it and says why.
  o.delta = FeatureRecon::automatic;
  EXPECT_EQ(extract_reeb_skeleton(m, o).delta, e.delta);
  EXPECT_EQ(extract_reeb_skeleton(m, e.radius, o).delta, e.delta);
  EXPECT_EQ(extract_reeb_skeleton(m, 0.5 * e.scale, o).delta, 2.25 * e.scale);
  EXPECT_EQ(extract_reeb_skeleton(m, 3 * e.scale, o).delta, 3 * e.scale);
  EXPECT_EQ(extract_reeb_skeleton(range, e.radius, o).delta, e.delta);
  EXPECT_EQ(
      invalid_argument_message([&] { extract_reeb_skeleton(build_rips_graph(m, e.radius), m, o); }),
      "extract_reeb_skeleton: delta is automatic (the suggested delta), which needs points or a distance "
      "matrix: give a value");
  o.delta = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(extract_reeb_skeleton(m, o), std::invalid_argument);
  // A negative delta asked for the suggested one before FeatureRecon::automatic; it is refused, saying so,
  // by every overload (it would otherwise be taken for a value).
  o.delta = -1;
  for (const std::string& message :
       {invalid_argument_message([&] { extract_reeb_skeleton(m, o); }),
        invalid_argument_message([&] { extract_reeb_skeleton(m, e.radius, o); }),
        invalid_argument_message([&] { extract_reeb_skeleton(build_rips_graph(m, e.radius), m, o); })})
    EXPECT_EQ(message,
              "extract_reeb_skeleton: delta must be finite and >= 0 (FeatureRecon::automatic: the suggested "
              "delta, with points or a distance matrix; 0: no simplification), got -1");

  // Both callbacks hear the estimate: the run's (first tenth) and the estimate's own (0 to 1).
  Rips_radius_options ro;
  std::vector<double> own;
  ro.progress = test::recording_progress(own);
  seen.clear();
  o.delta = FeatureRecon::automatic;
  o.progress = test::recording_progress(seen);
  extract_reeb_skeleton(m, o, ro);
  ASSERT_EQ(own.size(), 601u);  // 600 reference points, then 1
  EXPECT_EQ(own.back(), 1.0);
  EXPECT_GE(std::count_if(seen.begin(), seen.end(), [](double t) { return t <= 0.1; }), 601);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  // The estimate's own callback can stop the run too.
  ro.progress = [](double t) { return t < 0.5; };
  EXPECT_EQ(extract_reeb_skeleton(m, o, ro).status, Status::interrupted);

  // Stopped during the estimate: interrupted, nothing built.
  o.progress = [](double t) { return t < 0.05; };
  const Reeb_skeleton stopped = extract_reeb_skeleton(m, o);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(num_vertices(stopped.graph), 0u);
}

TEST(EstimateRipsRadius, SuggestedDeltaAtAGivenRadiusReportsProgressAndCanStop) {
  // A negative delta with a given radius ran the suggestion's estimate (600 reference points here) with
  // default options: no progress and no stop during it, and the rest of the run took the whole range.
  const Point_matrix m = noisy_circle(600, 0.3, 7);
  const Rips_radius_estimate e = estimate_rips_radius(m);
  std::vector<double> seen, given_seen;
  Skeleton_options o, given;
  o.delta = FeatureRecon::automatic;
  o.progress = test::recording_progress(seen);
  given.delta = e.delta;
  given.progress = test::recording_progress(given_seen);
  const Reeb_skeleton s = extract_reeb_skeleton(m, e.radius, o),
                      g = extract_reeb_skeleton(m, e.radius, given);
  EXPECT_EQ(s.status, Status::success);
  EXPECT_EQ(s.delta, e.delta);
  EXPECT_EQ(num_vertices(s.graph), num_vertices(g.graph));
  EXPECT_EQ(num_edges(s.graph), num_edges(g.graph));
  // The estimate's 601 reports fill the first tenth; the run's own follow, scaled into the rest.
  ASSERT_EQ(seen.size(), given_seen.size() + 601);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen[1], 0.1 * (1.0 / 600));
  EXPECT_EQ(seen[600], 0.1);
  for (std::size_t i = 0; i < given_seen.size(); ++i) EXPECT_EQ(seen[601 + i], 0.1 + 0.9 * given_seen[i]);
  // A stop during the estimate: interrupted, nothing built, the given radius and the caller's delta.
  std::size_t calls = 0;
  o.progress = [&calls](double t) {
    ++calls;
    return t < 0.05;
  };
  const Reeb_skeleton stopped = extract_reeb_skeleton(m, e.radius, o);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(stopped.rips_radius, e.radius);
  EXPECT_TRUE(std::isnan(stopped.delta));  // not known yet
  EXPECT_EQ(num_vertices(stopped.graph), 0u);
  EXPECT_EQ(calls, 301u);  // 0, 1/600, ..., 300/600 of the first tenth: 0.05 is the first refused
  // The distance-matrix overload alike.
  const Row_major_matrix matrix = distance_matrix_of(m);
  calls = 0;
  const Reeb_skeleton stopped_matrix = extract_reeb_skeleton_from_distance_matrix(matrix, e.radius, o);
  EXPECT_EQ(stopped_matrix.status, Status::interrupted);
  EXPECT_EQ(stopped_matrix.rips_radius, e.radius);
  EXPECT_TRUE(std::isnan(stopped_matrix.delta));
  EXPECT_EQ(num_vertices(stopped_matrix.graph), 0u);
  EXPECT_EQ(calls, 301u);
  seen.clear();
  o.progress = test::recording_progress(seen);
  const Reeb_skeleton from_matrix = extract_reeb_skeleton_from_distance_matrix(matrix, e.radius, o);
  EXPECT_EQ(from_matrix.status, Status::success);
  EXPECT_EQ(from_matrix.delta, e.delta);
  ASSERT_GE(seen.size(), 601u);
  EXPECT_EQ(seen[600], 0.1);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
}

TEST(EstimateRipsRadius, ProgressAndStop) {
  const Point_matrix m = noisy_circle(300, 0.3, 8);
  Rips_radius_options o;
  o.reference_points = 50;
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  EXPECT_EQ(estimate_rips_radius(m, o).status, Status::success);
  ASSERT_EQ(seen.size(), 51u);  // before each reference point, then 1
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
  std::size_t calls = 0;
  o.progress = [&calls](double) { return ++calls < 10; };
  const Rips_radius_estimate stopped = estimate_rips_radius(m, o);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(stopped.radius, 0.0);
  EXPECT_TRUE(stopped.radii.empty());
  EXPECT_EQ(calls, 10u);
}

TEST(EstimateRipsRadius, BadOptionsAndPointsAreNamed) {
  const Point_matrix m = noisy_circle(20, 0.3, 9);
  auto message = [&m](const Rips_radius_options& o) {
    return invalid_argument_message([&] { estimate_rips_radius(m, o); });
  };
  Rips_radius_options o;
  o.reference_points = 0;
  EXPECT_TRUE(contains(message(o), "reference_points must be >= 1"));
  o = {};
  o.min_neighbours = 0.5;
  EXPECT_TRUE(contains(message(o), "min_neighbours must be finite and >= 1"));
  o.min_neighbours = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(message(o), "min_neighbours"));
  o = {};
  o.dimension_margin = -1;
  EXPECT_TRUE(contains(message(o), "dimension_margin"));
  o = {};
  o.radius_factor = 0;
  EXPECT_TRUE(contains(message(o), "radius_factor"));
  o = {};
  o.delta_factor = -1;
  EXPECT_TRUE(contains(message(o), "delta_factor"));
  o = {};
  o.max_expected_gaps = 0;
  EXPECT_TRUE(contains(message(o), "max_expected_gaps must be in (0, 1]"));
  // The bounds themselves are allowed.
  o = {};
  o.radius_factor = 0x1p100;
  o.max_expected_gaps = 1;
  o.min_neighbours = 1;
  o.delta_factor = 0x1p100;
  EXPECT_NO_THROW(estimate_rips_radius(m, o));
  Point_matrix bad = m;
  bad.data[2 * 7 + 1] = std::numeric_limits<double>::infinity();
  try {
    estimate_rips_radius(bad);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "point 7"));
    EXPECT_TRUE(contains(e.what(), "estimate_rips_radius"));
  }
}
