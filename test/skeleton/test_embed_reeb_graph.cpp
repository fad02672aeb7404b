// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/embed_reeb_graph.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {
/// A noisy circle of radius 10 (400 points) in R^d: the plane spanned by two random orthonormal directions.
Point_matrix circle_in(std::size_t d, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd frame = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(d), 2);
  if (d == 2) {
    frame.setIdentity();
  } else {
    for (Eigen::Index r = 0; r < frame.rows(); ++r) frame(r, 0) = g(rng), frame(r, 1) = g(rng);
    frame = Eigen::HouseholderQR<Eigen::MatrixXd>(frame).householderQ() *
            Eigen::MatrixXd::Identity(frame.rows(), 2);
  }
  Point_matrix m;
  m.rows = 400;
  m.dimension = d;
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * std::acos(-1.0) * i / 400;
    const Eigen::VectorXd x =
        frame * Eigen::Vector2d(10 * std::cos(a) + noise(rng), 10 * std::sin(a) + noise(rng));
    for (Eigen::Index c = 0; c < x.size(); ++c) m.data.push_back(x[c]);
  }
  return m;
}

double norm3(const std::array<double, 3>& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }
}  // namespace

TEST(EmbedReebGraph, CirclePolylinesStayOnTheCircle) {
  for (std::size_t d : {2u, 50u}) {
    const Point_matrix m = circle_in(d, 5);
    const Simplicial_complex_2 K = build_flag_complex_2(build_rips_graph(m, 0.8));
    const auto f = compute_geodesic_function(K).values;
    const Reeb_graph G = simplify_by_persistence(compute_augmented_reeb_graph(K, f), 1.0).graph;
    EXPECT_EQ(G.loops(), 1u) << "d = " << d;
    const std::vector<std::array<double, 3>> xyz = project_to_3d(m);
    const Reeb_graph_embedding E = embed_reeb_graph(G, xyz, f, d);
    EXPECT_EQ(E.dimension, std::min<std::size_t>(d, 3));
    ASSERT_EQ(E.arc_polylines.size(), G.arcs.size());
    std::size_t points = 0;
    for (std::size_t k = 0; k < G.arcs.size(); ++k) {
      const auto& line = E.arc_polylines[k];
      EXPECT_EQ(line.front(), E.node_positions[G.arcs[k].lower]);
      EXPECT_EQ(line.back(), E.node_positions[G.arcs[k].upper]);
      for (const auto& p : line) {
        // The circle's centre is the origin in 2D and the projected mean in 50D; centroids of level-set
        // pieces lie a little inside the circle (chords), never far.
        EXPECT_NEAR(norm3(p), 10.0, 0.6) << "d = " << d;
        ++points;
      }
    }
    EXPECT_GT(points, 40u);  // pieces, not just the nodes
  }
}

// A loop of 8 vertices on the unit circle gives arcs of 3 level-set pieces. Laplacian rounds shrink such a
// coarse arc onto the chord between its ends (10 rounds: a fifth of the width left); Taubin rounds keep its
// shape.
TEST(EmbedReebGraph, TaubinSmoothingKeepsTheShapeOfCoarseArcs) {
  Proximity_graph g;
  g.number_of_vertices = 8;
  std::vector<std::array<double, 3>> xyz;
  for (int i = 0; i < 8; ++i) {
    xyz.push_back({std::cos(std::acos(-1.0) * i / 4), std::sin(std::acos(-1.0) * i / 4), 0.0});
    g.edges.push_back({static_cast<Vertex_index>(std::min(i, (i + 1) % 8)),
                       static_cast<Vertex_index>(std::max(i, (i + 1) % 8))});
  }
  std::sort(g.edges.begin(), g.edges.end());
  g.edge_lengths.assign(8, 2 * std::sin(std::acos(-1.0) / 8));
  const Simplicial_complex_2 K = build_flag_complex_2(g);
  const auto f = compute_geodesic_function(K).values;
  const Reeb_graph G = simplify_by_persistence(compute_augmented_reeb_graph(K, f), 0.0).graph;
  ASSERT_EQ(G.loops(), 1u);
  ASSERT_EQ(G.arcs.size(), 2u);
  auto extent = [&](Embedding_options::Smoothing method, double& smallest_radius) {
    Embedding_options o;
    o.smoothing = method;
    const Reeb_graph_embedding E = embed_reeb_graph(G, xyz, f, 2, o);
    double widest = 0;  // distance from the line through the two nodes (the minimum and the maximum of f)
    smallest_radius = 2;
    const auto a = E.node_positions[G.arcs.front().lower], b = E.node_positions[G.arcs.front().upper];
    const double ux = (b[0] - a[0]) / std::hypot(b[0] - a[0], b[1] - a[1]),
                 uy = (b[1] - a[1]) / std::hypot(b[0] - a[0], b[1] - a[1]);
    for (const auto& line : E.arc_polylines) {
      EXPECT_EQ(line.size(), 5u);  // the two nodes and three pieces
      for (const auto& p : line) {
        widest = std::max(widest, std::fabs(-(p[0] - a[0]) * uy + (p[1] - a[1]) * ux));
        smallest_radius = std::min(smallest_radius, std::hypot(p[0], p[1]));
      }
    }
    return widest;
  };
  double r_taubin = 0, r_laplacian = 0;
  const double taubin = extent(Embedding_options::Smoothing::taubin, r_taubin);
  const double laplacian = extent(Embedding_options::Smoothing::laplacian, r_laplacian);
  EXPECT_GT(taubin, 0.85);
  EXPECT_GT(r_taubin, 0.75) << r_laplacian;
  EXPECT_LT(r_laplacian, 0.5);     // the middle piece near the centre
  EXPECT_LT(laplacian, 0.25);      // 0.854^10 = 0.21 of the middle piece's offset
  EXPECT_LE(taubin, 1.0 + 1e-12);  // no overshoot beyond the circle
}

TEST(EmbedReebGraph, ProjectionKeepsDistancesOfPlanarData) {
  const Point_matrix m = circle_in(50, 9);
  const auto xyz = project_to_3d(m);
  for (std::size_t i = 0; i < 400; i += 37)
    for (std::size_t j = i + 1; j < 400; j += 53) {
      double d50 = 0;
      for (std::size_t c = 0; c < 50; ++c) d50 += (m.row(i)[c] - m.row(j)[c]) * (m.row(i)[c] - m.row(j)[c]);
      double d3 = 0;
      for (int c = 0; c < 3; ++c) d3 += (xyz[i][c] - xyz[j][c]) * (xyz[i][c] - xyz[j][c]);
      EXPECT_NEAR(std::sqrt(d3), std::sqrt(d50), 1e-9);
    }
  EXPECT_EQ(project_to_3d(m), xyz);  // deterministic, signs included
}

