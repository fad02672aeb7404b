// SPDX-License-Identifier: GPL-3.0-or-later
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>

std::size_t loops_of_other_translation_unit() {
  const auto K = FeatureRecon::skeleton::make_simplicial_complex_2(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {});
  return FeatureRecon::skeleton::compute_augmented_reeb_graph(K, std::vector<double>{0, 1, 2, 1.5})
      .reeb_graph()
      .loops();
}
