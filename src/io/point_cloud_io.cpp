// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "io/point_cloud_io.h"

#include "io/featurerecon_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>

namespace FeatureRecon {
namespace io {
namespace {
using K = CGAL::Epick;
using Pwn = std::pair<K::Point_3, K::Vector_3>;
using Point_map = CGAL::First_of_pair_property_map<Pwn>;
using Normal_map = CGAL::Second_of_pair_property_map<Pwn>;


[[noreturn]] void fail(const std::string& path, const std::string& what) { throw Input_error(path + ": " + what); }

/// Whether the file stores normals, from its header (PLY, OFF) or its first data line (XYZ).
bool file_has_normals(const std::string& path, const std::string& ext) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  std::string line;
  if (ext == "ply") {
    bool normals = false;
    while (std::getline(in, line)) {
      if (line.rfind("property", 0) == 0 && (line.find(" nx") != std::string::npos)) normals = true;
      if (line.rfind("end_header", 0) == 0) return normals;
    }
    fail(path, "no PLY header (end_header missing)");
  }
  if (ext == "off") {
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      return line.rfind("NOFF", 0) == 0 || line.rfind("CNOFF", 0) == 0;
    }
    fail(path, "empty file");
  }
  while (std::getline(in, line)) {  // xyz
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double x;
    int count = 0;
    while (s >> x) ++count;
    if (count != 3 && count != 6) fail(path, "expected 3 or 6 numbers per line (x y z [nx ny nz]), got " + std::to_string(count));
    return count == 6;
  }
  fail(path, "empty file");
}
}  // namespace

Point_cloud read_point_cloud(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext != "ply" && ext != "off" && ext != "xyz")
    fail(path, "unknown point-cloud format '." + ext + "' (expected .ply, .off or .xyz)");
  require_readable_file(path);
  const bool normals = file_has_normals(path, ext);
  std::vector<Pwn> pwn;
  bool ok = false;
  if (normals)
    ok = CGAL::IO::read_points(path, std::back_inserter(pwn),
                               CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  else
    ok = CGAL::IO::read_points(path, std::back_inserter(pwn), CGAL::parameters::point_map(Point_map()));
  if (!ok) fail(path, "not a readable " + ext + " point cloud");
  if (pwn.empty()) fail(path, "no points");
  Point_cloud c;
  c.points.reserve(pwn.size());
  for (std::size_t i = 0; i < pwn.size(); ++i) {
    const K::Point_3& p = pwn[i].first;
    if (!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      fail(path, "point " + std::to_string(i) + " has a non-finite coordinate");
    c.points.push_back({p.x(), p.y(), p.z()});
    if (normals) c.normals.push_back({pwn[i].second.x(), pwn[i].second.y(), pwn[i].second.z()});
  }
  return c;
}

void write_point_cloud(const std::string& path, const Point_cloud& cloud, const std::vector<std::size_t>& indices) {
  const std::string ext = file_extension(path);
  if (ext != "ply" && ext != "off" && ext != "xyz")
    throw Input_error(path + ": unknown point-cloud format '." + ext + "' (expected .ply, .off or .xyz)");
  std::vector<Pwn> pwn;
  pwn.reserve(indices.size());
  for (const std::size_t i : indices) {
    const auto& p = cloud.points[i];
    const auto n = cloud.has_normals() ? cloud.normals[i] : std::array<double, 3>{0, 0, 0};
    pwn.push_back({K::Point_3(p[0], p[1], p[2]), K::Vector_3(n[0], n[1], n[2])});
  }
  bool ok = false;
  if (cloud.has_normals())
    ok = CGAL::IO::write_points(path, pwn,
                                CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).stream_precision(17).use_binary_mode(false));
  else
    ok = CGAL::IO::write_points(path, pwn,
                                CGAL::parameters::point_map(Point_map()).stream_precision(17).use_binary_mode(false));
  if (!ok) throw Input_error(path + ": cannot write");
}

void estimate_normals(Point_cloud& cloud, unsigned neighbors) {
  std::vector<Pwn> pwn;
  pwn.reserve(cloud.points.size());
  for (const auto& p : cloud.points) pwn.push_back({K::Point_3(p[0], p[1], p[2]), K::Vector_3(0, 0, 0)});
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(pwn, neighbors,
                                                   CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  // mst_orient_normals reorders the range: orient tuples that remember the indices.
  using Indexed = std::tuple<K::Point_3, K::Vector_3, std::size_t>;
  std::vector<Indexed> indexed;
  indexed.reserve(pwn.size());
  for (std::size_t i = 0; i < pwn.size(); ++i) indexed.emplace_back(pwn[i].first, pwn[i].second, i);
  CGAL::mst_orient_normals(indexed, neighbors,
                           CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Indexed>())
                               .normal_map(CGAL::Nth_of_tuple_property_map<1, Indexed>()));
  cloud.normals.assign(pwn.size(), {0, 0, 0});
  for (const auto& [p, n, i] : indexed) {
    (void)p;
    const double len = std::sqrt(n.squared_length());
    cloud.normals[i] = len > 0 ? std::array<double, 3>{n.x() / len, n.y() / len, n.z() / len}
                               : std::array<double, 3>{0, 0, 1};
  }
}

}  // namespace io
}  // namespace FeatureRecon