TEST(EmbedReebGraph, ProjectionKeepsTinyAndHugeCoordinates) {
  // Ten collinear points in 4D, spacing s along the first axis: projected to 3D they span +-4.5 s on the
  // first axis. The covariance of s = 1e-170 underflowed and of s = 1e200 overflowed: every projection was 0.
  for (const double spacing : {1.0, 1e-170, 1e-300, 1e200, 1e300}) {
    Point_matrix m;
    m.dimension = 4;
    m.rows = 10;
    for (int i = 0; i < 10; ++i) m.data.insert(m.data.end(), {i * spacing, 0.0, 0.0, 0.0});
    const auto xyz = project_to_3d(m);
    for (int i = 0; i < 10; ++i) {
      EXPECT_NEAR(xyz[static_cast<std::size_t>(i)][0] / spacing, i - 4.5, 1e-9) << spacing << " point " << i;
      EXPECT_EQ(xyz[static_cast<std::size_t>(i)][1], 0.0);
      EXPECT_EQ(xyz[static_cast<std::size_t>(i)][2], 0.0);
    }
  }
}

TEST(EmbedReebGraph, BadInput) {
  Reeb_graph G;
  G.nodes = {{7, 0.0, minimum | maximum, {}}};
  EXPECT_THROW(embed_reeb_graph(G, {{0, 0, 0}}, {0.0}, 2), std::invalid_argument);
  Embedding_options o;
  o.smoothing_weight = 2;
  EXPECT_THROW(embed_reeb_graph(Reeb_graph{}, {}, {}, 2, o), std::invalid_argument);
  // Taubin's inflating step grows the zigzag above a weight of 2/3; Laplacian rounds take up to 1.
  o.smoothing_weight = 0.7;
  EXPECT_TRUE(contains(
      FeatureRecon::test::invalid_argument_message([&] { embed_reeb_graph(Reeb_graph{}, {}, {}, 2, o); }),
      "[0, 2/3] for Taubin smoothing"));
  o.smoothing = Embedding_options::Smoothing::laplacian;
  EXPECT_NO_THROW(embed_reeb_graph(Reeb_graph{}, {}, {}, 2, o));
  o.smoothing = Embedding_options::Smoothing::taubin;
  o.smoothing_weight = 2.0 / 3;
  EXPECT_NO_THROW(embed_reeb_graph(Reeb_graph{}, {}, {}, 2, o));
  // Arcs naming missing nodes and graph edges naming missing vertices are refused by index (they used to be
  // read out of bounds).
  Reeb_graph two;
  two.nodes = {{0, 0.0, minimum, {}}, {1, 1.0, maximum, {}}};
  two.arcs = {{0, 1, {}}, {0, 5, {}}};
  auto message = [](auto&& call) { return FeatureRecon::test::invalid_argument_message(call); };
  const std::vector<std::array<double, 3>> positions{{0, 0, 0}, {1, 0, 0}};
  EXPECT_TRUE(contains(message([&] { embed_reeb_graph(two, positions, {0.0, 1.0}, 2); }), "arc 1"));
  two.arcs.pop_back();
  Proximity_graph g;
  g.number_of_vertices = 2;
  g.edges = {{0, 7}};
  EXPECT_TRUE(contains(message([&] { embed_reeb_graph(two, g, positions, {0.0, 1.0}, 2); }), "graph edge 0"));
  // Positions and values of other lengths: both counts named.
  EXPECT_TRUE(contains(message([&] {
                         embed_reeb_graph(two, positions, {0.0, 1.0, 2.0}, 2);
                       }),
                       "positions has 2 points and values 3 entries: one of each per vertex"));
  // Non-finite values and positions of the graph's vertices are named (a NaN position gave NaN polylines).
  EXPECT_TRUE(contains(message([&] {
                         embed_reeb_graph(two, positions, {0.0, std::nan("")}, 2);
                       }),
                       "vertex 1 has value"));
  EXPECT_TRUE(contains(message([&] {
                         embed_reeb_graph(two, {{0, 0, 0}, {std::nan(""), 0, 0}}, {0.0, 1.0}, 2);
                       }),
                       "vertex 1 has coordinate"));
  // classical_mds_3d checks its matrix.
  EXPECT_TRUE(contains(message([] { classical_mds_3d({0, 1, 1}, 2); }), "entries"));
  EXPECT_TRUE(contains(message([] { classical_mds_3d({0, std::nan(""), 1, 0}, 2); }), "entry (0, 1)"));
  EXPECT_TRUE(contains(message([] { classical_mds_3d({0, -1, -1, 0}, 2); }), "entry (0, 1)"));
  EXPECT_TRUE(contains(message([] {
                         classical_mds_3d({0, -1, 1, 0}, 2);
                       }),
                       "entry (0, 1) of the distance matrix is -1"));
  EXPECT_TRUE(contains(message([] { classical_mds_3d({}, std::size_t(1) << 32); }), "entries"));
  EXPECT_TRUE(contains(message([] {
                         classical_mds_3d({0, 1, 1, 1, 7, 1, 1, 1, 0}, 3);
                       }),
                       "diagonal entry (1, 1) is 7"));
  EXPECT_TRUE(contains(message([] {
                         classical_mds_3d({0, 1, 2, 1, 0, 3, 2, 100, 0}, 3);
                       }),
                       "not symmetric at (1, 2): 3 vs 100"));
  const auto two_points = classical_mds_3d({0, 2, 2, 0}, 2);
  EXPECT_NEAR(std::abs(two_points[0][0] - two_points[1][0]), 2.0, 1e-12);
}

namespace {
/// Distance from p to the L-shaped path (0,0)-(20,0)-(20,20).
double distance_to_l(const std::array<double, 3>& p) {
  const double a = std::hypot(p[0] - std::clamp(p[0], 0.0, 20.0), p[1]);
  const double b = std::hypot(p[0] - 20, p[1] - std::clamp(p[1], 0.0, 20.0));
  return std::min(a, b);
}
double distance_to_corner(const std::vector<std::array<double, 3>>& line) {
  double best = 1e300;
  for (const auto& p : line) best = std::min(best, std::hypot(p[0] - 20, p[1]));
  return best;
}
// An L of 41 points spaced `scale` (corner at (20, 0) scale), its path graph, and a Reeb graph of one arc
// without points of its own between the two ends.
struct L_shape {
  std::vector<std::array<double, 3>> xyz;
  Proximity_graph g;
  Reeb_graph G;
  std::vector<double> f;
};
L_shape l_shape(double scale = 1) {
  L_shape l;
  for (int i = 0; i <= 20; ++i) l.xyz.push_back({scale * i, 0, 0});
  for (int i = 1; i <= 20; ++i) l.xyz.push_back({scale * 20, scale * i, 0});
  l.g.number_of_vertices = l.xyz.size();
  for (Vertex_index v = 0; v + 1 < l.xyz.size(); ++v) l.g.edges.push_back({v, v + 1});
  const auto last = static_cast<Vertex_index>(l.xyz.size() - 1);
  l.G.nodes = {{0, 0.0, minimum, {}}, {last, 0.5, maximum, {}}};
  l.G.arcs = {{0, 1, {}}};
  l.f.assign(l.xyz.size(), 0.25);
  return l;
}
}  // namespace

