// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Exact-count and radius sampling of point sets (issue 4, section 5): FeatureRecon's weighted sample
// elimination and dart throwing (Euclidean and bilateral) against GUDHI's choose_n_farthest_points and
// sparsify_point_set (2D) and CGAL's grid, hierarchy and WLOP simplification (points with normals on the
// surface of a cube, whose edges are creases). Every benchmark reports the output size and its relative
// radius rho = d_min / d_hex.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/grid_simplify_point_set.h>
#include <CGAL/hierarchy_simplify_point_set.h>
#include <CGAL/property_map.h>
#include <CGAL/wlop_simplify_and_regularize_point_set.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bench_common.h"
#ifdef FEATURERECON_WITH_GUDHI
#include "sampling/gudhi_subsampling_peer.h"
#endif
#ifdef FEATURERECON_WITH_OPEN3D
#include "sampling/open3d_peer.h"
#endif
#include <CGAL/IO/polygon_soup_io.h>

namespace {
using namespace FeatureRecon;
namespace fs = FeatureRecon::sampling;
using K = CGAL::Epick;
using Pwn = std::pair<K::Point_3, K::Vector_3>;

double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// n uniform points in the unit square; with `outlier`, one more point far away at (1e7, 0) (last).
const std::vector<K::Point_2>& square(std::size_t n, bool outlier = false) {
  static std::map<std::pair<std::size_t, bool>, std::vector<K::Point_2>> cache;
  auto& p = cache[{n, outlier}];
  if (p.empty()) {
    std::mt19937_64 rng(1);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = uniform01(rng);
      p.emplace_back(x, uniform01(rng));
    }
    if (outlier) p.emplace_back(1e7, 0);
  }
  return p;
}

/// The centres of a side x side picture's pixels in the unit square: many pairs at each distance, so that the
/// count of a throw jumps over most goals.
const std::vector<K::Point_2>& pixel_grid(std::size_t side) {
  static std::map<std::size_t, std::vector<K::Point_2>> cache;
  auto& p = cache[side];
  if (p.empty())
    for (std::size_t i = 0; i < side; ++i)
      for (std::size_t j = 0; j < side; ++j)
        p.emplace_back((double(i) + 0.5) / double(side), (double(j) + 0.5) / double(side));
  return p;
}

/// n points on the surface of the unit cube with their face normals (12 crease edges).
const std::vector<Pwn>& cube(std::size_t n) {
  static std::map<std::size_t, std::vector<Pwn>> cache;
  auto& p = cache[n];
  if (p.empty()) {
    std::mt19937_64 rng(2);
    for (std::size_t i = 0; i < n; ++i) {
      const int face = int(rng() % 6), axis = face / 2;
      double c[3] = {uniform01(rng), uniform01(rng), uniform01(rng)};
      c[axis] = face % 2;
      double nv[3] = {0, 0, 0};
      nv[axis] = face % 2 ? 1 : -1;
      p.push_back({K::Point_3(c[0], c[1], c[2]), K::Vector_3(nv[0], nv[1], nv[2])});
    }
  }
  return p;
}

/// Relative radius of the kept points of the unit square (a far outlier left out).
double rho_2d(const std::vector<K::Point_2>& s) {
  std::vector<K::Point_2> inside;
  for (const auto& q : s)
    if (q.x() <= 1) inside.push_back(q);
  fs::Sampling_quality_options o;
  o.domain_measure = 1;
  return fs::sampling_quality(inside, o).relative_radius;
}
double rho_cube(const std::vector<K::Point_3>& s) {
  fs::Sampling_quality_options o;
  o.domain_measure = 6;
  o.intrinsic_dimension = 2;
  return fs::sampling_quality(s, o).relative_radius;
}

template <bool Outlier>
void BM_elimination_2d(benchmark::State& state) {
  const auto& p = square(std::size_t(state.range(0)), Outlier);
  const std::size_t m = std::size_t(state.range(1));
  std::vector<std::size_t> kept;
  for (auto _ : state) {
    kept.clear();
    fs::Elimination_options o;
    o.domain_measure = 1;
    fs::weighted_sample_elimination(p, m, std::back_inserter(kept), o);
  }
  std::vector<K::Point_2> s;
  for (std::size_t i : kept) s.push_back(p[i]);
  state.counters["kept"] = double(kept.size());
  state.counters["rho"] = rho_2d(s);
}

