// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Augmented Reeb graph build: FeatureRecon vs VTK's vtkReebGraph (triangles only) on the same complexes:
// upright torus grids with a tilted height (100k, 400k, 4M triangles) and the Rips complex of the first
// 30,000 Chicago GPS points at r = 12 m with the geodesic function.
// Simplification beside the Reeb graph it starts from, on a comb of 1,000,000 vertices (a path with a spur at
// every vertex, f rising along the path; delta 2 removes all 500,000 spurs): no library simplifies Reeb
// graphs, so the peer is our own Reeb graph of the same input. The same for the shapes that were quadratic
// before session 39: a flat stem with a tall tooth at every vertex ("teethN") and a fan of loops ("fanN"),
// simplified at delta 1, and joining the dead ends of a street with a stub at every other vertex ("stubsN",
// connect_dead_ends with a bound), and a nearly flat noisy path ("noisyN", quadratic before session 64).
// Dead ends of dashes in a square ("fieldN"), with one bound (a strip) and two (a grid; session 65).
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#ifdef FEATURERECON_WITH_VTK
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkEdgeListIterator.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkReebGraph.h>
#endif

#include <map>
#include <memory>

#include "bench_common.h"

namespace {
using namespace FeatureRecon;
namespace sk = FeatureRecon::skeleton;

struct Input {
  sk::Simplicial_complex_2 complex;
  std::vector<double> f;
  std::vector<std::array<double, 3>> positions;
};

/// The number at the end of an input's name ("teeth400000": 400000).
std::size_t size_of(const std::string& name) {
  return std::stoul(name.substr(name.find_first_of("0123456789")));
}

/// Inputs by name, built once per process.
const Input& input(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Input>> cache;
  auto& slot = cache[name];
  if (slot) return *slot;
  slot = std::make_unique<Input>();
  if (name == "chicago30k") {
    const auto points = bench::chicago_points(30000);
    slot->complex = sk::build_rips_complex_2(points, 12.0);
    slot->f = sk::compute_geodesic_function(slot->complex).values;
    for (const auto& p : points) slot->positions.push_back({p[0], p[1], 0.0});
  } else if (name == "comb1M") {
    const std::size_t k = 500000;
    std::vector<sk::Edge> edges;
    for (std::size_t i = 0; i < k; ++i) {
      slot->f.push_back(2.0 * static_cast<double>(i));  // the path
      edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(k + i)});
      if (i + 1 < k)
        edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(i + 1)});
    }
    for (std::size_t i = 0; i < k; ++i) slot->f.push_back(2.0 * static_cast<double>(i) + 1.5);  // spur tips
    slot->complex = sk::make_simplicial_complex_2(2 * k, std::move(edges), {});
  } else if (name.rfind("teeth", 0) == 0) {  // the unit tests' flat comb: stem f = i * 1e-6, tooth f(i) + 0.5
    const std::size_t n = size_of(name);
    std::vector<sk::Edge> edges;
    slot->f.resize(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      slot->f[i] = 1e-6 * static_cast<double>(i);
      slot->f[n + i] = slot->f[i] + 0.5;
      if (i + 1 < n)
        edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(i + 1)});
      edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(n + i)});
    }
    slot->complex = sk::make_simplicial_complex_2(2 * n, std::move(edges), {});
  } else if (name.rfind("fan", 0) ==
             0) {  // vertex 0 joined to every vertex of the path 1..n, f = 0.5 + 1e-6 i
    const std::size_t n = size_of(name);
    std::vector<sk::Edge> edges;
    slot->f.assign(n + 1, 0.0);
    for (std::size_t i = 1; i <= n; ++i) {
      slot->f[i] = 0.5 + 1e-6 * static_cast<double>(i);
      edges.push_back({0, static_cast<sk::Vertex_index>(i)});
      if (i < n) edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(i + 1)});
    }
    slot->complex = sk::make_simplicial_complex_2(n + 1, std::move(edges), {});
  } else if (name.rfind("noisy", 0) == 0) {  // a path of n values drawn in [0, 0.001) (session 64)
    const std::size_t n = size_of(name);
    std::mt19937_64 rng(5);
    std::vector<sk::Edge> edges;
    for (std::size_t i = 0; i < n; ++i) {
      slot->f.push_back(1e-3 * static_cast<double>(rng() >> 11) * 0x1p-53);
      if (i + 1 < n)
        edges.push_back({static_cast<sk::Vertex_index>(i), static_cast<sk::Vertex_index>(i + 1)});
    }
    slot->complex = sk::make_simplicial_complex_2(n, std::move(edges), {});
  } else if (name.rfind("stubs", 0) == 0) {  // a street on the x axis, a stub from y 0.5 to 5 at every odd x
    const std::size_t length = 2 * size_of(name) + 2;
    std::vector<sk::Edge> edges;
    for (std::size_t i = 0; i < length; ++i) {
      slot->positions.push_back({double(i), 0.0, 0.0});
      if (i > 0) edges.push_back({sk::Vertex_index(i - 1), sk::Vertex_index(i)});
    }
    for (std::size_t j = 1; j + 1 < length; j += 2) {
      const auto a = sk::Vertex_index(slot->positions.size());
      slot->positions.push_back({double(j), 0.5, 0.0});
      slot->positions.push_back({double(j), 5.0, 0.0});
      edges.push_back({a, sk::Vertex_index(a + 1)});
    }
    for (const auto& p : slot->positions) slot->f.push_back(p[0] + 1e-3 * p[1]);
    slot->complex = sk::make_simplicial_complex_2(slot->positions.size(), std::move(edges), {});
  } else if (name.rfind("field", 0) == 0) {
    // k x k rows of dashes in a square, k = sqrt(n): 4 points at x = 4c + 0, 1, 2, 3.1, y = 4r; each dash's
    // right end lies 0.9 from the next dash's left end (joined at distance 1), rows 4 apart (never joined).
    const auto k = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(size_of(name)))));
    std::vector<sk::Edge> edges;
    for (std::size_t r = 0; r < k; ++r)
      for (std::size_t c = 0; c < k; ++c)
        for (const double dx : {0.0, 1.0, 2.0, 3.1}) {
          if (dx > 0)
            edges.push_back(
                {sk::Vertex_index(slot->positions.size() - 1), sk::Vertex_index(slot->positions.size())});
          slot->positions.push_back({4.0 * double(c) + dx, 4.0 * double(r), 0.0});
        }
    for (const auto& p : slot->positions) slot->f.push_back(p[0] + 1e-3 * p[1]);
    slot->complex = sk::make_simplicial_complex_2(slot->positions.size(), std::move(edges), {});
  } else {
    const std::size_t kt = std::stoul(name.substr(5));  // "torusN": N thousand triangles
    const std::size_t nu = kt == 100   ? 250
                           : kt == 400 ? 500
                                       : 2000,
                      nv = kt == 100   ? 200
                           : kt == 400 ? 400
                                       : 1000;
    bench::Torus t = bench::torus_grid(nu, nv);
    slot->complex = std::move(t.complex);
    slot->f = std::move(t.f);
    slot->positions = std::move(t.positions);
  }
  return *slot;
}

