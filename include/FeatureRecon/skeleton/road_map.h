// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_ROAD_MAP_H
#define FEATURERECON_SKELETON_ROAD_MAP_H

// Road maps from GPS traces in one call (dissertation Ch. 3.4): the GPS front end of gps_traces.h, then the
// skeleton stages of extract_reeb_skeleton.h, with every unset parameter derived from the data. The same
// rules drive `featurerecon skeleton --tracks`. Stage by stage:
//
//   const Road_map_options used = resolve_road_map_options(trips, options);  // radius, delta, ... set
//   const double R = *used.rips_radius;
//   const Gps_trace_sample S = sample_gps_traces(trips, R, used.traces);
//   const Proximity_graph g = build_gps_trace_graph(S, R);
//   const Reeb_skeleton k = extract_reeb_skeleton(g, S.points, road_map_skeleton_options(used));
//   const Embedded_graph_2 lines = skeleton_to_road_map(k.graph);
//   const Embedded_graph_2 map = merge_road_lines(lines, road_map_merge_options(used)).map;  // when
//   *used.merge_distance > 0

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/map_comparison.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// The trace options road maps start from: directions kept (heading tolerance 30 degrees), samples lighter
/// than 5 % of their direction's local maximum or 30 % of its maximum beside them dropped (since session 27,
/// which added the second rule and lowered the first from 10 %: Chicago 0.672 -> 0.702, benchmark/README.md,
/// "Scatter beside a street"); spacing, link gap and density radius automatic.
inline Gps_trace_options road_map_trace_options() {
  Gps_trace_options o;
  o.heading_tolerance = 30;
  o.min_relative_density = 0.05;
  o.min_lateral_density = 0.3;
  return o;
}

/// The embedding road maps draw their skeleton with: 2 smoothing rounds instead of 10, so that streets keep
/// their corners (the pieces of a road-map skeleton lie about half the Rips radius apart, and 10 rounds round
/// a corner over about 30 m). With road_merge_embedding_options() for the last stage this lifts the synthetic
/// city at every sampling rate and Chicago a little (benchmark/README.md, "Road maps"). Laplacian rounds:
/// Taubin rounds, which do not shrink, scored lower on every road map measured in session 25 (Chicago 0.672
/// -> 0.667, the grid city at 12 s 0.755 -> 0.699).
inline Embedding_options road_map_embedding_options() {
  Embedding_options o;
  o.smoothing = Embedding_options::Smoothing::laplacian;
  o.smoothing_iterations = 2;
  return o;
}

/// The embedding merge_road_lines() draws the merged lines with: 20 smoothing rounds. Its level-set pieces
/// lie a few metres apart (the map is sampled every distance / 3), so more rounds smooth over a similar
/// length. Laplacian rounds, as road_map_embedding_options().
inline Embedding_options road_merge_embedding_options() {
  Embedding_options o;
  o.smoothing = Embedding_options::Smoothing::laplacian;
  o.smoothing_iterations = 20;
  return o;
}

/// The planar map of a skeleton: vertex i is node i (its first two coordinates), followed by the interior
/// points of every arc's polyline in edge order; each polyline becomes a chain of edges between its nodes.
inline Embedded_graph_2 skeleton_to_road_map(const Skeleton_graph& g) {
  Embedded_graph_2 map;
  for (auto v : boost::make_iterator_range(vertices(g)))
    map.positions.push_back({g[v].position[0], g[v].position[1]});
  for (auto e : boost::make_iterator_range(edges(g))) {
    const auto& line = g[e].polyline;
    const auto s = static_cast<Vertex_index>(source(e, g)), t = static_cast<Vertex_index>(target(e, g));
    // The polyline runs from the lower node to the upper one; the edge's source may be either.
    const bool forward = line.empty() || line.front() == g[s].position;
    Vertex_index previous = forward ? s : t;
    for (std::size_t k = 1; k + 1 < line.size(); ++k) {
      map.positions.push_back({line[k][0], line[k][1]});
      const auto current = static_cast<Vertex_index>(map.positions.size() - 1);
      map.edges.push_back({previous, current});
      previous = current;
    }
    map.edges.push_back({previous, forward ? t : s});
  }
  return map;
}

