// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_SAMPLED_BILATERAL_FILTER_H
#define FEATURERECON_SAMPLING_SAMPLED_BILATERAL_FILTER_H

/// \file
/// Image subsampling for bilateral filtering (dissertation Sec. 2.2.3). The bilateral filter of an 8-bit
/// image,
///
///     out(x) = sum_q w_s(q - x) w_r(I(q) - I(x)) I(q) / sum_q w_s(q - x) w_r(I(q) - I(x)),
///
/// with w_s(d) = exp(-|d|^2 / (2 sigma_spatial^2)) over the pixels q of a (2R + 1) x (2R + 1) window and
/// w_r(d) = exp(-|d|^2 / (2 sigma_range^2)) on the channels scaled to [0, 1], is evaluated exactly by
/// bilateral_filter() and on a subset of taps by sampled_bilateral_filter(): the taps are blue-noise samples
/// of continuous positions, each reading the pixel it falls in, drawn
///  - uniformly (Euclidean Poisson-disk) or bilaterally (Poisson-disk in the bilateral distance
///    xi^2 = |dp|^2 + |dI|^2 / sigma_feature^2, pixels and [0, 1] channel units, so that taps crowd where the
///    image changes and both sides of an edge are sampled), and
///  - locally (a pattern per output pixel, dart throwing over a seeded pool of candidate sets in its window)
///    or globally (one pattern for the image, made once by bilateral_tap_pattern(); each output pixel uses
///    the taps inside its window).
/// The budget is the number of taps per kernel pixel; the dart radius is calibrated on the image so that the
/// mean over the windows (global: the whole image) meets it. Bilateral patterns are denser near edges; with
/// `compensate_density` each tap is weighted by the inverse of the density a saturated pattern has at its
/// pixel relative to a flat image (its exclusion area in the stacked space over the flat one), so that the
/// estimator tends to the exact filter as the budget grows. Every output pixel also reads its own pixel,
/// exactly (weight 1), and the sampled taps stand for 1 / density pixels each (a Horvitz-Thompson estimate of
/// the rest of the window; taps falling in the centre pixel are not counted twice): a pixel whose window has
/// no similar tap keeps about its own value instead of taking its neighbours'.

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/random.h>
#include <FeatureRecon/sampling/internal/radius_search.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// The weights of a bilateral filter.
struct Bilateral_kernel {
  /// spatial Gaussian width in pixels (> 0; at most 2048 when the radius is derived from it); default 3
  double sigma_spatial = 3;
  /// range Gaussian width on channels scaled to [0, 1], in [1e-150, 1e150] (its square a normal double);
  /// default 0.1
  double sigma_range = 0.1;
  int radius = 0;  ///< window half-width R in pixels, in [0, 4096]; default 0: ceil(2 sigma_spatial)
};

/// Options of bilateral_filter() (the exact filter).
struct Bilateral_filter_options {
  Bilateral_kernel kernel;     ///< the weights
  Progress_callback progress;  ///< fraction of the rows done; returning false stops (the result is empty)
};

/// How the taps of the sampled filter are distributed.
enum class Tap_sampling {
  uniform,   ///< Euclidean Poisson-disk taps
  bilateral  ///< Poisson-disk taps in the bilateral distance with the colour as the feature
};

/// Where the tap patterns come from.
enum class Tap_mode {
  local,  ///< a pattern per output pixel, made in its window
  global  ///< one pattern for the whole image; each output pixel uses the taps in its window
};

/// Options of sampled_bilateral_filter() and bilateral_tap_pattern().
struct Sampled_bilateral_filter_options {
  Bilateral_kernel kernel;                          ///< the filter's weights
  Tap_sampling sampling = Tap_sampling::bilateral;  ///< uniform or bilateral taps; default bilateral
  Tap_mode mode = Tap_mode::global;                 ///< local or global patterns; default global
  double budget = 0.5;                              ///< taps per kernel pixel (> 0, <= 16); default 0.5
  /// sigma_feature of the bilateral sampling distance on [0, 1] channels, in [1e-150, 1e150]; default 0:
  /// sigma_range
  double sampling_sigma_feature = 0;
  bool compensate_density = true;  ///< weight bilateral taps by their inverse relative density
  double candidates_per_tap = 4;   ///< uniform candidates thrown per tap of the budget, in [2, 64]; default 4
  std::size_t local_patterns = 64;  ///< local mode: candidate sets in the pool, in [1, 65536]; default 64
  std::uint64_t seed = 0;           ///< random seed; the same seed gives the same output
  Progress_callback progress;       ///< fraction of the work done; returning false stops (empty result)
};

/// Output of bilateral_filter() and sampled_bilateral_filter().
struct Bilateral_filter_result {
  /// The filtered image, width * height * channels values on the 0..255 scale, unrounded, rows from the top.
  std::vector<float> values;
  std::size_t taps = 0;  ///< sampled taps over all output pixels (with multiplicity)
  /// sampled taps over the in-image pixels of all windows (the centre pixel read besides them is not counted;
  /// 1 for the exact filter)
  double taps_per_kernel_pixel = 0;
  double sampling_radius = 0;       ///< the dart radius in xi units (pixels); 0 for the exact filter
  Status status = Status::success;  ///< degenerate_input for an empty image; interrupted when stopped
};

/// A global tap pattern: blue-noise taps over the image, sorted by pixel (row-major), ties in the order the
/// darts were accepted.
struct Tap_pattern {
  int width = 0;   ///< the image's width
  int height = 0;  ///< the image's height
  /// continuous positions, x right, y down, in [0, w) x [0, h)
  std::vector<std::array<double, 2>> positions;
  std::vector<std::uint32_t> pixels;  ///< the pixel each tap reads, row * width + column
  std::vector<float> weights;         ///< the taps' density compensation (1 without it)
  double radius = 0;                  ///< the dart radius in xi units
  Status status = Status::success;    ///< degenerate_input for an empty image; interrupted when stopped
};