// The same squares sampled on the unit torus (Elimination_options::periodic,
// Dart_throwing_options::periodic), rho measured on the torus: the cost of the nearest-image distances and
// the shifted grid look-ups.
void BM_periodic_2d(benchmark::State& state) {
  const auto& p = square(std::size_t(state.range(0)), false);
  const bool darts = state.range(2) != 0;
  std::vector<std::size_t> kept;
  for (auto _ : state) {
    kept.clear();
    if (darts) {
      fs::Dart_throwing_options o;
      o.periodic = true;
      fs::bilateral_dart_throwing(p, double(state.range(1)) / 1000.0, std::back_inserter(kept), o);
    } else {
      fs::Elimination_options o;
      o.periodic = true;
      fs::weighted_sample_elimination(p, std::size_t(state.range(1)), std::back_inserter(kept), o);
    }
  }
  std::vector<K::Point_2> s;
  for (std::size_t i : kept) s.push_back(p[i]);
  fs::Sampling_quality_options q;
  q.periodic = true;
  state.counters["kept"] = double(kept.size());
  state.counters["rho"] = fs::sampling_quality(s, q).relative_radius;
}

template <bool Outlier>
void BM_darts_2d(benchmark::State& state) {
  const auto& p = square(std::size_t(state.range(0)), Outlier);
  const double r = double(state.range(1)) / 1000.0;
  std::vector<std::size_t> kept;
  for (auto _ : state) {
    kept.clear();
    fs::bilateral_dart_throwing(p, r, std::back_inserter(kept));
  }
  std::vector<K::Point_2> s;
  for (std::size_t i : kept) s.push_back(p[i]);
  state.counters["kept"] = double(kept.size());
  state.counters["rho"] = rho_2d(s);
}

// Dart throwing with an exact count (bilateral_dart_throwing_count: a radius search of whole throws), against
// the same count by elimination and by GUDHI's farthest-point sampling.
template <bool Grid>
void BM_darts_count_2d(benchmark::State& state) {
  const auto& p = Grid ? pixel_grid(std::size_t(state.range(0))) : square(std::size_t(state.range(0)), false);
  const std::size_t m = std::size_t(state.range(1));
  std::vector<std::size_t> kept;
  std::size_t throws = 0;
  for (auto _ : state) {
    kept.clear();
    fs::Dart_throwing_count_options o;
    throws = 0;
    o.darts.progress = [&throws](double) { return ++throws > 0; };
    fs::bilateral_dart_throwing_count(p, m, std::back_inserter(kept), o);
  }
  std::vector<K::Point_2> s;
  for (std::size_t i : kept) s.push_back(p[i]);
  state.counters["kept"] = double(kept.size());
  state.counters["throws"] = double(throws - 1);  // a progress call per throw, and the last one
  state.counters["rho"] = rho_2d(s);
}

void BM_elimination_cube(benchmark::State& state) {
  const auto& p = cube(200000);
  const bool bilateral = state.range(0) != 0;
  std::vector<std::size_t> kept;
  for (auto _ : state) {
    kept.clear();
    fs::Elimination_options o;
    o.domain_measure = 6;
    o.intrinsic_dimension = 2;
    if (bilateral) o.sigma_feature = 0.5;
    fs::weighted_sample_elimination(p, 10000, std::back_inserter(kept), o);
  }
  std::vector<K::Point_3> s;
  for (std::size_t i : kept) s.push_back(p[i].first);
  state.counters["kept"] = double(kept.size());
  state.counters["rho"] = rho_cube(s);
}

std::vector<K::Point_3> cube_points() {
  std::vector<K::Point_3> q;
  for (const Pwn& x : cube(200000)) q.push_back(x.first);
  return q;
}

void BM_cgal_grid(benchmark::State& state) {
  std::vector<K::Point_3> q;
  for (auto _ : state) {
    state.PauseTiming();
    q = cube_points();
    state.ResumeTiming();
    q.erase(CGAL::grid_simplify_point_set(q, 0.0245), q.end());
  }
  state.counters["kept"] = double(q.size());
  state.counters["rho"] = rho_cube(q);
}

void BM_cgal_hierarchy(benchmark::State& state) {
  std::vector<K::Point_3> q;
  for (auto _ : state) {
    state.PauseTiming();
    q = cube_points();
    state.ResumeTiming();
    q.erase(CGAL::hierarchy_simplify_point_set(q, CGAL::parameters::size(20).maximum_variation(0.33)),
            q.end());
  }
  state.counters["kept"] = double(q.size());
  state.counters["rho"] = rho_cube(q);
}

