// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_CONTINUOUS_DART_THROWING_H
#define FEATURERECON_SAMPLING_CONTINUOUS_DART_THROWING_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/internal/box.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// A sample of a continuous domain: its position and the feature there.
template <class Feature>
struct Continuous_sample {
  std::array<double, 2> position;  ///< (x, y)
  Feature feature;                 ///< the feature function's value at the position
};

/// Result of continuous_bilateral_dart_throwing().
template <class Feature>
struct Continuous_sampling_result {
  std::vector<Continuous_sample<Feature>> samples;  ///< in acceptance order
  std::size_t darts = 0;                            ///< darts thrown
  Status status = Status::success;  ///< degenerate_input for an empty box; interrupted when stopped
};

/// Bilateral dart throwing in a continuous 2D domain (dissertation Sec. 2.2.2): uniform random darts in the
/// box [x0, x1) x [y0, y1); the feature at a dart comes from `feature_at` (for an image, the interpolated
/// colour); a dart is kept when no kept sample is closer than bilateral distance r (one exactly r away is
/// no conflict, as in bilateral_dart_throwing()). Stops after `max_consecutive_failures` (at least 1,
/// checked) rejections in a row (then the set is close to maximal: rho about 0.75 for Euclidean darts) or
/// `max_samples` samples. Kept samples sit in a hash grid of side r sigma_position. With `options.periodic`
/// the box is a torus (distances of the nearest images, periods its sides): the set tiles the plane, as the
/// periodogram of sampling_spectrum() assumes for the unit box.
/// \tparam FeatureFunction callable `(double x, double y) -> Feature`.
/// \tparam FeatureDistance callable `(const Feature&, const Feature&) -> double`, the squared feature
///   distance.
/// \param box {x0, y0, x1, y1} with x0 <= x1 and y0 <= y1, finite (checked; throws).
/// \param radius the conflict radius in bilateral units (> 0, checked; throws).
/// \throws std::invalid_argument also when a dart's feature is not at a finite distance from itself (NaN),
///   or at a NaN or negative distance from a sample's (naming the dart and the sample).
/// \note Random numbers come from std::mt19937_64 turned into doubles by bit manipulation, so the same seed
///   gives the same samples on every platform.
template <class FeatureFunction, class FeatureDistance>
auto continuous_bilateral_dart_throwing(const std::array<double, 4>& box, double radius,
                                        FeatureFunction feature_at, FeatureDistance feature_distance,
                                        const Continuous_dart_throwing_options& options = {}) {
  using Feature = std::decay_t<decltype(feature_at(0.0, 0.0))>;
  const char* fn = "continuous_bilateral_dart_throwing";
  internal::check_box(box, fn);
  if (!(std::isfinite(radius) && radius > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and > 0, got ", radius);
  internal::check_sigmas(options.sigma_position, options.sigma_feature, fn);
  internal::check_position_scale(std::max(box[2] - box[0], box[3] - box[1]), options.sigma_position, fn);
  if (options.max_consecutive_failures == 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "max_consecutive_failures must be >= 1");
  Continuous_sampling_result<Feature> result;
  if (box[0] == box[2] || box[1] == box[3]) {
    result.status = Status::degenerate_input;
    return result;
  }
  std::mt19937_64 rng(options.seed);
  const std::array<double, 2> low{box[0], box[1]}, period{box[2] - box[0], box[3] - box[1]};
  auto uniform = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  // The grid needs all positions up front: it only uses them for its frame, so pass the box corners.
  std::vector<std::array<double, 2>> positions{{box[0], box[1]}, {box[2], box[3]}};
  internal::with_metric(options, [&](const auto& metric) {
    const double reach = radius * metric.spatial_scale(), reach2 = internal::prefilter_bound(reach);
    // About as many cells as samples fit at spacing `reach` (fewer when max_samples caps them): then the grid
    // is a dense array, not a hash map.
    const double fit = (box[2] - box[0]) * (box[3] - box[1]) / (reach * reach);
    const double expected = options.max_samples > 0 ? std::min(fit, double(options.max_samples)) : fit;
    // On the torus with a margin for the rounding of shifted queries (see torus_search_reach()).
    const double extent = std::max({std::abs(box[0]), std::abs(box[1]), std::abs(box[2]), std::abs(box[3])});
    const double cell = options.periodic ? internal::torus_search_reach(reach, extent) : reach;
    FeatureRecon::internal::Dynamic_grid<2> grid(positions, cell,
                                                 static_cast<std::size_t>(std::min(expected, 0x1p40)) + 1);
    std::size_t failures = 0;
    // the largest share of the failure budget seen (a success resets the run of failures)
    double reported = 0;
    while (failures < options.max_consecutive_failures &&
           (options.max_samples == 0 || result.samples.size() < options.max_samples)) {
      if ((result.darts & 65535) == 0 && result.darts != 0) {
        reported = std::max(reported, double(failures) / double(options.max_consecutive_failures));
        if (!FeatureRecon::internal::report_progress(options.progress, reported)) {
          result.status = Status::interrupted;
          return;
        }
      }
      ++result.darts;
      std::array<double, 2> p{box[0] + (box[2] - box[0]) * uniform(), box[1] + (box[3] - box[1]) * uniform()};
      // Far from the origin x0 + L u can round up to x1, outside the half-open box: on the torus that is x0,
      // otherwise the last double before x1.
      for (std::size_t k = 0; k < 2; ++k)
        if (p[k] >= box[2 + k]) p[k] = options.periodic ? box[k] : std::nextafter(box[2 + k], box[k]);
      const Feature f = feature_at(p[0], p[1]);
      const double self = double(feature_distance(f, f));
      if (!(self >= 0 && self < std::numeric_limits<double>::infinity()))  // a NaN feature never conflicts
        FeatureRecon::internal::throw_invalid_argument(
            fn, "feature_at(", p[0], ", ", p[1], ") is at distance ",
            std::isnan(self) ? std::string("NaN") : std::to_string(self),
            " from itself (NaN in the feature?)");
      bool conflict = false;
      const auto test = [&](std::uint32_t j) {
        if (conflict) return;
        const auto& q = positions[j];
        double d2 = 0;
        for (int k = 0; k < 2; ++k) {
          double d = std::abs(p[std::size_t(k)] - q[std::size_t(k)]);
          if (options.periodic) d = std::min(d, period[std::size_t(k)] - d);
          d2 += d * d;
        }
        if (!(d2 < reach2)) return;
        conflict = metric(d2, internal::checked_feature_distance(
                                  double(feature_distance(f, result.samples[j - 2].feature)), fn, "dart",
                                  result.darts - 1, "sample", j - 2)) < radius;
      };
      if (options.periodic)
        internal::for_each_torus_candidate(
            grid, p, cell, [&](std::uint32_t j, int) { test(j); }, low, period);
      else
        grid.for_each_candidate(p, test);
      if (conflict) {
        ++failures;
        continue;
      }
      failures = 0;
      positions.push_back(p);
      grid.insert(static_cast<std::uint32_t>(positions.size() - 1));
      result.samples.push_back({p, f});
    }
  });
  if (result.status != Status::interrupted)
    (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_CONTINUOUS_DART_THROWING_H