void report(benchmark::State& state, const Input& in, std::size_t nodes, std::size_t arcs,
            std::size_t loops) {
  state.counters["triangles"] = static_cast<double>(in.complex.number_of_triangles());
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["arcs"] = static_cast<double>(arcs);
  state.counters["loops"] = static_cast<double>(loops);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.complex.number_of_triangles()));
}

void BM_reeb_featurerecon(benchmark::State& state, const std::string& name) {
  const Input& in = input(name);
  sk::Reeb_graph R;
  for (auto _ : state) {
    const sk::Augmented_reeb_graph A = sk::compute_augmented_reeb_graph(in.complex, in.f);
    R = A.reeb_graph();
    benchmark::DoNotOptimize(R);
  }
  report(state, in, R.nodes.size(), R.arcs.size(), R.loops());
}

void BM_simplify_featurerecon(benchmark::State& state, const std::string& name, double delta) {
  const Input& in = input(name);
  sk::Reeb_simplification_result S;
  for (auto _ : state) {
    const sk::Augmented_reeb_graph A = sk::compute_augmented_reeb_graph(in.complex, in.f);
    S = sk::simplify_by_persistence(A, delta);
    benchmark::DoNotOptimize(S);
  }
  state.counters["removed_branches"] = static_cast<double>(S.removed_branches);
  state.counters["removed_loops"] = static_cast<double>(S.removed_loops);
  state.counters["glued_triangles"] = static_cast<double>(S.glued_triangles);
  report(state, in, S.graph.nodes.size(), S.graph.arcs.size(), S.graph.loops());
}

/// The Reeb graph and the joining of its dead ends closer than 1 (stubs: each stub's end to the street below
/// it, which is split there), the x coordinate as the bound, and with `two_bounds` y as the second one.
void BM_dead_ends_featurerecon(benchmark::State& state, const std::string& name, bool two_bounds) {
  const Input& in = input(name);
  sk::Reeb_dead_end_result J;
  sk::Reeb_repair_options options;
  options.bound = [&in](sk::Vertex_index v) { return in.positions[v][0]; };
  if (two_bounds) options.second_bound = [&in](sk::Vertex_index v) { return in.positions[v][1]; };
  auto distance = [&in](sk::Vertex_index a, sk::Vertex_index b) {
    return std::hypot(in.positions[a][0] - in.positions[b][0], in.positions[a][1] - in.positions[b][1]);
  };
  for (auto _ : state) {
    const sk::Reeb_graph R = sk::compute_augmented_reeb_graph(in.complex, in.f).reeb_graph();
    J = sk::connect_dead_ends(R, in.f, 1.0, distance, options);
    benchmark::DoNotOptimize(J);
  }
  state.counters["connected"] = static_cast<double>(J.connected);
  report(state, in, J.graph.nodes.size(), J.graph.arcs.size(), J.graph.loops());
}

