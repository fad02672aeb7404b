// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_INTERNAL_EXACT_DISTANCE_H
#define FEATURERECON_SKELETON_INTERNAL_EXACT_DISTANCE_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>

#include <cstddef>

namespace FeatureRecon {
namespace skeleton {
namespace internal {

/// \cond
/// Exact sign of |p - q|^2 - |p - s|^2 (coordinates are doubles, d of them): interval filter, then
/// exact rational arithmetic. Returns -1, 0 or +1.
inline int compare_squared_distances(const double* p, const double* q, const double* s, std::size_t d) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    CGAL::Interval_nt<false> a(0), b(0);
    for (std::size_t i = 0; i < d; ++i) {
      const CGAL::Interval_nt<false> u = CGAL::Interval_nt<false>(p[i]) - q[i];
      const CGAL::Interval_nt<false> v = CGAL::Interval_nt<false>(p[i]) - s[i];
      a += CGAL::square(u);
      b += CGAL::square(v);
    }
    const CGAL::Uncertain<CGAL::Comparison_result> c = CGAL::compare(a, b);
    if (CGAL::is_certain(c)) return static_cast<int>(CGAL::get_certain(c));
  }
  CGAL::Exact_rational a(0), b(0);
  for (std::size_t i = 0; i < d; ++i) {
    const CGAL::Exact_rational u = CGAL::Exact_rational(p[i]) - CGAL::Exact_rational(q[i]);
    const CGAL::Exact_rational v = CGAL::Exact_rational(p[i]) - CGAL::Exact_rational(s[i]);
    a += u * u;
    b += v * v;
  }
  return a < b ? -1 : (b < a ? 1 : 0);
}

/// Exact test |p - q| <= r for double coordinates and a double radius r >= 0.
inline bool distance_at_most(const double* p, const double* q, std::size_t d, double r) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    CGAL::Interval_nt<false> a(0);
    for (std::size_t i = 0; i < d; ++i) a += CGAL::square(CGAL::Interval_nt<false>(p[i]) - q[i]);
    const CGAL::Uncertain<bool> c = (a <= CGAL::square(CGAL::Interval_nt<false>(r)));
    if (CGAL::is_certain(c)) return CGAL::get_certain(c);
  }
  CGAL::Exact_rational a(0);
  for (std::size_t i = 0; i < d; ++i) {
    const CGAL::Exact_rational u = CGAL::Exact_rational(p[i]) - CGAL::Exact_rational(q[i]);
    a += u * u;
  }
  const CGAL::Exact_rational rr(r);
  return !(rr * rr < a);
}
/// \endcond

}  // namespace internal
}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_INTERNAL_EXACT_DISTANCE_H
