// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/road_map.h>
#include <FeatureRecon/skeleton/synthetic_city.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_utilities.h"

using FeatureRecon::test::contains;
using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {
/// Two trips along a straight street, fixes `step` apart.
std::vector<Gps_trip> street(double step) {
  std::vector<Gps_trip> trips(2);
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 20; ++i) trips[k].push_back({i * step, 3.0 * k, 100.0 * k + i});
  return trips;
}

double segment_distance(const std::array<double, 2>& p, const std::array<double, 2>& a,
                        const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// The adjacency of a city's street graph (intersections 0..n-1, then the inner points of bent streets).
std::vector<std::vector<Vertex_index>> street_adjacency(const Synthetic_city& c) {
  std::vector<std::vector<Vertex_index>> adj(c.streets.positions.size());
  for (const Edge& e : c.streets.edges) {
    adj[e[0]].push_back(e[1]);
    adj[e[1]].push_back(e[0]);
  }
  return adj;
}

// Each street once, as the polyline from an intersection a through the inner points (indices n and up, of
// degree 2) to the intersection b >= a at its other end.
std::vector<std::vector<Vertex_index>> street_lines(const std::vector<std::vector<Vertex_index>>& adj,
                                                    std::size_t n) {
  std::vector<std::vector<Vertex_index>> lines;
  for (Vertex_index a = 0; a < n; ++a)
    for (const Vertex_index first : adj[a]) {
      std::vector<Vertex_index> line{a, first};
      while (line.back() >= n)
        line.push_back(adj[line.back()][0] == line[line.size() - 2] ? adj[line.back()][1]
                                                                    : adj[line.back()][0]);
      if (line.back() >= a) lines.push_back(std::move(line));
    }
  return lines;
}

template <class F>
std::string message_of(F f) {
  return test::thrown_message<std::invalid_argument>(f);
}

Synthetic_city small_city(std::uint64_t seed = 3) {
  Synthetic_city_options o;
  o.columns = 5;
  o.rows = 4;
  o.trips = 150;
  o.seed = seed;
  return make_synthetic_city(o);
}
}  // namespace

TEST(RoadMap, AutomaticParametersFollowTheMedianStep) {
  // R is the median step clamped to [10, 30] m; delta 3R, repair 2.5R, prune 5R.
  for (const auto& [step, R] : {std::pair{20.0, 20.0}, std::pair{4.0, 10.0}, std::pair{200.0, 30.0}}) {
    const Road_map_options u = resolve_road_map_options(street(step), {});
    EXPECT_DOUBLE_EQ(u.rips_radius.value(), R) << step;
    EXPECT_DOUBLE_EQ(u.delta.value(), 3 * R);
    EXPECT_DOUBLE_EQ(u.repair_distance.value(), 2.5 * R);
    EXPECT_DOUBLE_EQ(u.prune_height.value(), 5 * R);
    EXPECT_DOUBLE_EQ(u.merge_distance.value(), 8);
    EXPECT_EQ(u.branch_merge_distance, 0.0);  // off unless asked for
  }
  Road_map_options o;
  o.min_radius = 25;
  EXPECT_DOUBLE_EQ(resolve_road_map_options(street(20), o).rips_radius.value(), 25);
  o.rips_radius = 7;  // explicit values win; 0 turns a stage off, as in Skeleton_options
  o.delta = 11;
  o.repair_distance = 0;
  o.prune_height = 0;
  o.merge_distance = 0;
  o.branch_merge_distance = FeatureRecon::automatic;
  const Road_map_options u = resolve_road_map_options(street(20), o);
  EXPECT_DOUBLE_EQ(u.rips_radius.value(), 7);
  EXPECT_DOUBLE_EQ(u.delta.value(), 11);
  EXPECT_EQ(u.repair_distance, 0.0);
  EXPECT_EQ(u.prune_height, 0.0);
  EXPECT_EQ(u.merge_distance, 0.0);
  EXPECT_FALSE(u.branch_merge_distance);  // the skeleton's rule, which needs its level width
  const Skeleton_options so = road_map_skeleton_options(u);
  EXPECT_DOUBLE_EQ(so.delta.value(), 11);
  EXPECT_EQ(so.repair_distance, 0);
  EXPECT_EQ(so.prune_height, 0);
  EXPECT_FALSE(so.branch_merge_distance);
  // No trip with two fixes: no step to derive from, the lower clamp.
  EXPECT_DOUBLE_EQ(resolve_road_map_options({}, {}).rips_radius.value(), 10);
}

TEST(RoadMap, OneCallEqualsTheStagesAndIsDeterministic) {
  const Synthetic_city city = small_city();
  const Road_map m = extract_road_map(city.trips);
  ASSERT_EQ(m.status, Status::success);
  const Road_map_options used = resolve_road_map_options(city.trips, {});
  const Gps_trace_sample S = sample_gps_traces(city.trips, used.rips_radius.value(), used.traces);
  const Proximity_graph g = build_gps_trace_graph(S, used.rips_radius.value());
  const Reeb_skeleton k = extract_reeb_skeleton(g, S.points, road_map_skeleton_options(used));
  const Embedded_graph_2 lines = skeleton_to_road_map(k.graph);
  EXPECT_DOUBLE_EQ(used.merge_distance.value(), 8);
  const Road_merge_result merged = merge_road_lines(lines, road_map_merge_options(used));
  // The merge's delta: automatic is its distance; 0 simplifies nothing (stubs where lines meet stay).
  EXPECT_DOUBLE_EQ(merged.delta, 8);
  Road_merge_options unsimplified = road_map_merge_options(used);
  unsimplified.delta = 0;
  const Road_merge_result stubs = merge_road_lines(lines, unsimplified);
  EXPECT_EQ(stubs.delta, 0.0);
  EXPECT_GT(num_edges(stubs.skeleton), num_edges(merged.skeleton) + 10);
  // The values used reproduce the map, and every optional field is set after the run.
  const Road_map again = extract_road_map(city.trips, m.used);
  EXPECT_EQ(again.map.positions, m.map.positions);
  EXPECT_EQ(again.map.edges, m.map.edges);
  for (const std::optional<double>& field :
       {m.used.rips_radius, m.used.delta, m.used.repair_distance, m.used.prune_height, m.used.merge_distance,
        m.used.branch_merge_distance, m.used.traces.sample_spacing, m.used.traces.max_link_gap,
        m.used.traces.density_radius, m.used.traces.segment_support, m.used.embedding.level_width,
        m.used.embedding.max_gap})
    EXPECT_TRUE(field.has_value());
  EXPECT_EQ(*m.used.traces.sample_spacing, m.sample.sample_spacing);
  EXPECT_EQ(*m.used.embedding.level_width, m.skeleton.level_width);
  // Options not resolved are refused by the stage helpers, naming the field.
  EXPECT_EQ(message_of([] { road_map_skeleton_options(Road_map_options{}); }),
            "road_map_skeleton_options: the options' delta is automatic: pass the result of "
            "resolve_road_map_options()");
  EXPECT_EQ(message_of([] { road_map_merge_options(Road_map_options{}); }),
            "road_map_merge_options: the options' merge_distance is automatic: pass the result of "
            "resolve_road_map_options()");
  Road_map_options merge_off = used;
  merge_off.merge_distance = 0;  // merging off: no options to give merge_road_lines() (it refuses distance 0)
  EXPECT_EQ(message_of([&] { road_map_merge_options(merge_off); }),
            "road_map_merge_options: merge_distance is 0: merging is off, there are no merge options");
  EXPECT_EQ(m.map.positions, merged.map.positions);
  EXPECT_EQ(m.map.edges, merged.map.edges);
  EXPECT_EQ(m.sample.points.data, S.points.data);
  EXPECT_EQ(extract_road_map(city.trips).map.positions, m.map.positions);
  // Merging the two directions of the city's two-way streets removes about a third of the length.
  EXPECT_LT(merged.length_after, 0.8 * merged.length_before);
  EXPECT_GT(merged.length_after, 0.4 * merged.length_before);
  // The map: the merged skeleton's nodes first at their positions; every edge joins two distinct vertices.
  const Skeleton_graph& sk = m.merged.skeleton;
  ASSERT_GE(m.map.positions.size(), num_vertices(sk));
  for (std::size_t v = 0; v < num_vertices(sk); ++v) {
    EXPECT_EQ(m.map.positions[v][0], sk[v].position[0]);
    EXPECT_EQ(m.map.positions[v][1], sk[v].position[1]);
  }
  std::size_t polyline_edges = 0;
  for (auto e : boost::make_iterator_range(edges(sk))) polyline_edges += sk[e].polyline.size() - 1;
  EXPECT_EQ(m.map.edges.size(), polyline_edges);
  for (const Edge& e : m.map.edges) {
    EXPECT_NE(e[0], e[1]);
    EXPECT_LT(std::max(e[0], e[1]), m.map.positions.size());
  }
  // Merging off: the skeleton's map itself.
  Road_map_options off;
  off.merge_distance = 0;
  const Road_map u = extract_road_map(city.trips, off);
  EXPECT_EQ(u.used.merge_distance, 0.0);
  EXPECT_EQ(u.map.positions, lines.positions);
  EXPECT_EQ(u.map.edges, lines.edges);
  EXPECT_EQ(num_vertices(u.merged.skeleton), 0u);
}

TEST(RoadMap, SkeletonLinesDoNotGoOutAndBack) {
  // Where a wide gap is bridged through the graph and the next bridge leaves through the same vertex, the
  // line went out to the piece's centroid and back: X B X, twice the same point two steps apart (about 1 % of
  // the length of the city's skeleton lines were such spikes).
  for (const std::uint64_t seed : {3u, 4u, 5u}) {
    const Synthetic_city city = small_city(seed);
    Road_map_options off;
    off.merge_distance = 0;
    const Road_map m = extract_road_map(city.trips, off);
    ASSERT_EQ(m.status, Status::success);
    std::size_t points = 0;
    for (auto e : boost::make_iterator_range(edges(m.skeleton.graph))) {
      const auto& line = m.skeleton.graph[e].polyline;
      points += line.size();
      for (std::size_t i = 2; i < line.size(); ++i) EXPECT_NE(line[i], line[i - 2]) << "seed " << seed;
    }
    EXPECT_GT(points, 300u);
  }
}

