// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// A skeleton in R^50 with the one-call pipeline: a noisy sample of a figure-eight with a tail (two circles in
// random planes of R^50, touching at one point, and a segment hanging off one circle),
// extract_reeb_skeleton() with a Rips radius and a persistence threshold, then the result: its nodes, arcs
// and loops, how far its input-space polylines are from the true graph, the same with the radius and
// threshold estimated from the points (estimate_rips_radius()), and (with --svg FILE) a picture of the 3D
// embedding (PCA of the points, viewed at an angle): doc/images/high_dimensional_skeleton.svg.

#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace sk = FeatureRecon::skeleton;

namespace {

constexpr std::size_t D = 50;
constexpr double pi = 3.14159265358979323846;

/// Gaussian numbers by Box-Muller from a mt19937 (the same on every standard library).
struct Gaussian {
  std::mt19937 rng;
  double operator()() {
    const double u = (rng() + 0.5) / 4294967296.0, v = (rng() + 0.5) / 4294967296.0;
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * pi * v);
  }
};

using Vec = std::vector<double>;

Vec unit(Gaussian& g) {
  Vec v(D);
  double n = 0;
  for (double& x : v) {
    x = g();
    n += x * x;
  }
  for (double& x : v) x /= std::sqrt(n);
  return v;
}

/// The true graph as a polyline soup: segments (a, b) in R^50.
struct Truth {
  std::vector<std::pair<Vec, Vec>> segments;
  double distance(const double* p) const {
    double best = 1e300;
    for (const auto& [a, b] : segments) {
      double ab = 0, t = 0;
      for (std::size_t k = 0; k < D; ++k)
        ab += (b[k] - a[k]) * (b[k] - a[k]), t += (p[k] - a[k]) * (b[k] - a[k]);
      t = std::clamp(t / ab, 0.0, 1.0);
      double s = 0;
      for (std::size_t k = 0; k < D; ++k)
        s += (a[k] + t * (b[k] - a[k]) - p[k]) * (a[k] + t * (b[k] - a[k]) - p[k]);
      best = std::min(best, std::sqrt(s));
    }
    return best;
  }
};

/// Figure-eight (two circles of radius 2 in random planes, touching at the origin) with a tail of length 4
/// from the far point of the second circle; every segment sampled every 0.25 with noise 0.01 per coordinate.
Truth make_truth(Gaussian& g) {
  Truth t;
  Vec far;
  for (int c = 0; c < 2; ++c) {
    Vec e1 = unit(g), e2 = unit(g);
    double dot = 0, n = 0;
    for (std::size_t k = 0; k < D; ++k) dot += e1[k] * e2[k];
    for (std::size_t k = 0; k < D; ++k) n += (e2[k] -= dot * e1[k]) * e2[k];
    for (double& x : e2) x /= std::sqrt(n);
    const double side = c == 0 ? -1 : 1;
    auto at = [&](double a) {
      Vec p(D);
      for (std::size_t k = 0; k < D; ++k)
        p[k] = side * 2 * (1 - std::cos(a)) * e1[k] + 2 * std::sin(a) * e2[k];
      return p;
    };
    for (int i = 0; i < 64; ++i) t.segments.push_back({at(2 * pi * i / 64), at(2 * pi * (i + 1) / 64)});
    if (c == 1) far = at(pi);
  }
  Vec dir = unit(g), end(D);
  for (std::size_t k = 0; k < D; ++k) end[k] = far[k] + 4 * dir[k];
  t.segments.push_back({far, end});
  return t;
}

sk::Point_matrix sample(const Truth& t, Gaussian& g) {
  sk::Point_matrix m;
  m.dimension = D;
  for (const auto& [a, b] : t.segments) {
    double len = 0;
    for (std::size_t k = 0; k < D; ++k) len += (b[k] - a[k]) * (b[k] - a[k]);
    const int n = std::max(1, static_cast<int>(std::ceil(std::sqrt(len) / 0.25)));
    for (int i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < D; ++k) m.data.push_back(a[k] + (b[k] - a[k]) * i / n + 0.01 * g());
      ++m.rows;
    }
  }
  return m;
}