/// Options of merge_road_lines(). Lengths in the map's unit (metres for road maps).
struct Road_merge_options {
  /// Parts of the map closer than this (and farther apart along the map) become one line. Default 8, between
  /// the 3-5 m that separate the two directions of a street and the 10 m or more of a divided road's
  /// carriageways.
  double distance = 8;
  /// The edges are sampled at most this far apart before the neighbourhood is built (> 0). Automatic
  /// (default): distance / 3. Two lines whose samples lie this far apart along them are joined by triangles
  /// wherever the samples fall while the lines are less than sqrt(distance^2 - spacing^2) apart (0.94
  /// distance). A quarter of the distance (before session 52) drew maps of the same quality (F within 0.012
  /// either way on 28 cities and thinned or noisy traces, mean -0.0003) in about twice the time (the merge of
  /// a 680 km city: 13 s -> 7.1 s); a half took less time still but left lines 7-8 m apart unmerged (a
  /// 200-trip synthetic city 0.812 -> 0.799). benchmark/README.md, "The merge samples every third of its
  /// distance".
  std::optional<double> spacing = FeatureRecon::automatic;
  /// Branches and loops of persistence up to this (along the map) are removed from the skeleton: stubs where
  /// two lines meet at an angle. Automatic (default): `distance`; 0: none.
  std::optional<double> delta = FeatureRecon::automatic;
  /// How the merged lines are drawn (level width automatic: the median edge length of the neighbourhood);
  /// default road_merge_embedding_options().
  Embedding_options embedding = road_merge_embedding_options();
  /// Skeleton_options::max_triangles of the neighbourhood's complex (its samples lie at least spacing / 2
  /// apart, so it stays far below the default unless `distance` is very large against `spacing`). The merge
  /// needs about 90 bytes per triangle, 1.5 KB per sample at the default spacing (a 680 km city: 415,469
  /// samples, 7.0 million triangles, 0.63 GB): the default 2^27 refuses, before storing a triangle, a complex
  /// that would need more than about 12 GB.
  std::size_t max_triangles = Skeleton_options().max_triangles;
  /// The most points inserted along the edges (the vertices not counted): a long edge against a short spacing
  /// is refused before any is inserted. Default 2^26; 0: no limit (but for 2^50, which no memory would hold).
  /// Dense maps meet max_triangles first (1,000 lines 3.6 km long and 3 m apart: 1.35 million samples, 52.8
  /// million triangles, 3.7 GB; 3,000 of them are refused at the triangle count, 1.8 GB peak).
  std::size_t max_samples = std::size_t(1) << 26;
  Progress_callback progress;  ///< fraction done; returning false stops (status interrupted, map empty)
};

/// Result of merge_road_lines().
struct Road_merge_result {
  Embedded_graph_2 map;      ///< the merged map: skeleton nodes first, then polyline interior points
  Skeleton_graph skeleton;   ///< its skeleton graph (nodes and arcs with polylines)
  double length_before = 0;  ///< total edge length of the input map (repeated edges once)
  double length_after = 0;   ///< total edge length of the merged map
  std::size_t samples = 0;   ///< points the neighbourhood was built on
  std::size_t samples_contracted = 0;  ///< samples within spacing / 2 of an earlier one, merged into it
  std::size_t rips_edges = 0;          ///< edges of the neighbourhood's complex (Reeb_skeleton::rips_edges)
  std::size_t rips_triangles = 0;      ///< its triangles (Reeb_skeleton::rips_triangles)
  std::size_t thin_loops_removed = 0;  ///< arcs removed as one side of a thin loop (see merge_road_lines())
  double spacing = 0;                  ///< value used
  double delta = 0;                    ///< value used
  double level_width = 0;              ///< the embedding's level width used (Reeb_skeleton::level_width)
  /// the embedding's max_gap used (Reeb_skeleton::max_gap)
  double max_gap = std::numeric_limits<double>::infinity();
  /// degenerate_input for a map without vertices; interrupted by the callback
  Status status = Status::success;
};

