// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Rips 2-complex construction: FeatureRecon (build_rips_graph + build_flag_complex_2) vs GUDHI
// (Rips_complex + create_complex(simplex_tree, 2)) on the same points and radius; one case with an outlier
// far away (the float filter of the brute-force search was centred at the mean: every pair went to the exact
// stage) and one with two clusters far apart (each is searched alone since session 40).
#include <FeatureRecon/skeleton/embed_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <CGAL/Epick_d.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_d.h>
#include <CGAL/Simple_cartesian.h>
#include <benchmark/benchmark.h>

#ifdef FEATURERECON_WITH_GUDHI
#include <gudhi/Rips_complex.h>
#include <gudhi/Simplex_tree.h>
#include <gudhi/distance_functions.h>
#endif

#include <map>
#include <memory>
#include <random>

#include "bench_common.h"

namespace {
using namespace FeatureRecon;
namespace sk = FeatureRecon::skeleton;

struct Case {
  std::vector<std::vector<double>> points;
  double radius = 0;
};

const Case& get_case(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Case>> cache;
  auto& slot = cache[name];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  if (name == "chicago20k_r20") {
    for (const auto& p : bench::chicago_points(20000)) slot->points.push_back({p[0], p[1]});
    slot->radius = 20.0;
  } else if (name == "chicago118k_r4") {
    for (const auto& p : bench::chicago_points()) slot->points.push_back({p[0], p[1]});
    slot->radius = 4.0;
  } else if (name == "uniform3d_50k") {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 50000; ++i) slot->points.push_back({u(rng), u(rng), u(rng)});
    slot->radius = 0.04;
  } else if (name == "gaussian50d_5k") {
    std::mt19937 rng(2);
    std::normal_distribution<double> g(0, 1);
    for (int i = 0; i < 5000; ++i) {
      std::vector<double> p(50);
      for (double& x : p) x = g(rng);
      slot->points.push_back(p);
    }
    slot->radius = 6.5;
  } else if (name ==
             "gaussian50d_5k_outlier") {  // the same points, one of them moved to 1e7 on the first axis
    slot->points = get_case("gaussian50d_5k").points;
    slot->points[2500][0] = 1e7;
    slot->radius = 6.5;
  } else if (name == "gaussian50d_5k_two_clusters") {  // the same points, every other one moved by 1e7
    slot->points = get_case("gaussian50d_5k").points;
    for (std::size_t i = 1; i < slot->points.size(); i += 2) slot->points[i][0] += 1e7;
    slot->radius = 6.5;
  }
  return *slot;
}

void BM_rips_featurerecon(benchmark::State& state, const std::string& name) {
  const Case& c = get_case(name);
  std::size_t simplices = 0;
  for (auto _ : state) {
    const sk::Simplicial_complex_2 k = sk::build_flag_complex_2(sk::build_rips_graph(c.points, c.radius));
    simplices = k.number_of_vertices + k.number_of_edges() + k.number_of_triangles();
    benchmark::DoNotOptimize(k);
  }
  state.counters["simplices"] = static_cast<double>(simplices);
}

#ifdef FEATURERECON_WITH_GUDHI
void BM_rips_gudhi(benchmark::State& state, const std::string& name) {
  const Case& c = get_case(name);
  std::size_t simplices = 0;
  for (auto _ : state) {
    Gudhi::rips_complex::Rips_complex<double> rips(c.points, c.radius, Gudhi::Euclidean_distance());
    Gudhi::Simplex_tree<> st;
    rips.create_complex(st, 2);
    simplices = st.num_simplices();
    benchmark::DoNotOptimize(st);
  }
  state.counters["simplices"] = static_cast<double>(simplices);
}
#endif

// k nearest neighbours on points with many copies (8,000 of one point beside a line), on a plain grid and on
// the Gaussian cases in R^50 above: FeatureRecon's build_knn_graph (exact, ties by index, each distinct
// position searched once) against CGAL's own Orthogonal_k_neighbor_search asked for k + 1 neighbours of every
// point (no tie rule; in R^50 on Epick_d points with Search_traits_d).
std::vector<std::vector<double>> knn_points(const std::string& name) {
  std::vector<std::vector<double>> p;
  if (name.rfind("gaussian50d", 0) == 0) return get_case(name).points;
  if (name == "copies8100") {  // 8,000 copies of one point and a line of 100 points beside it
    for (int c = 0; c < 8000; ++c) p.push_back({0.0, 0.0});
    for (int i = 0; i < 100; ++i) p.push_back({10.0 + i, 0.0});
  } else {
    for (int i = 0; i < 141; ++i)
      for (int j = 0; j < 141; ++j) p.push_back({double(i), double(j)});
  }
  return p;
}

void BM_knn_featurerecon(benchmark::State& state, const std::string& name) {
  const auto p = knn_points(name);
  std::size_t edges = 0;
  for (auto _ : state) {
    const sk::Proximity_graph g = sk::build_knn_graph(p, 8);
    edges = g.edges.size();
    benchmark::DoNotOptimize(g);
  }
  state.counters["edges"] = static_cast<double>(edges);
}

