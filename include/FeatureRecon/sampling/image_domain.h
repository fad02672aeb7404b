// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_IMAGE_DOMAIN_H
#define FEATURERECON_SAMPLING_IMAGE_DOMAIN_H

/// \file
/// An 8-bit image as a sampling domain: its pixels as items for the discrete samplers (Grey_pixel or
/// Rgb_pixel with Pixel_traits), or the continuous rectangle [0, width) x [0, height) with bilinearly
/// interpolated colours for continuous_bilateral_dart_throwing().

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

namespace internal {
/// \cond
inline void check_image(int width, int height, std::size_t channels, std::size_t values, const char* fn) {
  if (width < 0 || height < 0)
    FeatureRecon::internal::throw_invalid_argument(fn, "width and height must be >= 0, got ", width, " x ",
                                                   height);
  const std::size_t expected = std::size_t(width) * std::size_t(height) * channels;
  if (values != expected)
    FeatureRecon::internal::throw_invalid_argument(fn, "data has ", values, " values, a ", width, " x ",
                                                   height, " image with ", channels, " channel(s) needs ",
                                                   expected);
}
/// \endcond
}  // namespace internal

/// The pixels of an 8-bit image as sampler items, rows from the top, channels interleaved.
/// \tparam Pixel Grey_pixel (1 channel) or Rgb_pixel (3 channels).
/// \param width columns (>= 0). \param height rows (>= 0).
/// \param data width * height * channels values (checked; throws std::invalid_argument naming the sizes).
template <class Pixel>
std::vector<Pixel> image_pixels(int width, int height, const std::vector<std::uint8_t>& data) {
  static_assert(std::is_same<Pixel, Grey_pixel>::value || std::is_same<Pixel, Rgb_pixel>::value,
                "FeatureRecon: image_pixels makes Grey_pixel or Rgb_pixel");
  constexpr std::size_t channels = std::is_same<Pixel, Rgb_pixel>::value ? 3 : 1;
  internal::check_image(width, height, channels, data.size(), "image_pixels");
  std::vector<Pixel> pixels(std::size_t(width) * std::size_t(height));
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const std::size_t i = std::size_t(row) * std::size_t(width) + std::size_t(column);
      Pixel& p = pixels[i];
      p.column = column;
      p.row = row;
      if constexpr (channels == 1)
        p.value = data[i];
      else
        for (std::size_t c = 0; c < 3; ++c) p.rgb[c] = data[3 * i + c];
    }
  return pixels;
}

/// An 8-bit image as a continuous domain: the box [0, width) x [0, height) in pixel units (x to the right, y
/// down, pixel (column, row) centred at (column + 1/2, row + 1/2), as Pixel_traits places it), with the
/// colour interpolated bilinearly between pixel centres and held constant beyond the outer centres. Channel
/// values are scaled to [0, 1]. Keeps its own copy of the pixels.
/// \tparam Channels 1 (grey) or 3 (RGB).
template <std::size_t Channels>
class Bilinear_image {
  static_assert(Channels == 1 || Channels == 3, "FeatureRecon: Bilinear_image has 1 or 3 channels");

 public:
  using Feature = std::array<double, Channels>;  ///< the interpolated channels, each in [0, 1]

  /// \param width columns (>= 0). \param height rows (>= 0).
  /// \param data width * height * Channels values, rows from the top, channels interleaved (checked; throws
  ///   std::invalid_argument naming the sizes). An empty image (width or height 0) has an empty box.
  Bilinear_image(int width, int height, std::vector<std::uint8_t> data)
      : m_width(width), m_height(height), m_data(std::move(data)) {
    internal::check_image(width, height, Channels, m_data.size(), "Bilinear_image");
  }

  int width() const { return m_width; }    ///< in pixels
  int height() const { return m_height; }  ///< in pixels
  /// The domain {x0, y0, x1, y1} = {0, 0, width, height}, the box continuous_bilateral_dart_throwing() takes.
  std::array<double, 4> box() const { return {0.0, 0.0, double(m_width), double(m_height)}; }

  /// The colour at (x, y). \pre the image is not empty and x, y are finite.
  /// \param x column coordinate in pixels. \param y row coordinate in pixels (down).
  Feature operator()(double x, double y) const {
    const double u = clamp(x - 0.5, m_width), v = clamp(y - 0.5, m_height);
    const int c0 = static_cast<int>(std::floor(u)), r0 = static_cast<int>(std::floor(v));
    const int c1 = std::min(c0 + 1, m_width - 1), r1 = std::min(r0 + 1, m_height - 1);
    const double s = u - c0, t = v - r0;
    Feature f;
    for (std::size_t k = 0; k < Channels; ++k) {
      const double top = (1 - s) * at(c0, r0, k) + s * at(c1, r0, k);
      const double bottom = (1 - s) * at(c0, r1, k) + s * at(c1, r1, k);
      f[k] = ((1 - t) * top + t * bottom) / 255.0;
    }
    return f;
  }

 private:
  static double clamp(double u, int size) { return std::min(std::max(u, 0.0), double(size - 1)); }
  double at(int column, int row, std::size_t channel) const {
    return m_data[(std::size_t(row) * std::size_t(m_width) + std::size_t(column)) * Channels + channel];
  }
  int m_width, m_height;
  std::vector<std::uint8_t> m_data;
};

/// Squared colour distance of two interpolated colours: the mean squared channel difference, in [0, 1] (the
/// same scale as Pixel_traits' feature distance, so one sigma_feature means the same for pixels and for the
/// continuous image).
struct Mean_squared_channel_distance {
  /// The distance. \tparam C the number of channels. \param a one colour. \param b the other.
  template <std::size_t C>
  double operator()(const std::array<double, C>& a, const std::array<double, C>& b) const {
    double s = 0;
    for (std::size_t k = 0; k < C; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return s / double(C);
  }
};

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_IMAGE_DOMAIN_H