// Simplification can leave an arc with no points of its own between two nodes far apart: with the graph, the
// arc is drawn along the graph's shortest path (through the data), not straight across.
TEST(EmbedReebGraph, ArcsWithoutPointsFollowTheGraph) {
  const L_shape l = l_shape();
  const auto& xyz = l.xyz;
  const auto& g = l.g;
  const auto& G = l.G;
  const auto& f = l.f;
  const Reeb_graph_embedding E = embed_reeb_graph(G, g, xyz, f, 2);
  ASSERT_EQ(E.arc_polylines.size(), 1u);
  const auto& line = E.arc_polylines[0];
  EXPECT_EQ(line.front(), E.node_positions[0]);
  EXPECT_EQ(line.back(), E.node_positions[1]);
  EXPECT_GT(line.size(), 30u);
  for (const auto& p : line) EXPECT_LE(distance_to_l(p), 1.5);
  EXPECT_LE(distance_to_corner(line), 1.5);
  // Off, or without a graph: the straight segment (its two ends, 20 from the corner).
  Embedding_options straight;
  straight.max_gap = 0;
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, straight).arc_polylines[0].size(), 2u);
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, straight).max_gap, std::numeric_limits<double>::infinity());
  straight.max_gap = std::numeric_limits<double>::infinity();
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, straight).arc_polylines[0].size(), 2u);
  EXPECT_EQ(embed_reeb_graph(G, xyz, f, 2).arc_polylines[0].size(), 2u);
  EXPECT_NEAR(distance_to_corner(embed_reeb_graph(G, xyz, f, 2).arc_polylines[0]), 20.0, 1e-12);
  // A gap the graph cannot bridge (no path) stays straight; a gap below max_gap too.
  Proximity_graph cut = g;
  cut.edges.erase(cut.edges.begin() + 10);
  EXPECT_EQ(embed_reeb_graph(G, cut, xyz, f, 2).arc_polylines[0].size(), 2u);
  Embedding_options wide;
  wide.max_gap = 30;
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, wide).arc_polylines[0].size(), 2u);
  Embedding_options bad;
  bad.max_gap = std::nan("");
  EXPECT_THROW(embed_reeb_graph(G, g, xyz, f, 2, bad), std::invalid_argument);
  // A negative gap turned bridging off before FeatureRecon::automatic; now 0 does, and a negative one is
  // refused. A level width of 0 (automatic before) too.
  bad.max_gap = -1;
  EXPECT_EQ(
      FeatureRecon::test::invalid_argument_message([&] { embed_reeb_graph(G, g, xyz, f, 2, bad); }),
      "embed_reeb_graph: embedding max_gap must be >= 0 (FeatureRecon::automatic: twice the median edge "
      "length; 0: off), got -1");
  bad = {};
  bad.level_width = 0;
  EXPECT_EQ(FeatureRecon::test::invalid_argument_message([&] { embed_reeb_graph(G, g, xyz, f, 2, bad); }),
            "embed_reeb_graph: embedding level_width must be > 0 (FeatureRecon::automatic: 1/64 of the range "
            "of f; in extract_reeb_skeleton(), the median edge length of the complex), got 0");
}

TEST(EmbedReebGraph, AnArcBetweenNodesAtOnePlaceKeepsItsPoints) {
  // Nodes at (0, 0) and the arc's one point 0.1 away: the line goes out and back, X B X, and stays so (the
  // removal of out-and-back spikes made it the single point X: not a line).
  const std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {0.1, 0, 0}, {0, 0, 0}};
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{0, 1}, {1, 2}};
  Reeb_graph G;
  G.nodes = {{0, 0.0, minimum, {}}, {2, 1.0, maximum, {}}};
  G.arcs = {{0, 1, {1}}};
  const auto line = embed_reeb_graph(G, g, xyz, {0.0, 0.5, 1.0}, 2).arc_polylines.at(0);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line.front(), xyz[0]);
  EXPECT_EQ(line.back(), xyz[2]);
}

namespace {
std::vector<std::array<double, 3>> mds(const std::vector<double>& D, std::size_t n, std::size_t dense_limit) {
  bool stopped = true;
  auto out = skeleton::internal::classical_mds_3d(D, n, Progress_callback(), stopped, dense_limit);
  EXPECT_FALSE(stopped);
  return out;
}
std::vector<double> distances_of(const std::vector<std::vector<double>>& points) {
  const std::size_t n = points.size();
  std::vector<double> D(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < points[i].size(); ++k)
        s += (points[i][k] - points[j][k]) * (points[i][k] - points[j][k]);
      D[i * n + j] = std::sqrt(s);
    }
  return D;
}
/// Largest |distance in the embedding - D(i, j)| over all pairs.
double distance_error(const std::vector<std::array<double, 3>>& x, const std::vector<double>& D) {
  const std::size_t n = x.size();
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      worst = std::max(worst, std::fabs(std::hypot(x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]) -
                                        D[i * n + j]));
  return worst;
}
/// Per embedding axis, the sum of squares: the eigenvalue behind it.
std::array<double, 3> axis_eigenvalues(const std::vector<std::array<double, 3>>& x) {
  std::array<double, 3> s{0, 0, 0};
  for (const auto& p : x)
    for (int c = 0; c < 3; ++c) s[c] += p[c] * p[c];
  return s;
}
}  // namespace

TEST(ClassicalMds, KrylovSolverAgreesWithTheDenseOne) {
  // 500 points in R^6 with distinct spreads per axis: three well separated eigenvalues on top, so both
  // solvers give the same coordinates (signs fixed by the largest coordinate), and they give the top three
  // principal axes.
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  const double spread[6] = {10, 6, 3, 1, 0.5, 0.2};
  std::vector<std::vector<double>> pts(500, std::vector<double>(6));
  for (auto& p : pts)
    for (int k = 0; k < 6; ++k) p[k] = spread[k] * g(rng);
  const std::vector<double> D = distances_of(pts);
  const auto krylov = mds(D, pts.size(), 0), dense = mds(D, pts.size(), 1000);
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::fabs(krylov[i][c] - dense[i][c]));
      largest = std::max(largest, std::fabs(dense[i][c]));
    }
  EXPECT_LT(worst, 1e-7 * largest);
  EXPECT_GT(largest, 20.0);
  // The public function uses the Krylov solver above 300 points: the same result.
  const auto pub = classical_mds_3d(D, pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pub[i][c], krylov[i][c]);
  // Distances of 1e150 or 1e-150 (squares overflow or underflow): the same picture, scaled (before: off by 98
  // %).
  for (const double factor : {0x1p500, 0x1p-500}) {
    std::vector<double> scaled = D;
    for (double& d : scaled) d *= factor;
    const auto big = mds(scaled, pts.size(), 0), big_dense = mds(scaled, pts.size(), 1000);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(big_dense[i][c], dense[i][c] * factor);  // powers of two: exact
        EXPECT_NEAR(big[i][c] / factor, krylov[i][c], 1e-9 * largest);
      }
  }
}

