// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// GUDHI's extended persistence of a lower-star filtration, behind a plain interface: GUDHI's union-find
// does not compile in a translation unit that also includes CGAL's graph headers, so it lives alone.
#ifndef FEATURERECON_TEST_SKELETON_GUDHI_EXTENDED_PERSISTENCE_H
#define FEATURERECON_TEST_SKELETON_GUDHI_EXTENDED_PERSISTENCE_H

#include <cstddef>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace test {

using Point_pair = std::pair<long, long>;
/// The four extended subdiagrams (Ordinary, Relative, Extended+, Extended-) per dimension 0, 1, 2.
struct Extended_diagrams {
  std::vector<Point_pair> ord[3], rel[3], ext_plus[3], ext_minus[3];
};

/// GUDHI extended persistence of the lower-star filtration with integer vertex values `value`, on a
/// complex given by its simplices (vertices 0..n-1). Zero-length pairs are dropped; diagrams sorted.
Extended_diagrams gudhi_extended_persistence(std::size_t n, const std::vector<std::vector<int>>& simplices,
                                             const std::vector<long>& value);

}  // namespace test
}  // namespace FeatureRecon

#endif