namespace internal {
/// \cond
using FeatureRecon::internal::splitmix64;

/// The image, its weight tables and the checks every entry point makes.
class Filter_image {
 public:
  Filter_image(int width, int height, int channels, const std::vector<std::uint8_t>& data,
               const Bilateral_kernel& kernel, const char* fn)
      : w(width), h(height), c(channels), I(data.data()) {
    if (width < 0 || height < 0)
      FeatureRecon::internal::throw_invalid_argument(fn, "width and height must be >= 0, got ", width, " x ",
                                                     height);
    if (channels != 1 && channels != 3)
      FeatureRecon::internal::throw_invalid_argument(fn, "channels must be 1 or 3, got ", channels);
    const std::size_t expected = std::size_t(width) * std::size_t(height) * std::size_t(channels);
    if (data.size() != expected)
      FeatureRecon::internal::throw_invalid_argument(fn, "data has ", data.size(), " values, a ", width,
                                                     " x ", height, " image with ", channels,
                                                     " channel(s) needs ", expected);
    if (!(std::isfinite(kernel.sigma_spatial) && kernel.sigma_spatial > 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "kernel.sigma_spatial must be finite and > 0, got ",
                                                     kernel.sigma_spatial);
    if (!(kernel.sigma_range >= 1e-150 && kernel.sigma_range <= 1e150))  // its square a normal double
      FeatureRecon::internal::throw_invalid_argument(
          fn, "kernel.sigma_range must be in [1e-150, 1e150], got ", kernel.sigma_range);
    if (kernel.radius < 0 || kernel.radius > 4096)
      FeatureRecon::internal::throw_invalid_argument(fn, "kernel.radius must be in [0, 4096], got ",
                                                     kernel.radius);
    if (kernel.radius == 0 && kernel.sigma_spatial > 2048)
      FeatureRecon::internal::throw_invalid_argument(fn,
                                                     "kernel.sigma_spatial must be <= 2048 when the radius "
                                                     "is derived from it, got ",
                                                     kernel.sigma_spatial);
    R = kernel.radius > 0 ? kernel.radius : std::max(1, int(std::ceil(2 * kernel.sigma_spatial)));
    side = 2 * R + 1;
    spatial.resize(std::size_t(side) * std::size_t(side));
    for (int dy = -R; dy <= R; ++dy)
      for (int dx = -R; dx <= R; ++dx)
        spatial[std::size_t(dy + R) * std::size_t(side) + std::size_t(dx + R)] =
            float(std::exp(-double(dx * dx + dy * dy) / (2 * kernel.sigma_spatial * kernel.sigma_spatial)));
    range.resize(std::size_t(channels) * 255 * 255 + 1);
    const double s = 255 * kernel.sigma_range;
    for (std::size_t d2 = 0; d2 < range.size(); ++d2) range[d2] = float(std::exp(-double(d2) / (2 * s * s)));
  }
  std::size_t pixels() const { return std::size_t(w) * std::size_t(h); }
  /// Squared difference of two pixels' integer channel values.
  int d2(std::size_t p, std::size_t q) const {
    int s = 0;
    for (int k = 0; k < c; ++k) {
      const int d = int(I[p * std::size_t(c) + std::size_t(k)]) - int(I[q * std::size_t(c) + std::size_t(k)]);
      s += d * d;
    }
    return s;
  }
  float spatial_weight(int dx, int dy) const {
    return spatial[std::size_t(dy + R) * std::size_t(side) + std::size_t(dx + R)];
  }
  /// In-image pixels of the window of (x, y).
  std::size_t window_pixels(int x, int y) const {
    return std::size_t(std::min(R, w - 1 - x) + std::min(R, x) + 1) *
           std::size_t(std::min(R, h - 1 - y) + std::min(R, y) + 1);
  }

  int w, h, c;
  const std::uint8_t* I;
  int R = 0, side = 0;
  std::vector<float> spatial, range;
};

/// Accumulates weighted taps of one output pixel.
struct Tap_sum {
  double num[3] = {0, 0, 0};
  double den = 0;
  void add(const Filter_image& F, std::size_t q, double weight) {
    den += weight;
    for (int k = 0; k < F.c; ++k) num[k] += weight * double(F.I[q * std::size_t(F.c) + std::size_t(k)]);
  }
  void write(const Filter_image& F, std::size_t p, std::vector<float>& out) const {
    for (int k = 0; k < F.c; ++k)
      out[p * std::size_t(F.c) + std::size_t(k)] =
          den > 0 ? float(num[k] / den) : float(F.I[p * std::size_t(F.c) + std::size_t(k)]);
  }
};

/// Runs the filter over every output pixel, row by row with progress: taps(x, y, p, sum) adds the taps of
/// pixel p = (x, y) to `sum` and returns how many it evaluated. Fills values, taps and their mean per kernel
/// pixel, or sets `interrupted` with no values.
template <class Taps>
void filter_pixels(const Filter_image& F, const Progress_callback& progress, Bilateral_filter_result& result,
                   Taps taps) {
  result.values.resize(F.pixels() * std::size_t(F.c));
  std::size_t count = 0, window = 0;
  for (int y = 0; y < F.h; ++y) {
    if (!FeatureRecon::internal::report_progress(progress, double(y) / F.h)) {
      result.values.clear();
      result.status = Status::interrupted;
      return;
    }
    for (int x = 0; x < F.w; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(F.w) + std::size_t(x);
      Tap_sum sum;
      count += taps(x, y, p, sum);
      window += F.window_pixels(x, y);
      sum.write(F, p, result.values);
    }
  }
  (void)FeatureRecon::internal::report_progress(progress, 1.0);
  result.taps = count;
  result.taps_per_kernel_pixel = window == 0 ? 0 : double(count) / double(window);
}

inline void check_sampled_options(const Sampled_bilateral_filter_options& o, const char* fn) {
  if (!(std::isfinite(o.budget) && o.budget > 0 && o.budget <= 16))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "budget must be in (0, 16] taps per kernel pixel, got ", o.budget);
  if (!(o.sampling_sigma_feature == 0 ||
        (o.sampling_sigma_feature >= 1e-150 && o.sampling_sigma_feature <= 1e150)))
    FeatureRecon::internal::throw_invalid_argument(fn,
                                                   "sampling_sigma_feature must be in [1e-150, 1e150] (or 0 "
                                                   "for sigma_range), got ",
                                                   o.sampling_sigma_feature);
  if (!(std::isfinite(o.candidates_per_tap) && o.candidates_per_tap >= 2 && o.candidates_per_tap <= 64))
    FeatureRecon::internal::throw_invalid_argument(fn, "candidates_per_tap must be in [2, 64], got ",
                                                   o.candidates_per_tap);
  if (o.local_patterns < 1 || o.local_patterns > 65536)
    FeatureRecon::internal::throw_invalid_argument(fn, "local_patterns must be in [1, 65536], got ",
                                                   o.local_patterns);
}

/// 1 / (255^2 sigma_feature^2): the factor turning integer squared channel differences into xi^2 units;
/// 0 for uniform sampling.
inline double feature_factor(const Sampled_bilateral_filter_options& o) {
  if (o.sampling == Tap_sampling::uniform) return 0;
  const double s = o.sampling_sigma_feature > 0 ? o.sampling_sigma_feature : o.kernel.sigma_range;
  return 1 / (255.0 * 255.0 * s * s);
}

/// Density compensation per pixel for bilateral darts of radius r: the pixel's exclusion area in the stacked
/// space (sub-pixel points within xi < r of its centre, 4 x 4 per pixel, each reading its pixel's colour)
/// over that of a flat image with the same in-image points. 1 everywhere for uniform sampling. The pixels of
/// the disc are read every `stride` pixels in x and y (0: automatic, 1 up to r = 24, then ceil(e / 24) with e
/// = min(r, width + height), as offsets beyond width + height meet no pixel): the cost per pixel stays about
/// 1,800 offsets (a tiny budget asks for r = 74 at 1e-4 and took 30 s on 256 x 256 pixels).
inline std::vector<float> density_compensation(const Filter_image& F, double r, double factor,
                                               int stride = 0) {
  std::vector<float> weight(F.pixels(), 1.0f);
  if (factor == 0 || F.pixels() == 0) return weight;
  // Offsets beyond the image's width plus height meet no pixel: the disc is walked that far at most (a budget
  // of 1e-300 asked for r = 1e150, and its int reach overflowed).
  const double extent = std::min(r, double(F.w) + double(F.h));
  if (stride <= 0) stride = extent <= 24 ? 1 : int(std::ceil(extent / 24));
  constexpr int S = 4;
  struct Offset {  // a pixel offset and the sorted squared distances of its sub-points within r
    int dx, dy;
    std::size_t begin, end;
  };
  std::vector<Offset> offsets;
  std::vector<double> sub_d2;
  const int reach = int(std::ceil(extent)) + 1;
  const double r2 = r * r;
  for (int py = -reach / stride * stride; py <= reach; py += stride)  // multiples of the stride: 0 is one
    for (int px = -reach / stride * stride; px <= reach; px += stride) {
      const std::size_t begin = sub_d2.size();
      for (int sy = 0; sy < S; ++sy)
        for (int sx = 0; sx < S; ++sx) {
          const double ux = px + (sx + 0.5) / S - 0.5, uy = py + (sy + 0.5) / S - 0.5;
          if (ux * ux + uy * uy < r2) sub_d2.push_back(ux * ux + uy * uy);
        }
      if (sub_d2.size() == begin) continue;
      std::sort(sub_d2.begin() + std::ptrdiff_t(begin), sub_d2.end());
      offsets.push_back({px, py, begin, sub_d2.size()});
    }
  for (int y = 0; y < F.h; ++y)
    for (int x = 0; x < F.w; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(F.w) + std::size_t(x);
      std::size_t inside = 0, excluded = 0;
      for (const Offset& o : offsets) {
        const int qx = x + o.dx, qy = y + o.dy;
        if (qx < 0 || qy < 0 || qx >= F.w || qy >= F.h) continue;
        inside += o.end - o.begin;
        const double room =
            r2 - factor * double(F.d2(p, std::size_t(qy) * std::size_t(F.w) + std::size_t(qx)));
        if (room <= sub_d2[o.begin]) continue;
        std::size_t k = o.begin;
        while (k < o.end && sub_d2[k] < room) ++k;
        excluded += k - o.begin;
      }
      weight[p] = inside == 0 ? 1.0f : float(double(excluded) / double(inside));
    }
  return weight;
}

/// Uniform doubles in [0, 1) from std::mt19937_64 by bit manipulation (the same on every platform).
using FeatureRecon::internal::Unit_random;

/// Global darts: candidates (continuous positions, in the order thrown) thinned with radius r; returns the
/// accepted candidates in acceptance order. Conflicts are strict (xi < r).
inline std::vector<std::uint32_t> global_darts(const Filter_image& F,
                                               const std::vector<std::array<double, 2>>& cand,
                                               const std::vector<std::uint32_t>& cand_pixel, double r,
                                               double factor) {
  const double cell = r;
  const int gw = int(std::ceil(F.w / cell)) + 1, gh = int(std::ceil(F.h / cell)) + 1;
  std::vector<std::int32_t> head(std::size_t(gw) * std::size_t(gh), -1), next;
  std::vector<std::uint32_t> accepted;
  next.reserve(cand.size() / 2);
  const double r2 = r * r;
  for (std::uint32_t k = 0; k < cand.size(); ++k) {
    const int cx = int(cand[k][0] / cell), cy = int(cand[k][1] / cell);
    bool conflict = false;
    for (int yy = std::max(0, cy - 1); yy <= std::min(gh - 1, cy + 1) && !conflict; ++yy)
      for (int xx = std::max(0, cx - 1); xx <= std::min(gw - 1, cx + 1) && !conflict; ++xx)
        for (std::int32_t a = head[std::size_t(yy) * std::size_t(gw) + std::size_t(xx)]; a >= 0;
             a = next[std::size_t(a)]) {
          const std::uint32_t j = accepted[std::size_t(a)];
          const double dx = cand[k][0] - cand[j][0], dy = cand[k][1] - cand[j][1];
          const double d2 = dx * dx + dy * dy;
          if (d2 >= r2) continue;
          if (d2 + factor * double(F.d2(cand_pixel[k], cand_pixel[j])) < r2) {
            conflict = true;
            break;
          }
        }
    if (conflict) continue;
    const std::size_t g = std::size_t(cy) * std::size_t(gw) + std::size_t(cx);
    next.push_back(head[g]);
    head[g] = std::int32_t(accepted.size());
    accepted.push_back(k);
  }
  return accepted;
}

/// The pool of local candidate sets: offsets from the window's centre pixel, uniform in the window square,
/// each with its earlier candidates within Euclidean distance `reach`.
struct Local_pool {
  struct Neighbour {
    std::uint32_t index;
    float d2;
  };
  std::size_t per_set = 0;
  std::vector<std::array<double, 2>> offset;  // sets * per_set
  std::vector<std::array<int, 2>> pixel;      // integer pixel offsets
  std::vector<std::uint32_t> first;           // CSR of the neighbour lists, sets * per_set + 1
  std::vector<Neighbour> neighbours;

