// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_WEIGHTED_SAMPLE_ELIMINATION_H
#define FEATURERECON_SAMPLING_WEIGHTED_SAMPLE_ELIMINATION_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/traits.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace FeatureRecon {
namespace sampling {

namespace internal {
/// \cond
/// Binary max-heap over items 0..n-1 keyed by (weight, priority), with positions for decrease-key.
class Elimination_heap {
 public:
  Elimination_heap(const std::vector<double>& weight, const std::vector<std::uint32_t>& priority)
      : m_weight(&weight), m_priority(&priority), m_heap(weight.size()), m_position(weight.size()) {
    std::iota(m_heap.begin(), m_heap.end(), std::uint32_t(0));
    for (std::size_t i = 0; i < m_heap.size(); ++i) m_position[i] = static_cast<std::uint32_t>(i);
    for (std::size_t i = m_heap.size() / 2; i-- > 0;) sift_down(i);
  }
  std::uint32_t pop() {
    const std::uint32_t top = m_heap[0];
    m_heap[0] = m_heap.back();
    m_position[m_heap[0]] = 0;
    m_heap.pop_back();
    if (!m_heap.empty()) sift_down(0);
    return top;
  }
  /// After the weight of x decreased.
  void decreased(std::uint32_t x) { sift_down(m_position[x]); }

