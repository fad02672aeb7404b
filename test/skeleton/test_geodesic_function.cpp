// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/geodesic_function.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>
#include <vector>

#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {
/// `call` throws std::invalid_argument with `part` in its message.
template <class Call>
void expect_refused(Call&& call, const std::string& part) {
  const std::string message = FeatureRecon::test::invalid_argument_message(call);
  EXPECT_TRUE(contains(message, part));
}
}  // namespace

namespace {
/// Floyd-Warshall distances (oracle on small graphs).
std::vector<std::vector<double>> all_pairs(const Proximity_graph& g) {
  const std::size_t n = g.number_of_vertices;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> d(n, std::vector<double>(n, inf));
  for (std::size_t i = 0; i < n; ++i) d[i][i] = 0;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    auto [u, v] = g.edges[e];
    d[u][v] = d[v][u] = std::min(d[u][v], g.length(e));
  }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
  return d;
}

Proximity_graph random_graph(std::size_t n, double p, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Proximity_graph g;
  g.number_of_vertices = n;
  for (Vertex_index i = 0; i < n; ++i)
    for (Vertex_index j = i + 1; j < n; ++j)
      if (u(rng) < p) {
        g.edges.push_back({i, j});
        g.edge_lengths.push_back(std::floor(u(rng) * 4));  // small integers: many ties, some zero lengths
      }
  return g;
}
}  // namespace

TEST(GeodesicFunction, MatchesAllPairsOracleWithFarthestBase) {
  for (std::uint32_t seed = 1; seed <= 30; ++seed) {
    const Proximity_graph g = random_graph(25, 0.09, seed);
    const auto d = all_pairs(g);
    const Geodesic_result r = compute_geodesic_function(g);
    const Connected_components cc = connected_components(g);
    ASSERT_EQ(r.base_points.size(), cc.count);
    for (std::size_t c = 0; c < cc.count; ++c) {
      // Start: smallest vertex of the component; base: farthest from it, smallest index on ties.
      std::size_t start = 0;
      while (cc.label[start] != c) ++start;
      std::size_t base = start;
      for (std::size_t v = 0; v < g.number_of_vertices; ++v)
        if (cc.label[v] == c && d[start][v] > d[start][base]) base = v;
      EXPECT_EQ(r.base_points[c], base) << "seed " << seed << " component " << c;
      for (std::size_t v = 0; v < g.number_of_vertices; ++v)
        if (cc.label[v] == c) {
          EXPECT_DOUBLE_EQ(r.values[v], d[base][v]);
        }
    }
  }
}

TEST(GeodesicFunction, UserBasePointsAndComponents) {
  Proximity_graph g;
  g.number_of_vertices = 6;
  g.edges = {{0, 1}, {1, 2}, {3, 4}};
  g.edge_lengths = {1.0, 2.0, 5.0};
  Geodesic_options o;
  o.base_points = {1};
  const Geodesic_result r = compute_geodesic_function(g, o);
  // Component {0,1,2}: the given base 1; {3,4}: 4, farthest from 3; {5}: itself.
  EXPECT_EQ(r.base_points, (std::vector<std::size_t>{1, 4, 5}));
  EXPECT_EQ(r.values, (std::vector<double>{1, 0, 2, 5, 0, 0}));
  // Two base points in one component are refused, naming both (one base point per component defines f).
  o.base_points = {3, 0, 2};
  expect_refused([&] { compute_geodesic_function(g, o); }, "base points 1 and 2 (vertices 0 and 2)");
  o.base_points = {9};
  expect_refused([&] { compute_geodesic_function(g, o); }, "base point 0 is vertex 9");
}

TEST(GeodesicFunction, DegenerateInputs) {
  EXPECT_EQ(compute_geodesic_function(Proximity_graph{}).status, Status::degenerate_input);
  Proximity_graph one;
  one.number_of_vertices = 1;
  const auto r = compute_geodesic_function(one);
  EXPECT_EQ(r.values, std::vector<double>{0.0});
  EXPECT_EQ(r.base_points, std::vector<std::size_t>{0});
  // Unweighted path: lengths 1, base is the far end.
  Proximity_graph path;
  path.number_of_vertices = 4;
  path.edges = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_EQ(compute_geodesic_function(path).values, (std::vector<double>{3, 2, 1, 0}));
  // All-zero lengths (duplicates): constant 0, base = smallest index.
  Proximity_graph zero = path;
  zero.edge_lengths = {0, 0, 0};
  const auto z = compute_geodesic_function(zero);
  EXPECT_EQ(z.values, (std::vector<double>{0, 0, 0, 0}));
  EXPECT_EQ(z.base_points, std::vector<std::size_t>{0});
}