  // `progress` is asked before each set; when it says stop, `stopped` is set and the pool is left unfinished.
  Local_pool(int R, std::size_t sets, std::size_t per, double reach, std::uint64_t seed,
             const Progress_callback& progress, bool& stopped)
      : per_set(per) {
    const double half = R + 0.5;
    offset.resize(sets * per);
    pixel.resize(sets * per);
    first.assign(sets * per + 1, 0);
    const int cells = std::max(1, int(std::floor(2 * half / reach)));
    const double cell = 2 * half / cells;
    std::vector<std::vector<std::uint32_t>> grid(std::size_t(cells) * std::size_t(cells));
    for (std::size_t s = 0; s < sets; ++s) {
      if (!FeatureRecon::internal::report_progress(progress, double(s) / double(sets))) {
        stopped = true;
        return;
      }
      Unit_random random(splitmix64(seed ^ (0x51ed27f1c0a3b9d7ULL + s)));
      for (auto& g : grid) g.clear();
      for (std::size_t k = 0; k < per; ++k) {
        const std::size_t i = s * per + k;
        const double ox = -half + 2 * half * random(), oy = -half + 2 * half * random();
        offset[i] = {ox, oy};
        pixel[i] = {std::clamp(int(std::floor(ox + 0.5)), -R, R),
                    std::clamp(int(std::floor(oy + 0.5)), -R, R)};
        const int cx = std::min(cells - 1, int((ox + half) / cell)),
                  cy = std::min(cells - 1, int((oy + half) / cell));
        for (int yy = std::max(0, cy - 1); yy <= std::min(cells - 1, cy + 1); ++yy)
          for (int xx = std::max(0, cx - 1); xx <= std::min(cells - 1, cx + 1); ++xx)
            for (std::uint32_t j : grid[std::size_t(yy) * std::size_t(cells) + std::size_t(xx)]) {
              const double dx = ox - offset[s * per + j][0], dy = oy - offset[s * per + j][1];
              const double d2 = dx * dx + dy * dy;
              if (d2 < reach * reach) neighbours.push_back({j, float(d2)});
            }
        first[i + 1] = std::uint32_t(neighbours.size());
        grid[std::size_t(cy) * std::size_t(cells) + std::size_t(cx)].push_back(std::uint32_t(k));
      }
    }
  }
  std::size_t sets() const { return per_set == 0 ? 0 : offset.size() / per_set; }
};

/// Runs darts of radius r over candidate set `s` in the window of (x, y); calls on_tap(q) for every accepted
/// candidate inside the image. Bilateral darts (factor > 0) skip candidates outside the image; Euclidean ones
/// thin them too, so that the taps are those of the window-independent pattern clipped to the image.
/// `accepted` and `pix` are scratch of size per_set.
template <class OnTap>
void local_darts(const Filter_image& F, const Local_pool& pool, std::size_t s, int x, int y, double r,
                 double factor, std::vector<char>& accepted, std::vector<std::uint32_t>& pix, OnTap on_tap) {
  const double r2 = r * r;
  for (std::size_t k = 0; k < pool.per_set; ++k) {
    const std::size_t i = s * pool.per_set + k;
    accepted[k] = 0;
    const int qx = x + pool.pixel[i][0], qy = y + pool.pixel[i][1];
    const bool inside = qx >= 0 && qy >= 0 && qx < F.w && qy < F.h;
    if (!inside && factor != 0) continue;  // no colour: not a candidate
    const std::uint32_t q = inside ? std::uint32_t(qy) * std::uint32_t(F.w) + std::uint32_t(qx) : 0;
    pix[k] = q;
    bool conflict = false;
    for (std::uint32_t a = pool.first[i]; a < pool.first[i + 1]; ++a) {
      const Local_pool::Neighbour& nb = pool.neighbours[a];
      if (!accepted[nb.index] || double(nb.d2) >= r2) continue;
      if (double(nb.d2) + (factor == 0 ? 0.0 : factor * double(F.d2(q, pix[nb.index]))) < r2) {
        conflict = true;
        break;
      }
    }
    if (conflict) continue;
    accepted[k] = 1;
    if (inside) on_tap(q);
  }
}

/// The candidate set a window uses.
inline std::size_t local_set(std::uint64_t seed, std::size_t p, std::size_t sets) {
  return std::size_t(splitmix64(seed * 0x2545f4914f6cdd1dULL + p) % sets);
}

/// Calibrates the local dart radius so that the taps over the in-image window pixels of a seeded subset of
/// windows meet the budget (secant steps on count ~ 1 / r^2, then bisection), r in (0, reach]. `progress` is
/// asked before each of the (at most 30) counts; when it says stop, `stopped` is set and the radius so far
/// returned. `short_of_reach` is set when the budget was not met because even radii next to `reach` keep too
/// many taps (then a pool with a longer reach can do better).
inline double calibrate_local_radius(const Filter_image& F, const Local_pool& pool, double budget,
                                     double factor, std::uint64_t seed, double reach,
                                     const Progress_callback& progress, bool& stopped, bool& short_of_reach) {
  short_of_reach = false;
  const std::size_t n = F.pixels();
  std::vector<std::size_t> probes;
  if (n <= 4096) {
    for (std::size_t p = 0; p < n; ++p) probes.push_back(p);
  } else {
    std::mt19937_64 rng(splitmix64(seed ^ 0x6a09e667f3bcc909ULL));
    for (int k = 0; k < 2048; ++k) probes.push_back(std::size_t(rng() % n));
  }
  std::size_t window = 0;
  for (std::size_t p : probes)
    window += F.window_pixels(int(p % std::size_t(F.w)), int(p / std::size_t(F.w)));
  const double target = budget * double(window);
  std::vector<char> accepted(pool.per_set);
  std::vector<std::uint32_t> pix(pool.per_set);
  auto count = [&](double r) {
    std::size_t taps = 0;
    for (std::size_t p : probes)
      local_darts(F, pool, local_set(seed, p, pool.sets()), int(p % std::size_t(F.w)),
                  int(p / std::size_t(F.w)), r, factor, accepted, pix, [&](std::uint32_t) { ++taps; });
    return double(taps);
  };
  Radius_search search;
  search.hi = reach;
  double r = std::sqrt(0.46 / budget);
  if (!(r < reach)) r = 0.5 * reach;
  double best = r, best_miss = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 30; ++step) {
    if (!FeatureRecon::internal::report_progress(progress, step / 30.0)) {
      stopped = true;
      return r;
    }
    const double c = count(r);
    if (std::abs(c - target) <= 0.005 * target) return r;
    if (std::abs(c - target) < best_miss) {
      best_miss = std::abs(c - target);
      best = r;
    }
    if (c > target && r >= 0.999 * reach) {  // the count can only fall with a radius the pool cannot test
      short_of_reach = true;
      return r;
    }
    r = search.next(r, c, target, c > target);
  }
  return best;
}
/// \endcond
}  // namespace internal

