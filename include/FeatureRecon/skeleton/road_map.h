// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_ROAD_MAP_H
#define FEATURERECON_SKELETON_ROAD_MAP_H

// Road maps from GPS traces in one call (dissertation Ch. 3.4): the GPS front end of gps_traces.h, then the
// skeleton stages of extract_reeb_skeleton.h, with every unset parameter derived from the data. The same
// rules drive `featurerecon skeleton --tracks`. Stage by stage:
//
//   const Road_map_options used = resolve_road_map_options(trips, options);
//   const Gps_trace_sample S = sample_gps_traces(trips, used.rips_radius, used.traces);
//   const Proximity_graph g = build_gps_trace_graph(S, used.rips_radius, used.traces.heading_tolerance);
//   const Reeb_skeleton k = extract_reeb_skeleton(g, S.points, road_map_skeleton_options(used));
//   const Embedded_graph_2 map = skeleton_to_road_map(k.graph);

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/map_comparison.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// The trace options road maps start from: directions kept (heading tolerance 30 degrees), samples lighter than
/// 10 % of their direction's local maximum dropped; spacing, link gap and density radius automatic.
inline Gps_trace_options road_map_trace_options() {
  Gps_trace_options o;
  o.heading_tolerance = 30;
  o.min_relative_density = 0.1;
  return o;
}

/// Options of extract_road_map(). Coordinates are metres. A value of 0 asks for the rule on the field, derived
/// from the median step M between consecutive fixes of a trip (median_gps_step()) through the Rips radius R;
/// a negative value turns the stage off. resolve_road_map_options() returns the values used.
struct Road_map_options {
  double rips_radius = 0;      ///< 0: M clamped to [min_radius, max_radius]
  double min_radius = 10;      ///< lower clamp of the automatic radius (m); default 10
  double max_radius = 30;      ///< upper clamp of the automatic radius (m); default 30
  double delta = 0;            ///< persistence threshold of the simplification; 0: 3 R; negative: none
  double repair_distance = 0;  ///< join dead ends at most this far apart; 0: 2.5 R; negative: no repair
  double prune_height = 0;     ///< drop components of smaller height (range of f); 0: 5 R; negative: keep all
  /// Sampling, linking and density filter (sample_gps_traces()); its own automatic rules (spacing R/2, link gap
  /// max(4M, 2R), density radius 2R) apply and are reported in Road_map::sample.
  Gps_trace_options traces = road_map_trace_options();
  bool connect_dead_ends = true;  ///< Skeleton_options::connect_dead_ends
  bool trim_stubs = true;         ///< Skeleton_options::trim_stubs
  Embedding_options embedding;    ///< how arcs are drawn (level width 0: median edge length of the complex)
  Progress_callback progress;     ///< fraction done; returning false stops (Road_map::status interrupted)
};

/// Result of extract_road_map().
struct Road_map {
  Embedded_graph_2 map;      ///< the road map: skeleton nodes first (same indices), then polyline interior points
  Reeb_skeleton skeleton;    ///< the skeleton graph with its stage counts
  Gps_trace_sample sample;   ///< the samples the skeleton is built on, with the trace parameters used
  Road_map_options used;     ///< the options with every automatic value filled in (no progress callback)
  Status status = Status::success;  ///< degenerate_input when no fix is left; interrupted by the callback
};

/// The options with every automatic value of extract_road_map() filled in (delta, repair and prune become 0
/// when turned off). The trace options' own automatic values are left to sample_gps_traces().
/// \throws std::invalid_argument naming a non-finite option, a negative radius or clamp, or min_radius > max_radius.
inline Road_map_options resolve_road_map_options(const std::vector<Gps_trip>& trips, const Road_map_options& options) {
  const char* fn = "extract_road_map";
  if (!std::isfinite(options.rips_radius) || options.rips_radius < 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "rips_radius must be finite and >= 0 (0: automatic), got ",
                                                   options.rips_radius);
  if (!(options.min_radius > 0 && options.min_radius <= options.max_radius && std::isfinite(options.max_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "need 0 < min_radius <= max_radius < infinity, got ",
                                                   options.min_radius, " and ", options.max_radius);
  if (!std::isfinite(options.delta) || !std::isfinite(options.repair_distance) || std::isnan(options.prune_height))
    FeatureRecon::internal::throw_invalid_argument(fn, "delta, repair_distance and prune_height must be finite");
  Road_map_options u = options;
  u.progress = nullptr;
  const double M = median_gps_step(trips);
  const double R =
      options.rips_radius > 0 ? options.rips_radius : std::min(options.max_radius, std::max(options.min_radius, M));
  u.rips_radius = R;
  auto rule = [](double value, double automatic) { return value > 0 ? value : value == 0 ? automatic : 0.0; };
  u.delta = rule(options.delta, 3 * R);
  u.repair_distance = rule(options.repair_distance, 2.5 * R);
  u.prune_height = rule(options.prune_height, 5 * R);
  return u;
}

/// The skeleton options of a resolved Road_map_options (the progress callback is not copied).
inline Skeleton_options road_map_skeleton_options(const Road_map_options& used) {
  Skeleton_options o;
  o.delta = std::max(0.0, used.delta);
  o.repair_distance = std::max(0.0, used.repair_distance);
  o.prune_height = std::max(0.0, used.prune_height);
  o.connect_dead_ends = used.connect_dead_ends;
  o.trim_stubs = used.trim_stubs;
  o.embedding = used.embedding;
  return o;
}

/// The planar map of a skeleton: vertex i is node i (its first two coordinates), followed by the interior
/// points of every arc's polyline in edge order; each polyline becomes a chain of edges between its nodes.
inline Embedded_graph_2 skeleton_to_road_map(const Skeleton_graph& g) {
  Embedded_graph_2 map;
  for (auto v : boost::make_iterator_range(vertices(g))) map.positions.push_back({g[v].position[0], g[v].position[1]});
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

/// A road map from GPS traces in one call: resolve_road_map_options(), sample_gps_traces(),
/// build_gps_trace_graph(), extract_reeb_skeleton() on the graph, skeleton_to_road_map(). Deterministic (no
/// randomness; the same trips in the same order give the same map bit for bit). Trips with no or one fix are
/// allowed; with no fix at all the map is empty and the status degenerate_input.
/// \throws std::invalid_argument for bad options (resolve_road_map_options(), sample_gps_traces()) or a fix with
///         a non-finite coordinate or time (naming the trip and the fix). `trips` is not modified.
inline Road_map extract_road_map(const std::vector<Gps_trip>& trips, const Road_map_options& options = {}) {
  Road_map r;
  r.used = resolve_road_map_options(trips, options);
  if (!FeatureRecon::internal::report_progress(options.progress, 0.0)) {
    r.status = Status::interrupted;
    return r;
  }
  r.sample = sample_gps_traces(trips, r.used.rips_radius, r.used.traces);
  if (!FeatureRecon::internal::report_progress(options.progress, 0.1)) {
    r.status = Status::interrupted;
    return r;
  }
  Skeleton_options so = road_map_skeleton_options(r.used);
  if (options.progress) so.progress = [&options](double t) { return options.progress(0.1 + 0.9 * t); };
  r.skeleton = extract_reeb_skeleton(build_gps_trace_graph(r.sample, r.used.rips_radius, r.used.traces.heading_tolerance),
                                     r.sample.points, so);
  r.status = r.skeleton.status;
  if (r.status != Status::interrupted) r.map = skeleton_to_road_map(r.skeleton.graph);
  return r;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_ROAD_MAP_H
