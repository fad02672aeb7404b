// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_SAMPLING_QUALITY_H
#define FEATURERECON_SAMPLING_SAMPLING_QUALITY_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/sampling/internal/periodogram.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/traits.h>

#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// Options of sampling_quality().
struct Sampling_quality_options {
  double sigma_position = 1;  ///< spatial scale of the metric; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  Bilateral_form form = Bilateral_form::gaussian;  ///< form of the bilateral distance
  /// Area (2D) or volume (3D) of the domain. Default 0: the bounding box of the samples (or the torus when
  /// `periodic`: the unit square / cube, or the product of `period`); for 3D positions with
  /// intrinsic_dimension 2, the area of the surface they sample, estimated as weighted_sample_elimination()
  /// estimates it (discs reaching the 8th nearest neighbour).
  double domain_measure = 0;
  /// 2 (images, surfaces) or 3 (volumes). Default 0: the dimension of the positions.
  int intrinsic_dimension = 0;
  /// Distances on the unit torus [0, 1)^d (positions are taken modulo 1; or on the torus of `period`), as the
  /// point-set analysis tools of Heck, Schlömer and Deussen measure them; default false.
  bool periodic = false;
  /// With `periodic`, the torus [0, period[0]) x [0, period[1]) (x [0, period[2])) instead of the unit one
  /// (positions modulo the periods; without domain_measure its measure is their product): one value per axis,
  /// each in [1e-150, 1e150] and their product a finite normal number. Default empty: the unit torus. Given
  /// without `periodic`, refused.
  std::vector<double> period;
  /// Fraction of the samples measured, every 4096 samples (the periodic search, when repeated with a wider
  /// band, counts its second pass in the second half); returning false stops: the statistics stay 0 and the
  /// status is interrupted.
  Progress_callback progress;
};

/// Spacing statistics of a sample set (Lagae and Dutré 2008; Schlömer's PSA conventions).
struct Sampling_quality {
  std::size_t samples = 0;    ///< number of samples N
  double domain_measure = 0;  ///< the area or volume used: the option's, or the default it stands for
  /// d_hex: nearest distance of the densest packing of N points (hexagonal in 2D, FCC in 3D); 0 (not
  /// computed) when the status is degenerate_input.
  double hexagonal_distance = 0;
  /// smallest nearest-neighbour (bilateral) distance; 0 (not computed) when degenerate
  double minimum_distance = 0;
  double relative_radius = 0;  ///< rho = minimum_distance / d_hex (1 for the hexagonal lattice)
  /// mean nearest-neighbour distance / d_hex (about 0.466 for white noise in 2D)
  double average_minimum_distance = 0;
  /// degenerate_input for fewer than two samples, a domain of zero measure or samples of lower affine
  /// dimension (collinear, coplanar); interrupted when the progress callback stopped the run (statistics 0)
  Status status = Status::success;
};

