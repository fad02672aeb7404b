// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The sampled bilateral filter (issue 5, section 5) against the exact filter in the same run, on a 512 x 512
// RGB image of random coloured discs with noise (sigma_spatial 3, window 13 x 13, sigma_range 0.1): uniform
// and bilateral taps, global (the pattern stage and the filter stage timed apart) and local patterns, at
// budgets of 0.25, 0.5 and 1 tap per kernel pixel. Counters: the PSNR (dB) and SSIM of the result against the
// exact filter and the taps per kernel pixel used.
#include <FeatureRecon/sampling/image_quality.h>
#include <FeatureRecon/sampling/sampled_bilateral_filter.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {
namespace fs = FeatureRecon::sampling;
constexpr int side = 512;

const std::vector<std::uint8_t>& image() {
  static std::vector<std::uint8_t> bytes;
  if (bytes.empty()) {
    std::mt19937_64 rng(5);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    std::vector<double> v(std::size_t(side) * side * 3, 128);
    for (int k = 0; k < 150; ++k) {
      const double cx = u() * side, cy = u() * side, r = 8 + 50 * u();
      const double colour[3] = {255 * u(), 255 * u(), 255 * u()};
      for (int y = std::max(0, int(cy - r)); y < std::min(side, int(cy + r) + 1); ++y)
        for (int x = std::max(0, int(cx - r)); x < std::min(side, int(cx + r) + 1); ++x)
          if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r)
            for (int c = 0; c < 3; ++c)
              v[(std::size_t(y) * side + std::size_t(x)) * 3 + std::size_t(c)] = colour[c];
    }
    bytes.resize(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      bytes[i] = std::uint8_t(std::clamp(v[i] + 24 * u() - 12, 0.0, 255.0));
  }
  return bytes;
}

const fs::Bilateral_filter_result& exact() {
  static const fs::Bilateral_filter_result r = fs::bilateral_filter(side, side, 3, image());
  return r;
}

fs::Sampled_bilateral_filter_options options(const benchmark::State& state, fs::Tap_mode mode) {
  fs::Sampled_bilateral_filter_options o;
  o.mode = mode;
  o.sampling = state.range(0) == 0 ? fs::Tap_sampling::uniform : fs::Tap_sampling::bilateral;
  o.budget = double(state.range(1)) / 100;
  o.seed = 1;
  return o;
}

void quality(benchmark::State& state, const fs::Bilateral_filter_result& r) {
  state.counters["psnr_db"] = fs::psnr(exact().values, r.values);
  state.counters["ssim"] = fs::ssim(side, side, 3, exact().values, r.values);
  state.counters["taps_per_kernel_pixel"] = r.taps_per_kernel_pixel;
}

void BM_Exact(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fs::bilateral_filter(side, side, 3, image()));
}

void BM_Global_pattern(benchmark::State& state) {
  const auto o = options(state, fs::Tap_mode::global);
  for (auto _ : state) benchmark::DoNotOptimize(fs::bilateral_tap_pattern(side, side, 3, image(), o));
}

void BM_Global_filter(benchmark::State& state) {
  const auto o = options(state, fs::Tap_mode::global);
  const fs::Tap_pattern pattern = fs::bilateral_tap_pattern(side, side, 3, image(), o);
  fs::Bilateral_filter_result r;
  for (auto _ : state) r = fs::sampled_bilateral_filter(side, side, 3, image(), pattern, o);
  quality(state, r);
}

void BM_Local(benchmark::State& state) {
  const auto o = options(state, fs::Tap_mode::local);
  fs::Bilateral_filter_result r;
  for (auto _ : state) r = fs::sampled_bilateral_filter(side, side, 3, image(), o);
  quality(state, r);
}

void budgets(benchmark::internal::Benchmark* b) {
  b->ArgNames({"bilateral", "budget_percent"});
  for (int s : {0, 1})
    for (int budget : {25, 50, 100}) b->Args({s, budget});
  b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
}
}  // namespace

BENCHMARK(BM_Exact)
    ->Name("sampling/bilateral_filter/exact_512x512_rgb")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_Global_pattern)->Name("sampling/bilateral_filter/global_pattern_512x512_rgb")->Apply(budgets);
BENCHMARK(BM_Global_filter)->Name("sampling/bilateral_filter/global_filter_512x512_rgb")->Apply(budgets);
BENCHMARK(BM_Local)->Name("sampling/bilateral_filter/local_512x512_rgb")->Apply(budgets);
BENCHMARK_MAIN();
