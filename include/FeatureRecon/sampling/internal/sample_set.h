// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_SAMPLE_SET_H
#define FEATURERECON_SAMPLING_INTERNAL_SAMPLE_SET_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/traits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace sampling {
namespace internal {

/// \cond
/// True when a scale's square is a normal double: distances divided by it neither overflow nor divide by zero
/// (a sigma of 1e-160 squared is 0, and darts then never stopped).
inline bool is_usable_scale(double sigma) { return sigma >= 1e-150 && sigma <= 1e150; }

/// A coordinate on the torus of period `period` (default: the unit torus), in [0, period): x - floor(x) on
/// the unit torus, else fmod(x, period) (exact) moved up by one period when negative. A tiny negative x
/// (-1e-20) wraps to the period itself in floating point and is taken as 0, the same point of the torus, and
/// so is the -0 that fmod gives for -0 and negative multiples of the period.
inline double torus_coordinate(double x, double period = 1) {
  double t = period == 1 ? x - std::floor(x) : std::fmod(x, period);
  if (t < 0) t += period;
  return t > 0 && t < period ? t : 0.0;
}

/// An array of D copies of v.
template <std::size_t D>
constexpr std::array<double, D> filled_array(double v) {
  std::array<double, D> a{};
  for (std::size_t k = 0; k < D; ++k) a[k] = v;
  return a;
}

/// The periods of the torus the options of a discrete sampler or of sampling_quality() describe: 1 along
/// every axis when `period` is empty, else its D values. Throws std::invalid_argument (naming `fn`) for a
/// period given without `periodic`, one of another length than the positions' dimension, or a value outside
/// [1e-150, 1e150] (naming its index), or periods whose product overflows or vanishes.
template <std::size_t D>
std::array<double, D> torus_period(const std::vector<double>& period, bool periodic, const char* fn) {
  if (period.empty()) return filled_array<D>(1.0);
  if (!periodic)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "period is given (", period.size(),
        " values) but periodic is false: set periodic, or leave period empty");
  if (period.size() != D)
    FeatureRecon::internal::throw_invalid_argument(fn, "period has ", period.size(),
                                                   " values for positions of dimension ", D,
                                                   " (one per axis, or none for the unit torus)");
  std::array<double, D> out{};
  double measure = 1;
  for (std::size_t k = 0; k < D; ++k) {
    if (!is_usable_scale(period[k]))
      FeatureRecon::internal::throw_invalid_argument(fn, "period[", k, "] must be in [1e-150, 1e150], got ",
                                                     period[k]);
    out[k] = period[k];
    measure *= period[k];
  }
  // The torus's measure (area, volume) stands for the domain's: it must neither overflow nor vanish.
  if (!(measure >= std::numeric_limits<double>::min() && measure <= std::numeric_limits<double>::max()))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the product of the periods (the torus's measure) must be a finite normal number, got ", measure);
  return out;
}

/// The largest of the periods (the coordinate magnitude of positions on the torus).
template <std::size_t D>
double largest_period(const std::array<double, D>& period) {
  return *std::max_element(period.begin(), period.end());
}

/// The measure (area, volume) of the torus: the product of its periods (1, the unit torus's, for none).
template <class Periods>
double torus_measure(const Periods& period) {
  double m = 1;
  for (const double p : period) m *= p;
  return m;
}

/// The positions modulo the periods (torus_coordinate() of every coordinate; default: the unit torus).
template <std::size_t D>
std::vector<std::array<double, D>> torus_positions(
    std::vector<std::array<double, D>> positions,
    const std::array<double, D>& period = filled_array<D>(1.0)) {
  for (auto& p : positions)
    for (std::size_t k = 0; k < D; ++k) p[k] = torus_coordinate(p[k], period[k]);
  return positions;
}

/// Squared distance of a and b on the torus of the periods (default: the unit torus; coordinates in [0,
/// period), as torus_coordinate() gives them): each coordinate difference d counts as min(|d|, period - |d|),
/// the nearest image.
template <std::size_t D>
double torus_squared_distance(const std::array<double, D>& a, const std::array<double, D>& b,
                              const std::array<double, D>& period = filled_array<D>(1.0)) {
  double sum = 0;
  for (std::size_t k = 0; k < D; ++k) {
    double d = std::abs(a[k] - b[k]);
    d = std::min(d, period[k] - d);
    sum += d * d;
  }
  return sum;
}

/// The shift s in {-1, 0, 1}^D whose image w + s period of w lies nearest p on the torus (default: the unit
/// torus), coded as the sum of (s_k + 1) 3^k: along each axis s_k = -1 when p_k - w_k > period_k / 2, +1 when
/// it is <= -period_k / 2, else 0 (decided on the one rounded difference, so that exactly one shift is chosen
/// for every pair, also at distance period_k / 2).
template <std::size_t D>
int nearest_image_shift(const std::array<double, D>& p, const std::array<double, D>& w,
                        const std::array<double, D>& period = filled_array<D>(1.0)) {
  int code = 0;
  for (std::size_t k = D; k-- > 0;) {
    const double t = p[k] - w[k], half = 0.5 * period[k];
    code = 3 * code + (t > half ? 0 : t <= -half ? 2 : 1);
  }
  return code;
}

/// The reach to build a grid of positions on a torus with, and to look it up with for_each_torus_candidate(),
/// so that every pair whose torus distance is computed below `reach` is found: the shifted queries p +- 1 and
/// their cells are rounded, and the nearest-image difference min(|d|, period - |d|) too, by up to a few ulps
/// of the coordinates (found from one side only, a pair within a few ulps of 2 r_max made the elimination's
/// weights wrap around). A relative margin of 2^-40 and an absolute one of 2^-48 times `extent`, the largest
/// coordinate magnitude (1 on the unit torus); the exact distance test still decides.
inline double torus_search_reach(double reach, double extent = 1) {
  return reach * (1 + 0x1p-40) + extent * 0x1p-48;
}

/// Calls f(j, shift) for the candidates j of a uniform grid of the positions modulo 1 (a Uniform_grid or
/// Dynamic_grid whose cells are at least `reach`) near p and, along the axes where p lies within `reach` of a
/// face of the unit cell, near its images p + s for s in {-1, 0, 1}^D (every combination of such axes);
/// `shift` codes s as nearest_image_shift() does. Every position whose nearest image lies within `reach` of p
/// is found at least once, at its nearest shift; a caller that must see each position once keeps only the
/// call whose shift is nearest_image_shift(p, position). With `low` and `period` the cell is the box [low,
/// low + period) instead, and the images lie at p + s period.
template <std::size_t D, class Grid, class F>
void for_each_torus_candidate(const Grid& grid, const std::array<double, D>& p, double reach, F&& f,
                              const std::array<double, D>& low = {},
                              const std::array<double, D>& period = filled_array<D>(1.0)) {
  int shifts = 1;
  for (std::size_t k = 0; k < D; ++k) shifts *= 3;
  for (int shift = 0; shift < shifts; ++shift) {
    std::array<double, D> q = p;
    bool needed = true;
    for (std::size_t k = 0, c = std::size_t(shift); k < D; ++k, c /= 3) {
      const int s = int(c % 3) - 1;
      needed = needed && (s == 0 || (s > 0 ? p[k] - low[k] < reach : p[k] - low[k] > period[k] - reach));
      q[k] += double(s) * period[k];
    }
    if (needed) grid.for_each_candidate(q, [&](std::uint32_t j) { f(j, shift); });
  }
}

/// `d`, a user's squared feature distance between two features that are each at a finite distance from
/// themselves (checked when they were read); throws std::invalid_argument naming both (`what_a` i, `what_b`
/// j) when it is NaN (Property_map_traits reports NaN as -1) or negative: such a pair was silently a
/// conflict, or never one. A cosine rounded above 1 under acos() is the usual cause.
inline double checked_feature_distance(double d, const char* fn, const char* what_a, std::size_t i,
                                       const char* what_b, std::size_t j) {
  if (!(d >= 0))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the squared feature distance between ", what_a, " ", i, " and ", what_b, " ", j,
        " is NaN or negative (", d, "); the traits' feature distance must be >= 0 for every pair");
  return d;
}