TEST(GeodesicFunction, InterruptAndNonCanonical) {
  Geodesic_options o;
  o.progress = [](double) { return false; };
  Proximity_graph path;
  path.number_of_vertices = 3;
  path.edges = {{0, 1}, {1, 2}};
  EXPECT_EQ(compute_geodesic_function(path, o).status, Status::interrupted);
  path.edge_lengths = {1.0, -2.0};
  EXPECT_THROW(compute_geodesic_function(path), std::invalid_argument);
}

TEST(GeodesicFunction, DistancesBeyondTheLargestDoubleAreRefused) {
  // Each length is finite, their sums are not: success with inf values (and an inf vertex as the base point)
  // would only fail later, in the Reeb graph, without saying why.
  Proximity_graph path;
  path.number_of_vertices = 4;
  path.edges = {{0, 1}, {1, 2}, {2, 3}};
  path.edge_lengths = {1e308, 1e308, 1e308};
  expect_refused([&] { compute_geodesic_function(path); }, "the geodesic distance of vertex 2 overflows");
  path.edge_lengths = {5e307, 5e307, 5e307};  // 1.5e308: still finite
  EXPECT_EQ(compute_geodesic_function(path).values, (std::vector<double>{1.5e308, 1e308, 5e307, 0}));
}

// "no shortest path longer than the largest double (checked: throws naming a vertex whose distance
// overflows)": on the path 1 - 0 - 2 (lengths 1e308) every distance from the start vertex 0 is finite, but
// from the automatic base point (1, an end) vertex 2 lies 2e308 away; the same with that base point given.
TEST(GeodesicFunction, OverflowFromTheBasePointIsRefused) {
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{0, 1}, {0, 2}};
  g.edge_lengths = {1e308, 1e308};
  for (const std::vector<std::size_t>& given : {std::vector<std::size_t>{}, std::vector<std::size_t>{1}}) {
    Geodesic_options o;
    o.base_points = given;
    expect_refused([&] { compute_geodesic_function(g, o); }, "the geodesic distance of vertex 2 overflows");
  }
  g.edge_lengths = {8e307, 8e307};  // 1.6e308: finite
  EXPECT_EQ(compute_geodesic_function(g).values, (std::vector<double>{8e307, 0, 1.6e308}));
}

// Geodesic_result::component: "connected component of each vertex (numbered by smallest vertex)", isolated
// vertices included; base points follow that numbering. "every base point in options is <
// number_of_vertices": number_of_vertices itself is refused.
TEST(GeodesicFunction, ComponentsAndTheRangeOfBasePoints) {
  Proximity_graph g;
  g.number_of_vertices = 6;
  g.edges = {{0, 4}, {1, 2}, {2, 5}};
  const Geodesic_result r = compute_geodesic_function(g);
  EXPECT_EQ(r.component, (std::vector<std::uint32_t>{0, 1, 1, 2, 0, 1}));
  EXPECT_EQ(r.base_points, (std::vector<std::size_t>{4, 5, 3}));
  EXPECT_EQ(r.values, (std::vector<double>{1, 2, 1, 0, 0, 0}));
  Geodesic_options o;
  o.base_points = {6};
  expect_refused([&] { compute_geodesic_function(g, o); }, "base point 0 is vertex 6, out of range [0, 6)");
}

// Geodesic_options::progress, "called with the fraction done; returning false stops": the two Dijkstra runs
// report 0, 0.5 and 1; a refusal at 0 or at 0.5 returns status interrupted at once, without values and
// without asking again.
TEST(GeodesicFunction, ProgressReportsAndStops) {
  Proximity_graph path;
  path.number_of_vertices = 4;
  path.edges = {{0, 1}, {1, 2}, {2, 3}};
  std::vector<double> seen;
  Geodesic_options o;
  o.progress = test::recording_progress(seen);
  EXPECT_EQ(compute_geodesic_function(path, o).status, Status::success);
  EXPECT_EQ(seen, (std::vector<double>{0.0, 0.5, 1.0}));
  for (const std::size_t stop_at : {1u, 2u}) {
    seen.clear();
    o.progress = [&seen, stop_at](double t) {
      seen.push_back(t);
      return seen.size() < stop_at;
    };
    const Geodesic_result r = compute_geodesic_function(path, o);
    EXPECT_EQ(r.status, Status::interrupted) << stop_at;
    EXPECT_TRUE(r.values.empty()) << stop_at;
    EXPECT_EQ(seen.size(), stop_at);
  }
}

// "g canonical (checked)": a graph out of canonical form is refused as such, naming the problem, not by
// Dijkstra on a negative length (another std::invalid_argument) or, for unsorted edges, not at all.
TEST(GeodesicFunction, NonCanonicalGraphsAreRefusedAsSuch) {
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{0, 1}, {1, 2}};
  g.edge_lengths = {1.0, -2.0};
  for (int variant = 0; variant < 2; ++variant) {
    expect_refused([&] { compute_geodesic_function(g); },
                   "compute_geodesic_function: the graph is not canonical");
    g.edges = {{1, 2}, {0, 1}};  // unsorted
    g.edge_lengths = {1.0, 2.0};
  }
}
