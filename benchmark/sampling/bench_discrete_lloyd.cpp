// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Discrete bilateral Lloyd (issue 5, section 5): one discrete_lloyd_step on a 1024 x 1024 grey image
// (1 megapixel) with 10k sites, Euclidean and bilateral, against one nearest-neighbour pass over the pixels
// (CGAL's kd-tree, Orthogonal_k_neighbor_search with k = 1, the plainest assignment there is), in the same
// run. Also kernel_relaxation's energy and gradient for the same 10k sites. The image is smooth noise with
// edges (sums of random discs); the sites come from 5 Euclidean Lloyd steps from white noise.
#include <FeatureRecon/sampling/discrete_lloyd.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/kernel_relaxation.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Simple_cartesian.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace {
namespace fs = FeatureRecon::sampling;
using Site = fs::Bilateral_site<FeatureRecon::Grey_pixel_traits>;
constexpr int side = 1024;
constexpr std::size_t sites_n = 10000;

struct Setup {
  std::vector<FeatureRecon::Grey_pixel> pixels;
  std::vector<Site> sites;
  std::vector<FeatureRecon::Grey_pixel> logo;  // black square of side / 4 in the middle, on white
  std::vector<Site> logo_sites;                // the sites shrunk into the square
};

const Setup& setup() {
  static Setup s;
  if (s.pixels.empty()) {
    std::mt19937_64 rng(3);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    std::vector<double> v(std::size_t(side) * side, 60);
    for (int k = 0; k < 300; ++k) {
      const double cx = u() * side, cy = u() * side, r = 10 + 60 * u(), add = 80 * u() - 30;
      for (int y = std::max(0, int(cy - r)); y < std::min(side, int(cy + r) + 1); ++y)
        for (int x = std::max(0, int(cx - r)); x < std::min(side, int(cx + r) + 1); ++x)
          if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r)
            v[std::size_t(y) * side + std::size_t(x)] += add;
    }
    std::vector<std::uint8_t> bytes(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      bytes[i] = std::uint8_t(std::min(255.0, std::max(0.0, v[i] + 20 * u())));
    s.pixels = fs::image_pixels<FeatureRecon::Grey_pixel>(side, side, bytes);
    std::vector<Site> sites(sites_n);
    for (auto& x : sites) x = Site{{u() * side, u() * side}, {0}};
    fs::Discrete_lloyd_options<2> o;
    o.max_iterations = 5;
    s.sites = fs::discrete_bilateral_lloyd(s.pixels, sites, o).sites;
    std::vector<std::uint8_t> logo(std::size_t(side) * side, 255);
    constexpr int from = side * 3 / 8, to = side * 5 / 8;
    for (int y = from; y < to; ++y)
      for (int x = from; x < to; ++x) logo[std::size_t(y) * side + std::size_t(x)] = 0;
    s.logo = fs::image_pixels<FeatureRecon::Grey_pixel>(side, side, logo);
    for (const Site& x : s.sites)
      s.logo_sites.push_back(Site{{from + x.position[0] / 4, from + x.position[1] / 4}, {0}});
  }
  return s;
}

void BM_Nearest_neighbour_pass(benchmark::State& state) {
  const Setup& s = setup();
  using K = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Search_traits_2<K>;
  using Knn = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::vector<K::Point_2> points;
  for (const auto& x : s.sites) points.emplace_back(x.position[0], x.position[1]);
  for (auto _ : state) {
    Knn::Tree tree(points.begin(), points.end());
    tree.build();
    double sum = 0;
    for (const auto& p : s.pixels) {
      Knn search(tree, K::Point_2(p.column + 0.5, p.row + 0.5), 1);
      sum += search.begin()->second;
    }
    benchmark::DoNotOptimize(sum);
  }
}

void BM_Discrete_lloyd_step(benchmark::State& state) {
  const Setup& s = setup();
  fs::Discrete_lloyd_options<2> o;
  const double d_hex = std::sqrt(2.0 * side * side / (std::sqrt(3.0) * double(sites_n)));
  if (state.range(0) >= 1) {  // bilateral: positions in units of the spacing, sigma_feature 0.3
    o.sigma_position = d_hex;
    o.sigma_feature = 0.3;
  }
  // 2: the logo, its sites on a sixteenth of the image (most pixels far from every site); 3: the same with
  // the exponential form (the feature factor exp(1 / 0.09) multiplies the white pixels' distances to every
  // site)
  const bool logo = state.range(0) >= 2;
  if (logo) o.sigma_position = d_hex / 4;
  if (state.range(0) == 3) o.form = fs::Bilateral_form::exponential;
  for (auto _ : state) {
    auto step = fs::discrete_lloyd_step(logo ? s.logo : s.pixels, logo ? s.logo_sites : s.sites, o);
    benchmark::DoNotOptimize(step.max_move);
  }
}

void BM_Kernel_energy(benchmark::State& state) {
  const Setup& s = setup();
  fs::Kernel_relaxation_options<2> o;
  for (auto _ : state) {
    auto e = fs::kernel_energy(s.pixels, s.sites, o);
    benchmark::DoNotOptimize(e.energy);
  }
}
}  // namespace

BENCHMARK(BM_Nearest_neighbour_pass)
    ->Name("sampling/discrete_lloyd/nearest_neighbour_pass_1MP_10k")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Discrete_lloyd_step)
    ->Name("sampling/discrete_lloyd/step_1MP_10k")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Kernel_energy)
    ->Name("sampling/kernel_relaxation/energy_gradient_1MP_10k")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