/// The exact bilateral filter (every pixel of the window), the reference of sampled_bilateral_filter().
/// Range weights come from a table over integer squared channel differences; O(n (2R + 1)^2) time.
/// \param width, height the image size (>= 0). \param channels 1 (grey) or 3 (RGB).
/// \param data width * height * channels 8-bit values, rows from the top, channels interleaved.
/// \param options the kernel and the progress callback.
/// \returns the filtered values (unrounded, 0..255 scale), taps = the in-image window pixels, taps per kernel
///   pixel 1; status degenerate_input for an empty image, interrupted (with no values) when stopped.
/// \throws std::invalid_argument naming the argument: sizes that disagree, channels other than 1 or 3, a
///   non-finite or non-positive sigma_spatial (above 2048 when the radius is derived from it), a sigma_range
///   out of [1e-150, 1e150], a radius out of [0, 4096].
inline Bilateral_filter_result bilateral_filter(int width, int height, int channels,
                                                const std::vector<std::uint8_t>& data,
                                                const Bilateral_filter_options& options = {}) {
  const internal::Filter_image F(width, height, channels, data, options.kernel, "bilateral_filter");
  Bilateral_filter_result result;
  if (F.pixels() == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  internal::filter_pixels(
      F, options.progress, result, [&](int x, int y, std::size_t p, internal::Tap_sum& sum) {
        std::size_t taps = 0;
        for (int dy = -std::min(F.R, y); dy <= std::min(F.R, F.h - 1 - y); ++dy)
          for (int dx = -std::min(F.R, x); dx <= std::min(F.R, F.w - 1 - x); ++dx, ++taps) {
            const std::size_t q = std::size_t(y + dy) * std::size_t(F.w) + std::size_t(x + dx);
            sum.add(F, q, double(F.spatial_weight(dx, dy) * F.range[std::size_t(F.d2(p, q))]));
          }
        return taps;
      });
  return result;
}

namespace internal {
/// \cond
/// bilateral_tap_pattern() on a checked image.
inline Tap_pattern tap_pattern(const Filter_image& F, const Sampled_bilateral_filter_options& options) {
  Tap_pattern pattern;
  pattern.width = F.w;
  pattern.height = F.h;
  if (F.pixels() == 0) {
    pattern.status = Status::degenerate_input;
    return pattern;
  }
  const double factor = feature_factor(options);
  const std::size_t target =
      std::max<std::size_t>(1, std::size_t(std::llround(options.budget * double(F.pixels()))));
  const std::size_t m = std::size_t(std::ceil(options.candidates_per_tap * double(target)));
  std::vector<std::array<double, 2>> cand(m);
  std::vector<std::uint32_t> cand_pixel(m);
  Unit_random random(options.seed);
  for (std::size_t k = 0; k < m; ++k) {
    const double x = std::min(double(F.w) * random(), std::nextafter(double(F.w), 0.0));
    const double y = std::min(double(F.h) * random(), std::nextafter(double(F.h), 0.0));
    cand[k] = {x, y};
    cand_pixel[k] = std::uint32_t(y) * std::uint32_t(F.w) + std::uint32_t(x);
  }
  // Euclidean darts over 4 candidates per tap keep about 0.46 / r^2 per unit area.
  double r = std::sqrt(0.46 * double(F.pixels()) / double(target));
  std::vector<std::uint32_t> kept;
  double thrown = r;     // the radius `kept` was thrown with
  Radius_search search;  // counts at search.lo reach the target, at search.hi not
  for (int step = 0; step < 40; ++step) {
    if (!FeatureRecon::internal::report_progress(options.progress, 0.05 * step / 40)) {
      pattern.status = Status::interrupted;
      return pattern;
    }
    kept = global_darts(F, cand, cand_pixel, r, factor);
    thrown = r;
    const double c = double(kept.size());
    if (c >= double(target) && c <= 1.01 * double(target) + 1) break;
    r = search.next(r, c, 1.005 * double(target), c >= double(target));
  }
  // After the 40 steps r is the next radius to try, not the one the taps were thrown with (the pattern
  // reported it and compensated the density for it).
  r = thrown;
  if (kept.size() < target) {  // fall back to the largest radius known to keep enough
    r = search.lo;
    if (r > 0) kept = global_darts(F, cand, cand_pixel, r, factor);
    if (r == 0 || kept.size() < target) {  // r -> 0 keeps every candidate, m >= target
      kept.resize(m);
      for (std::size_t k = 0; k < m; ++k) kept[k] = std::uint32_t(k);
    }
  }
  kept.resize(target);
  const std::vector<float> comp =
      options.compensate_density ? density_compensation(F, r, factor) : std::vector<float>(F.pixels(), 1.0f);
  std::stable_sort(kept.begin(), kept.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return cand_pixel[a] < cand_pixel[b]; });
  pattern.positions.reserve(target);
  for (std::uint32_t k : kept) {
    pattern.positions.push_back(cand[k]);
    pattern.pixels.push_back(cand_pixel[k]);
    pattern.weights.push_back(comp[cand_pixel[k]]);
  }
  pattern.radius = r;
  return pattern;
}
/// \endcond
}  // namespace internal

