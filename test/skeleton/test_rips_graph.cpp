// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/rips_graph.h>

#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/graph/adjacency_list.hpp>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using FeatureRecon::test::throws_with;

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {

using Coords = std::vector<std::vector<double>>;
/// A Boost graph with double edge weights, as users hand to proximity_graph_from_boost_graph().
using Weighted_boost_graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                          boost::property<boost::edge_weight_t, double>>;

Coords random_points(std::size_t n, std::size_t d, std::uint32_t seed, double scale = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, scale);
  Coords p(n, std::vector<double>(d));
  for (auto& x : p)
    for (double& c : x) c = u(rng);
  return p;
}

double dist(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

/// All pairs within r (brute force, doubles: exact on the integer grids used with it).
std::vector<Edge> brute_rips(const Coords& p, double r) {
  std::vector<Edge> e;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (dist(p[i], p[j]) <= r) e.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>(j)});
  return e;
}

/// Symmetrised kNN with ties by index (brute force).
std::vector<Edge> brute_knn(const Coords& p, std::size_t k) {
  std::vector<Edge> e;
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::vector<std::pair<double, std::size_t>> d;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i) d.emplace_back(dist(p[i], p[j]), j);
    std::sort(d.begin(), d.end());
    for (std::size_t t = 0; t < std::min(k, d.size()); ++t) {
      const auto a = static_cast<Vertex_index>(std::min(i, d[t].second)),
                 b = static_cast<Vertex_index>(std::max(i, d[t].second));
      e.push_back({a, b});
    }
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

/// Brute-force 3-cliques.
std::vector<Triangle> brute_triangles(const Proximity_graph& g) {
  std::vector<Triangle> t;
  const std::size_t n = g.number_of_vertices;
  for (Vertex_index a = 0; a < n; ++a)
    for (Vertex_index b = a + 1; b < n; ++b)
      for (Vertex_index c = b + 1; c < n; ++c)
        if (g.find_edge(a, b) >= 0 && g.find_edge(b, c) >= 0 && g.find_edge(a, c) >= 0)
          t.push_back({a, b, c});
  return t;
}

}  // namespace

TEST(RipsGraph, MatchesBruteForceInEveryDimensionAndSearch) {
  for (std::size_t d : {1u, 2u, 3u, 5u, 12u}) {
    const Coords p = random_points(300, d, static_cast<std::uint32_t>(d));
    const double r = 0.12 * std::sqrt(static_cast<double>(d));
    const auto expected = brute_rips(p, r);
    for (Neighbor_search s :
         {Neighbor_search::automatic, Neighbor_search::brute_force, Neighbor_search::kd_tree}) {
      if (s == Neighbor_search::kd_tree && d > 3) {
        Proximity_graph_options o;
        o.search = s;
        try {
          build_rips_graph(p, r, o);
          ADD_FAILURE() << "kd-tree in dimension " << d << ": expected an exception";
        } catch (const std::invalid_argument& e) {  // names the option and what to use instead
          EXPECT_EQ(
              std::string(e.what()),
              "build_rips_graph: the kd-tree search (options.search = Neighbor_search::kd_tree) supports "
              "dimension <= 3, got " +
                  std::to_string(d) + ": use automatic or brute_force");
        }
        continue;
      }
      Proximity_graph_options o;
      o.search = s;
      const Proximity_graph g = build_rips_graph(p, r, o);
      EXPECT_EQ(g.edges, expected) << "d = " << d;
      ASSERT_EQ(g.edge_lengths.size(), g.edges.size());
      for (std::size_t e = 0; e < g.edges.size(); ++e)
        EXPECT_NEAR(g.edge_lengths[e], dist(p[g.edges[e][0]], p[g.edges[e][1]]), 1e-12);
      EXPECT_TRUE(is_canonical(g));
    }
  }
}

TEST(RipsGraph, RadiusIsInclusiveOnGrids) {
  // Unit grid 6x6 in 2D: at r = 1 exactly the 4-neighbours, at r = sqrt(2) (rounded down) still only them,
  // at the next double above sqrt(2) the diagonals join.
  Coords p;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) p.push_back({double(i), double(j)});
  for (Neighbor_search s : {Neighbor_search::kd_tree, Neighbor_search::brute_force}) {
    Proximity_graph_options o;
    o.search = s;
    EXPECT_EQ(build_rips_graph(p, 1.0, o).number_of_edges(), 60u);
    EXPECT_EQ(build_rips_graph(p, std::nextafter(1.0, 0.0), o).number_of_edges(), 0u);
    const double s2 = std::sqrt(2.0);  // rounded: the exact test decides on which side of sqrt(2) it lies
    const bool s2_at_least = CGAL::Exact_rational(s2) * CGAL::Exact_rational(s2) >= CGAL::Exact_rational(2);
    EXPECT_EQ(build_rips_graph(p, s2, o).number_of_edges(), s2_at_least ? 110u : 60u);
    EXPECT_EQ(build_rips_graph(p, std::nextafter(s2, 2.0), o).number_of_edges(), 110u);
  }
}

TEST(RipsGraph, DegenerateInputs) {
  EXPECT_EQ(build_rips_graph(Coords{}, 1.0).number_of_vertices, 0u);
  const Proximity_graph one = build_rips_graph(Coords{{1, 2, 3}}, 1.0);
  EXPECT_EQ(one.number_of_vertices, 1u);
  EXPECT_EQ(one.number_of_edges(), 0u);
  // Duplicates are joined at length 0, even with radius 0.
  const Coords dup{{1, 1}, {1, 1}, {1, 1}, {5, 5}};
  const Proximity_graph g0 = build_rips_graph(dup, 0.0);
  EXPECT_EQ(g0.edges, (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(g0.edge_lengths, (std::vector<double>{0, 0, 0}));
  // Collinear points: a path.
  Coords line;
  for (int i = 0; i < 10; ++i) line.push_back({double(i), 2.0 * i, 0.0});
  EXPECT_EQ(build_rips_graph(line, std::sqrt(5.0) + 1e-9).number_of_edges(), 9u);
  // Points on a circle (cocircular): a cycle with chords only at the chosen radius.
  Coords circle;
  for (int i = 0; i < 12; ++i) circle.push_back({std::cos(i * M_PI / 6), std::sin(i * M_PI / 6)});
  const Simplicial_complex_2 k = build_rips_complex_2(circle, 0.6);
  EXPECT_EQ(k.number_of_edges(), 12u);
  EXPECT_EQ(k.number_of_triangles(), 0u);
}

TEST(RipsGraph, HugeAndTinyCoordinatesInTheBruteForceSearch) {
  // The brute-force search filters candidates in float: coordinates far outside float's range (2^130, 2^-130)
  // must still find every pair, with the exact decision on the doubles. A 4 x 4 grid of spacing s in 5-D (the
  // automatic search is brute force above 3-D) and in 2-D with the brute force asked for, radius s
  // (inclusive).
  for (const double s : {std::ldexp(1.0, 130), std::ldexp(1.0, -130)}) {
    for (const std::size_t d : {2u, 5u}) {
      Coords p;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          std::vector<double> x(d, 0.0);
          x[0] = s * i;
          x[1] = s * j;
          p.push_back(x);
        }
      p.push_back(p[5]);  // a duplicate
      Proximity_graph_options o;
      o.search = Neighbor_search::brute_force;
      const Proximity_graph g = build_rips_graph(p, s, o);
      EXPECT_EQ(g.edges, brute_rips(p, s)) << "s = " << s << ", d = " << d;
      EXPECT_EQ(g.number_of_edges(), 24u + 5u)
          << "s = " << s;  // grid edges plus the duplicate's 4 and itself
      EXPECT_EQ(build_knn_graph(p, 1, o).edges, brute_knn(p, 1)) << "s = " << s << ", d = " << d;
    }
  }
  // Next to the largest doubles: a duplicate pair 3e300 from the origin and a far point; no overflow.
  const Coords far{{3e300, 0, 0, 0, 0}, {3e300, 0, 0, 0, 0}, {-3e300, 0, 0, 0, 0}};
  EXPECT_EQ(build_rips_graph(far, 1.0).edges, (std::vector<Edge>{{0, 1}}));
  const Proximity_graph knn = build_knn_graph(far, 1);
  EXPECT_EQ(knn.edges, (std::vector<Edge>{{0, 1}, {0, 2}}));
  // Lengths whose squares overflow (6e300) or underflow (3e-200) come out right, and the graph stays
  // canonical.
  EXPECT_EQ(knn.edge_lengths, (std::vector<double>{0.0, 6e300}));
  EXPECT_TRUE(is_canonical(knn));
  const Coords tiny{{0, 0}, {3e-200, 0}, {1, 0}};
  EXPECT_EQ(build_knn_graph(tiny, 1).edge_lengths, (std::vector<double>{3e-200, 1.0}));
  // A length beyond the largest double is refused, naming the edge.
  const Coords beyond{{1.7e308, 0}, {-1.7e308, 0}};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { build_knn_graph(beyond, 1); },
      "build_knn_graph: edge 0 (points 0 and 1) is longer than the largest double"));
}