void BM_cgal_wlop(benchmark::State& state) {
  std::vector<K::Point_3> q = cube_points();  // WLOP shuffles its input
  std::vector<K::Point_3> out;
  for (auto _ : state) {
    out.clear();
    CGAL::wlop_simplify_and_regularize_point_set<CGAL::Sequential_tag>(
        q, std::back_inserter(out), CGAL::parameters::select_percentage(5.0));
  }
  state.counters["kept"] = double(out.size());
  state.counters["rho"] = rho_cube(out);
}

#ifdef FEATURERECON_WITH_GUDHI
std::vector<std::array<double, 2>> square_arrays(std::size_t n, bool outlier) {
  std::vector<std::array<double, 2>> a;
  for (const auto& x : square(n, outlier)) a.push_back({x.x(), x.y()});
  return a;
}
std::vector<K::Point_2> to_points(const std::vector<std::array<double, 2>>& a) {
  std::vector<K::Point_2> p;
  for (const auto& x : a) p.emplace_back(x[0], x[1]);
  return p;
}
template <bool Outlier>
void BM_gudhi_farthest(benchmark::State& state) {
  const auto a = square_arrays(std::size_t(state.range(0)), Outlier);
  std::vector<std::array<double, 2>> out;
  for (auto _ : state) out = bench::gudhi_choose_n_farthest_points(a, std::size_t(state.range(1)));
  state.counters["kept"] = double(out.size());
  state.counters["rho"] = rho_2d(to_points(out));
}
void BM_gudhi_farthest_pixels(benchmark::State& state) {
  std::vector<std::array<double, 2>> a;
  for (const auto& x : pixel_grid(std::size_t(state.range(0)))) a.push_back({x.x(), x.y()});
  std::vector<std::array<double, 2>> out;
  for (auto _ : state) out = bench::gudhi_choose_n_farthest_points(a, std::size_t(state.range(1)));
  state.counters["kept"] = double(out.size());
  state.counters["rho"] = rho_2d(to_points(out));
}
template <bool Outlier>
void BM_gudhi_sparsify(benchmark::State& state) {
  const auto a = square_arrays(std::size_t(state.range(0)), Outlier);
  std::vector<std::array<double, 2>> out;
  for (auto _ : state) out = bench::gudhi_sparsify_point_set(a, double(state.range(1)) / 1000.0);
  state.counters["kept"] = double(out.size());
  state.counters["rho"] = rho_2d(to_points(out));
}
#endif

/// fandisk as a triangle soup (from ../shared/data), with its area.
struct Soup {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
  double area = 0;
};
const Soup& fandisk() {
  static Soup s;
  if (!s.vertices.empty()) return s;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(FEATURERECON_SHARED_DATA_DIR "/meshes/fandisk.off", points, polygons))
    throw std::runtime_error("cannot read fandisk.off from ../shared/data/meshes");
  for (const auto& p : points) s.vertices.push_back({p.x(), p.y(), p.z()});
  for (const auto& f : polygons) {
    s.triangles.push_back({int(f[0]), int(f[1]), int(f[2])});
    s.area += std::sqrt(K::Triangle_3(points[f[0]], points[f[1]], points[f[2]]).squared_area());
  }
  return s;
}

/// As Open3D does it: count x init_factor area-uniform samples of the mesh, then exact-count elimination.
void BM_fandisk_featurerecon(benchmark::State& state) {
  const Soup& m = fandisk();
  const std::size_t count = std::size_t(state.range(0));
  std::vector<K::Point_3> out;
  for (auto _ : state) {
    std::mt19937_64 rng(3);
    std::vector<double> cumulative;
    double total = 0;
    for (const auto& t : m.triangles) {
      const K::Point_3 a(m.vertices[t[0]][0], m.vertices[t[0]][1], m.vertices[t[0]][2]),
          b(m.vertices[t[1]][0], m.vertices[t[1]][1], m.vertices[t[1]][2]),
          c(m.vertices[t[2]][0], m.vertices[t[2]][1], m.vertices[t[2]][2]);
      cumulative.push_back(total += std::sqrt(K::Triangle_3(a, b, c).squared_area()));
    }
    std::vector<K::Point_3> dense;
    for (std::size_t i = 0; i < 5 * count; ++i) {
      const std::size_t k = std::min<std::size_t>(
          m.triangles.size() - 1,
          std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total) -
                      cumulative.begin()));
      double u = uniform01(rng), v = uniform01(rng);
      if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      const auto& t = m.triangles[k];
      std::array<double, 3> p;
      for (int d = 0; d < 3; ++d)
        p[d] = m.vertices[t[0]][d] + u * (m.vertices[t[1]][d] - m.vertices[t[0]][d]) +
               v * (m.vertices[t[2]][d] - m.vertices[t[0]][d]);
      dense.emplace_back(p[0], p[1], p[2]);
    }
    fs::Elimination_options o;
    o.intrinsic_dimension = 2;
    o.domain_measure = total;
    std::vector<std::size_t> kept;
    fs::weighted_sample_elimination(dense, count, std::back_inserter(kept), o);
    out.clear();
    for (std::size_t i : kept) out.push_back(dense[i]);
  }
  fs::Sampling_quality_options q;
  q.intrinsic_dimension = 2;
  q.domain_measure = m.area;
  state.counters["kept"] = double(out.size());
  state.counters["rho"] = fs::sampling_quality(out, q).relative_radius;
}