/// Nearest-neighbour statistics of a sample set: the relative radius rho = d_min / d_hex and the average
/// minimum distance, both relative to the nearest distance d_hex of the densest packing of N points in the
/// domain (d_hex = sqrt(2 A / (sqrt(3) N)) in 2D, cbrt(sqrt(2) V / N) in 3D). With a finite sigma_feature the
/// distances are bilateral (in units of xi times sigma_position), which measures spacing in the stacked
/// space. Nearest neighbours are found exactly with a CGAL kd-tree over the distinct positions: Euclidean
/// (infinite sigma_feature), its two nearest places; bilateral, visiting samples by increasing spatial
/// distance until it exceeds the best bilateral distance (O(n log n) in practice, also for sparse or
/// clustered sets, while features follow position; where they do not, e.g. random normals on a plane with a
/// sigma_feature small against sigma_position, each sample visits every sample within its bilateral
/// distance in space: 10,000 / 20,000 / 40,000 such samples took 4 / 14 / 58 s in session 65's audit).
/// \tparam ItemRange a forward range of `Traits::Item`. \tparam Traits a model of FeaturePointTraits.
/// \throws std::invalid_argument for non-finite coordinates (naming the item), sigma_position <= 0,
///   sigma_feature <= 0, a negative domain_measure, an intrinsic_dimension other than 0, 2 or 3 or above the
///   positions' dimension, a `period` given without `periodic`, of another length than the positions'
///   dimension or with a value outside [1e-150, 1e150] (naming the index), or with a finite sigma_feature a
///   feature at a non-finite distance from itself (a zero normal; naming the item).
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Sampling_quality sampling_quality(const ItemRange& items, const Sampling_quality_options& options = {},
                                  const Traits& traits = Traits()) {
  const char* fn = "sampling_quality";
  internal::check_sigmas(options.sigma_position, options.sigma_feature, fn);
  internal::check_domain(options.domain_measure, options.intrinsic_dimension, Traits::dimension, fn);
  internal::Sample_set<Traits> S(items, traits, fn, std::isfinite(options.sigma_feature));
  internal::check_position_scale(S.extent(), options.sigma_position, fn);
  constexpr int D = Traits::dimension;
  const std::size_t n = S.size();
  Sampling_quality q;
  q.samples = n;
  const std::array<double, D> period = internal::torus_period<D>(options.period, options.periodic, fn);
  if (options.periodic) S.positions = internal::torus_positions(std::move(S.positions), period);
  const int dim = options.intrinsic_dimension == 0 ? D : options.intrinsic_dimension;
  const int affine = internal::affine_dimension<D>(S.positions);
  double measure = options.domain_measure;
  if (measure == 0 && options.periodic) measure = internal::torus_measure(period);
  if constexpr (D == 3) {
    // A surface in space: its area, not the volume of its bounding box (which read a flat grid as measure 0
    // and a wall 0.5 thick as 185 for an area of 524). Estimated on the distinct positions: copies would be
    // neighbours at distance 0.
    if (measure == 0 && dim == 2 && affine >= 2) {
      const std::vector<std::array<double, 3>> places = internal::distinct_positions(S.positions);
      measure = internal::estimate_surface_area(places, internal::Knn_3(places));
    }
  }
  if (measure == 0) measure = internal::bounding_box_measure<D>(S.positions);
  q.domain_measure = measure;
  if (n < 2 || !(measure > 0) || affine < dim) {
    q.status = Status::degenerate_input;
    return q;
  }
  q.hexagonal_distance = dim == 2 ? std::sqrt(2 * measure / (std::sqrt(3.0) * double(n)))
                                  : std::cbrt(std::sqrt(2.0) * measure / double(n));
  // Periodic images of the points within `band` of the faces of the torus's cell (at most half a period),
  // so the tree sees the torus. The search is exact when every nearest distance found stays below the band
  // (the images within that distance of a point in the cell are then all in the tree); otherwise it is
  // repeated with half of every period, which holds every nearest image. Returns the largest nearest
  // distance, or -1 when the callback stopped the pass.
  const auto measure_with_band = [&](double band, double from, double to) {
    double farthest = 0;
    std::vector<std::array<double, D>> points = S.positions;
    std::vector<std::size_t> source(n);
    for (std::size_t i = 0; i < n; ++i) source[i] = i;
    if (options.periodic) {
      int offsets = 1;
      for (int k = 0; k < D; ++k) offsets *= 3;
      for (std::size_t i = 0; i < n; ++i)
        for (int o = 0; o < offsets; ++o) {  // every shift in {-1, 0, 1}^d but zero
          std::array<double, D> p = S.positions[i];
          bool inside = true, zero = true;
          for (int k = 0, c = o; k < D; ++k, c /= 3) {
            p[k] += double(c % 3 - 1) * period[std::size_t(k)];
            zero = zero && c % 3 == 1;
            const double reach = std::min(band, 0.5 * period[std::size_t(k)]);
            inside = inside && p[k] > -reach && p[k] < period[std::size_t(k)] + reach;
          }
          if (!zero && inside) {
            points.push_back(p);
            source.push_back(i);
          }
        }
    }
    internal::with_metric(options, [&](const auto& metric) {
      const double scale = metric.spatial_scale();
      // Nearest neighbours from a CGAL kd-tree (sliding midpoint: clusters and isolated samples alike),
      // visited by increasing spatial distance until it exceeds the best bilateral distance so far (xi >= the
      // spatial distance) or that is 0, so the minimum is exact.
      using Kd_kernel = CGAL::Simple_cartesian<double>;
      using Kd_point = std::conditional_t<D == 2, Kd_kernel::Point_2, Kd_kernel::Point_3>;
      using Base_traits =
          std::conditional_t<D == 2, CGAL::Search_traits_2<Kd_kernel>, CGAL::Search_traits_3<Kd_kernel>>;
      using Traits_with_index =
          CGAL::Search_traits_adapter<std::uint32_t, typename CGAL::Pointer_property_map<Kd_point>::type,
                                      Base_traits>;
      using Incremental = CGAL::Orthogonal_incremental_neighbor_search<Traits_with_index>;
      // The tree holds the distinct places, each with its points (place k: at[start[k], start[k + 1])): a
      // kd-tree peels one copy of a point per level, so c copies cost O(c^2) to build and 40,000 of them
      // overflowed the stack. Without copies the places are the points, in their order (place k is point k:
      // the indirection cost white noise a third more time).
      std::vector<std::uint32_t> at = internal::order_by_position(points);
      std::size_t copies = 0;
      for (std::size_t j = 1; j < at.size(); ++j) copies += points[at[j]] == points[at[j - 1]];
      std::vector<std::size_t> start;
      std::vector<Kd_point> kd_points;
      auto kd_point = [](const auto& p) {
        if constexpr (std::tuple_size<std::decay_t<decltype(p)>>::value == 2)
          return Kd_point(p[0], p[1]);
        else
          return Kd_point(p[0], p[1], p[2]);
      };
      if (copies == 0) {
        at.clear();
        for (const auto& p : points) kd_points.push_back(kd_point(p));
      } else {
        for (std::size_t j = 0; j < at.size(); ++j)
          if (j == 0 || points[at[j]] != points[at[j - 1]]) {
            start.push_back(j);
            kd_points.push_back(kd_point(points[at[j]]));
          }
        start.push_back(at.size());
      }
      std::vector<std::uint32_t> keys(kd_points.size());
      for (std::size_t j = 0; j < keys.size(); ++j) keys[j] = static_cast<std::uint32_t>(j);
      typename Incremental::Tree tree(keys.begin(), keys.end(), typename Incremental::Tree::Splitter(),
                                      Traits_with_index(CGAL::make_property_map(kd_points)));
      tree.build();
      typename Incremental::Distance tree_distance(CGAL::make_property_map(kd_points));
      auto xi = [&](std::size_t i, std::size_t j_point) {
        double d2 = 0;
        for (int k = 0; k < D; ++k) {
          const double d = S.positions[i][k] - points[j_point][k];
          d2 += d * d;
        }
        return metric(d2, S.squared_feature_distance(i, source[j_point])) * scale;
      };
      // Euclidean (infinite sigma_feature): the nearest other point is in one of the two nearest places (its
      // own, at distance 0, and the next). The tree sums the same squared coordinate differences in the same
      // order as xi(), so it ranks the candidates as xi() does. A k-nearest search costs a quarter of the
      // incremental one, which the bilateral distance needs. On the torus the tree also holds the point's own
      // images, a period or more away, and at most 2^d - 1 of them (one shift per axis lies within half a
      // period of the cell): they are skipped, and when they can be nearer than another point (a period
      // shorter than the torus's half diagonal, which bounds every nearest distance) the search takes 2^d + 1
      // neighbours.
      double half_diagonal2 = 0, shortest = std::numeric_limits<double>::infinity();
      for (const double p : period) {
        half_diagonal2 += 0.25 * p * p;
        shortest = std::min(shortest, p);
      }
      const unsigned neighbours =
          options.periodic && !(half_diagonal2 < shortest * shortest) ? (1u << D) + 1 : 2;
      using Nearest = CGAL::Orthogonal_k_neighbor_search<Traits_with_index>;
      const bool euclidean = std::isinf(options.sigma_feature);
      double minimum = std::numeric_limits<double>::infinity(), sum = 0;
      farthest = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (i % 4096 == 0 && !FeatureRecon::internal::report_progress(
                                 options.progress, from + (to - from) * double(i) / double(n))) {
          farthest = -1;
          return;
        }
        double best = std::numeric_limits<double>::infinity();
        // The points of place k other than i (and its images) as candidates; none is nearer than 0.
        auto measure_place = [&](std::size_t k) {
          if (copies == 0) {
            if (source[k] != i) best = std::min(best, xi(i, k));
            return;
          }
          for (std::size_t j = start[k]; j < start[k + 1] && best > 0; ++j)
            if (source[at[j]] != i) best = std::min(best, xi(i, at[j]));
        };
        const Kd_point query = copies == 0 ? kd_points[i] : kd_point(S.positions[i]);
        if (euclidean) {
          Nearest search(tree, query, neighbours, 0.0, true, tree_distance);
          for (auto it = search.begin(); it != search.end(); ++it) measure_place(it->first);
        } else {
          Incremental search(tree, query, 0.0, true, tree_distance);
          for (auto it = search.begin(); it != search.end() && best > 0; ++it) {
            // it->second: squared spatial distance (rounded; the margin covers it)
            if (std::sqrt(it->second) > best * (1 + 1e-9)) break;
            measure_place(it->first);
          }
        }
        minimum = std::min(minimum, best);
        farthest = std::max(farthest, best);
        sum += best;
      }
      q.minimum_distance = minimum;
      q.average_minimum_distance = sum / double(n) / q.hexagonal_distance;
      q.relative_radius = minimum / q.hexagonal_distance;
    });
    return farthest;
  };
  // The first band: twice d_hex, unless that reaches half of the shortest period (then every nearest image).
  const double half = 0.5 * *std::min_element(period.begin(), period.end());
  const double band = std::min(half, 2 * q.hexagonal_distance);
  const double all = std::numeric_limits<double>::infinity();  // half of every period
  const bool partial = options.periodic && band < half;
  double farthest = measure_with_band(options.periodic ? (partial ? band : all) : 0, 0, partial ? 0.5 : 1);
  if (farthest >= 0 && partial && !(farthest * (1 + 1e-9) < band)) farthest = measure_with_band(all, 0.5, 1);
  if (farthest < 0) {
    Sampling_quality stopped;
    stopped.samples = n;
    stopped.domain_measure = measure;
    stopped.status = Status::interrupted;
    return stopped;
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return q;
}