TEST(RipsGraph, BruteForceKeepsPairsAtTheRadiusThatUnderflowInFloat) {
  // Two points 2^e apart close to the centre of points at +-1: scaled for float, their coordinates' products
  // underflow (e <= -108), the float Gram matrix gave them the squared distance |p|^2 + |q|^2, and a purely
  // relative error bound rejected the pair at exactly the radius before the exact test (0 edges; the kd-tree
  // found 1). First the reported points, then a scan of spacings with the pair on an axis through the centre
  // and off it, in 4 and 8 dimensions; the k-nearest-neighbour search shares the filter.
  const double s116 = std::ldexp(1.0, -116);
  const Coords reported{{1, 0, 0, 0}, {-1, 0, 0, 0}, {s116, 0, 0, 0}, {2 * s116, 0, 0, 0}};
  for (Neighbor_search s : {Neighbor_search::brute_force, Neighbor_search::automatic}) {
    Proximity_graph_options o;
    o.search = s;
    EXPECT_EQ(build_rips_graph(reported, s116, o).edges, (std::vector<Edge>{{2, 3}}));
  }
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  std::size_t compared = 0;
  for (int e = -60; e >= -148; e -= 4)
    for (const std::size_t d : {4u, 8u})
      for (const bool off_axis : {false, true}) {
        const double c = std::ldexp(1.0, e), s = std::ldexp(1.0, e - 1);
        Coords p;
        for (std::size_t axis = 0; axis < 3; ++axis)
          for (const double sign : {1.0, -1.0}) {
            p.emplace_back(d, 0.0);
            p.back()[axis] = sign;
          }
        p.emplace_back(d, 0.0);
        p.emplace_back(d, 0.0);
        p[6][0] = c;  // the pair (c, 0) and (c + s, 0), or (c, c) and (c + s, c); the centre stays at 0
        p[7][0] = c + s;
        if (off_axis) p[6][1] = p[7][1] = c;
        const Proximity_graph g = build_rips_graph(p, s, o);
        EXPECT_EQ(g.edges, brute_rips(p, s)) << "e = " << e << ", d = " << d << ", off axis = " << off_axis;
        EXPECT_GE(g.find_edge(6, 7), 0) << "e = " << e << ", d = " << d << ", off axis = " << off_axis;
        EXPECT_EQ(build_rips_graph(p, std::nextafter(s, 0.0), o).find_edge(6, 7), -1) << "e = " << e;
        // (Not brute_knn(): in double, 1 - c and 1 - c - s tie for the points at +-1.)
        EXPECT_GE(build_knn_graph(p, 1, o).find_edge(6, 7), 0) << "e = " << e << ", d = " << d;
        ++compared;
      }
  EXPECT_EQ(compared, 92u);
}

TEST(RipsGraph, OneOutlierDoesNotMakeEveryPairACandidate) {
  // The brute force's float filter has an error growing with the squared distance from the centre: centred at
  // the mean, one point at 1e7 moved every other point 1e3 from it and every pair went to the exact predicate
  // (7.5 s instead of 0.4 s on 10,000 points in 50-D). Counted, not timed: with the outlier, the pairs left
  // to the double and exact stages are those of the cloud alone plus at most the outlier's row.
  const std::size_t n = 1500;
  Coords p = random_points(n, 20, 9);
  const double r = 1.2;
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  const auto counted = [&](const Coords& q, skeleton::internal::Rips_search_counts& counts) {
    return skeleton::internal::rips_graph(make_point_matrix(q), r, o, &counts);
  };
  skeleton::internal::Rips_search_counts alone;
  const Proximity_graph g = counted(p, alone);
  EXPECT_EQ(g.edges, brute_rips(p, r));
  EXPECT_GT(g.number_of_edges(), 50u);
  EXPECT_LT(alone.refined, 200u);
  for (const double far : {1e7, -1e30, 1e300}) {
    Coords q = p;
    q[n / 2][0] = far;
    skeleton::internal::Rips_search_counts counts;
    EXPECT_EQ(counted(q, counts).edges, brute_rips(q, r)) << far;
    EXPECT_LE(counts.refined, alone.refined + n) << far;
    EXPECT_LE(counts.exact, alone.exact) << far;
    // brute_knn() ties the outlier's distances in double from 1e30 on: compared without its edges.
    const auto without_outlier = [&](std::vector<Edge> edges) {
      const auto touches = [&](const Edge& e) { return e[0] == n / 2 || e[1] == n / 2; };
      edges.erase(std::remove_if(edges.begin(), edges.end(), touches), edges.end());
      return edges;
    };
    EXPECT_EQ(without_outlier(build_knn_graph(q, 3, o).edges), without_outlier(brute_knn(q, 3))) << far;
  }
}

TEST(RipsGraph, FarApartClustersAreSearchedEachWithItsOwnCentre) {
  // Two equal clusters 1e7 apart: the float filter's centre (the coordinate-wise median) lies in one of them,
  // and every pair of the other went to the double stage (4.1 s on 10,000 points in 50-D). Each group that no
  // edge crosses is now searched alone: with the second cluster interleaved by index (odd indices; the edges
  // map back to them) the counts are those of the two clusters alone, and the graph the brute force's.
  const std::size_t n = 1500;
  const double r = 1.2;
  Coords a = random_points(n, 20, 9), b = random_points(n, 20, 10);
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  skeleton::internal::Rips_search_counts ca, cb, both;
  const std::size_t ea = skeleton::internal::rips_graph(make_point_matrix(a), r, o, &ca).number_of_edges();
  const std::size_t eb = skeleton::internal::rips_graph(make_point_matrix(b), r, o, &cb).number_of_edges();
  Coords mixed;
  for (std::size_t i = 0; i < n; ++i) {
    mixed.push_back(a[i]);
    mixed.push_back(b[i]);
    mixed.back()[3] += 1e7;
  }
  const Proximity_graph g = skeleton::internal::rips_graph(make_point_matrix(mixed), r, o, &both);
  EXPECT_EQ(g.edges, brute_rips(mixed, r));
  EXPECT_EQ(g.number_of_edges(), ea + eb);
  EXPECT_GT(ea, 50u);
  EXPECT_LE(both.refined, ca.refined + cb.refined + n);  // b's coordinates differ by the rounding at 1e7
  EXPECT_EQ(both.exact, ca.exact + cb.exact);
  // The groups: a gap wider than the radius on the widest axis cuts, one of exactly the radius does not (the
  // pair across it is an edge), and each part is cut again on its own widest axis.
  const auto groups = [](const Coords& p, double radius) {
    return skeleton::internal::separated_groups(make_point_matrix(p), radius);
  };
  using Groups = std::vector<std::vector<std::uint32_t>>;
  EXPECT_EQ(groups({{0, 0}, {10, 0}, {1, 0}, {11, 0.5}}, 1.0), (Groups{{0, 2}, {1, 3}}));
  EXPECT_EQ(groups({{0, 0}, {10, 0}, {1, 0}, {11, 0.5}}, 9.0), (Groups{{0, 1, 2, 3}}));
  EXPECT_EQ(groups({{0, 0}, {1, 0}, {2, 0}}, 1.0), (Groups{{0, 1, 2}}));              // gaps of exactly r
  EXPECT_EQ(groups({{0, 0}, {std::nextafter(1.0, 2.0), 0}}, 1.0), (Groups{{0, 1}}));  // within the slack
  EXPECT_EQ(groups({{0, 0}, {0, 0}, {0, 0}}, 0.0), (Groups{{0, 1, 2}}));              // duplicates
  EXPECT_EQ(groups({{0, 0}, {0, 5}, {8, 0}, {8, 5}}, 2.0), (Groups{{0}, {1}, {2}, {3}}));  // x, then y
  EXPECT_EQ(groups({{0, 0}, {1e308, 0}, {-1e308, 0}}, 1.0), (Groups{{0}, {1}, {2}}));  // the range overflows
  EXPECT_EQ(groups({}, 1.0).size(), 1u);
  for (const double radius :
       {0.0, 1.0, 2.0})  // the same graphs as the brute force on small grids with copies
    for (const Coords& p :
         {Coords{{0, 0}, {0, 0}, {3, 0}, {3, 1}, {6, 1}}, Coords{{0, 0, 0}, {2, 2, 2}, {2, 2, 4}}})
      EXPECT_EQ(build_rips_graph(p, radius, o).edges, brute_rips(p, radius)) << radius;
}

TEST(RipsGraph, TinyAndHugeCoordinatesInTheKdTree) {
  // Squared distances of coordinates below about 1e-154 are subnormal, rounded absolutely: the kd-tree's ball
  // (with a relative slack) lost pairs within r, and its nearest neighbours were wrong. The same clouds
  // scaled by 2^537 (exactly) are the oracle. Also scaled by 2^500 up, where squares overflowed.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t compared = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Coords unit_cloud;
    // An integer grid: the oracle's squared distances are exact, so are its ties.
    for (int i = 0; i < 30; ++i) unit_cloud.push_back({std::round(u(rng) * 20), std::round(u(rng) * 20)});
    const double r = 1 + u(rng) * 5;
    for (const int e : {-537, 500}) {
      Coords scaled = unit_cloud;
      for (auto& x : scaled)
        for (double& c : x) c = std::ldexp(c, e);
      Proximity_graph_options o;
      o.search = Neighbor_search::kd_tree;
      EXPECT_EQ(build_rips_graph(scaled, std::ldexp(r, e), o).edges, brute_rips(unit_cloud, r))
          << trial << " " << e;
      EXPECT_EQ(build_knn_graph(scaled, 2, o).edges, brute_knn(unit_cloud, 2)) << trial << " " << e;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 200u);
  // The smallest case: two points within r at 2^-535.
  const Coords two{{0, 0}, {0x1.62b6588bca4f5p-535, 0x1.6d2299c2349aep-535}};
  EXPECT_EQ(build_rips_graph(two, 0x1.fd0ff72c70e89p-535).edges, (std::vector<Edge>{{0, 1}}));
}

TEST(RipsGraph, BadInputNamesThePoint) {
  Coords p = random_points(5, 3, 1);
  p[3][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { build_rips_graph(p, 1.0); }, "point 3"));
  p[3][1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(build_knn_graph(p, 2), std::invalid_argument);
  Coords mixed{{0, 0}, {1, 1, 1}};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { build_rips_graph(mixed, 1.0); }, "point 1"));
  EXPECT_THROW(build_rips_graph(random_points(3, 2, 1), -1.0), std::invalid_argument);
  EXPECT_THROW(build_rips_graph(random_points(3, 2, 1), std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  EXPECT_THROW(build_knn_graph(random_points(3, 2, 1), 0), std::invalid_argument);
}

TEST(KnnGraph, MatchesBruteForceWithTiesByIndex) {
  // Integer grid with duplicates: many equal distances.
  Coords p;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 5; ++j) p.push_back({double(i), double(j)});
  p.push_back({3, 2});
  p.push_back({3, 2});
  for (std::size_t k : {1u, 2u, 4u, 7u}) {
    for (Neighbor_search s : {Neighbor_search::kd_tree, Neighbor_search::brute_force}) {
      Proximity_graph_options o;
      o.search = s;
      EXPECT_EQ(build_knn_graph(p, k, o).edges, brute_knn(p, k)) << "k = " << k;
    }
  }
  for (std::size_t d : {2u, 3u, 8u}) {
    const Coords q = random_points(200, d, 40 + static_cast<std::uint32_t>(d));
    EXPECT_EQ(build_knn_graph(q, 6).edges, brute_knn(q, 6)) << "d = " << d;
  }
  // Many copies of few positions (the kd-tree search handles each position once) among scattered points, with
  // k below, at and above the number of copies; and integer points with ties at every distance.
  Coords heavy = random_points(80, 3, 77);
  for (int c = 0; c < 40; ++c) {
    heavy.push_back({0.5, 0.5, 0.5});
    heavy.push_back({0.25, 0.75, 0.5});
    if (c % 2 == 0) heavy.push_back(heavy[3]);
  }
  std::shuffle(heavy.begin(), heavy.end(), std::mt19937(5));
  for (std::size_t k : {1u, 3u, 19u, 20u, 21u, 39u, 40u, 41u, 100u}) {
    Proximity_graph_options kd;
    kd.search = Neighbor_search::kd_tree;
    EXPECT_EQ(build_knn_graph(heavy, k, kd).edges, brute_knn(heavy, k)) << "k = " << k;
  }
  Coords ties;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int c = 0; c <= (i + j) % 3; ++c) ties.push_back({double(i), double(j)});
  for (std::size_t k : {1u, 2u, 4u, 5u, 9u})
    EXPECT_EQ(build_knn_graph(ties, k).edges, brute_knn(ties, k)) << "k = " << k;
  // n <= k: the complete graph.
  EXPECT_EQ(build_knn_graph(random_points(4, 2, 3), 10).number_of_edges(), 6u);
  EXPECT_EQ(build_knn_graph(Coords{{0.0, 0.0}}, 3).number_of_edges(), 0u);
  EXPECT_EQ(build_knn_graph(Coords{}, 3).number_of_vertices, 0u);
}