TEST(ClassicalMds, KrylovSolverFindsTheWeakAxesOfElongatedData) {
  // Spreads 1e6, 1 and 0.5 in R^3: the second and third eigenvalues are 1e-12 of the first. Both solvers
  // recover the weak axes (before: the Krylov solver stopped on a tolerance relative to the largest
  // eigenvalue and returned noise there).
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<std::vector<double>> pts(400, std::vector<double>(3));
  for (auto& p : pts) p = {1e6 * g(rng), g(rng), 0.5 * g(rng)};
  const std::vector<double> D = distances_of(pts);
  const auto krylov = mds(D, pts.size(), 0), dense = mds(D, pts.size(), 1000);
  for (int c = 1; c < 3; ++c) {
    double sk = 0, sd = 0, skd = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      sk += krylov[i][c] * krylov[i][c];
      sd += dense[i][c] * dense[i][c];
      skd += krylov[i][c] * dense[i][c];
    }
    EXPECT_GT(std::fabs(skd) / std::sqrt(sk * sd), 0.999) << "axis " << c;
  }
}

TEST(ClassicalMds, KrylovSolverOnDegenerateAndNonEuclideanMatrices) {
  // A circle (the top eigenvalue is double), a line (rank one), one point repeated (B = 0): the distances are
  // reproduced exactly up to rounding.
  std::vector<std::vector<double>> circle, line, same(320, std::vector<double>{3.0, 4.0});
  for (int i = 0; i < 400; ++i) {
    const double t = 6.283185307179586 * i / 400;
    circle.push_back({50 * std::cos(t), 50 * std::sin(t)});
    line.push_back({0.25 * i - 7, 0.5 * i + 1});
  }
  for (const auto* pts : {&circle, &line, &same}) {
    const std::vector<double> D = distances_of(*pts);
    const auto x = mds(D, pts->size(), 0);
    EXPECT_LT(distance_error(x, D), 1e-8 * (1 + D[pts->size() - 1]));
  }
  const std::vector<double> zeros(same.size() * same.size(), 0);
  EXPECT_EQ(distance_error(mds(distances_of(same), same.size(), 0), zeros), 0);
  // Geodesic distances on a cycle of 360 vertices are not Euclidean (B has negative eigenvalues) and the top
  // eigenvalues come in equal pairs: the embedding's axes carry the same eigenvalues as the dense solver's.
  const std::size_t n = 360;
  std::vector<double> cycle(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      cycle[i * n + j] = static_cast<double>(std::min((i + n - j) % n, (j + n - i) % n));
  const auto a = axis_eigenvalues(mds(cycle, n, 0)), b = axis_eigenvalues(mds(cycle, n, 1000));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-8 * b[0]) << c;
  EXPECT_NEAR(a[0], a[1], 1e-8 * a[0]);
  // The callback can stop it between steps.
  bool stopped = false;
  skeleton::internal::classical_mds_3d(
      cycle, n, [](double) { return false; }, stopped, 0);
  EXPECT_TRUE(stopped);
  // The public overload with options: the same positions as without when it runs to the end (reports from 0
  // to 1, increasing), all 0 and interrupted after a stop at the second report; a stop at the start on the
  // dense path (10 points) too.
  std::vector<double> seen;
  Classical_mds_options o;
  o.progress = test::recording_progress(seen);
  const Classical_mds full = classical_mds_3d(cycle, n, o);
  EXPECT_EQ(full.status, Status::success);
  EXPECT_EQ(full.positions, classical_mds_3d(cycle, n));
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  int calls = 0;
  o.progress = [&](double) { return ++calls < 2; };
  const Classical_mds cut = classical_mds_3d(cycle, n, o);
  EXPECT_EQ(cut.status, Status::interrupted);
  EXPECT_EQ(cut.positions, (std::vector<std::array<double, 3>>(n, {0.0, 0.0, 0.0})));
  const std::vector<double> small(cycle.begin(), cycle.begin() + 10);  // not a matrix: the check comes first
  EXPECT_THROW(classical_mds_3d(small, 10, o), std::invalid_argument);
  std::vector<double> ten(100);
  for (std::size_t i = 0; i < 10; ++i)
    for (std::size_t j = 0; j < 10; ++j) ten[i * 10 + j] = std::fabs(double(i) - double(j));
  o.progress = [](double) { return false; };
  EXPECT_EQ(classical_mds_3d(ten, 10, o).status, Status::interrupted);
}

TEST(ClassicalMds, TakesADenseMatrixAsTheOtherDistanceMatrixEntryPoints) {
  // classical_mds_3d() took only a flat vector and its size, where the other distance-matrix entry points
  // take an Eigen-like matrix or a range of rows.
  const std::size_t n = 40;
  std::vector<std::array<double, 3>> helix;
  for (std::size_t i = 0; i < n; ++i) helix.push_back({std::cos(0.3 * i), std::sin(0.3 * i), 0.05 * i});
  std::vector<double> flat(n * n);
  std::vector<std::vector<double>> rows(n, std::vector<double>(n));
  Eigen::MatrixXd E(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double d =
          std::hypot(helix[i][0] - helix[j][0], helix[i][1] - helix[j][1], helix[i][2] - helix[j][2]);
      flat[i * n + j] = rows[i][j] = E(Eigen::Index(i), Eigen::Index(j)) = d;
    }
  const std::vector<std::array<double, 3>> expected = classical_mds_3d(flat, n);
  const Classical_mds from_eigen = classical_mds_3d(E), from_rows = classical_mds_3d(rows);
  EXPECT_EQ(from_eigen.status, Status::success);
  EXPECT_EQ(from_eigen.positions, expected);
  EXPECT_EQ(from_rows.positions, expected);
  // The helix is Euclidean in 3D: the embedding keeps its distances.
  EXPECT_LT(distance_error(expected, flat), 1e-9);
  std::vector<double> seen;
  Classical_mds_options o;
  o.progress = test::recording_progress(seen);
  EXPECT_EQ(classical_mds_3d(rows, o).positions, expected);
  EXPECT_EQ(seen, (std::vector<double>{0.0, 1.0}));  // 40 points: the dense solver, no steps between
  o.progress = [](double) { return false; };
  EXPECT_EQ(classical_mds_3d(E, o).status, Status::interrupted);
  // Checked as the other entry points check a matrix, naming the problem.
  Eigen::MatrixXd wide(3, 4);
  wide.setZero();
  EXPECT_TRUE(contains(test::invalid_argument_message([&] { classical_mds_3d(wide); }),
                       "classical_mds_3d: the distance matrix is 3 x 4, not square"));
  rows[3].pop_back();
  EXPECT_TRUE(contains(test::invalid_argument_message([&] { classical_mds_3d(rows); }),
                       "classical_mds_3d: row 3 of the distance matrix has 39 entries, expected 40"));
  E(1, 2) += 1;
  EXPECT_TRUE(contains(test::invalid_argument_message([&] { classical_mds_3d(E); }),
                       "classical_mds_3d: the distance matrix is not symmetric at (1, 2)"));
}

