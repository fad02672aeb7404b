// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_MAP_COMPARISON_H
#define FEATURERECON_SKELETON_MAP_COMPARISON_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/gps_traces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// A graph embedded in the plane (a road map): vertex positions and undirected edges.
struct Embedded_graph_2 {
  std::vector<std::array<double, 2>> positions;  ///< vertex coordinates (metres)
  std::vector<Edge> edges;                       ///< undirected; repeated and reversed pairs are merged
};

/// How compare_maps() pairs the samples of the two maps.
enum class Map_matching {
  /// Pairs accepted by increasing distance, each ground-truth sample taking the nearest available admissible
  /// one among its `candidates` nearest reconstruction samples (the GraphSamplingToolkit's matching; the
  /// default)
  greedy,
  /// A maximum-weight bipartite matching over every admissible pair, weight = match_distance - distance
  /// (exact up to rounding; deterministic). It matches at least as much weight as the greedy one; on the
  /// Chicago maps 0.1-0.7 % more samples
  optimal
};

/// Options of compare_maps() (the graph-sampling metric of Biagioni and Eriksson, global variant).
struct Map_comparison_options {
  /// Samples match when at most this far apart (m); default 15. Within [2^-450, 2^450] (about 3e-136 to
  /// 3e135): squares of distances near it stay normal doubles
  double match_distance = 15.0;
  double interval = 5.0;  ///< distance between samples along edges (m; finite and > 0); default 5
  /// Samples match when their direction-insensitive bearings (differences in [0, 90]) differ by less
  /// (degrees, > 0; above 90: bearings are ignored); default 45
  double bearing_limit = 45.0;
  /// Nearest reconstruction samples the greedy matching considers per ground-truth sample; default 10 (the
  /// optimal matching considers every admissible pair)
  std::size_t candidates = 10;
  Map_matching matching = Map_matching::greedy;  ///< how samples are paired; default greedy
  bool keep_samples = false;  ///< also return both sample sets with their match flags (for diagnosis)
  /// Called with the fraction done (compare_maps(): both maps sampled at 0.1, then the matching); returning
  /// false stops: status interrupted, no pair (matched 0, scores 0, every partner -1; the sample counts and,
  /// with keep_samples, the sample lists stay).
  Progress_callback progress;
};

/// A sample of a map: position and the bearing of its edge in [0, 360) degrees.
struct Map_sample {
  std::array<double, 2> position;  ///< metres
  double bearing;                  ///< degrees in [0, 360)
};

/// Result of compare_maps().
struct Map_comparison_result {
  std::size_t ground_truth_samples = 0;    ///< |H|
  std::size_t reconstruction_samples = 0;  ///< |G|
  std::size_t matched = 0;                 ///< m
  double precision = 0;                    ///< m / |G| (0 when G is empty)
  double recall = 0;                       ///< m / |H| (0 when H is empty)
  double f_score = 0;                      ///< 2m / (|G| + |H|)
  /// With Map_comparison_options::keep_samples: the ground-truth samples H (sample_map() order), else empty.
  std::vector<Map_sample> ground_truth_sample_list;
  /// With keep_samples: the reconstruction samples G, else empty.
  std::vector<Map_sample> reconstruction_sample_list;
  /// With keep_samples: for each sample of H, the index in G of its partner, or -1 when unmatched.
  std::vector<std::int64_t> ground_truth_partner;
  /// With keep_samples: for each sample of G, the index in H of its partner, or -1 when unmatched.
  std::vector<std::int64_t> reconstruction_partner;
  Status status = Status::success;  ///< interrupted when the progress callback returned false (no pair)
};

namespace internal {
inline double bearing_of(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  const double deg = std::atan2(b[0] - a[0], b[1] - a[1]) * 180.0 / std::acos(-1.0);  // from north, clockwise
  // A hair west of north: deg + 360 rounds to 360, outside [0, 360); the largest double below it instead.
  return deg < 0 ? std::min(deg + 360.0, std::nextafter(360.0, 0.0)) : deg;
}
/// The range of distances a metric accepts: their squares stay normal doubles.
constexpr double min_metric_distance = 0x1p-450, max_metric_distance = 0x1p450;
/// Direction-insensitive bearing difference in [0, 90].
inline double bearing_difference(double a, double b) {
  const double d = std::abs(a - b);
  return std::min({d, std::abs(180.0 - d), std::abs(360.0 - d)});
}
}  // namespace internal

/// Samples a map every `interval` metres: per connected component, a breadth-first walk over the edges from
/// a root at half the component's cumulative edge length (edges in breadth-first order from the component's
/// smallest vertex), the leftover offset carried across vertices. Each sample keeps its edge's bearing. Edges
/// of length 0 (distinct vertices at one position) have no bearing and give no sample; the walk passes them.
/// \pre interval > 0 and finite (checked; throws); edge indices in range (checked; throws naming the edge).
inline std::vector<Map_sample> sample_map(const Embedded_graph_2& g, double interval) {
  const char* fn = "sample_map";
  if (!(interval > 0 && std::isfinite(interval)))
    FeatureRecon::internal::throw_invalid_argument(fn, "interval must be finite and > 0, got ", interval);
  const std::size_t n = g.positions.size();
  std::vector<Edge> edges;
  for (std::size_t k = 0; k < g.edges.size(); ++k) {
    Edge e = g.edges[k];
    if (e[0] >= n || e[1] >= n)
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", k, " has a vertex out of range [0, ", n,
                                                     ")");
    for (const Vertex_index v : e)
      if (!std::isfinite(g.positions[v][0]) || !std::isfinite(g.positions[v][1]))
        FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " (of edge ", k,
                                                       ") has a non-finite coordinate");
    if (e[0] == e[1]) continue;
    if (e[0] > e[1]) std::swap(e[0], e[1]);
    edges.push_back(e);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  auto length = [&](std::size_t e) {
    const auto& a = g.positions[edges[e][0]];
    const auto& b = g.positions[edges[e][1]];
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  std::vector<std::vector<std::size_t>> incident(n);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    incident[edges[e][0]].push_back(e);
    incident[edges[e][1]].push_back(e);
  }
  // Finite coordinates can still be too far apart for the interval (t += interval would stop moving), and a
  // tiny interval would fill the memory: 2^25 samples a map (a 167,000 km network at 5 m) take about 5 GB to
  // compare (75 bytes a sample).
  double total = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) total += length(e);
  if (!(total / interval < 33554432.0))
    FeatureRecon::internal::throw_invalid_argument(fn, "the map's ", total, " m of edges at interval ",
                                                   interval, " would give more than 2^25 samples");
  std::vector<Map_sample> samples;
  // `listed` marks edges put in a component's order; an edge belongs to one component, so one array serves
  // all.
  std::vector<char> edge_done(edges.size(), 0), vertex_seen(n, 0), listed(edges.size(), 0);
  // A walk step: traverse edge e from vertex `from`, first sample at `offset` metres along it.
  struct Step {
    std::size_t edge;
    Vertex_index from;
    double offset;
  };
  auto walk = [&](const Step& s, std::deque<Step>& queue) {
    const Edge& ed = edges[s.edge];
    const Vertex_index to = ed[0] == s.from ? ed[1] : ed[0];
    const auto& a = g.positions[s.from];
    const auto& b = g.positions[to];
    const double len = length(s.edge), bearing = internal::bearing_of(a, b);
    double t = s.offset;
    for (; len > 0 && t <= len;
         t += interval) {  // an edge of length 0 has no bearing: no sample, offset kept
      const double u = len > 0 ? t / len : 0.0;
      samples.push_back({{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])}, bearing});
    }
    const double carry = t - len;  // leftover to the next sample, carried across the vertex
    for (const std::size_t f : incident[to])
      if (!edge_done[f]) {
        edge_done[f] = 1;
        queue.push_back({f, to, carry});
      }
  };
  for (Vertex_index start = 0; start < n; ++start) {
    if (vertex_seen[start] || incident[start].empty()) continue;
    // The component's edges in breadth-first order from its smallest vertex.
    std::vector<std::size_t> order;
    std::deque<Vertex_index> bfs{start};
    vertex_seen[start] = 1;
    while (!bfs.empty()) {
      const Vertex_index v = bfs.front();
      bfs.pop_front();
      for (const std::size_t e : incident[v]) {
        if (!listed[e]) {
          listed[e] = 1;
          order.push_back(e);
        }
        const Vertex_index w = edges[e][0] == v ? edges[e][1] : edges[e][0];
        if (!vertex_seen[w]) {
          vertex_seen[w] = 1;
          bfs.push_back(w);
        }
      }
    }
    double total = 0;
    for (const std::size_t e : order) total += length(e);
    if (!(total > 0)) continue;  // every edge of length 0: nothing to sample, no bearing
    // Root: the point at half the cumulative length; walk both ways from it.
    double acc = 0;
    std::size_t root_edge = order.front();
    double root_t = 0;
    for (const std::size_t e : order) {
      if (acc + length(e) >= total / 2) {
        root_edge = e;
        root_t = total / 2 - acc;
        break;
      }
      acc += length(e);
    }
    edge_done[root_edge] = 1;
    const Edge& re = edges[root_edge];
    const double len = length(root_edge);
    std::deque<Step> queue;
    // Two half-edges from the root: towards e[1] starting at the root, towards e[0] one interval back.
    {
      const auto& a = g.positions[re[0]];
      const auto& b = g.positions[re[1]];
      const double bearing = internal::bearing_of(a, b);
      double t = root_t;
      for (; t <= len; t += interval) {
        const double u = len > 0 ? t / len : 0.0;
        samples.push_back({{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])}, bearing});
      }
      const double carry_forward = t - len;
      double s = root_t - interval;
      for (; s >= 0; s -= interval) {
        const double u = len > 0 ? s / len : 0.0;
        samples.push_back({{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])}, bearing});
      }
      const double carry_backward = -s;
      for (const std::size_t f : incident[re[1]])
        if (!edge_done[f]) {
          edge_done[f] = 1;
          queue.push_back({f, re[1], carry_forward});
        }
      for (const std::size_t f : incident[re[0]])
        if (!edge_done[f]) {
          edge_done[f] = 1;
          queue.push_back({f, re[0], carry_backward});
        }
    }
    while (!queue.empty()) {
      const Step s = queue.front();
      queue.pop_front();
      walk(s, queue);
    }
  }
  return samples;
}