TEST(KnnGraph, NearestByIntervalsThenExactly) {
  // keep_nearest_exactly() orders by enclosures of the squared distances and calls the exact predicate only
  // where they overlap and are not one exact value; the oracle sorts every candidate with the exact
  // predicate. Candidates are exact ties with inexact squares (0.1 on different axes), neighbours in the last
  // bit, copies, and integers.
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> pick(0, 5);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t d = trial % 2 == 0 ? 3 : 5;
    Point_matrix m;
    m.dimension = d;
    const std::vector<double> base = {0.1, 0.3, 1.0, 3.0, 0.7};
    for (std::size_t i = 0; i < 40; ++i)
      for (std::size_t c = 0; c < d; ++c) {
        double x = base[(i + c) % 5] * (pick(rng) - 2);
        if (pick(rng) == 0) x = std::nextafter(x, 10.0);
        if (trial % 3 == 0) x = std::round(x * 10);
        m.data.push_back(x);
      }
    m.rows = 40;
    std::vector<std::uint32_t> cand;
    for (std::uint32_t j = 1; j < 40; ++j) cand.push_back(j);
    std::vector<std::uint32_t> oracle = cand;
    std::sort(oracle.begin(), oracle.end(), [&](std::uint32_t a, std::uint32_t b) {
      const int c = skeleton::internal::compare_squared_distances(m.row(0), m.row(a), m.row(b), d);
      return c < 0 || (c == 0 && a < b);
    });
    const std::size_t keep = 1 + static_cast<std::size_t>(trial % 39);
    skeleton::internal::keep_nearest_exactly(m, m.row(0), cand, keep);
    oracle.resize(keep);
    EXPECT_EQ(cand, oracle) << "trial " << trial;
  }
}

TEST(KnnGraph, KdTreeSkipsTheBallOnlyPastAClearGap) {
  // Up to 3-D the kd-tree search asks for one position more than it needs; when that one lies clearly beyond
  // the last needed, the positions before it are the candidates and no ball query is made. Ties (exact, or of
  // inexact squares: multiples of 0.1), copies, collinear points, UTM-sized offsets and tiny or huge scales
  // are compared with the brute force (whose exact order is tested above), and the ball is counted.
  std::mt19937_64 rng(7);
  std::size_t balls = 0, positions = 0;
  for (int trial = 0; trial < 900; ++trial) {
    const std::size_t d = 1 + static_cast<std::size_t>(trial % 3), n = 1 + rng() % 60;
    const int kind = (trial / 3) % 5;
    const double scale = trial % 7 == 0 ? 1e9 : (trial % 7 == 1 ? 1e-200 : 1.0),
                 offset = trial % 11 == 0 ? 4.6e6 : 0;
    Point_matrix m;
    m.dimension = d;
    m.rows = n;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < d; ++c) {
        double x = 0;
        if (kind == 0) x = std::uniform_real_distribution<double>(0, 1)(rng);
        if (kind == 1) x = static_cast<double>(rng() % 5);  // a grid with copies
        if (kind == 2) x = static_cast<double>(rng() % 3) * 0.1;
        if (kind == 3) x = c == 0 ? static_cast<double>(rng() % 20) : 0.0;  // collinear
        if (kind == 4) x = std::ldexp(static_cast<double>(rng() % 8), -static_cast<int>(rng() % 3));
        m.data.push_back(offset + x * scale);
      }
    const std::size_t k = 1 + rng() % 10;
    Proximity_graph_options kd, brute;
    kd.search = Neighbor_search::kd_tree;
    brute.search = Neighbor_search::brute_force;
    skeleton::internal::Knn_search_counts counts;
    EXPECT_EQ(skeleton::internal::knn_graph(m, k, kd, &counts).edges, build_knn_graph(m, k, brute).edges)
        << "trial " << trial;
    balls += counts.ball_queries;
    positions += n;
  }
  EXPECT_GT(balls, positions / 20);  // the ties and copies need the ball
  // A grid with k = 8: the 8 nearest (4 at 1, 4 at sqrt 2) are followed by a gap (2) everywhere but where the
  // border makes ties at the k-th.
  Point_matrix grid;
  grid.dimension = 2;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) grid.data.insert(grid.data.end(), {double(i), double(j)});
  grid.rows = 900;
  skeleton::internal::Knn_search_counts counts;
  Proximity_graph_options kd;
  kd.search = Neighbor_search::kd_tree;
  const Proximity_graph g = skeleton::internal::knn_graph(grid, 8, kd, &counts);
  Proximity_graph_options brute;
  brute.search = Neighbor_search::brute_force;
  EXPECT_EQ(g.edges, build_knn_graph(grid, 8, brute).edges);
  EXPECT_GT(counts.ball_queries, 0u);
  EXPECT_LT(counts.ball_queries, 200u);
}

TEST(KnnGraph, FarClustersAreSearchedAloneAndJoinedAcrossGaps) {
  // The brute force (dimension > 3) splits off groups far from the rest (isolated_groups()) and searches each
  // with its own float filter; a group answers for a point only when the k-th nearest within it lies within
  // the group's separation, other points are searched among all. Two clusters 1e7 apart interleaved by index:
  // one centre made every pair of one cluster go to the double stage (4 s on 10,000 points in 50-D); now the
  // counts are the clusters' own.
  const std::size_t n = 600, k = 4;
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  const Coords a = random_points(n, 12, 21), b = random_points(n, 12, 22);
  Coords mixed;
  for (std::size_t i = 0; i < n; ++i) {
    mixed.push_back(a[i]);
    mixed.push_back(b[i]);
    mixed.back()[5] += 1e7;
  }
  skeleton::internal::Knn_search_counts ca, cb, both;
  (void)skeleton::internal::knn_graph(make_point_matrix(a), k, o, &ca);
  (void)skeleton::internal::knn_graph(make_point_matrix(b), k, o, &cb);
  const Proximity_graph g = skeleton::internal::knn_graph(make_point_matrix(mixed), k, o, &both);
  EXPECT_EQ(g.edges, brute_knn(mixed, k));
  EXPECT_EQ(both.unresolved, 0u);
  EXPECT_LE(both.refined, ca.refined + cb.refined + 2 * n);  // b's coordinates differ by the rounding at 1e7
  EXPECT_LT(both.refined, n * n / 10);                       // one filter for both: every pair of one cluster
  const auto groups = skeleton::internal::isolated_groups(make_point_matrix(mixed), k + 1);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].rows.front(), 0u);
  EXPECT_EQ(groups[1].rows.front(), 1u);
  EXPECT_GT(groups[0].separation, 9e6);

  // Two groups whose gap on the widest axis (10, from x = 9 to x = 19) exceeds both sides' widest ranges (9),
  // but not every distance within them: A = (t, t, t, t) and B = (19 + t, 9, 9, 9), t = 0..9, shuffled. For k
  // = 9, A's (9, 9, 9, 9) has its k-th nearest within A at 18 (the origin), beyond the separation: it is
  // searched among all, and finds B's points at 10..18 (the one at 18 ties with the origin, decided by
  // index).
  Coords ab;
  for (int t = 0; t < 10; ++t) {
    ab.push_back({double(t), double(t), double(t), double(t)});
    ab.push_back({19.0 + t, 9.0, 9.0, 9.0});
  }
  std::shuffle(ab.begin(), ab.end(), std::mt19937(3));
  const auto cut = skeleton::internal::isolated_groups(make_point_matrix(ab), 10);
  ASSERT_EQ(cut.size(),
            2u);  // (A and B are not cut further: their gaps of 1 are not wider than their points)
  for (const auto& group : cut) {
    EXPECT_EQ(group.rows.size(), 10u);
    EXPECT_EQ(group.separation, std::nextafter(10 * (1 - 0x1p-50), 0.0));
  }
  for (const std::size_t kl : {1u, 3u, 8u, 9u, 10u, 12u, 19u}) {
    skeleton::internal::Knn_search_counts c;
    EXPECT_EQ(skeleton::internal::knn_graph(make_point_matrix(ab), kl, o, &c).edges, brute_knn(ab, kl))
        << "k = " << kl;
    if (kl == 1) {
      EXPECT_EQ(c.unresolved, 0u);
    }
    if (kl == 9) {  // every point of A has one of A at 10 or more (B's points are within 9 of each other)
      EXPECT_EQ(c.unresolved, 10u);
    }
    if (kl >= 10) {
      EXPECT_EQ(c.unresolved, 0u);  // A and B would hold fewer than k + 1 points: not cut
    }
  }
  // Progress with groups: their rows in [0, 0.9], the points searched among all in [0.9, 1], non-decreasing;
  // a stop in the second stage ends it (no report after the refusal, fewer edges).
  {
    std::vector<double> seen;
    Proximity_graph_options watched = o;
    watched.progress = test::recording_progress(seen);
    const std::vector<Edge> all = build_knn_graph(ab, 9, watched).edges;
    EXPECT_EQ(all, brute_knn(ab, 9));
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 0.9), 1);  // the second stage's start
    std::vector<double> after_stop;
    bool refused = false;
    watched.progress = [&](double t) {
      if (refused) after_stop.push_back(t);
      refused = refused || t >= 0.9;
      return t < 0.9;
    };
    EXPECT_LT(build_knn_graph(ab, 9, watched).edges.size(), all.size());
    EXPECT_TRUE(after_stop.empty());
  }
  // A gap of subnormal width: exact, and gap (1 - 2^-50) rounds back to it, so the separation is one step
  // below. The origin's nearest (k = 1) ties at 2^-1073 between points 0, 1 (across the gap) and 3 (its own
  // side; the brute force in double squares these to 0): point 0 by index.
  const double eps = std::numeric_limits<double>::denorm_min();
  const Coords tiny = {
      {2 * eps, 0, 0, 0, 0}, {2 * eps, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, eps, eps, eps, eps}};
  const auto tiny_groups = skeleton::internal::isolated_groups(make_point_matrix(tiny), 2);
  ASSERT_EQ(tiny_groups.size(), 2u);
  EXPECT_LT(tiny_groups[0].separation, 2 * eps);
  EXPECT_EQ(build_knn_graph(tiny, 1, o).edges, (std::vector<Edge>{{0, 1}, {0, 2}, {2, 3}}));
  // Three clusters far apart on one axis (400, 5 and 200 points; the 5 are a group of their own for k = 4,
  // too few for k = 5 and go with a neighbour), copies across clusters, a far point of a group's float
  // filter; every answer the brute force's.
  Coords three = random_points(400, 6, 23);
  for (int c = 0; c < 5; ++c) three.push_back({1e9 + c, 0, 0, 0, 0, 0});
  Coords other = random_points(200, 6, 24);
  for (auto& q : other) {
    q[0] -= 5e8;
    three.push_back(q);
  }
  three.push_back(three[7]);
  three.push_back(three[410]);
  three.push_back({0.5, 0.5, 1e6, 0.5, 0.5, 0.5});  // within the first cluster's group, 1e6 from it
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(three), 5).size(), 3u);
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(three), 6).size(), 2u);
  for (const std::size_t kl : {1u, 2u, 4u, 5u, 8u})
    EXPECT_EQ(build_knn_graph(three, kl, o).edges, brute_knn(three, kl)) << "k = " << kl;
  // Spread-out data and grids are not cut (4-D grid: every gap is 1, the parts beside it span 4); no points,
  // no groups.
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(random_points(500, 8, 25)), 2).size(), 1u);
  Coords grid;
  for (int i = 0; i < 625; ++i)
    grid.push_back({double(i % 5), double(i / 5 % 5), double(i / 25 % 5), double(i / 125)});
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(grid), 2).size(), 1u);
  EXPECT_EQ(build_knn_graph(grid, 8, o).edges, brute_knn(grid, 8));
  Coords line;  // evenly spaced: every gap exceeds 1/16 of the range, but not the parts beside it
  for (int x = 0; x < 10; ++x) line.push_back({double(x), 0, 0, 0});
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(line), 2).size(), 1u);
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(line), 1).size(),
            10u);  // singletons allowed
  line.push_back({1e3, 0, 0, 0});
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(line), 2).size(),
            1u);  // one point: too few
  line.push_back({1e3 + 1, 0, 0, 0});
  EXPECT_EQ(skeleton::internal::isolated_groups(make_point_matrix(line), 2).size(), 2u);
  EXPECT_TRUE(skeleton::internal::isolated_groups(make_point_matrix(Coords{}), 1).empty());
}

