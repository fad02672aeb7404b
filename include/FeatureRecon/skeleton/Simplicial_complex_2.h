// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_2_H
#define FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_2_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Index of a vertex of a complex; 32 bits keep large Rips complexes small in memory.
using Vertex_index = std::uint32_t;
using Edge = std::array<Vertex_index, 2>;
using Triangle = std::array<Vertex_index, 3>;

/// A weighted graph on the vertices 0..number_of_vertices-1: the 1-skeleton of a complex.
/// \note Canonical form (what every builder of this library returns, and what `is_canonical()` checks):
/// every edge has `e[0] < e[1]`, edges are sorted lexicographically without repetition,
/// `edge_lengths` is empty (all lengths 1) or aligned with `edges` with finite values >= 0.
struct Proximity_graph {
  std::size_t number_of_vertices = 0;  ///< vertices are 0..number_of_vertices-1
  std::vector<Edge> edges;             ///< sorted pairs (u, v), u < v
  std::vector<double> edge_lengths;    ///< aligned with `edges`; empty means every length is 1
  /// How the builder that returned the graph ended: success, or interrupted when its progress callback
  /// returned false (the graph then holds what that builder documents, e.g. the edges of the points visited).
  /// Not part of the graph: ignored by every function that takes a graph.
  Status status = Status::success;

  std::size_t number_of_edges() const { return edges.size(); }  ///< number of edges
  /// Length of edge e (1 when the graph is unweighted).
  double length(std::size_t e) const { return edge_lengths.empty() ? 1.0 : edge_lengths[e]; }

  /// Index of edge (u, v) (either order) or -1; O(log m).
  std::int64_t find_edge(Vertex_index u, Vertex_index v) const {
    if (u > v) std::swap(u, v);
    const Edge key{u, v};
    const auto it = std::lower_bound(edges.begin(), edges.end(), key);
    return (it != edges.end() && *it == key) ? static_cast<std::int64_t>(it - edges.begin()) : -1;
  }
};

/// A simplicial 2-complex: a proximity graph plus triangles. Every face of a triangle is in `edges`.
/// \note Canonical form: that of Proximity_graph, and every triangle has `t[0] < t[1] < t[2]`,
/// triangles sorted lexicographically without repetition.
struct Simplicial_complex_2 : Proximity_graph {
  std::vector<Triangle> triangles;  ///< sorted triples (a, b, c), a < b < c
  std::size_t number_of_triangles() const { return triangles.size(); }  ///< number of triangles
};

namespace internal {
/// \cond
// Sorts `keys` (all below 2^bits) into increasing order, stably, moving `payload` (aligned with keys) with
// them: least-significant-digit radix sort on 11-bit digits; a digit that every key shares is skipped. O(bits
// / 11 n) time, 2 n keys and payloads of memory.
template <class Payload>
void radix_sort(std::vector<std::uint64_t>& keys, std::vector<Payload>& payload, int bits) {
  constexpr int digit = 11;
  constexpr std::size_t buckets = std::size_t(1) << digit;
  std::vector<std::uint64_t> keys_out(keys.size());
  std::vector<Payload> payload_out(payload.size());
  std::vector<std::size_t> count(buckets);
  for (int shift = 0; shift < bits; shift += digit) {
    std::fill(count.begin(), count.end(), std::size_t(0));
    for (const std::uint64_t k : keys) ++count[(k >> shift) & (buckets - 1)];
    if (std::find(count.begin(), count.end(), keys.size()) != count.end()) continue;  // one digit for all
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::size_t at = count[(keys[i] >> shift) & (buckets - 1)]++;
      keys_out[at] = keys[i];
      payload_out[at] = payload[i];
    }
    keys.swap(keys_out);
    payload.swap(payload_out);
  }
}

