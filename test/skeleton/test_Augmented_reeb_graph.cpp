// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplicial_complex_from_mesh.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {

Reeb_graph reeb(const Complex_with_function& c) {
  return compute_augmented_reeb_graph(c.complex, c.f).reeb_graph();
}

/// Checks the structural invariants of an augmented Reeb graph and its Reeb graph.
void expect_invariants(const Simplicial_complex_2& K, const std::vector<double>& f) {
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, f);
  const Reeb_graph R = A.reeb_graph();
  ASSERT_EQ(A.number_of_nodes(), K.number_of_vertices);
  for (const auto& a : A.arcs()) EXPECT_LT(A.rank()[a.lower], A.rank()[a.upper]);
  // Every vertex is a critical node or interior to exactly one arc; interiors increase along the arc.
  std::vector<int> seen(K.number_of_vertices, 0);
  for (const auto& node : R.nodes) ++seen[node.vertex];
  for (const auto& arc : R.arcs) {
    Vertex_index prev = R.nodes[arc.lower].vertex;
    for (Vertex_index v : arc.vertices) {
      ++seen[v];
      EXPECT_LT(A.rank()[prev], A.rank()[v]);
      prev = v;
    }
    EXPECT_LT(A.rank()[prev], A.rank()[R.nodes[arc.upper].vertex]);
  }
  for (std::size_t v = 0; v < K.number_of_vertices; ++v) EXPECT_EQ(seen[v], 1) << "vertex " << v;
  // Components of the Reeb graph are those of the complex; loops never exceed b1 of the 1-skeleton.
  EXPECT_EQ(R.components, connected_components(K).count);
  EXPECT_LE(R.loops(), K.number_of_edges() + R.components - K.number_of_vertices);
  // Degrees: sum of up-degrees = sum of down-degrees = number of augmented arcs.
  std::size_t up = 0, down = 0;
  for (Vertex_index v = 0; v < K.number_of_vertices; ++v) {
    up += A.up_degree(v);
    down += A.down_degree(v);
  }
  EXPECT_EQ(up, A.number_of_arcs());
  EXPECT_EQ(down, A.number_of_arcs());
}

}  // namespace

TEST(AugmentedReebGraph, YGraph) {
  // Stem 0-1-2, arms 2-3-4 and 2-5-6; f = height; 3 and 5 tie (broken by index).
  const auto c = make(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {2, 5}, {5, 6}}, {}, {0, 1, 2, 3, 4, 3, 4});
  const Reeb_graph R = reeb(c);
  ASSERT_EQ(R.nodes.size(), 4u);
  EXPECT_EQ(R.arcs.size(), 3u);
  EXPECT_EQ(R.loops(), 0u);
  EXPECT_EQ(R.count(minimum), 1u);
  EXPECT_EQ(R.count(maximum), 2u);
  EXPECT_EQ(R.count(up_fork), 1u);
  EXPECT_EQ(R.count(down_fork), 0u);
  EXPECT_EQ(R.nodes[1].vertex, 2u);
  EXPECT_EQ(R.nodes[1].type, unsigned(up_fork));
  // Arcs with their interior vertices.
  ASSERT_EQ(R.arcs[0].vertices, std::vector<Vertex_index>({1}));
  std::vector<std::vector<Vertex_index>> arms{R.arcs[1].vertices, R.arcs[2].vertices};
  std::sort(arms.begin(), arms.end());
  EXPECT_EQ(arms, (std::vector<std::vector<Vertex_index>>{{3}, {5}}));
}

TEST(AugmentedReebGraph, Circle) {
  const Reeb_graph R = reeb(circle(12));
  ASSERT_EQ(R.nodes.size(), 2u);
  EXPECT_EQ(R.arcs.size(), 2u);
  EXPECT_EQ(R.loops(), 1u);
  EXPECT_EQ(R.nodes[0].type, unsigned(minimum | up_fork));
  EXPECT_EQ(R.nodes[1].type, unsigned(maximum | down_fork));
  EXPECT_EQ(R.arcs[0].vertices.size() + R.arcs[1].vertices.size(), 10u);
}