TEST(RipsGraph, KernelsAndUserPointTypes) {
  const Coords p = random_points(80, 3, 5);
  const auto expected = build_rips_graph(p, 0.3).edges;
  std::vector<CGAL::Epick::Point_3> epick;
  std::vector<CGAL::Epeck::Point_3> epeck;
  std::vector<CGAL::Epick_d<CGAL::Dynamic_dimension_tag>::Point_d> dyn;
  std::vector<std::array<double, 3>> arr;
  std::vector<Eigen::Vector3d> eig;
  for (const auto& x : p) {
    epick.emplace_back(x[0], x[1], x[2]);
    epeck.emplace_back(x[0], x[1], x[2]);
    dyn.emplace_back(x.begin(), x.end());
    arr.push_back({x[0], x[1], x[2]});
    eig.emplace_back(x[0], x[1], x[2]);
  }
  EXPECT_EQ(build_rips_graph(epick, 0.3).edges, expected);
  EXPECT_EQ(build_rips_graph(epeck, 0.3).edges, expected);
  EXPECT_EQ(build_rips_graph(dyn, 0.3).edges, expected);
  EXPECT_EQ(build_rips_graph(arr, 0.3).edges, expected);
  EXPECT_EQ(build_rips_graph(eig, 0.3).edges, expected);
  // 2D CGAL points.
  std::vector<CGAL::Epick::Point_2> p2;
  Coords c2;
  for (const auto& x : p) {
    p2.emplace_back(x[0], x[1]);
    c2.push_back({x[0], x[1]});
  }
  EXPECT_EQ(build_rips_graph(p2, 0.2).edges, build_rips_graph(c2, 0.2).edges);
  // A user's own point type with its own traits.
  struct My_point {
    float xyz[3];
  };
  struct My_traits {
    using Point = My_point;
    std::size_t dimension(const Point&) const { return 3; }
    double coordinate(const Point& p, std::size_t i) const { return p.xyz[i]; }
  };
  std::vector<My_point> mine;
  Coords as_float;
  for (const auto& x : p) {
    mine.push_back({{float(x[0]), float(x[1]), float(x[2])}});
    as_float.push_back({double(float(x[0])), double(float(x[1])), double(float(x[2]))});
  }
  EXPECT_EQ(build_rips_graph(mine, 0.3, {}, My_traits{}).edges, build_rips_graph(as_float, 0.3).edges);
}

TEST(DistanceMatrix, RipsAndKnnMatchPoints) {
  const Coords p = random_points(60, 4, 8);
  std::vector<std::vector<double>> D(p.size(), std::vector<double>(p.size()));
  Eigen::MatrixXd M(p.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) M(i, j) = D[i][j] = dist(p[i], p[j]);
  EXPECT_EQ(build_rips_graph_from_distance_matrix(D, 0.5).edges, brute_rips(p, 0.5));
  EXPECT_EQ(build_rips_graph_from_distance_matrix(M, 0.5).edges, brute_rips(p, 0.5));
  EXPECT_EQ(build_knn_graph_from_distance_matrix(D, 5).edges, brute_knn(p, 5));
  // Inclusive radius.
  std::vector<std::vector<double>> E{{0, 1, 2}, {1, 0, 1}, {2, 1, 0}};
  EXPECT_EQ(build_rips_graph_from_distance_matrix(E, 1.0).number_of_edges(), 2u);
  EXPECT_EQ(build_rips_graph_from_distance_matrix(E, 2.0).number_of_edges(), 3u);
  EXPECT_EQ(build_rips_graph_from_distance_matrix(std::vector<std::vector<double>>{}, 1.0).number_of_vertices,
            0u);
}

TEST(DistanceMatrix, ProgressAndStopOfBothBuilders) {
  // 4100 points on a line (distance |i - j|): the Rips graph at radius 1 is the path. Reports every 4096 rows
  // (Rips: fraction of the pairs; k-NN every 1024 rows: fraction of the rows), increasing, ending at 1; a
  // stop keeps the edges of the rows visited before it.
  const std::size_t n = 4100;
  Eigen::MatrixXd D(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) D(i, j) = std::fabs(double(i) - double(j));
  std::vector<double> seen;
  Proximity_graph_options o;
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const Proximity_graph full = build_rips_graph_from_distance_matrix(D, 1.0, o);
  EXPECT_EQ(full.number_of_edges(), n - 1);
  EXPECT_EQ(full.status, Status::success);
  ASSERT_EQ(seen.size(), 2u);  // row 4096, then 1
  EXPECT_NEAR(seen[0], 1 - std::pow(1 - 4096.0 / n, 2), 1e-12);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
  int calls = 0;
  o.progress = [&](double) { return ++calls < 1; };
  const Proximity_graph stopped = build_rips_graph_from_distance_matrix(D, 1.0, o);
  EXPECT_EQ(stopped.number_of_edges(), 4096u);  // rows 0..4095 each give their edge to the next
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(calls, 1);  // returning false stops: no report (of 1) after it
  seen.clear();
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const Proximity_graph knn = build_knn_graph_from_distance_matrix(D, 1, o);
  EXPECT_EQ(knn.number_of_edges(), n - 1);
  EXPECT_EQ(knn.status, Status::success);
  EXPECT_EQ(seen, (std::vector<double>{1024.0 / n, 2048.0 / n, 3072.0 / n, 4096.0 / n, 1.0}));
  calls = 0;
  o.progress = [&](double) { return ++calls < 2; };
  // Rows 0..2047; the nearest of i > 0 is i - 1 (the tie with i + 1 goes to the smaller index): the path to
  // 2047.
  const Proximity_graph knn_stopped = build_knn_graph_from_distance_matrix(D, 1, o);
  EXPECT_EQ(knn_stopped.number_of_edges(), 2047u);
  EXPECT_EQ(knn_stopped.status, Status::interrupted);
  EXPECT_EQ(calls, 2);  // no report (of 1) after the refusal
}

TEST(DistanceMatrix, BadMatricesNameTheEntry) {
  auto refused_with = [](const std::vector<std::vector<double>>& D, const std::string& part) {
    return test::throws_with<std::invalid_argument>([&] { build_rips_graph_from_distance_matrix(D, 1.0); },
                                                    part);
  };
  EXPECT_TRUE(refused_with({{0, 1, 2}, {1, 0, 1}, {2, 1.5, 0}}, "not symmetric at (1, 2)"));
  EXPECT_TRUE(refused_with({{0, -1}, {-1, 0}}, "entry (0, 1)"));
  EXPECT_TRUE(refused_with({{0, 1}, {1, 0.5}}, "diagonal entry (1, 1)"));
  EXPECT_TRUE(refused_with({{0, 1}, {1}}, "row 1"));
  EXPECT_TRUE(refused_with({{0, std::nan("")}, {std::nan(""), 0}}, "entry (0, 1)"));
  Eigen::MatrixXd M(2, 3);
  M.setZero();
  EXPECT_THROW(build_rips_graph_from_distance_matrix(M, 1.0), std::invalid_argument);
}

