// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Shared fixtures of the skeleton tests: complexes with known Reeb graphs, noisy samples of graphs, and a
// brute-force augmented Reeb graph used as an oracle.
#ifndef FEATURERECON_TEST_SKELETON_TEST_UTILITIES_H
#define FEATURERECON_TEST_SKELETON_TEST_UTILITIES_H

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "test_utilities.h"

namespace FeatureRecon {
namespace test {

using skeleton::Edge;
using skeleton::Simplicial_complex_2;
using skeleton::Triangle;
using skeleton::Vertex_index;

/// The message of the std::invalid_argument that call() throws, or "no exception".
template <class Call>
std::string invalid_argument_message(Call&& call) {
  return thrown_message<std::invalid_argument>(std::forward<Call>(call));
}

/// A complex with a function on its vertices.
/// Input distance between planar points (the repair stages' Distance): Euclidean.
struct Planar_points {
  std::vector<std::array<double, 2>> p;
  double operator()(Vertex_index a, Vertex_index b) const {
    return std::hypot(p[a][0] - p[b][0], p[a][1] - p[b][1]);
  }
};

struct Complex_with_function {
  Simplicial_complex_2 complex;
  std::vector<double> f;
};

inline Complex_with_function make(std::size_t n, std::vector<Edge> e, std::vector<Triangle> t,
                                  std::vector<double> f) {
  return {skeleton::make_simplicial_complex_2(n, std::move(e), std::move(t)), std::move(f)};
}

/// The Reeb graph of a complex with a function.
inline skeleton::Reeb_graph reeb_graph_of(const Complex_with_function& c) {
  return skeleton::compute_augmented_reeb_graph(c.complex, c.f).reeb_graph();
}

/// A polygon with k vertices on the unit circle, f = height (plus a tilt to avoid symmetric ties).
inline Complex_with_function circle(std::size_t k) {
  std::vector<Edge> e;
  std::vector<double> f;
  const double pi = std::acos(-1.0);
  for (std::size_t i = 0; i < k; ++i) {
    e.push_back({static_cast<Vertex_index>(i), static_cast<Vertex_index>((i + 1) % k)});
    const double a = 2 * pi * static_cast<double>(i) / static_cast<double>(k);
    f.push_back(std::sin(a) + 0.01 * std::cos(a));
  }
  return make(k, e, {}, f);
}

/// Torus grid (nu x nv quads, 2 triangles each), standing upright: f = tilted height. Its Reeb graph has
/// one loop (the vertical class); the horizontal class of the torus does not appear.
inline Complex_with_function upright_torus(std::size_t nu, std::size_t nv, double tilt = 0.05) {
  const double pi = std::acos(-1.0), R = 2.0, r = 0.7;
  std::vector<double> f;
  std::vector<Triangle> t;
  auto id = [&](std::size_t i, std::size_t j) { return static_cast<Vertex_index>((i % nu) * nv + (j % nv)); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * static_cast<double>(i) / static_cast<double>(nu);
      const double v = 2 * pi * static_cast<double>(j) / static_cast<double>(nv);
      const double x = (R + r * std::cos(v)) * std::cos(u), y = r * std::sin(v),
                   z = (R + r * std::cos(v)) * std::sin(u);
      f.push_back(z + tilt * x + 0.3 * tilt * y);
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make(nu * nv, {}, t, f);
}

/// Vertical cylinder (open tube) with nu vertices around and nv rings: f = tilted height.
inline Complex_with_function cylinder(std::size_t nu, std::size_t nv) {
  const double pi = std::acos(-1.0);
  std::vector<double> f;
  std::vector<Triangle> t;
  auto id = [&](std::size_t i, std::size_t j) { return static_cast<Vertex_index>(j * nu + (i % nu)); };
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const double u = 2 * pi * static_cast<double>(i) / static_cast<double>(nu);
      f.push_back(static_cast<double>(j) + 0.1 * std::cos(u) + 0.03 * std::sin(u));
      if (j + 1 < nv) {
        t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return make(nu * nv, {}, t, f);
}

/// Deterministic random Rips-like complex: noisy samples of a plane graph given by its segments, joined
/// within `radius`, with triangles on 3-cliques. Returns points too.
struct Sampled_graph {
  std::vector<std::array<double, 2>> points;
};

inline Sampled_graph sample_segments(const std::vector<std::array<double, 4>>& segments, double spacing,
                                     double noise, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  Sampled_graph s;
  for (const auto& seg : segments) {
    const double len = std::hypot(seg[2] - seg[0], seg[3] - seg[1]);
    const std::size_t k = std::max<std::size_t>(1, static_cast<std::size_t>(len / spacing));
    for (std::size_t i = 0; i <= k; ++i) {
      const double a = static_cast<double>(i) / static_cast<double>(k);
      s.points.push_back(
          {seg[0] + a * (seg[2] - seg[0]) + gauss(rng), seg[1] + a * (seg[3] - seg[1]) + gauss(rng)});
    }
  }
  return s;
}

/// Segments of a figure-eight (two squares sharing a corner), a tree and a 3x3 grid.
inline std::vector<std::array<double, 4>> figure_eight_segments() {
  return {{0, 0, 4, 0}, {4, 0, 4, 4}, {4, 4, 0, 4}, {0, 4, 0, 0},
          {4, 4, 8, 4}, {8, 4, 8, 8}, {8, 8, 4, 8}, {4, 8, 4, 4}};
}
inline std::vector<std::array<double, 4>> tree_segments() {
  return {{0, 0, 0, 5}, {0, 5, -4, 9}, {0, 5, 4, 9}, {4, 9, 4, 13}, {4, 9, 8, 10}, {-4, 9, -7, 6}};
}
inline std::vector<std::array<double, 4>> grid_segments() {
  std::vector<std::array<double, 4>> s;
  for (int i = 0; i < 3; ++i) {
    s.push_back({0, 4.0 * i, 8, 4.0 * i});
    s.push_back({4.0 * i, 0, 4.0 * i, 8});
  }
  return s;
}

/// Augmented arcs as a sorted multiset of (lower vertex, upper vertex).
inline std::vector<std::pair<Vertex_index, Vertex_index>> arc_multiset(
    const skeleton::Augmented_reeb_graph& R) {
  std::vector<std::pair<Vertex_index, Vertex_index>> a;
  for (const auto& arc : R.arcs()) a.emplace_back(arc.lower, arc.upper);
  std::sort(a.begin(), a.end());
  return a;
}

/// Brute-force augmented Reeb graph: for every slab between consecutive vertices (in (f, index) order) the
/// components of the level set are recomputed from scratch with union-find over the crossing edges, joined by
/// the crossing triangles. O(n (m + t)). Returns the sorted arc multiset.
inline std::vector<std::pair<Vertex_index, Vertex_index>> brute_force_reeb_arcs(
    const Simplicial_complex_2& K, const std::vector<double>& f) {
  const std::size_t n = K.number_of_vertices, E = K.number_of_edges();
  std::vector<Vertex_index> order(n), rank(n);
  std::iota(order.begin(), order.end(), Vertex_index(0));
  std::sort(order.begin(), order.end(),
            [&](Vertex_index a, Vertex_index b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });
  for (std::size_t i = 0; i < n; ++i) rank[order[i]] = static_cast<Vertex_index>(i);
  auto lo = [&](std::size_t e) { return std::min(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  auto hi = [&](std::size_t e) { return std::max(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  std::vector<std::pair<Vertex_index, Vertex_index>> arcs_out;
  std::vector<std::int64_t> prev_arc(E, -1), cur_arc(E, -1);
  std::vector<Vertex_index> arc_start;
  std::vector<std::size_t> parent(E);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t s = 0; s < n; ++s) {
    const Vertex_index v = order[s];
    // Arcs ending at v: arcs of the previous slab's components that contain an edge ending at v.
    std::vector<std::int64_t> ending;
    for (std::size_t e = 0; e < E; ++e)
      if (hi(e) == s && prev_arc[e] >= 0) ending.push_back(prev_arc[e]);
    std::sort(ending.begin(), ending.end());
    ending.erase(std::unique(ending.begin(), ending.end()), ending.end());
    for (std::int64_t a : ending) arcs_out.emplace_back(arc_start[static_cast<std::size_t>(a)], v);
    // Slab s: crossing edges lo <= s < hi.
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (const Triangle& t : K.triangles) {
      std::array<Vertex_index, 3> r{rank[t[0]], rank[t[1]], rank[t[2]]};
      std::sort(r.begin(), r.end());
      const auto e_ab = static_cast<std::size_t>(K.find_edge(order[r[0]], order[r[1]]));
      const auto e_bc = static_cast<std::size_t>(K.find_edge(order[r[1]], order[r[2]]));
      const auto e_ac = static_cast<std::size_t>(K.find_edge(order[r[0]], order[r[2]]));
      if (r[0] <= s && s < r[1]) parent[find(e_ab)] = find(e_ac);
      if (r[1] <= s && s < r[2]) parent[find(e_bc)] = find(e_ac);
    }
    std::map<std::size_t, std::int64_t> comp_arc;
    // Components containing an edge starting at v start new arcs.
    for (std::size_t e = 0; e < E; ++e)
      if (lo(e) == s && !comp_arc.count(find(e))) {
        comp_arc[find(e)] = static_cast<std::int64_t>(arc_start.size());
        arc_start.push_back(v);
      }
    // Other components continue the arc of the previous slab.
    for (std::size_t e = 0; e < E; ++e)
      if (lo(e) < s && s < hi(e) && !comp_arc.count(find(e))) comp_arc[find(e)] = prev_arc[e];
    std::fill(cur_arc.begin(), cur_arc.end(), -1);
    for (std::size_t e = 0; e < E; ++e)
      if (lo(e) <= s && s < hi(e)) cur_arc[e] = comp_arc[find(e)];
    prev_arc.swap(cur_arc);
  }
  std::sort(arcs_out.begin(), arcs_out.end());
  return arcs_out;
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_SKELETON_TEST_UTILITIES_H