/// A matching of two sample sets (match_map_samples()).
struct Map_sample_matching {
  std::size_t matched = 0;  ///< number of pairs
  /// For each ground-truth sample, the index of its partner among the reconstruction samples, or -1.
  std::vector<std::int64_t> ground_truth_partner;
  /// For each reconstruction sample, the index of its partner among the ground-truth samples, or -1.
  std::vector<std::int64_t> reconstruction_partner;
  Status status = Status::success;  ///< interrupted when the progress callback returned false (no pair)
};

namespace internal {
/// \cond
inline void check_map_comparison_options(const Map_comparison_options& options, const char* fn) {
  if (!(options.match_distance >= min_metric_distance && options.match_distance <= max_metric_distance))
    FeatureRecon::internal::throw_invalid_argument(
        fn,
        "match_distance must be within [2^-450, 2^450] (positive and "
        "finite; squares of distances near it stay normal), got ",
        options.match_distance);
  if (!(options.bearing_limit > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "bearing_limit must be > 0, got ",
                                                   options.bearing_limit);
  if (options.candidates < 1)
    FeatureRecon::internal::throw_invalid_argument(fn, "candidates must be >= 1, got 0");
  if (options.matching != Map_matching::greedy && options.matching != Map_matching::optimal)
    FeatureRecon::internal::throw_invalid_argument(fn, "matching must be greedy or optimal, got ",
                                                   static_cast<int>(options.matching));
}

/// A matching of no pair (every partner -1) of h ground-truth and g reconstruction samples.
inline Map_sample_matching no_pairs(std::size_t h, std::size_t g, Status status = Status::success) {
  Map_sample_matching M;
  M.ground_truth_partner.assign(h, -1);
  M.reconstruction_partner.assign(g, -1);
  M.status = status;
  return M;
}

inline void pair_samples(Map_sample_matching& M, std::size_t h, std::size_t g) {
  M.ground_truth_partner[h] = static_cast<std::int64_t>(g);
  M.reconstruction_partner[g] = static_cast<std::int64_t>(h);
  ++M.matched;
}

/// Greedy: each ground-truth sample h proposes the nearest admissible available sample among its `candidates`
/// nearest; proposals are accepted by increasing distance (ties: smaller h), a sample whose partner was taken
/// proposing again.
/// Returns false when the progress callback stopped it (M then holds the pairs made so far).
inline bool match_greedy(const std::vector<Map_sample>& H, const std::vector<Map_sample>& G,
                         const Map_comparison_options& options, Map_sample_matching& M) {
  const std::size_t stride = 4096;  // samples between two progress reports
  using K = CGAL::Simple_cartesian<double>;
  using Point = K::Point_2;
  using Traits = CGAL::Search_traits_adapter<std::uint32_t, CGAL::Pointer_property_map<Point>::type,
                                             CGAL::Search_traits_2<K>>;
  using Knn = CGAL::Orthogonal_k_neighbor_search<Traits>;
  // The tree holds the positions times a power of two that brings the largest to about 2^30 (exact), so that
  // squared distances of maps drawn at 1e-200 or 1e160 neither underflow nor overflow; distances are then
  // taken from the positions themselves.
  double largest = 0;
  for (const auto* set : {&H, &G})
    for (const Map_sample& s : *set)
      largest = std::max({largest, std::abs(s.position[0]), std::abs(s.position[1])});
  const double unit = largest > 0 ? std::ldexp(1.0, std::clamp(30 - std::ilogb(largest), -1000, 1000)) : 1.0;
  std::vector<Point> gp;
  for (const Map_sample& s : G) gp.emplace_back(s.position[0] * unit, s.position[1] * unit);
  std::vector<std::uint32_t> keys(G.size());
  std::iota(keys.begin(), keys.end(), 0u);
  typename Knn::Tree tree(keys.begin(), keys.end(), typename Knn::Tree::Splitter(),
                          Traits(CGAL::make_property_map(gp)));
  tree.build();
  typename Knn::Distance dist(tree.traits().point_property_map());
  std::vector<char> taken(G.size(), 0);
  // Nearest admissible (bearing) available partner among the k nearest, or none.
  auto best_partner = [&](std::size_t h, double& d) -> std::int64_t {
    const Point q(H[h].position[0] * unit, H[h].position[1] * unit);
    // At most |G| neighbours exist (and more than 2^32 - 1 would wrap to 0 in the cast).
    const std::size_t k = std::min<std::size_t>(options.candidates, G.size());
    Knn search(tree, q, static_cast<unsigned>(std::min<std::size_t>(k, 0xffffffffu)), 0.0, true, dist);
    for (const auto& nb : search) {
      const std::uint32_t g = nb.first;
      if (taken[g]) continue;
      if (bearing_difference(H[h].bearing, G[g].bearing) < options.bearing_limit) {
        d = std::hypot(G[g].position[0] - H[h].position[0], G[g].position[1] - H[h].position[1]);
        return g;
      }
    }
    return -1;
  };
  struct Candidate {
    double distance;
    std::size_t h;
    std::int64_t g;
  };
  auto later = [](const Candidate& a, const Candidate& b) {
    return a.distance > b.distance || (a.distance == b.distance && a.h > b.h);
  };
  std::vector<Candidate> heap;
  for (std::size_t h = 0; h < H.size(); ++h) {
    if (h % stride == stride - 1 &&
        !FeatureRecon::internal::report_progress(
            options.progress, 0.8 * static_cast<double>(h) / static_cast<double>(H.size())))
      return false;
    double d = 0;
    const std::int64_t g = best_partner(h, d);
    if (g >= 0) heap.push_back({d, h, g});
  }
  std::make_heap(heap.begin(), heap.end(), later);
  // The fraction is the share of the first proposals settled (paired or given up); searches again do not
  // count.
  const double proposals = static_cast<double>(std::max<std::size_t>(heap.size(), 1));
  std::size_t settled = 0;
  for (std::size_t pops = 1; !heap.empty(); ++pops) {
    if (pops % stride == 0 &&
        !FeatureRecon::internal::report_progress(
            options.progress, 0.8 + 0.19 * std::min(1.0, static_cast<double>(settled) / proposals)))
      return false;
    std::pop_heap(heap.begin(), heap.end(), later);
    Candidate c = heap.back();
    heap.pop_back();
    if (c.distance > options.match_distance) break;
    if (!taken[c.g]) {
      taken[c.g] = 1;
      pair_samples(M, c.h, static_cast<std::size_t>(c.g));
      ++settled;
      continue;
    }
    double d = 0;
    const std::int64_t g = best_partner(c.h, d);
    if (g >= 0) {
      heap.push_back({d, c.h, g});
      std::push_heap(heap.begin(), heap.end(), later);
    } else {
      ++settled;
    }
  }
  return true;
}

/// The cell of a grid whose 3 x 3 candidates must hold every point within `distance` (exactly that far
/// included): a hair wider, since the rounding of (p - low) / cell put two points exactly `distance` apart
/// two cells apart, and which pairs at the limit were seen depended on the grid's corner (one sample 1 km
/// away changed the optimal matching). Up to 2^20 cells per axis (the grid's dense range) the rounding stays
/// far below the 2^-20 margin.
inline double search_cell(double distance) { return distance * (1 + 0x1p-20); }

/// Whether a and b may pair: at most match_distance apart (the box test first: hypot only for those within
/// it) and bearings within the limit.
inline bool admissible_pair(const Map_sample& a, const Map_sample& b, const Map_comparison_options& options) {
  const double dx = b.position[0] - a.position[0], dy = b.position[1] - a.position[1];
  const double T = options.match_distance;
  return std::fabs(dx) <= T && std::fabs(dy) <= T && std::hypot(dx, dy) <= T &&
         bearing_difference(a.bearing, b.bearing) < options.bearing_limit;
}

[[noreturn]] inline void throw_too_many_pairs(const char* fn, std::size_t max_pairs, double T) {
  FeatureRecon::internal::throw_invalid_argument(fn, "more than ", max_pairs, " sample pairs lie within ",
                                                 "match_distance (", T, " m) of each other (maps stacked on ",
                                                 "themselves?): too many for the optimal matching; use the "
                                                 "greedy one");
}

/// The admissible pairs of each sample of L with samples of R, as lists (CSR: first, partner, cost).
struct Admissible_pairs {
  std::vector<std::size_t> first{0};
  std::vector<std::uint32_t> partner;
  std::vector<double> cost;
};

/// Optimal: a maximum-weight matching, weight T - d over the admissible pairs (distance d <= T =
/// match_distance, bearings within the limit). L (`nl` samples, their admissible pairs in P as lists; R has
/// `nr`) is the side that is assigned: every sample of L also gets a private "unmatched" partner of cost T,
/// so that minimising the total cost (d for a pair, T for an unmatched sample) is maximising the weight; this
/// assignment problem is solved by successive shortest augmenting paths (Dijkstra on reduced costs with
/// vertex potentials, one sample of L at a time, stopping at the first free sample reached). A search only
/// visits what lies closer than its augmenting path: the samples around the new one on the few lines near it.
/// At equal distance a free sample is settled first (a dense cluster of equal distances ends its search
/// there), then a matched one, then an "unmatched" partner (a tie between pairing and leaving unmatched goes
/// to pairing), smaller indices first. Returns for each sample of L the index of its partner in R or `none`.
/// Stopped by the progress callback: `stopped` set, the assignment partial. `searched` (if not null) counts
/// the matched samples of R that the searches settle (for tests).
inline std::vector<std::size_t> assign_optimally(std::size_t nl, std::size_t nr, const Admissible_pairs& P,
                                                 const Map_comparison_options& options, bool& stopped,
                                                 std::size_t* searched = nullptr) {
  const double T = options.match_distance;
  const std::vector<std::size_t>& first = P.first;
  const std::vector<std::uint32_t>& partner = P.partner;
  const std::vector<double>& cost = P.cost;
  const std::size_t stride = 1024;  // samples between two progress reports
  auto stop_at = [&](std::size_t i, double from, double to) {
    return i % stride == stride - 1 &&
           (stopped = !FeatureRecon::internal::report_progress(
                options.progress, from + (to - from) * static_cast<double>(i) / static_cast<double>(nl)));
  };
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<double> pot_l(nl, 0), pot_r(nr, 0), dist_r(nr, 0), dist_l(nl, 0);
  std::vector<std::size_t> mate_l(nl, none), mate_r(nr, none), from_r(nr, none), stamp_r(nr, 0);
  std::vector<char> done_r(nr, 0);
  std::vector<std::size_t> reached_l, settled_r;
  // Heap of (distance, class, node): node < nr a sample of R (class 0 free, 1 matched), nr + x the
  // "unmatched" partner of x (class 2).
  using Entry = std::tuple<double, int, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (std::size_t s = 0; s < nl; ++s) {
    if (stop_at(s, 0.1, 1.0)) return mate_l;
    if (first[s] == first[s + 1]) continue;  // no admissible partner: unmatched
    const std::size_t phase = s + 1;
    reached_l.assign(1, s);
    settled_r.clear();
    dist_l[s] = 0;
    heap = {};
    // Reduced cost of the arc x -> g: cost + pot_l[x] - pot_r[g] >= 0 (up to rounding: clamped).
    auto relax = [&](std::size_t x, double d) {
      for (std::size_t k = first[x]; k < first[x + 1]; ++k) {
        const std::size_t g = partner[k];
        if (g == mate_l[x] || (stamp_r[g] == phase && done_r[g])) continue;
        const double nd = std::max(d, d + cost[k] + pot_l[x] - pot_r[g]);
        if (stamp_r[g] != phase || nd < dist_r[g]) {
          stamp_r[g] = phase;
          done_r[g] = 0;
          dist_r[g] = nd;
          from_r[g] = x;
          heap.push({nd, mate_r[g] == none ? 0 : 1, g});
        }
      }
      heap.push({std::max(d, d + T + pot_l[x]), 2, nr + x});  // its "unmatched" partner, potential 0
    };
    relax(s, 0);
    std::size_t end = none;
    double D = 0;
    while (!heap.empty()) {
      const auto [d, type, node] = heap.top();
      heap.pop();
      if (type == 2) {  // x gives up its partner and stays unmatched
        end = node;
        D = d;
        break;
      }
      if (done_r[node] || d != dist_r[node]) continue;  // a stale entry
      done_r[node] = 1;
      if (type == 0) {
        end = node;
        D = d;
        break;
      }
      settled_r.push_back(node);
      if (searched) ++*searched;
      const std::size_t x = mate_r[node];
      dist_l[x] = d;
      reached_l.push_back(x);
      relax(x, d);
    }
    FEATURERECON_assertion(end != none);  // the "unmatched" partner of s is always reachable
    // Potentials: every node settled closer than D moves by its distance minus D; reduced costs stay >= 0 and
    // are 0 along the augmenting path.
    for (const std::size_t x : reached_l) pot_l[x] -= D - dist_l[x];
    for (const std::size_t g : settled_r) pot_r[g] -= D - dist_r[g];
    // Augment: flip the path back to s.
    std::size_t x = end >= nr ? end - nr : from_r[end];
    std::size_t g = end >= nr ? none : end;
    while (true) {
      const std::size_t previous = mate_l[x];
      mate_l[x] = g;
      if (g != none) mate_r[g] = x;
      if (x == s) break;
      g = previous;
      x = from_r[g];
    }
  }
  return mate_l;
}

/// The optimal matching of H and G, one connected component of the admissible pairs at a time (pairs of
/// different components do not interact): in each the smaller side is assigned (assign_optimally(); ties:
/// the ground truth), so that the samples left over search only while the other side still has free samples
/// near them. With the larger side assigned, each surplus sample of a dense cluster would search all of it;
/// choosing the side by the whole maps did that wherever a map was larger overall but smaller there (a street
/// drawn 300 times against 600: 40 s). Returns false when the progress callback stopped it (M then holds no
/// pair). `searched`: see assign_optimally(). More than `max_pairs` admissible pairs are refused (memory).
inline bool match_optimal(const std::vector<Map_sample>& H, const std::vector<Map_sample>& G,
                          const Map_comparison_options& options, Map_sample_matching& M, const char* fn,
                          std::size_t max_pairs = std::size_t(1) << 26, std::size_t* searched = nullptr) {
  const std::size_t nh = H.size(), ng = G.size();
  const double T = options.match_distance;
  // Components: union-find over the admissible pairs (ground-truth samples 0..nh-1, then reconstruction
  // ones).
  FeatureRecon::internal::Union_find<std::size_t> sets(nh + ng);
  std::vector<char> paired(nh, 0);  // a ground-truth sample with an admissible pair
  // The admissible pairs, enumerated once (by ground-truth sample; each component's lists are cut from them).
  Admissible_pairs all;
  all.first.assign(nh + 1, 0);
  {
    std::vector<std::array<double, 2>> gp(ng);
    for (std::size_t g = 0; g < ng; ++g) gp[g] = G[g].position;
    const FeatureRecon::internal::Uniform_grid<2> grid(gp, search_cell(T));
    for (std::size_t h = 0; h < nh; ++h) {
      if (h % 4096 == 4095 &&
          !FeatureRecon::internal::report_progress(options.progress, 0.05 * static_cast<double>(h) / nh))
        return false;
      grid.for_each_candidate(H[h].position, [&](std::uint32_t g) {
        if (admissible_pair(H[h], G[g], options)) {
          all.partner.push_back(g);
          all.cost.push_back(
              std::hypot(G[g].position[0] - H[h].position[0], G[g].position[1] - H[h].position[1]));
          paired[h] = 1;
          sets.unite(h, nh + g);
        }
      });
      if (all.partner.size() > max_pairs) throw_too_many_pairs(fn, max_pairs, T);
      all.first[h + 1] = all.partner.size();
    }
  }
  // Members of each component with a pair, in index order (components by their smallest ground-truth sample).
  std::vector<std::size_t> slot(nh + ng, std::numeric_limits<std::size_t>::max());
  std::vector<std::vector<std::size_t>> members_h, members_g;
  for (std::size_t x = 0; x < nh + ng; ++x) {
    const std::size_t r = sets.find(x);
    if (x < nh ? !paired[x] : r == x)
      continue;  // no pair (a ground-truth sample is the root of its component)
    if (slot[r] == std::numeric_limits<std::size_t>::max()) {
      slot[r] = members_h.size();
      members_h.emplace_back();
      members_g.emplace_back();
    }
    (x < nh ? members_h[slot[r]] : members_g[slot[r]]).push_back(x < nh ? x : x - nh);
  }
  std::size_t done = 0, in_components = 0;  // samples of the components (assigned so far), for the progress
  for (std::size_t c = 0; c < members_h.size(); ++c)
    in_components += members_h[c].size() + members_g[c].size();
  const double total = static_cast<double>(std::max<std::size_t>(in_components, 1));
  bool stopped = false;
  // Each sample's position in its component's member list.
  std::vector<std::uint32_t> local(nh + ng, 0);
  for (std::size_t c = 0; c < members_h.size(); ++c) {
    for (std::size_t i = 0; i < members_h[c].size(); ++i)
      local[members_h[c][i]] = static_cast<std::uint32_t>(i);
    for (std::size_t j = 0; j < members_g[c].size(); ++j)
      local[nh + members_g[c][j]] = static_cast<std::uint32_t>(j);
  }
  Admissible_pairs sub_pairs;
  for (std::size_t c = 0; c < members_h.size() && !stopped; ++c) {
    const std::vector<std::size_t>& mh = members_h[c];
    const std::vector<std::size_t>& mg = members_g[c];
    const std::size_t size = mh.size() + mg.size();
    const double from = 0.05 + 0.95 * static_cast<double>(done) / total;
    if (c % 256 == 255 && !FeatureRecon::internal::report_progress(options.progress, from)) return false;
    Map_comparison_options sub = options;
    if (options.progress) {
      const double share = 0.95 * static_cast<double>(size) / total;
      sub.progress = [&options, from, share](double f) { return options.progress(from + share * f); };
    }
    // The component's pairs, by its ground-truth samples or (the smaller side assigned) by its reconstruction
    // ones. The order within a list does not matter: the searches pop by (distance, class, index).
    const bool swap = mg.size() < mh.size();
    const std::size_t nl = swap ? mg.size() : mh.size();
    sub_pairs.first.assign(nl + 1, 0);
    sub_pairs.partner.clear();
    sub_pairs.cost.clear();
    if (!swap) {
      for (std::size_t i = 0; i < mh.size(); ++i) {
        for (std::size_t k = all.first[mh[i]]; k < all.first[mh[i] + 1]; ++k) {
          sub_pairs.partner.push_back(local[nh + all.partner[k]]);
          sub_pairs.cost.push_back(all.cost[k]);
        }
        sub_pairs.first[i + 1] = sub_pairs.partner.size();
      }
    } else {  // transposed: count, then fill
      for (const std::size_t h : mh)
        for (std::size_t k = all.first[h]; k < all.first[h + 1]; ++k)
          ++sub_pairs.first[local[nh + all.partner[k]] + 1];
      for (std::size_t j = 0; j < nl; ++j) sub_pairs.first[j + 1] += sub_pairs.first[j];
      sub_pairs.partner.resize(sub_pairs.first[nl]);
      sub_pairs.cost.resize(sub_pairs.first[nl]);
      std::vector<std::size_t> fill(sub_pairs.first.begin(), sub_pairs.first.end() - 1);
      for (std::size_t i = 0; i < mh.size(); ++i)
        for (std::size_t k = all.first[mh[i]]; k < all.first[mh[i] + 1]; ++k) {
          const std::size_t at = fill[local[nh + all.partner[k]]]++;
          sub_pairs.partner[at] = static_cast<std::uint32_t>(i);
          sub_pairs.cost[at] = all.cost[k];
        }
    }
    const std::vector<std::size_t> mate =
        assign_optimally(nl, swap ? mh.size() : mg.size(), sub_pairs, sub, stopped, searched);
    if (stopped) return false;
    for (std::size_t i = 0; i < mate.size(); ++i)
      if (mate[i] != std::numeric_limits<std::size_t>::max()) {
        if (swap)
          pair_samples(M, mh[mate[i]], mg[i]);
        else
          pair_samples(M, mh[i], mg[mate[i]]);
      }
    done += size;
  }
  return true;
}
/// \endcond
}  // namespace internal

/// Matches the samples of two maps (the pairing step of compare_maps()): a ground-truth sample h and a
/// reconstruction sample g may pair when at most match_distance apart and their direction-insensitive
/// bearings differ by less than bearing_limit; options.matching says how pairs are chosen (Map_matching). The
/// progress callback is asked every few thousand samples; a stop leaves no pair (status interrupted).
/// \throws std::invalid_argument for options as compare_maps() refuses them, a non-finite position or a
///   bearing outside [0, 360) (naming the map and the sample).
inline Map_sample_matching match_map_samples(const std::vector<Map_sample>& ground_truth,
                                             const std::vector<Map_sample>& reconstruction,
                                             const Map_comparison_options& options = {}) {
  const char* fn = "match_map_samples";
  internal::check_map_comparison_options(options, fn);
  for (const auto* set : {&ground_truth, &reconstruction})
    for (std::size_t i = 0; i < set->size(); ++i) {
      const Map_sample& s = (*set)[i];
      if (!std::isfinite(s.position[0]) || !std::isfinite(s.position[1]) ||
          !(s.bearing >= 0 && s.bearing < 360))
        FeatureRecon::internal::throw_invalid_argument(
            fn, set == &ground_truth ? "ground-truth" : "reconstruction", " sample ", i,
            " has a non-finite position or a bearing ", "outside [0, 360) (", s.bearing, ")");
    }
  Map_sample_matching M = internal::no_pairs(ground_truth.size(), reconstruction.size());
  if (!ground_truth.empty() && !reconstruction.empty() &&
      !(options.matching == Map_matching::optimal
            ? internal::match_optimal(ground_truth, reconstruction, options, M, fn)
            : internal::match_greedy(ground_truth, reconstruction, options, M)))
    return internal::no_pairs(ground_truth.size(), reconstruction.size(), Status::interrupted);
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return M;
}

/// Compares a reconstructed map with a ground truth by the graph-sampling metric: both maps are sampled
/// (sample_map()) and their samples matched (match_map_samples(); by default greedily: each ground-truth
/// sample h takes the nearest of its `candidates` nearest reconstruction samples whose bearing differs by
/// less than the limit; pairs are accepted by increasing distance up to `match_distance`, a ground-truth
/// sample whose partner was taken looking again among its nearest available ones). precision = m/|G|, recall
/// = m/|H|, F = 2m/(|G| + |H|). A stop through the progress callback leaves the sample counts, no pair and
/// status interrupted.
/// \pre positive, finite options (checked; throws).
inline Map_comparison_result compare_maps(const Embedded_graph_2& ground_truth,
                                          const Embedded_graph_2& reconstruction,
                                          const Map_comparison_options& options = {}) {
  const char* fn = "compare_maps";
  internal::check_map_comparison_options(options, fn);
  // Says which map is bad.
  auto sampled = [&](const Embedded_graph_2& g, const char* which) {
    try {
      return sample_map(g, options.interval);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(fn) + ": " + which + ": " + e.what());
    }
  };
  std::vector<Map_sample> H = sampled(ground_truth, "ground truth");
  std::vector<Map_sample> G = sampled(reconstruction, "reconstruction");
  Map_comparison_result r;
  r.ground_truth_samples = H.size();
  r.reconstruction_samples = G.size();
  Map_sample_matching M = internal::no_pairs(H.size(), G.size(), Status::interrupted);
  if (FeatureRecon::internal::report_progress(options.progress, 0.1)) {
    Map_comparison_options matching = options;
    if (options.progress)
      matching.progress = [&options](double t) { return options.progress(0.1 + 0.9 * t); };
    M = match_map_samples(H, G, matching);
  }
  r.status = M.status;
  r.matched = M.matched;
  if (options.keep_samples) {
    r.ground_truth_sample_list = std::move(H);
    r.reconstruction_sample_list = std::move(G);
    r.ground_truth_partner = std::move(M.ground_truth_partner);
    r.reconstruction_partner = std::move(M.reconstruction_partner);
  }
  const double m = static_cast<double>(r.matched);
  const std::size_t nh = r.ground_truth_samples, ng = r.reconstruction_samples;
  r.precision = ng == 0 ? 0.0 : m / static_cast<double>(ng);
  r.recall = nh == 0 ? 0.0 : m / static_cast<double>(nh);
  r.f_score = (ng + nh) == 0 ? 0.0 : 2 * m / static_cast<double>(ng + nh);
  return r;
}

