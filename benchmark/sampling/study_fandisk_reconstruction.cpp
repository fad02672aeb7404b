// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Reconstruction study (issue 4, section 4): fandisk sampled densely (points with face normals), downsampled
// to 5, 10 and 20 % by bilateral elimination, Euclidean elimination, CGAL's WLOP, hierarchy and grid
// simplification, each reconstructed with CGAL's advancing front. Reports the two-sided distance between the
// reconstruction and the original mesh, near the creases (within 2 sample spacings of a sharp edge) and
// elsewhere, in units of the sample spacing h = sqrt(area / M). Prints a Markdown table.
//
// usage: study_fandisk_reconstruction [MESH.off] [DENSE_POINTS] [SVG_DIRECTORY]
//   (defaults: ../shared/data/meshes/fandisk.off, 200000; with a directory, the 10 % bilateral and Euclidean
//   samplings are drawn there as fandisk_sampling_{bilateral,euclidean}.svg, samples near creases in red)
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/grid_simplify_point_set.h>
#include <CGAL/hierarchy_simplify_point_set.h>
#include <CGAL/wlop_simplify_and_regularize_point_set.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {
using K = CGAL::Epick;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Pwn = std::pair<Point, Vector>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Mesh_tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using Triangles = std::vector<K::Triangle_3>;
using Triangle_tree =
    CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;
using Segments = std::vector<K::Segment_3>;
using Segment_tree =
    CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;

double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// Uniform samples of triangles (area-weighted), with the triangles' unit normals.
std::vector<Pwn> sample_triangles(const Triangles& t, std::size_t n, std::uint64_t seed) {
  std::vector<double> cumulative;
  double total = 0;
  for (const auto& tr : t) cumulative.push_back(total += std::sqrt(tr.squared_area()));
  std::mt19937_64 rng(seed);
  std::vector<Pwn> out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = std::size_t(
        std::lower_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total) - cumulative.begin());
    const auto& tr = t[std::min(k, t.size() - 1)];
    double a = uniform01(rng), b = uniform01(rng);
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    const Point p = tr[0] + a * (tr[1] - tr[0]) + b * (tr[2] - tr[0]);
    Vector nv = CGAL::cross_product(tr[1] - tr[0], tr[2] - tr[0]);
    nv = nv / std::sqrt(nv.squared_length());
    out.push_back({p, nv});
  }
  return out;
}

struct Stats {
  double mean = 0, p99 = 0, max = 0;
};
Stats stats(std::vector<double> d) {
  Stats s;
  if (d.empty()) return s;
  std::sort(d.begin(), d.end());
  for (double x : d) s.mean += x / double(d.size());
  s.p99 = d[std::min(d.size() - 1, std::size_t(0.99 * double(d.size())))];
  s.max = d.back();
  return s;
}

