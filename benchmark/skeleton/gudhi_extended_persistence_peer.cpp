// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "gudhi_extended_persistence_peer.h"

#include <iostream>  // GUDHI 3.7 uses std::cout without including it

#include <gudhi/Persistent_cohomology.h>
#include <gudhi/Rips_complex.h>
#include <gudhi/Simplex_tree.h>
#include <gudhi/distance_functions.h>

#include <algorithm>

namespace FeatureRecon {
namespace bench {
namespace {

using ST = Gudhi::Simplex_tree<>;

Gudhi_result extended_persistence(ST& st, const std::vector<double>& values) {
  // Lower-star filtration of the vertex values.
  for (auto sh : st.complex_simplex_range()) {
    double f = -std::numeric_limits<double>::infinity();
    for (auto v : st.simplex_vertex_range(sh)) f = std::max(f, values[static_cast<std::size_t>(v)]);
    st.assign_filtration(sh, f);
  }
  st.initialize_filtration();
  Gudhi_result r;
  r.simplices = st.num_simplices();
  const auto efd = st.extend_filtration();
  Gudhi::persistent_cohomology::Persistent_cohomology<ST, Gudhi::persistent_cohomology::Field_Zp> pcoh(st);
  pcoh.init_coefficients(2);
  pcoh.compute_persistent_cohomology(0.0);
  for (const auto& pair : pcoh.get_persistent_pairs()) {
    if (std::get<1>(pair) == st.null_simplex()) continue;
    const auto b = st.decode_extended_filtration(st.filtration(std::get<0>(pair)), efd);
    if (b.second == Gudhi::Extended_simplex_type::EXTRA) continue;
    ++r.pairs;
  }
  return r;
}

}  // namespace

Gudhi_result gudhi_rips_extended_persistence(const std::vector<std::vector<double>>& points, double radius,
                                             const std::vector<double>& values) {
  Gudhi::rips_complex::Rips_complex<double> rips(points, radius, Gudhi::Euclidean_distance());
  ST st;
  rips.create_complex(st, 2);
  return extended_persistence(st, values);
}

Gudhi_result gudhi_flag_extended_persistence(std::size_t n,
                                             const std::vector<std::array<std::uint32_t, 2>>& edges,
                                             const std::vector<double>& values) {
  ST st;
  for (std::size_t v = 0; v < n; ++v) st.insert_simplex({static_cast<int>(v)}, 0.0);
  for (const auto& e : edges) st.insert_simplex({static_cast<int>(e[0]), static_cast<int>(e[1])}, 0.0);
  st.expansion(2);
  return extended_persistence(st, values);
}

}  // namespace bench
}  // namespace FeatureRecon