namespace internal {

inline double map_length(const std::vector<std::array<double, 2>>& positions,
                         const std::vector<Edge>& edges) {
  double L = 0;
  for (const Edge& e : edges)
    L += std::hypot(positions[e[1]][0] - positions[e[0]][0], positions[e[1]][1] - positions[e[0]][1]);
  return L;
}

using Polyline_3 = std::vector<std::array<double, 3>>;

/// Distance from p to the closest point of any segment of the polylines (first two coordinates).
inline double distance_to_polylines(const std::array<double, 3>& p,
                                    const std::vector<const Polyline_3*>& lines) {
  double best = std::numeric_limits<double>::infinity();
  for (const Polyline_3* line : lines)
    for (std::size_t i = 0; i < line->size(); ++i) {
      const auto& a = (*line)[i];
      const auto& b = (*line)[i + 1 < line->size() ? i + 1 : i];
      const double dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
      const double t = L2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
    }
  return best;
}

/// True when every vertex of each side lies within `d` of the other side (both sides as sets of polylines).
inline bool sides_within(const std::vector<const Polyline_3*>& a, const std::vector<const Polyline_3*>& b,
                         double d) {
  for (const auto* side : {&a, &b})
    for (const Polyline_3* line : *side)
      for (const auto& p : *line)
        if (distance_to_polylines(p, side == &a ? b : a) > d) return false;
  return true;
}

inline double polyline_length(const Polyline_3& line) {
  double L = 0;
  for (std::size_t i = 1; i < line.size(); ++i)
    L += std::hypot(line[i][0] - line[i - 1][0], line[i][1] - line[i - 1][1]);
  return L;
}

/// Removes the thin loops merging leaves behind where two lines diverge for a short stretch: two arcs between
/// the same nodes, or an arc u-w beside a path u-v-w, whose sides lie within `d` of each other. The longer
/// side goes (the direct arc when v has other arcs); its members join the side that stays. Nodes left without
/// arcs are removed. Returns the number of loops removed (one or two arcs each).
inline std::size_t remove_thin_loops(Skeleton_graph& g, double d) {
  using Arc = Skeleton_graph::edge_descriptor;
  std::size_t removed = 0;
  auto take_members = [&g](Arc from, Arc to) {
    auto& m = g[to].members;
    m.insert(m.end(), g[from].members.begin(), g[from].members.end());
  };
  // One pass over the arcs. Removing arcs only takes candidates away (polylines never change and no arc is
  // added), so an arc that has no thin loop never gets one: after a removal the scan goes on at the same arc
  // (or the next one, when that arc went), which is what restarting from the first arc would find. The
  // restart was quadratic: 0.8 s of a 3,000-intersection city's 12 s.
  const auto last = edges(g).second;  // the arcs are a std::list: removing one leaves the others' iterators
  for (auto it = edges(g).first; it != last;) {
    const Arc e = *it;
    const auto next = std::next(it);  // read when nothing changed or when e went, and then alone
    const auto u = source(e, g), w = target(e, g);
    bool changed = false, e_removed = false;
    if (u != w) {
      for (auto f : boost::make_iterator_range(out_edges(u, g))) {
        if (f == e) continue;
        const auto v = target(f, g);
        if (v == w) {  // two arcs between u and w
          if (!sides_within({&g[e].polyline}, {&g[f].polyline}, d)) continue;
          const bool drop_e = polyline_length(g[e].polyline) >= polyline_length(g[f].polyline);
          take_members(drop_e ? e : f, drop_e ? f : e);
          remove_edge(drop_e ? e : f, g);
          changed = true;
          e_removed = drop_e;
          break;
        }
        if (v == u) continue;
        for (auto h : boost::make_iterator_range(out_edges(v, g))) {
          if (target(h, g) != w || h == e) continue;
          if (!sides_within({&g[e].polyline}, {&g[f].polyline, &g[h].polyline}, d)) continue;
          const double direct = polyline_length(g[e].polyline);
          const double around = polyline_length(g[f].polyline) + polyline_length(g[h].polyline);
          if (degree(v, g) > 2 || direct >= around) {
            take_members(e, f);
            remove_edge(e, g);
            e_removed = true;
          } else {  // v is a kink of the longer side: the side u-v-w goes, v with it
            take_members(f, e);
            take_members(h, e);
            auto& m = g[e].members;
            m.insert(m.end(), g[v].members.begin(), g[v].members.end());
            g[v].members.clear();
            remove_edge(f, g);  // e stays: `next` (perhaps f or h) is not read
            remove_edge(h, g);
          }
          changed = true;
          break;
        }
        if (changed) break;
      }
    }
    if (changed) ++removed;
    if (!changed || e_removed) it = next;  // else e again, with the arcs it has left
  }
  // Nodes that lost all their arcs (never an isolated node of the input: those have no loop) go, and the
  // others are renumbered in order, the arcs' `lower` and `upper` with them. The graph is rebuilt once, its
  // arcs added in the order of the arc list, which is every node's order of arcs as well (boost appends an
  // arc to both lists and removes it from both keeping the order); boost's remove_vertex() renumbers the
  // whole graph for each node (16,000 kinks took 8 s).
  const std::size_t n = num_vertices(g), none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> index(n, none);
  std::size_t kept = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (degree(v, g) != 0 || !g[v].members.empty()) index[v] = kept++;
  if (kept == n) return removed;
  Skeleton_graph h(kept);
  for (std::size_t v = 0; v < n; ++v)
    if (index[v] != none) h[index[v]] = std::move(g[v]);
  for (auto e : boost::make_iterator_range(edges(g))) {
    Skeleton_arc& a = g[e];
    FEATURERECON_assertion(index[a.lower] != none && index[a.upper] != none);  // an arc's nodes have an arc
    a.lower = index[a.lower];
    a.upper = index[a.upper];
    add_edge(index[source(e, g)], index[target(e, g)], std::move(a), h);
  }
  g = std::move(h);
  return removed;
}

/// Greedy contraction of a planar point set: in index order, a point with an earlier kept point closer than
/// `h` joins the nearest such point (ties: the smaller index); the others are kept. `P` keeps the kept points
/// in their order and `edges` are renamed to them, loops dropped, repeats once, sorted. Returns the number of
/// points removed. Deterministic. When some point lies farther than 2^52 h from the origin (h tiny against
/// the coordinates) nothing is contracted.
inline std::size_t contract_close_samples(Point_matrix& P, double h, std::vector<Edge>& edges) {
  const std::size_t n = P.rows;
  if (n < 2 || !(h > 0)) return 0;
  double lo[2] = {P.data[0], P.data[1]}, hi[2] = {P.data[0], P.data[1]};
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c) {
      if (!(std::fabs(P.data[2 * i + c]) / h < 0x1p52)) return 0;
      lo[c] = std::min(lo[c], P.data[2 * i + c]);
      hi[c] = std::max(hi[c], P.data[2 * i + c]);
    }
  Planar_grid kept_in(lo[0], lo[1], hi[0], hi[1], h, n);  // kept points by cell of side h
  std::vector<std::size_t> to(n);
  std::size_t removed = 0;
  const double h2 = h * h;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = kept_in.cell_of(P.data[2 * i], P.data[2 * i + 1]);
    std::size_t best = n;
    double best_d2 = h2;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::vector<std::uint32_t>* bucket = kept_in.find(c[0] + dx, c[1] + dy);
        if (bucket == nullptr) continue;
        for (const std::size_t k : *bucket) {
          const double ex = P.data[2 * i] - P.data[2 * k], ey = P.data[2 * i + 1] - P.data[2 * k + 1];
          const double d2 = ex * ex + ey * ey;
          if (d2 < best_d2 || (d2 == best_d2 && best < n && k < best)) {
            best = k;
            best_d2 = d2;
          }
        }
      }
    if (best < n) {
      to[i] = best;
      ++removed;
    } else {
      to[i] = i;
      kept_in.push(c, static_cast<std::uint32_t>(i));
    }
  }
  if (removed == 0) return 0;
  std::vector<Vertex_index> index(n, 0);
  std::vector<double> data;
  data.reserve(2 * (n - removed));
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (to[i] == i) {
      index[i] = static_cast<Vertex_index>(m++);
      data.insert(data.end(), {P.data[2 * i], P.data[2 * i + 1]});
    }
  P.data = std::move(data);
  P.rows = m;
  std::vector<Edge> out;
  out.reserve(edges.size());
  for (const Edge& e : edges) {
    const Vertex_index a = index[to[e[0]]], b = index[to[e[1]]];
    if (a != b) out.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  edges = std::move(out);
  return removed;
}