/// The global tap pattern of sampled_bilateral_filter() (its first stage in global mode): round(budget * n)
/// taps for an n-pixel image, uniform (Euclidean) or bilateral Poisson-disk by dart throwing over
/// candidates_per_tap times as many uniform random candidates, with the radius set by secant steps so that
/// the darts keep at least the budget (the first ones accepted are kept).
/// \param width, height, channels, data the image (as for bilateral_filter()).
/// \param options sampling, budget, sigma of the sampling distance, compensation, candidates, seed, progress.
/// \returns the taps sorted by pixel with their weights and the radius; degenerate_input for an empty image,
///   interrupted (no taps) when stopped.
/// \throws std::invalid_argument naming the argument (as bilateral_filter(), and the budget in (0, 16],
///   candidates_per_tap in [2, 64], local_patterns in [1, 65536], a sampling_sigma_feature other than 0 out
///   of [1e-150, 1e150]).
inline Tap_pattern bilateral_tap_pattern(int width, int height, int channels,
                                         const std::vector<std::uint8_t>& data,
                                         const Sampled_bilateral_filter_options& options = {}) {
  const char* fn = "bilateral_tap_pattern";
  const internal::Filter_image F(width, height, channels, data, options.kernel, fn);
  internal::check_sampled_options(options, fn);
  return internal::tap_pattern(F, options);
}

