// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Oracle: the persistence diagrams that survive in the Reeb graph (design notes 1.2) must equal GUDHI's
// extended persistence of the complex, with the lower-star filtration of f:
//   Ord0(R) = Ord0(K), Rel1(R) = Rel1(K) (branches), Ext+0(R) = Ext+0(K), Ext-1(R) = Ext-1(K) (loops).
// Both sides are computed by GUDHI (the Reeb graph as a 1-complex), on the simulation-of-simplicity ranks of
// f, so every value is distinct and the comparison is exact.
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gudhi_extended_persistence.h"
#include "skeleton_test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

using Point_pair = FeatureRecon::test::Point_pair;
using FeatureRecon::test::Extended_diagrams;
using FeatureRecon::test::gudhi_extended_persistence;

/// Diagrams of the complex K and of its Reeb graph R (each arc subdivided once so that parallel arcs become
/// simplicial: a midpoint with value 2*rank(lower)+1, nodes at 2*rank).
std::pair<Extended_diagrams, Extended_diagrams> diagrams(const Simplicial_complex_2& K,
                                                         const std::vector<double>& f) {
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, f);
  const std::size_t n = K.number_of_vertices;
  std::vector<long> rank2(n);
  for (std::size_t v = 0; v < n; ++v) rank2[v] = 2 * static_cast<long>(A.rank()[v]);
  std::vector<std::vector<int>> ks;
  for (const Edge& e : K.edges) ks.push_back({static_cast<int>(e[0]), static_cast<int>(e[1])});
  for (const Triangle& t : K.triangles)
    ks.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  std::vector<std::vector<int>> rs;
  std::vector<long> rvalue = rank2;
  for (const auto& a : A.arcs()) {
    const int mid = static_cast<int>(rvalue.size());
    rvalue.push_back(rank2[a.lower] + 1);
    rs.push_back({static_cast<int>(a.lower), mid});
    rs.push_back({mid, static_cast<int>(a.upper)});
  }
  return {gudhi_extended_persistence(n, ks, rank2), gudhi_extended_persistence(rvalue.size(), rs, rvalue)};
}

/// Compares the diagrams; returns the number of diagram points of K compared (Ord0, Rel1, Ext+0, Ext-1) and
/// adds the loops (Ext-1) to `loops` when given.
std::size_t expect_reeb_diagrams_match(const Simplicial_complex_2& K, const std::vector<double>& f,
                                       const std::string& what, std::size_t* loops = nullptr) {
  const auto [dk, dr] = diagrams(K, f);
  if (loops != nullptr) *loops += dk.ext_minus[1].size();
  EXPECT_EQ(dr.ord[0], dk.ord[0]) << what << ": Ord0";
  EXPECT_EQ(dr.rel[1], dk.rel[1]) << what << ": Rel1 (branches)";
  EXPECT_EQ(dr.ext_plus[0], dk.ext_plus[0]) << what << ": Ext+0";
  EXPECT_EQ(dr.ext_minus[1], dk.ext_minus[1]) << what << ": Ext-1 (loops)";
  // A graph has no horizontal classes and no ordinary 1-dim deaths.
  EXPECT_TRUE(dr.ext_plus[1].empty()) << what;
  EXPECT_TRUE(dr.ord[1].empty()) << what;
  // The number of loops is the size of Ext-1 (every loop pairs an essential down-fork with an up-fork).
  const Reeb_graph R = compute_augmented_reeb_graph(K, f).reeb_graph();
  EXPECT_EQ(R.loops(), dr.ext_minus[1].size()) << what;
  return dk.ord[0].size() + dk.rel[1].size() + dk.ext_plus[0].size() + dk.ext_minus[1].size();
}

}  // namespace

TEST(ReebPersistenceOracle, RunningExampleFixtureOfDesignNotes) {
  // The torus: Ext-1 has one point, Ext+1 (horizontal class) exists in K but not in R.
  const auto t = upright_torus(20, 10);
  const auto [dk, dr] = diagrams(t.complex, t.f);
  EXPECT_EQ(dk.ext_minus[1].size(), 1u);
  EXPECT_EQ(dk.ext_plus[1].size(), 1u);
  EXPECT_TRUE(dr.ext_plus[1].empty());
  expect_reeb_diagrams_match(t.complex, t.f, "torus");
}

TEST(ReebPersistenceOracle, RandomRipsComplexesOfNoisyGraphs) {
  const std::vector<std::pair<std::string, std::vector<std::array<double, 4>>>> shapes{
      {"figure-eight", figure_eight_segments()}, {"tree", tree_segments()}, {"grid", grid_segments()}};
  std::mt19937 rng(2026);
  std::size_t points = 0, loops = 0;
  for (int trial = 0; trial < 18; ++trial) {
    const auto& shape = shapes[trial % 3];
    const auto s = sample_segments(shape.second, 0.35, 0.1, 500 + trial);
    const Simplicial_complex_2 K = build_rips_complex_2(s.points, 0.75);
    ASSERT_LT(K.number_of_edges() + K.number_of_triangles(), 100000u);
    std::vector<double> f;
    if (trial % 2 == 0) {
      f = compute_geodesic_function(K).values;
    } else {
      const double a = std::uniform_real_distribution<double>(0, 6.3)(rng);
      for (const auto& p : s.points) f.push_back(std::cos(a) * p[0] + std::sin(a) * p[1]);
    }
    points += expect_reeb_diagrams_match(K, f, shape.first + " trial " + std::to_string(trial), &loops);
  }
  // The comparisons were not empty (measured: 142 diagram points, 30 of them loops).
  EXPECT_GT(points, 100u);
  EXPECT_GT(loops, 20u);
}

TEST(ReebPersistenceOracle, GeodesicFunctionOnFigureEightHasTwoLoops) {
  const auto s = sample_segments(figure_eight_segments(), 0.3, 0.05, 9);
  const Simplicial_complex_2 K = build_rips_complex_2(s.points, 0.7);
  const auto geo = compute_geodesic_function(K);
  const auto [dk, dr] = diagrams(K, geo.values);
  EXPECT_EQ(dr.ext_minus[1].size(), 2u);
  EXPECT_EQ(dr.ext_minus[1], dk.ext_minus[1]);
  // One minimum per component for a geodesic function: Ord0 is empty.
  EXPECT_TRUE(dk.ord[0].empty());
}