/// The vertices merge_road_lines() keeps: every vertex not of degree 2 in `edges` (unique, no loops), and
/// along each chain of degree-2 vertices the first one at least `min_step` along the chain from the last kept
/// one (a cycle of degree-2 vertices keeps its smallest index). With `min_step` a fraction of the sampling
/// spacing this drops only vertices closer together than the samples (a skeleton drawn at a small radius has
/// polylines with vertices centimetres apart, which made the neighbourhood graph quadratic); returns the kept
/// vertices' flags and the edges between consecutive kept vertices (unique, sorted), or no edges when every
/// vertex is kept.
inline std::vector<Edge> thin_map_chains(const std::vector<std::array<double, 2>>& positions,
                                         const std::vector<Edge>& edges, double min_step,
                                         std::vector<char>& kept) {
  const std::size_t n = positions.size();
  std::vector<std::vector<std::pair<Vertex_index, std::size_t>>> around(n);  // (neighbour, edge)
  for (std::size_t e = 0; e < edges.size(); ++e) {
    around[edges[e][0]].push_back({edges[e][1], e});
    around[edges[e][1]].push_back({edges[e][0], e});
  }
  auto length = [&](Vertex_index a, Vertex_index b) {
    return std::hypot(positions[b][0] - positions[a][0], positions[b][1] - positions[a][1]);
  };
  kept.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) kept[v] = around[v].size() != 2;
  std::vector<char> walked(edges.size(), 0);
  std::vector<Edge> out;
  bool dropped = false;
  // Walks the chain leaving kept vertex `start` by edge `first`, keeping vertices as described.
  auto walk = [&](Vertex_index start, Vertex_index next, std::size_t first) {
    Vertex_index previous = start, last_kept = start;
    double along = 0;
    for (std::size_t e = first;;) {
      walked[e] = 1;
      along += length(previous, next);
      if (kept[next] || along >= min_step) {
        if (!kept[next]) kept[next] = 1;
        if (last_kept != next) out.push_back({std::min(last_kept, next), std::max(last_kept, next)});
        last_kept = next;
        along = 0;
      } else {
        dropped = true;
      }
      if (around[next].size() != 2 || next == start) break;
      const auto& two = around[next];
      const std::size_t k = two[0].second == e ? 1 : 0;
      if (walked[two[k].second]) {  // back at the start of a cycle
        if (last_kept != start) out.push_back({std::min(last_kept, start), std::max(last_kept, start)});
        break;
      }
      previous = next;
      next = two[k].first;
      e = two[k].second;
    }
  };
  for (std::size_t v = 0; v < n; ++v)
    if (kept[v] && around[v].size() != 2)
      for (const auto& [w, e] : around[v])
        if (!walked[e]) walk(static_cast<Vertex_index>(v), w, e);
  for (std::size_t v = 0; v < n; ++v)  // cycles of degree-2 vertices only
    if (!kept[v] && around[v].size() == 2 && !walked[around[v][0].second]) {
      kept[v] = 1;
      walk(static_cast<Vertex_index>(v), around[v][0].first, around[v][0].second);
    }
  if (!dropped) return {};
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace internal

