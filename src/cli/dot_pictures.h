// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Dots on a raster, as `stipple` and `sample-image` draw them: colours to bytes, the copies of a dot on a
// tile (--periodic), and a dot's anti-aliased coverage.
#ifndef FEATURERECON_CLI_DOT_PICTURES_H
#define FEATURERECON_CLI_DOT_PICTURES_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/image_io.h"

namespace FeatureRecon {
namespace cli {

/// A channel in [0, 1] (clamped) as a byte, rounded.
inline std::uint8_t to_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::min(1.0, std::max(0.0, v)) * 255));
}

/// Where a dot of radius `dot` at p is drawn: at p and, for a tile (--periodic), at each of its copies
/// shifted by whole widths and heights of the picture that reaches into it, so that tiles laid side by side
/// continue the dots across their seams.
inline std::vector<std::array<double, 2>> drawn_at(const std::array<double, 2>& p, double dot, int width,
                                                   int height, bool periodic) {
  std::vector<std::array<double, 2>> at{p};
  if (!periodic) return at;
  const int ki = int(std::ceil(dot / width)), kj = int(std::ceil(dot / height));
  for (int i = -ki; i <= ki; ++i)
    for (int j = -kj; j <= kj; ++j) {
      const std::array<double, 2> q{p[0] + double(i) * width, p[1] + double(j) * height};
      if ((i != 0 || j != 0) && q[0] + dot > 0 && q[0] - dot < width && q[1] + dot > 0 && q[1] - dot < height)
        at.push_back(q);
    }
  return at;
}

/// Blends a dot of radius `dot` centred at (x, y) in `colour` into `rgb` (width x height, 3 channels in [0,
/// 1]), each pixel by its coverage from 4 x 4 supersampling.
inline void paint_dot(std::vector<double>& rgb, int width, int height, double x, double y, double dot,
                      const std::array<double, 3>& colour) {
  const int c0 = std::max(0, static_cast<int>(std::floor(x - dot))),
            c1 = std::min(width - 1, static_cast<int>(x + dot));
  const int r0 = std::max(0, static_cast<int>(std::floor(y - dot))),
            r1 = std::min(height - 1, static_cast<int>(y + dot));
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      int inside = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double dx = c + (a + 0.5) / 4 - x, dy = r + (b + 0.5) / 4 - y;
          inside += dx * dx + dy * dy <= dot * dot;
        }
      const double w = inside / 16.0;
      double* p = &rgb[(std::size_t(r) * std::size_t(width) + std::size_t(c)) * 3];
      for (std::size_t k = 0; k < 3; ++k) p[k] = (1 - w) * p[k] + w * colour[k];
    }
}

/// The RGB picture of `rgb` (channels in [0, 1]).
inline io::Image rgb_picture(const std::vector<double>& rgb, int width, int height) {
  io::Image picture;
  picture.width = width;
  picture.height = height;
  picture.channels = 3;
  picture.data.resize(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) picture.data[i] = to_byte(rgb[i]);
  return picture;
}

}  // namespace cli
}  // namespace FeatureRecon

#endif  // FEATURERECON_CLI_DOT_PICTURES_H
