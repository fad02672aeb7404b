// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// True graphs in R^d made of segments (a random tree, a figure-eight of two polygonal circles) and their
// noisy samples, for the high-dimensional skeleton tests and the example. Deterministic for a seed
// (std::mt19937 and a Box-Muller transform of our own, so the numbers do not depend on the standard library).
#ifndef FEATURERECON_TEST_HIGH_DIMENSIONAL_GRAPHS_H
#define FEATURERECON_TEST_HIGH_DIMENSIONAL_GRAPHS_H

#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace FeatureRecon {
namespace test {

/// Gaussian numbers from a mt19937 by Box-Muller (portable, unlike std::normal_distribution).
class Portable_gaussian {
 public:
  explicit Portable_gaussian(std::uint32_t seed) : m_rng(seed) {}
  double uniform() { return (static_cast<double>(m_rng()) + 0.5) / 4294967296.0; }
  double operator()() {
    if (m_has_spare) {
      m_has_spare = false;
      return m_spare;
    }
    const double u = uniform(), v = uniform();
    const double r = std::sqrt(-2 * std::log(u)), a = 2 * 3.14159265358979323846 * v;
    m_spare = r * std::sin(a);
    m_has_spare = true;
    return r * std::cos(a);
  }
  std::uint32_t next() { return m_rng(); }

 private:
  std::mt19937 m_rng;
  double m_spare = 0;
  bool m_has_spare = false;
};

inline double point_segment_distance(const double* p, const double* a, const double* b, std::size_t d) {
  double ab2 = 0, t = 0;
  for (std::size_t k = 0; k < d; ++k) {
    ab2 += (b[k] - a[k]) * (b[k] - a[k]);
    t += (p[k] - a[k]) * (b[k] - a[k]);
  }
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double s = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double x = a[k] + t * (b[k] - a[k]) - p[k];
    s += x * x;
  }
  return std::sqrt(s);
}

/// A graph of straight segments between vertices in R^d.
struct Segment_graph {
  std::size_t dimension = 0;
  std::vector<std::vector<double>> vertices;
  std::vector<std::array<std::size_t, 2>> segments;
  /// vertices that are nodes of the graph (polygon corners are not)
  std::vector<std::size_t> graph_vertices;

  std::vector<std::size_t> degrees() const {
    std::vector<std::size_t> deg(vertices.size(), 0);
    for (const auto& s : segments) ++deg[s[0]], ++deg[s[1]];
    return deg;
  }
  std::size_t leaves() const {
    std::size_t n = 0;
    for (const std::size_t d : degrees()) n += d == 1 ? 1 : 0;
    return n;
  }
  /// Degrees of the branch vertices (degree >= 3), sorted.
  std::vector<std::size_t> branch_degrees() const {
    std::vector<std::size_t> b;
    for (const std::size_t d : degrees())
      if (d >= 3) b.push_back(d);
    std::sort(b.begin(), b.end());
    return b;
  }
  std::size_t branch_excess() const {
    std::size_t n = 0;
    for (const std::size_t d : degrees()) n += d >= 3 ? d - 2 : 0;
    return n;
  }
  double distance(const double* p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& s : segments)
      best =
          std::min(best, point_segment_distance(p, vertices[s[0]].data(), vertices[s[1]].data(), dimension));
    return best;
  }
  /// Points every `spacing` along every segment (both ends included).
  std::vector<std::vector<double>> sample(double spacing) const {
    std::vector<std::vector<double>> out;
    for (const auto& s : segments) {
      const auto &a = vertices[s[0]], &b = vertices[s[1]];
      double len = 0;
      for (std::size_t k = 0; k < dimension; ++k) len += (b[k] - a[k]) * (b[k] - a[k]);
      const std::size_t n =
          std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::sqrt(len) / spacing)));
      for (std::size_t i = 0; i <= n; ++i) {
        std::vector<double> p(dimension);
        for (std::size_t k = 0; k < dimension; ++k)
          p[k] = a[k] + (b[k] - a[k]) * static_cast<double>(i) / static_cast<double>(n);
        out.push_back(std::move(p));
      }
    }
    return out;
  }
  /// One point every `spacing` of arc length along chains of consecutive segments (a segment continues the
  /// chain when it starts where the previous one ended; a new chain starts at its first vertex): no point
  /// twice, also where segments are shorter than the spacing.
  std::vector<std::vector<double>> sample_along(double spacing) const {
    std::vector<std::vector<double>> out;
    double next = 0;  // arc length into the current segment of the next point
    std::size_t previous_end = vertices.size();
    for (const auto& s : segments) {
      if (s[0] != previous_end) next = 0;
      const auto &a = vertices[s[0]], &b = vertices[s[1]];
      double len = 0;
      for (std::size_t k = 0; k < dimension; ++k) len += (b[k] - a[k]) * (b[k] - a[k]);
      len = std::sqrt(len);
      for (; next < len; next += spacing) {
        std::vector<double> p(dimension);
        for (std::size_t k = 0; k < dimension; ++k) p[k] = a[k] + (b[k] - a[k]) * next / len;
        out.push_back(std::move(p));
      }
      next -= len;
      previous_end = s[1];
    }
    return out;
  }
  /// sample(spacing) (or sample_along(spacing)) with independent Gaussian noise of standard deviation `noise`
  /// per coordinate; with sample(), points shared by two segments are taken once per segment (duplicates up
  /// to noise).
  skeleton::Point_matrix noisy_sample(double spacing, double noise, std::uint32_t seed,
                                      bool along = false) const {
    Portable_gaussian g(seed * 7919u + 17u);
    skeleton::Point_matrix m;
    m.dimension = dimension;
    for (const auto& p : along ? sample_along(spacing) : sample(spacing)) {
      for (std::size_t k = 0; k < dimension; ++k) m.data.push_back(p[k] + noise * g());
      ++m.rows;
    }
    return m;
  }
};