/// Merges the lines of a road map that run closer than `options.distance` (see the file comment). Vertices
/// come first in the samples (a map with more vertices than twice the samples its length calls for first
/// loses those closer together along a line than half the spacing, thin_map_chains()), then every edge longer
/// than the spacing gets evenly spaced interior points, and a sample closer than half the spacing to an
/// earlier one joins it (contract_close_samples(): lines that share a stretch are sampled once; a vertex with
/// no edge stays a node unless it lies that close to an earlier sample). The graph of the Rips edges at
/// `distance` and the edges' own chains is passed to extract_reeb_skeleton() with delta, no repair, no
/// pruning and no branch merging (branch_merge_distance 0: forks stay where the lines diverge). Where two
/// lines diverge beyond `distance` for a short stretch the skeleton keeps a thin loop; loops whose two sides
/// lie within `distance` of each other (two arcs between the same nodes, or an arc beside a two-arc path)
/// lose their longer side. Deterministic. The map is not modified.
/// \throws std::invalid_argument naming a non-finite vertex, an edge with an end out of range, an edge whose
///   length overflows, edges that would need more than `max_samples` points inserted along them (naming the
///   longest edge), a neighbourhood complex with more than `max_triangles` triangles (checked before any is
///   stored), a non-positive or non-finite distance or spacing, a negative or non-finite delta, or bad
///   `embedding` options (named by extract_reeb_skeleton()).
inline Road_merge_result merge_road_lines(const Embedded_graph_2& map,
                                          const Road_merge_options& options = {}) {
  const char* fn = "merge_road_lines";
  if (!(options.distance > 0 && std::isfinite(options.distance)))
    FeatureRecon::internal::throw_invalid_argument(fn, "distance must be positive and finite, got ",
                                                   options.distance);
  FeatureRecon::internal::check_optional_length(fn, options.spacing, "spacing", "distance / 3");
  FeatureRecon::internal::check_optional_length(fn, options.delta, "delta", "distance", "no simplification");
  for (std::size_t v = 0; v < map.positions.size(); ++v)
    if (!std::isfinite(map.positions[v][0]) || !std::isfinite(map.positions[v][1]))
      FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " has a non-finite coordinate");
  for (std::size_t e = 0; e < map.edges.size(); ++e)
    if (map.edges[e][0] >= map.positions.size() || map.edges[e][1] >= map.positions.size())
      FeatureRecon::internal::throw_invalid_argument(
          fn, "edge ", e, " (", map.edges[e][0], ", ", map.edges[e][1],
          ") has an end out of range: the map has ", map.positions.size(), " vertices");
  Road_merge_result r;
  r.spacing = options.spacing.value_or(options.distance / 3);
  r.delta = options.delta.value_or(options.distance);
  // Repeated and reversed edges once, loops dropped.
  std::vector<Edge> edges;
  for (const Edge& e : map.edges)
    if (e[0] != e[1]) edges.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  r.length_before = internal::map_length(map.positions, edges);
  // A map with more vertices than twice the samples its length calls for (a skeleton drawn at a small radius:
  // polyline vertices centimetres apart made the neighbourhood graph quadratic, 35 s and 4.4 GB for 164 fixes
  // at radius 0.5) loses the vertices closer together along a line than half the spacing; other maps are
  // sampled as they are.
  std::vector<char> kept;
  std::vector<Edge> thinned;
  if (static_cast<double>(map.positions.size()) > 2 * (r.length_before / r.spacing + 1))
    thinned = internal::thin_map_chains(map.positions, edges, r.spacing / 2, kept);
  std::vector<std::array<double, 2>> positions;
  if (!thinned.empty()) {
    std::vector<Vertex_index> index(map.positions.size(), 0);
    for (std::size_t v = 0; v < map.positions.size(); ++v)
      if (kept[v]) {
        index[v] = static_cast<Vertex_index>(positions.size());
        positions.push_back(map.positions[v]);
      }
    for (Edge& e : thinned) e = {index[e[0]], index[e[1]]};
    edges = std::move(thinned);
  } else {
    positions = map.positions;
  }
  if (map.positions.empty()) {
    r.status = Status::degenerate_input;
    return r;
  }
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) {
    r.status = Status::interrupted;
    return r;
  }
  // Samples: the vertices, then interior points of each edge; the chains of the edges. Counted first: an edge
  // of 1e9 m at a spacing of 2.7 m would insert 375 million points.
  double sample_count = 0, longest = 0;  // points along the edges
  std::array<double, 4> longest_ends{};
  for (const Edge& e : edges) {
    const auto a = positions[e[0]], b = positions[e[1]];
    const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (!std::isfinite(L))
      FeatureRecon::internal::throw_invalid_argument(fn, "the edge from (", a[0], ", ", a[1], ") to (", b[0],
                                                     ", ", b[1], ") has a length that overflows");
    sample_count += std::max(0.0, std::ceil(L / r.spacing) - 1);
    if (L > longest) {
      longest = L;
      longest_ends = {a[0], a[1], b[0], b[1]};
    }
  }
  const std::size_t max_samples = options.max_samples > 0 ? options.max_samples : std::size_t(1) << 50;
  if (sample_count > static_cast<double>(max_samples))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "sampling the map's ", r.length_before, " m of edges every ", r.spacing, " m would insert about ",
        sample_count, " points, more than max_samples (", max_samples, "); the longest edge, from (",
        longest_ends[0], ", ", longest_ends[1], ") to (", longest_ends[2], ", ", longest_ends[3], "), is ",
        longest, " long: raise spacing or max_samples");
  Point_matrix P;
  P.dimension = 2;
  P.rows = positions.size();
  for (const auto& p : positions) P.data.insert(P.data.end(), {p[0], p[1]});
  std::vector<Edge> chain;
  for (const Edge& e : edges) {
    const auto a = positions[e[0]], b = positions[e[1]];
    const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
    const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(L / r.spacing)));
    Vertex_index previous = e[0];
    for (std::size_t k = 1; k < n; ++k) {
      const double u = static_cast<double>(k) / static_cast<double>(n);
      P.data.insert(P.data.end(), {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])});
      const auto current = static_cast<Vertex_index>(P.rows++);
      chain.push_back({previous, current});
      previous = current;
    }
    chain.push_back({std::min(previous, e[1]), std::max(previous, e[1])});
  }
  // Samples closer than half the spacing (or half the distance, if smaller) to an earlier one become that one
  // (the nearest, ties by index): arcs that share a stretch (a skeleton's arcs following the same shortest
  // path across gaps, or coincident polylines) would otherwise stack their samples, and the neighbourhood's
  // cliques grow with the cube of the stack (the Chicago map at delta 1000 stacks up to 26 arcs: 52 s and 6
  // GB). Afterwards no disk of radius `distance` holds more than about (2 distance / spacing + 1)^2 samples.
  r.samples_contracted =
      internal::contract_close_samples(P, std::min(r.spacing, options.distance) / 2, chain);
  r.samples = P.rows;
  Proximity_graph_options po;
  bool stopped = false;  // a stop inside the Rips stage counts even if the callback answers true afterwards
  if (options.progress)
    po.progress = [&options, &stopped](double t) {
      return !(stopped = stopped || !options.progress(0.3 * t));
    };
  std::vector<Edge> neighbourhood = build_rips_graph(P, options.distance, po).edges;
  if (stopped || !FeatureRecon::internal::report_progress(options.progress, 0.3)) {
    r.status = Status::interrupted;
    return r;
  }
  neighbourhood.insert(neighbourhood.end(), chain.begin(), chain.end());
  const Proximity_graph g = internal::planar_graph(P, std::move(neighbourhood));
  Skeleton_options so;
  so.delta = r.delta;
  so.branch_merge_distance = 0;  // the lines are redrawn from the arcs; forks stay where the lines diverge
  so.max_triangles = options.max_triangles;
  so.embedding = options.embedding;
  if (options.progress) so.progress = [&options](double t) { return options.progress(0.3 + 0.7 * t); };
  // A complex above max_triangles (or the Reeb graph's own limit) is this stage's refusal, named here with
  // what to change here; other errors pass as they are.
  Reeb_skeleton k = [&] {
    try {
      return extract_reeb_skeleton(g, P, so);
    } catch (const std::invalid_argument& e) {
      std::string what = e.what();
      const std::string refusal = "extract_reeb_skeleton: the flag complex has more than ";
      const std::string advice = ": use a smaller radius or fewer points, or raise the limit";
      if (what.compare(0, refusal.size(), refusal) != 0) throw;
      if (what.size() > advice.size() &&
          what.compare(what.size() - advice.size(), advice.size(), advice) == 0)
        what.erase(what.size() - advice.size());
      const bool option = what.find("max_triangles of the options") != std::string::npos;
      FeatureRecon::internal::throw_invalid_argument(
          fn, "the complex of the lines' ", options.distance, " neighbourhood (", P.rows, " samples every ",
          r.spacing, ") has more than ", what.substr(refusal.size()), ": raise spacing or lower distance",
          option ? ", or raise max_triangles" : "");
    }
  }();
  if (k.status == Status::interrupted) {
    r.status = Status::interrupted;
    return r;
  }
  r.level_width = k.level_width;
  r.max_gap = k.max_gap;
  r.rips_edges = k.rips_edges;
  r.rips_triangles = k.rips_triangles;
  r.thin_loops_removed = internal::remove_thin_loops(k.graph, options.distance);
  r.map = skeleton_to_road_map(k.graph);
  r.skeleton = std::move(k.graph);
  r.length_after = internal::map_length(r.map.positions, r.map.edges);
  return r;
}