TEST(AugmentedReebGraph, FigureEight) {
  // Lower square 0-1-2-3 (0 bottom, 2 top), upper square 2-4-5-6 (2 bottom, 5 top).
  const auto c = make(7, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {4, 5}, {5, 6}, {6, 2}}, {},
                      {0, 1, 2, 1.5, 3, 4, 3.5});
  const Reeb_graph R = reeb(c);
  EXPECT_EQ(R.loops(), 2u);
  ASSERT_EQ(R.nodes.size(), 3u);
  EXPECT_EQ(R.nodes[1].type, unsigned(up_fork | down_fork));
  EXPECT_EQ(R.arcs.size(), 4u);
}

TEST(AugmentedReebGraph, UprightTorusHasOneLoop) {
  const auto c = upright_torus(24, 12);
  const Reeb_graph R = reeb(c);
  EXPECT_EQ(R.loops(), 1u);  // the horizontal class of the torus must not appear
  EXPECT_EQ(R.nodes.size(), 4u);
  EXPECT_EQ(R.arcs.size(), 4u);
  EXPECT_EQ(R.count(minimum), 1u);
  EXPECT_EQ(R.count(maximum), 1u);
  EXPECT_EQ(R.count(up_fork), 1u);
  EXPECT_EQ(R.count(down_fork), 1u);
  EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(c.complex, c.f)),
            brute_force_reeb_arcs(c.complex, c.f));
  expect_invariants(c.complex, c.f);
}

TEST(AugmentedReebGraph, LargerTorusGrid) {
  const auto c = upright_torus(200, 100);
  const Reeb_graph R = reeb(c);
  EXPECT_EQ(R.loops(), 1u);
  EXPECT_EQ(R.nodes.size(), 4u);
}

TEST(AugmentedReebGraph, Cylinder) {
  const auto c = cylinder(16, 6);
  const Reeb_graph R = reeb(c);
  EXPECT_EQ(R.loops(), 0u);
  ASSERT_EQ(R.nodes.size(), 2u);
  EXPECT_EQ(R.arcs.size(), 1u);
  EXPECT_EQ(R.nodes[0].type, unsigned(minimum));
  EXPECT_EQ(R.nodes[1].type, unsigned(maximum));
  EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(c.complex, c.f)),
            brute_force_reeb_arcs(c.complex, c.f));
}

TEST(AugmentedReebGraph, NonManifoldMixAgainstBruteForce) {
  // A book of three triangles on edge 0-1, a dangling path 4-5-6, a bow-tie at 6, an isolated vertex 11,
  // and a second component (triangle 12-13-14 with dangling edge 14-15).
  const std::vector<Edge> edges{{4, 5}, {5, 6}, {14, 15}};
  const std::vector<Triangle> tris{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {6, 7, 8}, {6, 9, 10}, {12, 13, 14}};
  std::mt19937 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<double> f(16);
    for (double& x : f)
      x = trial % 2 ? std::uniform_real_distribution<double>(0, 1)(rng)
                    : static_cast<double>(std::uniform_int_distribution<int>(0, 3)(rng));
    const auto c = make(16, edges, tris, f);
    const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
    EXPECT_EQ(arc_multiset(A), brute_force_reeb_arcs(c.complex, c.f)) << "trial " << trial;
    const Reeb_graph R = A.reeb_graph();
    EXPECT_EQ(R.components, 3u);
    EXPECT_EQ(R.loops(), 0u);  // every piece is contractible
    expect_invariants(c.complex, c.f);
  }
}

