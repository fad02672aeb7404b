// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// From unorganised points to a Reeb graph, stage by stage: Rips graph, Rips 2-complex, geodesic function,
// augmented Reeb graph, Reeb graph. Input: a noisy figure-eight (generated; argv[1] may name a point file
// with "x y" lines instead, argv[2] the radius). With --svg FILE it also draws the points and the Reeb graph
// (each arc through the positions of its input vertices, nodes coloured by type): doc/images/.

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {
/// Writes the points and the Reeb graph as an SVG picture (y up); false when the file cannot be written.
bool write_svg(const std::string& path, const std::vector<std::array<double, 2>>& points,
               const FeatureRecon::skeleton::Reeb_graph& reeb) {
  namespace sk = FeatureRecon::skeleton;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : points) {
    x0 = std::min(x0, p[0]);
    y0 = std::min(y0, p[1]);
    x1 = std::max(x1, p[0]);
    y1 = std::max(y1, p[1]);
  }
  const double scale = 560.0 / std::max({x1 - x0, y1 - y0, 1e-9}), margin = 20, top = 44;
  const double width = std::max(700.0, 2 * margin + (x1 - x0) * scale);
  const double left = (width - (x1 - x0) * scale) / 2;
  auto X = [&](double x) { return left + (x - x0) * scale; };
  auto Y = [&](double y) { return top + (y1 - y) * scale; };
  std::ofstream out(path);
  const double height = top + margin + (y1 - y0) * scale;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& p : points)
    out << "<circle cx=\"" << X(p[0]) << "\" cy=\"" << Y(p[1]) << "\" r=\"1.6\" fill=\"#bbbbbb\"/>\n";
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                           "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  std::size_t k = 0;
  for (const auto& arc : reeb.arcs) {
    out << "<polyline fill=\"none\" stroke-width=\"2.5\" stroke=\"" << colours[k++ % 8] << "\" points=\"";
    std::vector<sk::Vertex_index> chain{reeb.nodes[arc.lower].vertex};
    chain.insert(chain.end(), arc.vertices.begin(), arc.vertices.end());
    chain.push_back(reeb.nodes[arc.upper].vertex);
    for (const sk::Vertex_index v : chain) out << X(points[v][0]) << "," << Y(points[v][1]) << " ";
    out << "\"/>\n";
  }
  for (const auto& node : reeb.nodes) {
    const char* fill = (node.type & sk::minimum)     ? "#000000"
                       : (node.type & sk::maximum)   ? "#ffffff"
                       : (node.type & sk::down_fork) ? "#d62728"
                                                     : "#2ca02c";
    out << "<circle cx=\"" << X(points[node.vertex][0]) << "\" cy=\"" << Y(points[node.vertex][1])
        << "\" r=\"6\" stroke=\"black\" stroke-width=\"1.5\" fill=\"" << fill << "\"/>\n";
  }
  out << "<text x=\"" << margin
      << "\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">Reeb graph of the geodesic"
      << " function: " << reeb.nodes.size() << " nodes, " << reeb.arcs.size() << " arcs, " << reeb.loops()
      << " loops</text>\n<text x=\"" << margin
      << "\" y=\"33\" font-family=\"sans-serif\" font-size=\"12\">arcs through their input points; nodes: "
         "black minimum, white maximum, green up-fork,"
      << " red down-fork</text>\n</svg>\n";
  out.close();
  return static_cast<bool>(out);
}
}  // namespace

int main(int argc, char** argv) {
  namespace sk = FeatureRecon::skeleton;
  const char* usage =
      "usage: %s [POINTS_FILE [RADIUS]] [--svg FILE]\n"
      "  POINTS_FILE  'x y' lines (default: a noisy figure-eight of 400 points), RADIUS default 0.6\n";
  std::string svg;
  if (argc > 2 && std::strcmp(argv[argc - 2], "--svg") == 0) {
    svg = argv[argc - 1];
    argc -= 2;
  }
  if (argc > 3 || (argc > 1 && argv[1][0] == '-')) {
    std::fprintf(stderr, usage, argv[0]);
    return argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) ? 0 : 2;
  }
  std::vector<std::array<double, 2>> points;
  double radius = 0.6;
  if (argc > 1) {
    std::ifstream in(argv[1]);
    if (!in) {
      std::fprintf(stderr, "%s: cannot read '%s'\n", argv[0], argv[1]);
      return 1;
    }
    double x, y;
    while (in >> x >> y) points.push_back({x, y});
    if (!in.eof()) {
      std::fprintf(stderr, "%s: '%s': point %zu is not two numbers\n", argv[0], argv[1], points.size());
      return 1;
    }
    if (points.empty()) {
      std::fprintf(stderr, "%s: '%s' holds no 'x y' lines\n", argv[0], argv[1]);
      return 1;
    }
    if (argc > 2) {
      char* end = nullptr;
      radius = std::strtod(argv[2], &end);
      if (end == argv[2] || *end != '\0' || !(radius > 0 && std::isfinite(radius))) {
        std::fprintf(stderr, "%s: RADIUS must be a positive number, got '%s'\n", argv[0], argv[2]);
        return 2;
      }
    }
  } else {
    // Two circles of radius 2 touching at (0, 2), 200 noisy samples each (fixed seed).
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0.0, 0.05);
    const double pi = std::acos(-1.0);
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < 200; ++i) {
        const double a = 2 * pi * i / 200;
        points.push_back(
            {2 * std::sin(a) + noise(rng), (c == 0 ? -2 * std::cos(a) : 4 + 2 * std::cos(a)) + noise(rng)});
      }
  }

  // Stage 1: the proximity graph (kd-tree in 2D) and its Rips 2-complex.
  const sk::Proximity_graph graph = sk::build_rips_graph(points, radius);
  const sk::Simplicial_complex_2 complex = sk::build_flag_complex_2(graph);
  std::printf("Rips complex: %zu vertices, %zu edges, %zu triangles\n", complex.number_of_vertices,
              complex.number_of_edges(), complex.number_of_triangles());

  // Stage 2: geodesic distance to the vertex farthest from vertex 0.
  const sk::Geodesic_result geodesic = sk::compute_geodesic_function(complex);
  std::printf("base point: vertex %zu\n", geodesic.base_points.at(0));

  // Stage 3: augmented Reeb graph (every vertex is a node), then the Reeb graph proper.
  const sk::Augmented_reeb_graph augmented = sk::compute_augmented_reeb_graph(complex, geodesic.values);
  const sk::Reeb_graph reeb = augmented.reeb_graph();
  std::printf("Reeb graph: %zu nodes, %zu arcs, %zu loops, %zu components\n", reeb.nodes.size(),
              reeb.arcs.size(), reeb.loops(), reeb.components);
  for (const auto& node : reeb.nodes) {
    std::printf("  node at vertex %u, f = %.3f:", node.vertex, node.value);
    if (node.type & sk::minimum) std::printf(" minimum");
    if (node.type & sk::maximum) std::printf(" maximum");
    if (node.type & sk::up_fork) std::printf(" up-fork");
    if (node.type & sk::down_fork) std::printf(" down-fork");
    std::printf("\n");
  }
  for (const auto& arc : reeb.arcs)
    std::printf("  arc %zu -> %zu through %zu vertices\n", arc.lower, arc.upper, arc.vertices.size());
  if (!svg.empty() && !write_svg(svg, points, reeb)) {
    std::fprintf(stderr, "%s: cannot write '%s'\n", argv[0], svg.c_str());
    return 1;
  }
  return 0;
}