/// CGAL's Orthogonal_k_neighbor_search for 9 neighbours of every point (the tree built in the loop).
template <class Traits, class Point>
void cgal_knn(benchmark::State& state, const std::vector<Point>& p) {
  using Knn = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::size_t found = 0;
  for (auto _ : state) {
    typename Knn::Tree tree(p.begin(), p.end());
    tree.build();
    found = 0;
    for (const auto& q : p) {
      Knn search(tree, q, 9);
      for (auto it = search.begin(); it != search.end(); ++it) ++found;
    }
    benchmark::DoNotOptimize(found);
  }
  state.counters["neighbours"] = static_cast<double>(found);
}

/// The peer in R^50: CGAL's kd-tree on dD points (Epick_d, dynamic dimension).
void BM_knn_cgal_dd(benchmark::State& state, const std::string& name) {
  using K = CGAL::Epick_d<CGAL::Dynamic_dimension_tag>;
  std::vector<K::Point_d> p;
  for (const auto& q : knn_points(name)) p.emplace_back(static_cast<int>(q.size()), q.begin(), q.end());
  cgal_knn<CGAL::Search_traits_d<K>>(state, p);
}

void BM_knn_cgal(benchmark::State& state, const std::string& name) {
  using K = CGAL::Simple_cartesian<double>;
  std::vector<K::Point_2> p;
  for (const auto& q : knn_points(name)) p.emplace_back(q[0], q[1]);
  cgal_knn<CGAL::Search_traits_2<K>>(state, p);
}

/// Distance matrices for classical MDS (2,000 points): "circle50d" a noisy circle of radius 10 in R^50 (noise
/// 0.3 per axis; Euclidean); "sqrt5d" the square roots of the distances of Gaussian points in R^5 (not
/// Euclidean); "uniform12" entries uniform in [1, 2] (no geometry; the top eigenvalues crowd together, the
/// unit tests' case).
std::vector<double> mds_matrix(const std::string& name, std::size_t n) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  if (name == "uniform12") {
    std::uniform_real_distribution<double> u(1.0, 2.0);
    std::vector<double> D(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) D[i * n + j] = D[j * n + i] = u(rng);
    return D;
  }
  const std::size_t d = name == "circle50d" ? 50 : 5;
  std::vector<std::vector<double>> p(n, std::vector<double>(d));
  for (std::size_t i = 0; i < n; ++i) {
    for (auto& x : p[i]) x = name == "circle50d" ? 0.3 * g(rng) : 10.0 * g(rng);
    if (name == "circle50d") {
      p[i][0] += 10 * std::cos(6.283185307179586 * double(i) / double(n));
      p[i][1] += 10 * std::sin(6.283185307179586 * double(i) / double(n));
    }
  }
  std::vector<double> D(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < d; ++k) s += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
      D[i * n + j] = name == "circle50d" ? std::sqrt(s) : std::sqrt(std::sqrt(s));
    }
  return D;
}

/// classical_mds_3d: FeatureRecon's block Lanczos (dense_limit 300, the default) or the dense Eigen
/// SelfAdjointEigenSolver on the same double-centred matrix (dense_limit above n), the peer.
void BM_mds(benchmark::State& state, const std::string& name, std::size_t dense_limit) {
  const std::size_t n = 2000;
  const std::vector<double> D = mds_matrix(name, n);
  double first = 0;
  for (auto _ : state) {
    bool stopped = false;
    const auto x = sk::internal::classical_mds_3d(D, n, Progress_callback(), stopped, dense_limit);
    first = x[0][0];
    benchmark::DoNotOptimize(x);
  }
  state.counters["x0"] = first;
}

void register_all() {
  for (const std::string name : {"circle50d", "sqrt5d", "uniform12"}) {
    benchmark::RegisterBenchmark(("mds2000/featurerecon/" + name).c_str(), BM_mds, name, std::size_t(300))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("mds2000/eigen_dense/" + name).c_str(), BM_mds, name, std::size_t(1) << 40)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
  for (const std::string name : {"copies8100", "grid20k"}) {
    benchmark::RegisterBenchmark(("knn8/featurerecon/" + name).c_str(), BM_knn_featurerecon, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("knn8/cgal/" + name).c_str(), BM_knn_cgal, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  for (const std::string name : {"gaussian50d_5k", "gaussian50d_5k_outlier", "gaussian50d_5k_two_clusters"}) {
    benchmark::RegisterBenchmark(("knn8/featurerecon/" + name).c_str(), BM_knn_featurerecon, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("knn8/cgal_dD/" + name).c_str(), BM_knn_cgal_dd, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
  for (const std::string name : {"chicago20k_r20", "chicago118k_r4", "uniform3d_50k", "gaussian50d_5k",
                                 "gaussian50d_5k_outlier", "gaussian50d_5k_two_clusters"}) {
    benchmark::RegisterBenchmark(("rips/featurerecon/" + name).c_str(), BM_rips_featurerecon, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(1.0);
#ifdef FEATURERECON_WITH_GUDHI
    benchmark::RegisterBenchmark(("rips/gudhi/" + name).c_str(), BM_rips_gudhi, name)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
#endif
  }
}
}  // namespace

int main(int argc, char** argv) { return FeatureRecon::bench::run_benchmarks(argc, argv, register_all); }