TEST(AugmentedReebGraph, FansWithScatteredRimNumbersAgainstBruteForce) {
  // A disk fan: centre 0 and a rim of D vertices, triangles (0, rim p, rim p + 1), the rim numbered in order,
  // interleaved (even positions first) and at random. The triangles of the centre find their edges far apart
  // in its edge list (the search gallops there; it walked them one by one, quadratic in the degree).
  std::mt19937 rng(41);
  for (int trial = 0; trial < 12; ++trial) {
    const int D = 40 + 37 * trial;
    std::vector<Vertex_index> rim(static_cast<std::size_t>(D));
    for (int p = 0; p < D; ++p)
      rim[static_cast<std::size_t>(p)] =
          static_cast<Vertex_index>(1 + (trial % 3 == 1 ? (p % 2 == 0 ? p / 2 : (D + 1) / 2 + p / 2) : p));
    if (trial % 3 == 2) std::shuffle(rim.begin(), rim.end(), rng);
    std::vector<Edge> edges;
    std::vector<Triangle> tris;
    for (int p = 0; p < D; ++p) {
      const Vertex_index a = rim[static_cast<std::size_t>(p)], b = rim[static_cast<std::size_t>((p + 1) % D)];
      edges.push_back({0, a});
      edges.push_back({std::min(a, b), std::max(a, b)});
      Triangle t{0, a, b};
      std::sort(t.begin(), t.end());
      tris.push_back(t);
    }
    std::vector<double> f(static_cast<std::size_t>(D) + 1);
    for (int p = 0; p < D; ++p)  // a wavy rim: several maxima and minima, the centre in between
      f[rim[static_cast<std::size_t>(p)]] = std::cos(6.283185307179586 * 3 * p / D) + 0.01 * (p % 5);
    f[0] = 0.1 * (trial % 5) - 0.2;
    const auto c = make(static_cast<std::size_t>(D) + 1, edges, tris, f);
    EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(c.complex, c.f)),
              brute_force_reeb_arcs(c.complex, c.f))
        << "trial " << trial;
    expect_invariants(c.complex, c.f);
  }
}

TEST(AugmentedReebGraph, RandomRipsComplexesAgainstBruteForce) {
  const std::vector<std::vector<std::array<double, 4>>> shapes{figure_eight_segments(), tree_segments(),
                                                               grid_segments()};
  std::mt19937 rng(11);
  for (int trial = 0; trial < 24; ++trial) {
    const auto s = sample_segments(shapes[trial % 3], 0.45, 0.12, 100 + trial);
    const Simplicial_complex_2 K = build_rips_complex_2(s.points, 0.9);
    std::vector<double> f;
    switch (trial % 4) {
      case 0:
        f = compute_geodesic_function(K).values;
        break;
      case 1:
        for (const auto& p : s.points) f.push_back(p[1] + 0.3 * p[0]);
        break;
      case 2:
        for (std::size_t i = 0; i < s.points.size(); ++i)
          f.push_back(std::uniform_real_distribution<double>()(rng));
        break;
      default:
        for (std::size_t i = 0; i < s.points.size(); ++i)
          f.push_back(std::uniform_int_distribution<int>(0, 5)(rng));
    }
    EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(K, f)), brute_force_reeb_arcs(K, f))
        << "trial " << trial;
    expect_invariants(K, f);
  }
}

// Dense complexes: most triangles are redundant for the level-set connectivity, so this exercises the two
// union-finds that keep halves out of the link-cut tree (the local Kruskal and the fan of the top vertex),
// with tied values, duplicated points and points on a line.
TEST(AugmentedReebGraph, DenseRipsComplexesAgainstBruteForce) {
  std::mt19937 rng(29);
  std::size_t triangles = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 5 + static_cast<int>(rng() % 56);
    const double r = 0.15 + static_cast<double>(rng() % 100) / 300.0;
    std::vector<std::array<double, 2>> p(static_cast<std::size_t>(n));
    for (auto& q : p) {
      q = {static_cast<double>(rng() % 1000) / 1000.0, static_cast<double>(rng() % 1000) / 1000.0};
      if (rng() % 4 == 0) q[1] = 0.5;                                                         // on a line
      if (rng() % 8 == 0) q = p[static_cast<std::size_t>(rng() % static_cast<unsigned>(n))];  // a duplicate
    }
    const Simplicial_complex_2 K = build_rips_complex_2(p, r);
    std::vector<double> f(p.size());
    const int levels = 2 + static_cast<int>(rng() % 10);
    for (double& x : f)
      x = trial % 3 == 0 ? std::uniform_real_distribution<double>()(rng)
                         : static_cast<double>(rng() % levels);
    triangles += K.number_of_triangles();
    ASSERT_EQ(arc_multiset(compute_augmented_reeb_graph(K, f)), brute_force_reeb_arcs(K, f))
        << "trial " << trial;
  }
  EXPECT_GT(triangles, 100000u);  // dense enough to matter
}

