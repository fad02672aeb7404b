// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Must not compile (CTest compile_fail_reeb_graph_of_a_graph): compute_augmented_reeb_graph() of a
// Proximity_graph (the Rips graph, before build_flag_complex_2()) picked the triangle-mesh overload and
// failed deep inside CGAL's BGL code; one static_assert now names what to pass.
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplicial_complex_from_mesh.h>

#include <vector>

int main() {
  namespace sk = FeatureRecon::skeleton;
  const std::vector<std::vector<double>> points{{0, 0}, {1, 0}, {0, 1}};
  const sk::Proximity_graph g = sk::build_rips_graph(points, 2.0);
  sk::compute_augmented_reeb_graph(g, std::vector<double>{0, 1, 2});
}
