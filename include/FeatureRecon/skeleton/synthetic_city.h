// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SYNTHETIC_CITY_H
#define FEATURERECON_SKELETON_SYNTHETIC_CITY_H

// A synthetic city with known streets and simulated GPS trips on them: test and benchmark data for road-map
// construction where no other city's traces are at hand. The street network is a perturbed grid (rotated,
// jittered intersections, some streets missing, a diagonal avenue) or an organic network (random
// intersections joined by their Gabriel graph, some streets missing), its streets straight or bent; trips
// drive between two distinct random intersections on the right-hand side of the street, along the route that
// is shortest once each street's length is multiplied by a random factor in [1, 1.5) drawn per trip (so that
// trips between the same ends vary), and are recorded at a fixed interval with Gaussian noise and a per-trip
// bias. Deterministic for a seed on every platform
// (internal/random.h).

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/internal/random.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/map_comparison.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// How make_synthetic_city() lays out the intersections and streets.
enum class Synthetic_city_layout {
  grid,  ///< a columns x rows grid of blocks, jittered, with a diagonal avenue
  /// columns x rows random intersections in the grid's rectangle, at least 0.6 sqrt(block_width x
  /// block_height) apart (dart throwing; the spacing shrinks by 5 % whenever 1000 x columns x rows darts in a
  /// row miss, which only happens in a rectangle too small for them), joined by the streets of their Gabriel
  /// graph: junctions of any degree and angle, blocks of any shape
  organic
};

/// Options of make_synthetic_city(). Lengths in metres, times in seconds.
struct Synthetic_city_options {
  Synthetic_city_layout layout = Synthetic_city_layout::grid;  ///< default grid
  std::size_t columns = 8;                                     ///< intersections per row (>= 2); default 8
  std::size_t rows = 6;                                        ///< intersections per column (>= 2); default 6
  double block_width = 120;  ///< spacing of the intersections along a row; default 120
  double block_height = 90;  ///< spacing along a column; default 90
  /// of the whole grid, degrees counterclockwise (x towards y) about the coordinates' origin, where
  /// intersection (0, 0) lies before its jitter; default 0
  double rotation = 0;
  /// grid: each intersection moves uniformly within +-jitter in x and y; at most half the shorter block side
  /// (intersections keep their order), with the diagonal avenue at most w h / (2 (w + h)) of the block sides
  /// w and h (25.7 m for the default blocks: the avenue crosses no street); default 10
  double jitter = 10;
  double missing_streets = 0.1;  ///< fraction of streets removed, keeping the network connected; default 0.1
  bool diagonal = true;          ///< grid: a diagonal avenue through the intersections (i, i); default true
  /// Each street bends as a parabola whose middle lies up to curvature x its length (uniformly, either side)
  /// off the chord, drawn as a polyline with pieces of at most 10 m (at most 1000 pieces); 0 keeps streets
  /// straight. Bent streets may cross without a junction, like an overpass (the default organic city has 2
  /// such crossings at 0.15, about 20 at 0.3). In [0, 0.5]; default 0
  double curvature = 0;
  std::size_t trips = 300;  ///< default 300
  double speed = 10;        ///< mean driving speed (> 0); each trip drives at 0.7 to 1.3 times it; default 10
  /// time between fixes (> 0; the first one at a random phase); default 3.6
  double sampling_interval = 3.6;
  double noise = 4;      ///< standard deviation of the noise of each coordinate of a fix; default 4
  double trip_bias = 2;  ///< standard deviation of a constant offset per trip and coordinate; default 2
  /// vehicles drive this far right of the centre line, at most half the shorter block side; default 2
  double lane_offset = 2;
  std::uint64_t seed = 1;  ///< default 1
  /// Fraction done: the street layout counts for the first 5 % (the organic layout reports every 65536
  /// darts), then one report before each trip. Returning false stops: the trips made so far are kept,
  /// `driven` holds the streets they used, and the status is interrupted.
  Progress_callback progress;
};

/// Result of make_synthetic_city().
struct Synthetic_city {
  /// The street network (centre lines): the columns x rows intersections first (in the grid layout vertex
  /// j x columns + i is the grid's (i, j)), then the inner points of bent streets, each street's in order.
  Embedded_graph_2 streets;
  Embedded_graph_2 driven;          ///< the streets at least one trip used: the ground truth of a road map
  std::vector<Gps_trip> trips;      ///< the recorded fixes (trip k starts at time 10000 k)
  Status status = Status::success;  ///< interrupted when the progress callback stopped the run (fewer trips)
};