/// The items of a sampler's input as doubles (positions) and the traits' features, checked once.
template <class Traits>
struct Sample_set {
  static constexpr int D = Traits::dimension;
  static constexpr double max_coordinate = 1e100;
  using Point = std::array<double, D>;
  using Feature = typename Traits::Feature;
  std::vector<Point> positions;
  std::vector<Feature> features;
  typename Traits::Compute_feature_distance feature_distance;
  bool compared = true;  ///< whether features are compared (else squared_feature_distance() is 0)
  const char* fn;        ///< the sampler, named in errors

  /// `compare_features`: whether features will be compared (a finite sigma_feature); only then must each be
  /// at a finite distance from itself (checked; throws naming the item).
  template <class ItemRange>
  Sample_set(const ItemRange& items, const Traits& traits, const char* fn, bool compare_features = true)
      : feature_distance(traits.compute_feature_distance_object()), compared(compare_features), fn(fn) {
    static_assert(FeatureRecon::internal::Is_feature_point_traits<Traits>::value,
                  "FeatureRecon: the traits class is not a model of FeaturePointTraits (see "
                  "doc/concepts/FeaturePointTraits.h)");
    static_assert(D == 2 || D == 3, "FeatureRecon: the samplers take 2D or 3D positions");
    const auto construct_point = traits.construct_point_object();
    const auto construct_feature = traits.construct_feature_object();
    std::size_t i = 0;
    for (const auto& item : items) {
      const auto p = construct_point(item);
      Point q;
      for (int k = 0; k < D; ++k) {
        q[k] = CGAL::to_double(p[k]);
        if (!std::isfinite(q[k]))
          FeatureRecon::internal::throw_invalid_argument(fn, "item ", i, " has a non-finite coordinate (",
                                                         q[k], ")");
        // Squared distances, areas and volumes of the extent must stay finite doubles.
        if (!(std::fabs(q[k]) <= max_coordinate))
          FeatureRecon::internal::throw_invalid_argument(
              fn, "item ", i, " has coordinate ", q[k],
              " beyond +-1e100 (squared distances and volumes would "
              "overflow); scale the input");
      }
      positions.push_back(q);
      features.push_back(construct_feature(item));
      // A feature must be at a finite distance from itself: a zero normal or a NaN channel is not, and would
      // make every comparison with it false (never a conflict: such items were always kept).
      const double self =
          compared ? CGAL::to_double(feature_distance(features.back(), features.back())) : 0.0;
      if (!(self >= 0 && self < std::numeric_limits<double>::infinity()))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "item ", i, " has a feature at distance ",
            std::isnan(self) || self < 0 ? std::string("NaN") : std::to_string(self),
            " from itself (a zero normal, or NaN in the feature)");
      ++i;
    }
  }
  std::size_t size() const { return positions.size(); }
  /// The largest coordinate range of the positions (0 for no item or one place).
  double extent() const {
    double e = 0;
    for (int k = 0; k < D; ++k) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Point& p : positions) {
        lo = std::min(lo, p[k]);
        hi = std::max(hi, p[k]);
      }
      if (hi > lo) e = std::max(e, hi - lo);
    }
    return e;
  }
  /// The largest magnitude of a coordinate (0 for no item).
  double magnitude() const {
    double m = 0;
    for (const Point& p : positions)
      for (const double x : p) m = std::max(m, std::abs(x));
    return m;
  }
  double squared_distance(std::size_t i, std::size_t j) const {
    double s = 0;
    for (int k = 0; k < D; ++k) {
      const double d = positions[i][k] - positions[j][k];
      s += d * d;
    }
    return s;
  }
  /// The squared feature distance of items i and j; 0 when features are not compared (an infinite
  /// sigma_feature: the metrics ignore it, and the user's distance is neither paid for nor trusted there).
  /// \throws std::invalid_argument naming both items when the user's distance is NaN or negative.
  double squared_feature_distance(std::size_t i, std::size_t j) const {
    if (!compared) return 0.0;
    return checked_feature_distance(CGAL::to_double(feature_distance(features[i], features[j])), fn, "item",
                                    i, "item", j);
  }
};

