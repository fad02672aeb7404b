// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_ESTIMATE_RIPS_RADIUS_H
#define FEATURERECON_SKELETON_ESTIMATE_RIPS_RADIUS_H

// A Rips radius derived from the data: the scale at which a sample of a graph (a curve network with noise)
// starts to look one-dimensional, read off the correlation integral (the mean number of neighbours within r
// as a function of r, whose log-log slope is the dimension the points show at scale r).

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/point_traits.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Options of estimate_rips_radius().
struct Rips_radius_options {
  /// Points whose distances to all points are measured, spread evenly by index (point t * n / m for t < m);
  /// all points when there are fewer. The work is m * n distances. At least 1; default 1000.
  std::size_t reference_points = 1000;
  /// The scale is not below the radius at which a point has this many neighbours on average. Finite and >=
  /// 1; default 8.
  double min_neighbours = 8;
  /// The scale is the smallest radius at which the points show at most the intrinsic dimension plus this.
  /// Finite and >= 0; default 0.5.
  double dimension_margin = 0.5;
  /// The radius is this times the scale. In (0, 2^100]; default 1.5.
  double radius_factor = 1.5;
  /// The radius is also at least the first profile radius within which a point has 2 ln(n /
  /// max_expected_gaps) neighbours on average (at most (n - 1) / 2): where n points lie at random (Poisson)
  /// along curves, a point has 2 lambda r neighbours within r (lambda points per unit length), and the
  /// expected number of gaps wider than r, n exp(-lambda r), is then at most max_expected_gaps. A gap wider
  /// than the radius splits the skeleton. In (0, 1]; default 0.05.
  double max_expected_gaps = 0.05;
  /// The suggested persistence threshold is at least this times the scale (Rips_radius_estimate::delta).
  /// In [0, 2^100]; default 2.25 (1.5 times the default radius_factor).
  double delta_factor = 2.25;
  Progress_callback progress;  ///< called with the fraction of reference points done; returning false stops
};

/// Result of estimate_rips_radius().
struct Rips_radius_estimate {
  double radius = 0;  ///< max(radius_factor * scale, gap_radius): the Rips radius to use
  /// The scale read off the profile: the upper edge 2^((b+1)/4) of the first quarter-octave bin b at which
  /// the mean number of neighbours is at least min_neighbours and the local dimension at most
  /// intrinsic_dimension + dimension_margin. 0 when every distance is 0 or there are fewer than two points.
  double scale = 0;
  /// The smallest local dimension (slope of log mean neighbours against log r over one octave) where a point
  /// has min_neighbours to (n - 1) / 4 neighbours on average; NaN when no bin lies in that range (few points,
  /// or the count jumps across it: then the scale is the first radius with min(min_neighbours, (n - 1) / 2)
  /// neighbours).
  double intrinsic_dimension = std::numeric_limits<double>::quiet_NaN();
  double mean_neighbours = 0;  ///< mean number of other points within `scale` of a reference point
  /// The first profile radius with 2 ln(n / max_expected_gaps) neighbours (at most (n - 1) / 2) on average:
  /// the radius is the larger of it and radius_factor * scale. 0 when the scale is 0.
  double gap_radius = 0;
  /// A persistence threshold for the skeleton at this radius: max(radius, delta_factor * scale). Noise makes
  /// branches and loops of persistence up to about the band's width plus the radius: with delta = radius, 7
  /// of 20 noisy circles of 3,000 points kept a spur; with this delta none, while the branches of sparse
  /// trees (4 to 6 long, radius 2 from gap_radius) all stay (doc/skeleton.md).
  double delta = 0;
  /// The distinct points measured: copies (equal coordinates; for a matrix, equal rows) are one point, as the
  /// Rips stage of extract_reeb_skeleton() joins them (counted apart, 3 copies of every point of
  /// test/data/figure_eight.xyz took the radius from 0.59 to 0.25).
  std::size_t distinct_points = 0;
  std::size_t reference_points = 0;  ///< how many distinct points were measured against all distinct points
  /// The profile: radii[k] = 2^((b+1)/4) for consecutive bins b from the smallest positive distance to the
  /// largest (rounded: below 2^-1022 two edges can be equal; the last at most the largest double), and
  /// mean_neighbours_within[k] the mean number of other distinct points at distance < radii[k] of a reference
  /// point (rows of a matrix at distance 0 that are not copies count at every radius).
  std::vector<double> radii;
  std::vector<double> mean_neighbours_within;  ///< see radii
  /// degenerate_input: fewer than two points or every distance 0 (radius 0); interrupted: the callback
  /// stopped the measurement (radius 0, empty profile).
  Status status = Status::success;
};