TEST(BoostGraphInput, WeightedGraphBecomesCanonical) {
  Weighted_boost_graph g(5);
  add_edge(3, 1, 2.0, g);
  add_edge(0, 1, 1.0, g);
  add_edge(1, 0, 7.0, g);  // parallel: first weight kept
  add_edge(4, 4, 1.0, g);  // self-loop dropped
  const Proximity_graph p = proximity_graph_from_boost_graph(g, get(boost::edge_weight, g));
  EXPECT_EQ(p.number_of_vertices, 5u);
  EXPECT_EQ(p.edges, (std::vector<Edge>{{0, 1}, {1, 3}}));
  EXPECT_EQ(p.edge_lengths, (std::vector<double>{1.0, 2.0}));
  add_edge(2, 3, -1.0, g);
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] { proximity_graph_from_boost_graph(g, get(boost::edge_weight, g)); }, "edge 4"));
}

TEST(FlagComplex, TrianglesAreTheThreeCliques) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const Coords p = random_points(120, 2, seed);
    const Proximity_graph g = build_rips_graph(p, 0.15);
    const Simplicial_complex_2 k = build_flag_complex_2(g);
    EXPECT_EQ(k.triangles, brute_triangles(g));
    EXPECT_TRUE(is_canonical(k));
    EXPECT_EQ(k.edges, g.edges);
  }
  Proximity_graph bad;
  bad.number_of_vertices = 2;
  bad.edges = {{1, 0}};
  EXPECT_THROW(build_flag_complex_2(bad), std::invalid_argument);
}

// The triangle limit is checked while counting: exactly the limit passes, one less is refused with the
// counts; progress covers both passes (counting below one half), and a stop during counting stores no
// triangle.
TEST(FlagComplex, TriangleLimitAndProgressOfBothPasses) {
  Proximity_graph complete;  // K_12: C(12, 3) = 220 triangles
  complete.number_of_vertices = 12;
  for (Vertex_index u = 0; u < 12; ++u)
    for (Vertex_index v = u + 1; v < 12; ++v) complete.edges.push_back({u, v});
  Flag_complex_options o;
  o.max_triangles = 220;
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  const Simplicial_complex_2 k = build_flag_complex_2(complete, o);
  EXPECT_EQ(k.number_of_triangles(), 220u);
  EXPECT_EQ(k.status, Status::success);
  EXPECT_EQ(k.triangles, build_flag_complex_2(complete).triangles);
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_EQ(std::count_if(seen.begin(), seen.end(), [](double t) { return t < 0.5; }),
            12);  // counting: 12 vertices
  o.max_triangles = 219;
  try {
    build_flag_complex_2(complete, o);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(),
                         "build_flag_complex_2: the flag complex has more than 219 triangles "
                         "(Flag_complex_options::max_triangles; 12 vertices, 66 edges, the limit "
                         "was passed at vertex 9)"));
  }
  // 0: no limit.
  o.max_triangles = 0;
  EXPECT_EQ(build_flag_complex_2(complete, o).number_of_triangles(), 220u);
  // A stop at the first call (during counting): no triangles, and no further call.
  int calls = 0;
  o.progress = [&calls](double) { return ++calls > 1; };
  const Simplicial_complex_2 stopped = build_flag_complex_2(complete, o);
  EXPECT_TRUE(stopped.triangles.empty());
  EXPECT_EQ(stopped.edges, complete.edges);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(calls, 1);
  // A stop while storing (the first report of the second pass, 0.5): some triangles, status interrupted.
  o.progress = [](double t) { return t < 0.5; };
  const Simplicial_complex_2 storing = build_flag_complex_2(complete, o);
  EXPECT_LT(storing.number_of_triangles(), 220u);
  EXPECT_EQ(storing.status, Status::interrupted);
  // The callback overload takes any callable (a lambda, a std::function); `{}` is the options overload (it
  // was ambiguous between the options and a std::function).
  calls = 0;
  EXPECT_TRUE(build_flag_complex_2(complete, [&calls](double) { return ++calls > 1; }).triangles.empty());
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(build_flag_complex_2(complete, Progress_callback()).triangles, k.triangles);
  EXPECT_TRUE(build_flag_complex_2(complete, [n = 0](double) mutable { return ++n > 1; }).triangles.empty());
  EXPECT_EQ(build_flag_complex_2(complete, {}).triangles, k.triangles);
}

TEST(RipsComplex, TheOneCallTakesTheTriangleLimit) {
  // build_rips_complex_2() took only the graph's options, so a caller of the one call could not refuse a
  // radius too large for the data as build_flag_complex_2() and extract_reeb_skeleton() can.
  Coords circle;  // 12 points within 2 of each other: K_12 at radius 3, C(12, 3) = 220 triangles
  for (int i = 0; i < 12; ++i) circle.push_back({std::cos(0.5 * i), std::sin(0.5 * i)});
  Rips_complex_options o;
  o.max_triangles = 220;
  EXPECT_EQ(build_rips_complex_2(circle, 3.0, o).number_of_triangles(), 220u);
  o.max_triangles = 219;
  EXPECT_TRUE(contains(test::invalid_argument_message([&] { build_rips_complex_2(circle, 3.0, o); }),
                       "build_rips_complex_2: the flag complex has more than 219 triangles "
                       "(Rips_complex_options::max_triangles; 12 vertices, 66 edges"));
  o.max_triangles = 0;  // no limit
  EXPECT_EQ(build_rips_complex_2(circle, 3.0, o).number_of_triangles(), 220u);
  // The graph's options still convert (search and progress kept, no limit); `{}` is the default.
  Proximity_graph_options g;
  g.search = Neighbor_search::brute_force;
  int calls = 0;
  g.progress = [&calls](double) { return ++calls > 0; };
  EXPECT_EQ(build_rips_complex_2(circle, 3.0, g).number_of_triangles(), 220u);
  EXPECT_GT(calls, 2);
  EXPECT_EQ(build_rips_complex_2(circle, 3.0, {}).number_of_triangles(), 220u);
  const Rips_complex_options converted = g;
  EXPECT_EQ(converted.search, Neighbor_search::brute_force);
  EXPECT_EQ(converted.max_triangles, 0u);
  EXPECT_TRUE(static_cast<bool>(converted.progress));
}

TEST(RipsComplex, ProgressCoversBothStagesAndAStopEndsBoth) {
  // A 30 x 30 grid at radius 1.5 (diagonals in): the graph stage reports up to 0.5, the triangles up to 1, in
  // order; a stop in the graph stage builds no triangle and asks nothing more; the builders of graphs do not
  // report 1 after a stop (they did).
  Coords grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) grid.push_back({double(i), double(j)});
  const Simplicial_complex_2 plain = build_rips_complex_2(grid, 1.5);
  ASSERT_GT(plain.number_of_triangles(), 0u);
  std::vector<double> seen;
  Proximity_graph_options o;
  o.progress = test::recording_progress(seen);
  const Simplicial_complex_2 watched = build_rips_complex_2(grid, 1.5, o);
  EXPECT_EQ(watched.edges, plain.edges);
  EXPECT_EQ(watched.triangles, plain.triangles);
  EXPECT_EQ(watched.status, Status::success);
  EXPECT_EQ(plain.status, Status::success);
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::count(seen.begin(), seen.end(), 0.5) >= 1);  // the graph's end, the triangles' start
  EXPECT_GT(std::count_if(seen.begin(), seen.end(), [](double t) { return t > 0 && t < 0.5; }), 10);
  EXPECT_GT(std::count_if(seen.begin(), seen.end(), [](double t) { return t > 0.5 && t < 1; }), 10);
  for (const Neighbor_search search : {Neighbor_search::kd_tree, Neighbor_search::brute_force}) {
    std::vector<double> after_stop;
    bool refused = false;
    o.search = search;
    o.progress = [&](double t) {
      if (refused) after_stop.push_back(t);
      refused = refused || t >= 0.25;
      return t < 0.25;
    };
    const Simplicial_complex_2 stopped = build_rips_complex_2(grid, 1.5, o);
    EXPECT_TRUE(stopped.triangles.empty());
    EXPECT_LT(stopped.number_of_edges(), plain.number_of_edges());
    EXPECT_EQ(stopped.status, Status::interrupted);
    EXPECT_TRUE(after_stop.empty()) << after_stop.front();
    after_stop.clear();
    refused = false;
    EXPECT_EQ(build_knn_graph(grid, 4, o).status, Status::interrupted);
    EXPECT_TRUE(after_stop.empty()) << after_stop.front();
    // A refusal of the graph stage's last report (0.5): every edge, no triangle, status interrupted.
    o.progress = [](double t) { return t < 0.5; };
    const Simplicial_complex_2 graph_only = build_rips_complex_2(grid, 1.5, o);
    EXPECT_EQ(graph_only.edges, plain.edges);
    EXPECT_TRUE(graph_only.triangles.empty());
    EXPECT_EQ(graph_only.status, Status::interrupted);
  }
}

TEST(ProximityGraph, TheFirstNonCanonicalEdgeIsNamed) {
  auto problem = [](std::size_t n, std::vector<Edge> edges, std::vector<double> lengths = {}) {
    Proximity_graph g;
    g.number_of_vertices = n;
    g.edges = std::move(edges);
    g.edge_lengths = std::move(lengths);
    EXPECT_FALSE(is_canonical(g));
    return test::invalid_argument_message([&] { build_flag_complex_2(g); });
  };
  auto expect_in = [](const std::string& what, const std::string& part) {
    EXPECT_TRUE(contains(what, part));
  };
  expect_in(problem(3, {{0, 1}, {1, 1}}),
            "build_flag_complex_2: the graph is not canonical (see Proximity_graph): "
            "edge 1 (1, 1) is a loop");
  expect_in(problem(3, {{0, 1}, {1, 7}}), "edge 1 (1, 7) has a vertex beyond the 3 vertices");
  expect_in(problem(3, {{2, 0}}), "edge 0 (2, 0) is not in increasing order");
  expect_in(problem(3, {{0, 2}, {0, 1}}), "edge 1 (0, 1) is not after edge 0 (0, 2)");
  expect_in(problem(3, {{0, 1}, {0, 1}}), "edge 1 (0, 1) is not after edge 0 (0, 1)");
  expect_in(problem(3, {{0, 1}, {1, 2}}, {1.0, std::nan("")}), "edge 1 (1, 2) has length nan");
  expect_in(problem(3, {{0, 1}}, {1.0, 2.0}), "edge_lengths has 2 values for 1 edges");
  // connected_components() checked nothing: an edge beyond the vertices read out of bounds.
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{0, 1}, {1, 5}};
  try {
    connected_components(g);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    expect_in(e.what(), "connected_components: edge 1 (1, 5) has a vertex beyond the 3 vertices");
  }
}

