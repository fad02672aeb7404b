// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Continuous Lloyd relaxation (issue 5, section 5): one iteration of lloyd_relaxation's step (Voronoi cells
// from the Delaunay triangulation kept between iterations, exact integrals of a pixel density) against one
// CGAL Delaunay_triangulation_2 build of the same sites, in the same run. The sites are relaxed for 10
// iterations first (the steady state of stippling); the density is random per pixel. Sizes: 10k sites on
// 256 x 256 and 1024 x 1024 pixels, 100k sites on 1024 x 1024.
#include <FeatureRecon/sampling/lloyd_relaxation.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace {
namespace fs = FeatureRecon::sampling;
using K = CGAL::Epick;
using Sites = std::vector<std::array<double, 2>>;

struct Setup {
  fs::Pixel_density density;
  Sites sites;  // after 10 Lloyd iterations from white noise
};

const Setup& setup(std::size_t n, int side) {
  static std::map<std::pair<std::size_t, int>, Setup> cache;
  auto& s = cache[{n, side}];
  if (s.sites.empty()) {
    std::mt19937_64 rng(1);
    auto uniform = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    std::vector<double> values(std::size_t(side) * std::size_t(side));
    for (auto& v : values) v = 0.05 + uniform();
    s.density = fs::Pixel_density(side, side, std::move(values));
    Sites sites(n);
    for (auto& p : sites) p = {side * uniform(), side * uniform()};
    fs::Lloyd_options options;
    options.max_iterations = 10;
    s.sites = fs::lloyd_relaxation(sites, s.density, options).sites;
  }
  return s;
}

void BM_Delaunay_build(benchmark::State& state) {
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)));
  std::vector<K::Point_2> points;
  for (const auto& p : s.sites) points.emplace_back(p[0], p[1]);
  for (auto _ : state) {
    CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
}

// One iteration in the steady state: the builder keeps the triangulation of the previous iteration and
// moves its vertices (flips), as lloyd_relaxation does after its first iteration.
void BM_Lloyd_iteration(benchmark::State& state) {
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)));
  fs::internal::Voronoi_builder voronoi;
  Sites sites = s.sites;
  const unsigned threads = unsigned(state.range(2));
  sites = fs::internal::lloyd_step_impl(sites, s.density, voronoi, threads).centroids;
  for (auto _ : state) {
    auto step = fs::internal::lloyd_step_impl(sites, s.density, voronoi, threads);
    benchmark::DoNotOptimize(step.energy);
    sites = std::move(step.centroids);
  }
  state.counters["rebuilds"] = double(voronoi.rebuilds);
}

// The first iteration from the relaxed sites, triangulated from scratch.
void BM_Lloyd_first_iteration(benchmark::State& state) {
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)));
  for (auto _ : state) {
    auto step = fs::lloyd_step(s.sites, s.density);
    benchmark::DoNotOptimize(step.energy);
  }
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Args({10000, 256})->Args({10000, 1024})->Args({100000, 1024})->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_Delaunay_build)->Name("sampling/lloyd/delaunay_build")->Apply(sizes);
// Threads integrating the cells: 1, and 0 = every core (2 on the reference machine).
BENCHMARK(BM_Lloyd_iteration)->Name("sampling/lloyd/iteration")->ArgNames({"sites", "side", "threads"})
    ->Args({10000, 256, 1})->Args({10000, 1024, 1})->Args({100000, 1024, 1})
    ->Args({10000, 256, 0})->Args({10000, 1024, 0})->Args({100000, 1024, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lloyd_first_iteration)->Name("sampling/lloyd/first_iteration")->Apply(sizes);
BENCHMARK_MAIN();