TEST(RoadMap, BadOptionsAndFixesAreNamed) {
  const std::vector<Gps_trip> trips = street(20);
  Road_map_options o;
  o.rips_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "rips_radius"));
  o.rips_radius = 0;  // 0 asked for the automatic radius before FeatureRecon::automatic
  EXPECT_EQ(message_of([&] { extract_road_map(trips, o); }),
            "extract_road_map: rips_radius must be finite and > 0 (FeatureRecon::automatic: from the median "
            "step), got 0");
  o.rips_radius = 1e308;  // 5R overflowed and the skeleton named delta, repair_distance and prune_height
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }),
                       "extract_road_map: rips_radius must be at most 1e300"));
  o = {};
  o.min_radius = 1e305;
  o.max_radius = 1e306;
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "max_radius must be at most 1e300"));
  o = {};
  o.min_radius = 60;
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "min_radius"));
  o = {};
  o.delta = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "delta"));
  o = {};
  o.traces.heading_tolerance = -1;
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "heading_tolerance"));
  o = {};
  o.merge_distance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(message_of([&] { extract_road_map(trips, o); }), "merge_distance"));
  // A negative value turned a stage off before FeatureRecon::automatic; now 0 does, and a negative value is
  // refused, naming the field, the rule and the off value (it would otherwise be taken for a value).
  const std::vector<std::pair<std::optional<double> Road_map_options::*, std::string>> fields = {
      {&Road_map_options::delta, "delta must be finite and >= 0 (FeatureRecon::automatic: 3 R; 0: off)"},
      {&Road_map_options::repair_distance,
       "repair_distance must be finite and >= 0 (FeatureRecon::automatic: 2.5 R; 0: off)"},
      {&Road_map_options::prune_height, "prune_height must be >= 0 (FeatureRecon::automatic: 5 R; 0: off)"},
      {&Road_map_options::merge_distance,
       "merge_distance must be finite and >= 0 (FeatureRecon::automatic: 8 m; 0: off)"},
      {&Road_map_options::branch_merge_distance,
       "branch_merge_distance must be finite and >= 0 (FeatureRecon::automatic: twice the level width; 0: "
       "off)"}};
  for (const auto& [field, text] : fields) {
    o = {};
    o.*field = -1;
    EXPECT_EQ(message_of([&] { extract_road_map(trips, o); }), "extract_road_map: " + text + ", got -1");
  }
  o = {};
  o.prune_height = std::numeric_limits<double>::infinity();  // prune everything
  EXPECT_NO_THROW(extract_road_map(trips, o));
  // A merge distance so small that the merge stage refuses its samples is named as the caller's field (the
  // stage's spacing and sample cap are not options of extract_road_map()); a radius whose automatic spacing
  // underflows, as the radius.
  o = {};
  o.merge_distance = 1e-300;
  const std::string tiny = message_of([&] { extract_road_map(trips, o); });
  EXPECT_EQ(tiny.rfind("extract_road_map: merge_distance 1e-300 (the merge samples the lines every third of "
                       "it) is refused by merge_road_lines: ",
                       0),
            0u)
      << tiny;
  o = {};
  o.rips_radius = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(message_of([&] { extract_road_map(trips, o); })
                .rfind("sample_gps_traces: rips_radius 4.94066e-324 "
                       "is too small",
                       0),
            0u);
  std::vector<Gps_trip> bad = trips;
  bad[1][2].y = std::numeric_limits<double>::quiet_NaN();
  const std::string m = message_of([&] { extract_road_map(bad, {}); });
  EXPECT_TRUE(contains(m, "trip 1, fix 2"));
}

TEST(RoadMap, DegenerateInput) {
  for (const std::vector<Gps_trip>& trips : {std::vector<Gps_trip>{}, std::vector<Gps_trip>(3)}) {
    const Road_map m = extract_road_map(trips);
    EXPECT_EQ(m.status, Status::degenerate_input);
    EXPECT_TRUE(m.map.positions.empty());
    EXPECT_TRUE(m.map.edges.empty());
    // No complex: the embedding and the branch merge did not run, and `used` keeps them as given (max_gap
    // read 0, off, before).
    EXPECT_FALSE(m.used.embedding.level_width.has_value());
    EXPECT_FALSE(m.used.embedding.max_gap.has_value());
    EXPECT_EQ(m.used.branch_merge_distance, Road_map_options{}.branch_merge_distance);
    Road_map_options automatic_merge;
    automatic_merge.branch_merge_distance = FeatureRecon::automatic;
    EXPECT_FALSE(extract_road_map(trips, automatic_merge).used.branch_merge_distance.has_value());
  }
  // One fix, or one fix repeated: one sample, and a component of height 0 is pruned (a map with no streets).
  for (const std::size_t copies : {1u, 5u}) {
    std::vector<Gps_trip> one(copies, Gps_trip{{5, 5, 0}});
    const Road_map m = extract_road_map(one);
    EXPECT_EQ(m.sample.points.rows, 1u);
    EXPECT_EQ(m.status, Status::success);
    EXPECT_TRUE(m.map.edges.empty());
    Road_map_options keep;
    keep.prune_height = 0;
    const Road_map k = extract_road_map(one, keep);
    ASSERT_EQ(k.map.positions.size(), 1u);
    EXPECT_EQ(k.map.positions[0], (std::array<double, 2>{5, 5}));
  }
}

TEST(RoadMap, ProgressIsMonotoneAndCancelStops) {
  const Synthetic_city city = small_city();
  Road_map_options o;
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  const Road_map m = extract_road_map(city.trips, o);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1], seen[i]);
  EXPECT_EQ(m.map.positions, extract_road_map(city.trips).map.positions);
  // The neighbourhood graph reports between 0.1 and 0.15, and a stop there ends the pipeline.
  EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double t) { return t > 0.1 && t < 0.15; }));
  for (const double stop_at : {0.0, 0.05, 0.12, 0.15, 0.3, 0.4, 0.95}) {
    o.progress = [stop_at](double t) { return t < stop_at; };
    const Road_map c = extract_road_map(city.trips, o);
    EXPECT_EQ(c.status, Status::interrupted) << stop_at;
    EXPECT_TRUE(c.map.positions.empty());
  }
}

