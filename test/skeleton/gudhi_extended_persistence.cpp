// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "gudhi_extended_persistence.h"

#include <iostream>  // GUDHI 3.7 uses std::cout without including it

#include <gudhi/Persistent_cohomology.h>
#include <gudhi/Simplex_tree.h>

#include <algorithm>
#include <cmath>

namespace FeatureRecon {
namespace test {

/// GUDHI extended persistence of the lower-star filtration with integer vertex values `value`, on a
/// complex given by its simplices (vertices 0..n-1). Zero-length pairs are dropped.
Extended_diagrams gudhi_extended_persistence(std::size_t n, const std::vector<std::vector<int>>& simplices,
                                             const std::vector<long>& value) {
  using ST = Gudhi::Simplex_tree<>;
  using PCoh =
      Gudhi::persistent_cohomology::Persistent_cohomology<ST, Gudhi::persistent_cohomology::Field_Zp>;
  ST st;
  for (std::size_t v = 0; v < n; ++v) st.insert_simplex({static_cast<int>(v)}, static_cast<double>(value[v]));
  for (const auto& s : simplices) {
    long f = 0;
    for (int v : s) f = std::max(f, value[static_cast<std::size_t>(v)]);
    st.insert_simplex_and_subfaces(s, static_cast<double>(f));
  }
  st.make_filtration_non_decreasing();
  const auto efd = st.extend_filtration();
  PCoh pcoh(st);
  pcoh.init_coefficients(2);
  pcoh.compute_persistent_cohomology(0.0);
  Extended_diagrams d;
  for (const auto& pair : pcoh.get_persistent_pairs()) {
    const auto b_sh = std::get<0>(pair), d_sh = std::get<1>(pair);
    if (d_sh == st.null_simplex()) continue;
    const int dim = st.dimension(b_sh);
    const auto b = st.decode_extended_filtration(st.filtration(b_sh), efd);
    const auto e = st.decode_extended_filtration(st.filtration(d_sh), efd);
    if (b.second == Gudhi::Extended_simplex_type::EXTRA || e.second == Gudhi::Extended_simplex_type::EXTRA)
      continue;
    const Point_pair p{std::lround(b.first), std::lround(e.first)};
    if (p.first == p.second) continue;
    if (dim > 2) continue;
    using T = Gudhi::Extended_simplex_type;
    if (b.second == T::UP && e.second == T::UP)
      d.ord[dim].push_back(p);
    else if (b.second == T::DOWN && e.second == T::DOWN)
      d.rel[dim].push_back(p);
    else if (p.first < p.second)
      d.ext_plus[dim].push_back(p);
    else
      d.ext_minus[dim].push_back(p);
  }
  for (int k = 0; k < 3; ++k)
    for (auto* v : {&d.ord[k], &d.rel[k], &d.ext_plus[k], &d.ext_minus[k]}) std::sort(v->begin(), v->end());
  return d;
}

}  // namespace test
}  // namespace FeatureRecon
