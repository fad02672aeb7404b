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
  internal::check_domain(options.domain_measure, options.intrinsic_dimension, fn);
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

/// Options of sampling_spectrum().
struct Sampling_spectrum_options {
  /// Largest integer frequency per axis of the periodogram. Default 0: 2 sqrt(N) (rounded up), which covers
  /// the first peak of any blue-noise set.
  std::size_t max_frequency = 0;
  double threshold = 0.1;  ///< power level that ends the zero region (-10 dB) for the effective Nyquist frequency
  Progress_callback progress;  ///< fraction of the samples transformed; returning false stops (empty result)
};

/// Fourier statistics of a 2D sample set on the unit torus (positions modulo 1), as the point-set analysis
/// of Lagae and Dutré (2008) and Heck, Schlömer and Deussen (2013) defines them.
struct Sampling_spectrum {
  std::size_t samples = 0;              ///< N
  std::vector<double> frequency;        ///< annulus k (k = 0, 1, ...): integer radius k, in units of nu_N = sqrt(N)/2
  std::vector<double> radial_power;     ///< radially averaged periodogram per annulus (white noise: 1)
  std::vector<double> anisotropy;       ///< 10 log10(variance / mean^2) of the periodogram in each annulus (dB)
  /// Effective Nyquist frequency, in units of nu_N: where the radial power first reaches `threshold`
  /// (interpolated linearly between annuli; the zero region below it).
  double effective_nyquist = 0;
  double oscillation = 0;  ///< the largest radial power beyond the effective Nyquist frequency (its first peak)
  Status status = Status::success;  ///< degenerate_input for fewer than two samples; interrupted when stopped
};

namespace internal {
/// \cond
/// Effective Nyquist frequency (the first crossing of the threshold after the DC annulus, interpolated) and
/// oscillation (the largest radial power from there on) of a radial spectrum.
inline void finish_spectrum(Sampling_spectrum& s, double threshold) {
  const std::size_t bins = s.radial_power.size();
  const double nu = std::sqrt(double(s.samples)) / 2;
  s.effective_nyquist = 0;
  s.oscillation = 0;
  if (bins == 0 || nu == 0) return;
  std::size_t cross = bins;
  for (std::size_t b = 1; b < bins; ++b)
    if (s.radial_power[b] >= threshold) {
      cross = b;
      break;
    }
  if (cross == bins) {
    s.effective_nyquist = double(bins - 1) / nu;
    return;
  }
  const double p0 = cross > 1 ? s.radial_power[cross - 1] : 0.0, p1 = s.radial_power[cross];
  const double t = p1 > p0 ? (threshold - p0) / (p1 - p0) : 1.0;
  s.effective_nyquist = (double(cross) - 1 + std::min(1.0, std::max(0.0, t))) / nu;
  for (std::size_t b = cross; b < bins; ++b) s.oscillation = std::max(s.oscillation, s.radial_power[b]);
}
/// \endcond
}  // namespace internal

