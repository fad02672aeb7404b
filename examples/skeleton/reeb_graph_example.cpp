// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// From unorganised points to a Reeb graph, stage by stage: Rips graph, Rips 2-complex, geodesic function,
// augmented Reeb graph, Reeb graph. Input: a noisy figure-eight (generated; argv[1] may name a point file
// with "x y" lines instead).

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <vector>

int main(int argc, char** argv) {
  namespace sk = FeatureRecon::skeleton;
  std::vector<std::array<double, 2>> points;
  double radius = 0.6;
  if (argc > 1) {
    std::ifstream in(argv[1]);
    double x, y;
    while (in >> x >> y) points.push_back({x, y});
    if (argc > 2) radius = std::atof(argv[2]);
  } else {
    // Two circles of radius 2 touching at (0, 2), 200 noisy samples each (fixed seed).
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0.0, 0.05);
    const double pi = std::acos(-1.0);
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < 200; ++i) {
        const double a = 2 * pi * i / 200;
        points.push_back({2 * std::sin(a) + noise(rng), (c == 0 ? -2 * std::cos(a) : 4 + 2 * std::cos(a)) + noise(rng)});
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
  std::printf("Reeb graph: %zu nodes, %zu arcs, %zu loops, %zu components\n", reeb.nodes.size(), reeb.arcs.size(),
              reeb.loops(), reeb.components);
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
  return 0;
}
