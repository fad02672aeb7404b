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
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

namespace internal {
/// \cond
/// Binary max-heap over items 0..n-1 keyed by (weight, priority), with positions for decrease-key.
class Elimination_heap {
 public:
  Elimination_heap(const std::vector<std::uint64_t>& weight, const std::vector<std::uint32_t>& priority)
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
    const std::uint64_t wa = (*m_weight)[a], wb = (*m_weight)[b];
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
  const std::vector<std::uint64_t>* m_weight;
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
/// neighbours per item, O(n k) memory (4 bytes per neighbour); k is about 3.6 n / count in 2D, 5.9 n / count
/// in 3D. When those lists would exceed 2^24 ids (and n > 16 count) the elimination is progressive: stages of
/// factor 4 (each with the r_max of its own count) first bring n down to max(16 count, sqrt(2^24 count / c)).
/// With `options.periodic` the positions are taken modulo 1 (or modulo `options.period` per axis) and
/// distances are those of the torus, so that the kept set tiles the plane (or space), as Yuksel's tileable
/// sets; the grid is then looked up also shifted by the period across the faces the neighbourhood reaches.
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
///   `degenerate_input` for an empty input, and where the automatic r_max (max_radius 0, count > 0) meets
///   input of lower affine dimension than the domain, decided by exact predicates: collinear points without a
///   domain_measure (r_max = L / (2 count) for the segment of length L), coplanar 3D points asked to be
///   sampled as a volume without a domain_measure (sampled as a surface), one repeated position (the seed
///   picks the items), and positions so close together (spans below about 1e-154) that r_max underflows to 0
///   (the seed picks the items); with a given max_radius or domain_measure, or for count 0, nothing is
///   estimated and such input gives success; `interrupted` (nothing written) when the callback stopped.
/// \throws std::invalid_argument naming the argument: neighbour lists longer than max_neighbor_entries (a
///   max_radius far too large; found while counting them, before they are stored), count larger than the
///   input, non-finite coordinates (naming the item), sigma_position <= 0, sigma_feature <= 0, negative
///   max_radius or domain_measure, intrinsic_dimension other than 0, 2 or 3 or above the positions'
///   dimension, alpha <= 0, a `period` given without `periodic`, of another length than the positions'
///   dimension or with a value outside [1e-150, 1e150] (naming the index), with a finite sigma_feature a
///   feature at a non-finite distance from itself (a zero normal, NaN; naming the item) or two features at a
///   NaN or negative distance (naming both). The input is never modified.
/// \note Duplicated items (the same position at bilateral distance 0) are eliminated first, before the
///   neighbour lists are built (weight limiting gives them the largest weight, and copies would cost
///   neighbour lists quadratic in their number): of each group of copies the item of lowest seeded priority
///   stays. When there are more copies than eliminations, copies are removed one at a time from the largest
///   group (whose copies weigh the most; neighbours are not weighed). Ties between weights that compare equal
///   are broken by a permutation drawn from `seed`, so the same input and seed give the same output on every
///   platform. Weights are sums of pair weights rounded to multiples of 2^-(63 - b) times the largest pair
///   weight (2^b above the most neighbours of an item; 2^-56 up to 127), kept in 64-bit integers: removing a
///   neighbour subtracts its pair weight exactly, so weights equal in exact arithmetic (on a grid) tie and
///   the seed decides, never the rounding of the order in which neighbours went.
/// \sa sampling_quality(), bilateral_dart_throwing().
template <class ItemRange, class OutputIterator, class Traits = Default_traits_t<ItemRange>>
Sampling_result<OutputIterator> weighted_sample_elimination(const ItemRange& items, std::size_t count,
                                                            OutputIterator selected,
                                                            const Elimination_options& options = {},
                                                            const Traits& traits = Traits()) {
  const char* fn = "weighted_sample_elimination";
  internal::check_sigmas(options.sigma_position, options.sigma_feature, fn);
  if (!(options.max_radius >= 0 && std::isfinite(options.max_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "max_radius must be finite and >= 0, got ",
                                                   options.max_radius);
  if (!(options.max_radius * options.sigma_position <= 1e100))  // items lie within +-1e100
    FeatureRecon::internal::throw_invalid_argument(fn, "max_radius (", options.max_radius,
                                                   ") times sigma_position (", options.sigma_position,
                                                   ") is beyond 1e100, farther than any two "
                                                   "items can lie apart");
  internal::check_domain(options.domain_measure, options.intrinsic_dimension, Traits::dimension, fn);
  if (!(options.alpha > 0 && std::isfinite(options.alpha)))
    FeatureRecon::internal::throw_invalid_argument(fn, "alpha must be finite and > 0, got ", options.alpha);
  const internal::Sample_set<Traits> S(items, traits, fn, std::isfinite(options.sigma_feature));
  internal::check_position_scale(S.extent(), options.sigma_position, fn);
  constexpr int D = Traits::dimension;
  // On the torus, the positions modulo the periods stand for the items everywhere below.
  const std::array<double, D> period = internal::torus_period<D>(options.period, options.periodic, fn);
  const std::vector<std::array<double, D>> wrapped = options.periodic
                                                         ? internal::torus_positions(S.positions, period)
                                                         : std::vector<std::array<double, D>>();
  const std::vector<std::array<double, D>>& where = options.periodic ? wrapped : S.positions;
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
  // The dimension of the packing behind r_max: how the radius of an intermediate stage scales with its count.
  int packing_dimension = options.intrinsic_dimension != 0 ? options.intrinsic_dimension : 2;
  if (r_max == 0 && count > 0) {
    int dim = options.intrinsic_dimension;
    double measure = options.domain_measure;
    if (options.periodic && measure == 0 && (dim == 0 || dim == D)) {
      dim = D;  // the torus itself, whatever the items' own extent
      measure = internal::torus_measure(period);
    }
    const int affine = internal::affine_dimension<D>(where);
    if constexpr (D == 3) {
      if (affine >= 2 && (dim == 0 || (dim == 2 && measure == 0) || (affine == 2 && measure == 0))) {
        // Estimated on the distinct positions: copies would be neighbours at distance 0.
        const std::vector<std::array<double, 3>> places = internal::distinct_positions(where);
        const internal::Knn_3 knn(places);
        if (dim == 0) dim = affine == 2 ? 2 : internal::estimate_intrinsic_dimension(places, knn);
        if (affine == 2 && dim == 3) {
          dim = 2;
          result.status = Status::degenerate_input;
        }
        if (dim == 2 && measure == 0) measure = internal::estimate_surface_area(places, knn);
      }
    }
    if (dim == 0) dim = 2;  // 2D positions, and collinear 3D ones with a measure given
    if (affine <= 1 && measure == 0) {
      // Collinear (r_max = L / (2 count), the packing of a segment) or one position (r_max = 0).
      result.status = Status::degenerate_input;
      r_max = internal::collinear_length<D>(where) / (2.0 * double(count)) / options.sigma_position;
      packing_dimension = 1;
    } else {
      if (measure == 0) measure = internal::bounding_box_measure<D>(where);
      r_max = internal::packing_radius(measure, count, dim) / options.sigma_position;
      packing_dimension = dim;
    }
    if (!(r_max > 0))
      result.status = Status::degenerate_input;  // one place, or an extent whose squares underflow
  }
  result.radius = r_max;

  std::vector<std::uint8_t> removed(n, 0);
  if (count < n && r_max > 0) {
    const std::vector<std::uint32_t> global_priority = internal::seeded_permutation(n, options.seed);
    // Exact copies (the same position at bilateral distance 0) weigh the most and go first; but each copy's
    // neighbour list would hold every other copy of its place (quadratic: 20,000 copies of one point among
    // 200,000 took 33 s and 1.6 GB). They are removed up front: of each group of copies the item of lowest
    // priority stays, the one the heap pops last among equal weights.
    std::size_t eliminated_before = 0;
    internal::with_metric(options, [&](const auto& metric) {
      std::vector<std::pair<std::array<double, D>, std::uint32_t>> by_position(n);  // contiguous: a fast sort
      for (std::size_t i = 0; i < n; ++i) by_position[i] = {where[i], static_cast<std::uint32_t>(i)};
      std::sort(by_position.begin(), by_position.end());
      // Groups of copies: per place, one group per feature class (the first member stands for it).
      std::vector<std::vector<std::uint32_t>> groups;
      std::size_t surplus = 0;
      for (std::size_t a = 0, b = 0; a < n; a = b) {
        for (b = a + 1; b < n && by_position[b].first == by_position[a].first;) ++b;
        if (b - a < 2) continue;
        const std::size_t first_group = groups.size();
        for (std::size_t k = a; k < b; ++k) {
          const std::uint32_t x = by_position[k].second;
          const auto same = std::find_if(groups.begin() + std::ptrdiff_t(first_group), groups.end(),
                                         [&](const std::vector<std::uint32_t>& g) {
                                           return metric(0.0, S.squared_feature_distance(x, g.front())) == 0;
                                         });
          if (same == groups.end())
            groups.push_back({x});
          else
            same->push_back(x);
        }
      }
      for (auto& g : groups) {  // the member the heap pops first comes first: highest priority
        std::sort(g.begin(), g.end(),
                  [&](std::uint32_t x, std::uint32_t y) { return global_priority[x] > global_priority[y]; });
        surplus += g.size() - 1;
      }
      const std::size_t budget = n - count;
      if (surplus <= budget) {  // every copy but the last of each group
        for (const auto& g : groups)
          for (std::size_t k = 0; k + 1 < g.size(); ++k) removed[g[k]] = 1;
        eliminated_before = surplus;
      } else {
        // More copies than eliminations: only copies go, each time one of the largest group, whose copies
        // weigh the most (ties: the higher priority of the next copy to go; other neighbours are not
        // weighed).
        std::vector<std::size_t> next(groups.size(), 0);  // copies removed from each group so far
        auto lighter = [&](std::size_t u, std::size_t v) {
          const std::size_t su = groups[u].size() - next[u], sv = groups[v].size() - next[v];
          return su != sv ? su < sv
                          : global_priority[groups[u][next[u]]] < global_priority[groups[v][next[v]]];
        };
        std::vector<std::size_t> heap;
        for (std::size_t g = 0; g < groups.size(); ++g)
          if (groups[g].size() >= 2) heap.push_back(g);
        std::make_heap(heap.begin(), heap.end(), lighter);
        for (std::size_t e = 0; e < budget; ++e) {
          std::pop_heap(heap.begin(), heap.end(), lighter);
          const std::size_t g = heap.back();
          removed[groups[g][next[g]++]] = 1;
          if (groups[g].size() - next[g] >= 2)
            std::push_heap(heap.begin(), heap.end(), lighter);
          else
            heap.pop_back();
        }
        eliminated_before = budget;
      }
    });
    std::vector<std::uint32_t> active;  // the items still in
    active.reserve(n - eliminated_before);
    for (std::size_t i = 0; i < n; ++i)
      if (!removed[i]) active.push_back(static_cast<std::uint32_t>(i));
    const std::size_t n_active = active.size();
    // Progressive elimination. Every item has about k = c n / count neighbours within 2 r_max (c = 3.6 for a
    // surface or image, 5.9 for a volume, 2 on a line): far fewer kept than given items would need O(n^2 /
    // count) memory and time. The last stage, Yuksel's elimination itself, therefore starts from at most
    // max(16 count, sqrt(2^24 count / c)) items (neighbour lists of at most 2^24 ids, 64 MB, beyond 16
    // count); more items are first reduced to that many in stages of factor 4, each with the r_max of its own
    // count, r_max (count / target)^(1 / dimension). Inputs within the bound are eliminated in one stage.
    const double per_neighbor = packing_dimension >= 3 ? 5.92 : packing_dimension == 2 ? 3.63 : 2.0;
    const double fit = std::sqrt(16777216.0 * double(count) / per_neighbor);
    std::vector<std::size_t> targets;  // decreasing, the last one count
    if (count > 0 && n_active / 16 > count && double(n_active) > fit) {
      std::vector<std::size_t> up{std::max(16 * count, static_cast<std::size_t>(fit))};
      while (up.back() <= n_active / 8) up.push_back(4 * up.back());
      targets.assign(up.rbegin(), up.rend());
    }
    targets.push_back(count);
    const double total_eliminations = double(n - count);
    bool interrupted = false;
    for (const std::size_t target : targets) {
      const std::size_t m = active.size();
      if (target >= m) continue;
      const double stage_r = target == count || target == 0
                                 ? r_max
                                 : r_max * std::pow(double(count) / double(target), 1.0 / packing_dimension);
      const double two_r = 2 * stage_r;
      const double r_min =
          options.weight_limiting ? two_r * 0.65 * (1 - std::pow(double(target) / double(m), 1.5)) : 0.0;
      std::vector<std::array<double, D>> positions(m);
      for (std::size_t i = 0; i < m; ++i) positions[i] = where[active[i]];
      // Neighbour lists (CSR, local ids only: 4 bytes per neighbour; the weights are recomputed when an item
      // goes, which costs less than storing them on this scale). Two passes over the grid: count, then fill.
      internal::with_metric(options, [&](const auto& metric) {
        const double spatial = two_r * metric.spatial_scale(), spatial2 = internal::prefilter_bound(spatial);
        // The grid's cell and look-up reach: on the torus with a margin for the rounding of shifted queries.
        const double cell = options.periodic
                                ? internal::torus_search_reach(spatial, internal::largest_period(period))
                                : spatial;
        // Weight of the pair (i, j) (local ids), or a negative number when j is not within 2 r of i.
        auto pair_weight = [&](std::size_t i, std::size_t j) {
          double d2 = 0;  // from the stage's own copy of the positions (contiguous, no indirection)
          if (options.periodic)
            d2 = internal::torus_squared_distance(positions[i], positions[j], period);
          else
            for (int k = 0; k < D; ++k)
              d2 += (positions[i][k] - positions[j][k]) * (positions[i][k] - positions[j][k]);
          if (!(d2 < spatial2)) return -1.0;
          const double xi = metric(d2, S.squared_feature_distance(active[i], active[j]));
          if (!(xi < two_r)) return -1.0;
          const double base = 1 - std::max(xi, r_min) / two_r;
          if (options.alpha == 8) {  // the default: three multiplications instead of pow
            const double b2 = base * base, b4 = b2 * b2;
            return b4 * b4;
          }
          return std::pow(base, options.alpha);
        };
        // The stage's items in grid-cell order (ties by input index): neighbours then lie close in memory.
        // The result does not depend on it: weights are sums of fixed-point integers (exact in any order),
        // and the heap pops by (weight, priority) alone. The grid below keeps the frame and core box chosen
        // here (from the positions alone, whatever their order).
        FeatureRecon::internal::Grid_frame<D> frame(positions, cell);
        const bool dense_cells = FeatureRecon::internal::use_core_cells(frame, positions, m);
        {
          std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(m);
          for (std::size_t i = 0; i < m; ++i)
            keyed[i] = {frame.order_key(frame.cell_of(positions[i])), active[i]};
          std::sort(keyed.begin(), keyed.end());
          for (std::size_t i = 0; i < m; ++i) {
            active[i] = keyed[i].second;
            positions[i] = where[active[i]];
          }
        }
        const FeatureRecon::internal::Uniform_grid<D> grid(positions, frame, dense_cells);
        // Calls f(j) for the candidates j near item i; on the torus each once, at its nearest image (with
        // 2 r_max above half a period, several images of j can lie within reach).
        auto for_each_candidate = [&](std::size_t i, const auto& f) {
          if (!options.periodic) return grid.for_each_candidate(positions[i], f);
          internal::for_each_torus_candidate(
              grid, positions[i], cell,
              [&](std::uint32_t j, int shift) {
                if (shift == internal::nearest_image_shift(positions[i], positions[j], period)) f(j);
              },
              {}, period);
        };
        // The callback is asked at the start of every stage and every 16,384 items or eliminations after it,
        // the neighbour lists included (dense clusters make them the long part).
        auto stop = [&](std::size_t step) {
          return (step & 16383) == 0 && !FeatureRecon::internal::report_progress(
                                            options.progress, double(eliminated_before) / total_eliminations);
        };
        std::vector<std::size_t> offset(m + 1, 0);
        std::size_t entries = 0, since_asked = 0;
        // Elimination_options::max_neighbor_entries, 0: 64 times what this stage needs at the automatic
        // r_max.
        const double automatic_limit = std::max(536870912.0, 64 * per_neighbor * double(m) * double(m) /
                                                                 double(std::max<std::size_t>(target, 1)));
        const std::size_t limit = options.max_neighbor_entries > 0 ? options.max_neighbor_entries
                                  : automatic_limit >= 1e18        ? std::numeric_limits<std::size_t>::max()
                                                            : static_cast<std::size_t>(automatic_limit);
        for (std::size_t i = 0; i < m; ++i) {
          // Asked at the start and then about every 16,384 items, sooner when they have many candidates (the
          // count's work grows with them).
          if (i == 0 || since_asked >= 16384) {
            since_asked = 0;
            if (!FeatureRecon::internal::report_progress(options.progress,
                                                         double(eliminated_before) / total_eliminations)) {
              interrupted = true;
              return;
            }
          }
          std::size_t visited = 0;
          for_each_candidate(i, [&](std::uint32_t j) {
            ++visited;
            if (j != i && pair_weight(i, j) >= 0) ++offset[i + 1];
          });
          entries += offset[i + 1];
          since_asked += visited / 16 + 1;
          if (entries > limit)
            FeatureRecon::internal::throw_invalid_argument(
                fn, "the neighbour lists within 2 r_max would hold more than ", limit, " entries (",
                options.max_neighbor_entries > 0 ? "" : "automatic ",
                "Elimination_options::max_neighbor_entries; r_max ", stage_r, " in the stage from ", m,
                " items to ", target, "; the first ", i + 1, " items have ", entries,
                " neighbours): max_radius is too large for these items (0: the automatic r_max) or they "
                "crowd "
                "at one spot; raise the limit for a larger run");
        }
        for (std::size_t i = 0; i < m; ++i) offset[i + 1] += offset[i];
        std::vector<std::uint32_t> neighbor(offset[m]);
        // Weights in fixed point: pair weights (at most w_max, the weight of a pair at distance r_min or
        // less) in units of 2^-(63 - b) w_max rounded up to a power of two, 2^b above the most neighbours any
        // item has (2^-56 w_max for up to 127), summed in 64-bit integers without overflow. A weight kept up
        // to date by subtraction is then exactly the sum over the neighbours left, and weights equal in exact
        // arithmetic compare equal: the seed breaks their tie, not the rounding of the order in which
        // neighbours went (doubles did that on grids). Scaled by w_max, not 1: with alpha 64, w_max =
        // 0.35^64, every weight rounded to 0 and the seed alone chose.
        std::size_t most_neighbours = 0;
        for (std::size_t i = 0; i < m; ++i)
          most_neighbours = std::max(most_neighbours, offset[i + 1] - offset[i]);
        int bits = 0;
        while (bits < 63 && (std::uint64_t(1) << bits) <= most_neighbours) ++bits;
        const double base_max = 1 - r_min / two_r, b2 = base_max * base_max, b4 = b2 * b2;
        const double w_max = options.alpha == 8 ? b4 * b4 : std::pow(base_max, options.alpha);
        const int top = w_max > 0 ? std::ilogb(w_max) + 1 : 0;  // w_max < 2^top
        const double scale = std::ldexp(1.0, std::min(1000, 63 - bits - top));
        auto fixed = [scale](double w) { return static_cast<std::uint64_t>(std::llround(w * scale)); };
        std::vector<std::uint64_t> weight(m, 0);
        for (std::size_t i = 0; i < m; ++i) {
          if (i > 0 && stop(i)) {
            interrupted = true;
            return;
          }
          std::size_t k = offset[i];
          for_each_candidate(i, [&](std::uint32_t j) {
            if (j == i) return;
            const double w = pair_weight(i, j);
            if (!(w >= 0)) return;  // the test of the count
            neighbor[k++] = j;
            weight[i] += fixed(w);
          });
        }
        std::vector<std::uint32_t> priority(m);
        for (std::size_t i = 0; i < m; ++i) priority[i] = global_priority[active[i]];
        internal::Elimination_heap heap(weight, priority);
        std::vector<std::uint8_t> gone(m, 0);
        const std::size_t eliminations = m - target;
        for (std::size_t e = 0; e < eliminations; ++e) {
          if (e > 0 && (e & 16383) == 0 &&
              !FeatureRecon::internal::report_progress(options.progress,
                                                       double(eliminated_before + e) / total_eliminations)) {
            interrupted = true;
            return;
          }
          const std::uint32_t x = heap.pop();
          gone[x] = 1;
          removed[active[x]] = 1;
          for (std::size_t k = offset[x]; k < offset[x + 1]; ++k) {
            const std::uint32_t y = neighbor[k];
            if (gone[y]) continue;
            weight[y] -= fixed(pair_weight(y, x));
            heap.decreased(y);
          }
        }
        eliminated_before += eliminations;
      });
      if (interrupted) break;
      active.erase(
          std::remove_if(active.begin(), active.end(), [&](std::uint32_t i) { return removed[i] != 0; }),
          active.end());
    }
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