namespace {
/// Straight lines y = offset[k] from x = 0 to x = length, each a chain of 10 m edges; optionally joined at
/// both ends by short vertical edges (one street drawn once per direction).
Embedded_graph_2 parallel_lines(const std::vector<double>& offsets, double length, bool joined) {
  Embedded_graph_2 g;
  std::vector<Vertex_index> first, last;
  for (const double y : offsets) {
    const auto n = static_cast<std::size_t>(length / 10);
    for (std::size_t i = 0; i <= n; ++i) {
      g.positions.push_back({10.0 * double(i), y});
      if (i > 0)
        g.edges.push_back({Vertex_index(g.positions.size() - 2), Vertex_index(g.positions.size() - 1)});
    }
    first.push_back(Vertex_index(g.positions.size() - n - 1));
    last.push_back(Vertex_index(g.positions.size() - 1));
  }
  if (joined)
    for (std::size_t k = 1; k < offsets.size(); ++k) {
      g.edges.push_back({first[k - 1], first[k]});
      g.edges.push_back({last[k], last[k - 1]});  // reversed on purpose
    }
  return g;
}

double map_length(const Embedded_graph_2& g) {
  double L = 0;
  for (const Edge& e : g.edges)
    L += std::hypot(g.positions[e[0]][0] - g.positions[e[1]][0], g.positions[e[0]][1] - g.positions[e[1]][1]);
  return L;
}

std::size_t map_components(const Embedded_graph_2& g) {
  std::vector<std::size_t> parent(g.positions.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t c = parent.size();
  for (const Edge& e : g.edges)
    if (find(e[0]) != find(e[1])) {
      parent[find(e[0])] = find(e[1]);
      --c;
    }
  return c;
}
}  // namespace

TEST(MergeRoadLines, TwoDirectionsOfAStreetBecomeOneLineInTheMiddle) {
  for (const bool joined : {false, true}) {
    const Embedded_graph_2 street = parallel_lines({0.0, 4.0}, 300, joined);
    const Road_merge_result r = merge_road_lines(street);
    ASSERT_EQ(r.status, Status::success);
    EXPECT_NEAR(r.length_before, joined ? 608 : 600, 1e-9);
    EXPECT_EQ(map_components(r.map), 1u) << joined;
    // One line of about the street's length, every vertex between the two input lines and near the middle.
    EXPECT_NEAR(r.length_after, 300, 15) << joined;
    EXPECT_NEAR(map_length(r.map), r.length_after, 1e-9);
    // (The ends are the extrema of the geodesic function, single points of either line.)
    for (const auto& p : r.map.positions) {
      EXPECT_GE(p[1], -1e-9);
      EXPECT_LE(p[1], 4 + 1e-9);
      if (p[0] > 20 && p[0] < 280) {
        EXPECT_NEAR(p[1], 2.0, 1.0) << p[0];
      }
      EXPECT_GE(p[0], -1e-9);
      EXPECT_LE(p[0], 300 + 1e-9);
    }
    // No loop is left: a tree (edges = vertices - components).
    EXPECT_EQ(r.map.edges.size() + map_components(r.map), r.map.positions.size()) << joined;
    EXPECT_EQ(r.spacing, 8.0 / 3);
    EXPECT_EQ(r.delta, 8.0);
  }
}

// A map drawn with vertices centimetres apart (a skeleton at a small radius) is thinned to half the spacing
// before the neighbourhood is built: the same one line as the sparse map, from about as many samples (each of
// the 60,000 vertices was a sample, and the neighbourhood graph held 800 neighbours each: 35 s and 4.4 GB in
// the CLI).
TEST(MergeRoadLines, AMapWithVerticesCentimetresApartIsThinnedFirst) {
  Embedded_graph_2 dense;
  for (const double y : {0.0, 4.0})
    for (int i = 0; i <= 30000; ++i) {
      dense.positions.push_back({0.01 * i, y});
      if (i > 0)
        dense.edges.push_back(
            {Vertex_index(dense.positions.size() - 2), Vertex_index(dense.positions.size() - 1)});
    }
  const Road_merge_result sparse = merge_road_lines(parallel_lines({0.0, 4.0}, 300, false));
  const Road_merge_result r = merge_road_lines(dense);
  ASSERT_EQ(r.status, Status::success);
  EXPECT_LE(r.samples, 2 * sparse.samples);  // about 300 / 2 + 1 per line, not 60,002
  EXPECT_EQ(map_components(r.map), 1u);
  EXPECT_NEAR(r.length_after, sparse.length_after, 5);
  EXPECT_NEAR(r.length_before, 600, 1e-6);
  for (const auto& p : r.map.positions)
    if (p[0] > 20 && p[0] < 280) {
      EXPECT_NEAR(p[1], 2.0, 1.0) << p[0];
    }
}

// Chains of degree-2 vertices keep a vertex every `min_step` along them; junctions, ends and isolated
// vertices stay; a cycle of degree-2 vertices keeps its smallest index; no vertex dropped: no edges returned.
TEST(MergeRoadLines, ThinningKeepsJunctionsAndEnds) {
  Embedded_graph_2 g;
  // A T: a line along x (0..10 by 0.25) with a branch up from x = 5 (0.25 steps to y = 3), a square cycle of
  // side 0.5 elsewhere, and an isolated vertex.
  for (int i = 0; i <= 40; ++i) g.positions.push_back({0.25 * i, 0});  // vertices 0..40, junction 20 (x = 5)
  for (int i = 1; i <= 12; ++i) g.positions.push_back({5, 0.25 * i});  // 41..52
  std::vector<Edge> edges;
  for (Vertex_index i = 0; i < 40; ++i) edges.push_back({i, i + 1});
  edges.push_back({20, 41});
  for (Vertex_index i = 41; i < 52; ++i) edges.push_back({i, i + 1});
  const Vertex_index square = Vertex_index(g.positions.size());  // 53..56
  for (const auto& p : {std::array<double, 2>{20, 0}, {20.5, 0}, {20.5, 0.5}, {20, 0.5}})
    g.positions.push_back(p);
  for (Vertex_index k = 0; k < 4; ++k)
    edges.push_back({std::min<Vertex_index>(square + k, square + (k + 1) % 4),
                     std::max<Vertex_index>(square + k, square + (k + 1) % 4)});
  g.positions.push_back({50, 50});  // isolated: 57
  std::sort(edges.begin(), edges.end());
  std::vector<char> kept;
  const std::vector<Edge> thinned =
      FeatureRecon::skeleton::internal::thin_map_chains(g.positions, edges, 1.0, kept);
  // Along x: 0, 1, 2, 3, 4, then the junction (5) ... every fourth vertex, as along the branch.
  for (Vertex_index v : {0u, 4u, 8u, 12u, 16u, 20u, 24u, 28u, 32u, 36u, 40u, 44u, 48u, 52u, 53u, 55u, 57u})
    EXPECT_TRUE(kept[v]) << v;
  for (Vertex_index v : {1u, 2u, 3u, 21u, 39u, 41u, 51u, 54u, 56u}) EXPECT_FALSE(kept[v]) << v;
  EXPECT_EQ(std::count(kept.begin(), kept.end(), 1), 17);
  // Edges join consecutive kept vertices; the square becomes one edge between its two kept corners.
  const std::vector<Edge> expected = {{0, 4},   {4, 8},   {8, 12},  {12, 16}, {16, 20}, {20, 24}, {20, 44},
                                      {24, 28}, {28, 32}, {32, 36}, {36, 40}, {44, 48}, {48, 52}, {53, 55}};
  EXPECT_EQ(thinned, expected);
  // Vertices already farther apart than the step: nothing dropped, no edges returned.
  EXPECT_TRUE(FeatureRecon::skeleton::internal::thin_map_chains(g.positions, edges, 0.2, kept).empty());
  EXPECT_EQ(std::count(kept.begin(), kept.end(), 1), 58);
}

// Greedy contraction against brute force: points on a half-unit lattice (duplicates and ties at exactly h)
// and continuous ones; every removed point joins the nearest earlier kept point closer than h (ties: smaller
// index).
TEST(MergeRoadLines, ContractCloseSamplesEqualsBruteForce) {
  std::mt19937_64 rng(11);
  for (const double h : {1.0, 0.5, 2.5}) {
    Point_matrix P;
    P.dimension = 2;
    for (int i = 0; i < 400; ++i) {
      const bool lattice = i % 4 != 3;
      const double x = lattice ? 0.5 * double(rng() % 13) : 6.0 * double(rng() % 100000) / 100000.0;
      const double y = lattice ? 0.5 * double(rng() % 13) : 6.0 * double(rng() % 100000) / 100000.0;
      P.data.insert(P.data.end(), {x, y});
      ++P.rows;
    }
    std::vector<Edge> edges;
    for (int k = 0; k < 600; ++k) {
      const auto a = Vertex_index(rng() % P.rows), b = Vertex_index(rng() % P.rows);
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
    // Brute force.
    std::vector<std::size_t> kept, to(P.rows);
    for (std::size_t i = 0; i < P.rows; ++i) {
      std::size_t best = P.rows;
      double best_d2 = h * h;
      for (std::size_t k : kept) {
        const double dx = P.data[2 * i] - P.data[2 * k], dy = P.data[2 * i + 1] - P.data[2 * k + 1];
        const double d2 = dx * dx + dy * dy;
        if (d2 < best_d2) {  // kept is increasing: the first of equal distances is the smaller index
          best = k;
          best_d2 = d2;
        }
      }
      to[i] = best < P.rows ? best : i;
      if (best == P.rows) kept.push_back(i);
    }
    std::vector<Vertex_index> index(P.rows);
    for (std::size_t k = 0; k < kept.size(); ++k) index[kept[k]] = Vertex_index(k);
    std::vector<Edge> expected_edges;
    for (const Edge& e : edges) {
      const Vertex_index a = index[to[e[0]]], b = index[to[e[1]]];
      if (a != b) expected_edges.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(expected_edges.begin(), expected_edges.end());
    expected_edges.erase(std::unique(expected_edges.begin(), expected_edges.end()), expected_edges.end());
    std::vector<double> expected_data;
    for (std::size_t k : kept) expected_data.insert(expected_data.end(), {P.data[2 * k], P.data[2 * k + 1]});

    const std::size_t removed = FeatureRecon::skeleton::internal::contract_close_samples(P, h, edges);
    EXPECT_EQ(removed, 400 - kept.size()) << h;
    EXPECT_GT(removed, 100u) << h;  // the lattice has at most 169 distinct points
    EXPECT_EQ(P.rows, kept.size()) << h;
    EXPECT_EQ(P.data, expected_data) << h;
    EXPECT_EQ(edges, expected_edges) << h;
    // The kept points are pairwise at least h apart.
    for (std::size_t i = 0; i < P.rows; ++i)
      for (std::size_t j = i + 1; j < P.rows; ++j)
        EXPECT_GE(std::hypot(P.data[2 * i] - P.data[2 * j], P.data[2 * i + 1] - P.data[2 * j + 1]), h)
            << i << " " << j;
  }
  // Nothing closer than h: nothing changes; a tiny h against the extent: left alone.
  Point_matrix Q;
  Q.dimension = 2;
  Q.rows = 2;
  Q.data = {0, 0, 1e17, 0};
  std::vector<Edge> e = {{0, 1}};
  EXPECT_EQ(FeatureRecon::skeleton::internal::contract_close_samples(Q, 1.0, e), 0u);
  EXPECT_EQ(FeatureRecon::skeleton::internal::contract_close_samples(Q, 1e-3, e), 0u);
  EXPECT_EQ(Q.rows, 2u);
  EXPECT_EQ(e, (std::vector<Edge>{{0, 1}}));
}

// Forty copies of one street, each with its own vertices (a skeleton's arcs that follow the same path across
// a gap), and a crossing street: sampled once, so the merge equals that of one copy (the copies' samples
// stacked 40 deep made cliques of 320 samples; the Chicago map at delta 1000 took 52 s and 6 GB, 0.9 s and 58
// MB now).
TEST(MergeRoadLines, StackedCopiesOfALineAreSampledOnce) {
  auto with_crossing = [](Embedded_graph_2 g) {
    for (int i = 0; i <= 20; ++i) {
      g.positions.push_back({150, -100.0 + 10.0 * i});
      if (i > 0)
        g.edges.push_back({Vertex_index(g.positions.size() - 2), Vertex_index(g.positions.size() - 1)});
    }
    return g;
  };
  const Road_merge_result one = merge_road_lines(with_crossing(parallel_lines({0.0}, 300, false)));
  const Road_merge_result stacked =
      merge_road_lines(with_crossing(parallel_lines(std::vector<double>(40, 0.0), 300, false)));
  ASSERT_EQ(stacked.status, Status::success);
  EXPECT_EQ(stacked.samples, one.samples);
  // each further copy: its 31 vertices and the 3 points inside each of its 30 edges of 10 m (spacing 8/3)
  EXPECT_EQ(stacked.samples_contracted, one.samples_contracted + 39 * (31 + 30 * 3));
  EXPECT_EQ(one.samples_contracted, 1u);  // the crossing's vertex at (150, 0)
  EXPECT_EQ(stacked.map.positions, one.map.positions);
  EXPECT_EQ(stacked.map.edges, one.map.edges);
  EXPECT_EQ(map_components(stacked.map), 1u);
  EXPECT_NEAR(stacked.length_after, 500, 25);
}

TEST(MergeRoadLines, AStopDuringTheRipsStageEndsTheRun) {
  // The callback says stop once (its second call, inside the Rips stage) and go on afterwards.
  int calls = 0;
  Road_merge_options o;
  o.progress = [&calls](double) { return ++calls != 2; };
  const Road_merge_result r = merge_road_lines(parallel_lines({0.0, 4.0}, 300, false), o);
  EXPECT_EQ(r.status, Status::interrupted);
  EXPECT_TRUE(r.map.positions.empty());
}

TEST(MergeRoadLines, LinesFartherApartStay) {
  // A divided road: carriageways 20 m apart (the default distance is 8 m); two streets, 12 m apart.
  for (const double gap : {20.0, 12.0}) {
    const Road_merge_result r = merge_road_lines(parallel_lines({0.0, gap}, 300, false));
    EXPECT_EQ(map_components(r.map), 2u) << gap;
    EXPECT_NEAR(r.length_after, 600, 30) << gap;
    for (const auto& p : r.map.positions)
      EXPECT_LT(std::min(std::fabs(p[1]), std::fabs(p[1] - gap)), 0.5) << gap;
  }
  // ... unless the distance asks for it.
  Road_merge_options o;
  o.distance = 13;
  EXPECT_EQ(map_components(merge_road_lines(parallel_lines({0.0, 12.0}, 300, false), o).map), 1u);
  // A spacing far above the distance does not contract samples of lines farther apart than the distance (half
  // the spacing, 20, would have made the two lines 15 apart one).
  o = {};
  o.spacing = 40;
  const Road_merge_result sparse = merge_road_lines(parallel_lines({0.0, 15.0}, 300, false), o);
  EXPECT_EQ(map_components(sparse.map), 2u);
  EXPECT_EQ(sparse.samples_contracted, 0u);
  // The complex's triangle limit is the merge's own option.
  o = {};
  o.max_triangles = 1;
  const std::string m = message_of([&] { merge_road_lines(parallel_lines({0.0, 4.0}, 300, false), o); });
  EXPECT_TRUE(contains(m, "has more than 1 triangles (max_triangles of the options"));
}

TEST(MergeRoadLines, DegenerateInputAndDeterminism) {
  const Road_merge_result empty = merge_road_lines({});
  EXPECT_EQ(empty.status, Status::degenerate_input);
  EXPECT_TRUE(empty.map.positions.empty());
  // A lone vertex stays a node; repeated, reversed and degenerate edges count once.
  Embedded_graph_2 one;
  one.positions = {{3, 4}};
  one.edges = {{0, 0}};
  const Road_merge_result r1 = merge_road_lines(one);
  EXPECT_EQ(r1.status, Status::success);
  ASSERT_EQ(r1.map.positions.size(), 1u);
  EXPECT_EQ(r1.map.positions[0], (std::array<double, 2>{3, 4}));
  EXPECT_TRUE(r1.map.edges.empty());
  Embedded_graph_2 twice;
  twice.positions = {{0, 0}, {50, 0}, {0, 0}};  // a duplicate vertex too
  twice.edges = {{0, 1}, {1, 0}, {0, 1}, {2, 1}};
  const Road_merge_result r2 = merge_road_lines(twice);
  EXPECT_NEAR(r2.length_before, 100, 1e-9);  // (0, 1) once, (2, 1) once
  EXPECT_NEAR(r2.length_after, 50, 1);
  EXPECT_EQ(map_components(r2.map), 1u);
  // Collinear chains on a grid of ties: bit-identical on a second run.
  const Embedded_graph_2 grid = parallel_lines({0.0, 3.0, 6.0, 30.0}, 100, true);
  const Road_merge_result a = merge_road_lines(grid), b = merge_road_lines(grid);
  EXPECT_EQ(a.map.positions, b.map.positions);
  EXPECT_EQ(a.map.edges, b.map.edges);
}

TEST(MergeRoadLines, BadInputIsNamedAndCancelStops) {
  const Embedded_graph_2 street = parallel_lines({0.0, 4.0}, 100, false);
  Road_merge_options o;
  o.distance = 0;
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(street, o); }), "distance"));
  o.distance = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(street, o); }), "distance"));
  o = {};
  o.spacing = -1;
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(street, o); }), "spacing"));
  o.spacing = 0;  // automatic before FeatureRecon::automatic
  EXPECT_EQ(
      message_of([&] { merge_road_lines(street, o); }),
      "merge_road_lines: spacing must be finite and > 0 (FeatureRecon::automatic: distance / 3), got 0");
  o = {};
  o.delta = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(street, o); }), "delta"));
  o.delta = -1;
  EXPECT_EQ(message_of([&] { merge_road_lines(street, o); }),
            "merge_road_lines: delta must be finite and >= 0 (FeatureRecon::automatic: distance; 0: no "
            "simplification), got -1");
  // Automatic values are the documented ones: distance / 3 and distance.
  o = {};
  const Road_merge_result defaults = merge_road_lines(street, o);
  EXPECT_DOUBLE_EQ(defaults.spacing, 8.0 / 3);
  EXPECT_DOUBLE_EQ(defaults.delta, 8.0);
  // A complex above max_triangles is refused as this stage's, with what to change here.
  o = {};
  o.max_triangles = 100;
  const std::string big = message_of([&] { merge_road_lines(street, o); });
  EXPECT_EQ(big.rfind("merge_road_lines: the complex of the lines' 8 neighbourhood (", 0), 0u) << big;
  EXPECT_TRUE(contains(big, ") has more than 100 triangles (max_triangles of the options;"));
  const std::string advice = "): raise spacing or lower distance, or raise max_triangles";
  ASSERT_GT(big.size(), advice.size());
  EXPECT_EQ(big.substr(big.size() - advice.size()), advice) << big;
  // Other errors of the stages inside pass as they are.
  o = {};
  o.embedding.level_width = -1;
  const std::string embedding = message_of([&] { merge_road_lines(street, o); });
  EXPECT_EQ(embedding.rfind("extract_reeb_skeleton: ", 0), 0u) << embedding;
  EXPECT_TRUE(contains(embedding, "level_width"));
  Embedded_graph_2 bad = street;
  bad.edges[3] = {0, 99};
  const std::string m = message_of([&] { merge_road_lines(bad); });
  EXPECT_TRUE(contains(m, "edge 3"));
  bad = street;
  bad.positions[5][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(bad); }), "vertex 5"));
  // A far-off vertex: an edge of 2e9 m would be sampled every 2.7 m (750 million points), one of 2e308 m
  // overflows. Both are refused before any sampling, naming the edge; max_samples 0 lifts the limit.
  bad = street;
  bad.positions[5] = {1e9, 0};
  bad.positions[6] = {-1e9, 0};
  bad.edges.push_back({5, 6});
  std::string far = message_of([&] { merge_road_lines(bad); });
  EXPECT_TRUE(
      contains(far,
               "points, more than max_samples (67108864); the longest edge, from (1e+09, 0) to (-1e+09, 0), "
               "is 2e+09"));
  o = {};
  o.spacing = 1e5;
  EXPECT_EQ(merge_road_lines(bad, o).status, Status::success);  // 20,000 samples
  o.spacing = 100;
  o.max_samples = 1000;
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(bad, o); }), "max_samples (1000)"));
  // The limit counts the points inserted along edges, not the vertices: a 1,000 km edge at spacing 100 m
  // takes 9,999.
  Embedded_graph_2 one_edge;
  one_edge.positions = {{0, 0}, {1e6, 0}};
  one_edge.edges = {{0, 1}};
  o.max_samples = 9999;
  EXPECT_EQ(merge_road_lines(one_edge, o).status, Status::success);
  o.max_samples = 9998;
  EXPECT_TRUE(contains(message_of([&] { merge_road_lines(one_edge, o); }),
                       "would insert about 9999 points, more than "
                       "max_samples (9998)"));
  bad.positions[5] = {1e308, 0};
  bad.positions[6] = {-1e308, 0};
  far = message_of([&] { merge_road_lines(bad); });
  EXPECT_TRUE(contains(far, "the edge from (1e+308, 0) to (-1e+308, 0) has a length that overflows"));
  for (const double stop_at : {0.0, 0.2, 0.5}) {
    o = {};
    o.progress = [stop_at](double t) { return t < stop_at; };
    const Road_merge_result r = merge_road_lines(street, o);
    EXPECT_EQ(r.status, Status::interrupted) << stop_at;
    EXPECT_TRUE(r.map.positions.empty());
  }
}