/// How sampling_spectrum() evaluates the periodogram's sums.
enum class Spectrum_method {
  automatic,  ///< the faster of the two for the number of samples and frequencies (gridded from about 200
              ///< samples at the default F)
  direct,     ///< every exponential summed: O(N F^2), exact to rounding
  /// a non-uniform FFT (Gaussian gridding on a grid twice as fine, Greengard and Lee 2004): O(N + F^2 log F),
  /// the sums to about 2e-11 N (clustered samples; 2e-13 N spread)
  gridded
};

/// Options of sampling_spectrum().
struct Sampling_spectrum_options {
  /// Largest integer frequency per axis of the periodogram (on another torus than the unit one, the last
  /// annulus: see `period`). Default 0: 6 sqrt(N) (rounded up), that is 12 in units of sqrt(N)/2, which holds
  /// the oscillation band of Heck et al. (10 units from where the power first reaches 1) for every set whose
  /// power reaches 1 below 2 units (any blue-noise set). At most 16384: the periodogram holds (2 F + 1)(F +
  /// 1) complex sums (8.6 GB at 16384; the gridded method needs about twice that); on a torus of aspect ratio
  /// r, (2 K + 1)(K + 1) with K = (F + 1/2) sqrt(r), at most 16384.
  std::size_t max_frequency = 0;
  /// Level of the mean power over a disc of frequencies that ends the zero region (Heck et al.: 0.1, -10 dB).
  double threshold = 0.1;
  Spectrum_method method = Spectrum_method::automatic;  ///< how the sums are evaluated
  /// The torus [0, W) x [0, H) of the samples, {W, H} (tiles of a W x H picture), instead of the unit one:
  /// positions modulo W and H, and frequencies (k_x / W, k_y / H) for integers k_x, k_y, measured as on the
  /// torus scaled to area 1, g = sqrt(W H) (k_x / W, k_y / H): annuli of width 1 in g (annulus k: round(|g|)
  /// = k), nu_N = sqrt(N)/2 in g, and annuli 0..`max_frequency` complete. Annulus 0 holds DC alone: on a
  /// torus of aspect ratio r = max(W/H, H/W) above 4 the few other frequencies with |g| < 1/2 count in
  /// annulus 1. A set scaled with its torus keeps its spectrum, and a square lattice has nu_eff 1 on any
  /// torus it tiles. The sums are those of the square up to K = (F + 1/2) sqrt(r) (r times the square's work
  /// and memory), K at most 16384. Each in [1e-150, 1e150] and their product a finite normal number. Default
  /// empty: the unit torus.
  std::vector<double> period;
  Progress_callback progress;  ///< fraction of the work done; returning false stops (empty result)
};