TEST(AugmentedReebGraph, ConstantFunctionUsesIndexOrder) {
  auto c = circle(9);
  std::fill(c.f.begin(), c.f.end(), 2.5);
  const Reeb_graph R = reeb(c);
  EXPECT_EQ(R.loops(), 1u);
  EXPECT_EQ(R.nodes.front().vertex, 0u);  // the smallest index is the minimum
  EXPECT_EQ(R.nodes.back().vertex, 8u);
  auto t = upright_torus(10, 6);
  std::fill(t.f.begin(), t.f.end(), 0.0);
  EXPECT_EQ(reeb(t).loops(), 1u);
  EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(t.complex, t.f)),
            brute_force_reeb_arcs(t.complex, t.f));
}

TEST(AugmentedReebGraph, SymmetricTiesAreDeterministic) {
  const auto c = upright_torus(16, 8, 0.0);  // exactly symmetric height: many equal values
  const Augmented_reeb_graph a = compute_augmented_reeb_graph(c.complex, c.f);
  const Augmented_reeb_graph b = compute_augmented_reeb_graph(c.complex, c.f);
  ASSERT_EQ(a.number_of_arcs(), b.number_of_arcs());
  for (std::size_t i = 0; i < a.number_of_arcs(); ++i) {
    EXPECT_EQ(a.arcs()[i].lower, b.arcs()[i].lower);
    EXPECT_EQ(a.arcs()[i].upper, b.arcs()[i].upper);
  }
  EXPECT_EQ(arc_multiset(a), brute_force_reeb_arcs(c.complex, c.f));
  EXPECT_EQ(a.reeb_graph().loops(), 1u);
}

TEST(AugmentedReebGraph, EmptyAndSingleVertex) {
  const Augmented_reeb_graph empty =
      compute_augmented_reeb_graph(Simplicial_complex_2{}, std::vector<double>{});
  EXPECT_EQ(empty.status(), Status::degenerate_input);
  EXPECT_EQ(empty.number_of_nodes(), 0u);
  const Reeb_graph R0 = empty.reeb_graph();
  EXPECT_EQ(R0.nodes.size(), 0u);
  EXPECT_EQ(R0.components, 0u);
  EXPECT_EQ(R0.loops(), 0u);

  const auto one = make(1, {}, {}, {3.0});
  const Reeb_graph R1 = reeb(one);
  ASSERT_EQ(R1.nodes.size(), 1u);
  EXPECT_EQ(R1.nodes[0].type, unsigned(minimum | maximum));
  EXPECT_EQ(R1.arcs.size(), 0u);
  EXPECT_EQ(R1.components, 1u);

  // Isolated vertices and a single edge.
  const auto few = make(4, {{1, 2}}, {}, {0, 0, 0, 0});
  const Reeb_graph R2 = reeb(few);
  EXPECT_EQ(R2.components, 3u);
  EXPECT_EQ(R2.arcs.size(), 1u);
}