// make_simplicial_complex_2 sorts edges by a comparison sort below 1024 edges and by radix sorts on 64-bit
// keys from 1024 on: both give the lexicographic order without repetitions, each edge with its first
// occurrence's length, for vertex indices up to the largest 32-bit one.
TEST(MakeSimplicialComplex, EdgeOrderAndFirstLengthsOnBothSortPaths) {
  std::mt19937 rng(2026);
  for (const std::size_t m : {0u, 1u, 1023u, 1024u, 1025u, 50000u}) {
    for (const std::size_t n :
         {std::size_t(2), std::size_t(40), std::size_t(5000), std::size_t(4294967295u)}) {
      std::vector<Edge> edges;
      std::vector<double> lengths;
      while (edges.size() < m) {
        Vertex_index a = static_cast<Vertex_index>(rng() % n), b = static_cast<Vertex_index>(rng() % n);
        if (a == b) continue;
        if (rng() % 2 != 0) std::swap(a, b);  // either order
        edges.push_back({a, b});
        lengths.push_back(static_cast<double>(edges.size()));  // the occurrence's position
      }
      // Reference: the first occurrence of each edge by a map.
      std::map<Edge, double> first;
      for (std::size_t i = 0; i < edges.size(); ++i)
        first.emplace(Edge{std::min(edges[i][0], edges[i][1]), std::max(edges[i][0], edges[i][1])},
                      lengths[i]);
      const Simplicial_complex_2 weighted = make_simplicial_complex_2(n, edges, {}, lengths);
      const Simplicial_complex_2 plain = make_simplicial_complex_2(n, edges, {});
      ASSERT_EQ(weighted.edges.size(), first.size()) << m << " edges on " << n << " vertices";
      EXPECT_EQ(plain.edges, weighted.edges);
      std::size_t i = 0;
      for (const auto& [edge, length] : first) {
        EXPECT_EQ(weighted.edges[i], edge);
        EXPECT_EQ(weighted.edge_lengths[i], length) << "edge " << i;
        ++i;
      }
      EXPECT_TRUE(is_canonical(weighted));
      if (m >= 1024 && n == 40) {  // the radix path met repetitions (780 edges exist)
        EXPECT_LT(first.size(), m);
      }
    }
  }
}

// The two radix sorts called directly, at every size (the threshold above does not hide them): the in-place
// sort of edges against std::sort, the stable sort of keys with a payload against std::stable_sort.
TEST(MakeSimplicialComplex, RadixSortsMatchComparisonSorts) {
  std::mt19937_64 rng(7);
  for (const std::size_t m : {0u, 1u, 2u, 63u, 64u, 65u, 700u, 20000u}) {
    for (const int b : {1, 5, 11, 22, 32}) {
      const std::uint64_t range = std::uint64_t(1) << b;
      std::vector<Edge> edges(m);
      for (Edge& e : edges)
        e = {static_cast<Vertex_index>(rng() % range), static_cast<Vertex_index>(rng() % range)};
      std::vector<Edge> expected = edges;
      std::sort(expected.begin(), expected.end());
      skeleton::internal::flag_sort_edges(edges.data(), edges.data() + edges.size(), b,
                                          2 * b >= 8 ? 2 * b - 8 : 0);
      EXPECT_EQ(edges, expected) << m << " edges, " << b << " bits";
      std::vector<std::uint64_t> keys(m);
      std::vector<std::size_t> payload(m);
      for (std::size_t i = 0; i < m; ++i) {
        keys[i] = rng() % (std::uint64_t(1) << std::min(2 * b, 63)) / (i % 3 == 0 ? 1 : 64);  // repeated keys
        payload[i] = i;
      }
      std::vector<std::size_t> order = payload;
      std::stable_sort(order.begin(), order.end(),
                       [&keys](std::size_t x, std::size_t y) { return keys[x] < keys[y]; });
      std::vector<std::uint64_t> sorted_keys(m);
      for (std::size_t i = 0; i < m; ++i) sorted_keys[i] = keys[order[i]];
      skeleton::internal::radix_sort(keys, payload, 2 * b);
      EXPECT_EQ(keys, sorted_keys) << m << " keys, " << 2 * b << " bits";
      EXPECT_EQ(payload, order) << m << " keys, " << 2 * b << " bits";
    }
  }
  // Edges of triangles that repeat given edges keep the given lengths; the others get implied_edge_length.
  std::vector<Edge> given;
  std::vector<double> lengths;
  std::vector<Triangle> triangles;
  for (Vertex_index v = 0; v + 2 < 1500; ++v) {
    given.push_back({v, static_cast<Vertex_index>(v + 1)});
    lengths.push_back(0.5);
    triangles.push_back({v, static_cast<Vertex_index>(v + 1), static_cast<Vertex_index>(v + 2)});
  }
  const Simplicial_complex_2 K = make_simplicial_complex_2(1500, given, triangles, lengths, 2.5);
  ASSERT_EQ(K.edges.size(), 1499u + 1498u);  // the path and the chords v, v + 2
  for (std::size_t e = 0; e < K.edges.size(); ++e) {
    // (1498, 1499) is implied
    const bool is_given = K.edges[e][1] == K.edges[e][0] + 1 && K.edges[e][0] < 1498;
    EXPECT_EQ(K.edge_lengths[e], is_given ? 0.5 : 2.5) << "edge " << e;
  }
}

TEST(RipsGraph, SameInputSameOutput) {
  const Coords p = random_points(500, 3, 77);
  const Proximity_graph a = build_rips_graph(p, 0.1), b = build_rips_graph(p, 0.1);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_lengths, b.edge_lengths);
}

TEST(EveryEntryPoint, EmptyAndTiedInputs) {
  // Empty graph and complex.
  const Simplicial_complex_2 empty = build_flag_complex_2(Proximity_graph{});
  EXPECT_EQ(empty.number_of_vertices, 0u);
  EXPECT_TRUE(empty.triangles.empty());
  EXPECT_EQ(make_simplicial_complex_2(0, {}, {}).number_of_vertices, 0u);
  // Distance matrices with duplicates (zero off the diagonal) and all-equal distances: ties by index.
  const std::vector<std::vector<double>> dup{{0, 0, 1}, {0, 0, 1}, {1, 1, 0}};
  EXPECT_EQ(build_rips_graph_from_distance_matrix(dup, 0.0).edges, (std::vector<Edge>{{0, 1}}));
  std::vector<std::vector<double>> equal(5, std::vector<double>(5, 2.0));
  for (int i = 0; i < 5; ++i) equal[i][i] = 0;
  // Each vertex picks the two smallest other indices: 0->{1,2}, 1->{0,2}, 2->{0,1}, 3->{0,1}, 4->{0,1}.
  EXPECT_EQ(build_knn_graph_from_distance_matrix(equal, 2).edges,
            (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}}));
  EXPECT_EQ(build_knn_graph_from_distance_matrix(std::vector<std::vector<double>>{{0}}, 2).number_of_edges(),
            0u);
  // Points: all the same (a single cluster of duplicates) gives the complete graph at any radius and k.
  const Coords same(6, std::vector<double>{1.5, -2.0, 3.0});
  EXPECT_EQ(build_rips_graph(same, 0.0).number_of_edges(), 15u);
  EXPECT_EQ(build_flag_complex_2(build_rips_graph(same, 0.0)).number_of_triangles(), 20u);
  EXPECT_EQ(build_knn_graph(same, 2).edges, brute_knn(same, 2));
  // An empty Boost graph.
  const Weighted_boost_graph g0;
  EXPECT_EQ(proximity_graph_from_boost_graph(g0, get(boost::edge_weight, g0)).number_of_vertices, 0u);
}

namespace {
/// The smallest double r with |p - q| <= r, decided in exact rational arithmetic.
double smallest_radius_holding(const std::vector<double>& p, const std::vector<double>& q) {
  CGAL::Exact_rational d2(0);
  for (std::size_t c = 0; c < p.size(); ++c) {
    const CGAL::Exact_rational t = CGAL::Exact_rational(p[c]) - CGAL::Exact_rational(q[c]);
    d2 += t * t;
  }
  const auto holds = [&d2](double r) { return CGAL::Exact_rational(r) * CGAL::Exact_rational(r) >= d2; };
  double r = dist(p, q);
  while (!holds(r)) r = std::nextafter(r, std::numeric_limits<double>::infinity());
  while (r > 0 && holds(std::nextafter(r, 0.0))) r = std::nextafter(r, 0.0);
  return r;
}

}  // namespace

// build_rips_graph(): "an edge between every two points at distance <= radius (inclusive, decided exactly on
// the double coordinates)", in every search. Pairs of random points with inexact squared distances, at the
// smallest radius that holds them by an exact oracle: the edge is there, and gone one double below. Neither
// the kd-tree's ball (rounded squared distances of scaled coordinates) nor the brute force's float and
// double stages (sums of many rounded squares) may round such a pair out, or in.
TEST(RipsGraph, PairsAtExactlyTheRadiusInEverySearch) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t pairs = 0;
  for (const std::size_t d : {2u, 3u, 16u, 300u}) {
    for (int trial = 0; trial < 200; ++trial) {
      const double scale = trial % 2 == 0 ? 1.0 : 1e5;
      Coords p(2, std::vector<double>(d));
      for (auto& x : p)
        for (double& c : x) c = u(rng) * scale;
      const double r = smallest_radius_holding(p[0], p[1]);
      for (const Neighbor_search s : {Neighbor_search::kd_tree, Neighbor_search::brute_force}) {
        if (s == Neighbor_search::kd_tree && d > 3) continue;
        Proximity_graph_options o;
        o.search = s;
        EXPECT_EQ(build_rips_graph(p, r, o).number_of_edges(), 1u)
            << "d = " << d << ", trial " << trial << ", kd-tree " << (s == Neighbor_search::kd_tree);
        EXPECT_EQ(build_rips_graph(p, std::nextafter(r, 0.0), o).number_of_edges(), 0u)
            << "d = " << d << ", trial " << trial << ", kd-tree " << (s == Neighbor_search::kd_tree);
      }
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, 800u);
}