TEST(MergeRoadLines, ThinLoopsAreRemoved) {
  // Two arcs between the same nodes whose sides lie within the distance: one goes, the shorter stays.
  Skeleton_graph g(2);
  g[0].position = {0, 0, 0};
  g[1].position = {40, 0, 0};
  g[0].members = {0};
  g[1].members = {1};
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {20, 3, 0}, {40, 0, 0}}, {2, 3}, {}, 0, 1}, g);
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {20, 0, 0}, {40, 0, 0}}, {4}, {}, 0, 1}, g);
  Skeleton_graph wide = g;
  EXPECT_EQ(skeleton::internal::remove_thin_loops(g, 5), 1u);
  ASSERT_EQ(num_edges(g), 1u);
  const auto e = *edges(g).first;
  EXPECT_EQ(g[e].polyline[1][1], 0.0);
  std::vector<Vertex_index> members = g[e].members;
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<Vertex_index>{2, 3, 4}));
  EXPECT_EQ(skeleton::internal::remove_thin_loops(wide, 2.5), 0u);  // 3 m apart: a loop of its own
  EXPECT_EQ(num_edges(wide), 2u);
  // An arc beside a path through a kink node of degree 2: the longer side (the path) goes with its node.
  Skeleton_graph t(3);
  for (std::size_t v = 0; v < 3; ++v) t[v].members = {Vertex_index(v)};
  t[0].position = {0, 0, 0};
  t[1].position = {40, 0, 0};
  t[2].position = {20, 4, 0};
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {40, 0, 0}}, {}, {}, 0, 1}, t);
  add_edge(0, 2, Skeleton_arc{{{0, 0, 0}, {20, 4, 0}}, {}, {}, 0, 2}, t);
  add_edge(2, 1, Skeleton_arc{{{20, 4, 0}, {40, 0, 0}}, {}, {}, 2, 1}, t);
  EXPECT_EQ(skeleton::internal::remove_thin_loops(t, 5), 1u);
  EXPECT_EQ(num_vertices(t), 2u);
  EXPECT_EQ(num_edges(t), 1u);
  // The same with the kink numbered between the ends: removing it renumbers the far end, and the arc's
  // Skeleton_arc::lower / upper follow (they named vertex 2, now out of range).
  Skeleton_graph k(3);
  for (std::size_t v = 0; v < 3; ++v) k[v].members = {Vertex_index(v)};
  k[0].position = {0, 0, 0};
  k[1].position = {20, 4, 0};
  k[2].position = {40, 0, 0};
  add_edge(0, 2, Skeleton_arc{{{0, 0, 0}, {40, 0, 0}}, {}, {}, 0, 2}, k);
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {20, 4, 0}}, {}, {}, 0, 1}, k);
  add_edge(1, 2, Skeleton_arc{{{20, 4, 0}, {40, 0, 0}}, {}, {}, 1, 2}, k);
  EXPECT_EQ(skeleton::internal::remove_thin_loops(k, 5), 1u);
  ASSERT_EQ(num_vertices(k), 2u);
  ASSERT_EQ(num_edges(k), 1u);
  const auto kept = *edges(k).first;
  EXPECT_EQ(k[kept].lower, 0u);
  EXPECT_EQ(k[kept].upper, 1u);
  EXPECT_EQ(arc_polyline_from(k, kept, 1).front(), k[1].position);
}

// Whether the closed segments pq and rs share a point (exact orientation tests on the doubles, CGAL's).
bool segments_meet(const std::array<double, 2>& p, const std::array<double, 2>& q,
                   const std::array<double, 2>& r, const std::array<double, 2>& s) {
  using Point = CGAL::Epick::Point_2;
  return CGAL::do_intersect(CGAL::Epick::Segment_2(Point(p[0], p[1]), Point(q[0], q[1])),
                            CGAL::Epick::Segment_2(Point(r[0], r[1]), Point(s[0], s[1])));
}