namespace internal {

/// The quarter-octave bin of a distance d > 0: the b with 2^(b/4) <= d < 2^((b+1)/4), from its binary
/// exponent and three exact comparisons of the mantissa (no logarithm: the same on every platform).
inline int quarter_octave_bin(double d) {
  int e = 0;
  const double f = std::frexp(d, &e);  // d = f * 2^e, f in [0.5, 1)
  const int q = (f >= 0x1.306fe0a31b715p-1) + (f >= 0x1.6a09e667f3bcdp-1) + (f >= 0x1.ae89f995ad3adp-1);
  return 4 * (e - 1) + q;
}

/// 2^(b/4), correctly rounded.
inline double quarter_octave_power(int b) {
  static const double fraction[4] = {1.0, 0x1.306fe0a31b715p+0, 0x1.6a09e667f3bcdp+0, 0x1.ae89f995ad3adp+0};
  const int e = b >= 0 ? b / 4 : -((-b + 3) / 4);  // floor(b / 4)
  return std::ldexp(fraction[b - 4 * e], e);
}

/// Accumulates the distances of reference points to all points in quarter-octave bins and reads the estimate.
class Correlation_profile {
 public:
  void add(double d) {
    if (!(d > 0)) {
      ++zeros_;
      return;
    }
    // A distance beyond the largest double (point_distance() of coordinates near +-1e308) is binned at
    // 2^1024.
    const int b = d < std::numeric_limits<double>::infinity() ? quarter_octave_bin(d) : 4096;
    if (counts_.empty()) {
      low_ = b;
      counts_.assign(1, 0);
    } else if (b < low_) {
      counts_.insert(counts_.begin(), static_cast<std::size_t>(low_ - b), 0);
      low_ = b;
    } else if (b - low_ >= static_cast<int>(counts_.size())) {
      counts_.resize(static_cast<std::size_t>(b - low_) + 1, 0);
    }
    ++counts_[static_cast<std::size_t>(b - low_)];
  }

  Rips_radius_estimate estimate(std::size_t n, std::size_t m, const Rips_radius_options& options) const {
    Rips_radius_estimate out;
    out.reference_points = m;
    if (n < 2 || counts_.empty()) {
      out.status = Status::degenerate_input;
      out.mean_neighbours = n < 2 ? 0.0 : static_cast<double>(zeros_) / static_cast<double>(m);
      return out;
    }
    const std::size_t bins = counts_.size();
    std::vector<double> within(bins);
    std::uint64_t sum = zeros_;
    for (std::size_t k = 0; k < bins; ++k) {
      sum += counts_[k];
      within[k] = static_cast<double>(sum) / static_cast<double>(m);
      // 2^1024 (the bin of distances from 2^1023.75) is not a double: the largest one stands for it.
      out.radii.push_back(
          std::min(quarter_octave_power(low_ + static_cast<int>(k) + 1), std::numeric_limits<double>::max()));
    }
    out.mean_neighbours_within = within;
    // The local dimension at bin k: the slope over the octave from k - 2 to k + 2 (4 bins).
    auto slope = [&](std::size_t k) {
      return (std::log(within[k + 2]) - std::log(within[k - 2])) / std::log(2.0);
    };
    const double top = static_cast<double>(n - 1) / 4;
    auto in_range = [&](std::size_t k) {
      return k >= 2 && k + 2 < bins && within[k - 2] > 0 && within[k] >= options.min_neighbours &&
             within[k] <= top;
    };
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < bins; ++k)
      if (in_range(k)) lowest = std::min(lowest, slope(k));
    std::size_t chosen = bins - 1;
    if (lowest < std::numeric_limits<double>::infinity()) {
      out.intrinsic_dimension = lowest;
      for (std::size_t k = 0; k < bins; ++k)
        if (in_range(k) && slope(k) <= lowest + options.dimension_margin) {
          chosen = k;
          break;
        }
    } else {
      const double need = std::min(options.min_neighbours, static_cast<double>(n - 1) / 2);
      for (std::size_t k = 0; k < bins; ++k)
        if (within[k] >= need) {
          chosen = k;
          break;
        }
    }
    out.scale = out.radii[chosen];
    out.mean_neighbours = within[chosen];
    const double gap_need = std::min(2 * std::log(static_cast<double>(n) / options.max_expected_gaps),
                                     static_cast<double>(n - 1) / 2);
    for (std::size_t k = 0; k < bins; ++k)
      if (within[k] >= gap_need) {
        out.gap_radius = out.radii[k];
        break;
      }
    constexpr double largest = std::numeric_limits<double>::max();  // a radius_factor of 2^100 can overflow
    out.radius = std::min(largest, std::max(options.radius_factor * out.scale, out.gap_radius));
    out.delta = std::min(largest, std::max(out.radius, options.delta_factor * out.scale));
    return out;
  }