/// What the tests compare of a skeleton with the true graph.
struct Topology {
  std::size_t loops = 0, components = 0, leaves = 0, branch_excess = 0;  // branch_excess: sum of (degree - 2)
  std::vector<std::size_t> branch_degrees;  // degrees of the branch nodes (>= 3), sorted
};

inline Topology topology(const skeleton::Skeleton_graph& g) {
  Topology t;
  std::vector<int> comp(num_vertices(g));
  t.components =
      num_vertices(g) == 0 ? 0 : static_cast<std::size_t>(boost::connected_components(g, comp.data()));
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

inline std::vector<double> random_unit_vector(std::size_t d, Portable_gaussian& g) {
  std::vector<double> v(d);
  double n = 0;
  for (auto& x : v) {
    x = g();
    n += x * x;
  }
  for (auto& x : v) x /= std::sqrt(n);
  return v;
}

/// A random tree in R^d with `n` vertices and degrees at most 3: vertex i > 0 hangs off a random earlier
/// vertex of degree < 3 (at most 2 for the root), by a segment of length in [4, 6] in a random direction.
inline Segment_graph random_tree(std::size_t d, std::size_t n, std::uint32_t seed) {
  Portable_gaussian g(seed);
  Segment_graph t;
  t.dimension = d;
  t.vertices.push_back(std::vector<double>(d, 0.0));
  std::vector<std::size_t> deg(1, 0);
  for (std::size_t i = 1; i < n; ++i) {
    std::vector<std::size_t> open;
    for (std::size_t j = 0; j < i; ++j)
      if (deg[j] < (j == 0 ? 2u : 3u)) open.push_back(j);
    const std::size_t parent = open[g.next() % open.size()];
    const std::vector<double> u = random_unit_vector(d, g);
    const double len = 4 + 2 * g.uniform();
    std::vector<double> p(t.vertices[parent]);
    for (std::size_t k = 0; k < d; ++k) p[k] += len * u[k];
    t.vertices.push_back(std::move(p));
    t.segments.push_back({parent, i});
    ++deg[parent];
    deg.push_back(1);
  }
  return t;
}

/// Two circles of the given radius touching at one point, each a 64-gon in its own random 2-plane of R^d.
inline Segment_graph figure_eight(std::size_t d, double radius, std::uint32_t seed) {
  Portable_gaussian g(seed + 1000u);
  Segment_graph t;
  t.dimension = d;
  t.vertices.push_back(std::vector<double>(d, 0.0));  // the touching point
  for (int c = 0; c < 2; ++c) {
    // Orthonormal pair (Gram-Schmidt) spanning the circle's plane; the centre is at -radius * e1 (first
    // circle) or +radius * e1 (second), so both pass through the origin.
    std::vector<double> e1 = random_unit_vector(d, g), e2 = random_unit_vector(d, g);
    double dot = 0;
    for (std::size_t k = 0; k < d; ++k) dot += e1[k] * e2[k];
    double n = 0;
    for (std::size_t k = 0; k < d; ++k) {
      e2[k] -= dot * e1[k];
      n += e2[k] * e2[k];
    }
    for (auto& x : e2) x /= std::sqrt(n);
    const double side = c == 0 ? -1.0 : 1.0;
    std::size_t previous = 0;
    for (int i = 1; i < 64; ++i) {
      const double a = 2 * 3.14159265358979323846 * i / 64;
      std::vector<double> p(d);
      for (std::size_t k = 0; k < d; ++k)
        p[k] = side * radius * e1[k] - side * radius * std::cos(a) * e1[k] + radius * std::sin(a) * e2[k];
      t.vertices.push_back(std::move(p));
      t.segments.push_back({previous, t.vertices.size() - 1});
      previous = t.vertices.size() - 1;
    }
    t.segments.push_back({previous, 0});
  }
  return t;
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_HIGH_DIMENSIONAL_GRAPHS_H
