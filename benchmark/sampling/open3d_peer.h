// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Open3D's Poisson-disk sampling of a triangle mesh, in its own translation unit.
#ifndef FEATURERECON_BENCHMARK_SAMPLING_OPEN3D_PEER_H
#define FEATURERECON_BENCHMARK_SAMPLING_OPEN3D_PEER_H

#include <array>
#include <cstddef>
#include <vector>

namespace FeatureRecon {
namespace bench {
/// open3d::geometry::TriangleMesh::SamplePointsPoissonDisk(count, init_factor): uniform samples of the mesh
/// (init_factor x count), then weighted sample elimination.
std::vector<std::array<double, 3>> open3d_poisson_disk(const std::vector<std::array<double, 3>>& vertices,
                                                       const std::vector<std::array<int, 3>>& triangles,
                                                       std::size_t count, double init_factor);
}  // namespace bench
}  // namespace FeatureRecon

#endif  // FEATURERECON_BENCHMARK_SAMPLING_OPEN3D_PEER_H