 private:
  std::uint64_t zeros_ = 0;
  int low_ = 0;
  std::vector<std::uint64_t> counts_;
};

inline void check_rips_radius_options(const Rips_radius_options& o, const char* fn) {
  if (o.reference_points == 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "reference_points must be >= 1");
  if (!(o.min_neighbours >= 1 && std::isfinite(o.min_neighbours)))
    FeatureRecon::internal::throw_invalid_argument(fn, "min_neighbours must be finite and >= 1, got ",
                                                   o.min_neighbours);
  if (!(o.dimension_margin >= 0 && std::isfinite(o.dimension_margin)))
    FeatureRecon::internal::throw_invalid_argument(fn, "dimension_margin must be finite and >= 0, got ",
                                                   o.dimension_margin);
  if (!(o.radius_factor > 0 && o.radius_factor <= 0x1p100))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius_factor must be in (0, 2^100], got ",
                                                   o.radius_factor);
  if (!(o.delta_factor >= 0 && o.delta_factor <= 0x1p100))
    FeatureRecon::internal::throw_invalid_argument(fn, "delta_factor must be in [0, 2^100], got ",
                                                   o.delta_factor);
  if (!(o.max_expected_gaps > 0 && o.max_expected_gaps <= 1))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_expected_gaps must be in (0, 1], got ",
                                                   o.max_expected_gaps);
}

/// The estimate over the distinct points (`first[i]` the first copy of point i, empty when all are distinct)
/// of n points, `distance(i, j)` the distance of points i and j: reference points evenly spread over the
/// distinct ones, each measured against every other distinct one.
template <class Distance>
Rips_radius_estimate estimate_over_distinct(std::size_t n, const std::vector<Vertex_index>& first,
                                            const Rips_radius_options& options, Distance&& distance) {
  std::vector<std::size_t> distinct;
  for (std::size_t i = 0; i < n; ++i)
    if (first.empty() || first[i] == i) distinct.push_back(i);
  const std::size_t d = distinct.size(), m = std::min(d, options.reference_points);
  auto stopped = [m, d] {
    Rips_radius_estimate out;
    out.distinct_points = d;
    out.reference_points = m;
    out.status = Status::interrupted;
    return out;
  };
  Correlation_profile profile;
  for (std::size_t t = 0; t < m; ++t) {
    if (!FeatureRecon::internal::report_progress(options.progress,
                                                 static_cast<double>(t) / static_cast<double>(m)))
      return stopped();
    // floor(t * d / m) without forming t * d (m <= d; t * (d % m) < m^2).
    const std::size_t i = distinct[m == d ? t : t * (d / m) + t * (d % m) / m];
    for (const std::size_t j : distinct)
      if (j != i) profile.add(distance(i, j));
  }
  Rips_radius_estimate out = profile.estimate(d, m, options);
  out.distinct_points = d;
  if (!FeatureRecon::internal::report_progress(options.progress, 1.0)) return stopped();
  return out;
}

}  // namespace internal

