// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Continuous Lloyd relaxation (issue 5, section 5): one iteration of lloyd_relaxation's step (Voronoi cells
// from the Delaunay triangulation kept between iterations, exact integrals of a pixel density) against one
// CGAL Delaunay_triangulation_2 build of the same sites, in the same run. The sites are relaxed for 10
// iterations first (the steady state). Densities: uniform (plain Lloyd, integrated in closed form) and random
// per pixel (adaptive stippling, integrated pixel by pixel). Sizes: 10k and 100k sites on 1024 x 1024 pixels,
// and 10k sites on 256 x 256. The torus (periodic_iteration) beside the plain iteration.
#include <FeatureRecon/sampling/lloyd_relaxation.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <random>
#include <tuple>
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

// `pixels`: 1 for a density random per pixel, 0 for a uniform one.
const Setup& setup(std::size_t n, int side, int pixels) {
  static std::map<std::tuple<std::size_t, int, int>, Setup> cache;
  auto& s = cache[{n, side, pixels}];
  if (s.sites.empty()) {
    std::mt19937_64 rng(1);
    auto uniform = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    std::vector<double> values(std::size_t(side) * std::size_t(side), 1.0);
    if (pixels != 0)
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
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)), int(state.range(2)));
  std::vector<K::Point_2> points;
  for (const auto& p : s.sites) points.emplace_back(p[0], p[1]);
  for (auto _ : state) {
    CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
}

// Iterations in the steady state with `step(sites, density, voronoi, threads)`: the Voronoi structure keeps
// the triangulation of the previous iteration and moves its vertices (flips), as lloyd_relaxation does after
// its first iteration.
template <class Voronoi, class Step>
void steady_iterations(benchmark::State& state, const Step& step) {
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)), int(state.range(3)));
  Voronoi voronoi;
  Sites sites = s.sites;
  const unsigned threads = unsigned(state.range(2));
  sites = step(sites, s.density, voronoi, threads).centroids;
  for (auto _ : state) {
    auto next = step(sites, s.density, voronoi, threads);
    benchmark::DoNotOptimize(next.energy);
    sites = std::move(next.centroids);
  }
  state.counters["rebuilds"] = double(voronoi.rebuilds);
}

void BM_Lloyd_iteration(benchmark::State& state) {
  steady_iterations<fs::internal::Voronoi_builder>(state, fs::internal::lloyd_step_impl);
}

// On the torus of the box (Lloyd_options::periodic): the triangulation holds the sites and their images near
// the faces. Same sites as the plain rows.
void BM_Lloyd_periodic_iteration(benchmark::State& state) {
  steady_iterations<fs::internal::Periodic_voronoi>(state, fs::internal::periodic_lloyd_step_impl);
}

// The first iteration from the relaxed sites, triangulated from scratch.
void BM_Lloyd_first_iteration(benchmark::State& state) {
  const Setup& s = setup(std::size_t(state.range(0)), int(state.range(1)), int(state.range(2)));
  for (auto _ : state) {
    auto step = fs::lloyd_step(s.sites, s.density);
    benchmark::DoNotOptimize(step.energy);
  }
}

// sites, side, and 0 (uniform) or 1 (random pixels).
void sizes(benchmark::internal::Benchmark* b) {
  for (int pixels : {0, 1})
    b->Args({10000, 256, pixels})->Args({10000, 1024, pixels})->Args({100000, 1024, pixels});
  b->ArgNames({"sites", "side", "pixels"})->Unit(benchmark::kMillisecond);
}

// The same with the threads integrating the cells: 1, and 0 = every core (2 on the reference machine).
void sizes_and_threads(benchmark::internal::Benchmark* b) {
  for (int pixels : {0, 1})
    for (int threads : {1, 0})
      b->Args({10000, 256, threads, pixels})
          ->Args({10000, 1024, threads, pixels})
          ->Args({100000, 1024, threads, pixels});
  b->ArgNames({"sites", "side", "threads", "pixels"})->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_Delaunay_build)->Name("sampling/lloyd/delaunay_build")->Apply(sizes);
BENCHMARK(BM_Lloyd_iteration)->Name("sampling/lloyd/iteration")->Apply(sizes_and_threads);
BENCHMARK(BM_Lloyd_periodic_iteration)->Name("sampling/lloyd/periodic_iteration")->Apply(sizes_and_threads);
BENCHMARK(BM_Lloyd_first_iteration)->Name("sampling/lloyd/first_iteration")->Apply(sizes);
BENCHMARK_MAIN();