/// Why the unmatched samples of one map found no partner in the other (see explain_unmatched_samples()).
struct Unmatched_sample_counts {
  /// an aligned sample of the other map lies within the threshold, yet the matching paired the two with
  /// nothing or with others: mostly because that sample was matched to another, where the maps differ in
  /// multiplicity (a parallel line, e.g. the second carriageway of a divided road, present in one map
  /// only); rarely because it was not among the `candidates` nearest ones the greedy matching considers
  std::size_t taken = 0;
  /// the nearest aligned sample of the other map lies between 1 and 2 thresholds away
  std::size_t offset = 0;
  /// within 2 thresholds the other map has samples, none aligned (a street crossing)
  std::size_t crossing = 0;
  std::size_t absent = 0;  ///< the other map has nothing within 2 thresholds
};

namespace internal {
/// Counts one unmatched sample given the distance to the nearest aligned sample of the other map (infinity
/// when none lies within 2 thresholds) and whether any sample of the other map lies within 2 thresholds.
inline void count_unmatched(double aligned, bool any, double threshold, Unmatched_sample_counts& c) {
  if (aligned <= threshold)
    ++c.taken;
  else if (aligned <= 2 * threshold)
    ++c.offset;
  else if (any)
    ++c.crossing;
  else
    ++c.absent;
}
}  // namespace internal