TEST(ClassicalMds, CrowdedTopEigenvaluesStayInTheKrylovSolverAndTheDenseFallbackReportsFirst) {
  // Entries uniform in [1, 2]: the top eigenvalues crowd together. On 500 points the Krylov solver needs
  // about 340 vectors; it had at most min(n / 2, 320) and then ran the dense solver unannounced (on 2,000
  // points: 26 s without a report, a stop ignored). Restarted, it converges in the Krylov solver (every
  // report below 0.5) past that old limit, to the dense solver's result.
  const auto random_metric = [](std::size_t n) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(1.0, 2.0);
    std::vector<double> D(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) D[i * n + j] = D[j * n + i] = u(rng);
    return D;
  };
  const std::size_t n = 500;
  const std::vector<double> D = random_metric(n);
  std::vector<double> seen;
  bool stopped = true;
  const auto krylov = skeleton::internal::classical_mds_3d(
      D, n,
      [&](double f) {
        seen.push_back(f);
        return true;
      },
      stopped, 0);
  EXPECT_FALSE(stopped);
  EXPECT_GT(seen.size() * 8, n / 2);  // steps of 8 vectors beyond the old limit
  EXPECT_LT(*std::max_element(seen.begin(), seen.end()), 0.5);
  const auto dense = mds(D, n, 1000);
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::fabs(krylov[i][c] - dense[i][c]));
      largest = std::max(largest, std::fabs(dense[i][c]));
    }
  EXPECT_LT(worst, 1e-6 * largest);
  // On 100 points (Krylov solver forced) such a matrix falls back to the dense solver after 100 vectors: that
  // is reported (0.5) first, a stop there is honoured, and without one the result is the dense solver's.
  const std::size_t m = 100;
  const std::vector<double> small = random_metric(m);
  seen.clear();
  const auto fallback = skeleton::internal::classical_mds_3d(
      small, m,
      [&](double f) {
        seen.push_back(f);
        return true;
      },
      stopped, 0);
  EXPECT_FALSE(stopped);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 0.5);
  EXPECT_EQ(fallback, mds(small, m, 1000));
  skeleton::internal::classical_mds_3d(
      small, m, [](double f) { return f < 0.5; }, stopped, 0);
  EXPECT_TRUE(stopped);
}

TEST(EmbedReebGraph, ProgressIsReportedAndAStopDrawsTheRestStraight) {
  // Three arcs of 40,000 points each on three parallel wavy lines: progress is asked every 65,536 points, so
  // before the third arc (80,002 points drawn, counting one more per arc). A stop there draws the third arc
  // as the segment between its nodes and leaves the first two as without a stop.
  const std::size_t per_arc = 40000;
  Reeb_graph G;
  std::vector<std::array<double, 3>> positions;
  std::vector<double> f;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vertex_index low = static_cast<Vertex_index>(positions.size());
    positions.push_back({0.0, 10.0 * k, 0.0});
    f.push_back(0.0);
    const Vertex_index high = static_cast<Vertex_index>(positions.size());
    positions.push_back({1.0, 10.0 * k, 0.0});
    f.push_back(1.0);
    G.nodes.push_back({low, 0.0, minimum, {}});
    G.nodes.push_back({high, 1.0, maximum, {}});
    Reeb_graph::Arc arc{2 * k, 2 * k + 1, {}};
    for (std::size_t i = 1; i <= per_arc; ++i) {
      const double x = static_cast<double>(i) / (per_arc + 1);
      arc.vertices.push_back(static_cast<Vertex_index>(positions.size()));
      positions.push_back({x, 10.0 * k + std::sin(6 * x), 0.0});
      f.push_back(x);
    }
    G.arcs.push_back(std::move(arc));
  }
  std::vector<double> seen;
  Embedding_options o;
  o.smoothing_iterations = 0;  // only drawing counts (smoothing rounds count as work: below)
  o.progress = test::recording_progress(seen);
  const Reeb_graph_embedding full = embed_reeb_graph(G, positions, f, 2, o);
  EXPECT_EQ(full.status, Status::success);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_NEAR(seen[0], 2.0 / 3, 1e-9);
  EXPECT_EQ(seen[1], 1.0);
  ASSERT_GT(full.arc_polylines[2].size(), 2u);
  std::size_t later = 0;
  bool refused = false;
  o.progress = [&](double) {
    later += refused;
    refused = true;
    return false;
  };
  const Reeb_graph_embedding partial = embed_reeb_graph(G, positions, f, 2, o);
  EXPECT_EQ(partial.status, Status::interrupted);
  EXPECT_EQ(later, 0u);
  EXPECT_EQ(partial.node_positions, full.node_positions);
  ASSERT_EQ(partial.arc_polylines.size(), 3u);
  EXPECT_EQ(partial.arc_polylines[0], full.arc_polylines[0]);
  EXPECT_EQ(partial.arc_polylines[1], full.arc_polylines[1]);
  EXPECT_EQ(partial.arc_polylines[2],
            (std::vector<std::array<double, 3>>{full.node_positions[4], full.node_positions[5]}));
  // The same in input space (any dimension) and with a graph.
  Point_matrix P;
  P.rows = positions.size();
  P.dimension = 2;
  for (const auto& p : positions) P.data.insert(P.data.end(), {p[0], p[1]});
  Proximity_graph path;
  path.number_of_vertices = P.rows;
  for (const auto& arc : G.arcs) {
    path.edges.push_back({G.nodes[arc.lower].vertex, arc.vertices.front()});
    for (std::size_t i = 0; i + 1 < arc.vertices.size(); ++i)
      path.edges.push_back({arc.vertices[i], arc.vertices[i + 1]});
    path.edges.push_back({arc.vertices.back(), G.nodes[arc.upper].vertex});
  }
  for (auto& e : path.edges)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(path.edges.begin(), path.edges.end());
  refused = false;
  const Reeb_graph_input_embedding input = embed_reeb_graph_in_input_space(G, path, P, f, o);
  EXPECT_EQ(input.status, Status::interrupted);
  ASSERT_EQ(input.arc_polylines.size(), 3u);
  EXPECT_EQ(input.arc_polylines[2], (std::vector<double>{0.0, 20.0, 1.0, 20.0}));
  refused = false;
  EXPECT_EQ(embed_reeb_graph(G, path, positions, f, 2, o).status, Status::interrupted);
  EXPECT_EQ(later, 0u);
  // Smoothing rounds count: 40,001 units per round and arc besides the 40,001 of drawing, 3 x 40,001 x (1 +
  // 4) in all; a report is due after a round once 65,536 units passed since the last one. A stop during the
  // second arc's rounds draws it straight too.
  o.smoothing_iterations = 4;
  seen.clear();
  o.progress = test::recording_progress(seen);
  const Reeb_graph_embedding smoothed = embed_reeb_graph(G, positions, f, 2, o);
  EXPECT_EQ(smoothed.status, Status::success);
  const std::vector<double> due = {2.0 / 15, 4.0 / 15, 7.0 / 15, 9.0 / 15, 12.0 / 15, 14.0 / 15, 1.0};
  ASSERT_EQ(seen.size(), due.size());
  for (std::size_t i = 0; i < due.size(); ++i) EXPECT_NEAR(seen[i], due[i], 1e-12) << i;
  std::size_t calls = 0;
  o.progress = [&calls](double) { return ++calls < 3; };  // stops at 7 x 40,001: the second arc's 1st round
  const Reeb_graph_embedding stopped = embed_reeb_graph(G, positions, f, 2, o);
  EXPECT_EQ(stopped.status, Status::interrupted);
  EXPECT_EQ(calls, 3u);
  EXPECT_EQ(stopped.arc_polylines[0], smoothed.arc_polylines[0]);
  for (std::size_t a : {1u, 2u})
    EXPECT_EQ(stopped.arc_polylines[a], (std::vector<std::array<double, 3>>{full.node_positions[2 * a],
                                                                            full.node_positions[2 * a + 1]}));
}