/// Fourier statistics of a 2D sample set on the unit torus (positions modulo 1; or on the torus of
/// Sampling_spectrum_options::period), as the point-set analysis of Lagae and Dutre (2008) and Heck,
/// Schloemer and Deussen (2013) defines them. Frequencies are in units of nu_N = sqrt(N)/2, the Nyquist
/// frequency of a square lattice of N points (the point-set analysis tool's unit), on the torus scaled to
/// area 1.
struct Sampling_spectrum {
  std::size_t samples = 0;           ///< N
  std::vector<double> frequency;     ///< annulus k (k = 0, 1, ...): integer radius k, in units of nu_N
  std::vector<double> radial_power;  ///< radially averaged periodogram per annulus (white noise: 1)
  std::vector<double> anisotropy;    ///< 10 log10(variance / mean^2) of the periodogram in each annulus (dB)
  std::vector<std::size_t> annulus_size;  ///< number of integer frequencies f with round(|f|) = k
  /// Effective Nyquist frequency nu_eff (Heck et al.): half the radius nu* of the largest disc of
  /// frequencies, centred on 0 and without the DC term, whose mean power stays below `threshold`, taken below
  /// the first radius of at least one unit where that mean exceeds 0.5 (interpolated between annuli). In
  /// units of nu_N, so a square lattice has nu_eff = 1 and white noise nu_eff = 0.
  double effective_nyquist = 0;
  /// Oscillation Omega (Heck et al.): 10 times the root mean square of P - 1 over the ring of frequencies
  /// from `oscillation_from` (the first annulus after DC where the radial power reaches 0.98) to
  /// `oscillation_to` (10 units further, or the end of the spectrum when that comes first), weighted by area.
  /// A sampling that is flat beyond its zero region has Omega near 0; a lattice-like one has large Omega.
  double oscillation = 0;
  double oscillation_from = 0;      ///< start of the oscillation band, units of nu_N
  double oscillation_to = 0;        ///< end of the oscillation band, units of nu_N
  Status status = Status::success;  ///< degenerate_input for fewer than two samples; interrupted when stopped
  /// how the sums were evaluated (automatic resolved; automatic when nothing was evaluated)
  Spectrum_method method = Spectrum_method::automatic;
};