TEST(SyntheticCity, StreetsAndTrips) {
  Synthetic_city_options o;
  o.noise = 0;
  o.trip_bias = 0;
  o.trips = 40;
  const Synthetic_city c = make_synthetic_city(o);
  const std::size_t grid = (o.columns - 1) * o.rows + o.columns * (o.rows - 1);
  EXPECT_EQ(c.streets.positions.size(), o.columns * o.rows);
  EXPECT_EQ(c.streets.edges.size(), grid - std::size_t(std::floor(o.missing_streets * double(grid))) +
                                        std::min(o.columns, o.rows) - 1);
  EXPECT_LE(c.driven.edges.size(), c.streets.edges.size());
  EXPECT_EQ(c.trips.size(), o.trips);
  // Without noise and bias every fix lies lane_offset from a driven street, and consecutive fixes are at most
  // speed x interval apart (1.3 speed at most) along the route.
  std::size_t fixes = 0;
  for (const Gps_trip& t : c.trips) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      double d = std::numeric_limits<double>::infinity();
      for (const Edge& e : c.driven.edges)
        d = std::min(d,
                     segment_distance({t[i].x, t[i].y}, c.driven.positions[e[0]], c.driven.positions[e[1]]));
      EXPECT_LE(d, o.lane_offset + 1e-9);
      if (i > 0) {
        EXPECT_LT(t[i - 1].time, t[i].time);
        EXPECT_LE(std::hypot(t[i].x - t[i - 1].x, t[i].y - t[i - 1].y),
                  1.3 * o.speed * o.sampling_interval + 1e-9);
      }
    }
    fixes += t.size();
  }
  EXPECT_GT(fixes, 10 * o.trips);
  // Deterministic for a seed; another seed gives another city.
  const Synthetic_city again = make_synthetic_city(o);
  EXPECT_EQ(again.streets.positions, c.streets.positions);
  ASSERT_EQ(again.trips.size(), c.trips.size());
  for (std::size_t t = 0; t < c.trips.size(); ++t)
    for (std::size_t i = 0; i < c.trips[t].size(); ++i) EXPECT_EQ(again.trips[t][i].x, c.trips[t][i].x);
  // Progress: 0, then before each trip 0.05 + 0.95 t / trips, then 1. A stop before trip 10 keeps the first
  // ten trips as they were and the streets they drove.
  std::vector<double> seen;
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  EXPECT_EQ(make_synthetic_city(o).status, Status::success);
  ASSERT_EQ(seen.size(), o.trips + 2);
  EXPECT_EQ(seen[0], 0.0);
  EXPECT_EQ(seen[1], 0.05);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  int calls = 0;
  o.progress = [&](double) { return ++calls <= 11; };  // the start and trips 0-9
  const Synthetic_city part = make_synthetic_city(o);
  EXPECT_EQ(part.status, Status::interrupted);
  ASSERT_EQ(part.trips.size(), 10u);
  for (std::size_t t = 0; t < 10; ++t) EXPECT_EQ(part.trips[t].size(), c.trips[t].size());
  EXPECT_LT(part.driven.edges.size(), c.driven.edges.size());
  for (const Edge& e : part.driven.edges)
    EXPECT_TRUE(std::find(c.driven.edges.begin(), c.driven.edges.end(), e) != c.driven.edges.end());
  o.layout = Synthetic_city_layout::organic;  // a stop at the start: no streets, no trips
  o.progress = [](double) { return false; };
  const Synthetic_city none = make_synthetic_city(o);
  EXPECT_EQ(none.status, Status::interrupted);
  EXPECT_TRUE(none.streets.positions.empty() && none.trips.empty());
  o.layout = Synthetic_city_layout::grid;
  o.progress = nullptr;
  o.seed = 2;
  EXPECT_NE(make_synthetic_city(o).streets.positions, c.streets.positions);
  // Bad options are named.
  Synthetic_city_options b;
  b.columns = 1;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "columns"));
  b = {};
  b.sampling_interval = 0;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "sampling_interval"));
  b = {};
  b.missing_streets = 1.5;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "missing_streets"));
  b = {};
  b.noise = -1;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "noise"));
  // Limits found before the work (10^8 trips ran 31 s to reach the limit on fixes) or at the first fix out of
  // range (a noise of 1e308 wrote inf into the tracks).
  b = {};
  b.trips = (std::size_t(1) << 26) + 1;
  EXPECT_EQ(
      message_of([&] { make_synthetic_city(b); }),
      "make_synthetic_city: trips must be at most 2^26 (the most fixes the trips may record), got 67108865");
  b = {};
  b.noise = 1e308;
  EXPECT_EQ(
      message_of([&] { make_synthetic_city(b); }),
      "make_synthetic_city: fix 0 of trip 0 lies beyond the largest double: noise (1e+308), trip_bias (2) or "
      "lane_offset (2) too large");
  b.noise = 4;
  b.trip_bias = 1e308;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "trip_bias (1e+308)"));
  // Jitter at its largest: without the diagonal avenue half the shorter block side (90 / 2 = 45), with it
  // 120 x 90 / (2 x 210) = 25.71 (at 35 and 45 the avenue crossed streets in 13 and 34 of 200 cities). At the
  // limit no two streets without a common intersection meet, in 40 cities each (exact predicates); the
  // intersections keep their order. Beyond, refused naming the rule; a lane offset beyond half a block too.
  ASSERT_TRUE(segments_meet({0, 0}, {2, 2}, {0, 2}, {2, 0}));  // the check itself: a crossing, a touch
  ASSERT_TRUE(segments_meet({0, 0}, {2, 2}, {1, 1}, {3, 0}));
  ASSERT_FALSE(segments_meet({0, 0}, {2, 2}, {1, 1.001}, {0, 3}));
  for (const bool diagonal : {true, false}) {
    b = {};
    b.trips = 0;
    b.missing_streets = 0;
    b.diagonal = diagonal;
    EXPECT_NEAR(synthetic_city_max_jitter(b), diagonal ? 120.0 * 90.0 / (2 * 210.0) : 45.0, 1e-12);
    b.jitter = synthetic_city_max_jitter(b);  // the limits as the callers may ask for them
    b.lane_offset = 45;
    EXPECT_EQ(synthetic_city_max_lane_offset(b), 45.0);
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      b.seed = seed;
      const Synthetic_city city = make_synthetic_city(b);
      const auto& P = city.streets.positions;
      const auto& E = city.streets.edges;
      for (std::size_t j = 0; j < b.rows; ++j)
        for (std::size_t i = 0; i + 1 < b.columns; ++i) {
          EXPECT_LT(P[j * b.columns + i][0], P[j * b.columns + i + 1][0]) << seed;
          if (j + 1 < b.rows) {
            EXPECT_LT(P[j * b.columns + i][1], P[(j + 1) * b.columns + i][1]) << seed;
          }
        }
      for (std::size_t e = 0; e < E.size(); ++e)
        for (std::size_t f = e + 1; f < E.size(); ++f) {
          if (E[e][0] == E[f][0] || E[e][0] == E[f][1] || E[e][1] == E[f][0] || E[e][1] == E[f][1]) continue;
          EXPECT_FALSE(segments_meet(P[E[e][0]], P[E[e][1]], P[E[f][0]], P[E[f][1]]))
              << "seed " << seed << ", streets " << e << " and " << f << (diagonal ? " (avenue)" : "");
        }
    }
  }
  b.diagonal = true;
  b.jitter = 26;
  EXPECT_EQ(message_of([&] { make_synthetic_city(b); }),
            "make_synthetic_city: jitter must be at most 25.7143 (block_width x block_height / (2 "
            "(block_width + block_height)), with the diagonal avenue), got 26: intersections would pass each "
            "other and streets cross");
  b.diagonal = false;
  b.jitter = 45.5;  // 1e5 made 3.7 million fixes on streets that crossed
  EXPECT_EQ(
      message_of([&] { make_synthetic_city(b); }),
      "make_synthetic_city: jitter must be at most 45 (half the shorter of block_width and block_height), "
      "got 45.5: intersections would pass each other and streets cross");
  b.layout = Synthetic_city_layout::organic;  // no jitter there
  EXPECT_EQ(make_synthetic_city(b).status, Status::success);
  EXPECT_EQ(synthetic_city_max_jitter(b), std::numeric_limits<double>::infinity());
  Synthetic_city_options tiny;  // blocks of 1e-300: w h underflowed to a limit of 0
  tiny.block_width = tiny.block_height = 1e-300;
  EXPECT_DOUBLE_EQ(synthetic_city_max_jitter(tiny), 2.5e-301);
  b.lane_offset = 1e5;
  EXPECT_EQ(
      message_of([&] { make_synthetic_city(b); }),
      "make_synthetic_city: lane_offset must be at most half the shorter of block_width and block_height "
      "(45), got 100000: the lanes would lie nearer the parallel streets");
  // A huge rotation is a rotation (1e308 degrees times pi overflowed: every intersection was NaN).
  b = {};
  b.trips = 3;
  b.rotation = 1e308;
  const Synthetic_city turned = make_synthetic_city(b);
  for (const auto& p : turned.streets.positions) EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]));
  b.rotation = std::fmod(1e308, 360.0);
  EXPECT_EQ(make_synthetic_city(b).streets.positions, turned.streets.positions);
}

TEST(SyntheticCity, StreetRemovalEqualsTheGreedySearch) {
  // The union-find removal against the definition: try the edges in order, remove one when a search finds the
  // rest still connected, until `count` are gone. Random multigraphs (loops, parallel edges, disconnected
  // ones).
  std::mt19937_64 rng(5);
  for (int round = 0; round < 400; ++round) {
    const std::size_t n = 1 + rng() % 9, m = rng() % 20;
    std::vector<Edge> edges;
    for (std::size_t k = 0; k < m; ++k)
      edges.push_back({static_cast<Vertex_index>(rng() % n), static_cast<Vertex_index>(rng() % n)});
    std::vector<std::size_t> order(m);
    for (std::size_t k = 0; k < m; ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), rng);
    const std::size_t count = rng() % (m + 2);
    std::vector<char> expected(m, 0);
    auto connected = [&]() {  // relabel until every edge's ends agree: one label left means connected
      std::vector<std::size_t> label(n);
      for (std::size_t v = 0; v < n; ++v) label[v] = v;
      for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < m; ++k)
          if (!expected[k] && label[edges[k][0]] != label[edges[k][1]]) {
            label[edges[k][0]] = label[edges[k][1]] = std::min(label[edges[k][0]], label[edges[k][1]]);
            changed = true;
          }
      }
      return std::all_of(label.begin(), label.end(), [](std::size_t l) { return l == 0; });
    };
    for (std::size_t k = 0, done = 0; k < m && done < count; ++k) {
      expected[order[k]] = 1;
      if (connected())
        ++done;
      else
        expected[order[k]] = 0;
    }
    EXPECT_EQ(skeleton::internal::remove_keeping_connected(n, edges, order, count), expected)
        << "round " << round << ", n " << n << ", m " << m << ", count " << count;
  }
}

TEST(SyntheticCity, GabrielEdgesOfDegenerateInput) {
  using skeleton::internal::gabriel_edges;
  EXPECT_TRUE(gabriel_edges({}).empty());
  EXPECT_TRUE(gabriel_edges({{1, 2}}).empty());
  EXPECT_EQ(gabriel_edges({{0, 0}, {3, 4}}), (std::vector<Edge>{{0, 1}}));
  // Collinear: the middle point lies in the outer pair's disc.
  EXPECT_EQ(gabriel_edges({{0, 0}, {2, 0}, {1, 0}}), (std::vector<Edge>{{0, 2}, {1, 2}}));
  // A square: its sides, not its diagonals (each has the two other corners on its circle).
  EXPECT_EQ(gabriel_edges({{0, 0}, {1, 0}, {1, 1}, {0, 1}}),
            (std::vector<Edge>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  // A grid of 3 x 3: the 12 unit streets.
  std::vector<std::array<double, 2>> grid;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) grid.push_back({double(i), double(j)});
  const std::vector<Edge> g = gabriel_edges(grid);
  ASSERT_EQ(g.size(), 12u);
  for (const Edge& e : g)
    EXPECT_DOUBLE_EQ(std::hypot(grid[e[0]][0] - grid[e[1]][0], grid[e[0]][1] - grid[e[1]][1]), 1.0);
  // Duplicates are refused, naming both points.
  EXPECT_TRUE(contains(message_of([] {
                         gabriel_edges({{0, 0}, {1, 0}, {0, 0}, {0, 1}});
                       }),
                       "points 0 and 2 coincide"));
}

TEST(SyntheticCity, OrganicLayoutWithBentStreets) {
  Synthetic_city_options o;
  o.layout = Synthetic_city_layout::organic;
  o.curvature = 0.15;
  o.noise = 0;
  o.trip_bias = 0;
  o.trips = 60;
  const Synthetic_city c = make_synthetic_city(o);
  const std::size_t n = o.columns * o.rows;
  ASSERT_GT(c.streets.positions.size(), n);  // the bends' inner points follow the intersections
  // Intersections: in the rectangle, at least 0.6 sqrt(block area) apart, joined by streets of their Gabriel
  // graph (checked against all points) that form a connected network; inner points have degree 2.
  const double spacing = 0.6 * std::sqrt(o.block_width * o.block_height);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = c.streets.positions[i];
    EXPECT_GE(p[0], 0);
    EXPECT_LE(p[0], double(o.columns - 1) * o.block_width);
    EXPECT_GE(p[1], 0);
    EXPECT_LE(p[1], double(o.rows - 1) * o.block_height);
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GE(std::hypot(p[0] - c.streets.positions[j][0], p[1] - c.streets.positions[j][1]), spacing);
  }
  const std::vector<std::vector<Vertex_index>> adj = street_adjacency(c);
  for (std::size_t v = n; v < adj.size(); ++v) EXPECT_EQ(adj[v].size(), 2u) << v;
  // Walk each street from an intersection to the next: its middle lies at most curvature x chord off the
  // chord, and its ends form a Gabriel pair.
  const std::vector<std::vector<Vertex_index>> lines = street_lines(adj, n);
  const std::size_t streets = lines.size();
  std::size_t bent = 0;
  for (const std::vector<Vertex_index>& line : lines) {
    const Vertex_index a = line.front(), b = line.back();
    const auto& P = c.streets.positions;
    const double L = std::hypot(P[b][0] - P[a][0], P[b][1] - P[a][1]);
    double off = 0;
    for (const Vertex_index v : line) off = std::max(off, segment_distance(P[v], P[a], P[b]));
    EXPECT_LE(off, o.curvature * L + 1e-9);
    bent += off > 1;
    const std::array<double, 2> mid{(P[a][0] + P[b][0]) / 2, (P[a][1] + P[b][1]) / 2};
    for (Vertex_index w = 0; w < n; ++w)
      if (w != a && w != b) {
        EXPECT_GT(std::hypot(P[w][0] - mid[0], P[w][1] - mid[1]), L / 2) << a << "-" << b;
      }
  }
  EXPECT_GT(streets, n);         // more streets than a tree
  EXPECT_GT(bent, streets / 2);  // most streets bend
  std::vector<char> seen(n, 0);
  std::vector<Vertex_index> stack{0};
  seen[0] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const Vertex_index v = stack.back();
    stack.pop_back();
    for (const Vertex_index w0 : adj[v]) {
      Vertex_index prev = v, w = w0;
      while (w >= n) {
        const Vertex_index next = adj[w][0] == prev ? adj[w][1] : adj[w][0];
        prev = w;
        w = next;
      }
      if (!seen[w]) seen[w] = 1, ++reached, stack.push_back(w);
    }
  }
  EXPECT_EQ(reached, n);
  // Without noise every fix lies lane_offset from a driven street piece.
  for (const Gps_trip& t : c.trips)
    for (const Gps_fix& f : t) {
      double d = std::numeric_limits<double>::infinity();
      for (const Edge& e : c.driven.edges)
        d = std::min(d, segment_distance({f.x, f.y}, c.driven.positions[e[0]], c.driven.positions[e[1]]));
      EXPECT_LE(d, o.lane_offset + 1e-9);
    }
  // Deterministic for a seed.
  EXPECT_EQ(make_synthetic_city(o).streets.positions, c.streets.positions);
  Synthetic_city_options b;
  b.columns = std::size_t(1) << 32;  // the product would wrap around
  b.rows = std::size_t(1) << 32;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "columns x rows"));
  b = {};
  b.curvature = 0.6;
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "curvature"));
  b.curvature = std::nan("");
  EXPECT_TRUE(contains(message_of([&] { make_synthetic_city(b); }), "curvature"));
}