// Sorts [first, last) in place by key(e) = e[0] << b | e[1] (vertices below 2^b), the lexicographic order of
// the pairs: most-significant-digit radix sort (American flag sort) on the 8-bit digit at `shift` and below,
// small ranges by a comparison sort. O(b / 4 n) time and no memory beyond the edges.
inline void flag_sort_edges(Edge* first, Edge* last, int b, int shift) {
  auto key = [b](const Edge& e) { return (std::uint64_t(e[0]) << b) | e[1]; };
  if (last - first < 64) {
    std::sort(first, last, [&key](const Edge& x, const Edge& y) { return key(x) < key(y); });
    return;
  }
  auto digit = [&key, shift](const Edge& e) { return static_cast<std::size_t>((key(e) >> shift) & 255); };
  std::array<std::size_t, 257> start{};  // bucket d is [start[d], start[d + 1])
  for (const Edge* e = first; e != last; ++e) ++start[digit(*e) + 1];
  for (std::size_t d = 0; d < 256; ++d) start[d + 1] += start[d];
  std::array<std::size_t, 256> next;
  std::copy(start.begin(), start.end() - 1, next.begin());
  for (std::size_t d = 0; d < 256; ++d)
    while (next[d] <
           start[d + 1]) {  // place the edge at next[d], and the edges it displaces, until one is d's
      Edge e = first[next[d]];
      for (std::size_t de = digit(e); de != d; de = digit(e)) std::swap(e, first[next[de]++]);
      first[next[d]++] = e;
    }
  if (shift == 0) return;
  const int lower = shift >= 8 ? shift - 8 : 0;  // a last digit overlapping this one: equal bits in a bucket
  for (std::size_t d = 0; d < 256; ++d)
    if (start[d + 1] - start[d] > 1) flag_sort_edges(first + start[d], first + start[d + 1], b, lower);
}

// Sorts edges lexicographically and removes repetitions; with lengths (aligned with edges), each edge keeps
// the length of its first occurrence. From 1024 edges on, by radix sorts on keys u << b | v (vertices below
// 2^b), which order as the pairs do: in place without lengths, stable (on a copy of the keys) with them.
inline void sort_unique_edges(std::vector<Edge>& edges, std::vector<double>* lengths) {
  const bool weighted = lengths != nullptr && !lengths->empty();
  Vertex_index largest = 0;
  for (const Edge& e : edges) largest = std::max({largest, e[0], e[1]});
  int b = 1;
  while (b < 32 && (largest >> b) != 0) ++b;
  if (!weighted) {
    if (edges.size() < 1024)
      std::sort(edges.begin(), edges.end());
    else
      flag_sort_edges(edges.data(), edges.data() + edges.size(), b, 2 * b >= 8 ? 2 * b - 8 : 0);
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return;
  }
  if (edges.size() < 1024) {
    std::vector<std::size_t> order(edges.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t c) { return edges[a] < edges[c]; });
    std::vector<Edge> e;
    std::vector<double> l;
    for (const std::size_t i : order) {
      if (!e.empty() && e.back() == edges[i]) continue;  // keep the first occurrence's length
      e.push_back(edges[i]);
      l.push_back((*lengths)[i]);
    }
    edges.swap(e);
    lengths->swap(l);
    return;
  }
  std::vector<std::uint64_t> keys(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) keys[i] = (std::uint64_t(edges[i][0]) << b) | edges[i][1];
  const std::uint64_t low = (std::uint64_t(1) << b) - 1;
  edges = std::vector<Edge>();  // its memory is not needed while the keys are sorted
  std::size_t kept = 0;
  std::vector<double> l = std::move(*lengths);
  radix_sort(keys, l, 2 * b);  // stable: the first occurrence of an edge comes first
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (i == 0 || keys[i] != keys[kept - 1]) {
      keys[kept] = keys[i];
      l[kept++] = l[i];
    }
  l.resize(kept);
  l.shrink_to_fit();
  *lengths = std::move(l);
  edges.resize(kept);
  for (std::size_t i = 0; i < kept; ++i)
    edges[i] = {static_cast<Vertex_index>(keys[i] >> b), static_cast<Vertex_index>(keys[i] & low)};
}
/// \endcond
}  // namespace internal