// Proximity_graph_options::progress, "called with the fraction done; returning false stops":
// build_rips_graph() reports non-decreasing fractions from 0 to 1 in both searches (the brute force searches
// two clusters farther apart than the radius each alone, several blocks each: one scale for both), and after
// a refusal it reports nothing more (not even 1).
TEST(RipsGraph, ProgressIsNonDecreasingAndEndsAtARefusal) {
  Coords two = random_points(300, 4, 41);
  for (const auto& x : random_points(300, 4, 42)) {
    two.push_back(x);
    two.back()[0] += 10;
  }
  const double r = 0.4;
  for (const Neighbor_search s : {Neighbor_search::kd_tree, Neighbor_search::brute_force}) {
    Coords p = two;
    if (s == Neighbor_search::kd_tree)
      for (auto& x : p) x.resize(3);
    std::vector<double> seen;
    Proximity_graph_options o;
    o.search = s;
    o.progress = test::recording_progress(seen);
    const Proximity_graph g = build_rips_graph(p, r, o);
    EXPECT_EQ(g.edges, brute_rips(p, r));
    EXPECT_EQ(g.status, Status::success);
    ASSERT_GT(seen.size(), 2u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << "kd-tree " << (s == Neighbor_search::kd_tree);
    EXPECT_EQ(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
    int calls = 0;
    o.progress = [&calls](double) {
      ++calls;
      return false;
    };
    const Proximity_graph stopped = build_rips_graph(p, r, o);
    EXPECT_LT(stopped.number_of_edges(), brute_rips(p, r).size());
    EXPECT_EQ(stopped.status, Status::interrupted);
    EXPECT_EQ(calls, 1) << "kd-tree " << (s == Neighbor_search::kd_tree);
  }
}

// make_point_matrix() "throws std::invalid_argument naming the first point whose dimension differs from the
// first point's, that has dimension 0, or that has a NaN or infinite coordinate"; a Point_matrix built by
// hand is checked by the builders (rows * dimension values, dimension >= 1 with rows, finite coordinates,
// naming the point), and their Point_matrix overloads check k >= 1 and the radius as the range ones do.
TEST(RipsGraph, PointMatricesAreChecked) {
  const auto expect_in = [](const std::string& what, const std::string& part) {
    EXPECT_TRUE(contains(what, part));
  };
  const double inf = std::numeric_limits<double>::infinity();
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_point_matrix(Coords{{}, {}});
            }),
            "point 0 has dimension 0");
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_point_matrix(Coords{{0, 0, 0}, {1, 1}});
            }),
            "point 1 has dimension 2 but point 0 has dimension 3");
  expect_in(FeatureRecon::test::invalid_argument_message([&] {
              make_point_matrix(Coords{{0, 0}, {1, -inf}});
            }),
            "point 1 has a non-finite coordinate 1");
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_point_matrix(Coords{{0, std::nan("")}});
            }),
            "point 0 has a non-finite coordinate 1");
  Point_matrix m;
  m.dimension = 2;
  m.rows = 2;
  m.data = {0, 0, 1, 1, 2};
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_rips_graph(m, 1.0); }),
            "points has 2 rows of dimension 2 but 5 values");
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_knn_graph(m, 1); }),
            "points has 2 rows of dimension 2 but 5 values");
  m.data = {0, 0, inf, 1};
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_rips_graph(m, 1.0); }),
            "point 1 has a non-finite coordinate 0");
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_knn_graph(m, 1); }),
            "point 1 has a non-finite coordinate 0");
  m.data = {0, 0, 1, 1};
  EXPECT_EQ(build_rips_graph(m, 2.0).number_of_edges(), 1u);
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_knn_graph(m, 0); }),
            "build_knn_graph: k must be >= 1, got 0");
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_rips_graph(m, -1.0); }),
            "build_rips_graph: radius must be finite");
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_rips_graph(m, inf); }),
            "build_rips_graph: radius must be finite");
  m.dimension = 0;
  m.data.clear();
  expect_in(FeatureRecon::test::invalid_argument_message([&] { build_rips_graph(m, 1.0); }),
            "points has dimension 0");
}

// isolated_groups() cuts a set at the gaps of its widest coordinate "that exceed 1/16 of that coordinate's
// range and the extent (widest coordinate range) of the parts on both sides, when both parts have at least
// min_size points": a gap equal to the parts' extent does not cut, one a double wider does. The parts are
// those between gaps over 1/16 of the range: one point left alone between a gap of 1/11 of the range and the
// wide gap is a part too small, so neither gap cuts (were the point a part of its cluster, the wide gap would
// cut). The k-nearest-neighbour graphs stay the brute force's.
TEST(KnnGraph, IsolatedGroupsCutOnlyAtTheDocumentedGaps) {
  const auto groups = [](const Coords& p, std::size_t min_size) {
    return skeleton::internal::isolated_groups(make_point_matrix(p), min_size).size();
  };
  EXPECT_EQ(groups({{0, 0}, {0, 1}, {1, 0}, {1, 1}}, 2), 1u);
  const double wider = std::nextafter(1.0, 2.0);
  EXPECT_EQ(groups({{0, 0}, {0, 1}, {wider, 0}, {wider, 1}}, 2), 2u);
  const Coords lone{{0, 0, 0, 0},  {0.01, 0, 0, 0},  {0.02, 0, 0, 0},  {0.9, 0, 0, 0},
                    {10, 0, 0, 0}, {10.01, 0, 0, 0}, {10.02, 0, 0, 0}, {10.03, 0, 0, 0}};
  EXPECT_EQ(groups(lone, 2), 1u);
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  for (const std::size_t k : {1u, 2u, 3u})
    EXPECT_EQ(build_knn_graph(lone, k, o).edges, brute_knn(lone, k)) << "k = " << k;
}

// first_copies() / first_copies_of_rows(): "first[i] is the smallest index whose coordinates equal row i's
// (i for the first copy) ... Returns false, leaving first empty, when every row is distinct": copies are
// found wherever they sort, also as the first two rows of the lexicographic order.
TEST(Copies, FoundWhereverTheySort) {
  Point_matrix q;
  q.dimension = 2;
  q.data = {1, 3, 0, 0, 0, 0};
  q.rows = 3;
  std::vector<Vertex_index> first;
  ASSERT_TRUE(skeleton::internal::first_copies(q, first));
  EXPECT_EQ(first, (std::vector<Vertex_index>{0, 1, 1}));
  const std::vector<double> a{0, 0, 5, 0, 0, 5, 5, 5, 0};  // points 0 and 1 are copies
  ASSERT_TRUE(skeleton::internal::first_copies_of_rows(a, 3, first));
  EXPECT_EQ(first, (std::vector<Vertex_index>{0, 0, 2}));
  const std::vector<double> b{0, 1, 5, 1, 0, 5, 5, 5, 0};
  EXPECT_FALSE(skeleton::internal::first_copies_of_rows(b, 3, first));
  EXPECT_TRUE(first.empty());
}

// proximity_graph_from_boost_graph(): "every weight is finite and >= 0": a zero weight (two copies of a
// point) is an edge of length 0.
TEST(BoostGraphInput, ZeroWeightsAreEdges) {
  Weighted_boost_graph g(3);
  add_edge(2, 0, 0.0, g);
  add_edge(1, 2, 1.5, g);
  const Proximity_graph p = proximity_graph_from_boost_graph(g, get(boost::edge_weight, g));
  EXPECT_EQ(p.edges, (std::vector<Edge>{{0, 2}, {1, 2}}));
  EXPECT_EQ(p.edge_lengths, (std::vector<double>{0.0, 1.5}));
}