/// Breakdown of the unmatched samples of both maps.
struct Unmatched_samples_breakdown {
  Unmatched_sample_counts missed;    ///< ground-truth samples without a partner (lost recall)
  Unmatched_sample_counts spurious;  ///< reconstruction samples without a partner (lost precision)
};

/// Sorts every unmatched sample of a comparison into the classes of Unmatched_sample_counts: a diagnosis of
/// what a reconstruction lacks (missed) and adds (spurious). Aligned means a bearing difference below the
/// limit.
/// \pre `r` was computed with options.keep_samples (checked; throws). The classes are measured with
/// `options`' match distance and bearing limit: pass the options of the comparison (not checked; the result
/// does not record them).
inline Unmatched_samples_breakdown explain_unmatched_samples(const Map_comparison_result& r,
                                                             const Map_comparison_options& options = {}) {
  const auto& H = r.ground_truth_sample_list;
  const auto& G = r.reconstruction_sample_list;
  if (H.size() != r.ground_truth_samples || G.size() != r.reconstruction_samples ||
      r.ground_truth_partner.size() != H.size() || r.reconstruction_partner.size() != G.size())
    FeatureRecon::internal::throw_invalid_argument("explain_unmatched_samples",
                                                   "the comparison was not computed with keep_samples");
  internal::check_map_comparison_options(options, "explain_unmatched_samples");
  const double t = options.match_distance, reach = 2 * t;
  // Classifies the unmatched samples of `from` against the samples of `to` (bucketed on a grid of cell
  // `reach`).
  auto classify = [&](const std::vector<Map_sample>& from, const std::vector<std::int64_t>& from_partner,
                      const std::vector<Map_sample>& to) {
    Unmatched_sample_counts c;
    std::vector<std::array<double, 2>> positions(to.size());
    for (std::size_t j = 0; j < to.size(); ++j) positions[j] = to[j].position;
    const FeatureRecon::internal::Uniform_grid<2> grid(positions, internal::search_cell(reach));
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (from_partner[i] >= 0) continue;
      double aligned = std::numeric_limits<double>::infinity();
      bool any = false;
      grid.for_each_candidate(from[i].position, [&](std::uint32_t j) {
        const double d =
            std::hypot(to[j].position[0] - from[i].position[0], to[j].position[1] - from[i].position[1]);
        if (d > reach) return;
        any = true;
        if (internal::bearing_difference(from[i].bearing, to[j].bearing) < options.bearing_limit)
          aligned = std::min(aligned, d);
      });
      internal::count_unmatched(aligned, any, t, c);
    }
    return c;
  };
  Unmatched_samples_breakdown b;
  b.missed = classify(H, r.ground_truth_partner, G);
  b.spurious = classify(G, r.reconstruction_partner, H);
  return b;
}

