// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_SAMPLING_QUALITY_H
#define FEATURERECON_SAMPLING_SAMPLING_QUALITY_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/traits.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// Options of sampling_quality().
struct Sampling_quality_options {
  double sigma_position = 1;                                        ///< spatial scale of the metric; default 1
  double sigma_feature = std::numeric_limits<double>::infinity();   ///< feature scale; default infinity (Euclidean)
  Bilateral_form form = Bilateral_form::gaussian;                   ///< form of the bilateral distance
  /// Area (2D) or volume (3D) of the domain. Default 0: the bounding box of the samples (or the unit square /
  /// cube when `periodic`).
  double domain_measure = 0;
  /// 2 (images, surfaces: pass the area as domain_measure) or 3 (volumes). Default 0: the dimension of the
  /// positions.
  int intrinsic_dimension = 0;
  /// Distances on the unit torus [0, 1)^d (positions are taken modulo 1), as the point-set analysis tools of
  /// Heck, Schlömer and Deussen measure them; default false.
  bool periodic = false;
};

/// Spacing statistics of a sample set (Lagae and Dutré 2008; Schlömer's PSA conventions).
struct Sampling_quality {
  std::size_t samples = 0;            ///< number of samples N
  double hexagonal_distance = 0;      ///< d_hex: nearest distance of the densest packing of N points (hexagonal in 2D, FCC in 3D)
  double minimum_distance = 0;        ///< smallest nearest-neighbour (bilateral) distance
  double relative_radius = 0;         ///< rho = minimum_distance / d_hex (1 for the hexagonal lattice)
  double average_minimum_distance = 0;  ///< mean nearest-neighbour distance / d_hex (about 0.466 for white noise in 2D)
  Status status = Status::success;    ///< degenerate_input for fewer than two samples, a domain of zero measure or samples of lower affine dimension (collinear, coplanar)
};

/// Nearest-neighbour statistics of a sample set: the relative radius rho = d_min / d_hex and the average
/// minimum distance, both relative to the nearest distance d_hex of the densest packing of N points in the
/// domain (d_hex = sqrt(2 A / (sqrt(3) N)) in 2D, cbrt(sqrt(2) V / N) in 3D). With a finite sigma_feature the
/// distances are bilateral (in units of xi times sigma_position), which measures spacing in the stacked space.
/// Nearest neighbours are found in a uniform grid of side d_hex, exactly: a point whose candidates are all
/// farther than the grid side falls back to a scan of all samples.
/// \tparam ItemRange a forward range of `Traits::Item`. \tparam Traits a model of FeaturePointTraits.
/// \throws std::invalid_argument for non-finite coordinates (naming the item), sigma_position <= 0,
///   sigma_feature <= 0, a negative domain_measure or an intrinsic_dimension other than 0, 2 or 3.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Sampling_quality sampling_quality(const ItemRange& items, const Sampling_quality_options& options = {},
                                  const Traits& traits = Traits()) {
  const char* fn = "sampling_quality";
  internal::check_sigmas(options.sigma_position, options.sigma_feature, fn);
  if (!(options.domain_measure >= 0 && std::isfinite(options.domain_measure)))
    FeatureRecon::internal::throw_invalid_argument(fn, "domain_measure must be finite and >= 0, got ",
                                                   options.domain_measure);
  if (options.intrinsic_dimension != 0 && options.intrinsic_dimension != 2 && options.intrinsic_dimension != 3)
    FeatureRecon::internal::throw_invalid_argument(fn, "intrinsic_dimension must be 0 (automatic), 2 or 3, got ",
                                                   options.intrinsic_dimension);
  internal::Sample_set<Traits> S(items, traits, fn);
  constexpr int D = Traits::dimension;
  const std::size_t n = S.size();
  Sampling_quality q;
  q.samples = n;
  if (options.periodic)
    for (auto& p : S.positions)
      for (int k = 0; k < D; ++k) p[k] -= std::floor(p[k]);
  const int dim = options.intrinsic_dimension == 0 ? D : options.intrinsic_dimension;
  double measure = options.domain_measure;
  if (measure == 0) measure = options.periodic ? 1.0 : internal::bounding_box_measure<D>(S.positions);
  if (n < 2 || !(measure > 0) || internal::affine_dimension<D>(S.positions) < dim) {
    q.status = Status::degenerate_input;
    return q;
  }
  q.hexagonal_distance = dim == 2 ? std::sqrt(2 * measure / (std::sqrt(3.0) * double(n)))
                                  : std::cbrt(std::sqrt(2.0) * measure / double(n));
  // Periodic images of the points near the faces of the unit cell, so the grid sees the torus.
  std::vector<std::array<double, D>> points = S.positions;
  std::vector<std::size_t> source(n);
  for (std::size_t i = 0; i < n; ++i) source[i] = i;
  const double side = q.hexagonal_distance;
  if (options.periodic) {
    const double band = std::min(0.5, 2 * side);
    int offsets = 1;
    for (int k = 0; k < D; ++k) offsets *= 3;
    for (std::size_t i = 0; i < n; ++i)
      for (int o = 0; o < offsets; ++o) {  // every shift in {-1, 0, 1}^d but zero
        std::array<double, D> p = S.positions[i];
        bool inside = true, zero = true;
        for (int k = 0, c = o; k < D; ++k, c /= 3) {
          p[k] += double(c % 3 - 1);
          zero = zero && c % 3 == 1;
          inside = inside && p[k] > -band && p[k] < 1 + band;
        }
        if (!zero && inside) {
          points.push_back(p);
          source.push_back(i);
        }
      }
  }
  internal::with_metric(options, [&](const auto& metric) {
    const double scale = metric.spatial_scale();
    const FeatureRecon::internal::Uniform_grid<D> grid(points, side);
    auto xi = [&](std::size_t i, std::size_t j_point) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = S.positions[i][k] - points[j_point][k];
        d2 += d * d;
      }
      return metric(d2, S.squared_feature_distance(i, source[j_point])) * scale;
    };
    double minimum = std::numeric_limits<double>::infinity(), sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity();
      grid.for_each_candidate(S.positions[i], [&](std::uint32_t j) {
        if (j == i) return;
        best = std::min(best, xi(i, j));
      });
      if (!(best <= grid.cell_size()))  // the nearest may lie outside the 3^d cells: scan everything
        for (std::size_t j = 0; j < points.size(); ++j)
          if (j != i) best = std::min(best, xi(i, j));
      minimum = std::min(minimum, best);
      sum += best;
    }
    q.minimum_distance = minimum;
    q.average_minimum_distance = sum / double(n) / q.hexagonal_distance;
    q.relative_radius = minimum / q.hexagonal_distance;
  });
  return q;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_SAMPLING_QUALITY_H