/// The bound of the spatial prefilter |dp|^2 < reach^2 of the samplers' neighbour searches: reach^2, or
/// infinity (no prefilter: the metric decides) where that square underflows and pairs within reach, copies at
/// distance 0 among them, would be rejected.
inline double prefilter_bound(double reach) {
  return reach * reach >= 0x1p-960 ? reach * reach : std::numeric_limits<double>::infinity();
}

/// Checks the sigmas of the bilateral distance: each in [1e-150, 1e150], sigma_feature also infinity.
inline void check_sigmas(double sigma_position, double sigma_feature, const char* fn) {
  if (!is_usable_scale(sigma_position))
    FeatureRecon::internal::throw_invalid_argument(fn, "sigma_position must be in [1e-150, 1e150], got ",
                                                   sigma_position);
  if (!(is_usable_scale(sigma_feature) || sigma_feature == std::numeric_limits<double>::infinity()))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "sigma_feature must be in [1e-150, 1e150] (or infinity for Euclidean), got ", sigma_feature);
}

/// Checks that positions spanning `extent` are measured in units of sigma_position without overflow of the
/// squared bilateral distances: extent / sigma_position at most 2^400 (each alone was accepted, but positions
/// of 1e100 with sigma_position 1e-150 made every distance infinite, and the samplers returned arbitrary sets
/// with status success). A span far below sigma_position is degenerate geometry (all items at about one
/// place), which each sampler handles.
inline void check_position_scale(double extent, double sigma_position, const char* fn) {
  const double ratio = extent / sigma_position;
  if (!(ratio <= 0x1p400))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "sigma_position (", sigma_position, ") is too small for positions spanning ", extent,
        ": the span in units ", "of sigma_position (", ratio,
        ") must be at most 2^400 (about 2.6e120), else squared bilateral distances "
        "overflow; scale the positions or sigma_position");
}