#ifdef FEATURERECON_WITH_VTK
void BM_reeb_vtk(benchmark::State& state, const std::string& name) {
  const Input& in = input(name);
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> pts;
  for (const auto& p : in.positions) pts->InsertNextPoint(p[0], p[1], p[2]);
  mesh->SetPoints(pts);
  vtkNew<vtkCellArray> cells;
  for (const auto& t : in.complex.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  mesh->SetPolys(cells);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(in.f.size()));
  for (std::size_t i = 0; i < in.f.size(); ++i) scalars->SetValue(static_cast<vtkIdType>(i), in.f[i]);
  mesh->GetPointData()->SetScalars(scalars);
  std::size_t nodes = 0, arcs = 0, loops = 0;
  for (auto _ : state) {
    vtkNew<vtkReebGraph> graph;
    if (graph->Build(mesh, scalars) < 0) state.SkipWithError("vtkReebGraph::Build failed");
    nodes = static_cast<std::size_t>(graph->GetNumberOfVertices());
    arcs = static_cast<std::size_t>(graph->GetNumberOfEdges());
    // loops = arcs - nodes + components
    std::vector<vtkIdType> parent(nodes);
    for (std::size_t i = 0; i < nodes; ++i) parent[i] = static_cast<vtkIdType>(i);
    auto find = [&](vtkIdType x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::size_t components = nodes;
    vtkNew<vtkEdgeListIterator> it;
    graph->GetEdges(it);
    while (it->HasNext()) {
      const vtkEdgeType e = it->Next();
      const vtkIdType a = find(e.Source), b = find(e.Target);
      if (a != b) {
        parent[a] = b;
        --components;
      }
    }
    loops = arcs + components - nodes;
  }
  report(state, in, nodes, arcs, loops);
}
#endif

void register_all() {
  for (const std::string name : {"torus100", "torus400", "torus4000", "chicago30k", "comb1M"}) {
    // At least 3 calls each: the first call on a large complex also pays the kernel's huge-page set-up.
    auto* b = benchmark::RegisterBenchmark(("reeb/featurerecon/" + name).c_str(), BM_reeb_featurerecon, name);
    b->Unit(benchmark::kMillisecond)->UseRealTime();
    if (name == "torus4000" || name == "chicago30k" || name == "comb1M")
      b->Iterations(3);
    else
      b->MinTime(2.0);
    if (name == "comb1M") {  // the simplification of the same input, Reeb graph included; VTK needs triangles
      benchmark::RegisterBenchmark("simplify/featurerecon/comb1M", BM_simplify_featurerecon, name, 2.0)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(3);
      continue;
    }
#ifdef FEATURERECON_WITH_VTK
    if (name != "torus4000")  // hours with VTK
      benchmark::RegisterBenchmark(("reeb/vtk/" + name).c_str(), BM_reeb_vtk, name)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
#endif
  }
  // Shapes that were quadratic (session 39), each beside its own Reeb graph; the simplification and the
  // repair include it. 4,000 as in the unit tests (131 s and 174 s before; stubs 40,000: 6.0 s), then tenfold
  // sizes.
  for (const std::string size : {"4000", "40000", "400000"}) {
    for (const std::string shape : {"teeth", "fan", "stubs", "noisy"}) {
      // noisy: the merging edges of a nearly flat noisy path span O(n) levels each, O(n log n) triangles in
      // all since session 64 (O(n^2) before: 5,000 took 6.4 s); 400,000 would glue about 45 million.
      if (shape == std::string("noisy") && size == std::string("400000")) continue;
      const std::string name = shape + size;
      const std::string stage = shape == "stubs" ? "dead_ends" : "simplify";
      for (const std::string what : {std::string("reeb"), stage}) {
        auto* b = what == "reeb" ? benchmark::RegisterBenchmark(("reeb/featurerecon/" + name).c_str(),
                                                                BM_reeb_featurerecon, name)
                  : what == "simplify"
                      ? benchmark::RegisterBenchmark(("simplify/featurerecon/" + name).c_str(),
                                                     BM_simplify_featurerecon, name, 1.0)
                      : benchmark::RegisterBenchmark(("dead_ends/featurerecon/" + name).c_str(),
                                                     BM_dead_ends_featurerecon, name, false);
        b->Unit(benchmark::kMillisecond)->UseRealTime();
        if (size == "4000")
          b->MinTime(1.0);
        else
          b->Iterations(3);
      }
    }
  }
  // Dead ends in the plane (session 65): n dashes in a square, with x as the only bound (a strip: O(sqrt n)
  // candidates per dead end) and with y as the second bound (a grid: O(1)), beside their Reeb graph.
  for (const std::string size : {"40000", "160000", "640000"}) {
    const std::string name = "field" + size;
    benchmark::RegisterBenchmark(("reeb/featurerecon/" + name).c_str(), BM_reeb_featurerecon, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    for (const bool two : {false, true})
      benchmark::RegisterBenchmark(
          ("dead_ends/featurerecon/" + std::string(two ? "xy/" : "x/") + name).c_str(),
          BM_dead_ends_featurerecon, name, two)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(3);
  }
}
}  // namespace

int main(int argc, char** argv) { return FeatureRecon::bench::run_benchmarks(argc, argv, register_all); }
