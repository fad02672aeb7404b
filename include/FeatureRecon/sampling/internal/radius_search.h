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

/// A root search for count(r) = goal on whole throws, count falling in r, between a lower end `lo` that keeps
/// at least the goal (0 before one is known) and an upper end `hi` that keeps fewer: the bracket shrinks
/// every step. The count falls about as r^-2, so while `lo` is 0 the step is that law from `hi`, and once
/// both ends are known log count is interpolated linearly in log r between them (regula falsi, within the
/// middle 90 % of the bracket). After a step that did not halve the bracket the next one bisects it (halves
/// `hi` while `lo` is 0): near the count of every item the law moved the radius by 1 % a throw (125 throws
/// found no lower end), and regula falsi can creep along one end; so never more than about twice the steps of
/// a bisection, and in practice about half of them (13 throws where a bisection took 26).
struct Bracketed_radius_search {
  double lo = 0, hi = 0;            ///< the bracket (hi > lo must be set before next())
  double kept_lo = 0, kept_hi = 0;  ///< the counts thrown at its ends (0: not thrown)
  bool bisect = false;              ///< the last step did not halve the bracket: bisect next
  bool halved = false;              ///< the last step halved the bracket (or more)
  /// The radius to throw next, strictly inside (lo, hi) unless the bracket has no double between its ends.
  double next(double goal) const {
    const double width = hi - lo;
    double mid = lo + width / 2;
    if (bisect) return mid;
    if (lo == 0) {
      const double guess = kept_hi > 0 ? hi * std::sqrt(kept_hi / goal) : 0.0;
      if (guess > 0 && guess < hi) mid = guess;
    } else if (kept_hi > 0 && kept_lo > kept_hi) {
      const double exponent = std::log(kept_lo / kept_hi) / std::log(hi / lo);
      const double guess = lo * std::pow(kept_lo / goal, 1 / exponent);
      if (std::isfinite(guess)) mid = std::min(hi - 0.05 * width, std::max(lo + 0.05 * width, guess));
    }
    return mid;
  }
  /// Records a throw at radius r (strictly inside the bracket) that kept `kept`; `enough`: r becomes the
  /// lower end.
  void record(double r, double kept, bool enough) {
    const double width = hi - lo;
    const bool first_lower_end = enough && lo == 0;  // both ends known now: interpolate next
    if (enough) {
      lo = r;
      kept_lo = kept;
    } else {
      hi = r;
      kept_hi = kept;
    }
    halved = hi - lo <= 0.5 * width;
    bisect = !bisect && !halved && !first_lower_end;
  }
};
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_RADIUS_SEARCH_H