#ifdef FEATURERECON_WITH_OPEN3D
void BM_fandisk_open3d(benchmark::State& state) {
  const Soup& m = fandisk();
  std::vector<std::array<double, 3>> out;
  for (auto _ : state)
    out = bench::open3d_poisson_disk(m.vertices, m.triangles, std::size_t(state.range(0)), 5);
  std::vector<K::Point_3> p;
  for (const auto& x : out) p.emplace_back(x[0], x[1], x[2]);
  fs::Sampling_quality_options q;
  q.intrinsic_dimension = 2;
  q.domain_measure = m.area;
  state.counters["kept"] = double(p.size());
  state.counters["rho"] = fs::sampling_quality(p, q).relative_radius;
}
#endif

/// 160,000 points: white noise in the unit square (0), or half of them in the corner square of side 0.01 (1).
const std::vector<K::Point_2>& quality_set(int clustered) {
  static std::map<int, std::vector<K::Point_2>> cache;
  auto& p = cache[clustered];
  if (p.empty()) {
    std::mt19937_64 rng(3);
    for (std::size_t i = 0; i < 160000; ++i) {
      const double s = clustered && i % 2 ? 0.01 : 1.0;
      const double x = s * uniform01(rng);
      p.emplace_back(x, s * uniform01(rng));
    }
  }
  return p;
}
/// sampling_quality: every point's nearest neighbour (exact, ties by index), d_min, rho and the averages.
void BM_quality(benchmark::State& state) {
  const auto& p = quality_set(int(state.range(0)));
  double rho = 0;
  for (auto _ : state) {
    fs::Sampling_quality_options o;
    o.domain_measure = 1;
    fs::Sampling_quality q = fs::sampling_quality(p, o);
    benchmark::DoNotOptimize(q);
    rho = q.relative_radius;
  }
  state.counters["rho"] = rho;
}
/// Peer: the same nearest neighbours from CGAL's kd-tree (2 neighbours of each point, itself included).
void BM_cgal_nearest(benchmark::State& state) {
  using Traits = CGAL::Search_traits_2<K>;
  using Knn = CGAL::Orthogonal_k_neighbor_search<Traits>;
  const auto& p = quality_set(int(state.range(0)));
  double smallest = 0;
  for (auto _ : state) {
    Knn::Tree tree(p.begin(), p.end());
    tree.build();
    smallest = std::numeric_limits<double>::infinity();
    for (const auto& q : p) {
      Knn search(tree, q, 2);
      for (auto it = search.begin(); it != search.end(); ++it)
        if (it->second > 0) smallest = std::min(smallest, it->second);
    }
    benchmark::ClobberMemory();
  }
  state.counters["d_min"] = std::sqrt(smallest);
}

/// sampling_spectrum() of N white-noise points on the unit torus at the default F = 6 sqrt(N), by the sums'
/// method (0 direct, 1 gridded); the counter is the oscillation, the same to about 1e-11 either way.
void BM_spectrum(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0));
  std::mt19937_64 rng(5);
  std::vector<K::Point_2> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = uniform01(rng);
    p.emplace_back(x, uniform01(rng));
  }
  fs::Sampling_spectrum_options o;
  o.method = state.range(1) == 0 ? fs::Spectrum_method::direct : fs::Spectrum_method::gridded;
  double oscillation = 0;
  for (auto _ : state) {
    const fs::Sampling_spectrum s = fs::sampling_spectrum(p, o);
    benchmark::DoNotOptimize(s);
    oscillation = s.oscillation;
  }
  state.counters["oscillation"] = oscillation;
}