namespace internal {
/// \cond
inline void check_spectrum_threshold(double threshold, const char* fn) {
  if (!(threshold > 0 && threshold < 0.5))  // 0.5 is the level that ends the search for the zero region
    FeatureRecon::internal::throw_invalid_argument(fn, "threshold must lie in (0, 0.5), got ", threshold);
}

/// The largest frequency F of a periodogram of n samples: `max_frequency`, or by default 6 sqrt(n) rounded
/// up, refused above 16384 (more than 7,456,540 samples; sums of 11 GB and more).
inline long spectrum_frequency(std::size_t n, std::size_t max_frequency, const char* fn) {
  if (max_frequency != 0) return static_cast<long>(max_frequency);  // checked by the caller
  const long F = static_cast<long>(std::ceil(6 * std::sqrt(double(n))));
  if (F > 16384)
    FeatureRecon::internal::throw_invalid_argument(fn, "the default max_frequency 6 sqrt(N) is ", F, " for ",
                                                   n, " samples, above the limit 16384: give max_frequency");
  return F;
}

/// Effective Nyquist frequency and oscillation (Heck, Schloemer and Deussen 2013) from the radial power and
/// the annulus sizes.
inline void finish_spectrum(Sampling_spectrum& s, double threshold) {
  const std::size_t bins = s.radial_power.size();
  const double nu = std::sqrt(double(s.samples)) / 2;
  s.effective_nyquist = s.oscillation = s.oscillation_from = s.oscillation_to = 0;
  if (bins < 2 || nu == 0 || s.annulus_size.size() != bins) return;
  // disc[k]: mean power over the frequencies of annuli 1..k, the disc of radius k + 1/2 without DC.
  std::vector<double> disc(bins, 0.0);
  double power = 0, count = 0;
  for (std::size_t b = 1; b < bins; ++b) {
    power += s.radial_power[b] * double(s.annulus_size[b]);
    count += double(s.annulus_size[b]);
    disc[b] = count > 0 ? power / count : 0.0;
  }
  // The first disc of radius >= 1 unit with mean power above 0.5, then down to the last one below threshold.
  std::size_t high = bins;
  for (std::size_t b = 1; b < bins; ++b)
    if (double(b) + 0.5 >= nu && disc[b] > 0.5) {
      high = b;
      break;
    }
  double radius = 0;  // nu* in integer frequency
  if (high == bins) {
    radius = double(bins) - 0.5;  // the whole spectrum is quiet: a lower bound
  } else {
    std::size_t b = high;
    while (b > 0 && disc[b] >= threshold) --b;
    if (b > 0) {
      // disc[b] < threshold <= disc[b + 1]: interpolate the radius between b + 1/2 and b + 3/2.
      const double t = (threshold - disc[b]) / (disc[b + 1] - disc[b]);
      radius = double(b) + 0.5 + std::min(1.0, std::max(0.0, t));
    }
  }
  s.effective_nyquist = radius / nu / 2;
  // Oscillation over the ring from the first annulus reaching 0.98 to 10 units beyond it.
  std::size_t from = bins;
  for (std::size_t b = 1; b < bins; ++b)
    if (s.radial_power[b] >= 0.98) {
      from = b;
      break;
    }
  if (from == bins) return;
  const std::size_t to = std::min(bins - 1, from + static_cast<std::size_t>(std::ceil(10 * nu)));
  double deviation = 0, area = 0;
  for (std::size_t b = from; b <= to; ++b) {
    const double d = s.radial_power[b] - 1, a = double(s.annulus_size[b]);
    deviation += d * d * a;
    area += a;
  }
  s.oscillation = area > 0 ? 10 * std::sqrt(deviation / area) : 0.0;
  s.oscillation_from = double(from) / nu;
  s.oscillation_to = double(to) / nu;
}
/// \endcond
}  // namespace internal

