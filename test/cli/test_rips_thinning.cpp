// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The command line's thinning of points whose Rips radius it estimated (src/cli/rips_thinning.h), on
// hand-made profiles: each case sits on one boundary of the rule.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "cli/rips_thinning.h"

using FeatureRecon::cli::Thinning;
using FeatureRecon::cli::thinning_spacing;
using FeatureRecon::skeleton::Rips_radius_estimate;

namespace {

/// A profile over radii 1, 2, 4, 8, 16 with the given counts: radius 8, gap radius `gap`, 200 points.
Rips_radius_estimate profile(const std::vector<double>& within, double gap) {
  Rips_radius_estimate e;
  e.radii = {1, 2, 4, 8, 16};
  e.mean_neighbours_within = within;
  e.radius = 8;
  e.gap_radius = gap;
  e.distinct_points = 200;
  return e;
}

}  // namespace

TEST(RipsThinning, NoneUpTo32NeighboursWithinTheRadius) {
  // The count at the first profile radius >= R (8, not 16): 30 and exactly 32 thin nothing, 33 does.
  for (const double at_radius : {30.0, 32.0}) {
    const Thinning t = thinning_spacing(profile({2, 10, 20, at_radius, 199}, 4), 0);
    EXPECT_EQ(t.spacing, 0.0) << at_radius;
    EXPECT_FALSE(t.beyond_cap);
  }
  EXPECT_GT(thinning_spacing(profile({2, 10, 20, 33, 199}, 0), 0).spacing, 0.0);
  // The cap is (R - gap radius) / 2, never negative.
  EXPECT_EQ(thinning_spacing(profile({2, 10, 20, 30, 199}, 4), 0).cap, 2.0);
  EXPECT_EQ(thinning_spacing(profile({2, 10, 20, 30, 199}, 12), 0).cap, 0.0);
}

TEST(RipsThinning, TheSmallestSpacingThatLeavesAbout32) {
  // C(R) = 100: C(R) / (1 + C(S)) <= 32 first at S = 1 when C(1) = 2.2 (31.25; 100 / 2.2 would not be), at S
  // = 2 when C(1) = 2 (33.3 at 1). The cap (gap radius 0) is 4: the spacing is the one needed, not the cap.
  EXPECT_EQ(thinning_spacing(profile({2.2, 10, 40, 100, 199}, 0), 0).spacing, 1.0);
  const Thinning t = thinning_spacing(profile({2, 10, 40, 100, 199}, 0), 0);
  EXPECT_EQ(t.spacing, 2.0);
  EXPECT_FALSE(t.beyond_cap);
  // Needed exactly at the cap (gap radius 4: cap 2) is within it, whatever the triangle limit.
  const Thinning at_cap = thinning_spacing(profile({2, 10, 40, 100, 199}, 4), 100);
  EXPECT_EQ(at_cap.spacing, 2.0);
  EXPECT_FALSE(at_cap.beyond_cap);
}

TEST(RipsThinning, BeyondTheCapOnlyWhenTheComplexThereIsTooLarge) {
  // C(R) = 100 needs S = 4 (100 / 41), beyond the cap 2. At the cap (C(2) = 2, the largest profile radius not
  // above it) 200 / 3 points keep 100 / 3 neighbours each: 66.7 * 33.3^2 / 6 = 12,345.7 triangles.
  const Rips_radius_estimate e = profile({1, 2, 40, 100, 199}, 4);
  const Thinning within = thinning_spacing(e, 100000);  // a quarter is 25,000: the cap holds
  EXPECT_EQ(within.spacing, 2.0);
  EXPECT_FALSE(within.beyond_cap);
  const Thinning beyond = thinning_spacing(e, 40000);  // a quarter is 10,000: thinned as needed, beyond it
  EXPECT_EQ(beyond.spacing, 4.0);
  EXPECT_TRUE(beyond.beyond_cap);
  EXPECT_NEAR(beyond.triangles_at_cap, 200.0 / 3 * (100.0 / 3) * (100.0 / 3) / 6, 1e-9);
  // No limit (0): the cap holds.
  const Thinning unlimited = thinning_spacing(e, 0);
  EXPECT_EQ(unlimited.spacing, 2.0);
  EXPECT_FALSE(unlimited.beyond_cap);
}

TEST(RipsThinning, ARadiusBeyondTheProfileThinsNothing) {
  Rips_radius_estimate e = profile({2, 10, 40, 100, 199}, 0);
  e.radius = 32;  // above the last profile radius
  EXPECT_EQ(thinning_spacing(e, 0).spacing, 0.0);
  EXPECT_EQ(thinning_spacing(Rips_radius_estimate{}, 0).spacing, 0.0);  // no profile (fewer than two points)
}
