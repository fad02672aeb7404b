// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_BILATERAL_DART_THROWING_H
#define FEATURERECON_SAMPLING_BILATERAL_DART_THROWING_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/internal/radius_search.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>
#include <FeatureRecon/traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace FeatureRecon {
namespace sampling {

namespace internal {
/// \cond
/// The visiting order of dart throwing: by decreasing priority (ties by index) or a seeded permutation.
inline std::vector<std::uint32_t> dart_order(std::size_t n, const Dart_throwing_options& o) {
  if (o.priority.empty()) return seeded_permutation(n, o.seed);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), std::uint32_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return o.priority[a] > o.priority[b]; });
  return order;
}

inline void check_dart_options(const Dart_throwing_options& o, std::size_t n, double extent, const char* fn) {
  check_sigmas(o.sigma_position, o.sigma_feature, fn);
  check_position_scale(extent, o.sigma_position, fn);
  if (!o.radii.empty() && o.radii.size() != n)
    FeatureRecon::internal::throw_invalid_argument(fn, "radii has ", o.radii.size(), " values for ", n,
                                                   " items");
  for (std::size_t i = 0; i < o.radii.size(); ++i)
    if (!(std::isfinite(o.radii[i]) && o.radii[i] > 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "radii[", i, "] must be finite and > 0, got ",
                                                     o.radii[i]);
  if (!o.priority.empty() && o.priority.size() != n)
    FeatureRecon::internal::throw_invalid_argument(fn, "priority has ", o.priority.size(), " values for ", n,
                                                   " items");
  for (std::size_t i = 0; i < o.priority.size(); ++i)
    if (std::isnan(o.priority[i]))
      FeatureRecon::internal::throw_invalid_argument(fn, "priority[", i, "] is NaN");
}

/// The largest factor t with t m <= xi in floating point (xi >= 0, m > 0): a pair at distance xi whose larger
/// radius is m conflicts at the factor t' exactly when t' > t. xi / m rounded can lie an ulp either side of
/// it (a throw at a returned factor then lost a pair); with m = 1, xi itself.
inline double largest_factor_within(double xi, double m) {
  double t = xi / m;
  if (!std::isfinite(t)) return t;
  while (t > 0 && t * m > xi) t = std::nextafter(t, 0.0);
  for (double up = std::nextafter(t, std::numeric_limits<double>::infinity()); up * m <= xi;
       up = std::nextafter(t, std::numeric_limits<double>::infinity()))
    t = up;
  return t;
}

/// One pass of dart throwing over the items in `order`; returns the accepted items in acceptance order, or
/// nothing with `interrupted` set. With per-item radii `radius` is a factor: item i's radius is radius
/// o.radii[i] (1 for the radii as given). With `largest_conflict`, also the largest over the rejected items
/// of the distance to their nearest earlier accepted item (-infinity when none was rejected), with per-item
/// radii divided by the larger radius of the pair: every radius (factor) above it and up to `radius` rejects
/// the same items, so throws the same set.
template <class Traits>
std::vector<std::uint32_t> throw_darts(const Sample_set<Traits>& S, double radius,
                                       const Dart_throwing_options& o,
                                       const std::vector<std::uint32_t>& order, bool& interrupted,
                                       double* largest_conflict = nullptr) {
  constexpr int D = Traits::dimension;
  const std::size_t n = S.size();
  std::vector<std::uint32_t> accepted;
  const double largest =
      o.radii.empty() ? radius : radius * *std::max_element(o.radii.begin(), o.radii.end());
  interrupted = false;
  if (largest_conflict != nullptr) *largest_conflict = -std::numeric_limits<double>::infinity();
  // On the torus (o.periodic) the grid holds the positions modulo the periods; a position within the reach
  // of a face of the cell is also looked up shifted by minus or plus the period along that axis (every
  // combination of such shifts), and distances take the nearest image of each coordinate difference, for any
  // reach.
  const std::array<double, D> period = torus_period<D>(o.period, o.periodic, "bilateral_dart_throwing");
  const std::vector<std::array<double, D>> wrapped =
      o.periodic ? torus_positions(S.positions, period) : std::vector<std::array<double, D>>();
  const auto& where = o.periodic ? wrapped : S.positions;
  const auto squared_distance = [&](std::uint32_t i, std::uint32_t j) {
    return o.periodic ? torus_squared_distance(wrapped[i], wrapped[j], period) : S.squared_distance(i, j);
  };
  with_metric(o, [&](const auto& metric) {
    const double reach = largest * metric.spatial_scale();
    // margin: see torus_search_reach()
    const double cell = o.periodic ? torus_search_reach(reach, largest_period(period)) : reach;
    FeatureRecon::internal::Dynamic_grid<D> grid(where, cell);
    const double reach2 = prefilter_bound(reach);
    // Calls f(j) for every kept candidate near position p, on the torus also near its shifted copies.
    const auto for_each_candidate = [&](const std::array<double, D>& p, const auto& f) {
      if (!o.periodic) return grid.for_each_candidate(p, f);
      for_each_torus_candidate(
          grid, p, cell, [&](std::uint32_t j, int) { f(j); }, {}, period);
    };
    std::size_t failures = 0;
    for (std::size_t step = 0; step < n; ++step) {
      if ((step & 65535) == 0 &&
          !FeatureRecon::internal::report_progress(o.progress, double(step) / double(n))) {
        interrupted = true;
        accepted.clear();
        return;
      }
      const std::uint32_t i = order[step];
      const double ri = o.radii.empty() ? radius : radius * o.radii[i];
      bool conflict = false;
      if (largest_conflict == nullptr) {
        for_each_candidate(where[i], [&](std::uint32_t j) {
          if (conflict) return;
          const double d2 = squared_distance(i, j);
          if (!(d2 < reach2)) return;
          const double rj = o.radii.empty() ? radius : radius * o.radii[j];
          conflict = metric(d2, S.squared_feature_distance(i, j)) < std::max(ri, rj);
        });
      } else {
        double nearest = std::numeric_limits<double>::infinity();
        for_each_candidate(where[i], [&](std::uint32_t j) {
          // A rejected item's nearest conflict only counts when it exceeds the largest so far.
          if (conflict && nearest <= *largest_conflict) return;
          const double d2 = squared_distance(i, j);
          if (!(d2 < reach2)) return;
          const double xi = metric(d2, S.squared_feature_distance(i, j));
          // The pair's radius in units of the factor (max(r_i, r_j) = radius unit, as above).
          const double unit = o.radii.empty() ? 1.0 : std::max(o.radii[i], o.radii[j]);
          if (xi < radius * unit) {
            conflict = true;
            nearest = std::min(nearest, o.radii.empty() ? xi : largest_factor_within(xi, unit));
          }
        });
        if (conflict) *largest_conflict = std::max(*largest_conflict, nearest);
      }
      if (conflict) {
        if (o.max_consecutive_failures != 0 && ++failures >= o.max_consecutive_failures) break;
        continue;
      }
      failures = 0;
      grid.insert(i);
      accepted.push_back(i);
      if (o.max_accepted != 0 && accepted.size() >= o.max_accepted) break;
    }
  });
  return accepted;
}

/// The smallest distance between two items of `kept` (a throw with `o`; with per-item radii each distance
/// divided by the larger radius of the pair), or `cap` when no pair lies closer: every radius (factor) from
/// the throw's up to it accepts the same items, so throws the same set.
/// Stops at the first distance below `stop_below` (then returns it). Pairs are searched within cap
/// sigma_position with a relative margin of 2^-40, so that no pair closer than `cap` is missed by the
/// rounding of the grid's cells.
template <class Traits>
double throw_separation(const Sample_set<Traits>& S, const std::vector<std::uint32_t>& kept, double cap,
                        const Dart_throwing_options& o, double stop_below) {
  constexpr int D = Traits::dimension;
  std::vector<std::array<double, D>> where(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) where[k] = S.positions[kept[k]];
  const std::array<double, D> period = torus_period<D>(o.period, o.periodic, "bilateral_dart_throwing");
  if (o.periodic) where = torus_positions(std::move(where), period);
  const auto squared_distance = [&](std::uint32_t a, std::uint32_t b) {
    return o.periodic ? torus_squared_distance(where[a], where[b], period)
                      : S.squared_distance(kept[a], kept[b]);
  };
  double smallest = cap;
  double widest = 1;  // with per-item radii, the largest of the kept items'
  if (!o.radii.empty() && !kept.empty()) {
    widest = 0;
    for (const std::uint32_t i : kept) widest = std::max(widest, o.radii[i]);
  }
  with_metric(o, [&](const auto& metric) {
    const double reach = cap * widest * metric.spatial_scale() * (1 + 0x1p-40);
    const double cell = o.periodic ? torus_search_reach(reach, largest_period(period)) : reach;
    FeatureRecon::internal::Dynamic_grid<D> grid(where, cell);
    const double reach2 = prefilter_bound(reach);
    for (std::uint32_t a = 0; a < where.size() && !(smallest < stop_below); ++a) {
      const auto visit = [&](std::uint32_t b) {
        const double d2 = squared_distance(a, b);
        const double unit = o.radii.empty() ? 1.0 : std::max(o.radii[kept[a]], o.radii[kept[b]]);
        if (d2 < reach2) {
          const double xi = metric(d2, S.squared_feature_distance(kept[a], kept[b]));
          smallest = std::min(smallest, o.radii.empty() ? xi : largest_factor_within(xi, unit));
        }
      };
      if (o.periodic)
        for_each_torus_candidate(
            grid, where[a], cell, [&](std::uint32_t b, int) { visit(b); }, {}, period);
      else
        grid.for_each_candidate(where[a], visit);
      grid.insert(a);
    }
  });
  return smallest;
}
/// \endcond
}  // namespace internal

