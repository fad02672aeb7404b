// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_CLI_RIPS_THINNING_H
#define FEATURERECON_SRC_CLI_RIPS_THINNING_H

// How far `featurerecon skeleton --points` thins points whose Rips radius it estimated (a header of its own
// so that the tests can pin the rule on hand-made profiles).

#include <FeatureRecon/skeleton/estimate_rips_radius.h>

#include <algorithm>
#include <cstddef>

namespace FeatureRecon {
namespace cli {

using skeleton::Rips_radius_estimate;

/// The thinning of points whose radius was estimated.
struct Thinning {
  double spacing = 0;           ///< 0: none
  double cap = 0;               ///< (R - gap radius) / 2
  bool beyond_cap = false;      ///< the spacing exceeds the cap (see thinning_spacing())
  double triangles_at_cap = 0;  ///< the rough triangle count at the cap, when beyond_cap
};

/// None while a point has at most 32 neighbours within R on average (the profile's count at the first radius
/// >= R); else the smallest profile radius S after which about 32 remain (C(R) / (1 + C(S)) <= 32: each kept
/// point stands for itself and its C(S) neighbours), at most (R - gap radius) / 2: thinning at S moves a gap
/// g between points to at most g + 2S between kept ones, and gaps are below the gap radius (at 95 % where
/// points lie at random). The cap is passed when at the cap the complex would still hold more than a quarter
/// of `max_triangles` (roughly n' C'^2 / 6 for n' = n / (1 + C(cap)) kept points with C' = C(R) / (1 +
/// C(cap)) neighbours each): noise in many dimensions keeps every point farther than the cap from all others
/// (20,000 points of a curve in R^50 with noise 0.2: 1.7 apart, radius 5.05, cap 1.52, about 2 x 10^10
/// triangles there; thinned at 2: 1,214 points and the two loops).
inline Thinning thinning_spacing(const Rips_radius_estimate& e, std::size_t max_triangles) {
  constexpr double kept_neighbours = 32;
  Thinning t;
  t.cap = std::max(0.0, (e.radius - e.gap_radius) / 2);
  std::size_t at_radius = 0;
  while (at_radius < e.radii.size() && e.radii[at_radius] < e.radius) ++at_radius;
  if (at_radius == e.radii.size() || e.mean_neighbours_within[at_radius] <= kept_neighbours) return t;
  const double within_radius = e.mean_neighbours_within[at_radius];
  double needed = 0;
  for (std::size_t k = 0; k < e.radii.size(); ++k)
    if (within_radius / (1 + e.mean_neighbours_within[k]) <= kept_neighbours) {
      needed = e.radii[k];
      break;
    }
  if (needed <= t.cap) {
    t.spacing = needed;
    return t;
  }
  double within_cap = 0;  // neighbours closer than the cap (the largest profile radius not above it)
  for (std::size_t k = 0; k < e.radii.size() && e.radii[k] <= t.cap; ++k)
    within_cap = e.mean_neighbours_within[k];
  const double kept = static_cast<double>(e.distinct_points) / (1 + within_cap),
               neighbours = within_radius / (1 + within_cap);
  t.triangles_at_cap = kept * neighbours * neighbours / 6;
  if (max_triangles > 0 && t.triangles_at_cap > static_cast<double>(max_triangles) / 4) {
    t.spacing = needed;
    t.beyond_cap = true;
  } else {
    t.spacing = t.cap;
  }
  return t;
}

}  // namespace cli
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_CLI_RIPS_THINNING_H