namespace internal {
/// Greedy deletion: for k = 0, 1, ..., edge order[k] is removed when the edges left without it still connect
/// the n vertices, until `count` are removed. Returns the removed flags by edge. O(m log m) instead of a
/// search per edge: the greedy deletion keeps, among the edges it looks at, exactly those that Kruskal's
/// algorithm picks when it adds them in the opposite order on top of the edges it never looks at
/// (reverse-delete = Kruskal). It looks at the first k* edges of the order, k* the first k with k - (c(k) -
/// 1) = count, where c(k) is the number of components of the edges order[k..m). A disconnected graph loses
/// nothing.
inline std::vector<char> remove_keeping_connected(std::size_t n, const std::vector<Edge>& edges,
                                                  const std::vector<std::size_t>& order, std::size_t count) {
  const std::size_t m = edges.size();
  std::vector<char> removed(m, 0);
  FeatureRecon::internal::Union_find<Vertex_index> sets(n);
  auto unite = [&](const Edge& e) { return sets.unite(e[0], e[1]); };  // true when e joined two components
  std::vector<std::size_t> components(m + 1, n);                       // c(k)
  for (std::size_t k = m; k-- > 0;) components[k] = components[k + 1] - (unite(edges[order[k]]) ? 1 : 0);
  if (components[0] != 1 || count == 0) return removed;
  std::size_t looked_at = m;
  for (std::size_t k = 1; k <= m; ++k)
    if (k + 1 - components[k] >= count) {  // c(k) - 1 <= k: no wrap-around
      looked_at = k;
      break;
    }
  sets.reset(n);
  for (std::size_t k = looked_at; k < m; ++k) unite(edges[order[k]]);
  for (std::size_t k = looked_at; k-- > 0;)
    if (!unite(edges[order[k]])) removed[order[k]] = 1;
  return removed;
}

/// The edges of the Gabriel graph of distinct points (pairs whose diametral disc holds no other point), from
/// their Delaunay triangulation with exact predicates; sorted, each as (smaller index, larger index). A point
/// on the boundary of a diametral disc removes the edge.
/// \throws std::invalid_argument naming two points that coincide.
inline std::vector<Edge> gabriel_edges(const std::vector<std::array<double, 2>>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Vertex_index, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  Dt dt;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t before = dt.number_of_vertices();
    const auto v = dt.insert(K::Point_2(points[i][0], points[i][1]));
    if (dt.number_of_vertices() == before)
      FeatureRecon::internal::throw_invalid_argument("gabriel_edges", "points ", v->info(), " and ", i,
                                                     " coincide");
    v->info() = static_cast<Vertex_index>(i);
  }
  std::vector<Edge> edges;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int i = e->second;
    const auto u = f->vertex(Dt::cw(i)), v = f->vertex(Dt::ccw(i));
    bool gabriel = true;  // collinear points (dimension 1): every Delaunay edge joins neighbours on the line
    if (dt.dimension() == 2)
      for (const auto& [face, index] :
           {std::pair{f, i}, std::pair{f->neighbor(i), f->neighbor(i)->index(f)}}) {
        const auto w = face->vertex(index);
        if (!dt.is_infinite(w) &&
            CGAL::side_of_bounded_circle(u->point(), v->point(), w->point()) != CGAL::ON_UNBOUNDED_SIDE)
          gabriel = false;
      }
    if (gabriel) edges.push_back({std::min(u->info(), v->info()), std::max(u->info(), v->info())});
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}
}  // namespace internal

/// The largest `jitter` make_synthetic_city() accepts for these blocks: half the shorter block side, with the
/// diagonal avenue block_width x block_height / (2 (block_width + block_height)) (grid layout; the organic
/// layout does not jitter: infinity). Smaller blocks than about 40 m (with the avenue) refuse the default 10;
/// a caller that did not choose a jitter can take min(jitter, this).
inline double synthetic_city_max_jitter(const Synthetic_city_options& o) {
  // An intersection that may move farther than half a block can pass its neighbour: streets would cross
  // without a junction. With the diagonal avenue, the corners (i + 1, i) and (i, i + 1) of a block lie w h /
  // sqrt(w^2 + h^2) from its diagonal, and a jitter J moves the corner and the diagonal towards each other by
  // up to 2 J (w + h) / sqrt(w^2 + h^2): below w h / (2 (w + h)) the avenue crosses no street.
  if (o.layout != Synthetic_city_layout::grid) return std::numeric_limits<double>::infinity();
  // w h / (2 (w + h)) as min(w, h) (max(w, h) / (2 (w + h))): w h underflowed for blocks of 1e-300.
  const double shorter = std::min(o.block_width, o.block_height),
               longer = std::max(o.block_width, o.block_height);
  return o.diagonal ? shorter * (longer / (2 * (o.block_width + o.block_height))) : shorter / 2;
}