namespace internal {
/// \cond
/// The second stage of the global mode on a checked image.
inline Bilateral_filter_result filter_on_pattern(const Filter_image& F, const Tap_pattern& pattern,
                                                 const Progress_callback& progress, const char* fn) {
  if (pattern.width != F.w || pattern.height != F.h)
    FeatureRecon::internal::throw_invalid_argument(fn, "pattern is ", pattern.width, " x ", pattern.height,
                                                   ", the image ", F.w, " x ", F.h);
  if (pattern.pixels.size() != pattern.weights.size())
    FeatureRecon::internal::throw_invalid_argument(fn, "pattern has ", pattern.pixels.size(), " pixels and ",
                                                   pattern.weights.size(), " weights");
  // A stopped pattern (or one without taps) filtered nothing: every pixel came back as it was.
  if (pattern.status == Status::interrupted)
    FeatureRecon::internal::throw_invalid_argument(
        fn,
        "pattern was stopped while it was made (status interrupted): "
        "make it again");
  if (pattern.pixels.empty() && F.pixels() > 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "pattern has no taps for a ", F.w, " x ", F.h,
                                                   " image");
  for (std::size_t i = 0; i < pattern.pixels.size(); ++i) {
    if (pattern.pixels[i] >= F.pixels())
      FeatureRecon::internal::throw_invalid_argument(fn, "pattern.pixels[", i, "] = ", pattern.pixels[i],
                                                     " is outside the image");
    if (!(std::isfinite(pattern.weights[i]) && pattern.weights[i] >= 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "pattern.weights[", i,
                                                     "] must be finite and >= 0, got ", pattern.weights[i]);
  }
  Bilateral_filter_result result;
  result.sampling_radius = pattern.radius;
  if (F.pixels() == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  // Taps merged per pixel: the pixels holding taps in row-major order with their summed weights and counts.
  std::vector<std::uint32_t> first(F.pixels() + 1, 0);
  for (std::uint32_t q : pattern.pixels) ++first[q + 1];
  std::vector<std::uint32_t> holds;  // pixels with taps
  for (std::size_t q = 0; q < F.pixels(); ++q)
    if (first[q + 1] > 0) holds.push_back(std::uint32_t(q));
  std::vector<float> weight(holds.size(), 0);
  std::vector<std::uint32_t> count(holds.size(), 0);
  {
    std::vector<std::uint32_t> slot(F.pixels(), 0);
    for (std::size_t k = 0; k < holds.size(); ++k) slot[holds[k]] = std::uint32_t(k);
    for (std::size_t i = 0; i < pattern.pixels.size(); ++i) {
      weight[slot[pattern.pixels[i]]] += pattern.weights[i];
      ++count[slot[pattern.pixels[i]]];
    }
  }
  for (std::size_t q = 0; q < F.pixels(); ++q) first[q + 1] = first[q] + (first[q + 1] > 0 ? 1 : 0);
  // The centre pixel enters exactly (weight 1); the other taps stand for 1 / density pixels each.
  const double per_tap = pattern.pixels.empty() ? 0 : double(F.pixels()) / double(pattern.pixels.size());
  filter_pixels(F, progress, result, [&](int x, int y, std::size_t p, Tap_sum& sum) {
    std::size_t taps = 0;
    sum.add(F, p, 1.0);
    const int x0 = x - std::min(F.R, x), x1 = x + std::min(F.R, F.w - 1 - x);
    for (int yy = y - std::min(F.R, y); yy <= y + std::min(F.R, F.h - 1 - y); ++yy) {
      const std::size_t row = std::size_t(yy) * std::size_t(F.w);
      for (std::uint32_t k = first[row + std::size_t(x0)]; k < first[row + std::size_t(x1) + 1]; ++k) {
        const std::size_t q = holds[k];
        taps += count[k];
        if (q == p) continue;
        const double w = per_tap * double(weight[k]) * double(F.spatial_weight(int(q - row) - x, yy - y));
        sum.add(F, q, w * double(F.range[std::size_t(F.d2(p, q))]));
      }
    }
    return taps;
  });
  return result;
}
/// \endcond
}  // namespace internal

/// The bilateral filter on a global tap pattern (the second stage of the global mode): each output pixel
/// sums the taps of `pattern` inside its window, weighted by the kernel and the taps' weights.
/// \param width, height, channels, data the image. \param pattern a pattern of this image's size (checked).
/// \param options the kernel and the progress callback (the sampling fields are not used).
/// \throws std::invalid_argument for a pattern of another size, with inconsistent arrays, without taps or
///   stopped while it was made (status interrupted), and as bilateral_filter().
inline Bilateral_filter_result sampled_bilateral_filter(int width, int height, int channels,
                                                        const std::vector<std::uint8_t>& data,
                                                        const Tap_pattern& pattern,
                                                        const Sampled_bilateral_filter_options& options) {
  const char* fn = "sampled_bilateral_filter";
  const internal::Filter_image F(width, height, channels, data, options.kernel, fn);
  return internal::filter_on_pattern(F, pattern, options.progress, fn);
}

/// The bilateral filter evaluated on sampled taps (dissertation Sec. 2.2.3), in the mode and with the
/// sampling of `options`: global = bilateral_tap_pattern() then the filter on that pattern; local = a pool of
/// `local_patterns` seeded candidate sets of candidates_per_tap * budget * (2R' + 1)^2 uniform positions in
/// the window's square of radius R' = min(R, max(width, height) - 1) (the offsets a tap inside the image can
/// have), each output pixel thinning the set a seeded hash of its index picks by dart throwing (uniform: in
/// the Euclidean distance, the same taps for every window; bilateral: in xi with the window's colours), with
/// the radius calibrated on every window of images up to 4096 pixels, else on 2048 seeded windows, so that
/// the taps over their in-image pixels meet the budget.
/// \param width, height, channels, data the image (as for bilateral_filter()).
/// \param options the kernel, sampling, mode, budget, seed and progress.
/// \returns the filtered values, the taps evaluated and their mean per kernel pixel, the dart radius, and
///   status degenerate_input for an empty image, interrupted (no values) when stopped. Progress: global mode,
///   the pattern up to 0.5 and the pixels from 0.5; local mode, the pool up to 0.05, the radius calibration
///   up to 0.15, pools of longer reach (strongly varying colours) up to 0.2, and the pixels from 0.2. When
///   the longest pool allowed (2^25 neighbour entries) still keeps too many taps, the result has more taps
///   per kernel pixel than the budget (taps_per_kernel_pixel says how many).
/// \throws std::invalid_argument naming the argument, as bilateral_tap_pattern().
/// \note Deterministic: the same image, options and seed give bit-identical values.
inline Bilateral_filter_result sampled_bilateral_filter(
    int width, int height, int channels, const std::vector<std::uint8_t>& data,
    const Sampled_bilateral_filter_options& options = {}) {
  const char* fn = "sampled_bilateral_filter";
  const internal::Filter_image F(width, height, channels, data, options.kernel, fn);
  internal::check_sampled_options(options, fn);
  Bilateral_filter_result result;
  if (F.pixels() == 0) {
    result.status = Status::degenerate_input;
    return result;
  }
  if (options.mode == Tap_mode::global) {
    Sampled_bilateral_filter_options first_stage = options;
    first_stage.progress = [&](double f) {
      return FeatureRecon::internal::report_progress(options.progress, 0.5 * f);
    };
    const Tap_pattern pattern = internal::tap_pattern(F, first_stage);
    if (pattern.status == Status::interrupted) {
      result.status = Status::interrupted;
      return result;
    }
    return internal::filter_on_pattern(
        F, pattern,
        [&](double f) { return FeatureRecon::internal::report_progress(options.progress, 0.5 + 0.5 * f); },
        fn);
  }
  const double factor = internal::feature_factor(options);
  // The pool covers the part of the window an in-image tap can reach: offsets beyond the image's larger side
  // land outside from every pixel. It was sized by the whole window: a 4 x 4 image with radius 200 took 46 s
  // and 2.7 GB, with radius 4096 more memory than there is.
  const int pool_R = std::min(F.R, std::max(0, std::max(F.w, F.h) - 1));
  const double pool_pixels = double(2 * pool_R + 1) * double(2 * pool_R + 1);
  const std::size_t per_set = std::max<std::size_t>(
      2, std::size_t(std::ceil(options.candidates_per_tap * options.budget * pool_pixels)));
  // Euclidean darts keep about 0.7 / r^2 per unit area, so Euclidean radii stay below this reach. A bilateral
  // radius may need more (colours far apart conflict only at long spatial distances: on RGB noise at budget
  // 0.1 the radius stopped at this reach with 0.22 taps per kernel pixel); the pool is then rebuilt with
  // twice the reach, up to the window's diagonal (every pair of a set) or 2^25 neighbour entries (256 MB).
  double reach = 1.6 * std::sqrt(0.7 / options.budget);
  const double diagonal = 2 * std::sqrt(2.0) * (pool_R + 0.5);
  // Progress: the pool up to 0.05, the radius calibration up to 0.15 and the longer reaches up to 0.2 (they
  // ran before the first report: 26 s on a 512 x 512 picture at sigma 20), the pixels from 0.2.
  auto stage = [&options](double a, double b) -> Progress_callback {
    if (!options.progress) return {};
    return [&options, a, b](double t) { return options.progress(a + (b - a) * t); };
  };
  bool stopped = false, short_of_reach = false;
  internal::Local_pool pool(pool_R, options.local_patterns, per_set, reach, options.seed, stage(0, 0.05),
                            stopped);
  double r = stopped ? 0.0
                     : internal::calibrate_local_radius(F, pool, options.budget, factor, options.seed, reach,
                                                        stage(0.05, 0.15), stopped, short_of_reach);
  // Each longer reach reports in the next half of what is left of [0.15, 0.2).
  for (double a = 0.15, b = 0.175; !stopped && short_of_reach && reach < diagonal; a = b, b = (b + 0.2) / 2) {
    const double longer = std::min(2 * reach, diagonal);
    const double share = std::min(1.0, 3.14159 * longer * longer / (4.0 * (pool_R + 0.5) * (pool_R + 0.5)));
    if (double(options.local_patterns) * double(per_set) * double(per_set) / 2 * share > 0x1p25) break;
    reach = longer;
    pool = internal::Local_pool(pool_R, options.local_patterns, per_set, reach, options.seed,
                                stage(a, (a + b) / 2), stopped);
    if (!stopped)
      r = internal::calibrate_local_radius(F, pool, options.budget, factor, options.seed, reach,
                                           stage((a + b) / 2, b), stopped, short_of_reach);
  }
  if (stopped) {
    result.status = Status::interrupted;
    return result;
  }
  result.sampling_radius = r;
  const std::vector<float> comp = options.compensate_density ? internal::density_compensation(F, r, factor)
                                                             : std::vector<float>(F.pixels(), 1.0f);
  // Uniform: the thinned sets do not depend on the image.
  std::vector<std::vector<std::array<int, 2>>> uniform_taps;
  std::vector<char> accepted(per_set);
  std::vector<std::uint32_t> pix(per_set);
  if (factor == 0) {
    const std::vector<std::uint8_t> flat(std::size_t(F.side) * std::size_t(F.side), 0);
    const internal::Filter_image open(F.side, F.side, 1, flat, options.kernel, fn);
    uniform_taps.resize(pool.sets());
    for (std::size_t s = 0; s < pool.sets(); ++s)
      internal::local_darts(open, pool, s, F.R, F.R, r, 0, accepted, pix, [&](std::uint32_t q) {
        uniform_taps[s].push_back(
            {int(q % std::uint32_t(open.w)) - F.R, int(q / std::uint32_t(open.w)) - F.R});
      });
  }
  const double per_tap = 1 / options.budget;
  internal::filter_pixels(F, stage(0.2, 1), result, [&](int x, int y, std::size_t p, internal::Tap_sum& sum) {
    std::size_t taps = 0;
    sum.add(F, p, 1.0);  // the centre pixel exactly; the other taps stand for 1 / budget pixels each
    auto add = [&](std::uint32_t q) {
      ++taps;
      if (q == p) return;
      const int dx = int(q % std::uint32_t(F.w)) - x, dy = int(q / std::uint32_t(F.w)) - y;
      sum.add(F, q,
              per_tap * double(comp[q]) * double(F.spatial_weight(dx, dy)) *
                  double(F.range[std::size_t(F.d2(p, q))]));
    };
    const std::size_t s = internal::local_set(options.seed, p, pool.sets());
    if (factor == 0) {
      for (const auto& t : uniform_taps[s]) {
        const int qx = x + t[0], qy = y + t[1];
        if (qx >= 0 && qy >= 0 && qx < F.w && qy < F.h)
          add(std::uint32_t(qy) * std::uint32_t(F.w) + std::uint32_t(qx));
      }
    } else {
      internal::local_darts(F, pool, s, x, y, r, factor, accepted, pix, add);
    }
    return taps;
  });
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_SAMPLED_BILATERAL_FILTER_H