 private:
  bool above(std::uint32_t a, std::uint32_t b) const {
    const double wa = (*m_weight)[a], wb = (*m_weight)[b];
    return wa > wb || (wa == wb && (*m_priority)[a] > (*m_priority)[b]);
  }
  void sift_down(std::size_t i) {
    const std::size_t n = m_heap.size();
    const std::uint32_t x = m_heap[i];
    for (;;) {
      std::size_t c = 2 * i + 1;
      if (c >= n) break;
      if (c + 1 < n && above(m_heap[c + 1], m_heap[c])) ++c;
      if (!above(m_heap[c], x)) break;
      m_heap[i] = m_heap[c];
      m_position[m_heap[i]] = static_cast<std::uint32_t>(i);
      i = c;
    }
    m_heap[i] = x;
    m_position[x] = static_cast<std::uint32_t>(i);
  }
  const std::vector<double>* m_weight;
  const std::vector<std::uint32_t>* m_priority;
  std::vector<std::uint32_t> m_heap, m_position;
};

/// A seeded permutation of 0..n-1 (std::mt19937_64 and a Fisher-Yates shuffle written out, so the result
/// does not depend on the standard library's distributions).
inline std::vector<std::uint32_t> seeded_permutation(std::size_t n, std::uint64_t seed) {
  std::vector<std::uint32_t> p(n);
  std::iota(p.begin(), p.end(), std::uint32_t(0));
  std::mt19937_64 rng(seed);
  for (std::size_t i = n; i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(rng() % i);
    std::swap(p[i - 1], p[j]);
  }
  return p;
}
/// \endcond
}  // namespace internal

/// Selects exactly `count` of the items by weighted sample elimination (Yuksel 2015) generalised to the
/// bilateral distance: every item gets the weight sum_j (1 - xi_ij / (2 r_max))^alpha over its neighbours
/// within bilateral distance 2 r_max, and the heaviest item is removed (its neighbours' weights drop) until
/// `count` remain. The result is a subset of the input with blue-noise spacing in the bilateral metric: with
/// sigma_feature = infinity it is Yuksel's Euclidean elimination; a finite sigma_feature keeps more samples
/// where features change (creases, edges of an image, both sides of a thin wall).
///
/// r_max is in units of the bilateral distance (see Elimination_options::max_radius for the default from
/// the domain measure). Neighbours are found in a uniform grid of side 2 r_max sigma_position, which is
/// enough because every metric here satisfies xi >= |dp| / sigma_position. O(n k log n) time for k
/// neighbours per item, O(n k) memory (4 bytes per neighbour).
///
/// \tparam ItemRange a forward range of `Traits::Item`.
/// \tparam OutputIterator accepts std::size_t (indices into `items`).
/// \tparam Traits a model of FeaturePointTraits (default: Default_traits_t<ItemRange>).
/// \param items the input samples (2D or 3D positions with features).
/// \param count the exact number of items to keep, 0 <= count <= number of items (checked; throws).
/// \param selected receives the indices of the kept items, in increasing order.
/// \param options metric, r_max, weight exponent, seed (ties between equal weights), progress.
/// \param traits accessors for positions and features.
/// \returns the advanced iterator, the number written (count, or 0 when interrupted), r_max and the status:
///   `degenerate_input` for an empty input and for input of lower affine dimension than the domain, decided
///   by exact predicates: collinear points (r_max = L / (2 count) for the segment of length L), coplanar 3D
///   points asked to be sampled as a volume (sampled as a surface), one repeated position (the seed picks the
///   items), and positions so close together (spans below about 1e-154) that the automatic r_max underflows to
///   0 (the seed picks the items); `interrupted` (nothing written) when the callback stopped.
/// \throws std::invalid_argument naming the argument: count larger than the input, non-finite coordinates
///   (naming the item), sigma_position <= 0, sigma_feature <= 0, negative max_radius or domain_measure,
///   intrinsic_dimension other than 0, 2 or 3, alpha <= 0. The input is never modified.
/// \note Duplicated items are eliminated first (weight limiting gives them the largest weight); ties between
///   equal weights are broken by a permutation drawn from `seed`, so the same input and seed give the same
///   output on every platform.
/// \sa sampling_quality(), bilateral_dart_throwing().
template <class ItemRange, class OutputIterator, class Traits = Default_traits_t<ItemRange>>
Sampling_result<OutputIterator> weighted_sample_elimination(const ItemRange& items, std::size_t count,
                                                            OutputIterator selected,
                                                            const Elimination_options& options = {},
                                                            const Traits& traits = Traits()) {
  const char* fn = "weighted_sample_elimination";
  internal::check_sigmas(options.sigma_position, options.sigma_feature, fn);
  if (!(options.max_radius >= 0 && std::isfinite(options.max_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_radius must be finite and >= 0, got ", options.max_radius);
  internal::check_domain(options.domain_measure, options.intrinsic_dimension, fn);
  if (!(options.alpha > 0 && std::isfinite(options.alpha)))
    FeatureRecon::internal::throw_invalid_argument(fn, "alpha must be finite and > 0, got ", options.alpha);
  const internal::Sample_set<Traits> S(items, traits, fn);
  constexpr int D = Traits::dimension;
  const std::size_t n = S.size();
  internal::check_count(count, n, fn);
  Sampling_result<OutputIterator> result{selected, 0, 0, Status::success};
  if (n == 0) {
    result.status = Status::degenerate_input;
    return result;
  }

  // r_max in bilateral units. Input of lower affine dimension than the domain (collinear points, coplanar
  // points of a volume, one repeated position) is packed in its own dimension.
  double r_max = options.max_radius;
  if (r_max == 0 && count > 0) {
    int dim = options.intrinsic_dimension;
    double measure = options.domain_measure;
    const int affine = internal::affine_dimension<D>(S.positions);
    if constexpr (D == 3) {
      if (affine >= 2 && (dim == 0 || (dim == 2 && measure == 0) || (affine == 2 && measure == 0))) {
        const internal::Knn_3 knn(S.positions);
        if (dim == 0) dim = affine == 2 ? 2 : internal::estimate_intrinsic_dimension(S.positions, knn);
        if (affine == 2 && dim == 3) {
          dim = 2;
          result.status = Status::degenerate_input;
        }
        if (dim == 2 && measure == 0) measure = internal::estimate_surface_area(S.positions, knn);
      }
    } else {
      if (dim == 0) dim = 2;
    }
    if (affine <= 1 && measure == 0) {
      // Collinear (r_max = L / (2 count), the packing of a segment) or one position (r_max = 0).
      result.status = Status::degenerate_input;
      r_max = internal::collinear_length<D>(S.positions) / (2.0 * double(count)) / options.sigma_position;
    } else {
      if (measure == 0) measure = internal::bounding_box_measure<D>(S.positions);
      r_max = internal::packing_radius(measure, count, dim) / options.sigma_position;
    }
    if (!(r_max > 0)) result.status = Status::degenerate_input;  // one place, or an extent whose squares underflow
  }
  result.radius = r_max;

  std::vector<std::uint8_t> removed(n, 0);
  if (count < n && r_max > 0) {
    const double two_r = 2 * r_max;
    const double r_min = options.weight_limiting
                             ? two_r * 0.65 * (1 - std::pow(double(count) / double(n), 1.5))
                             : 0.0;
    // Neighbour lists (CSR, ids only: 4 bytes per neighbour; the weights are recomputed when an item goes,
    // which costs less than storing them on this scale). Two passes over the grid: count, then fill.
    bool interrupted = false;
    internal::with_metric(options, [&](const auto& metric) {
      const double spatial = two_r * metric.spatial_scale(), spatial2 = spatial * spatial;
      // Weight of the pair (i, j), or a negative number when j is not within 2 r_max of i.
      auto pair_weight = [&](std::size_t i, std::size_t j) {
        const double d2 = S.squared_distance(i, j);
        if (!(d2 < spatial2)) return -1.0;
        const double xi = metric(d2, S.squared_feature_distance(i, j));
        if (!(xi < two_r)) return -1.0;
        const double base = 1 - std::max(xi, r_min) / two_r;
        if (options.alpha == 8) {  // the default: three multiplications instead of pow
          const double b2 = base * base, b4 = b2 * b2;
          return b4 * b4;
        }
        return std::pow(base, options.alpha);
      };
      const FeatureRecon::internal::Uniform_grid<D> grid(S.positions, spatial);
      std::vector<std::size_t> offset(n + 1, 0);
      for (std::size_t i = 0; i < n; ++i)
        grid.for_each_candidate(S.positions[i], [&](std::uint32_t j) {
          if (j != i && pair_weight(i, j) >= 0) ++offset[i + 1];
        });
      for (std::size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
      std::vector<std::uint32_t> neighbor(offset[n]);
      std::vector<double> weight(n, 0.0);
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t k = offset[i];
        grid.for_each_candidate(S.positions[i], [&](std::uint32_t j) {
          if (j == i) return;
          const double w = pair_weight(i, j);
          if (w < 0) return;
          neighbor[k++] = j;
          weight[i] += w;
        });
      }

      const std::vector<std::uint32_t> priority = internal::seeded_permutation(n, options.seed);
      internal::Elimination_heap heap(weight, priority);
      const std::size_t eliminations = n - count;
      for (std::size_t e = 0; e < eliminations; ++e) {
        if ((e & 16383) == 0 &&
            !FeatureRecon::internal::report_progress(options.progress, double(e) / double(eliminations))) {
          interrupted = true;
          return;
        }
        const std::uint32_t x = heap.pop();
        removed[x] = 1;
        for (std::size_t k = offset[x]; k < offset[x + 1]; ++k) {
          const std::uint32_t y = neighbor[k];
          if (removed[y]) continue;
          weight[y] -= pair_weight(y, x);
          heap.decreased(y);
        }
      }
    });
    if (interrupted) {
      result.status = Status::interrupted;
      return result;
    }
  } else if (count < n) {
    // r_max = 0 (all items at one position, or a zero measure): no neighbourhoods; keep a seeded choice.
    const std::vector<std::uint32_t> priority = internal::seeded_permutation(n, options.seed);
    for (std::size_t i = 0; i < n; ++i) removed[i] = priority[i] >= count;
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  for (std::size_t i = 0; i < n; ++i)
    if (!removed[i]) {
      *result.out++ = i;
      ++result.selected;
    }
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_WEIGHTED_SAMPLE_ELIMINATION_H