/// Checks a domain measure (>= 0, 0 meaning automatic) and an intrinsic dimension (0, 2 or 3, at most the
/// dimension of the positions).
inline void check_domain(double measure, int intrinsic_dimension, int position_dimension, const char* fn) {
  if (!(measure >= 0 && std::isfinite(measure)))
    FeatureRecon::internal::throw_invalid_argument(fn, "domain_measure must be finite and >= 0, got ",
                                                   measure);
  if (intrinsic_dimension != 0 && intrinsic_dimension != 2 && intrinsic_dimension != 3)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "intrinsic_dimension must be 0 (automatic), 2 or 3, got ", intrinsic_dimension);
  if (intrinsic_dimension > position_dimension)
    FeatureRecon::internal::throw_invalid_argument(fn, "intrinsic_dimension ", intrinsic_dimension,
                                                   " exceeds the dimension of the positions (",
                                                   position_dimension, ")");
}

/// Checks an exact output count against the number of items.
inline void check_count(std::size_t count, std::size_t n, const char* fn) {
  if (count > n)
    FeatureRecon::internal::throw_invalid_argument(fn, "count (", count, ") exceeds the number of items (", n,
                                                   ")");
}

/// Calls f(metric) with the metric the options describe.
template <class Options, class F>
decltype(auto) with_metric(const Options& o, F&& f) {
  if (o.form == Bilateral_form::exponential)
    return f(Exponential_bilateral_metric{o.sigma_position, o.sigma_feature});
  return f(Gaussian_bilateral_metric{o.sigma_position, o.sigma_feature});
}

/// k nearest neighbours (excluding the point itself) of some 3D points, by a CGAL kd-tree.
struct Knn_3 {
  using K = CGAL::Simple_cartesian<double>;
  using Search_traits = CGAL::Search_traits_3<K>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Search_traits>;
  typename Search::Tree tree;
  explicit Knn_3(const std::vector<std::array<double, 3>>& p) {
    std::vector<K::Point_3> q;
    q.reserve(p.size());
    for (const auto& x : p) q.emplace_back(x[0], x[1], x[2]);
    tree.insert(q.begin(), q.end());
    tree.build();
  }
  /// Squared distances and points of the k nearest other points of x (x itself, at distance 0, is skipped
  /// once).
  std::vector<std::pair<double, K::Point_3>> query(const std::array<double, 3>& x, unsigned k) const {
    Search s(tree, K::Point_3(x[0], x[1], x[2]), k + 1);
    std::vector<std::pair<double, K::Point_3>> out;
    bool skipped = false;
    for (const auto& r : s) {
      if (!skipped && r.second == 0) {
        skipped = true;
        continue;
      }
      out.push_back({r.second, r.first});
    }
    if (out.size() > k) out.resize(k);
    return out;
  }
};