TEST(EmbedReebGraph, GapsAreMeasuredAtEveryScale) {
  // The L of ArcsWithoutPointsFollowTheGraph, scaled: bridged the same way at every scale. Gaps were measured
  // by their squares, which underflow below about 1e-160 (nothing bridged: a straight chord) and overflow
  // above about 1e154 (every gap bridged, also one below max_gap).
  for (const double scale : {1.0, 1e-170, 1e-200, 1e170, 1e200}) {
    const L_shape l = l_shape(scale);
    const auto line = embed_reeb_graph(l.G, l.g, l.xyz, l.f, 2).arc_polylines.at(0);
    EXPECT_GT(line.size(), 30u) << scale;
    std::vector<std::array<double, 3>> unscaled;
    for (const auto& p : line) unscaled.push_back({p[0] / scale, p[1] / scale, 0});
    EXPECT_LE(distance_to_corner(unscaled), 1.5) << scale;
    Embedding_options wide;
    wide.max_gap = 30 * scale;  // the chord is 28.3 long: nothing to bridge
    EXPECT_EQ(embed_reeb_graph(l.G, l.g, l.xyz, l.f, 2, wide).arc_polylines[0].size(), 2u) << scale;
  }
}

TEST(EmbedReebGraph, AnEdgeLongerThanTheLargestDoubleEnds) {
  // Two clusters near -1e308 and +1e308 joined by one edge whose length exceeds the largest double: its
  // length was NaN (inf * sqrt(0)), the shortest-path search never ended and filled the memory. It is
  // infinite now, and the skeleton is drawn.
  const double a[2] = {1e308, 0}, b[2] = {-1e308, 0}, c[2] = {-5e307, 0};
  EXPECT_EQ(skeleton::internal::point_distance(a, b, 2), std::numeric_limits<double>::infinity());
  EXPECT_EQ(skeleton::internal::point_distance(a, c, 2), 1.5e308);
  EXPECT_EQ(skeleton::internal::point_distance(c, a, 2), 1.5e308);
  Point_matrix P;
  P.dimension = 1;
  for (int i = 0; i < 6; ++i) P.data.push_back(-1e308 + 1e292 * i);
  for (int i = 0; i < 6; ++i) P.data.push_back(1e308 - 1e292 * (5 - i));
  P.rows = 12;
  Proximity_graph g;
  g.number_of_vertices = 12;
  for (Vertex_index v = 0; v + 1 < 12; ++v) {
    g.edges.push_back({v, v + 1});
    g.edge_lengths.push_back(1.0);
  }
  const Reeb_skeleton s = extract_reeb_skeleton(g, P);
  EXPECT_EQ(s.status, Status::success);
  EXPECT_EQ(num_edges(s.graph), 1u);
  for (auto e : boost::make_iterator_range(edges(s.graph)))
    for (const auto& p : s.graph[e].polyline) EXPECT_FALSE(std::isnan(p[0]));
}

TEST(EmbedReebGraph, LevelWidthsBelowTheValuesResolutionGiveEveryValueItsLevel) {
  // 201 points 0.1 apart on a line: one arc. Bins are floor(f / width); a width so small that the quotient
  // overflows (a denormal) put every point into one bin of infinity, the coarsest drawing instead of the
  // finest. Each value is its own level now, as for any width below the values' spacing.
  Point_matrix P;
  P.dimension = 2;
  P.rows = 201;
  for (int i = 0; i < 201; ++i) P.data.insert(P.data.end(), {0.1 * i, 0.0});
  auto points_drawn = [&P](double width) {
    Skeleton_options o;
    o.embedding.level_width = width;
    o.embedding.smoothing_iterations = 0;
    o.embedding.max_gap = 0;
    const Reeb_skeleton k = extract_reeb_skeleton(P, 0.15, o);
    std::size_t n = 0;
    for (const auto e : boost::make_iterator_range(edges(k.graph))) n += k.graph[e].polyline.size();
    return std::make_pair(n, k.branch_merge_distance);
  };
  const auto finest = points_drawn(1e-300);
  EXPECT_EQ(finest.first, 201u);
  for (const double width : {1e-310, std::numeric_limits<double>::denorm_min()})
    EXPECT_EQ(points_drawn(width).first, finest.first) << width;
  EXPECT_LT(points_drawn(1.0).first, finest.first);
  // An infinite width draws one piece per arc, and the automatic branch merge (twice the width) is off: it
  // merged every branch node at the largest double before.
  const auto coarsest = points_drawn(std::numeric_limits<double>::infinity());
  EXPECT_EQ(coarsest.first, 3u);
  EXPECT_EQ(coarsest.second, 0.0);
  EXPECT_EQ(points_drawn(1e308).second, std::numeric_limits<double>::max());  // 2 x 1e308 saturates
}