TEST(AugmentedReebGraph, BadInputThrows) {
  const auto c = circle(6);
  EXPECT_THROW(compute_augmented_reeb_graph(c.complex, std::vector<double>(5, 0.0)), std::invalid_argument);
  std::vector<double> f = c.f;
  f[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(
      throws_with<std::invalid_argument>([&] { compute_augmented_reeb_graph(c.complex, f); }, "vertex 3"));
  f[3] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(compute_augmented_reeb_graph(c.complex, f), std::invalid_argument);
  Simplicial_complex_2 bad = c.complex;
  bad.triangles.push_back({0, 2, 4});  // its edges are missing
  EXPECT_THROW(compute_augmented_reeb_graph(bad, c.f), std::invalid_argument);
  bad = c.complex;
  bad.triangles.push_back({0, 1, 2});  // edges 01 and 12 exist, 02 does not: the message names it
  EXPECT_TRUE(
      throws_with<std::invalid_argument>([&] { compute_augmented_reeb_graph(bad, c.f); }, "edge (0, 2)"));
  // A complex out of canonical order: the message names the first simplex out of order or range.
  auto message = [&](const Simplicial_complex_2& k) {
    return invalid_argument_message([&] { compute_augmented_reeb_graph(k, c.f); });
  };
  bad = c.complex;
  std::swap(bad.edges[0], bad.edges[1]);  // unsorted
  EXPECT_TRUE(contains(message(bad), "not canonical: edge 1 ("));
  bad = c.complex;
  bad.edges[2] = {bad.edges[2][1], bad.edges[2][0]};
  EXPECT_TRUE(contains(message(bad), "edge 2 ("));
  EXPECT_TRUE(contains(message(bad), "is not in increasing order"));
  bad = c.complex;
  bad.edges.back()[1] = 9;
  EXPECT_TRUE(contains(message(bad), "has a vertex beyond the 6 vertices"));
  bad = c.complex;
  bad.triangles = {{0, 1, 2}, {0, 1, 2}};
  EXPECT_TRUE(contains(message(bad), "triangle 1 (0, 1, 2) is not after triangle 0"));
  bad.triangles = {{1, 0, 2}};
  EXPECT_TRUE(contains(message(bad), "triangle 0 (1, 0, 2) is not in increasing order"));
  // Builder errors name the simplex.
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        make_simplicial_complex_2(3, {{0, 1}, {1, 7}}, {});
      },
      "edge 1"));
  EXPECT_THROW(make_simplicial_complex_2(3, {}, {{0, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(make_simplicial_complex_2(3, {{2, 2}}, {}), std::invalid_argument);
  // The length of edges implied by triangles is checked like the given ones, even when no triangle uses it.
  for (const double bad_length :
       {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_TRUE(throws_with<std::invalid_argument>(
        [&] {
          make_simplicial_complex_2(3, {}, {{0, 1, 2}}, {}, bad_length);
        },
        "implied_edge_length"))
        << bad_length;
  }
  EXPECT_EQ(make_simplicial_complex_2(3, {}, {{0, 1, 2}}, {}, 0.0).edge_lengths, std::vector<double>(3, 0.0));
}

// compute_augmented_reeb_graph() checks the canonical order of the complex: a triangle with a vertex equal to
// number_of_vertices is beyond the vertices (named), as an edge's is.
TEST(AugmentedReebGraph, ATriangleVertexAtTheVertexCountIsOutOfRange) {
  Simplicial_complex_2 k;
  k.number_of_vertices = 3;
  k.edges = {{0, 1}, {0, 2}, {1, 2}};
  k.triangles = {{0, 1, 3}};
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [&] {
        compute_augmented_reeb_graph(k, std::vector<double>{0, 1, 2});
      },
      "triangle 0 (0, 1, 3) has a vertex beyond the 3 vertices"));
}

TEST(AugmentedReebGraph, ProgressCanInterrupt) {
  const auto c = upright_torus(100, 100);
  Reeb_graph_options options;
  int calls = 0;
  options.progress = [&](double) { return ++calls < 2; };
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f, options);
  EXPECT_EQ(A.status(), Status::interrupted);
  EXPECT_LT(A.number_of_arcs(), compute_augmented_reeb_graph(c.complex, c.f).number_of_arcs());
  for (const auto& a : A.arcs()) EXPECT_NE(a.lower, a.upper);  // only closed arcs are kept
}

TEST(AugmentedReebGraph, SurfaceMeshWithRemovedVertices) {
  // A removed (not yet collected) vertex leaves a gap in the indices: refused, instead of an isolated phantom
  // vertex; after collect_garbage() the same mesh gives its 4 vertices.
  using K = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  Mesh mesh;
  const auto v0 = mesh.add_vertex({0, 0, 0}), v1 = mesh.add_vertex({9, 9, 9}),
             v2 = mesh.add_vertex({1, 0, 0}), v3 = mesh.add_vertex({0, 1, 0});
  mesh.add_vertex({5, 5, 5});
  mesh.add_face(v0, v2, v3);
  mesh.remove_vertex(v1);
  EXPECT_TRUE(
      throws_with<std::invalid_argument>([&] { simplicial_complex_from_mesh(mesh); }, "collect_garbage"));
  mesh.collect_garbage();
  const Simplicial_complex_2 k = simplicial_complex_from_mesh(mesh);
  EXPECT_EQ(k.number_of_vertices, 4u);
  EXPECT_EQ(k.number_of_triangles(), 1u);
  EXPECT_EQ(k.number_of_edges(), 3u);
}

namespace {
// Adds a tetrahedron's surface (a sphere) to `mesh`: vertices 0-3 at (0, 0, 0), (1, 0, z1), (0, 1, z2) and
// (0, 0, z3); returns its vertex property "v:height" = z.
template <class Mesh>
auto add_tetrahedron(Mesh& mesh, double z1, double z2, double z3) {
  const auto v0 = mesh.add_vertex({0, 0, 0}), v1 = mesh.add_vertex({1, 0, z1}),
             v2 = mesh.add_vertex({0, 1, z2}), v3 = mesh.add_vertex({0, 0, z3});
  mesh.add_face(v0, v2, v1);
  mesh.add_face(v0, v1, v3);
  mesh.add_face(v1, v2, v3);
  mesh.add_face(v2, v0, v3);
  auto height = mesh.template add_property_map<typename Mesh::Vertex_index, double>("v:height", 0.0).first;
  for (auto v : mesh.vertices()) height[v] = mesh.point(v).z();
  return height;
}
}  // namespace

TEST(AugmentedReebGraph, SurfaceMeshWithVertexPropertyMap) {
  using K = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  // A tetrahedron's surface (a sphere): a single arc; and a square with a hole? Keep to the sphere + tube.
  Mesh mesh;
  const auto height = add_tetrahedron(mesh, 0.2, 0.5, 1);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(mesh, height);
  const Reeb_graph R = A.reeb_graph();
  EXPECT_EQ(R.nodes.size(), 2u);
  EXPECT_EQ(R.arcs.size(), 1u);
  EXPECT_EQ(R.loops(), 0u);
  EXPECT_EQ(R.nodes[0].vertex, Vertex_index(0));
  // A quad face is rejected with its index.
  Mesh quad;
  const auto a = quad.add_vertex({0, 0, 0}), b = quad.add_vertex({1, 0, 0}), c = quad.add_vertex({1, 1, 0}),
             d = quad.add_vertex({0, 1, 0});
  quad.add_face(a, b, c, d);
  auto h2 = quad.add_property_map<Mesh::Vertex_index, double>("v:h", 0.0).first;
  EXPECT_THROW(compute_augmented_reeb_graph(quad, h2), std::invalid_argument);
}

// The mesh overload hands the values over by vertex index as they are (fractions too: the minimum is the
// vertex at height -0.5, not the one at 0) and passes its options on (a progress callback that stops at once
// leaves an interrupted graph without arcs); simplicial_complex_from_mesh() names a face that is not a
// triangle by its index among the faces.
TEST(AugmentedReebGraph, SurfaceMeshValuesOptionsAndFaceIndex) {
  using K = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  Mesh mesh;
  const auto height = add_tetrahedron(mesh, -0.5, 0.25, 1.75);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(mesh, height);
  ASSERT_EQ(A.values().size(), 4u);
  for (auto v : mesh.vertices()) EXPECT_EQ(A.values()[v.idx()], mesh.point(v).z());
  const Reeb_graph R = A.reeb_graph();
  ASSERT_EQ(R.count(minimum), 1u);
  for (const auto& node : R.nodes)
    if (node.type & minimum) {
      EXPECT_EQ(node.vertex, Vertex_index(1));
    }
  Reeb_graph_options stop;
  stop.progress = [](double) { return false; };
  const Augmented_reeb_graph stopped = compute_augmented_reeb_graph(mesh, height, stop);
  EXPECT_EQ(stopped.status(), Status::interrupted);
  EXPECT_EQ(stopped.number_of_arcs(), 0u);
  // A triangle, then a quadrilateral on its edge (b, c).
  Mesh mixed;
  const auto a = mixed.add_vertex({0, 0, 0}), b = mixed.add_vertex({1, 0, 0}),
             c = mixed.add_vertex({0, 1, 0}), d = mixed.add_vertex({2, 1, 0}),
             e = mixed.add_vertex({1, 2, 0});
  mixed.add_face(a, b, c);
  ASSERT_TRUE(mixed.add_face(c, b, d, e) != Mesh::null_face());
  try {
    simplicial_complex_from_mesh(mixed);
    ADD_FAILURE() << "a quadrilateral was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "simplicial_complex_from_mesh: face 1 has 4 vertices; triangulate the mesh first");
  }
}

TEST(AugmentedReebGraph, DuplicatedPointsKeepTheLoops) {
  // Every point of a noisy figure-eight twice: duplicates are joined at length 0, so the geodesic function
  // has ties everywhere; the Reeb graph still has the two loops.
  const auto s = sample_segments(figure_eight_segments(), 0.3, 0.05, 21);
  std::vector<std::array<double, 2>> doubled;
  for (const auto& p : s.points) {
    doubled.push_back(p);
    doubled.push_back(p);
  }
  const Simplicial_complex_2 K1 = build_rips_complex_2(s.points, 0.7);
  const Simplicial_complex_2 K2 = build_rips_complex_2(doubled, 0.7);
  const auto f1 = compute_geodesic_function(K1).values;
  const auto f2 = compute_geodesic_function(K2).values;
  EXPECT_EQ(compute_augmented_reeb_graph(K1, f1).reeb_graph().loops(), 2u);
  EXPECT_EQ(compute_augmented_reeb_graph(K2, f2).reeb_graph().loops(), 2u);
  EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(K2, f2)), brute_force_reeb_arcs(K2, f2));
}