/// The 3D embedding seen at an angle (orthographic), points grey, arcs coloured, nodes black; false when the
/// file cannot be written.
bool write_svg(const std::string& path, const std::vector<std::array<double, 3>>& xyz,
               const sk::Skeleton_graph& g) {
  const double ca = std::cos(0.6), sa = std::sin(0.6), cb = std::cos(0.35), sb = std::sin(0.35);
  auto view = [&](const std::array<double, 3>& p) {
    const double x = ca * p[0] - sa * p[1], y = sa * p[0] + ca * p[1];
    return std::array<double, 2>{x, cb * p[2] - sb * y};
  };
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : xyz) {
    const auto q = view(p);
    x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  }
  const double s = 560 / std::max(x1 - x0, y1 - y0), m = 20, top = 40;
  auto X = [&](double x) { return m + (x - x0) * s; };
  auto Y = [&](double y) { return top + (y1 - y) * s; };
  std::ofstream out(path);
  const double width = 2 * m + (x1 - x0) * s, height = top + m + (y1 - y0) * s;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& p : xyz) {
    const auto q = view(p);
    out << "<circle cx=\"" << X(q[0]) << "\" cy=\"" << Y(q[1]) << "\" r=\"1.5\" fill=\"#bbbbbb\"/>\n";
  }
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                           "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  std::size_t k = 0;
  for (auto e : boost::make_iterator_range(edges(g))) {
    out << "<polyline fill=\"none\" stroke-width=\"3\" stroke=\"" << colours[k++ % 8] << "\" points=\"";
    for (const auto& p : g[e].polyline) {
      const auto q = view(p);
      out << X(q[0]) << "," << Y(q[1]) << " ";
    }
    out << "\"/>\n";
  }
  for (auto v : boost::make_iterator_range(vertices(g))) {
    const auto q = view(g[v].position);
    out << "<circle cx=\"" << X(q[0]) << "\" cy=\"" << Y(q[1]) << "\" r=\"5\" fill=\"black\"/>\n";
  }
  out << "<text x=\"" << m << "\" y=\"22\" font-family=\"sans-serif\" font-size=\"13\">Skeleton of "
      << xyz.size() << " points in R^50 (figure-eight with a tail), PCA to 3D: " << num_vertices(g)
      << " nodes, " << num_edges(g) << " arcs</text>\n</svg>\n";
  out.close();
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  std::string svg;
  if (argc == 3 && std::strcmp(argv[1], "--svg") == 0) {
    svg = argv[2];
  } else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [--svg FILE]\n", argv[0]);
    return std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ? 0 : 2;
  }
  Gaussian g{std::mt19937(2026)};
  const Truth truth = make_truth(g);
  const sk::Point_matrix points = sample(truth, g);

  sk::Skeleton_options options;
  options.delta = 1.0;  // features of persistence <= 1 (noise) go; the loops (height ~4) and the tail stay
  const double rips_radius = 0.7;
  const sk::Reeb_skeleton s = sk::extract_reeb_skeleton(points, rips_radius, options);

  std::vector<int> component(num_vertices(s.graph));
  const std::size_t components =
      static_cast<std::size_t>(boost::connected_components(s.graph, component.data()));
  std::size_t leaves = 0, branch = 0;
  for (auto v : boost::make_iterator_range(vertices(s.graph))) {
    leaves += degree(v, s.graph) == 1;
    branch += degree(v, s.graph) >= 3;
  }
  double farthest = 0;  // from a polyline vertex (in R^50) to the true graph
  for (auto e : boost::make_iterator_range(edges(s.graph))) {
    const auto& line = s.graph[e].input_polyline;
    for (std::size_t i = 0; i + D <= line.size(); i += D)
      farthest = std::max(farthest, truth.distance(&line[i]));
  }
  std::printf("%zu points in R^%zu, Rips radius %.1f, delta %.1f\n", points.rows, points.dimension,
              rips_radius, *options.delta);
  std::printf("Rips 2-complex: %zu edges, %zu triangles\n", s.rips_edges, s.rips_triangles);
  std::printf("skeleton: %zu nodes, %zu arcs, %zu loops, %zu component(s), %zu leaf, %zu branch node(s)\n",
              num_vertices(s.graph), num_edges(s.graph),
              num_edges(s.graph) + components - num_vertices(s.graph), components, leaves, branch);
  std::printf(
      "true graph: 2 loops, 1 leaf, 2 branch nodes (the touching point, of degree 4, where %zu pair(s) of\n"
      "  forks were merged, and the foot of the tail)\n",
      s.merged_branch_arcs);
  // the bound the tests state (doc/skeleton.md, "Graphs in high dimension")
  const double bound = 0.7 * rips_radius;
  std::printf("every arc within 0.7 x radius = %.3f of the true graph: %s (farthest vertex %.2f)\n", bound,
              farthest <= bound ? "yes" : "no", farthest);
  // Without a radius: estimate_rips_radius() reads one off the points (the scale where they look
  // one-dimensional), and extract_reeb_skeleton(points, options) uses it; an automatic delta is the
  // estimate's too.
  const sk::Rips_radius_estimate estimate = sk::estimate_rips_radius(points);
  sk::Skeleton_options automatic;
  automatic.delta = FeatureRecon::automatic;
  const sk::Reeb_skeleton a = sk::extract_reeb_skeleton(points, automatic);
  std::vector<int> a_component(num_vertices(a.graph));
  const std::size_t a_components =
      static_cast<std::size_t>(boost::connected_components(a.graph, a_component.data()));
  std::printf("estimated: radius %.3f (scale %.3f, intrinsic dimension %.2f, gap radius %.3f), delta %.3f\n",
              estimate.radius, estimate.scale, estimate.intrinsic_dimension, estimate.gap_radius,
              estimate.delta);
  std::printf("skeleton at the estimate: %zu nodes, %zu arcs, %zu loops, %zu component(s)\n",
              num_vertices(a.graph), num_edges(a.graph),
              num_edges(a.graph) + a_components - num_vertices(a.graph), a_components);
  if (!svg.empty()) {
    if (!write_svg(svg, sk::project_to_3d(points), s.graph)) {
      std::fprintf(stderr, "%s: cannot write '%s'\n", argv[0], svg.c_str());
      return 1;
    }
    std::printf("wrote %s\n", svg.c_str());
  }
  return 0;
}