namespace {
/// A Reeb graph of two nodes (vertices `low` and `high`, f 0 and `top`) and one arc through `vertices`.
Reeb_graph one_arc(Vertex_index low, Vertex_index high, double top, std::vector<Vertex_index> vertices) {
  Reeb_graph G;
  G.nodes = {{low, 0.0, minimum, {}}, {high, top, maximum, {}}};
  G.arcs = {{0, 1, std::move(vertices)}};
  return G;
}
Embedding_options unsmoothed(double level_width) {
  Embedding_options o;
  o.level_width = level_width;
  o.smoothing_iterations = 0;
  o.max_gap = 0;
  return o;
}
}  // namespace

TEST(EmbedReebGraph, ANodeSitsAtTheCentroidOfItsVertexAndMembers) {
  // Node 0: vertex 0 and members 1, 2 at (0, 0), (2, 0), (4, 3): centroid (2, 1). Node 1: vertex 3 and member
  // 4, both at (1e308, -0.0): the sum overflows, the mean does not, and the mean of -0.0s is -0.0.
  const std::vector<std::array<double, 3>> xyz{
      {0, 0, 0}, {2, 0, 0}, {4, 3, 0}, {1e308, -0.0, 0}, {1e308, -0.0, 0}};
  Reeb_graph G = one_arc(0, 3, 1.0, {});
  G.nodes[0].members = {1, 2};
  G.nodes[1].members = {4};
  const Reeb_graph_embedding E = embed_reeb_graph(G, xyz, {0.0, 0.0, 0.0, 1.0, 1.0}, 2);
  ASSERT_EQ(E.node_positions.size(), 2u);
  EXPECT_EQ(E.node_positions[0], (std::array<double, 3>{2, 1, 0}));
  EXPECT_EQ(E.node_positions[1][0], 1e308);
  EXPECT_EQ(E.node_positions[1][1], 0.0);
  EXPECT_TRUE(std::signbit(E.node_positions[1][1]));
}

TEST(EmbedReebGraph, TheAutomaticLevelWidthIsA64thOfTheRangeOfF) {
  // f from 0 to 64 over the nodes: bins of width 1, [k, k + 1). The arc's 128 points at f = x = 0.25, 0.75,
  // 1.25, ... fall two into each bin: 64 pieces between the two nodes, the first at x = 0.5.
  std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {64, 0, 0}};
  std::vector<double> f{0, 64};
  std::vector<Vertex_index> vertices;
  for (int k = 0; k < 128; ++k) {
    vertices.push_back(static_cast<Vertex_index>(xyz.size()));
    xyz.push_back({0.25 + 0.5 * k, 0, 0});
    f.push_back(0.25 + 0.5 * k);
  }
  Embedding_options o;
  o.smoothing_iterations = 0;
  const auto line = embed_reeb_graph(one_arc(0, 1, 64, vertices), xyz, f, 2, o).arc_polylines.at(0);
  ASSERT_EQ(line.size(), 66u);
  for (std::size_t k = 1; k + 1 < line.size(); ++k)
    EXPECT_EQ(line[k], (std::array<double, 3>{0.5 + double(k - 1), 0, 0})) << k;
}

TEST(EmbedReebGraph, TheLargestPieceOfALevelCarriesThePolyline) {
  // Bins of width 1. In each of the bins 0..3: a lone point S_k at (k + 0.5, 5) first in f order, and a pair
  // B_k at (k + 0.5, 0) and (k + 0.5, 0.2). The S_k are joined from bin to bin in the graph, the pairs only
  // within their bin: a level-set piece is a component of one bin's points, so the pair (2 points) carries
  // the polyline, not the chain of lone points. In bin 4 two lone points tie: the one holding the earliest
  // point (at y = 3) carries it.
  std::vector<std::array<double, 3>> xyz{{-1, 0, 0}, {6, 0, 0}};
  std::vector<double> f{-1, 6};
  std::vector<Vertex_index> vertices;
  Proximity_graph g;
  auto add = [&](double x, double y, double value) {
    vertices.push_back(static_cast<Vertex_index>(xyz.size()));
    xyz.push_back({x, y, 0});
    f.push_back(value);
    return vertices.back();
  };
  Vertex_index previous_s = 0;
  for (int k = 0; k < 4; ++k) {
    const Vertex_index s = add(k + 0.5, 5, k + 0.1);
    const Vertex_index b1 = add(k + 0.5, 0, k + 0.2), b2 = add(k + 0.5, 0.2, k + 0.3);
    if (k > 0) g.edges.push_back({previous_s, s});
    g.edges.push_back({b1, b2});
    previous_s = s;
  }
  add(4.5, 3, 4.1);
  add(4.5, -3, 4.2);
  g.number_of_vertices = xyz.size();
  Reeb_graph G = one_arc(0, 1, 6, vertices);
  G.nodes[0].value = -1;
  const auto line = embed_reeb_graph(G, g, xyz, f, 2, unsmoothed(1.0)).arc_polylines.at(0);
  ASSERT_EQ(line.size(), 7u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(line[static_cast<std::size_t>(k) + 1][0], k + 0.5) << k;
    EXPECT_DOUBLE_EQ(line[static_cast<std::size_t>(k) + 1][1], 0.1) << k;
  }
  EXPECT_EQ(line[5], (std::array<double, 3>{4.5, 3, 0}));
}

TEST(EmbedReebGraph, TheAutomaticGapIsTwiceTheMedianEdgeAndNoneWithoutEdges) {
  const L_shape l = l_shape();
  EXPECT_EQ(embed_reeb_graph(l.G, l.g, l.xyz, l.f, 2).max_gap, 2.0);  // unit edges
  // A graph without edges: a median length of 0, nothing can be bridged (max_gap infinity), straight.
  Proximity_graph none;
  none.number_of_vertices = l.xyz.size();
  const Reeb_graph_embedding E = embed_reeb_graph(l.G, none, l.xyz, l.f, 2);
  EXPECT_EQ(E.max_gap, std::numeric_limits<double>::infinity());
  EXPECT_EQ(E.arc_polylines.at(0).size(), 2u);
}

