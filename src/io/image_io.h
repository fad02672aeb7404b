// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_IO_IMAGE_IO_H
#define FEATURERECON_SRC_IO_IMAGE_IO_H

// 8-bit grey and RGB images: PNG (libpng), JPEG (libjpeg) and binary or ASCII PGM/PPM.

#include <cstdint>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace io {

/// An 8-bit image, rows from the top, `channels` interleaved values per pixel.
struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;                ///< 1 (grey) or 3 (RGB)
  std::vector<std::uint8_t> data;  ///< width * height * channels values
  std::uint8_t at(int column, int row, int channel = 0) const {
    return data[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * std::size_t(channels) +
                std::size_t(channel)];
  }
};

/// Reads PNG, JPEG (.jpg, .jpeg), PGM or PPM by extension (case-insensitive). Palette, 16-bit and alpha PNGs
/// are converted to 8-bit grey or RGB (transparency composited onto white); CMYK JPEGs are rejected. Throws
/// Input_error naming the file and the problem.
Image read_image(const std::string& path);

/// Writes PNG, JPEG (quality 95), PGM (grey) or PPM (RGB; grey is expanded) by extension. Throws Input_error.
void write_image(const std::string& path, const Image& image);

/// Luma (ITU-R BT.601: 0.299 R + 0.587 G + 0.114 B) of an RGB image rounded to 8 bits; a grey image as it is.
Image to_grey(const Image& image);

}  // namespace io
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_IO_IMAGE_IO_H