/// A count-controlled peer: bisects a parameter until the output size is within 3 % of the budget.
std::vector<Point> bisect_to_budget(const std::vector<Point>& in, std::size_t budget, double lo, double hi,
                                    bool larger_keeps_fewer,
                                    const std::function<std::vector<Point>(double)>& run) {
  std::vector<Point> best;
  for (int it = 0; it < 30; ++it) {
    const double mid = std::sqrt(lo * hi);
    std::vector<Point> out = run(mid);
    if (best.empty() ||
        std::abs(double(out.size()) - double(budget)) < std::abs(double(best.size()) - double(budget)))
      best = out;
    if (std::abs(double(out.size()) - double(budget)) <= 0.03 * double(budget)) break;
    if ((out.size() > budget) == larger_keeps_fewer)
      lo = mid;
    else
      hi = mid;
  }
  (void)in;
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : FEATURERECON_SHARED_DATA_DIR "/meshes/fandisk.off";
  const std::size_t dense = argc > 2 ? std::size_t(std::stoul(argv[2])) : 200000;
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty()) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    return 1;
  }
  const double area = PMP::area(mesh);
  Triangles mesh_triangles;
  for (auto f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    mesh_triangles.emplace_back(mesh.point(target(h, mesh)), mesh.point(target(next(h, mesh), mesh)),
                                mesh.point(source(h, mesh)));
  }
  // Creases: edges with a dihedral angle sharper than 60 degrees.
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, 60.0, sharp);
  Segments creases;
  for (auto e : edges(mesh))
    if (sharp[e])
      creases.emplace_back(mesh.point(source(halfedge(e, mesh), mesh)),
                           mesh.point(target(halfedge(e, mesh), mesh)));
  const Segment_tree crease_tree(creases.begin(), creases.end());
  Mesh_tree mesh_tree(faces(mesh).first, faces(mesh).second, mesh);
  mesh_tree.accelerate_distance_queries();

  const std::vector<Pwn> cloud = sample_triangles(mesh_triangles, dense, 1);
  std::vector<Point> cloud_points;
  for (const Pwn& p : cloud) cloud_points.push_back(p.first);
  std::printf("mesh %s: %zu faces, area %.4f, %zu sharp edges; %zu dense samples with face normals\n\n",
              path.c_str(), std::size_t(mesh.number_of_faces()), area, creases.size(), dense);
  std::printf(
      "| budget | method | samples | triangles | near creases: mean / p99 / max (h) | elsewhere: mean / p99 "
      "/ max (h) | seconds (sampling) |\n");
  std::printf("|---|---|---:|---:|---|---|---:|\n");
  for (const double fraction : {0.05, 0.10, 0.20}) {
    const std::size_t budget = std::size_t(fraction * double(dense));
    const double h = std::sqrt(area / double(budget));
    struct Run {
      const char* name;
      std::vector<Point> points;
      double seconds;
    };
    std::vector<Run> runs;
    auto timed = [&](const char* name, const std::function<std::vector<Point>()>& f) {
      const auto t0 = std::chrono::steady_clock::now();
      std::vector<Point> p = f();
      runs.push_back(
          {name, std::move(p), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
    };
    for (const bool bilateral : {true, false})
      timed(bilateral ? "bilateral elimination (sigma_f 0.5)" : "Euclidean elimination", [&] {
        FeatureRecon::sampling::Elimination_options o;
        o.intrinsic_dimension = 2;
        o.domain_measure = area;
        if (bilateral) o.sigma_feature = 0.5;
        std::vector<std::size_t> kept;
        FeatureRecon::sampling::weighted_sample_elimination(cloud, budget, std::back_inserter(kept), o);
        std::vector<Point> p;
        for (std::size_t i : kept) p.push_back(cloud[i].first);
        return p;
      });
    timed("CGAL WLOP", [&] {
      std::vector<Point> in = cloud_points, out;
      CGAL::wlop_simplify_and_regularize_point_set<CGAL::Sequential_tag>(
          in, std::back_inserter(out), CGAL::parameters::select_percentage(100 * fraction));
      return out;
    });
    timed("CGAL hierarchy", [&] {
      return bisect_to_budget(cloud_points, budget, 2, 400, true, [&](double size) {
        std::vector<Point> p = cloud_points;
        p.erase(CGAL::hierarchy_simplify_point_set(
                    p, CGAL::parameters::size(unsigned(size)).maximum_variation(1.0 / 3)),
                p.end());
        return p;
      });
    });
    timed("CGAL grid", [&] {
      return bisect_to_budget(cloud_points, budget, h / 10, h * 10, true, [&](double eps) {
        std::vector<Point> p = cloud_points;
        p.erase(CGAL::grid_simplify_point_set(p, eps), p.end());
        return p;
      });
    });
    if (argc > 3 && fraction == 0.10)
      for (std::size_t k = 0; k < 2; ++k) {  // runs[0] bilateral, runs[1] Euclidean
        const std::string out =
            std::string(argv[3]) + "/fandisk_sampling_" + (k == 0 ? "bilateral" : "euclidean") + ".svg";
        std::FILE* f = std::fopen(out.c_str(), "w");
        if (!f) continue;
        // Orthographic view: rotate about z by 30 degrees, then about x by -60 degrees.
        auto project = [](const Point& p) {
          const double c = std::cos(0.52), s = std::sin(0.52), x = c * p.x() - s * p.y(),
                       y = s * p.x() + c * p.y();
          const double ca = std::cos(-1.05), sa = std::sin(-1.05);
          return std::array<double, 2>{x, ca * y - sa * p.z()};
        };
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (const Point& p : runs[k].points) {
          const auto q = project(p);
          for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], q[d]), hi[d] = std::max(hi[d], q[d]);
        }
        const double scale = 700 / std::max(hi[0] - lo[0], hi[1] - lo[1]);
        std::fprintf(f,
                     "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\">\n<rect "
                     "width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                     (hi[0] - lo[0]) * scale + 20, (hi[1] - lo[1]) * scale + 20);
        for (const Point& p : runs[k].points) {
          const auto q = project(p);
          const bool near_crease = !creases.empty() && std::sqrt(crease_tree.squared_distance(p)) < 2 * h;
          std::fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"1.1\" fill=\"%s\"/>\n",
                       (q[0] - lo[0]) * scale + 10, (hi[1] - q[1]) * scale + 10,
                       near_crease ? "#d62728" : "#1f3b73");
        }
        std::fprintf(f, "</svg>\n");
        std::fclose(f);
      }
    for (const Run& r : runs) {
      std::vector<std::array<std::size_t, 3>> faces_out;
      CGAL::advancing_front_surface_reconstruction(r.points.begin(), r.points.end(),
                                                   std::back_inserter(faces_out));
      Triangles rec;
      for (const auto& f : faces_out) rec.emplace_back(r.points[f[0]], r.points[f[1]], r.points[f[2]]);
      std::vector<double> near, far;
      if (!rec.empty()) {
        Triangle_tree rec_tree(rec.begin(), rec.end());
        rec_tree.accelerate_distance_queries();
        auto classify = [&](const Point& p, double d) {
          const double to_crease = creases.empty() ? 1e300 : std::sqrt(crease_tree.squared_distance(p));
          (to_crease < 2 * h ? near : far).push_back(d / h);
        };
        // Original -> reconstruction: the dense samples (every 4th); reconstruction -> original: samples of
        // it.
        for (std::size_t i = 0; i < cloud.size(); i += 4)
          classify(cloud[i].first, std::sqrt(rec_tree.squared_distance(cloud[i].first)));
        for (const Pwn& q : sample_triangles(rec, dense / 4, 2))
          classify(mesh_tree.closest_point(q.first), std::sqrt(mesh_tree.squared_distance(q.first)));
      }
      const Stats a = stats(near), b = stats(far);
      std::printf("| %.0f %% | %s | %zu | %zu | %.3f / %.2f / %.2f | %.3f / %.2f / %.2f | %.2f |\n",
                  100 * fraction, r.name, r.points.size(), rec.size(), a.mean, a.p99, a.max, b.mean, b.p99,
                  b.max, r.seconds);
      std::fflush(stdout);
    }
  }
  return 0;
}