TEST(EmbedReebGraph, AnInfiniteGapIsOffAsZeroIs) {
  // The arc's two pieces at (1, 0) and (0, 0) (the lower node's place): the polyline goes out and back and
  // on, X B X C. With bridging off (max_gap 0 or infinity) it is drawn as it is; with bridging on and nothing
  // to bridge (no edges), the out-and-back B X goes (X B C), and at the upper node W X B X becomes W X.
  const std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {5, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  const std::vector<double> f{0, 5, 1.5, 2.5};
  const Reeb_graph G = one_arc(0, 1, 5, {2, 3});
  Proximity_graph g;
  g.number_of_vertices = 4;
  Embedding_options o = unsmoothed(1.0);
  const std::vector<std::array<double, 3>> drawn{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {5, 0, 0}};
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, o).arc_polylines.at(0), drawn);
  o.max_gap = std::numeric_limits<double>::infinity();
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, o).arc_polylines.at(0), drawn);
  o.max_gap = 100;
  EXPECT_EQ(embed_reeb_graph(G, g, xyz, f, 2, o).arc_polylines.at(0),
            (std::vector<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {5, 0, 0}}));
  // W at (-3, 0), the pieces X (3, 0) and B (4, 0), the upper node at X.
  const std::vector<std::array<double, 3>> back{{-3, 0, 0}, {3, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  EXPECT_EQ(embed_reeb_graph(G, g, back, f, 2, o).arc_polylines.at(0),
            (std::vector<std::array<double, 3>>{{-3, 0, 0}, {3, 0, 0}}));
}

TEST(EmbedReebGraph, ABridgeVertexSitsAtTheMeanOfItsNeighbourhood) {
  // A diamond 0 (0, 0), 1 (1, 1), 2 (1, -1), 3 (2, 0) and an arc from 0 to 3 without points: the gap 2 is
  // bridged through the shortest path; of the two (ties), the one by the smaller vertex, 1, drawn at the mean
  // of 1 and its neighbours 0 and 3: (1, 1/3).
  const std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {1, 1, 0}, {1, -1, 0}, {2, 0, 0}};
  Proximity_graph g;
  g.number_of_vertices = 4;
  g.edges = {{0, 1}, {0, 2}, {1, 3}, {2, 3}};
  Embedding_options o = unsmoothed(1.0);
  o.max_gap = 1;
  const auto line =
      embed_reeb_graph(one_arc(0, 3, 1, {}), g, xyz, {0, 0.5, 0.5, 1}, 2, o).arc_polylines.at(0);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line[0], xyz[0]);
  EXPECT_DOUBLE_EQ(line[1][0], 1.0);
  EXPECT_DOUBLE_EQ(line[1][1], 1.0 / 3);
  EXPECT_EQ(line[2], xyz[3]);
  // A gap exactly max_gap wide is not wider: not bridged.
  o.max_gap = 2;
  EXPECT_EQ(embed_reeb_graph(one_arc(0, 3, 1, {}), g, xyz, {0, 0.5, 0.5, 1}, 2, o).arc_polylines.at(0).size(),
            2u);
}

TEST(EmbedReebGraph, AShortestPathAsLongAsTheLimitIsFound) {
  // The path finder returns a shortest path no longer than the limit: one exactly as long is one.
  Point_matrix P;
  P.dimension = 1;
  P.rows = 3;
  P.data = {0, 1, 2};
  Proximity_graph g;
  g.number_of_vertices = 3;
  g.edges = {{0, 1}, {1, 2}};
  const skeleton::internal::Adjacency adjacency = skeleton::internal::make_adjacency(g);
  skeleton::internal::Graph_path_finder finder(adjacency, P);
  std::vector<Vertex_index> interior;
  EXPECT_TRUE(finder.path(0, 2, 2.0, interior));
  EXPECT_EQ(interior, (std::vector<Vertex_index>{1}));
  EXPECT_FALSE(finder.path(0, 2, 1.5, interior));
}

TEST(EmbedReebGraph, ArcsWithoutPointsCountTheirSmoothingRounds) {
  // Three arcs without points, 65,535 rounds each: 1 + 65,535 units of work per arc, a report before the
  // second and the third arc.
  const std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {1, 0, 0}};
  Reeb_graph G = one_arc(0, 1, 1, {});
  G.arcs.push_back(G.arcs[0]);
  G.arcs.push_back(G.arcs[0]);
  std::vector<double> seen;
  Embedding_options o;
  o.smoothing_iterations = 65535;
  o.progress = test::recording_progress(seen);
  EXPECT_EQ(embed_reeb_graph(G, xyz, {0, 1}, 2, o).status, Status::success);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_NEAR(seen[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(seen[1], 2.0 / 3, 1e-15);
  EXPECT_EQ(seen[2], 1.0);
}

TEST(ClassicalMds, NegativeEigenvaluesGiveZeroCoordinates) {
  // Three points 1, 1 and 5 apart (no triangle): the double-centred matrix has one positive, one zero and one
  // negative eigenvalue; the axes of the last two are 0.
  const auto x = classical_mds_3d({0, 1, 5, 1, 0, 1, 5, 1, 0}, 3);
  for (const auto& p : x) EXPECT_EQ(p[2], 0.0);
  EXPECT_GT(std::fabs(x[0][0] - x[2][0]), 1.0);
}

TEST(EmbedReebGraph, GapsAreBridgedFromThePiecePointClosestToTheCentroid) {
  // Nodes A (0, 0) and U (20, 0); the arc's one piece at x = 10 has its centroid at (10, 0). The gaps A-piece
  // and piece-U (10 > max_gap 3) are bridged through the graph from the piece's point closest to the
  // centroid: (10, 0) of three points (not the first, (10, 1)); of two at (10, 1) and (10, -1), tied, the
  // earlier. Bridged from another point, the path passed through the closest one: a point more.
  for (const bool tie : {false, true}) {
    std::vector<std::array<double, 3>> xyz{{0, 0, 0}, {20, 0, 0}, {5, 0, 0}, {15, 0, 0}, {10, 1, 0}};
    std::vector<double> f{0, 3, 0, 0, 1.1};
    Proximity_graph g;
    std::vector<Vertex_index> vertices{4};
    if (!tie) {  // 5 (10, 0) and 6 (10, -1): A - 2 - 5 - 3 - U, 4 - 5 - 6
      xyz.push_back({10, 0, 0});
      xyz.push_back({10, -1, 0});
      f.push_back(1.2);
      f.push_back(1.3);
      vertices.push_back(5);
      vertices.push_back(6);
      g.edges = {{0, 2}, {2, 5}, {3, 5}, {1, 3}, {4, 5}, {5, 6}};
    } else {  // 5 (10, -1): A - 2 - 4 - 3 - U, 4 - 5
      xyz.push_back({10, -1, 0});
      f.push_back(1.2);
      vertices.push_back(5);
      g.edges = {{0, 2}, {2, 4}, {3, 4}, {1, 3}, {4, 5}};
    }
    g.number_of_vertices = xyz.size();
    Embedding_options o = unsmoothed(1.0);
    o.max_gap = 3;
    const auto line = embed_reeb_graph(one_arc(0, 1, 3, vertices), g, xyz, f, 2, o).arc_polylines.at(0);
    ASSERT_EQ(line.size(), 5u) << tie;
    EXPECT_EQ(line[2], (std::array<double, 3>{10, 0, 0})) << tie;
  }
}