// Each option is checked at its documented bound and a bad one is named: the accepted ones stop at the
// first progress report (interrupted, no exception), before any work, so that the bounds on sizes cost
// nothing.
TEST(SyntheticCity, OptionsAreCheckedAtTheirDocumentedBounds) {
  const auto problem = [](const std::function<void(Synthetic_city_options&)>& set) {
    Synthetic_city_options o;
    o.progress = [](double) { return false; };
    set(o);
    return message_of([&] { EXPECT_EQ(make_synthetic_city(o).status, Status::interrupted); });
  };
  const std::string fn = "make_synthetic_city: ";
  EXPECT_EQ(problem([](auto& o) { o.rows = 1; }), fn + "columns and rows must be >= 2, got 8 and 1");
  EXPECT_EQ(problem([](auto& o) { o.columns = 4097, o.rows = 4096; }),
            fn + "columns x rows must be at most 2^24 intersections, got 4097 x 4096");
  EXPECT_EQ(problem([](auto& o) { o.columns = 4096, o.rows = 4096; }), "no exception");
  EXPECT_EQ(problem([](auto& o) { o.speed = 0; }), fn + "speed must be positive and finite, got 0");
  EXPECT_EQ(problem([](auto& o) { o.block_height = -90; }),
            fn + "block_height must be positive and finite, got -90");
  EXPECT_EQ(problem([](auto& o) { o.trip_bias = -1; }), fn + "trip_bias must be finite and >= 0, got -1");
  EXPECT_EQ(problem([](auto& o) { o.jitter = -1; }), fn + "jitter must be finite and >= 0, got -1");
  EXPECT_EQ(problem([](auto& o) { o.lane_offset = -2; }), fn + "lane_offset must be finite and >= 0, got -2");
  EXPECT_EQ(problem([](auto& o) { o.rotation = std::nan(""); }), fn + "rotation must be finite, got nan");
  EXPECT_EQ(problem([](auto& o) { o.missing_streets = -0.1; }),
            fn + "missing_streets must be in [0, 1], got -0.1");
  EXPECT_EQ(problem([](auto& o) { o.curvature = -0.1; }), fn + "curvature must be in [0, 0.5], got -0.1");
  for (const double bound : {0.0, 1.0}) {
    EXPECT_EQ(problem([&](auto& o) { o.missing_streets = bound; }), "no exception") << bound;
  }
  EXPECT_EQ(problem([](auto& o) { o.curvature = 0.5; }), "no exception");
  EXPECT_EQ(problem([](auto& o) { o.trips = std::size_t(1) << 26; }), "no exception");
}

namespace {
/// A grid city exactly on the axes (no jitter, rotation, avenue or missing street): intersection (i, j) at
/// (120 i, 90 j), so that a fix's street, lane and offsets can be read off its coordinates.
Synthetic_city_options axis_grid() {
  Synthetic_city_options o;
  o.columns = 5;
  o.rows = 4;
  o.jitter = 0;
  o.diagonal = false;
  o.missing_streets = 0;
  o.noise = 0;
  o.trip_bias = 0;
  o.trips = 100;
  return o;
}
}  // namespace

// Without noise or bias on the axis-aligned grid: a fix between two fixes on the same row (column) street
// lies lane_offset right of the direction of travel; fixes are sampling_interval apart in time from a random
// phase after 10000 k (trip k), at one speed per trip in [0.7, 1.3] x speed; every trip (between two
// intersections) records fixes. The seed drives the trips too: another seed, same streets here, other trips.
TEST(SyntheticCity, TripsKeepRightAtTheIntervalAndTheirSpeed) {
  const Synthetic_city_options o = axis_grid();
  const Synthetic_city c = make_synthetic_city(o);
  for (std::size_t j = 0; j < o.rows; ++j)
    for (std::size_t i = 0; i < o.columns; ++i) {
      EXPECT_EQ(c.streets.positions[j * o.columns + i], (std::array<double, 2>{120.0 * i, 90.0 * j}));
    }
  std::size_t along_rows[2] = {0, 0}, along_columns[2] = {0, 0};  // [west, east], [south, north]
  double slowest = std::numeric_limits<double>::infinity(), fastest = 0, first_phase = 1, last_phase = 0;
  ASSERT_EQ(c.trips.size(), o.trips);
  for (std::size_t k = 0; k < c.trips.size(); ++k) {
    const Gps_trip& t = c.trips[k];
    ASSERT_FALSE(t.empty()) << "trip " << k;
    const double phase = (t[0].time - 10000.0 * double(k)) / o.sampling_interval;
    EXPECT_GE(phase, 0) << "trip " << k;
    EXPECT_LT(phase, 1) << "trip " << k;
    first_phase = std::min(first_phase, phase);
    last_phase = std::max(last_phase, phase);
    for (std::size_t i = 1; i < t.size(); ++i) {
      EXPECT_NEAR(t[i].time - t[i - 1].time, o.sampling_interval, 1e-9) << "trip " << k << ", fix " << i;
      const double dx = t[i].x - t[i - 1].x, dy = t[i].y - t[i - 1].y;
      if ((dx == 0) == (dy == 0)) continue;  // around a corner
      const double speed = std::hypot(dx, dy) / o.sampling_interval;
      slowest = std::min(slowest, speed);
      fastest = std::max(fastest, speed);
      if (dy == 0) {
        ++along_rows[dx > 0];
        EXPECT_NEAR(std::remainder(t[i].y, o.block_height), dx > 0 ? -o.lane_offset : o.lane_offset, 1e-9);
      } else {
        ++along_columns[dy > 0];
        EXPECT_NEAR(std::remainder(t[i].x, o.block_width), dy > 0 ? o.lane_offset : -o.lane_offset, 1e-9);
      }
    }
  }
  for (const std::size_t n : {along_rows[0], along_rows[1], along_columns[0], along_columns[1]})
    EXPECT_GT(n, 50u);
  EXPECT_GE(slowest, 0.7 * o.speed - 1e-9);
  EXPECT_LE(fastest, 1.3 * o.speed + 1e-9);
  EXPECT_LT(slowest, 0.75 * o.speed);  // the range is used
  EXPECT_GT(fastest, 1.25 * o.speed);
  EXPECT_LT(first_phase, 0.1);
  EXPECT_GT(last_phase, 0.9);
  Synthetic_city_options other = o;
  other.seed = 2;
  const Synthetic_city d = make_synthetic_city(other);
  EXPECT_EQ(d.streets.positions, c.streets.positions);
  EXPECT_EQ(d.streets.edges, c.streets.edges);
  std::size_t different = 0;
  for (std::size_t k = 0; k < o.trips; ++k)
    different += d.trips[k].empty() || c.trips[k].empty() || d.trips[k][0].x != c.trips[k][0].x ||
                 d.trips[k][0].y != c.trips[k][0].y;
  EXPECT_GT(different, o.trips * 9 / 10);
}

// trip_bias: one constant offset per trip and coordinate, read off the fixes on column streets (x = 120 i +
// b_x) and on row streets (y = 90 j + b_y) without noise or lane offset: the same along each trip, different
// in x and y, of standard deviation trip_bias over the trips.
TEST(SyntheticCity, TripBiasIsOneOffsetPerTripAndCoordinate) {
  Synthetic_city_options o = axis_grid();
  o.lane_offset = 0;
  o.trip_bias = 2;
  o.trips = 200;
  const Synthetic_city c = make_synthetic_city(o);
  std::vector<double> bx, by;
  std::size_t distinct = 0;
  for (const Gps_trip& t : c.trips) {
    std::vector<double> x, y;
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (t[i].x == t[i - 1].x) x.push_back(std::remainder(t[i].x, o.block_width));
      if (t[i].y == t[i - 1].y) y.push_back(std::remainder(t[i].y, o.block_height));
    }
    for (const double v : x) EXPECT_NEAR(v, x.front(), 1e-9);
    for (const double v : y) EXPECT_NEAR(v, y.front(), 1e-9);
    if (!x.empty()) bx.push_back(x.front());
    if (!y.empty()) by.push_back(y.front());
    if (!x.empty() && !y.empty()) distinct += std::abs(x.front() - y.front()) > 0.01;
  }
  ASSERT_GT(bx.size(), 100u);
  ASSERT_GT(by.size(), 100u);
  EXPECT_GT(distinct, 90u);
  for (const std::vector<double>* b : {&bx, &by}) {
    double sum = 0, squares = 0;
    for (const double v : *b) sum += v, squares += v * v;
    const double mean = sum / double(b->size());
    EXPECT_NEAR(mean, 0, 0.5);
    EXPECT_NEAR(std::sqrt(squares / double(b->size()) - mean * mean), o.trip_bias, 0.4);
  }
}

// noise: each coordinate of a fix gets its own deviate of standard deviation `noise`. On the axis-aligned
// grid without bias or lane offset, a fix away from the intersections on a row street is off by its y noise
// (y - 90 j), one on a column street by its x noise (x - 120 i).
TEST(SyntheticCity, NoiseHasTheGivenDeviationInEachCoordinate) {
  Synthetic_city_options o = axis_grid();
  o.lane_offset = 0;
  o.noise = 4;
  o.trips = 800;
  const Synthetic_city c = make_synthetic_city(o);
  double squares[2] = {0, 0};
  std::size_t count[2] = {0, 0};  // row streets, column streets
  for (const Gps_trip& t : c.trips)
    for (const Gps_fix& f : t) {
      const double dx = std::remainder(f.x, o.block_width), dy = std::remainder(f.y, o.block_height);
      if (std::abs(dy) < 20 && std::abs(dx) >= 20) squares[0] += dy * dy, ++count[0];
      if (std::abs(dx) < 20 && std::abs(dy) >= 20) squares[1] += dx * dx, ++count[1];
    }
  for (int s = 0; s < 2; ++s) {
    ASSERT_GT(count[s], 500u) << s;
    EXPECT_NEAR(std::sqrt(squares[s] / double(count[s])), o.noise, 0.4) << (s == 0 ? "rows" : "columns");
  }
}