/// Options of extract_road_map(). Coordinates are metres. An automatic value (FeatureRecon::automatic, the
/// default of the optional fields) asks for the rule on the field, derived from the median step M between
/// consecutive fixes of a trip (median_gps_step()) through the Rips radius R; 0 turns the stage off, and a
/// negative value is refused (before FeatureRecon::automatic, 0 asked for the rule and a negative value
/// turned the stage off). resolve_road_map_options() returns the values used.
struct Road_map_options {
  /// Rips radius (> 0); automatic (default): M clamped to [min_radius, max_radius]
  std::optional<double> rips_radius = FeatureRecon::automatic;
  double min_radius = 10;  ///< lower clamp of the automatic radius (m; > 0, <= max_radius); default 10
  double max_radius = 30;  ///< upper clamp of the automatic radius (m; finite); default 30
  /// persistence threshold of the simplification; automatic (default): 3 R; 0: none
  std::optional<double> delta = FeatureRecon::automatic;
  /// join dead ends at most this far apart; automatic (default): 2.5 R; 0: no repair
  std::optional<double> repair_distance = FeatureRecon::automatic;
  /// drop components of smaller height (range of f); automatic (default): 5 R; 0: keep all; infinity: drop
  /// all (an empty map)
  std::optional<double> prune_height = FeatureRecon::automatic;
  /// Sampling, linking and density filter (sample_gps_traces()); its own automatic rules (spacing R/2, link
  /// gap max(4M, 2R), segment support max(20 m, 2R/3), density radius 2R) apply and are reported in
  /// Road_map::sample.
  Gps_trace_options traces = road_map_trace_options();
  bool connect_dead_ends = true;  ///< Skeleton_options::connect_dead_ends
  bool trim_stubs = true;         ///< Skeleton_options::trim_stubs
  /// Skeleton_options::branch_merge_distance (automatic: twice the level width); default 0 (off): the road
  /// lines are drawn from the arcs and merged afterwards (merge_road_lines()); on Chicago merging forks at 1
  /// or 2 level widths (14.4 m, 28.9 m) scores F 0.7024 / 0.7014 against 0.7016.
  std::optional<double> branch_merge_distance = 0.0;
  /// Skeleton_options::max_triangles of the skeleton and of the merging stage (Road_merge_options).
  std::size_t max_triangles = Skeleton_options().max_triangles;
  /// How arcs are drawn (level width automatic: median edge length of the complex); default
  /// road_map_embedding_options().
  Embedding_options embedding = road_map_embedding_options();
  /// Last stage: lines of the map closer than this become one (merge_road_lines()). Driving directions keep a
  /// divided road's carriageways apart but also draw the two directions of a two-way street, a few metres
  /// apart. Automatic (default): 8 m (Road_merge_options::distance); 0: no merging.
  std::optional<double> merge_distance = FeatureRecon::automatic;
  Progress_callback progress;  ///< fraction done; returning false stops (Road_map::status interrupted)
};