/// Options of count_trips_along() and explain_trace_support().
struct Trace_support_options {
  /// A trip drives along a sample when one of its segments passes this close (m); default 15 (the
  /// comparison's); within [2^-450, 2^450]
  double radius = 15.0;
  /// ... with a direction-insensitive bearing difference below this (degrees); above 90 every direction
  /// counts; default 45 (the comparison's)
  double bearing_limit = 45.0;
};

/// The trace-support options that go with a comparison: its match distance as the radius, its bearing limit.
inline Trace_support_options trace_support_options(const Map_comparison_options& comparison) {
  Trace_support_options o;
  o.radius = comparison.match_distance;
  o.bearing_limit = comparison.bearing_limit;
  return o;
}

/// For each sample, the number of distinct trips that drive along it: trips with a segment between
/// consecutive fixes (by time, as sample_gps_traces() orders them) that passes within `radius` of the sample
/// (exact point-segment distance) with a bearing that differs by less than `bearing_limit` from the sample's,
/// regardless of direction. Segments between fixes at the same place have no bearing and count for nothing.
/// Time: per segment whose bounding box meets the samples' (grown by the radius), its length clipped to that
/// box over the radius, or the number of samples when that is less, plus the samples met; a glitch fix far
/// away costs nothing extra. (A segment with an end beyond 2^44 radii from the origin is checked against
/// every sample.)
/// \throws std::invalid_argument naming the option (radius outside [2^-450, 2^450], bearing limit not
///   positive), the sample with a non-finite position, or the trip and fix with a non-finite coordinate or
///   time.
inline std::vector<std::size_t> count_trips_along(const std::vector<Map_sample>& samples,
                                                  const std::vector<Gps_trip>& trips,
                                                  const Trace_support_options& options = {}) {
  const char* fn = "count_trips_along";
  if (!(options.radius >= internal::min_metric_distance && options.radius <= internal::max_metric_distance))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "radius must be within [2^-450, 2^450] (positive and finite; ",
        "squares of distances near it stay normal), got ", options.radius);
  if (!(options.bearing_limit > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "bearing_limit must be positive (degrees), got ",
                                                   options.bearing_limit);
  for (std::size_t t = 0; t < trips.size(); ++t)
    for (std::size_t i = 0; i < trips[t].size(); ++i)
      if (!std::isfinite(trips[t][i].x) || !std::isfinite(trips[t][i].y) || !std::isfinite(trips[t][i].time))
        FeatureRecon::internal::throw_invalid_argument(fn, "trip ", t, ", fix ", i,
                                                       " has a non-finite coordinate or time");
  std::array<double, 4> box{0, 0, 0, 0};  // of the samples, grown by the radius
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const auto& p = samples[j].position;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
      FeatureRecon::internal::throw_invalid_argument(fn, "sample ", j, " has a non-finite position");
    if (j == 0) box = {p[0], p[1], p[0], p[1]};
    box = {std::min(box[0], p[0]), std::min(box[1], p[1]), std::max(box[2], p[0]), std::max(box[3], p[1])};
  }
  box = {box[0] - options.radius, box[1] - options.radius, box[2] + options.radius, box[3] + options.radius};
  // Bucket the samples on a grid of cell `radius`. Every segment is clipped to the box. A short one visits
  // the cells of its bounding box grown by the radius; a long one is walked in steps of at most a cell, and a
  // sample within the radius of it lies within 1.5 cells of a step point, so in the 5 x 5 cells around one.
  // Each trip counts once per sample (trips are visited in order, so a sample's last counted trip tells
  // whether this one was counted already).
  const double cell_size = options.radius;
  // Clamped: no overflow for far-off coordinates (their keys may collide; the distances decide).
  auto cell = [cell_size](double v) {
    return static_cast<std::int64_t>(std::floor(std::clamp(v / cell_size, -4e18, 4e18)));
  };
  auto key = [](std::int64_t cx, std::int64_t cy) {
    return (static_cast<std::uint64_t>(cx) << 32) ^ (static_cast<std::uint64_t>(cy) & 0xffffffffULL);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t j = 0; j < samples.size(); ++j)
    grid[key(cell(samples[j].position[0]), cell(samples[j].position[1]))].push_back(
        static_cast<std::uint32_t>(j));
  std::vector<std::size_t> count(samples.size(), 0);
  std::vector<std::size_t> last_trip(samples.size(), std::numeric_limits<std::size_t>::max());
  const double r2 = options.radius * options.radius;
  std::vector<std::uint64_t> cells;
  for (std::size_t t = 0; t < trips.size(); ++t) {
    const std::vector<std::size_t> o = internal::time_order(trips[t]);  // as sample_gps_traces() reads a trip
    for (std::size_t i = 0; i + 1 < o.size(); ++i) {
      const Gps_fix& fa = trips[t][o[i]];
      const Gps_fix& fb = trips[t][o[i + 1]];
      if (fa.x == fb.x && fa.y == fb.y) continue;  // no bearing
      // A segment whose bounding box misses the samples' box (grown by the radius) passes near no sample.
      if (std::max(fa.x, fb.x) < box[0] || std::min(fa.x, fb.x) > box[2] || std::max(fa.y, fb.y) < box[1] ||
          std::min(fa.y, fb.y) > box[3])
        continue;
      // The segment from a to b, a the end nearer the samples' box (its coordinates are exact where the
      // samples are): a + t h, t in [0, 2], with h half of b - a (halves of finite coordinates do not
      // overflow).
      const double cx = 0.5 * box[0] + 0.5 * box[2], cy = 0.5 * box[1] + 0.5 * box[3];
      const bool a_first = std::max(std::fabs(fa.x - cx), std::fabs(fa.y - cy)) <=
                           std::max(std::fabs(fb.x - cx), std::fabs(fb.y - cy));
      const std::array<double, 2> a =
          a_first ? std::array<double, 2>{fa.x, fa.y} : std::array<double, 2>{fb.x, fb.y};
      const std::array<double, 2> b =
          a_first ? std::array<double, 2>{fb.x, fb.y} : std::array<double, 2>{fa.x, fa.y};
      const double hx = 0.5 * b[0] - 0.5 * a[0], hy = 0.5 * b[1] - 0.5 * a[1];
      const double bearing = internal::bearing_of({0.0, 0.0}, {hx, hy});  // direction does not matter
      // Below 2^44 cells (and 2^500) from the origin, points a + t h are placed to within a 256th of a cell
      // and distances in doubles are exact to far below the radius; beyond, every sample is decided exactly
      // (a filtered CGAL predicate) instead: only absurd fixes get there.
      const double magnitude = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(b[0]), std::fabs(b[1])});
      const bool placed = magnitude < std::min(0x1p44 * cell_size, 0x1p500);
      if (!placed) {
        using Exact_predicates = CGAL::Exact_predicates_inexact_constructions_kernel;
        const Exact_predicates::Segment_2 segment(Exact_predicates::Point_2(a[0], a[1]),
                                                  Exact_predicates::Point_2(b[0], b[1]));
        const auto compare = Exact_predicates().compare_squared_distance_2_object();
        for (std::size_t j = 0; j < samples.size(); ++j) {
          const auto& p = samples[j].position;
          if (last_trip[j] == t ||
              !(internal::bearing_difference(bearing, samples[j].bearing) < options.bearing_limit))
            continue;
          if (compare(Exact_predicates::Point_2(p[0], p[1]), segment, r2) != CGAL::LARGER) {
            last_trip[j] = t;
            ++count[j];
          }
        }
        continue;
      }
      const double half = std::hypot(hx, hy);
      if (!(half > 0)) continue;                    // (halves of two subnormals apart can round together)
      const double wx = hx / half, wy = hy / half;  // unit direction
      // Clip the parameter range [t0, t1] of a + t h to the box (Liang-Barsky).
      double t0 = 0, t1 = 2;
      for (const auto& [q, d] : {std::pair{a[0] - box[0], -hx}, std::pair{box[2] - a[0], hx},
                                 std::pair{a[1] - box[1], -hy}, std::pair{box[3] - a[1], hy}}) {
        if (d == 0) {
          if (q < 0) t0 = 3;  // parallel and outside
        } else if (d < 0) {
          t0 = std::max(t0, q / d);
        } else {
          t1 = std::min(t1, q / d);
        }
      }
      if (!(t0 <= t1)) continue;
      const double steps = std::ceil((t1 - t0) * (half / cell_size));
      // A walk longer than the samples are many (a tiny radius against a wide box) visits every sample
      // instead.
      const bool scan_all = !(steps * 25 <= static_cast<double>(samples.size()));
      cells.clear();
      if (scan_all) {
      } else if (steps <= 4) {  // short: the cells of its bounding box grown by the radius
        const double xa = a[0] + t0 * hx, xb = a[0] + t1 * hx, ya = a[1] + t0 * hy, yb = a[1] + t1 * hy;
        const std::int64_t x0 = cell(std::min(xa, xb) - options.radius),
                           x1 = cell(std::max(xa, xb) + options.radius);
        const std::int64_t y0 = cell(std::min(ya, yb) - options.radius),
                           y1 = cell(std::max(ya, yb) + options.radius);
        for (std::int64_t x = x0; x <= x1; ++x)
          for (std::int64_t y = y0; y <= y1; ++y) cells.push_back(key(x, y));
      } else {
        for (double k = 0; k <= steps; ++k) {
          const double u = t0 + (t1 - t0) * (k / steps);
          const std::int64_t x = cell(a[0] + u * hx), y = cell(a[1] + u * hy);
          for (std::int64_t dx = -2; dx <= 2; ++dx)
            for (std::int64_t dy = -2; dy <= 2; ++dy) cells.push_back(key(x + dx, y + dy));
        }
        std::sort(cells.begin(), cells.end());
        cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      }
      auto consider = [&](std::uint32_t j) {
        if (last_trip[j] == t) return;
        const auto& p = samples[j].position;
        // Distance to the segment: to an end when the projection s (along it from a) falls outside [0, 2
        // |h|], else across it, from the cross product (no cancellation between s and a). A distance that
        // overflows (or is NaN, far beyond any radius) does not count.
        const double px = p[0] - a[0], py = p[1] - a[1], s = px * wx + py * wy;
        double d2;
        if (s <= 0) {
          d2 = px * px + py * py;
        } else if (s >= 2 * half) {
          d2 = (p[0] - b[0]) * (p[0] - b[0]) + (p[1] - b[1]) * (p[1] - b[1]);
        } else {
          const double across = px * wy - py * wx;
          d2 = across * across;
        }
        if (!(d2 <= r2)) return;
        if (!(internal::bearing_difference(bearing, samples[j].bearing) < options.bearing_limit)) return;
        last_trip[j] = t;
        ++count[j];
      };
      if (scan_all)
        for (std::size_t j = 0; j < samples.size(); ++j) consider(static_cast<std::uint32_t>(j));
      for (const std::uint64_t c : cells) {
        const auto it = grid.find(c);
        if (it != grid.end())
          for (const std::uint32_t j : it->second) consider(j);
      }
    }
  }
  return count;
}