// Jitter moves each intersection within +-jitter of its grid place, both ways in x and y; rotation turns the
// whole grid rigidly by that many degrees (the direction is not documented: only the angle is checked).
TEST(SyntheticCity, JitterAndRotationOfTheGrid) {
  Synthetic_city_options o;
  o.trips = 0;
  const Synthetic_city c = make_synthetic_city(o);
  double low[2] = {0, 0}, high[2] = {0, 0};
  for (std::size_t j = 0; j < o.rows; ++j)
    for (std::size_t i = 0; i < o.columns; ++i) {
      const auto& p = c.streets.positions[j * o.columns + i];
      const double d[2] = {p[0] - o.block_width * double(i), p[1] - o.block_height * double(j)};
      for (int k = 0; k < 2; ++k) {
        EXPECT_LE(std::abs(d[k]), o.jitter) << i << " " << j;
        low[k] = std::min(low[k], d[k]);
        high[k] = std::max(high[k], d[k]);
      }
    }
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(low[k], -o.jitter / 2) << k;
    EXPECT_GT(high[k], o.jitter / 2) << k;
  }
  o.jitter = 0;
  for (const double degrees : {30.0, 90.0, -135.0}) {
    o.rotation = degrees;
    const auto& P = make_synthetic_city(o).streets.positions;
    const double cosine = std::cos(degrees * std::acos(-1.0) / 180);
    const double sine = std::sin(degrees * std::acos(-1.0) / 180);
    // Counterclockwise about the origin, where intersection (0, 0) stays. Along a row (i, 0) -> (i + 1, 0)
    // and a column (0, j) -> (0, j + 1): lengths kept, turned by `degrees`.
    EXPECT_NEAR(P[0][0], 0.0, 1e-12) << degrees;
    EXPECT_NEAR(P[0][1], 0.0, 1e-12) << degrees;
    EXPECT_NEAR(P[1][0] - P[0][0], o.block_width * cosine, 1e-9) << degrees;
    EXPECT_NEAR(P[1][1] - P[0][1], o.block_width * sine, 1e-9) << degrees;
    EXPECT_NEAR(P[o.columns][0] - P[0][0], -o.block_height * sine, 1e-9) << degrees;
    EXPECT_NEAR(P[o.columns][1] - P[0][1], o.block_height * cosine, 1e-9) << degrees;
    EXPECT_NEAR(std::hypot(P.back()[0] - P[0][0], P.back()[1] - P[0][1]),
                std::hypot(o.block_width * double(o.columns - 1), o.block_height * double(o.rows - 1)), 1e-9);
  }
}

// Bent streets: the middle of each lies up to curvature x its chord off the chord, either side, and the
// largest bends come near that bound; the polylines are drawn in pieces of at most 10 m.
TEST(SyntheticCity, BentStreetsReachTheirCurvatureInShortPieces) {
  Synthetic_city_options o;
  o.curvature = 0.5;  // the largest accepted
  o.trips = 0;
  const Synthetic_city c = make_synthetic_city(o);
  const auto& P = c.streets.positions;
  const std::size_t n = o.columns * o.rows;
  for (const Edge& e : c.streets.edges)
    EXPECT_LE(std::hypot(P[e[1]][0] - P[e[0]][0], P[e[1]][1] - P[e[0]][1]), 10 + 1e-9);
  double largest = 0;
  std::size_t sides[2] = {0, 0};
  const std::vector<std::vector<Vertex_index>> lines = street_lines(street_adjacency(c), n);
  const std::size_t streets = lines.size();
  for (const std::vector<Vertex_index>& line : lines) {
    const Vertex_index a = line.front(), b = line.back();
    const double L = std::hypot(P[b][0] - P[a][0], P[b][1] - P[a][1]);
    double off = 0, side = 0;
    for (const Vertex_index v : line) {
      const double d = segment_distance(P[v], P[a], P[b]);
      if (d > off)
        off = d, side = (P[b][0] - P[a][0]) * (P[v][1] - P[a][1]) - (P[b][1] - P[a][1]) * (P[v][0] - P[a][0]);
    }
    EXPECT_LE(off, o.curvature * L + 1e-9);
    largest = std::max(largest, off / (o.curvature * L));
    if (off > 1) ++sides[side > 0];
  }
  EXPECT_EQ(streets, c.streets.edges.size() - (P.size() - n));  // each inner point adds one piece
  EXPECT_GT(largest, 0.9);
  EXPECT_GT(sides[0], streets / 4);
  EXPECT_GT(sides[1], streets / 4);
}

// The stage helpers carry every field they name: the skeleton options take connect_dead_ends, trim_stubs,
// the branch merge distance, the triangle limit and the embedding; the merge options the triangle limit
// (Road_map_options::max_triangles is "of the skeleton and of the merging stage").
TEST(RoadMap, StageHelpersCopyTheirFields) {
  for (const bool on : {false, true}) {
    Road_map_options o;
    o.connect_dead_ends = on;
    o.trim_stubs = on;
    o.branch_merge_distance = on ? 7.5 : 0.0;
    o.max_triangles = on ? 12345 : 54321;
    o.embedding.smoothing_iterations = 5;
    const Road_map_options u = resolve_road_map_options(street(20), o);
    const Skeleton_options s = road_map_skeleton_options(u);
    EXPECT_EQ(s.connect_dead_ends, on);
    EXPECT_EQ(s.trim_stubs, on);
    EXPECT_EQ(s.branch_merge_distance, on ? 7.5 : 0.0);
    EXPECT_EQ(s.max_triangles, on ? 12345u : 54321u);
    EXPECT_EQ(s.embedding.smoothing_iterations, 5);
    const Road_merge_options m = road_map_merge_options(u);
    EXPECT_EQ(m.max_triangles, on ? 12345u : 54321u);
    EXPECT_EQ(m.distance, 8.0);
    EXPECT_FALSE(m.spacing.has_value());
    EXPECT_FALSE(m.delta.has_value());
  }
}

// The documented bounds are inclusive: min_radius may equal max_radius (0 < min_radius <= max_radius), and
// only a radius above 1e300 is refused.
TEST(RoadMap, ResolveAcceptsTheBoundaryValues) {
  Road_map_options o;
  o.min_radius = 15;
  o.max_radius = 15;
  EXPECT_DOUBLE_EQ(resolve_road_map_options(street(4), o).rips_radius.value(), 15);
  EXPECT_DOUBLE_EQ(resolve_road_map_options(street(200), o).rips_radius.value(), 15);
  o = {};
  o.rips_radius = 1e300;
  const Road_map_options u = resolve_road_map_options(street(20), o);
  EXPECT_EQ(u.rips_radius.value(), 1e300);
  EXPECT_EQ(u.delta.value(), 3e300);
  o = {};
  o.min_radius = 1e300;
  o.max_radius = 1e300;
  EXPECT_EQ(resolve_road_map_options(street(20), o).rips_radius.value(), 1e300);
}

// Road_map::used reports the branch merge distance the skeleton used (automatic: twice its level width).
TEST(RoadMap, UsedReportsTheAutomaticBranchMergeDistance) {
  Road_map_options o;
  o.branch_merge_distance = FeatureRecon::automatic;
  o.merge_distance = 0;
  const Road_map m = extract_road_map(street(20), o);
  ASSERT_EQ(m.status, Status::success);
  ASSERT_GT(m.skeleton.level_width, 0);
  ASSERT_TRUE(m.used.branch_merge_distance.has_value());
  EXPECT_EQ(*m.used.branch_merge_distance, m.skeleton.branch_merge_distance);
  EXPECT_DOUBLE_EQ(*m.used.branch_merge_distance, 2 * m.skeleton.level_width);
}

// An arc stored with its upper node as the edge's source: the chain still runs from the polyline's first
// point's node through the interior points in order.
TEST(MergeRoadLines, SkeletonToRoadMapFollowsThePolylineFromEitherSource) {
  Skeleton_graph g(2);
  g[0].position = {0, 0, 0};
  g[1].position = {30, 0, 0};
  const std::vector<std::array<double, 3>> line = {{0, 0, 0}, {10, 1, 0}, {20, -1, 0}, {30, 0, 0}};
  add_edge(1, 0, Skeleton_arc{line, {}, {}, 0, 1}, g);
  const Embedded_graph_2 m = skeleton_to_road_map(g);
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2], (std::array<double, 2>{10, 1}));
  EXPECT_EQ(m.positions[3], (std::array<double, 2>{20, -1}));
  std::vector<Edge> sorted;
  for (const Edge& e : m.edges) sorted.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<Edge>{{0, 2}, {1, 3}, {2, 3}}));
  double length = 0;
  for (std::size_t i = 1; i < line.size(); ++i)
    length += std::hypot(line[i][0] - line[i - 1][0], line[i][1] - line[i - 1][1]);
  EXPECT_DOUBLE_EQ(map_length(m), length);
}

// A map with no more vertices than twice the samples its length calls for is sampled as it is: every vertex
// and every point inserted along an edge is a sample or was contracted into one.
TEST(MergeRoadLines, AMapWithFewVerticesIsNotThinned) {
  Embedded_graph_2 g;
  for (int i = 0; i <= 18; ++i) g.positions.push_back({double(i), 0});  // 19 vertices 1 m apart
  g.positions.push_back({30, 0});                                       // and one 12 m further
  for (Vertex_index i = 0; i + 1 < g.positions.size(); ++i) g.edges.push_back({i, i + 1});
  // 20 vertices, 30 m at spacing 8/3: 2 (30 / (8/3) + 1) = 24.5; the 12 m edge takes 4 points inside.
  const Road_merge_result r = merge_road_lines(g);
  ASSERT_EQ(r.status, Status::success);
  EXPECT_EQ(r.samples + r.samples_contracted, 24u);
  EXPECT_GT(r.samples_contracted, 0u);
}

// remove_thin_loops() measures each side's vertices against the other side's segments (not their lines), in
// both directions, and keeps sides exactly `d` apart within `d`.
TEST(MergeRoadLines, ThinLoopSidesAreMeasuredBothWaysToSegments) {
  auto two_arcs = [](std::vector<std::array<double, 3>> a, std::vector<std::array<double, 3>> b) {
    Skeleton_graph g(2);
    g[0].position = {0, 0, 0};
    g[1].position = {40, 0, 0};
    g[0].members = {0};
    g[1].members = {1};
    add_edge(0, 1, Skeleton_arc{std::move(a), {2}, {}, 0, 1}, g);
    add_edge(0, 1, Skeleton_arc{std::move(b), {3}, {}, 0, 1}, g);
    return g;
  };
  const std::vector<std::array<double, 3>> straight = {{0, 0, 0}, {40, 0, 0}};
  // The second side runs on along the first one's line 15 beyond its end: 15 from the first side.
  Skeleton_graph overshoot = two_arcs(straight, {{0, 0, 0}, {20, 0, 0}, {55, 0, 0}, {40, 0, 0}});
  EXPECT_EQ(skeleton::internal::remove_thin_loops(overshoot, 5), 0u);
  EXPECT_EQ(num_edges(overshoot), 2u);
  // Every vertex of the straight side lies on the bent one, but the bend is 10 from the straight side.
  Skeleton_graph bent = two_arcs(straight, {{0, 0, 0}, {20, 10, 0}, {40, 0, 0}});
  EXPECT_EQ(skeleton::internal::remove_thin_loops(bent, 5), 0u);
  EXPECT_EQ(num_edges(bent), 2u);
  Skeleton_graph bent_first = two_arcs({{0, 0, 0}, {20, 10, 0}, {40, 0, 0}}, straight);
  EXPECT_EQ(skeleton::internal::remove_thin_loops(bent_first, 5), 0u);
  // Sides exactly 3 apart lie within 3.
  Skeleton_graph three = two_arcs({{0, 0, 0}, {20, 3, 0}, {40, 0, 0}}, {{0, 0, 0}, {20, 0, 0}, {40, 0, 0}});
  EXPECT_EQ(skeleton::internal::remove_thin_loops(three, 3), 1u);
  EXPECT_EQ(num_edges(three), 1u);
}