/// The indices of `p` sorted by position (lexicographic), copies of a position consecutive and in index
/// order.
template <std::size_t D>
std::vector<std::uint32_t> order_by_position(const std::vector<std::array<double, D>>& p) {
  // The positions sorted with their indices beside them: a sort of indices through `p` took three times as
  // long (160,000 points: 33-50 ms against 10-15 ms).
  std::vector<std::pair<std::array<double, D>, std::uint32_t>> keyed(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) keyed[i] = {p[i], static_cast<std::uint32_t>(i)};
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) order[i] = keyed[i].second;
  return order;
}

/// The distinct positions, each where it first occurs (the estimates below take them: copies are neighbours
/// at distance 0). Without copies, `p` itself.
template <std::size_t D>
std::vector<std::array<double, D>> distinct_positions(const std::vector<std::array<double, D>>& p) {
  const std::vector<std::uint32_t> order = order_by_position(p);
  std::vector<std::uint8_t> copy(p.size(), 0);
  for (std::size_t k = 1; k < order.size(); ++k) copy[order[k]] = p[order[k]] == p[order[k - 1]];
  std::vector<std::array<double, D>> out;
  out.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!copy[i]) out.push_back(p[i]);
  return out;
}

/// Moves every copy after the first (in index order) of a position by `step` along a direction fixed by its
/// index (golden-angle spiral: on the circle in 2D, on the sphere in 3D), so that coincident sites separate
/// where nothing else would move them apart. `position(i)` is a reference to the D coordinates of site i. A
/// move that would leave [lo, hi] (when given) goes the opposite way, clamped to the box (which may be
/// thinner than `step`).
template <int D, class Position>
void separate_copies(std::size_t n, double step, Position&& position,
                     const std::array<double, D>* lo = nullptr, const std::array<double, D>* hi = nullptr) {
  std::vector<std::array<double, D>> original(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) original[i][k] = position(i)[k];
  const std::vector<std::uint32_t> order = order_by_position(original);
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (original[order[k]] != original[order[k - 1]]) continue;
    const double a = 2.399963229728653 * double(order[k]);  // golden angle
    const double z = D == 3 ? std::cos(0.5 * a) : 0.0, r = std::sqrt(1 - z * z);
    std::array<double, D> offset{};
    offset[0] = step * r * std::cos(a);
    offset[1] = step * r * std::sin(a);
    if constexpr (D == 3) offset[2] = step * z;
    auto&& p = position(order[k]);
    for (int c = 0; c < D; ++c) {
      double x = original[order[k]][c] + offset[c];
      if (lo != nullptr && hi != nullptr && (x < (*lo)[c] || x > (*hi)[c]))
        x = std::min((*hi)[c], std::max((*lo)[c], original[order[k]][c] - offset[c]));
      p[c] = x;
    }
  }
}

/// Intrinsic dimension of 3D positions: 2 when at least half of up to 1000 evenly spread probes have a flat
/// neighbourhood (smallest eigenvalue of the covariance of 12 neighbours below 5 % of the trace; isotropic
/// volume samples give about 33 %), else 3.
inline int estimate_intrinsic_dimension(const std::vector<std::array<double, 3>>& p, const Knn_3& knn) {
  const std::size_t n = p.size(), probes = std::min<std::size_t>(n, 1000);
  if (n < 8) return 2;
  std::size_t flat = 0;
  for (std::size_t s = 0; s < probes; ++s) {
    const std::size_t i = s * n / probes;
    const auto nb = knn.query(p[i], 12);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& r : nb) mean += Eigen::Vector3d(r.second.x(), r.second.y(), r.second.z());
    mean /= double(nb.size());
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    for (const auto& r : nb) {
      const Eigen::Vector3d d = Eigen::Vector3d(r.second.x(), r.second.y(), r.second.z()) - mean;
      c += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(c, Eigen::EigenvaluesOnly);
    const double trace = es.eigenvalues().sum();
    if (trace <= 0 || es.eigenvalues()[0] < 0.05 * trace) ++flat;
  }
  return 2 * flat >= probes ? 2 : 3;
}