/// Bartlett's estimate of the spectrum of a sampling process: the radial power and anisotropy averaged over
/// several sets of the same size and frequency range (one periodogram is too noisy at low frequencies for the
/// effective Nyquist frequency; the point-set analysis literature averages ten). Recomputes the effective
/// Nyquist frequency and the oscillation from the averaged radial power.
/// \throws std::invalid_argument when the spectra are empty or differ in size or number of annuli.
inline Sampling_spectrum average_sampling_spectra(const std::vector<Sampling_spectrum>& spectra, double threshold = 0.1) {
  const char* fn = "average_sampling_spectra";
  if (spectra.empty()) FeatureRecon::internal::throw_invalid_argument(fn, "no spectra");
  Sampling_spectrum a = spectra[0];
  for (std::size_t k = 1; k < spectra.size(); ++k) {
    if (spectra[k].samples != a.samples || spectra[k].radial_power.size() != a.radial_power.size())
      FeatureRecon::internal::throw_invalid_argument(fn, "spectrum ", k, " has ", spectra[k].samples, " samples and ",
                                                     spectra[k].radial_power.size(), " annuli, spectrum 0 has ",
                                                     a.samples, " and ", a.radial_power.size());
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

/// Periodogram P(f) = |sum_k exp(-2 pi i f . x_k)|^2 / N over the integer frequencies |f_x|, |f_y| <= F of a 2D
/// sample set taken on the unit torus, its radial average and anisotropy over annuli of width 1, the effective
/// Nyquist frequency and the oscillation. O(N F^2) time.
/// \tparam ItemRange a forward range of `Traits::Item` with 2D positions. \tparam Traits a model of
///   FeaturePointTraits (the features are not used).
/// \throws std::invalid_argument for non-finite coordinates (naming the item) or a threshold <= 0.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Sampling_spectrum sampling_spectrum(const ItemRange& items, const Sampling_spectrum_options& options = {},
                                    const Traits& traits = Traits()) {
  const char* fn = "sampling_spectrum";
  static_assert(Traits::dimension == 2, "FeatureRecon: sampling_spectrum takes 2D positions");
  if (!(options.threshold > 0 && std::isfinite(options.threshold)))
    FeatureRecon::internal::throw_invalid_argument(fn, "threshold must be finite and > 0, got ", options.threshold);
  const internal::Sample_set<Traits> S(items, traits, fn);
  const std::size_t n = S.size();
  Sampling_spectrum result;
  result.samples = n;
  if (n < 2) {
    result.status = Status::degenerate_input;
    return result;
  }
  const long F = options.max_frequency != 0 ? static_cast<long>(options.max_frequency)
                                             : static_cast<long>(std::ceil(2 * std::sqrt(double(n))));
  const long W = 2 * F + 1;
  // Real and imaginary parts of sum_k exp(-2 pi i (fx x + fy y)) for fy >= 0 (P(-f) = P(f)).
  std::vector<double> re(std::size_t(W * (F + 1)), 0.0), im(re.size(), 0.0);
  const std::size_t width = static_cast<std::size_t>(W), height = static_cast<std::size_t>(F + 1);
  std::vector<double> ex_re(width), ex_im(width), ey_re(height), ey_im(height);
  const double two_pi = 6.283185307179586476925;
  for (std::size_t k = 0; k < n; ++k) {
    if ((k & 255) == 0 && !FeatureRecon::internal::report_progress(options.progress, double(k) / double(n))) {
      result.status = Status::interrupted;
      result.frequency.clear();
      return result;
    }
    const double x = S.positions[k][0] - std::floor(S.positions[k][0]);
    const double y = S.positions[k][1] - std::floor(S.positions[k][1]);
    for (long f = -F; f <= F; ++f) {  // direct evaluation: no drift of a recurrence over large F
      ex_re[std::size_t(f + F)] = std::cos(two_pi * double(f) * x);
      ex_im[std::size_t(f + F)] = -std::sin(two_pi * double(f) * x);
    }
    for (long f = 0; f <= F; ++f) {
      ey_re[std::size_t(f)] = std::cos(two_pi * double(f) * y);
      ey_im[std::size_t(f)] = -std::sin(two_pi * double(f) * y);
    }
    for (long fy = 0; fy <= F; ++fy) {
      const double a = ey_re[std::size_t(fy)], b = ey_im[std::size_t(fy)];
      double* r = re.data() + fy * W;
      double* i = im.data() + fy * W;
      for (long fx = 0; fx < W; ++fx) {
        r[fx] += ex_re[std::size_t(fx)] * a - ex_im[std::size_t(fx)] * b;
        i[fx] += ex_re[std::size_t(fx)] * b + ex_im[std::size_t(fx)] * a;
      }
    }
  }
  // Radial statistics over annuli |f| in [k - 1/2, k + 1/2).
  const std::size_t bins = std::size_t(F) + 1;
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0), count(bins, 0.0);
  for (long fy = -F; fy <= F; ++fy)
    for (long fx = -F; fx <= F; ++fx) {
      const std::size_t b = std::size_t(std::lround(std::sqrt(double(fx * fx + fy * fy))));
      if (b >= bins) continue;
      const long sy = fy < 0 ? -fy : fy, sx = fy < 0 ? -fx : fx;  // P(-f) = P(f)
      const std::size_t c = std::size_t(sy * W + sx + F);
      const double p = (re[c] * re[c] + im[c] * im[c]) / double(n);
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
  }
  internal::finish_spectrum(result, options.threshold);
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_SAMPLING_QUALITY_H
