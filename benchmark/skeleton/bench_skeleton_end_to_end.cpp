// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// End to end on Chicago: FeatureRecon's whole skeleton pipeline (sampling, graph, Rips 2-complex, geodesic
// function, Reeb graph, persistence simplification, repair, embedding) against what GUDHI needs to build the
// same 2-complex and compute its extended persistence (issue 3, section 5). The function values GUDHI filters
// by are our geodesic function, computed before the clock starts.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/road_map.h>

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "bench_common.h"
#ifdef FEATURERECON_WITH_GUDHI
#include "gudhi_extended_persistence_peer.h"
#endif

namespace {
using namespace FeatureRecon;
namespace sk = FeatureRecon::skeleton;

/// Chicago's trips with the options extract_road_map() derives from them (the defaults of --tracks).
struct Gps_case {
  std::vector<sk::Gps_trip> trips;
  sk::Road_map_options used;
  sk::Skeleton_options skeleton;
  double radius = 0;
};

const Gps_case& chicago_tracks() {
  static std::unique_ptr<Gps_case> c;
  if (c) return *c;
  c = std::make_unique<Gps_case>();
  std::map<long, std::size_t> index;
  for (const auto& r : bench::chicago_rows()) {
    const auto it = index.emplace(r.trip, c->trips.size()).first;
    if (it->second == c->trips.size()) c->trips.emplace_back();
    c->trips[it->second].push_back({r.x, r.y, r.t});
  }
  c->used = sk::resolve_road_map_options(c->trips, {});
  c->skeleton = sk::road_map_skeleton_options(c->used);
  c->radius = c->used.rips_radius.value();
  return *c;
}

void BM_tracks_featurerecon(benchmark::State& state) {
  const Gps_case& c = chicago_tracks();
  std::size_t arcs = 0, merged_arcs = 0;
  for (auto _ : state) {
    const sk::Road_map m = sk::extract_road_map(c.trips);
    arcs = num_edges(m.skeleton.graph);  // the skeleton of the samples (as in the run from the graph below)
    merged_arcs = num_edges(m.merged.skeleton);  // the map after the merging stage
    benchmark::DoNotOptimize(m);
  }
  state.counters["arcs"] = static_cast<double>(arcs);
  state.counters["merged_arcs"] = static_cast<double>(merged_arcs);
}

/// Only the stages GUDHI's run covers and the rest of ours on that complex: from the graph of the samples.
void BM_tracks_graph_featurerecon(benchmark::State& state) {
  const Gps_case& c = chicago_tracks();
  const sk::Gps_trace_sample S = sk::sample_gps_traces(c.trips, c.radius, c.used.traces);
  const sk::Proximity_graph g = sk::build_gps_trace_graph(S, c.radius);
  std::size_t arcs = 0;
  for (auto _ : state) {
    const sk::Reeb_skeleton s = sk::extract_reeb_skeleton(g, S.points, c.skeleton);
    arcs = num_edges(s.graph);
    benchmark::DoNotOptimize(s);
  }
  state.counters["arcs"] = static_cast<double>(arcs);
}

struct Points_case {
  std::vector<std::vector<double>> points;
  sk::Point_matrix matrix;
  double radius = 20;
};

const Points_case& chicago20k() {
  static std::unique_ptr<Points_case> c;
  if (c) return *c;
  c = std::make_unique<Points_case>();
  std::vector<std::array<double, 2>> p = bench::chicago_points(20000);
  for (const auto& q : p) c->points.push_back({q[0], q[1]});
  c->matrix = sk::make_point_matrix(p);
  return *c;
}

void BM_points_featurerecon(benchmark::State& state) {
  const Points_case& c = chicago20k();
  sk::Skeleton_options o;
  o.delta = c.radius;
  std::size_t arcs = 0;
  for (auto _ : state) {
    const sk::Reeb_skeleton s = sk::extract_reeb_skeleton(c.matrix, c.radius, o);
    arcs = num_edges(s.graph);
    benchmark::DoNotOptimize(s);
  }
  state.counters["arcs"] = static_cast<double>(arcs);
}

#ifdef FEATURERECON_WITH_GUDHI
std::vector<double> geodesic_values(const sk::Proximity_graph& g) {
  return sk::compute_geodesic_function(sk::build_flag_complex_2(g)).values;
}

void BM_tracks_gudhi(benchmark::State& state) {
  const Gps_case& c = chicago_tracks();
  const sk::Gps_trace_sample S = sk::sample_gps_traces(c.trips, c.radius, c.used.traces);
  const sk::Proximity_graph g = sk::build_gps_trace_graph(S, c.radius);
  const std::vector<double> f = geodesic_values(g);
  std::vector<std::array<std::uint32_t, 2>> edges(g.edges.begin(), g.edges.end());
  bench::Gudhi_result r;
  for (auto _ : state) r = bench::gudhi_flag_extended_persistence(g.number_of_vertices, edges, f);
  state.counters["simplices"] = static_cast<double>(r.simplices);
  state.counters["pairs"] = static_cast<double>(r.pairs);
}

void BM_points_gudhi(benchmark::State& state) {
  const Points_case& c = chicago20k();
  const std::vector<double> f = geodesic_values(sk::build_rips_graph(c.matrix, c.radius));
  bench::Gudhi_result r;
  for (auto _ : state) r = bench::gudhi_rips_extended_persistence(c.points, c.radius, f);
  state.counters["simplices"] = static_cast<double>(r.simplices);
  state.counters["pairs"] = static_cast<double>(r.pairs);
}
#endif

void register_all() {
  benchmark::RegisterBenchmark("skeleton/featurerecon/chicago_tracks", BM_tracks_featurerecon)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(2.0);
  benchmark::RegisterBenchmark("skeleton/featurerecon/chicago_tracks_from_graph",
                               BM_tracks_graph_featurerecon)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(2.0);
  benchmark::RegisterBenchmark("skeleton/featurerecon/chicago20k_r20", BM_points_featurerecon)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(2.0);
#ifdef FEATURERECON_WITH_GUDHI
  benchmark::RegisterBenchmark("skeleton/gudhi/chicago_tracks", BM_tracks_gudhi)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(3);
  benchmark::RegisterBenchmark("skeleton/gudhi/chicago20k_r20", BM_points_gudhi)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(1);
#endif
}
}  // namespace

int main(int argc, char** argv) { return FeatureRecon::bench::run_benchmarks(argc, argv, register_all); }