/// Area of a sampled surface: the sum over the points of the area of the disc reaching their 8th nearest
/// neighbour, divided by 8 (unbiased for uniform samples).
inline double estimate_surface_area(const std::vector<std::array<double, 3>>& p, const Knn_3& knn) {
  double a = 0;
  for (const auto& x : p) {
    const auto nb = knn.query(x, 8);
    if (!nb.empty()) a += 3.14159265358979323846 * nb.back().first / 8.0;
  }
  return a;
}

/// Measure of the bounding box (area or volume), at least the smallest positive double.
template <int D>
double bounding_box_measure(const std::vector<std::array<double, D>>& p) {
  if (p.empty()) return 0;
  std::array<double, D> lo = p[0], hi = p[0];
  for (const auto& x : p)
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  double m = 1;
  for (int k = 0; k < D; ++k) m *= hi[k] - lo[k];
  return m;
}

/// Affine dimension of the positions (0 for one position, 1 collinear, 2 coplanar, else D), decided by
/// Epick's exact orientation predicates on the positions as doubles, and the longest distance from the first
/// point (for collinear input: at least half the length of the segment they span).
template <int D>
int affine_dimension(const std::vector<std::array<double, D>>& p) {
  using Epick = CGAL::Epick;
  if (p.empty()) return 0;
  auto P2 = [&](std::size_t i) { return Epick::Point_2(p[i][0], p[i][1]); };
  auto P3 = [&](std::size_t i) { return Epick::Point_3(p[i][0], p[i][1], D == 3 ? p[i][D - 1] : 0.0); };
  std::size_t b = p.size();
  for (std::size_t i = 1; i < p.size() && b == p.size(); ++i)
    if (p[i] != p[0]) b = i;
  if (b == p.size()) return 0;
  std::size_t c = p.size();
  for (std::size_t i = b + 1; i < p.size() && c == p.size(); ++i) {
    if constexpr (D == 2) {
      if (!CGAL::collinear(P2(0), P2(b), P2(i))) c = i;
    } else {
      if (!CGAL::collinear(P3(0), P3(b), P3(i))) c = i;
    }
  }
  if (c == p.size()) return 1;
  if constexpr (D == 2) {
    return 2;
  } else {
    for (std::size_t i = c + 1; i < p.size(); ++i)
      if (!CGAL::coplanar(P3(0), P3(b), P3(c), P3(i))) return 3;
    return 2;
  }
}

/// Length of the segment spanned by collinear positions (two sweeps of farthest points).
template <int D>
double collinear_length(const std::vector<std::array<double, D>>& p) {
  auto farthest = [&](const std::array<double, D>& a) {
    std::size_t best = 0;
    double d = -1;
    for (std::size_t i = 0; i < p.size(); ++i) {
      double s = 0;
      for (int k = 0; k < D; ++k) s += (p[i][k] - a[k]) * (p[i][k] - a[k]);
      if (s > d) {
        d = s;
        best = i;
      }
    }
    return std::make_pair(best, std::sqrt(d));
  };
  if (p.empty()) return 0;
  return farthest(p[farthest(p[0]).first]).second;
}

/// r_max of Yuksel (2015): the radius of the densest packing of `count` discs (hexagonal) or balls (FCC).
inline double packing_radius(double measure, std::size_t count, int intrinsic_dimension) {
  if (intrinsic_dimension == 2) return std::sqrt(measure / (2 * std::sqrt(3.0) * double(count)));
  return std::cbrt(measure / (4 * std::sqrt(2.0) * double(count)));
}
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_SAMPLE_SET_H