/// How the samples of a comparison are supported by the GPS trips the reconstruction came from (see
/// explain_trace_support()). Counts are split by the number of trips driving along a sample: 0, 1, 2-3, 4 or
/// more.
struct Trace_support_breakdown {
  std::array<std::size_t, 4> ground_truth_by_trips{};  ///< all ground-truth samples
  std::array<std::size_t, 4> missed_by_trips{};        ///< ground-truth samples without a partner
  std::array<std::size_t, 4> spurious_by_trips{};      ///< reconstruction samples without a partner
  /// Ground-truth samples that at least one trip drives along: the part of the truth that the traces show.
  std::size_t ground_truth_driven = 0;
  std::size_t matched_driven = 0;  ///< ... of which matched
  double recall_of_driven = 0;     ///< matched_driven / ground_truth_driven (0 when none is driven)
};

/// Bins a trip count: 0, 1, 2-3, 4 or more.
inline std::size_t trip_count_bin(std::size_t trips) {
  return trips == 0 ? 0 : trips == 1 ? 1 : trips <= 3 ? 2 : 3;
}

/// Splits the samples of a comparison by the number of trips that drive along them (count_trips_along()):
/// which part of the truth no trip drives along (no reconstruction from these traces can be expected to find
/// it), the recall within the driven part, and how well the spurious lines are supported. The default radius
/// and bearing limit are those of Map_comparison_options; for other comparison options pass
/// trace_support_options(comparison_options).
/// \pre `r` was computed with options.keep_samples (checked; throws).
inline Trace_support_breakdown explain_trace_support(const Map_comparison_result& r,
                                                     const std::vector<Gps_trip>& trips,
                                                     const Trace_support_options& options = {}) {
  if (r.ground_truth_sample_list.size() != r.ground_truth_samples ||
      r.reconstruction_sample_list.size() != r.reconstruction_samples ||
      r.ground_truth_partner.size() != r.ground_truth_samples ||
      r.reconstruction_partner.size() != r.reconstruction_samples)
    FeatureRecon::internal::throw_invalid_argument("explain_trace_support",
                                                   "the comparison was not computed with keep_samples");
  Trace_support_breakdown b;
  const std::vector<std::size_t> h = count_trips_along(r.ground_truth_sample_list, trips, options);
  const std::vector<std::size_t> g = count_trips_along(r.reconstruction_sample_list, trips, options);
  for (std::size_t i = 0; i < h.size(); ++i) {
    ++b.ground_truth_by_trips[trip_count_bin(h[i])];
    if (r.ground_truth_partner[i] < 0) ++b.missed_by_trips[trip_count_bin(h[i])];
    if (h[i] > 0) {
      ++b.ground_truth_driven;
      if (r.ground_truth_partner[i] >= 0) ++b.matched_driven;
    }
  }
  for (std::size_t j = 0; j < g.size(); ++j)
    if (r.reconstruction_partner[j] < 0) ++b.spurious_by_trips[trip_count_bin(g[j])];
  b.recall_of_driven = b.ground_truth_driven == 0 ? 0.0
                                                  : static_cast<double>(b.matched_driven) /
                                                        static_cast<double>(b.ground_truth_driven);
  return b;
}