/// Bartlett's estimate of the spectrum of a sampling process: the radial power and anisotropy averaged over
/// several sets of the same size and frequency range (one periodogram is too noisy at low frequencies for the
/// effective Nyquist frequency; the point-set analysis literature averages ten). Recomputes the effective
/// Nyquist frequency and the oscillation from the averaged radial power.
/// \throws std::invalid_argument when the spectra are empty or differ in size, number of annuli or their
///   sizes (tori of different aspect ratios).
inline Sampling_spectrum average_sampling_spectra(const std::vector<Sampling_spectrum>& spectra,
                                                  double threshold = 0.1) {
  const char* fn = "average_sampling_spectra";
  internal::check_spectrum_threshold(threshold, fn);
  if (spectra.empty()) FeatureRecon::internal::throw_invalid_argument(fn, "no spectra");
  Sampling_spectrum a = spectra[0];
  for (std::size_t k = 1; k < spectra.size(); ++k) {
    if (spectra[k].samples != a.samples || spectra[k].radial_power.size() != a.radial_power.size())
      FeatureRecon::internal::throw_invalid_argument(
          fn, "spectrum ", k, " has ", spectra[k].samples, " samples and ", spectra[k].radial_power.size(),
          " annuli, spectrum 0 has ", a.samples, " and ", a.radial_power.size());
    if (spectra[k].annulus_size != a.annulus_size)
      FeatureRecon::internal::throw_invalid_argument(
          fn, "spectrum ", k, " has other annuli than spectrum 0 (a torus of another aspect ratio)");
    for (std::size_t b = 0; b < a.radial_power.size(); ++b) {
      a.radial_power[b] += spectra[k].radial_power[b];
      a.anisotropy[b] += spectra[k].anisotropy[b];
    }
  }
  for (std::size_t b = 0; b < a.radial_power.size(); ++b) {
    a.radial_power[b] /= double(spectra.size());
    a.anisotropy[b] /= double(spectra.size());
  }
  internal::finish_spectrum(a, threshold);
  return a;
}