/// The largest `lane_offset` make_synthetic_city() accepts: half the shorter block side (a lane farther off
/// its centre line would lie nearer the parallel street). Blocks under 4 m refuse the default 2.
inline double synthetic_city_max_lane_offset(const Synthetic_city_options& o) {
  return std::min(o.block_width, o.block_height) / 2;
}

/// Builds a synthetic city and its GPS trips (see the file comment).
/// \throws std::invalid_argument naming the option: fewer than 2 columns or rows, a non-positive or
///   non-finite block size, speed or sampling interval, a negative noise, bias, jitter or lane offset, a
///   jitter (grid layout) that lets streets cross (see `jitter`), a lane offset above half the shorter block
///   side, a missing fraction outside [0, 1], a curvature outside [0, 0.5], more than 2^24 intersections or
///   2^31 street vertices, coordinates beyond the largest double (of intersections, or of fixes with a huge
///   noise, bias or lane offset), more than 2^26 trips, or trips of more than 2^26 fixes in all.
inline Synthetic_city make_synthetic_city(const Synthetic_city_options& o = {}) {
  const char* fn = "make_synthetic_city";
  using FeatureRecon::internal::throw_invalid_argument;
  if (o.columns < 2 || o.rows < 2)
    throw_invalid_argument(fn, "columns and rows must be >= 2, got ", o.columns, " and ", o.rows);
  constexpr std::size_t max_intersections = std::size_t(1) << 24;
  if (o.columns > max_intersections / o.rows)
    throw_invalid_argument(fn, "columns x rows must be at most 2^24 intersections, got ", o.columns, " x ",
                           o.rows);
  auto positive = [&](double v, const char* name) {
    if (!(v > 0 && std::isfinite(v)))
      throw_invalid_argument(fn, name, " must be positive and finite, got ", v);
  };
  auto non_negative = [&](double v, const char* name) {
    if (!(v >= 0 && std::isfinite(v))) throw_invalid_argument(fn, name, " must be finite and >= 0, got ", v);
  };
  positive(o.block_width, "block_width");
  positive(o.block_height, "block_height");
  positive(o.speed, "speed");
  positive(o.sampling_interval, "sampling_interval");
  non_negative(o.noise, "noise");
  non_negative(o.trip_bias, "trip_bias");
  non_negative(o.jitter, "jitter");
  non_negative(o.lane_offset, "lane_offset");
  const double half_block = synthetic_city_max_lane_offset(o);
  const bool avenue = o.layout == Synthetic_city_layout::grid && o.diagonal;
  const double max_jitter = synthetic_city_max_jitter(o);
  if (o.jitter > max_jitter)
    throw_invalid_argument(
        fn, "jitter must be at most ", max_jitter,
        avenue ? " (block_width x block_height / (2 (block_width + block_height)), with the diagonal avenue)"
               : " (half the shorter of block_width and block_height)",
        ", got ", o.jitter, ": intersections would pass each other and streets cross");
  if (o.lane_offset > half_block)
    throw_invalid_argument(
        fn, "lane_offset must be at most half the shorter of block_width and block_height (", half_block,
        "), got ", o.lane_offset, ": the lanes would lie nearer the parallel streets");
  if (!std::isfinite(o.rotation)) throw_invalid_argument(fn, "rotation must be finite, got ", o.rotation);
  if (!(o.missing_streets >= 0 && o.missing_streets <= 1))
    throw_invalid_argument(fn, "missing_streets must be in [0, 1], got ", o.missing_streets);
  if (!(o.curvature >= 0 && o.curvature <= 0.5))
    throw_invalid_argument(fn, "curvature must be in [0, 0.5], got ", o.curvature);
  if (o.layout != Synthetic_city_layout::grid && o.layout != Synthetic_city_layout::organic)
    throw_invalid_argument(fn, "layout must be grid or organic");
  // Checked before any route is made: 10^8 trips took 31 s and 2.2 GB to reach the limit on fixes below.
  if (o.trips > (std::size_t(1) << 26))
    throw_invalid_argument(fn, "trips must be at most 2^26 (the most fixes the trips may record), got ",
                           o.trips);

  FeatureRecon::internal::Unit_random random(FeatureRecon::internal::splitmix64(o.seed));
  Synthetic_city city;
  const auto report = [&](double fraction) {
    return FeatureRecon::internal::report_progress(o.progress, fraction);
  };
  // A stop in the layout: no streets, no trips.
  const auto stopped_city = [] {
    Synthetic_city stopped;
    stopped.status = Status::interrupted;
    return stopped;
  };
  if (!report(0)) return stopped_city();
  const std::size_t nx = o.columns, ny = o.rows, n = nx * ny;
  // Degrees reduced to (-360, 360) first: 1e308 degrees times pi overflowed to a NaN rotation.
  const double a = std::fmod(o.rotation, 360.0) * 3.14159265358979323846 / 180, c = std::cos(a),
               s = std::sin(a);
  auto node = [nx](std::size_t i, std::size_t j) { return static_cast<Vertex_index>(j * nx + i); };
  std::vector<Edge> streets;
  // Every coordinate (rotated, with jitter) is at most |x| + |y| in size: the extents must fit a double, or
  // the organic layout's dart throwing would never place a point.
  if (!std::isfinite(double(nx - 1) * o.block_width + double(ny - 1) * o.block_height + 2 * o.jitter))
    throw_invalid_argument(fn, "the city of ", nx, " x ", ny, " blocks of ", o.block_width, " x ",
                           o.block_height, " (jitter ", o.jitter,
                           ") lies beyond the largest double: block_width or block_height too large");
  if (o.layout == Synthetic_city_layout::grid) {
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const double x = double(i) * o.block_width + o.jitter * (2 * random() - 1);
        const double y = double(j) * o.block_height + o.jitter * (2 * random() - 1);
        city.streets.positions.push_back({c * x - s * y, s * x + c * y});
      }
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        if (i + 1 < nx) streets.push_back({node(i, j), node(i + 1, j)});
        if (j + 1 < ny) streets.push_back({node(i, j), node(i, j + 1)});
      }
  } else {
    // Dart throwing in the grid's rectangle; after every 1000 n rejected darts the spacing shrinks by 5 %.
    const double w = double(nx - 1) * o.block_width, h = double(ny - 1) * o.block_height;
    double spacing = 0.6 * std::sqrt(o.block_width) * std::sqrt(o.block_height);
    std::vector<std::array<double, 2>> q;
    // Points bucketed on cells a little wider than the first spacing (the spacing only shrinks): a point
    // closer than the spacing lies in one of the 3 x 3 cells around a dart.
    const double cell = 1.001 * spacing;
    const auto columns = static_cast<std::size_t>(w / cell) + 1,
               rows = static_cast<std::size_t>(h / cell) + 1;
    std::vector<std::vector<std::uint32_t>> bucket(columns * rows);
    auto cell_of = [cell](double v, std::size_t size) {
      return std::min(size - 1, static_cast<std::size_t>(std::max(0.0, std::floor(v / cell))));
    };
    for (std::size_t rejected = 0, darts = 0; q.size() < n; ++darts) {
      if (darts % 65536 == 65535 && !report(0.05 * double(q.size()) / double(n))) return stopped_city();
      const std::array<double, 2> p{w * random(), h * random()};
      const std::size_t ci = cell_of(p[0], columns), cj = cell_of(p[1], rows);
      bool free = true;
      for (std::size_t j = cj == 0 ? 0 : cj - 1; free && j <= std::min(rows - 1, cj + 1); ++j)
        for (std::size_t i = ci == 0 ? 0 : ci - 1; free && i <= std::min(columns - 1, ci + 1); ++i)
          for (const std::uint32_t k : bucket[j * columns + i])
            if (!(std::hypot(p[0] - q[k][0], p[1] - q[k][1]) >= spacing)) {
              free = false;
              break;
            }
      if (free) {
        bucket[cj * columns + ci].push_back(static_cast<std::uint32_t>(q.size()));
        q.push_back(p);
      } else if (++rejected == 1000 * n) {
        spacing *= 0.95;
        rejected = 0;
      }
    }
    for (const auto& p : q) city.streets.positions.push_back({c * p[0] - s * p[1], s * p[0] + c * p[1]});
    streets = internal::gabriel_edges(city.streets.positions);
  }
  for (std::size_t i = 0; i < city.streets.positions.size(); ++i)
    if (!(std::isfinite(city.streets.positions[i][0]) && std::isfinite(city.streets.positions[i][1])))
      throw_invalid_argument(fn, "intersection ", i, " lies beyond the largest double: block_width (",
                             o.block_width, ") or block_height (", o.block_height, ") too large for ", nx,
                             " x ", ny, " blocks");
  // Remove streets in random order while the network stays connected.
  const std::size_t grid_streets = streets.size();
  std::vector<std::size_t> order(grid_streets);
  for (std::size_t k = 0; k < grid_streets; ++k) order[k] = k;
  for (std::size_t k = grid_streets; k > 1; --k)
    std::swap(order[k - 1], order[std::size_t(random() * double(k))]);
  const auto to_remove = static_cast<std::size_t>(std::floor(o.missing_streets * double(grid_streets)));
  const std::vector<char> removed = internal::remove_keeping_connected(n, streets, order, to_remove);
  for (std::size_t k = 0; k < grid_streets; ++k)
    if (!removed[k]) city.streets.edges.push_back(streets[k]);
  if (o.diagonal && o.layout == Synthetic_city_layout::grid)
    for (std::size_t i = 0; i + 1 < std::min(nx, ny); ++i)
      city.streets.edges.push_back({node(i, i), node(i + 1, i + 1)});
  // Street k runs along the polyline line[k] of vertices: its two intersections, and the inner points of a
  // bend.
  std::vector<std::vector<Vertex_index>> line;
  for (const Edge& e : city.streets.edges) line.push_back({e[0], e[1]});
  if (o.curvature > 0) {
    for (auto& l : line) {
      const auto p = city.streets.positions[l[0]], r = city.streets.positions[l[1]];
      const double L = std::hypot(r[0] - p[0], r[1] - p[1]);
      const double bend = o.curvature * L * (2 * random() - 1);  // the middle's distance off the chord
      const double cx = (p[0] + r[0]) / 2 + 2 * bend * (p[1] - r[1]) / L,
                   cy = (p[1] + r[1]) / 2 + 2 * bend * (r[0] - p[0]) / L;
      const auto pieces =
          static_cast<std::size_t>(std::min(1000.0, std::ceil(L * (1 + 4 * o.curvature) / 10)));
      if (city.streets.positions.size() + pieces > (std::size_t(1) << 31))
        throw_invalid_argument(fn, "the bent streets need more than 2^31 vertices: blocks too large");
      std::vector<Vertex_index> bent{l[0]};
      for (std::size_t i = 1; i < pieces; ++i) {
        const double t = double(i) / double(pieces), u = 1 - t;
        bent.push_back(static_cast<Vertex_index>(city.streets.positions.size()));
        city.streets.positions.push_back(
            {u * u * p[0] + 2 * u * t * cx + t * t * r[0], u * u * p[1] + 2 * u * t * cy + t * t * r[1]});
      }
      bent.push_back(l[1]);
      l = std::move(bent);
    }
    city.streets.edges.clear();
    for (const auto& l : line)
      for (std::size_t i = 0; i + 1 < l.size(); ++i) city.streets.edges.push_back({l[i], l[i + 1]});
  }

  // Trips: shortest routes (lengths times a random factor in [1, 1.5) per trip and street) between two random
  // intersections, driven on the right at a constant speed, recorded with noise.
  const auto& P = city.streets.positions;
  const std::size_t m = line.size();
  std::vector<std::vector<std::pair<Vertex_index, std::size_t>>> adj(n);
  for (std::size_t k = 0; k < m; ++k) {
    adj[line[k].front()].push_back({line[k].back(), k});
    adj[line[k].back()].push_back({line[k].front(), k});
  }
  std::vector<double> street_length(m, 0.0);
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t i = 0; i + 1 < line[k].size(); ++i)
      street_length[k] +=
          std::hypot(P[line[k][i + 1]][0] - P[line[k][i]][0], P[line[k][i + 1]][1] - P[line[k][i]][1]);
  auto length = [&](std::size_t k) { return street_length[k]; };
  std::vector<char> used(m, 0);
  const double max_fixes = double(std::size_t(1) << 26);
  double planned_fixes = 0;
  for (std::size_t t = 0; t < o.trips; ++t) {
    if (!report(0.05 + 0.95 * double(t) / double(o.trips))) {
      city.status = Status::interrupted;
      break;
    }
    std::vector<double> factor(m);
    for (double& f : factor) f = 1 + 0.5 * random();
    const auto from = static_cast<Vertex_index>(random() * double(n));
    auto to = static_cast<Vertex_index>(random() * double(n - 1));
    if (to >= from) ++to;
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> via(n, m);
    using Item = std::pair<double, Vertex_index>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    dist[from] = 0;
    queue.push({0.0, from});
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > dist[v]) continue;
      for (const auto& [w, k] : adj[v])
        if (d + length(k) * factor[k] < dist[w]) {
          dist[w] = d + length(k) * factor[k];
          via[w] = k;
          queue.push({dist[w], w});
        }
    }
    // The route's polyline, from `to` back to `from`, then reversed.
    std::vector<Vertex_index> route{to};
    for (Vertex_index v = to; v != from;) {
      const std::size_t k = via[v];
      used[k] = 1;
      if (line[k].back() == v)
        route.insert(route.end(), line[k].rbegin() + 1, line[k].rend());
      else
        route.insert(route.end(), line[k].begin() + 1, line[k].end());
      v = route.back();
    }
    std::reverse(route.begin(), route.end());
    const double speed = o.speed * (0.7 + 0.6 * random());
    // The fixes are counted before they are made: a tiny interval or speed must be refused, not fill the
    // memory (or loop: along += interval x speed stops moving when the step is below along's precision).
    double route_length = 0;
    for (std::size_t r = 0; r + 1 < route.size(); ++r)
      route_length += std::hypot(P[route[r + 1]][0] - P[route[r]][0], P[route[r + 1]][1] - P[route[r]][1]);
    const double step = o.sampling_interval * speed;
    planned_fixes += route_length / step + 1;
    if (!(planned_fixes <= max_fixes) || !(route_length + step > route_length))
      throw_invalid_argument(
          fn, "the trips would record more than 2^26 fixes (trip ", t, " alone: ", route_length / step,
          " at ", step, " m apart, along a route of ", route_length, " m): raise speed (", o.speed,
          ") or sampling_interval (", o.sampling_interval, "), or lower trips (", o.trips, "), block_width (",
          o.block_width, "), block_height (", o.block_height, ") or jitter (", o.jitter, ")");
    const double bias_x = o.trip_bias * random.normal(), bias_y = o.trip_bias * random.normal();
    double along = o.sampling_interval * random() * speed;  // arc length of the next fix
    double start = 0;                                       // arc length at the current segment's start
    Gps_trip trip;
    for (std::size_t r = 0; r + 1 < route.size(); ++r) {
      const auto& p = P[route[r]];
      const auto& q = P[route[r + 1]];
      const double L = std::hypot(q[0] - p[0], q[1] - p[1]);
      const double ux = (q[0] - p[0]) / L, uy = (q[1] - p[1]) / L;
      for (; along < start + L; along += o.sampling_interval * speed) {
        const double u = along - start;
        const double x = p[0] + u * ux + o.lane_offset * uy + bias_x + o.noise * random.normal();
        const double y = p[1] + u * uy - o.lane_offset * ux + bias_y + o.noise * random.normal();
        if (!std::isfinite(x) || !std::isfinite(y))  // a noise of 1e308 wrote inf into the tracks
          throw_invalid_argument(fn, "fix ", trip.size(), " of trip ", t,
                                 " lies beyond the largest double: noise (", o.noise, "), trip_bias (",
                                 o.trip_bias, ") or lane_offset (", o.lane_offset, ") too large");
        trip.push_back({x, y, 10000.0 * double(t) + along / speed});
      }
      start += L;
    }
    city.trips.push_back(std::move(trip));
  }
  city.driven.positions = P;
  for (std::size_t k = 0; k < m; ++k)
    if (used[k])
      for (std::size_t i = 0; i + 1 < line[k].size(); ++i)
        city.driven.edges.push_back({line[k][i], line[k][i + 1]});
  if (city.status == Status::success) (void)report(1);
  return city;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SYNTHETIC_CITY_H