TEST(AugmentedReebGraph, CollinearAndGridPointClouds) {
  // A line of points (a path): one arc. A 6x6 unit grid at r = 1 (4-neighbour graph, no triangles): the
  // geodesic function from a corner has many ties; every square of the grid is a loop of the 1-skeleton, and
  // with the Manhattan distance each square has a unique top and bottom, so the Reeb graph keeps all 25 of
  // them.
  std::vector<std::array<double, 2>> line, grid;
  for (int i = 0; i < 20; ++i) line.push_back({double(i), 0.0});
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) grid.push_back({double(i), double(j)});
  const Simplicial_complex_2 KL = build_rips_complex_2(line, 1.0);
  const Reeb_graph RL = compute_augmented_reeb_graph(KL, compute_geodesic_function(KL).values).reeb_graph();
  EXPECT_EQ(RL.arcs.size(), 1u);
  EXPECT_EQ(RL.loops(), 0u);
  const Simplicial_complex_2 KG = build_rips_complex_2(grid, 1.0);
  ASSERT_EQ(KG.number_of_triangles(), 0u);
  const auto fg = compute_geodesic_function(KG).values;
  EXPECT_EQ(compute_augmented_reeb_graph(KG, fg).reeb_graph().loops(), 25u);
  EXPECT_EQ(arc_multiset(compute_augmented_reeb_graph(KG, fg)), brute_force_reeb_arcs(KG, fg));
  // With the diagonals (r = 1.5) every square is filled: a contractible complex, no loop.
  const Simplicial_complex_2 KD = build_rips_complex_2(grid, 1.5);
  EXPECT_EQ(compute_augmented_reeb_graph(KD, compute_geodesic_function(KD).values).reeb_graph().loops(), 0u);
}

