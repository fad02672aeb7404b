// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_RADIUS_SEARCH_H
#define FEATURERECON_SAMPLING_INTERNAL_RADIUS_SEARCH_H

#include <algorithm>
#include <cmath>
#include <limits>

namespace FeatureRecon {
namespace sampling {
namespace internal {

/// \cond
/// The next radius of a root search for count(r) = goal with count decreasing in r: a secant step on
/// log count against log r (exponent 2 until two counts are known, clamped to [0.5, 8]), kept inside the
/// bracket (lo, hi) by bisection. Samplers whose kept count falls about as 1 / r^2 (one sample per disc)
/// reach the goal in a handful of throws where a bisection needs 15 or more.
struct Radius_search {
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  double last_r = 0, last_c = 0;
  /// Records that a throw at radius r kept c samples (`enough`: at least the goal, so r is a lower end) and
  /// returns the radius to try next.
  double next(double r, double c, double goal, bool enough) {
    if (enough)
      lo = std::max(lo, r);
    else
      hi = std::min(hi, r);
    double k = 2;
    if (last_r > 0 && last_c > 0 && c > 0 && last_c != c && last_r != r)
      k = std::clamp(-(std::log(c) - std::log(last_c)) / (std::log(r) - std::log(last_r)), 0.5, 8.0);
    last_r = r;
    last_c = c;
    double n = c > 0 ? r * std::pow(c / goal, 1 / k) : 0.5 * r;
    if (!(n > lo && n < hi)) n = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * r;
    return n;
  }
};
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_RADIUS_SEARCH_H
