// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <iostream>  // GUDHI 3.7 headers use std::cerr without including it

#include "gudhi_subsampling_peer.h"

#include <CGAL/Epick_d.h>
#include <gudhi/choose_n_farthest_points.h>
#include <gudhi/sparsify_point_set.h>

#include <iterator>

namespace FeatureRecon {
namespace bench {
namespace {
using Kernel = CGAL::Epick_d<CGAL::Dimension_tag<2>>;
using Point = Kernel::Point_d;
std::vector<Point> to_points(const std::vector<std::array<double, 2>>& p) {
  std::vector<Point> q;
  q.reserve(p.size());
  for (const auto& x : p) q.emplace_back(x[0], x[1]);
  return q;
}
std::vector<std::array<double, 2>> from_points(const std::vector<Point>& q) {
  std::vector<std::array<double, 2>> p;
  for (const Point& x : q) p.push_back({x[0], x[1]});
  return p;
}
}  // namespace

std::vector<std::array<double, 2>> gudhi_choose_n_farthest_points(const std::vector<std::array<double, 2>>& p,
                                                                  std::size_t count) {
  const std::vector<Point> q = to_points(p);
  std::vector<Point> out;
  Kernel k;
  Gudhi::subsampling::choose_n_farthest_points(k.squared_distance_d_object(), q, count, 0,
                                               std::back_inserter(out));
  return from_points(out);
}

std::vector<std::array<double, 2>> gudhi_sparsify_point_set(const std::vector<std::array<double, 2>>& p,
                                                            double min_distance) {
  const std::vector<Point> q = to_points(p);
  std::vector<Point> out;
  Gudhi::subsampling::sparsify_point_set(Kernel(), q, min_distance * min_distance, std::back_inserter(out));
  return from_points(out);
}
}  // namespace bench
}  // namespace FeatureRecon
