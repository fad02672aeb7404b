// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_PERIODOGRAM_H
#define FEATURERECON_SAMPLING_INTERNAL_PERIODOGRAM_H

#include <FeatureRecon/config.h>

#include <Eigen/Core>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace FeatureRecon {
namespace sampling {
namespace internal {
/// \cond

/// The sums S(fx, fy) = sum_k exp(-2 pi i (fx x_k + fy y_k)) of a periodogram, for fx in [-F, F] (row fx + F)
/// and fy in [0, F] (column fy); P(-f) = P(f) gives the other half. The gridded method leaves them in the
/// first 2F + 1 rows of a taller matrix.
using Periodogram_sums = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic>;

/// Positions taken modulo 1, in [0, 1).
using Torus_points = std::vector<std::array<double, 2>>;

/// Direct evaluation, O(N F^2): blocks of samples' exponentials multiplied by Eigen's blocked matrix product.
/// Returns false when `progress` (fractions from `from` to `to`) asks to stop.
inline bool direct_periodogram_sums(const Torus_points& points, long F, Periodogram_sums& sums,
                                    const Progress_callback& progress, double from, double to) {
  const std::size_t n = points.size();
  const long W = 2 * F + 1;
  sums = Periodogram_sums::Zero(W, F + 1);
  // Blocks of about 10^8 multiply-adds between reports (at most 256 samples): at F = 16384 one sample is
  // 5.4 x 10^8 of them, and 256 samples would run minutes deaf to a stop.
  const std::size_t block =
      static_cast<std::size_t>(std::max(1.0, std::min(256.0, 1e8 / (double(W) * double(F + 1)))));
  Periodogram_sums ex(static_cast<Eigen::Index>(block), W), ey(static_cast<Eigen::Index>(block), F + 1);
  const double two_pi = 6.283185307179586476925;
  for (std::size_t k0 = 0; k0 < n; k0 += block) {
    if (!FeatureRecon::internal::report_progress(progress, from + (to - from) * double(k0) / double(n)))
      return false;
    const std::size_t m = std::min(block, n - k0);
    for (std::size_t j = 0; j < m; ++j) {
      const double x = points[k0 + j][0], y = points[k0 + j][1];
      const Eigen::Index r = static_cast<Eigen::Index>(j);
      for (long f = -F; f <= F; ++f)  // direct evaluation: no drift of a recurrence over large F
        ex(r, f + F) = std::polar(1.0, -two_pi * double(f) * x);
      for (long f = 0; f <= F; ++f) ey(r, f) = std::polar(1.0, -two_pi * double(f) * y);
    }
    const Eigen::Index rows = static_cast<Eigen::Index>(m);
    sums.noalias() += ex.topRows(rows).transpose() * ey.topRows(rows);
  }
  return true;
}

/// The smallest 2^a 3^b 5^c (a >= 1) at least n: sizes the FFT factors well.
inline long fft_friendly_size(long n) {
  for (long m = std::max(2L, n);; ++m) {
    long r = m;
    if (r % 2 != 0) continue;
    for (long p : {2L, 3L, 5L})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

/// Half-width, in grid cells, of the Gaussian that spreads each sample onto the oversampled grid of
/// gridded_periodogram_sums(): 12 gives about 12 correct digits at oversampling 2 (Greengard and Lee 2004).
constexpr long periodogram_spreading_cells = 12;

/// Size of the oversampled grid of gridded_periodogram_sums() for frequencies up to F.
inline long periodogram_grid_size(long F) { return fft_friendly_size(2 * (2 * F + 2)); }

/// The same sums by a non-uniform FFT of type 1 (Greengard and Lee, "Accelerating the nonuniform fast Fourier
/// transform", SIAM Review 46, 2004): every sample is spread onto a periodic grid of G >= 2 (2F + 2) cells
/// per axis by a Gaussian of `periodogram_spreading_cells` cells on either side, the grid is transformed
/// (Eigen's FFT, rows then columns) and the Gaussian's transform divided out. O(N 24^2 + G^2 log G) time, G
/// (F + 1) complex numbers in all, about twice the sums' size: the sums are left in the first 2F + 1 rows of
/// `sums`, which has G rows. Agrees with the direct sums to about 2e-11 N (worst at the corners of the
/// frequency square for clustered samples; about 2e-13 N for spread ones). The grid is spread row by row
/// (the samples sorted by row), so the real grid is never held whole. Grid rows follow the samples' x, and
/// each row is transformed along y first (frequencies 0 .. F kept), then each column along x, in place.
inline bool gridded_periodogram_sums(const Torus_points& points, long F, Periodogram_sums& sums,
                                     const Progress_callback& progress, double from, double to) {
  const std::size_t n = points.size();
  const long M = 2 * F + 2;  // modes -M/2 .. M/2 - 1 hold -F .. F
  const long G = periodogram_grid_size(F);
  const long S = periodogram_spreading_cells;
  const double pi = 3.141592653589793238463, two_pi = 2 * pi;
  const double R = double(G) / double(M);
  const double tau = pi * double(S) / (double(M) * double(M) * R * (R - 0.5));
  const double h = two_pi / double(G);
  // Fast Gaussian gridding: exp(-(d - l h)^2 / 4 tau) = exp(-d^2 / 4 tau) q^l exp(-(l h)^2 / 4 tau), q =
  // exp(d h / 2 tau), d in [0, h) the offset of a sample from its grid cell.
  std::vector<double> gauss(static_cast<std::size_t>(S + 1));
  for (long l = 0; l <= S; ++l) gauss[std::size_t(l)] = std::exp(-double(l * l) * h * h / (4 * tau));
  struct Spread {
    long cell_x, cell_y;
    double base_x, q_x, base_y, q_y;
  };
  std::vector<Spread> spread(n);
  std::vector<std::size_t> first(static_cast<std::size_t>(G) + 1, 0), order(n);
  for (std::size_t k = 0; k < n; ++k) {
    Spread& s = spread[k];
    // The code's x is the samples' y: the rows' transforms keep f_y in [0, F], the columns' give f_x.
    const double X = two_pi * points[k][1], Y = two_pi * points[k][0];
    s.cell_x = std::min(G - 1, static_cast<long>(std::floor(X / h)));
    s.cell_y = std::min(G - 1, static_cast<long>(std::floor(Y / h)));
    const double dx = X - double(s.cell_x) * h, dy = Y - double(s.cell_y) * h;
    s.base_x = std::exp(-dx * dx / (4 * tau));
    s.q_x = std::exp(dx * h / (2 * tau));
    s.base_y = std::exp(-dy * dy / (4 * tau));
    s.q_y = std::exp(dy * h / (2 * tau));
    ++first[std::size_t(s.cell_y) + 1];
  }
  for (long y = 0; y < G; ++y) first[std::size_t(y) + 1] += first[std::size_t(y)];
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < n; ++k) order[next[std::size_t(spread[k].cell_y)]++] = k;
  }
  // weight(l) for l in [-S + 1, S] of one axis
  const auto weights = [&](double base, double q, double* w) {
    double up = base, down = base;
    const double inverse = 1 / q;
    w[S - 1] = base;  // l = 0
    for (long l = 1; l <= S; ++l) {
      up *= q;
      w[S - 1 + l] = up * gauss[std::size_t(l)];
    }
    for (long l = 1; l < S; ++l) {
      down *= inverse;
      w[S - 1 - l] = down * gauss[std::size_t(l)];
    }
  };
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  Periodogram_sums& half = sums;  // row y of the grid transformed along x, frequencies 0 .. F
  half.resize(G, F + 1);
  std::vector<double> row(static_cast<std::size_t>(G));
  std::vector<std::complex<double>> row_transform(static_cast<std::size_t>(G / 2 + 1));
  std::vector<double> wx(static_cast<std::size_t>(2 * S)), wy(static_cast<std::size_t>(2 * S));
  const double spreading = 0.8;  // share of the progress range
  std::size_t spread_count = 0;  // samples spread onto rows: a report every 2^16 (small grids, many samples)
  for (long y = 0; y < G; ++y) {
    const double fraction = from + (to - from) * spreading * double(y) / double(G);
    if (y % 64 == 0 && !FeatureRecon::internal::report_progress(progress, fraction)) return false;
    std::fill(row.begin(), row.end(), 0.0);
    for (long l = -S + 1; l <= S; ++l) {  // samples in cell row y - l reach row y at offset l
      const long cell = ((y - l) % G + G) % G;
      for (std::size_t i = first[std::size_t(cell)]; i < first[std::size_t(cell) + 1]; ++i) {
        if (++spread_count % 65536 == 0 && !FeatureRecon::internal::report_progress(progress, fraction))
          return false;
        const Spread& s = spread[order[i]];
        // Both axes' weights are recomputed for each of the 2S rows a sample reaches: stored per sample (48
        // doubles) and gathered in row order they took 0.29 s instead of 0.16 s for 10^5 samples at F = 20,
        // and more memory.
        weights(s.base_y, s.q_y, wy.data());
        const double w = wy[std::size_t(S - 1 + l)];
        weights(s.base_x, s.q_x, wx.data());
        const long x0 = s.cell_x - S + 1;
        if (x0 >= 0 && x0 + 2 * S <= G) {
          double* r = row.data() + x0;
          for (long j = 0; j < 2 * S; ++j) r[j] += w * wx[std::size_t(j)];
        } else {
          for (long j = 0; j < 2 * S; ++j) row[std::size_t(((x0 + j) % G + G) % G)] += w * wx[std::size_t(j)];
        }
      }
    }
    fft.fwd(row_transform.data(), row.data(), G);
    for (long fx = 0; fx <= F; ++fx) half(y, fx) = row_transform[std::size_t(fx)];
  }
  std::vector<std::complex<double>> column(static_cast<std::size_t>(G));
  const double scale = pi / tau / (double(G) * double(G));
  for (long fx = 0; fx <= F; ++fx) {  // the code's fx is the samples' f_y, its fy their f_x
    if (fx % 16 == 0 &&
        !FeatureRecon::internal::report_progress(
            progress, from + (to - from) * (spreading + (1 - spreading) * double(fx) / double(F + 1))))
      return false;
    fft.fwd(column.data(), half.col(fx).data(), G);
    for (long fy = -F; fy <= F; ++fy)  // rows 0 .. 2F of the column, in place
      half(fy + F, fx) =
          column[std::size_t((fy + G) % G)] * (scale * std::exp(double(fx * fx + fy * fy) * tau));
  }
  return true;
}

/// Whether gridded_periodogram_sums() is expected to finish before direct_periodogram_sums(): nanoseconds per
/// operation as measured on a 2-core VM (benchmark/README.md): 20 per complex exponential and 0.76 per
/// multiply-add of the direct sums; 1600 per sample spread and 2.3 per G^2 log2 G of the grid's FFT.
inline bool gridded_periodogram_is_faster(std::size_t n, long F) {
  const double G = double(periodogram_grid_size(F));
  const double direct = double(n) * (20.0 * double(3 * F + 2) + 0.76 * double(2 * F + 1) * double(F + 1));
  const double gridded = 1600.0 * double(n) + 2.3 * G * G * std::log2(G);
  return gridded < direct;
}

/// \endcond
}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_PERIODOGRAM_H
