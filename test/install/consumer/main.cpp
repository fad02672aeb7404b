// SPDX-License-Identifier: GPL-3.0-or-later
// A program using the installed headers; linked with other.cpp, which includes the same headers, so a
// missing `inline` shows up as a duplicate symbol.
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplicial_complex_from_mesh.h>

#include <cmath>
#include <cstdio>
#include <vector>

std::size_t loops_of_other_translation_unit();

int main() {
  std::vector<std::array<double, 2>> circle;
  for (int i = 0; i < 60; ++i)
    circle.push_back({std::cos(i * 0.10471975511965977), std::sin(i * 0.10471975511965977)});
  const auto K = FeatureRecon::skeleton::build_rips_complex_2(circle, 0.25);
  const auto f = FeatureRecon::skeleton::compute_geodesic_function(K).values;
  const auto R = FeatureRecon::skeleton::compute_augmented_reeb_graph(K, f).reeb_graph();
  std::printf("loops %zu %zu\n", R.loops(), loops_of_other_translation_unit());
  return (R.loops() == 1 && loops_of_other_translation_unit() == 1) ? 0 : 1;
}
