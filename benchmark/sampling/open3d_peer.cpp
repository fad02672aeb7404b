// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "open3d_peer.h"

#include <open3d/geometry/PointCloud.h>
#include <open3d/geometry/TriangleMesh.h>

namespace FeatureRecon {
namespace bench {
std::vector<std::array<double, 3>> open3d_poisson_disk(const std::vector<std::array<double, 3>>& vertices,
                                                       const std::vector<std::array<int, 3>>& triangles,
                                                       std::size_t count, double init_factor) {
  open3d::geometry::TriangleMesh mesh;
  for (const auto& v : vertices) mesh.vertices_.emplace_back(v[0], v[1], v[2]);
  for (const auto& t : triangles) mesh.triangles_.emplace_back(t[0], t[1], t[2]);
  const auto cloud = mesh.SamplePointsPoissonDisk(count, init_factor);
  std::vector<std::array<double, 3>> out;
  for (const auto& p : cloud->points_) out.push_back({p(0), p(1), p(2)});
  return out;
}
}  // namespace bench
}  // namespace FeatureRecon