/// Result of extract_road_map().
struct Road_map {
  /// The road map. Without merging: skeleton nodes first (same indices), then polyline interior points; with
  /// merging: merged.skeleton's nodes first, then its polylines' interior points.
  Embedded_graph_2 map;
  Reeb_skeleton skeleton;  ///< the skeleton graph of the samples with its stage counts (before merging)
  /// the merging stage (its `map` is moved to `map`); status success and empty if off
  Road_merge_result merged;
  Gps_trace_sample sample;  ///< the samples the skeleton is built on, with the trace parameters used
  /// The options with the values used (no progress callback): resolve_road_map_options()'s fields, then, as
  /// the stages run, the trace options' automatic lengths (from `sample`) and the embedding's level width and
  /// gap and the branch merge distance (from `skeleton`). After a run that completed every optional field
  /// is set, except a level width that no complex gave (no samples: automatic), and extract_road_map(trips,
  /// used) draws the same map; a stopped run leaves the fields of the stages it did not reach automatic.
  Road_map_options used;
  Status status = Status::success;  ///< degenerate_input when no fix is left; interrupted by the callback
};

/// The options with the automatic values of extract_road_map() that the fixes decide filled in: the radius,
/// delta, repair, prune and merge distance (0 when turned off). The rules of the trace options and of the
/// skeleton (level width, gap, an automatic branch merge distance) need the samples and the complex: they are
/// left automatic here, for sample_gps_traces() and extract_reeb_skeleton() (Road_map::used has them after a
/// run).
/// \throws std::invalid_argument naming a non-finite or negative option, a radius that is 0, a non-positive
///   clamp, min_radius > max_radius, or a radius above 1e300.
inline Road_map_options resolve_road_map_options(const std::vector<Gps_trip>& trips,
                                                 const Road_map_options& options) {
  const char* fn = "extract_road_map";
  FeatureRecon::internal::check_optional_length(fn, options.rips_radius, "rips_radius",
                                                "from the median step");
  if (!(options.min_radius > 0 && options.min_radius <= options.max_radius &&
        std::isfinite(options.max_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "need 0 < min_radius <= max_radius < infinity, got ",
                                                   options.min_radius, " and ", options.max_radius);
  const auto check = [fn](const std::optional<double>& value, const char* name, const char* rule,
                          bool infinity_allowed = false) {
    FeatureRecon::internal::check_optional_length(fn, value, name, rule, "off", infinity_allowed);
  };
  check(options.delta, "delta", "3 R");
  check(options.repair_distance, "repair_distance", "2.5 R");
  check(options.prune_height, "prune_height", "5 R", true);
  check(options.merge_distance, "merge_distance", "8 m");
  check(options.branch_merge_distance, "branch_merge_distance", "twice the level width");
  Road_map_options u = options;
  u.progress = nullptr;
  const double M = median_gps_step(trips);
  const double R = options.rips_radius ? *options.rips_radius
                                       : std::min(options.max_radius, std::max(options.min_radius, M));
  if (!(R <= 1e300))  // the automatic delta, repair and prune (3R, 2.5R, 5R) must be finite
    FeatureRecon::internal::throw_invalid_argument(
        fn, options.rips_radius ? "rips_radius" : "max_radius",
        " must be at most 1e300 (the automatic delta, repair_distance and ",
        "prune_height are 3, 2.5 and 5 times the radius), got ", R);
  u.rips_radius = R;
  u.delta = options.delta.value_or(3 * R);
  u.repair_distance = options.repair_distance.value_or(2.5 * R);
  u.prune_height = options.prune_height.value_or(5 * R);
  u.merge_distance = options.merge_distance.value_or(Road_merge_options{}.distance);
  return u;
}

namespace internal {
/// The value of a field that resolve_road_map_options() sets; refuses options it did not resolve.
inline double resolved(const std::optional<double>& value, const char* fn, const char* name) {
  if (!value)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the options' ", name, " is automatic: pass the result of resolve_road_map_options()");
  return *value;
}
}  // namespace internal

/// The skeleton options of a resolved Road_map_options (the progress callback is not copied).
/// \throws std::invalid_argument when delta, repair_distance or prune_height is automatic (options not
///   resolved by resolve_road_map_options()).
inline Skeleton_options road_map_skeleton_options(const Road_map_options& used) {
  const char* fn = "road_map_skeleton_options";
  Skeleton_options o;
  o.delta = internal::resolved(used.delta, fn, "delta");
  o.repair_distance = internal::resolved(used.repair_distance, fn, "repair_distance");
  o.prune_height = internal::resolved(used.prune_height, fn, "prune_height");
  o.connect_dead_ends = used.connect_dead_ends;
  o.trim_stubs = used.trim_stubs;
  o.branch_merge_distance = used.branch_merge_distance;
  o.max_triangles = used.max_triangles;
  o.embedding = used.embedding;
  return o;
}

/// The merging options of a resolved Road_map_options (used.merge_distance > 0; spacing, delta automatic).
/// \throws std::invalid_argument when merge_distance is automatic (options not resolved by
///   resolve_road_map_options()) or 0 (no merge to run).
inline Road_merge_options road_map_merge_options(const Road_map_options& used) {
  const char* fn = "road_map_merge_options";
  Road_merge_options o;
  o.distance = internal::resolved(used.merge_distance, fn, "merge_distance");
  if (!(o.distance > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "merge_distance is ", o.distance,
                                                   ": merging is off, there are no merge options");
  o.max_triangles = used.max_triangles;
  return o;
}

/// A road map from GPS traces in one call: resolve_road_map_options(), sample_gps_traces(),
/// build_gps_trace_graph(), extract_reeb_skeleton() on the graph, skeleton_to_road_map(), merge_road_lines()
/// (unless turned off). Deterministic (no randomness; the same trips in the same order give the same map bit
/// for bit). Trips with no or one fix are allowed; with no fix at all the map is empty and the status
/// degenerate_input.
/// \throws std::invalid_argument for bad options (resolve_road_map_options(), sample_gps_traces()), a
/// skeleton
///         whose lines would need more than Road_merge_options::max_samples points to merge
///         (merge_road_lines()), or a fix with a non-finite coordinate or time (naming the trip and the fix).
///         `trips` is not modified.
inline Road_map extract_road_map(const std::vector<Gps_trip>& trips, const Road_map_options& options = {}) {
  const char* fn = "extract_road_map";
  Road_map r;
  r.used = resolve_road_map_options(trips, options);
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) {
    r.status = Status::interrupted;
    return r;
  }
  Gps_trace_options to = r.used.traces;
  if (options.progress) to.progress = [&options](double t) { return options.progress(0.1 * t); };
  const double radius = r.used.rips_radius.value();
  r.sample = sample_gps_traces(trips, radius, to);
  r.used.traces.sample_spacing = r.sample.sample_spacing;
  r.used.traces.max_link_gap = r.sample.max_link_gap;
  r.used.traces.density_radius = r.sample.density_radius;
  r.used.traces.segment_support = r.sample.segment_support;
  if (r.sample.status == Status::interrupted ||
      !FeatureRecon::internal::report_progress(options.progress, 0.1)) {
    r.status = Status::interrupted;
    return r;
  }
  // The neighbourhood graph up to 0.15 (no report after a stop), the skeleton up to 0.9.
  bool stopped = false;
  Gps_trace_graph_options go;
  if (options.progress)
    go.progress = [&options, &stopped](double t) {
      if (!stopped && !options.progress(std::min(0.15, 0.1 + 0.05 * t))) stopped = true;  // (0.15 rounds up)
      return !stopped;
    };
  Proximity_graph graph = build_gps_trace_graph(r.sample, radius, go);
  if (stopped) {
    r.status = Status::interrupted;
    return r;
  }
  Skeleton_options so = road_map_skeleton_options(r.used);
  if (options.progress) so.progress = [&options](double t) { return options.progress(0.15 + 0.75 * t); };
  r.skeleton = extract_reeb_skeleton(graph, r.sample.points, so);
  graph = Proximity_graph();  // freed before the lines are merged
  r.status = r.skeleton.status;
  if (r.status == Status::interrupted) return r;
  // The skeleton's values used (a gap of infinity: none bridged, as with 0). A level width of 0: no complex,
  // the embedding and the branch merge did not run, and their options stay as given.
  if (r.skeleton.level_width > 0) {
    r.used.embedding.level_width = r.skeleton.level_width;
    r.used.embedding.max_gap = std::isinf(r.skeleton.max_gap) ? 0.0 : r.skeleton.max_gap;
    r.used.branch_merge_distance = r.skeleton.branch_merge_distance;
  }
  r.map = skeleton_to_road_map(r.skeleton.graph);
  if (*r.used.merge_distance > 0 && !r.map.positions.empty()) {
    Road_merge_options mo = road_map_merge_options(r.used);
    if (options.progress) mo.progress = [&options](double t) { return options.progress(0.9 + 0.1 * t); };
    try {
      r.merged = merge_road_lines(r.map, mo);
    } catch (const std::invalid_argument& e) {  // the stage's own options are not the caller's: say which
      FeatureRecon::internal::throw_invalid_argument(
          fn, "merge_distance ", mo.distance,
          " (the merge samples the lines every third of it) is refused by ", e.what());
    }
    if (r.merged.status == Status::interrupted) {
      r.status = Status::interrupted;
      r.map = {};
      return r;
    }
    r.map = std::move(r.merged.map);
    r.merged.map = {};
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return r;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_ROAD_MAP_H