/// Builds a canonical complex from unordered edges and triangles, adding the edges of every
/// triangle (lengths of added edges: `implied_edge_length`) and removing repetitions.
/// \param lengths empty, or aligned with `edges`.
/// \throws std::invalid_argument naming the index of an edge or triangle with a vertex out of range,
/// a repeated vertex, or a negative or non-finite length (implied_edge_length too).
inline Simplicial_complex_2 make_simplicial_complex_2(std::size_t number_of_vertices, std::vector<Edge> edges,
                                                      std::vector<Triangle> triangles,
                                                      std::vector<double> lengths = {},
                                                      double implied_edge_length = 1.0) {
  const char* fn = "make_simplicial_complex_2";
  if (number_of_vertices > std::numeric_limits<Vertex_index>::max())
    FeatureRecon::internal::throw_invalid_argument(fn, "too many vertices (", number_of_vertices, ")");
  if (!lengths.empty() && lengths.size() != edges.size())
    FeatureRecon::internal::throw_invalid_argument(fn, "lengths has ", lengths.size(), " entries for ",
                                                   edges.size(), " edges");
  for (std::size_t i = 0; i < edges.size(); ++i) {
    Edge& e = edges[i];
    if (e[0] >= number_of_vertices || e[1] >= number_of_vertices)
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", i, " (", e[0], ", ", e[1],
                                                     ") has a vertex index out of range [0, ",
                                                     number_of_vertices, ")");
    if (e[0] == e[1])
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", i, " is a loop at vertex ", e[0]);
    if (e[0] > e[1]) std::swap(e[0], e[1]);
    if (!lengths.empty() && !(std::isfinite(lengths[i]) && lengths[i] >= 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", i, " has length ", lengths[i],
                                                     " (must be finite and >= 0)");
  }
  if (!(std::isfinite(implied_edge_length) && implied_edge_length >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "implied_edge_length is ", implied_edge_length,
                                                   " (must be finite and >= 0)");
  const bool weighted = !lengths.empty() || (implied_edge_length != 1.0 && !triangles.empty());
  if (weighted && lengths.empty()) lengths.assign(edges.size(), 1.0);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    Triangle& t = triangles[i];
    for (Vertex_index v : t)
      if (v >= number_of_vertices)
        FeatureRecon::internal::throw_invalid_argument(fn, "triangle ", i, " has vertex index ", v,
                                                       " out of range [0, ", number_of_vertices, ")");
    std::sort(t.begin(), t.end());
    if (t[0] == t[1] || t[1] == t[2])
      FeatureRecon::internal::throw_invalid_argument(fn, "triangle ", i, " repeats vertex ", t[1]);
    for (const Edge& f : {Edge{t[0], t[1]}, Edge{t[1], t[2]}, Edge{t[0], t[2]}}) {
      edges.push_back(f);
      if (weighted) lengths.push_back(implied_edge_length);
    }
  }
  Simplicial_complex_2 k;
  k.number_of_vertices = number_of_vertices;
  internal::sort_unique_edges(edges, weighted ? &lengths : nullptr);
  k.edges = std::move(edges);
  k.edge_lengths = std::move(lengths);
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  k.triangles = std::move(triangles);
  return k;
}

namespace internal {
/// The first way in which `g` is not canonical, in words naming the edge ("" when it is canonical); with
/// `check_lengths` false, only the number of lengths is checked, not their values.
inline std::string canonical_form_problem(const Proximity_graph& g, bool check_lengths = true) {
  std::ostringstream os;
  if (!g.edge_lengths.empty() && g.edge_lengths.size() != g.edges.size()) {
    os << "edge_lengths has " << g.edge_lengths.size() << " values for " << g.edges.size() << " edges";
    return os.str();
  }
  for (std::size_t i = 0; i < g.edges.size(); ++i) {
    const Edge& e = g.edges[i];
    const bool in_order = e[0] < e[1] && e[1] < g.number_of_vertices && (i == 0 || g.edges[i - 1] < e);
    if (in_order && (!check_lengths || g.edge_lengths.empty() ||
                     (std::isfinite(g.edge_lengths[i]) && g.edge_lengths[i] >= 0)))
      continue;
    os << "edge " << i << " (" << e[0] << ", " << e[1] << ")";
    if (std::max(e[0], e[1]) >= g.number_of_vertices)
      os << " has a vertex beyond the " << g.number_of_vertices << " vertices";
    else if (e[0] == e[1])
      os << " is a loop";
    else if (e[0] > e[1])
      os << " is not in increasing order";
    else if (!in_order)
      os << " is not after edge " << i - 1 << " (" << g.edges[i - 1][0] << ", " << g.edges[i - 1][1]
         << ") (edges sorted, without repetition)";
    else
      os << " has length " << g.edge_lengths[i] << " (finite and >= 0 needed)";
    return os.str();
  }
  return {};
}
}  // namespace internal

/// True when `g` is in the canonical form documented at Proximity_graph (and, for a complex,
/// every triangle is sorted, unique and has its three edges). O(m log m).
inline bool is_canonical(const Proximity_graph& g) { return internal::canonical_form_problem(g).empty(); }

inline bool is_canonical(const Simplicial_complex_2& k) {
  if (!is_canonical(static_cast<const Proximity_graph&>(k))) return false;
  for (std::size_t i = 0; i < k.triangles.size(); ++i) {
    const Triangle& t = k.triangles[i];
    if (!(t[0] < t[1] && t[1] < t[2] && t[2] < k.number_of_vertices)) return false;
    if (i > 0 && !(k.triangles[i - 1] < t)) return false;
    if (k.find_edge(t[0], t[1]) < 0 || k.find_edge(t[1], t[2]) < 0 || k.find_edge(t[0], t[2]) < 0)
      return false;
  }
  return true;
}

namespace internal {
/// The O(m) part of is_canonical(): sorted, unique, in-range simplices (not that triangles' edges exist). The
/// first simplex out of order or range, in words ("" when there is none).
inline std::string canonical_order_problem(const Simplicial_complex_2& k) {
  if (std::string edges = canonical_form_problem(k, false); !edges.empty()) return edges;
  std::ostringstream os;
  for (std::size_t i = 0; i < k.triangles.size(); ++i) {
    const Triangle& t = k.triangles[i];
    if (t[0] < t[1] && t[1] < t[2] && t[2] < k.number_of_vertices && (i == 0 || k.triangles[i - 1] < t))
      continue;
    os << "triangle " << i << " (" << t[0] << ", " << t[1] << ", " << t[2] << ")";
    if (std::max({t[0], t[1], t[2]}) >= k.number_of_vertices)
      os << " has a vertex beyond the " << k.number_of_vertices << " vertices";
    else if (!(t[0] < t[1] && t[1] < t[2]))
      os << " is not in increasing order";
    else
      os << " is not after triangle " << i - 1 << " (triangles sorted, without repetition)";
    return os.str();
  }
  return {};
}
}  // namespace internal

/// Connected components of the graph: a label per vertex in 0..count-1, numbered in the order of
/// their smallest vertex. O(n + m).
struct Connected_components {
  std::vector<std::uint32_t> label;  ///< component of each vertex
  std::size_t count = 0;             ///< number of components (isolated vertices included)
};

/// \pre every edge's vertices are < number_of_vertices (checked; throws naming the edge).
inline Connected_components connected_components(const Proximity_graph& g) {
  for (std::size_t i = 0; i < g.edges.size(); ++i)
    if (std::max(g.edges[i][0], g.edges[i][1]) >= g.number_of_vertices)
      FeatureRecon::internal::throw_invalid_argument("connected_components", "edge ", i, " (", g.edges[i][0],
                                                     ", ", g.edges[i][1], ") has a vertex beyond the ",
                                                     g.number_of_vertices, " vertices");
  FeatureRecon::internal::Union_find<std::uint32_t> sets(g.number_of_vertices);  // root = smallest vertex
  for (const Edge& e : g.edges) sets.unite(e[0], e[1]);
  Connected_components cc;
  cc.label.assign(g.number_of_vertices, 0);
  std::vector<std::uint32_t> id(g.number_of_vertices, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t v = 0; v < g.number_of_vertices; ++v) {
    const std::uint32_t r = sets.find(static_cast<std::uint32_t>(v));
    if (id[r] == std::numeric_limits<std::uint32_t>::max()) id[r] = static_cast<std::uint32_t>(cc.count++);
    cc.label[v] = id[r];
  }
  return cc;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_2_H
