// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_IMAGE_QUALITY_H
#define FEATURERECON_SAMPLING_IMAGE_QUALITY_H

/// \file
/// Full-reference image quality: the peak signal-to-noise ratio and the structural similarity index (Wang,
/// Bovik, Sheikh and Simoncelli 2004) of a picture against a reference, on 8-bit scaled values (0..255) held
/// as any arithmetic type, so that unrounded filter outputs can be compared without quantisation noise.

#include <FeatureRecon/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace sampling {

namespace internal {
/// \cond
template <class A, class B>
void check_same_images(int width, int height, int channels, const std::vector<A>& reference,
                       const std::vector<B>& picture, const char* fn) {
  if (width < 0 || height < 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "width and height must be >= 0, got ", width, " x ",
                                                   height);
  if (channels < 1)
    FeatureRecon::internal::throw_invalid_argument(fn, "channels must be >= 1, got ", channels);
  const std::size_t expected = std::size_t(width) * std::size_t(height) * std::size_t(channels);
  if (reference.size() != expected)
    FeatureRecon::internal::throw_invalid_argument(fn, "reference has ", reference.size(), " values, a ",
                                                   width, " x ", height, " image with ", channels,
                                                   " channel(s) needs ", expected);
  if (picture.size() != expected)
    FeatureRecon::internal::throw_invalid_argument(fn, "picture has ", picture.size(), " values, a ", width,
                                                   " x ", height, " image with ", channels,
                                                   " channel(s) needs ", expected);
}

/// One pass of a separable Gaussian blur along x (along_x) or y, with the taps renormalised where the window
/// leaves the image.
inline std::vector<double> blur_pass(const std::vector<double>& plane, int width, int height,
                                     const std::vector<double>& taps, bool along_x) {
  const int radius = int(taps.size() / 2), extent = along_x ? width : height;
  std::vector<double> out(plane.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int at = along_x ? x : y;
      double sum = 0, weight = 0;
      for (int k = std::max(-radius, -at); k <= std::min(radius, extent - 1 - at); ++k) {
        const std::size_t q = along_x ? std::size_t(y) * std::size_t(width) + std::size_t(x + k)
                                      : std::size_t(y + k) * std::size_t(width) + std::size_t(x);
        sum += taps[std::size_t(k + radius)] * plane[q];
        weight += taps[std::size_t(k + radius)];
      }
      out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = sum / weight;
    }
  return out;
}

inline std::vector<double> blur_plane(const std::vector<double>& plane, int width, int height,
                                      const std::vector<double>& taps) {
  return blur_pass(blur_pass(plane, width, height, taps, true), width, height, taps, false);
}
/// \endcond
}  // namespace internal

/// Peak signal-to-noise ratio in dB, 10 log10(peak^2 / MSE), over every value of every channel.
/// \tparam A, B arithmetic value types (std::uint8_t, float, double).
/// \param reference the reference values (for a filter: the exact result). \param picture the values
///   compared, as many as the reference (checked; throws std::invalid_argument naming the sizes).
/// \param peak the largest possible value (> 0); default 255.
/// \returns +infinity when the two are equal; NaN for empty inputs.
template <class A, class B>
double psnr(const std::vector<A>& reference, const std::vector<B>& picture, double peak = 255) {
  if (reference.size() != picture.size())
    FeatureRecon::internal::throw_invalid_argument("psnr", "picture has ", picture.size(),
                                                   " values, reference has ", reference.size());
  if (!(std::isfinite(peak) && peak > 0))
    FeatureRecon::internal::throw_invalid_argument("psnr", "peak must be finite and > 0, got ", peak);
  if (reference.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const double d = double(reference[i]) - double(picture[i]);
    sum += d * d;
  }
  const double mse = sum / double(reference.size());
  return mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(peak * peak / mse);
}

/// Mean structural similarity index (SSIM) of a picture against a reference, both width x height with
/// `channels` interleaved values per pixel on the 0..255 scale: local means, variances and covariance under
/// an 11 x 11 Gaussian window of sigma 1.5 (renormalised where it leaves the image, so every pixel counts),
/// C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2, averaged over the pixels and then over the channels.
/// \tparam A, B arithmetic value types.
/// \param width, height the image size (>= 0). \param channels values per pixel (>= 1).
/// \param reference, picture width * height * channels values each (checked; throws std::invalid_argument
///   naming the argument and the sizes).
/// \returns a value in [-1, 1], 1 when the two are equal; NaN for an empty image.
template <class A, class B>
double ssim(int width, int height, int channels, const std::vector<A>& reference,
            const std::vector<B>& picture) {
  internal::check_same_images(width, height, channels, reference, picture, "ssim");
  const std::size_t n = std::size_t(width) * std::size_t(height);
  if (n == 0) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> taps(11);
  double total = 0;
  for (int k = -5; k <= 5; ++k)
    total += taps[std::size_t(k + 5)] = std::exp(-double(k * k) / (2 * 1.5 * 1.5));
  for (double& t : taps) t /= total;
  const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double mean_over_channels = 0;
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (int c = 0; c < channels; ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = double(reference[i * std::size_t(channels) + std::size_t(c)]);
      y[i] = double(picture[i * std::size_t(channels) + std::size_t(c)]);
      xx[i] = x[i] * x[i];
      yy[i] = y[i] * y[i];
      xy[i] = x[i] * y[i];
    }
    const auto mx = internal::blur_plane(x, width, height, taps),
               my = internal::blur_plane(y, width, height, taps);
    const auto mxx = internal::blur_plane(xx, width, height, taps),
               myy = internal::blur_plane(yy, width, height, taps);
    const auto mxy = internal::blur_plane(xy, width, height, taps);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double vx = std::max(0.0, mxx[i] - mx[i] * mx[i]), vy = std::max(0.0, myy[i] - my[i] * my[i]);
      // Clamped by Cauchy-Schwarz as the variances are clamped at 0: a constant picture against itself has
      // variances rounded below 0 (clamped) and the same negative covariance, which scored 0.9999999999986.
      const double bound = std::sqrt(vx * vy),
                   cxy = std::min(bound, std::max(-bound, mxy[i] - mx[i] * my[i]));
      sum += ((2 * mx[i] * my[i] + c1) * (2 * cxy + c2)) /
             ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    mean_over_channels += sum / double(n);
  }
  return mean_over_channels / double(channels);
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_IMAGE_QUALITY_H