void register_all() {
  auto ms = [](benchmark::internal::Benchmark* b) { return b->Unit(benchmark::kMillisecond)->UseRealTime(); };
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/elimination_2d", BM_elimination_2d<false>))
      ->Args({50000, 10000})
      ->Args({500000, 100000})
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/darts_2d", BM_darts_2d<false>))
      ->Args({100000, 20})
      ->Args({1000000, 10})
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/darts_count_2d", BM_darts_count_2d<false>))
      ->Args({50000, 10000})
      ->Args({500000, 100000})
      ->MinTime(1.0);
  // Arguments: the side of the pixel grid, the count.
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/darts_count_pixels", BM_darts_count_2d<true>))
      ->Args({512, 5000})
      ->Args({512, 20000})
      ->MinTime(1.0);
  // Arguments: candidates, count (elimination) or radius in thousandths (darts), darts or not.
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/periodic_2d", BM_periodic_2d))
      ->Args({50000, 10000, 0})
      ->Args({500000, 100000, 0})
      ->Args({100000, 20, 1})
      ->MinTime(1.0);
  // The same squares plus one point at (1e7, 0): the grids must keep their cell size.
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/elimination_2d_outlier", BM_elimination_2d<true>))
      ->Args({50000, 10000})
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/darts_2d_outlier", BM_darts_2d<true>))
      ->Args({100000, 20})
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/elimination_cube200k_euclidean",
                                  BM_elimination_cube))
      ->Arg(0)
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/elimination_cube200k_bilateral",
                                  BM_elimination_cube))
      ->Arg(1)
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/quality_160k", BM_quality))->Arg(0)->Arg(1);
  ms(benchmark::RegisterBenchmark("sampling/cgal/nearest_160k", BM_cgal_nearest))->Arg(0)->Arg(1);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/spectrum_direct", BM_spectrum))
      ->Args({1024, 0})
      ->Args({4096, 0})
      ->Args({16384, 0})
      ->Iterations(1);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/spectrum_gridded", BM_spectrum))
      ->Args({1024, 1})
      ->Args({4096, 1})
      ->Args({16384, 1})
      ->Args({100000, 1})
      ->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/cgal/grid_cube200k", BM_cgal_grid))->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/cgal/hierarchy_cube200k", BM_cgal_hierarchy))->MinTime(1.0);
  ms(benchmark::RegisterBenchmark("sampling/cgal/wlop_cube200k", BM_cgal_wlop))->Iterations(1);
  ms(benchmark::RegisterBenchmark("sampling/featurerecon/fandisk_poisson_disk", BM_fandisk_featurerecon))
      ->Arg(10000)
      ->Arg(50000)
      ->MinTime(1.0);
#ifdef FEATURERECON_WITH_OPEN3D
  ms(benchmark::RegisterBenchmark("sampling/open3d/fandisk_poisson_disk", BM_fandisk_open3d))
      ->Arg(10000)
      ->Arg(50000)
      ->MinTime(1.0);
#endif
#ifdef FEATURERECON_WITH_GUDHI
  ms(benchmark::RegisterBenchmark("sampling/gudhi/choose_n_farthest_points_2d", BM_gudhi_farthest<false>))
      ->Args({50000, 10000})
      ->Iterations(3);
  ms(benchmark::RegisterBenchmark("sampling/gudhi/choose_n_farthest_points_pixels", BM_gudhi_farthest_pixels))
      ->Args({512, 5000})
      ->Args({512, 20000})
      ->Iterations(1);
  ms(benchmark::RegisterBenchmark("sampling/gudhi/sparsify_point_set_2d", BM_gudhi_sparsify<false>))
      ->Args({100000, 20})
      ->Args({1000000, 10})
      ->Iterations(3);
  ms(benchmark::RegisterBenchmark("sampling/gudhi/choose_n_farthest_points_2d_outlier",
                                  BM_gudhi_farthest<true>))
      ->Args({50000, 10000})
      ->Iterations(3);
  ms(benchmark::RegisterBenchmark("sampling/gudhi/sparsify_point_set_2d_outlier", BM_gudhi_sparsify<true>))
      ->Args({100000, 20})
      ->Iterations(3);
#endif
}
}  // namespace

int main(int argc, char** argv) { return FeatureRecon::bench::run_benchmarks(argc, argv, register_all); }
