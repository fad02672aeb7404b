// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Inputs shared by the benchmarks: torus grids and the Chicago GPS points.
#ifndef FEATURERECON_BENCHMARK_BENCH_COMMON_H
#define FEATURERECON_BENCHMARK_BENCH_COMMON_H

#include <FeatureRecon/skeleton/Simplicial_complex_2.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace bench {

/// Torus grid of nu x nv quads (2 triangles each) standing upright, with the tilted height of the design
/// notes' VTK measurement (one loop). Positions are returned for the peers that need them.
struct Torus {
  skeleton::Simplicial_complex_2 complex;
  std::vector<double> f;
  std::vector<std::array<double, 3>> positions;
};

inline Torus torus_grid(std::size_t nu, std::size_t nv) {
  const double pi = std::acos(-1.0), R = 2.0, r = 0.7;
  Torus t;
  std::vector<skeleton::Triangle> tris;
  auto id = [&](std::size_t i, std::size_t j) {
    return static_cast<skeleton::Vertex_index>((i % nu) * nv + (j % nv));
  };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * static_cast<double>(i) / static_cast<double>(nu);
      const double v = 2 * pi * static_cast<double>(j) / static_cast<double>(nv);
      const double x = (R + r * std::cos(v)) * std::cos(u), y = r * std::sin(v),
                   z = (R + r * std::cos(v)) * std::sin(u);
      t.positions.push_back({x, y, z});
      t.f.push_back(z + 0.05 * x + 0.015 * y);
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  t.complex = skeleton::make_simplicial_complex_2(nu * nv, {}, std::move(tris));
  return t;
}

/// The Chicago GPS fixes (trip, x, y, t; UTM metres, seconds) in file order, from the shared data or the
/// bundled copy.
struct Gps_row {
  long trip;
  double x, y, t;
};
inline std::vector<Gps_row> chicago_rows(std::size_t max_rows = 0) {
  std::vector<Gps_row> rows;
  const std::string path = std::string(FEATURERECON_SHARED_DATA_DIR) + "/gps/chicago/tracks.txt";
  auto take = [&](const std::string& l) {
    if (l.empty() || l[0] == '#') return;
    std::istringstream is(l);
    Gps_row r{};
    if (is >> r.trip >> r.x >> r.y >> r.t) rows.push_back(r);
  };
  std::ifstream in(path);
  if (in) {
    std::string line;
    while (std::getline(in, line) && (max_rows == 0 || rows.size() < max_rows)) take(line);
  } else {
    const std::string command =
        "gzip -dc '" + std::string(FEATURERECON_DATA_DIR) + "/gps/chicago/tracks.txt.gz'";
    FILE* pipe = popen(command.c_str(), "r");
    char buf[256];
    while (pipe && std::fgets(buf, sizeof buf, pipe) && (max_rows == 0 || rows.size() < max_rows)) take(buf);
    if (pipe) pclose(pipe);
  }
  if (rows.empty()) {
    std::fprintf(stderr, "cannot read the Chicago tracks (%s)\n", path.c_str());
    std::exit(1);
  }
  return rows;
}

/// The Chicago GPS points (x y, UTM metres) in file order.
inline std::vector<std::array<double, 2>> chicago_points(std::size_t max_points = 0) {
  std::vector<std::array<double, 2>> p;
  for (const Gps_row& r : chicago_rows(max_points)) p.push_back({r.x, r.y});
  return p;
}

/// main() of a benchmark program whose benchmarks are registered at run time by `register_all`.
inline int run_benchmarks(int argc, char** argv, void (*register_all)()) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace bench
}  // namespace FeatureRecon

#endif  // FEATURERECON_BENCHMARK_BENCH_COMMON_H