TEST(AugmentedReebGraph, TheSetUpReportsAndAStopThereLeavesNoArc) {
  // The complete graph on 200 points: 1,313,400 triangles, so both passes over the triangles and the
  // bucketing after them report on their way (every 2^20 triangles). Until session 37 the first report after
  // 0 came when the sweep began: on a dense Rips complex two thirds of the time passed without one, and a
  // stop waited as long.
  std::vector<std::array<double, 2>> points;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) points.push_back({u(rng), u(rng)});
  const Simplicial_complex_2 K = build_flag_complex_2(build_rips_graph(points, 2.0));
  ASSERT_EQ(K.number_of_triangles(), 1313400u);
  std::vector<double> f(200);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = points[i][0] + 0.5 * points[i][1];
  Reeb_graph_options options;
  std::vector<double> seen;
  options.progress = test::recording_progress(seen);
  const Augmented_reeb_graph full = compute_augmented_reeb_graph(K, f, options);
  ASSERT_EQ(full.status(), Status::success);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  auto reports = [&seen](double from, double to) {
    return std::count_if(seen.begin(), seen.end(), [from, to](double t) { return t > from && t < to; });
  };
  EXPECT_GE(reports(0.05, 0.2), 1);  // counting the triangles by their first edge
  EXPECT_GE(reports(0.2, 0.35), 1);  // storing them
  EXPECT_GE(reports(0.35, 0.4), 2);  // bucketing them by their middle vertex (two passes)
  for (const double stop_at : {0.0, 0.05, 0.1, 0.2, 0.3, 0.35, 0.38, 0.4}) {
    std::size_t later = 0;
    bool refused = false;
    options.progress = [&](double t) {
      if (refused) ++later;
      refused = refused || t >= stop_at;
      return !refused;
    };
    const Augmented_reeb_graph A = compute_augmented_reeb_graph(K, f, options);
    EXPECT_EQ(A.status(), Status::interrupted) << stop_at;
    EXPECT_EQ(A.number_of_arcs(), 0u) << stop_at;
    EXPECT_EQ(A.order(), full.order()) << stop_at;
    EXPECT_EQ(later, 0u) << stop_at;
    EXPECT_EQ(A.reeb_graph().nodes.size(), 200u)
        << stop_at;  // every vertex isolated: a minimum and a maximum
  }
}

TEST(LargeArrayAllocator, HonoursTheAlignmentOfItsType) {
  // The link-cut tree's nodes are aligned to 32 bytes; blocks below 4 MiB came from malloc (16 bytes), so
  // about every second array of them was misaligned (undefined behaviour, reported by -fsanitize=alignment).
  struct alignas(32) Wide {
    double x[4];
  };
  std::vector<FeatureRecon::internal::Large_vector<Wide>> arrays;
  for (std::size_t n = 1; n <= 64; ++n) arrays.emplace_back(n);
  arrays.emplace_back((std::size_t(5) << 20) / sizeof(Wide));  // the huge-page path
  for (const auto& a : arrays)
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % alignof(Wide), 0u) << a.size();
  FeatureRecon::internal::Large_vector<char> bytes(3);  // ordinary types keep malloc
  EXPECT_EQ(bytes.size(), 3u);
}