/// Bilateral dart throwing on a discrete domain (a point cloud, the pixels of an image): the items are
/// visited in a random order (or by a given priority) and an item is kept when no kept item lies within
/// bilateral distance r of it (dissertation Sec. 2.2.2: only the distance changes, so uniform and adaptive
/// radii combine with it). Visiting every item once makes the result maximal on the domain. With
/// `options.radii` the radius varies per item and two items conflict when xi < max(r(s), r(t)).
///
/// Neighbours are searched in a uniform grid of side r_largest sigma_position (every metric here satisfies
/// xi >= |dp| / sigma_position). O(n k) time for k items per grid neighbourhood. With `options.periodic`
/// the positions are taken modulo 1 (or modulo `options.period` per axis) and distances are those of the
/// torus, so that the set tiles the plane (or space), as the spectral analysis of sampling_spectrum()
/// assumes (on the unit torus).
///
/// \tparam ItemRange a forward range of `Traits::Item`. \tparam OutputIterator accepts std::size_t.
/// \tparam Traits a model of FeaturePointTraits (default: Default_traits_t<ItemRange>).
/// \param items the input samples. \param radius the conflict radius in bilateral units (> 0, checked;
///   throws; ignored when `options.radii` is set). \param selected receives the kept indices in increasing
///   order.
/// \param options metric, per-item radii, priority, seed, early stops (consecutive failures, a cap on the
///   count), progress. \param traits accessors.
/// \returns the advanced iterator, the number kept, the radius and the status (`degenerate_input` for an
///   empty input, and for a radius below about 1e-144 position units, whose square lies below 2^-960: the
///   squared distances it is compared with have lost their digits, and the set kept may be neither a packing
///   nor maximal; `interrupted`, with nothing written, when the callback stopped).
/// \throws std::invalid_argument naming the argument: radius <= 0, radii or priority of the wrong size or
///   with bad values (naming the index), non-finite coordinates (naming the item), bad sigmas, a `period`
///   given without `periodic`, of another length than the positions' dimension or with a value outside
///   [1e-150, 1e150] (naming the index).
/// \note Conflicts are strict (xi < r): two items at distance exactly r may both be kept. The same input and
///   seed give the same output.
/// \sa bilateral_dart_throwing_count(), weighted_sample_elimination().
template <class ItemRange, class OutputIterator, class Traits = Default_traits_t<ItemRange>>
Sampling_result<OutputIterator> bilateral_dart_throwing(const ItemRange& items, double radius,
                                                        OutputIterator selected,
                                                        const Dart_throwing_options& options = {},
                                                        const Traits& traits = Traits()) {
  const char* fn = "bilateral_dart_throwing";
  if (options.radii.empty() && !(std::isfinite(radius) && radius > 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and > 0, got ", radius);
  const internal::Sample_set<Traits> S(items, traits, fn, std::isfinite(options.sigma_feature));
  internal::check_dart_options(options, S.size(), S.extent(), fn);
  (void)internal::torus_period<Traits::dimension>(options.period, options.periodic, fn);
  // With per-item radii, the largest of them (the `radius` argument is ignored).
  const double used =
      options.radii.empty() ? radius : *std::max_element(options.radii.begin(), options.radii.end());
  Sampling_result<OutputIterator> result{selected, 0, used, Status::success};
  if (S.size() == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  bool interrupted = false;
  std::vector<std::uint32_t> kept = internal::throw_darts(
      S, options.radii.empty() ? radius : 1.0, options, internal::dart_order(S.size(), options), interrupted);
  if (interrupted) {
    result.status = Status::interrupted;
    return result;
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  std::sort(kept.begin(), kept.end());
  for (const std::uint32_t i : kept) *result.out++ = i;
  result.selected = kept.size();
  // A radius whose square (in position units) is below 2^-960 cannot be compared with squared distances that
  // keep their digits (3000 points of spread 3e-163 at r = 1e-164 kept 220 instead of 566, success):
  // reported.
  const bool tiny = internal::with_metric(options, [&](const auto& metric) {
    const double reach = used * metric.spatial_scale();
    return reach > 0 && reach * reach < 0x1p-960;
  });
  if (tiny) result.status = Status::degenerate_input;
  return result;
}

/// Bilateral dart throwing with a target count: searches the radius until a maximal throw (same order
/// every time) keeps exactly `count` items. The kept count falls about as a power of the radius (r^-2 for
/// points spread in the plane), so each step interpolates log count against log radius between the bracket's
/// ends (regula falsi), with a bisection after a step that did not halve the bracket: about half the throws
/// of a plain bisection (13 instead of 26 for 10,000 of 50,000 points in the plane). When no radius gives
/// exactly `count` (the count is a step function of the radius), the throw at the largest radius found that
/// keeps more than `count` is cut to its first `count` accepted items, which still respect that radius but
/// are no longer maximal. The search knows that it is over when the count jumps over `count` at a single
/// distance, as on a grid or the pixels of a picture, where many pairs lie at the same distance: every radius
/// above the largest distance of a rejected item to its nearest accepted one throws the same set, and so does
/// every radius up to the smallest distance within a throw. Distances equal in exact arithmetic but rounded
/// apart (a grid 0.1 apart, far from the origin) count as one within 2^-40 relative plus 2^-48 times the
/// largest coordinate magnitude over sigma_position, so that a scaled or shifted grid gives the same items.
/// With the exponential form, items of very different features may never conflict (their distance
/// overflows): when no finite radius keeps as few as `count`, the throw at the largest radius tried (doubling
/// from the largest finite distance) is cut.
///
/// With per-item radii (`options.darts.radii`, adaptive sampling) they give the shape: the search is on the
/// factor t of the radii t r(s), and distances count divided by the larger r of the pair, so the jumps are
/// found as with a uniform radius (a stippling of a picture whose density is constant over large areas: the
/// count jumps over the goal there).
/// \param count the number of items to keep, 0 <= count <= number of items (checked; throws).
/// \returns as bilateral_dart_throwing(); `radius` is the radius of the returned set (when the search
///   ended at a jump, the largest radius known to throw the set that was cut); with per-item radii the
///   factor t. With `options.cut` false the whole throw at that radius (count or more items) is written.
/// \throws std::invalid_argument as bilateral_dart_throwing(), when `options.darts.max_accepted` is set,
///   for max_iterations 0, count_tolerance outside [0, 1] and a negative or non-finite initial_radius.
template <class ItemRange, class OutputIterator, class Traits = Default_traits_t<ItemRange>>
Sampling_result<OutputIterator> bilateral_dart_throwing_count(const ItemRange& items, std::size_t count,
                                                              OutputIterator selected,
                                                              const Dart_throwing_count_options& options = {},
                                                              const Traits& traits = Traits()) {
  const char* fn = "bilateral_dart_throwing_count";
  const internal::Sample_set<Traits> S(items, traits, fn, std::isfinite(options.darts.sigma_feature));
  const std::size_t n = S.size();
  internal::check_dart_options(options.darts, n, S.extent(), fn);
  (void)internal::torus_period<Traits::dimension>(options.darts.period, options.darts.periodic, fn);
  if (options.darts.max_accepted != 0)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "darts.max_accepted cannot be combined with a target count");
  internal::check_count(count, n, fn);
  if (options.max_iterations == 0)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "max_iterations must be >= 1 (bisection steps on the radius)");
  if (!(options.count_tolerance >= 0 && options.count_tolerance <= 1))
    FeatureRecon::internal::throw_invalid_argument(fn, "count_tolerance must be in [0, 1], got ",
                                                   options.count_tolerance);
  if (!(options.initial_radius >= 0 && std::isfinite(options.initial_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "initial_radius must be finite and >= 0, got ",
                                                   options.initial_radius);
  bool guessed = options.initial_radius == 0;  // the first throw at initial_radius is done
  // A throw keeping count to count + surplus items ends the search.
  const std::size_t surplus = static_cast<std::size_t>(std::floor(options.count_tolerance * double(count)));
  Sampling_result<OutputIterator> result{selected, 0, 0, Status::success};
  if (n == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  if (count == 0) return result;
  const std::vector<std::uint32_t> order = internal::dart_order(n, options.darts);
  Dart_throwing_options quiet = options.darts;
  quiet.progress = nullptr;
  // With per-item radii the search is on their factor t (item i's radius t radii[i]): a pair's distance
  // counts divided by its larger radius, at least the second smallest radius (pair_shape: the start bounds),
  // and the rounding of a distance by the largest (widest_shape: a tolerance too wide took false jumps when
  // one radius was tiny).
  double pair_shape = 1, widest_shape = 1;
  if (!quiet.radii.empty()) {
    std::vector<double> two(2);
    std::partial_sort_copy(quiet.radii.begin(), quiet.radii.end(), two.begin(), two.end());
    pair_shape = quiet.radii.size() > 1 ? two[1] : two[0];
    widest_shape = *std::max_element(quiet.radii.begin(), quiet.radii.end());
  }
  // Bracket: at `search.lo` the throw keeps more than `count` items (or everything), at `search.hi` at most
  // `count`.
  // Twice the largest distance from item 0 bounds the radius that keeps a single item (for the Gaussian
  // form, a metric; for the exponential form a heuristic start: the bisection only needs a bracket).
  const double high_start = internal::with_metric(quiet, [&](const auto& m) {
    double r = 0;
    for (std::size_t i = 0; i < n; ++i)
      r = std::max(r, m(S.squared_distance(0, i), S.squared_feature_distance(0, i)));
    return 2 * r / pair_shape;
  });
  internal::Bracketed_radius_search search;
  search.hi = high_start;
  bool interrupted = false;
  std::vector<std::uint32_t> best;  // the throw at `search.lo` (more than count items) or an exact hit
  double best_radius = 0;
  // Every radius in (hi_same_above, search.hi] throws the set of search.hi (infinity: not known), and every
  // radius from search.lo up to the smallest distance within `best` throws `best`. When the two meet, no
  // radius between keeps another count: on a grid or the pixels of a picture the count jumps over `count` at
  // one distance, and the bracket used to shrink around it until no double was left between its ends (all 60
  // steps; now 6-12 throws on grids and pictures). Distances equal in exact arithmetic (a grid 0.1 apart,
  // pixels far from the origin) differ in their last bits: they count as one within 2^-40 relative, plus
  // 2^-48 of the largest coordinate magnitude in units of sigma_position.
  double hi_same_above = std::numeric_limits<double>::infinity();
  double conflict = 0;  // throw_darts()' largest conflict of the last throw
  // Both bounds cost time (15 % more instructions on white noise, 50k -> 10k, when computed at every throw)
  // and only help where the count jumps: they are computed from the first throw that keeps as many as the
  // end it replaces (as every throw between the two sides of one jump does) on; 2-6 % more then.
  bool jumps = false;
  // (On the torus the distances are taken of coordinates in [0, period).)
  const double same_distance_absolute =
      0x1p-48 *
      (options.darts.periodic ? internal::largest_period(
                                    internal::torus_period<Traits::dimension>(options.darts.period, true, fn))
                              : S.magnitude()) /
      options.darts.sigma_position / widest_shape;
  // `best` has a pair this close (infinity: not searched yet): a lower threshold needs no new search while
  // it lies below.
  double best_has_pair_at = std::numeric_limits<double>::infinity();
  // True when the count jumps over `count` between the bracket's ends, then with best_radius the smallest
  // distance within `best` (at least hi_same_above's rounding neighbour); the search of that distance stops
  // at the first pair that is closer (nearly always the first few, while the bracket is wide).
  const auto one_jump = [&]() {
    if (search.kept_lo == 0 || !std::isfinite(hi_same_above)) return false;
    const double threshold = (hi_same_above - same_distance_absolute) / (1 + 0x1p-40);
    if (best_has_pair_at < threshold) return false;
    const double separation = internal::throw_separation(S, best, hi_same_above, quiet, threshold);
    if (!(separation >= threshold)) {
      best_has_pair_at = separation;
      return false;
    }
    best_radius = std::max(best_radius, separation);
    return true;
  };
  if (!std::isfinite(search.hi)) {
    // The exponential form overflows for far-apart features: start from the largest finite distance from item
    // 0 and double until a throw keeps at most `count` items (or the radius overflows: no bracket).
    const double finite_largest = internal::with_metric(quiet, [&](const auto& m) {
      double r = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double v = m(S.squared_distance(0, i), S.squared_feature_distance(0, i));
        if (std::isfinite(v)) r = std::max(r, v);
      }
      return r / pair_shape;
    });
    // Items that never conflict (another colour at an infinite distance) can make `count` unreachable: then
    // the first `count` items of the throw at the largest finite radius tried.
    search.hi = finite_largest > 0 ? 2 * finite_largest : 1.0;
    while (std::isfinite(search.hi)) {
      // Up to about 2000 throws when classes never conflict (a 512 x 512 picture: 44 s); each is a chance to
      // stop (at fraction 0: the bisection's share is not known yet).
      if (!FeatureRecon::internal::report_progress(options.darts.progress, 0.0)) {
        result.status = Status::interrupted;
        return result;
      }
      std::vector<std::uint32_t> kept = internal::throw_darts(S, search.hi, quiet, order, interrupted);
      if (kept.size() <= count) {
        search.kept_hi = double(kept.size());
        break;
      }
      search.lo = best_radius = search.hi;
      search.kept_lo = double(kept.size());
      best = std::move(kept);
      search.hi *= 2;
    }
  }
  // Shrinking `search.hi` (halving, or the smaller r^-2 guess) until a throw keeps more than `count` items
  // (the bracket's lower end) is not counted as a search step: with few steps (max_iterations 3 on 5000
  // points, count 200) no bracket was found and the result was the first items of the visiting order at
  // radius 0, labelled degenerate. At most 64 halvings go uncounted (a radius 2^-64 of the largest distance):
  // more duplicates than `count` distinct positions keep too few at every radius above 0, and halving down to
  // 0 took about 1078 throws (18 times the 60 steps).
  std::size_t uncounted = 0;
  // Progress: how far the log count ratio ln(kept_lo / kept_hi) of the bracket has shrunk from that of the
  // first bracket towards 1 / count, on a log scale (below 0.99), or the share of max_iterations used if
  // more. Most searches end after 6-17 of the 60 steps, and the steps' share alone showed 10-20 % until the
  // jump to 100 %.
  double first_spread = 0, shown = 0;
  const auto fraction = [&](std::size_t it) {
    double f = double(it) / double(options.max_iterations);
    if (search.kept_lo > 0 && search.kept_hi > 0 && search.kept_lo > search.kept_hi) {
      const double spread = std::log(search.kept_lo / search.kept_hi);
      if (first_spread == 0) first_spread = spread;
      // The ratio shrinks from first_spread to about 1 / count (counts next to the goal) at the end.
      const double steps = std::log(first_spread * double(count));
      if (steps > 0) f = std::max(f, std::min(0.99, std::log(first_spread / spread) / steps));
    }
    shown = std::max(shown, f);
    return shown;
  };
  for (std::size_t it = 0; it < options.max_iterations;) {
    if (!FeatureRecon::internal::report_progress(options.darts.progress, fraction(it))) {
      result.status = Status::interrupted;
      return result;
    }
    // A lower end keeps more than `count` items, an upper one at most `count`: the goal lies between.
    double mid = search.next(double(count) + double(surplus) / 2 + 0.5);  // the window's middle
    if (!guessed && options.initial_radius > search.lo && options.initial_radius < search.hi)
      mid = options.initial_radius;
    guessed = true;
    if (!(mid > search.lo && mid < search.hi)) break;
    std::vector<std::uint32_t> kept =
        internal::throw_darts(S, mid, quiet, order, interrupted, jumps ? &conflict : nullptr);
    if (kept.size() >= count && kept.size() - count <= surplus) {
      best = std::move(kept);
      best_radius = mid;
      break;
    }
    const bool more = kept.size() > count;
    const bool same_count = double(kept.size()) == (more ? search.kept_lo : search.kept_hi);
    search.record(mid, double(kept.size()), more);
    if (more) {
      best = std::move(kept);
      best_radius = mid;
      best_has_pair_at = std::numeric_limits<double>::infinity();
    } else {
      hi_same_above = jumps ? conflict : std::numeric_limits<double>::infinity();
    }
    if (jumps && one_jump()) break;
    jumps = jumps || same_count;
    // Only steps that halved the bracket count towards the 64 (the others alternate with halvings).
    if (search.lo > 0 || (search.halved && ++uncounted > 64)) ++it;
  }
  if (best.size() < count) {
    // No radius keeps `count` items (duplicates: a repeated position conflicts at any radius > 0; or all
    // items at one position): the first `count` items of the visiting order, at radius 0.
    best.assign(order.begin(), order.begin() + std::ptrdiff_t(count));
    best_radius = 0;
    result.status = Status::degenerate_input;
  }
  if (options.cut) best.resize(count);  // the first `count` accepted items when the hit was not exact
  std::sort(best.begin(), best.end());
  (void)FeatureRecon::internal::report_progress(options.darts.progress, 1.0);
  for (const std::uint32_t i : best) *result.out++ = i;
  result.selected = best.size();
  result.radius = best_radius;
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_BILATERAL_DART_THROWING_H