// An arc beside a path u-v-w whose middle node v has another arc: the direct arc goes even though it is the
// shorter side (v stays a junction). When v is a kink (degree 2), the path goes and v's members join the
// direct arc: the members still cover every point.
TEST(MergeRoadLines, ThinLoopBesideAJunctionLosesTheDirectArc) {
  Skeleton_graph t(4);
  for (std::size_t v = 0; v < 4; ++v) t[v].members = {Vertex_index(v)};
  t[0].position = {0, 0, 0};
  t[1].position = {40, 0, 0};
  t[2].position = {20, 4, 0};
  t[3].position = {20, 30, 0};
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {40, 0, 0}}, {4}, {}, 0, 1}, t);
  add_edge(0, 2, Skeleton_arc{{{0, 0, 0}, {20, 4, 0}}, {5}, {}, 0, 2}, t);
  add_edge(2, 1, Skeleton_arc{{{20, 4, 0}, {40, 0, 0}}, {6}, {}, 2, 1}, t);
  add_edge(2, 3, Skeleton_arc{{{20, 4, 0}, {20, 30, 0}}, {7}, {}, 2, 3}, t);
  EXPECT_EQ(skeleton::internal::remove_thin_loops(t, 5), 1u);
  ASSERT_EQ(num_vertices(t), 4u);
  ASSERT_EQ(num_edges(t), 3u);
  for (auto e : boost::make_iterator_range(edges(t))) EXPECT_TRUE(source(e, t) == 2 || target(e, t) == 2);
  auto all_members = [](const Skeleton_graph& g) {
    std::vector<Vertex_index> m;
    for (auto v : boost::make_iterator_range(vertices(g)))
      m.insert(m.end(), g[v].members.begin(), g[v].members.end());
    for (auto e : boost::make_iterator_range(edges(g)))
      m.insert(m.end(), g[e].members.begin(), g[e].members.end());
    std::sort(m.begin(), m.end());
    return m;
  };
  EXPECT_EQ(all_members(t), (std::vector<Vertex_index>{0, 1, 2, 3, 4, 5, 6, 7}));
  // The kink: the path and its node go, their members join the direct arc.
  Skeleton_graph k(3);
  for (std::size_t v = 0; v < 3; ++v) k[v].members = {Vertex_index(v)};
  k[0].position = {0, 0, 0};
  k[1].position = {40, 0, 0};
  k[2].position = {20, 4, 0};
  add_edge(0, 1, Skeleton_arc{{{0, 0, 0}, {40, 0, 0}}, {3}, {}, 0, 1}, k);
  add_edge(0, 2, Skeleton_arc{{{0, 0, 0}, {20, 4, 0}}, {4}, {}, 0, 2}, k);
  add_edge(2, 1, Skeleton_arc{{{20, 4, 0}, {40, 0, 0}}, {5}, {}, 2, 1}, k);
  EXPECT_EQ(skeleton::internal::remove_thin_loops(k, 5), 1u);
  ASSERT_EQ(num_vertices(k), 2u);
  EXPECT_EQ(all_members(k), (std::vector<Vertex_index>{0, 1, 2, 3, 4, 5}));
}

// remove_thin_loops() scans the arcs once, going on at the arc it changed. The oracle below restarts from the
// first arc after every change, as the function did before: removing arcs never makes a loop thin, so both
// remove the same arcs in the same order. Random multigraphs of up to 6 nodes and 12 arcs (parallel arcs,
// loops at a node, paths beside arcs, kinks of degree 2), each arc a polyline bent by up to 7 off its chord.
TEST(MergeRoadLines, ThinLoopsAreRemovedAsByRestartingTheScan) {
  auto by_restarting = [](Skeleton_graph& g, double d) {
    using Arc = Skeleton_graph::edge_descriptor;
    std::size_t removed = 0;
    auto take_members = [&g](Arc from, Arc to) {
      auto& m = g[to].members;
      m.insert(m.end(), g[from].members.begin(), g[from].members.end());
    };
    for (bool changed = true; changed;) {
      changed = false;
      for (auto e : boost::make_iterator_range(edges(g))) {
        const auto u = source(e, g), w = target(e, g);
        if (u == w) continue;
        for (auto f : boost::make_iterator_range(out_edges(u, g))) {
          if (f == e) continue;
          const auto v = target(f, g);
          if (v == w) {
            if (!skeleton::internal::sides_within({&g[e].polyline}, {&g[f].polyline}, d)) continue;
            const bool drop_e = skeleton::internal::polyline_length(g[e].polyline) >=
                                skeleton::internal::polyline_length(g[f].polyline);
            take_members(drop_e ? e : f, drop_e ? f : e);
            remove_edge(drop_e ? e : f, g);
            changed = true;
            break;
          }
          if (v == u) continue;
          for (auto h : boost::make_iterator_range(out_edges(v, g))) {
            if (target(h, g) != w || h == e) continue;
            if (!skeleton::internal::sides_within({&g[e].polyline}, {&g[f].polyline, &g[h].polyline}, d))
              continue;
            const double direct = skeleton::internal::polyline_length(g[e].polyline);
            const double around = skeleton::internal::polyline_length(g[f].polyline) +
                                  skeleton::internal::polyline_length(g[h].polyline);
            if (degree(v, g) > 2 || direct >= around) {
              take_members(e, f);
              remove_edge(e, g);
            } else {
              take_members(f, e);
              take_members(h, e);
              auto& m = g[e].members;
              m.insert(m.end(), g[v].members.begin(), g[v].members.end());
              g[v].members.clear();
              remove_edge(f, g);
              remove_edge(h, g);
            }
            changed = true;
            break;
          }
          if (changed) break;
        }
        if (changed) {
          ++removed;
          break;
        }
      }
    }
    for (std::size_t v = num_vertices(g); v-- > 0;)
      if (degree(v, g) == 0 && g[v].members.empty()) {
        remove_vertex(v, g);
        for (auto e : boost::make_iterator_range(edges(g))) {
          g[e].lower -= g[e].lower > v ? 1 : 0;
          g[e].upper -= g[e].upper > v ? 1 : 0;
        }
      }
    return removed;
  };
  // The whole graph as text, arcs in the order of the arc list and of each node's arcs: equal texts, equal
  // graphs.
  auto text = [](const Skeleton_graph& g) {
    std::string s;
    for (auto v : boost::make_iterator_range(vertices(g))) {
      s += "v" + std::to_string(v) + ":";
      for (const Vertex_index m : g[v].members) s += " " + std::to_string(m);
      s += " arcs";
      for (auto e : boost::make_iterator_range(out_edges(v, g))) {
        s += " " + std::to_string(target(e, g)) + "(";
        for (const Vertex_index m : g[e].members) s += " " + std::to_string(m);
        s += ")";
      }
      s += "\n";
    }
    for (auto e : boost::make_iterator_range(edges(g))) {
      s += "a " + std::to_string(source(e, g)) + "-" + std::to_string(target(e, g)) + " (" +
           std::to_string(g[e].lower) + ", " + std::to_string(g[e].upper) + ") " +
           std::to_string(g[e].polyline.size()) + " points:";
      for (const Vertex_index m : g[e].members) s += " " + std::to_string(m);
      s += "\n";
    }
    return s;
  };
  std::mt19937_64 rng(2026);
  std::size_t graphs_with_removals = 0, kinks_removed = 0, most_removed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::size_t n = 2 + rng() % 5, m = 1 + rng() % 12;
    Skeleton_graph g(n);
    Vertex_index next_member = 0;
    for (std::size_t v = 0; v < n; ++v) {
      // Nodes close together (less than 13 apart), so that paths u-v-w can lie beside an arc u-w.
      g[v].position = {static_cast<double>(rng() % 13), static_cast<double>(rng() % 5), 0};
      g[v].members = {next_member++};
    }
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t a = rng() % n, b = rng() % n;
      const auto& p = g[a].position;
      const auto& q = g[b].position;
      skeleton::internal::Polyline_3 line = {p};
      const int bends = static_cast<int>(rng() % 3);
      for (int i = 1; i <= bends; ++i) {
        const double t = static_cast<double>(i) / (bends + 1);
        line.push_back(
            {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) + static_cast<double>(rng() % 8), 0});
      }
      line.push_back(q);
      add_edge(a, b, Skeleton_arc{line, {next_member++}, {}, a, b}, g);
    }
    Skeleton_graph once = g, restarted = g;
    const std::size_t d = 1 + rng() % 6;
    const std::size_t removed = skeleton::internal::remove_thin_loops(once, static_cast<double>(d));
    ASSERT_EQ(removed, by_restarting(restarted, static_cast<double>(d))) << "trial " << trial;
    ASSERT_EQ(text(once), text(restarted)) << "trial " << trial;
    graphs_with_removals += removed > 0 ? 1 : 0;
    kinks_removed += num_vertices(g) - num_vertices(once);
    most_removed = std::max(most_removed, removed);
  }
  // The trials reach every branch: many graphs lose arcs, some several, and some lose kink nodes.
  EXPECT_GT(graphs_with_removals, 1000u);
  EXPECT_GE(most_removed, 5u);
  EXPECT_GT(kinks_removed, 20u);
}

// After merging no thin loop is left: removing them again at the merge distance finds none (the city's
// two-way streets leave some, which merge_road_lines() counts).
TEST(MergeRoadLines, NoThinLoopIsLeftAfterMerging) {
  const Synthetic_city city = small_city();
  Road_map_options off;
  off.merge_distance = 0;
  const Road_map lines = extract_road_map(city.trips, off);
  ASSERT_EQ(lines.status, Status::success);
  const Road_merge_result r = merge_road_lines(lines.map);
  ASSERT_EQ(r.status, Status::success);
  EXPECT_GT(r.thin_loops_removed, 0u);
  Skeleton_graph again = r.skeleton;
  EXPECT_EQ(skeleton::internal::remove_thin_loops(again, 8), 0u);
  EXPECT_EQ(num_edges(again), num_edges(r.skeleton));
}

// With merging off the progress still ends at 1 (the skeleton's stage ends at 0.9).
TEST(RoadMap, ProgressEndsAtOneWithMergingOff) {
  Road_map_options o;
  o.merge_distance = 0;
  std::vector<double> seen;
  o.progress = test::recording_progress(seen);
  const Road_map m = extract_road_map(street(20), o);
  ASSERT_EQ(m.status, Status::success);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1], seen[i]);
}