/// A Rips radius for extract_reeb_skeleton() from the points alone: the scale at which they look like a
/// graph.
///
/// A noisy sample of a curve network looks as many-dimensional as its noise below the noise's width and
/// one-dimensional above it, up to the size of its loops and branches. The mean number N(r) of other points
/// within r of a point (the correlation integral, measured from `reference_points` points evenly spread by
/// index against all) has a log-log slope that reads that dimension at each scale. The intrinsic dimension is
/// the smallest slope over one octave where a point has between min_neighbours and (n - 1) / 4 neighbours on
/// average (1 for curves; 2 for a sampled surface); the scale is the first radius, on a grid of quarter
/// octaves, with min_neighbours neighbours where the slope has come down to within dimension_margin of it;
/// the radius is radius_factor times the scale, or more where the points are too few for it to bridge the
/// random gaps between them (gap_radius). A 2D band of width w around a curve gives a scale of about w, so
/// the Rips complex joins across the band (its level sets are then pieces of the curve) while branches and
/// loops wider than a few times w stay apart. Measured on noisy trees, circles, a trefoil, a Y and
/// figure-eights in R^2, R^3 and R^50 (doc/skeleton.md, "A radius from the data"): at the estimated radius
/// and delta all but 1 of 120 samples give their true loops and branches (a trefoil of 1,000 points with a
/// random gap wider than the radius).
///
/// Copies of a point count once (Rips_radius_estimate::distinct_points): the Rips stage joins them, and
/// duplicating the input leaves the estimate as it was. Deterministic: distances are binned by exact
/// comparisons of their mantissas. Work: a sort to find the copies, then m * n distances (m = min(n,
/// reference_points), n distinct).
/// \returns radius 0 and status degenerate_input for fewer than two distinct points; status interrupted
///   (radius 0, empty profile) when the callback stopped it.
/// \throws std::invalid_argument for options out of range and points as build_rips_graph() refuses them.
inline Rips_radius_estimate estimate_rips_radius(const Point_matrix& points,
                                                 const Rips_radius_options& options = {}) {
  const char* fn = "estimate_rips_radius";
  internal::check_rips_radius_options(options, fn);
  internal::check_point_matrix(points, fn);
  std::vector<Vertex_index> first;
  internal::first_copies(points, first);
  return internal::estimate_over_distinct(
      points.rows, first, options, [&points](std::size_t i, std::size_t j) {
        return internal::point_distance(points.row(i), points.row(j), points.dimension);
      });
}

/// estimate_rips_radius() on a range of points through a PointCoordinateTraits model.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Rips_radius_estimate estimate_rips_radius(const PointRange& points, const Rips_radius_options& options = {},
                                          const Traits& traits = Traits()) {
  return estimate_rips_radius(make_point_matrix(points, traits, "estimate_rips_radius"), options);
}

/// estimate_rips_radius() for a dense distance matrix (the distances of its reference rows to all).
/// \tparam Matrix as build_rips_graph_from_distance_matrix() (checked the same way; throws).
template <class Matrix>
Rips_radius_estimate estimate_rips_radius_from_distance_matrix(const Matrix& D,
                                                               const Rips_radius_options& options = {}) {
  const char* fn = "estimate_rips_radius_from_distance_matrix";
  internal::check_rips_radius_options(options, fn);
  std::size_t n = 0;
  const std::vector<double> a = internal::checked_distance_matrix(D, n, fn);
  std::vector<Vertex_index> first;
  internal::first_copies_of_rows(a, n, first);
  return internal::estimate_over_distinct(n, first, options,
                                          [&a, n](std::size_t i, std::size_t j) { return a[i * n + j]; });
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_ESTIMATE_RIPS_RADIUS_H