/// Options of crop_map_to_trips().
struct Map_crop_options {
  /// an edge stays when every sample of it lies within this of a trace point; default 25
  double radius = 25;
  double sample_interval = 5;  ///< the edges' samples, from one end, the other end included; default 5
  /// The trace points: the fixes, and between two consecutive fixes of a trip (by time) at most max_gap
  /// apart, points that cut the segment into equal pieces of at most trace_step; default 10
  double trace_step = 10;
  double max_gap = 500;  ///< see trace_step; finite and >= 0; 0: the fixes alone; default 500
  /// Called with the fraction of the edges checked (every 4096 edges; the trace points are made at 0);
  /// returning false stops: the map holds the edges kept so far, status interrupted.
  Progress_callback progress;
};

/// Result of crop_map_to_trips().
struct Cropped_map {
  Embedded_graph_2 map;             ///< the input's positions, the edges kept (in input order)
  std::size_t trace_points = 0;     ///< fixes and interpolated points
  Status status = Status::success;  ///< interrupted when the progress callback stopped the run
};

/// Restricts a ground-truth map to the streets the trips cover, the crop of the Chicago reference ground
/// truth `chicago_gt_trk25` (its README): an edge is kept when every one of its samples (every
/// sample_interval from its first vertex, and its second vertex) lies within `radius` of a trace point, the
/// trace points being the fixes and points every trace_step along the segments between consecutive fixes of a
/// trip up to max_gap long (a trip's fixes ordered by time, equal times in the given order). The
/// interpolation keeps a street between sparse fixes (Chicago: 20-40 m apart; with the fixes alone 40 of the
/// reference's 1566 edges were lost, with it all are kept and 3 more). Ranges are inclusive. Exact up to the
/// rounding of the sample positions.
/// \throws std::invalid_argument naming the option (radius, sample_interval, trace_step: positive and finite;
///   max_gap finite and >= 0), the edge (a vertex out of range, a non-finite coordinate), the trip and fix (a
///   non-finite coordinate or time), or when the edges would give more than 2^25 samples or the trips more
///   than 2^27 trace points.
inline Cropped_map crop_map_to_trips(const Embedded_graph_2& map, const std::vector<Gps_trip>& trips,
                                     const Map_crop_options& options = {}) {
  const char* fn = "crop_map_to_trips";
  using FeatureRecon::internal::throw_invalid_argument;
  auto positive = [&](double v, const char* name) {
    if (!(v > 0 && std::isfinite(v)))
      throw_invalid_argument(fn, name, " must be positive and finite, got ", v);
  };
  positive(options.radius, "radius");
  positive(options.sample_interval, "sample_interval");
  positive(options.trace_step, "trace_step");
  if (!(options.max_gap >= 0 && std::isfinite(options.max_gap)))
    throw_invalid_argument(fn, "max_gap must be finite and >= 0, got ", options.max_gap);
  const std::size_t n = map.positions.size();
  auto length = [&](const Edge& e) {
    const auto& a = map.positions[e[0]];
    const auto& b = map.positions[e[1]];
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  // The samples are counted first: a tiny interval or a huge edge is refused, it does not loop (t += interval
  // stops moving once t is large) or run for hours; the bound is compare_maps' (2^25 samples).
  double samples = 0;
  for (std::size_t k = 0; k < map.edges.size(); ++k) {
    const Edge& e = map.edges[k];
    if (e[0] >= n || e[1] >= n)
      throw_invalid_argument(fn, "edge ", k, " has a vertex out of range [0, ", n, ")");
    for (const Vertex_index v : e)
      if (!std::isfinite(map.positions[v][0]) || !std::isfinite(map.positions[v][1]))
        throw_invalid_argument(fn, "vertex ", v, " (of edge ", k, ") has a non-finite coordinate");
    samples += std::floor(length(e) / options.sample_interval) + 2;
  }
  if (!(samples < 33554432.0))
    throw_invalid_argument(fn, "the edges at sample_interval ", options.sample_interval,
                           " would give more than 2^25 samples");
  Cropped_map out;
  out.map.positions = map.positions;
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) {
    out.status = Status::interrupted;
    return out;
  }
  using K = CGAL::Simple_cartesian<double>;
  using Tree_traits = CGAL::Search_traits_2<K>;
  std::vector<K::Point_2> points;
  double planned = 0;
  for (std::size_t t = 0; t < trips.size(); ++t) {
    const Gps_trip& trip = trips[t];
    for (std::size_t i = 0; i < trip.size(); ++i)
      if (!std::isfinite(trip[i].x) || !std::isfinite(trip[i].y) || !std::isfinite(trip[i].time))
        throw_invalid_argument(fn, "trip ", t, ", fix ", i, " has a non-finite coordinate or time");
    std::vector<std::size_t> order(trip.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&trip](std::size_t a, std::size_t b) { return trip[a].time < trip[b].time; });
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Gps_fix& f = trip[order[i]];
      points.emplace_back(f.x, f.y);
      if (i + 1 == order.size()) break;
      const Gps_fix& g = trip[order[i + 1]];
      const double d = std::hypot(g.x - f.x, g.y - f.y);
      if (!(d <= options.max_gap && d > options.trace_step)) continue;
      const double pieces = std::ceil(d / options.trace_step);
      planned += pieces;
      if (!(planned + double(points.size()) <= double(std::size_t(1) << 27)))
        throw_invalid_argument(fn, "the trips would give more than 2^27 trace points at trace_step ",
                               options.trace_step, " across gaps up to max_gap ", options.max_gap);
      for (double j = 1; j < pieces; ++j) {
        const double u = j / pieces;
        points.emplace_back(f.x + u * (g.x - f.x), f.y + u * (g.y - f.y));
      }
    }
  }
  out.trace_points = points.size();
  CGAL::Kd_tree<Tree_traits> tree(points.begin(), points.end());
  if (!points.empty())
    tree.build();  // (CGAL asserts on building an empty tree; no point keeps no edge below)
  auto covered = [&](double x, double y) {
    const CGAL::Fuzzy_sphere<Tree_traits> ball(K::Point_2(x, y), options.radius, 0.0);  // closed ball
    return static_cast<bool>(tree.search_any_point(ball));  // the first point found
  };
  for (std::size_t k = 0; k < map.edges.size(); ++k) {
    if (k % 4096 == 4095 &&
        !FeatureRecon::internal::report_progress(options.progress, double(k) / double(map.edges.size()))) {
      out.status = Status::interrupted;
      return out;
    }
    const Edge& e = map.edges[k];
    const auto& a = map.positions[e[0]];
    const auto& b = map.positions[e[1]];
    const double len = length(e);
    // reaches b
    const auto steps = static_cast<std::uint64_t>(std::floor(len / options.sample_interval)) + 1;
    bool keep = !points.empty();
    for (std::uint64_t i = 0; keep && i <= steps; ++i) {
      const double u = len > 0 ? std::min(1.0, static_cast<double>(i) * options.sample_interval / len) : 0.0;
      keep = covered(a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]));
    }
    if (keep) out.map.edges.push_back(e);
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return out;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_MAP_COMPARISON_H