/// Periodogram P(f) = |sum_k exp(-2 pi i f . x_k)|^2 / N over the integer frequencies |f_x|, |f_y| <= F of a
/// 2D sample set taken on the unit torus, its radial average and anisotropy over annuli of width 1, the
/// effective Nyquist frequency and the oscillation. By default (`Spectrum_method::automatic`) the sums go
/// through a non-uniform FFT whenever that is faster (from about 200 samples at the default F): O(N + F^2
/// log F) time and about twice the sums' (2 F + 1)(F + 1) complex numbers of memory, 1.6 s for 10^5
/// samples at F = 1898 where the direct O(N F^2) sums take minutes; both agree to about 2e-11 N.
/// \tparam ItemRange a forward range of `Traits::Item` with 2D positions. \tparam Traits a model of
///   FeaturePointTraits (the features are not used).
/// \throws std::invalid_argument for non-finite coordinates (naming the item), a threshold outside (0, 0.5),
///   a max_frequency above 16384 (given, or the default for more than 7.4 million samples), a `period` of
///   another length than 2 or outside [1e-150, 1e150], or an aspect ratio that needs integer frequencies
///   above 16384.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Sampling_spectrum sampling_spectrum(const ItemRange& items, const Sampling_spectrum_options& options = {},
                                    const Traits& traits = Traits()) {
  const char* fn = "sampling_spectrum";
  static_assert(Traits::dimension == 2, "FeatureRecon: sampling_spectrum takes 2D positions");
  internal::check_spectrum_threshold(options.threshold, fn);
  if (options.max_frequency > 16384)
    FeatureRecon::internal::throw_invalid_argument(
        fn,
        "max_frequency must be at most 16384 (the periodogram holds (2 F "
        "+ 1)(F + 1) complex sums), got ",
        options.max_frequency);
  const std::array<double, 2> period = internal::torus_period<2>(options.period, true, fn);
  const internal::Sample_set<Traits> S(items, traits, fn, false);
  const std::size_t n = S.size();
  Sampling_spectrum result;
  result.samples = n;
  if (n < 2) {
    result.status = Status::degenerate_input;
    return result;
  }
  const long F = internal::spectrum_frequency(n, options.max_frequency, fn);
  const double aspect = std::sqrt(period[1] / period[0]);
  // On a W x H torus the frequency (k_x / W, k_y / H) is g = (k_x a, k_y / a), a = sqrt(H / W), on the torus
  // scaled to area 1. Annuli 0..F hold |g| < F + 1/2: |k_x| <= Kx = (F + 1/2) / a and |k_y| <= Ky = (F + 1/2)
  // a, all within the sums' square of side K = max(Kx, Ky) (K = F on a square torus). Compared as doubles
  // before any cast (a ratio of 1e40 is a valid torus).
  const double reach_x = (double(F) + 0.5) / aspect, reach_y = (double(F) + 0.5) * aspect;
  if (!(std::floor(std::max(reach_x, reach_y)) <= 16384)) {
    const double stretch = std::max(aspect, 1 / aspect);  // the largest F with (F + 1/2) stretch < 16385
    double largest = std::floor(16385 / stretch - 0.5);
    if ((largest + 0.5) * stretch >= 16385) largest -= 1;
    FeatureRecon::internal::throw_invalid_argument(
        fn, "period ", period[0], " x ", period[1], " needs integer frequencies up to ",
        std::floor(std::max(reach_x, reach_y)), " for max_frequency ", F,
        ", above 16384 (the periodogram holds (2 K + 1)(K + 1) complex sums); max_frequency at most ",
        std::max(0.0, largest), " on this torus");
  }
  const long Kx = static_cast<long>(std::floor(reach_x)), Ky = static_cast<long>(std::floor(reach_y)),
             K = std::max(Kx, Ky);
  internal::Torus_points torus(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 2; ++a)
      torus[k][std::size_t(a)] = internal::torus_coordinate(
          options.period.empty() ? S.positions[k][a] : S.positions[k][a] / period[a]);
  result.method = options.method != Spectrum_method::automatic    ? options.method
                  : internal::gridded_periodogram_is_faster(n, K) ? Spectrum_method::gridded
                                                                  : Spectrum_method::direct;
  internal::Periodogram_sums storage;  // the sums in its first 2K + 1 rows
  const bool finished = result.method == Spectrum_method::direct
                            ? internal::direct_periodogram_sums(torus, K, storage, options.progress, 0, 1)
                            : internal::gridded_periodogram_sums(torus, K, storage, options.progress, 0, 1);
  if (!finished) {
    result.status = Status::interrupted;
    return result;
  }
  const auto sums = storage.topRows(2 * K + 1);
  // Radial statistics over annuli |g| in [k - 1/2, k + 1/2) (g = f on the unit torus: a = 1, exact).
  const std::size_t bins = std::size_t(F) + 1;
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0), count(bins, 0.0);
  for (long fy = -Ky; fy <= Ky; ++fy)
    for (long fx = -Kx; fx <= Kx; ++fx) {
      const double gx = double(fx) * aspect, gy = double(fy) / aspect;
      std::size_t b = std::size_t(std::lround(std::sqrt(gx * gx + gy * gy)));
      if (b >= bins) continue;
      if (b == 0 && (fx != 0 || fy != 0)) b = 1;  // annulus 0 is DC alone (|g| < 1/2 only when r > 4)
      const long sy = fy < 0 ? -fy : fy, sx = fy < 0 ? -fx : fx;  // P(-f) = P(f)
      const double p = std::norm(sums(sx + K, sy)) / double(n);
      sum[b] += p;
      sum2[b] += p * p;
      count[b] += 1;
    }
  const double nu = std::sqrt(double(n)) / 2;
  for (std::size_t b = 0; b < bins; ++b) {
    const double mean = count[b] > 0 ? sum[b] / count[b] : 0.0;
    const double var = count[b] > 1 ? (sum2[b] - count[b] * mean * mean) / (count[b] - 1) : 0.0;
    result.frequency.push_back(double(b) / nu);
    result.radial_power.push_back(mean);
    result.anisotropy.push_back(mean > 0 && var > 0 ? 10 * std::log10(var / (mean * mean)) : 0.0);
    result.annulus_size.push_back(static_cast<std::size_t>(count[b]));
  }
  internal::finish_spectrum(result, options.threshold);
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_SAMPLING_QUALITY_H