// The bounds of the canonical form. make_simplicial_complex_2() throws naming "an edge or triangle with a
// vertex out of range" (number_of_vertices itself is out of range) and lengths not aligned with the edges,
// accepts a length 0 (only negative or non-finite ones are refused) and removes repetitions, of triangles too
// (given in any vertex order); find_edge() takes "(either order)"; is_canonical() refuses a vertex equal to
// number_of_vertices and, for a complex, triangles out of order or without their three edges;
// connected_components() refuses an edge beyond the vertices.
TEST(MakeSimplicialComplex, BoundsOfTheCanonicalForm) {
  const auto expect_in = [](const std::string& what, const std::string& part) {
    EXPECT_TRUE(contains(what, part));
  };
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_simplicial_complex_2(3, {{0, 3}}, {});
            }),
            "edge 0 (0, 3) has a vertex index out of range [0, 3)");
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_simplicial_complex_2(3, {}, {{0, 1, 3}});
            }),
            "triangle 0 has vertex index 3 out of range [0, 3)");
  expect_in(FeatureRecon::test::invalid_argument_message([] {
              make_simplicial_complex_2(3, {{0, 1}}, {}, {1.0, 2.0});
            }),
            "lengths has 2 entries for 1 edges");
  const Simplicial_complex_2 k =
      make_simplicial_complex_2(3, {{1, 0}}, {{2, 1, 0}, {0, 1, 2}, {1, 2, 0}}, {0.0});
  EXPECT_EQ(k.triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(k.edges, (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(k.edge_lengths, (std::vector<double>{0.0, 1.0, 1.0}));
  EXPECT_TRUE(is_canonical(k));
  EXPECT_EQ(k.find_edge(1, 0), 0);
  EXPECT_EQ(k.find_edge(2, 1), 2);
  EXPECT_EQ(k.find_edge(2, 0), k.find_edge(0, 2));
  Simplicial_complex_2 bad = k;
  bad.triangles = {{0, 1, 2}, {0, 1, 2}};
  EXPECT_FALSE(is_canonical(bad));
  bad = k;
  bad.edges.pop_back();
  bad.edge_lengths.pop_back();
  EXPECT_FALSE(is_canonical(bad));  // edge (1, 2) of the triangle is missing
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{1, 3}};
  EXPECT_FALSE(is_canonical(g));
  expect_in(FeatureRecon::test::invalid_argument_message([&] { connected_components(g); }),
            "connected_components: edge 0 (1, 3) has a vertex beyond the 3 vertices");
}

// keep_nearest_exactly(): "only runs of overlapping enclosures that are not all the same exact value (a tie,
// which the index decides) are ordered by the exact predicate": a run whose first enclosure is inexact is
// ordered exactly, even when the others are one exact value equal to its lower end. From the origin, (1,
// 1e-10) (squared distance 1 + 1e-20, enclosed in [1, 1 + 2^-52]) is farther than (0, 1) and (-1, 0) (exactly
// 1), though its index is smaller.
TEST(KnnGraph, AnInexactEnclosureAtAnExactTieIsOrderedExactly) {
  Point_matrix m;
  m.dimension = 2;
  m.rows = 4;
  m.data = {0, 0, 1, 1e-10, 0, 1, -1, 0};
  for (const std::size_t keep : {1u, 2u, 3u}) {
    std::vector<std::uint32_t> cand{1, 2, 3};
    skeleton::internal::keep_nearest_exactly(m, m.row(0), cand, keep);
    std::vector<std::uint32_t> expected{2, 3, 1};
    expected.resize(keep);
    EXPECT_EQ(cand, expected) << "keep " << keep;
  }
}

// Neighbor_search::automatic: "kd-tree up to dimension 3, blocked brute force above". Counted: in 3-D the
// automatic search does exactly the kd-tree's work (ball queries for the ties of an integer grid), in 4-D the
// brute force's (no ball query).
TEST(KnnGraph, AutomaticSearchIsTheKdTreeUpToThreeDimensions) {
  for (const std::size_t d : {3u, 4u}) {
    Coords grid;
    for (int i = 0; i < 216; ++i) {
      grid.push_back({double(i % 6), double(i / 6 % 6), double(i / 36)});
      if (d == 4) grid.back().push_back(0.5 * (i % 2));
    }
    const Point_matrix m = make_point_matrix(grid);
    Proximity_graph_options automatic, explicit_search;
    explicit_search.search = d <= 3 ? Neighbor_search::kd_tree : Neighbor_search::brute_force;
    skeleton::internal::Knn_search_counts a, e;
    EXPECT_EQ(skeleton::internal::knn_graph(m, 6, automatic, &a).edges,
              skeleton::internal::knn_graph(m, 6, explicit_search, &e).edges);
    EXPECT_EQ(a.ball_queries, e.ball_queries) << "d = " << d;
    EXPECT_EQ(a.refined, e.refined) << "d = " << d;
    if (d <= 3) {
      EXPECT_GT(a.ball_queries, 0u);
    } else {
      EXPECT_EQ(a.ball_queries, 0u);
    }
  }
}

// Searches the kd-tree's Rips graph (radius r) and k-nearest graph (k) of `cloud` and of each of its copies
// moved by `move(coordinate, e)` (the radius by `move_radius(r, e)`) for e in `es`: the same graphs, as many
// pairs given to the exact test, and as many ball queries (at most as many, unless `same_ball_queries`). The
// cloud's own search must leave all but a fraction `max_exact` of its pairs out of the exact test.
template <class Move, class Move_radius>
void expect_kd_search_alike(const Coords& cloud, double r, std::size_t k, std::initializer_list<int> es,
                            Move move, Move_radius move_radius, double max_exact, bool same_ball_queries) {
  Proximity_graph_options kd;
  kd.search = Neighbor_search::kd_tree;
  skeleton::internal::Rips_search_counts rips_cloud;
  skeleton::internal::Knn_search_counts knn_cloud;
  const Proximity_graph r1 = skeleton::internal::rips_graph(make_point_matrix(cloud), r, kd, &rips_cloud);
  const Proximity_graph k1 = skeleton::internal::knn_graph(make_point_matrix(cloud), k, kd, &knn_cloud);
  const double n = static_cast<double>(cloud.size());
  ASSERT_LT(static_cast<double>(rips_cloud.exact), max_exact * n * (n - 1) / 2);  // the ball leaves most out
  for (const int e : es) {
    Coords moved = cloud;
    for (auto& x : moved)
      for (double& c : x) c = move(c, e);
    skeleton::internal::Rips_search_counts rips;
    skeleton::internal::Knn_search_counts knn;
    EXPECT_EQ(skeleton::internal::rips_graph(make_point_matrix(moved), move_radius(r, e), kd, &rips).edges,
              r1.edges)
        << e;
    EXPECT_EQ(skeleton::internal::knn_graph(make_point_matrix(moved), k, kd, &knn).edges, k1.edges) << e;
    EXPECT_EQ(rips.exact, rips_cloud.exact) << e;
    if (same_ball_queries)
      EXPECT_EQ(knn.ball_queries, knn_cloud.ball_queries) << e;
    else
      EXPECT_LE(knn.ball_queries, knn_cloud.ball_queries) << e;
  }
}

// The kd-tree searches in units scaled by a power of two (Kd_index: "so that CGAL's squared distances neither
// overflow nor sink into subnormals"): a cloud scaled by 2^-600 or 2^600 (exactly) is searched as at unit
// scale, with the same candidates (Rips: pairs given to the exact test) and ball queries (k nearest), and the
// same graphs.
TEST(RipsGraph, TheKdTreeSearchesEveryScaleAlike) {
  const auto scale = [](double x, int e) { return std::ldexp(x, e); };
  expect_kd_search_alike(random_points(200, 3, 61), 0.15, 4, {-600, 600}, scale, scale, 0.25, true);
}

// The kd-tree's ball does not grow with the coordinates: clouds translated by 2^40 and 2^50 (about 1e12 and
// 1e15; exactly, every coordinate a multiple of 1/4 in [0, 1024]) give the exact test the same number of
// pairs as at the origin and the same graphs (a slack of 1e-9 times the coordinates had made every pair of
// the cloud a candidate: featurerecon skeleton on GPS traces offset by 1e12 ran 15 times slower).
TEST(RipsGraph, TheKdTreeBallDoesNotGrowWithTheCoordinates) {
  Coords cloud = random_points(500, 3, 67);
  for (auto& x : cloud)
    for (double& c : x) c = std::round(4096 * c) / 4;
  expect_kd_search_alike(
      cloud, 102.4, 5, {40, 50}, [](double x, int e) { return x + std::ldexp(1.0, e); },
      [](double r, int) { return r; }, 0.1, false);
}

// The k-nearest-neighbour brute force leaves points "more than 2^15 times the median point's distance" from
// the centre out of its float filter: one outlier, even at 1e300 (where the others' float coordinates would
// underflow), adds at most its own row and column to the pairs refined in double (counted, not timed), and
// the graph among the others stays the brute force's.
TEST(KnnGraph, OneOutlierDoesNotMakeEveryPairARefinement) {
  const std::size_t n = 600, k = 3;
  const Coords p = random_points(n, 12, 51);
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  skeleton::internal::Knn_search_counts alone;
  EXPECT_EQ(skeleton::internal::knn_graph(make_point_matrix(p), k, o, &alone).edges, brute_knn(p, k));
  for (const double far : {1e7, -1e30, 1e300}) {
    Coords q = p;
    q[n / 2][0] = far;
    skeleton::internal::Knn_search_counts counts;
    std::vector<Edge> edges = skeleton::internal::knn_graph(make_point_matrix(q), k, o, &counts).edges;
    EXPECT_LE(counts.refined, alone.refined + 2 * n) << far;
    const auto touches = [&](const Edge& e) { return e[0] == n / 2 || e[1] == n / 2; };
    std::vector<Edge> expected = brute_knn(q, k);
    edges.erase(std::remove_if(edges.begin(), edges.end(), touches), edges.end());
    expected.erase(std::remove_if(expected.begin(), expected.end(), touches), expected.end());
    EXPECT_EQ(edges, expected) << far;
  }
}

// Proximity_graph_options::progress for the k-nearest-neighbour brute force with groups: "called with the
// fraction done", non-decreasing to 1, the groups' rows before the points searched among all. Two clusters 9
// apart (200 points, then 300 and an outlier of the second's group whose nearest lie beyond the gap): the
// second group's second block starts past nine tenths of the points.
TEST(KnnGraph, ProgressWithGroupsIsNonDecreasing) {
  Coords p = random_points(200, 4, 71);
  for (const auto& x : random_points(300, 4, 72)) {
    p.push_back(x);
    p.back()[0] += 10;
  }
  p.push_back({10.5, 8.5, 8.5, 8.5});
  ASSERT_EQ(skeleton::internal::isolated_groups(make_point_matrix(p), 4).size(), 2u);
  std::vector<double> seen;
  Proximity_graph_options o;
  o.search = Neighbor_search::brute_force;
  o.progress = test::recording_progress(seen);
  skeleton::internal::Knn_search_counts counts;
  EXPECT_EQ(skeleton::internal::knn_graph(make_point_matrix(p), 3, o, &counts).edges, brute_knn(p, 3));
  EXPECT_GE(counts.unresolved, 1u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
}

// The same point set through every kernel: Simple_cartesian<double>, Epick and Epeck, in 2D and 3D.
template <class Point>
class RipsGraphKernels : public ::testing::Test {};
using Kernel_points =
    ::testing::Types<CGAL::Simple_cartesian<double>::Point_2, CGAL::Epick::Point_2, CGAL::Epeck::Point_2,
                     CGAL::Simple_cartesian<double>::Point_3, CGAL::Epick::Point_3, CGAL::Epeck::Point_3>;
TYPED_TEST_SUITE(RipsGraphKernels, Kernel_points);

TYPED_TEST(RipsGraphKernels, SameGraphAsBruteForceOnAGridWithTies) {
  using Point = TypeParam;
  constexpr int dim = CGAL::Ambient_dimension<Point>::value;
  // A 5x5(x2) integer grid with a duplicate: many equal distances, points exactly at the radius.
  std::vector<Point> points;
  Coords coords;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < (dim == 3 ? 2 : 1); ++k) {
        if constexpr (dim == 2) {
          points.emplace_back(i, j);
          coords.push_back({double(i), double(j)});
        } else {
          points.emplace_back(i, j, k);
          coords.push_back({double(i), double(j), double(k)});
        }
      }
  points.push_back(points[7]);
  coords.push_back(coords[7]);
  for (double r : {0.0, 1.0, std::sqrt(2.0), 2.0}) {
    EXPECT_EQ(build_rips_graph(points, r).edges, build_rips_graph(coords, r).edges) << "r = " << r;
    EXPECT_EQ(build_rips_graph(points, r).edges, brute_rips(coords, r)) << "r = " << r;
  }
  EXPECT_EQ(build_knn_graph(points, 4).edges, brute_knn(coords, 4));
}
