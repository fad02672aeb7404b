// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_IO_PICTURE_H
#define FEATURERECON_SRC_IO_PICTURE_H

// A vector picture (discs, lines, polylines on a white page) written as SVG text or rasterised, anti-aliased,
// as PNG, JPEG, PGM or PPM: the same drawing either way, chosen by the file's extension. Shapes with a
// non-finite coordinate are left out of both.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "image_io.h"

namespace FeatureRecon {
namespace io {

/// Whether `path` names a format Picture::write knows (.svg, .png, .jpg, .jpeg, .pgm, .ppm;
/// case-insensitive).
bool is_picture_file(const std::string& path);

class Picture {
 public:
  /// A page of `width` x `height` pixels (y downwards), white.
  Picture(double width, double height);
  /// A filled disc; `colour` is "#rrggbb".
  void disc(double x, double y, double radius, const std::string& colour);
  void line(double x1, double y1, double x2, double y2, double width, const std::string& colour);
  /// An open polyline of constant width (joints drawn once, not darkened by overlap).
  void polyline(const std::vector<std::array<double, 2>>& points, double width, const std::string& colour);

  /// The SVG text (coordinates with two decimals).
  std::string svg() const;
  /// The raster (RGB, ceil(width) x ceil(height)); coverage from the distance of each pixel centre to the
  /// shape.
  Image raster() const;
  /// Writes by the extension of `path` (see is_picture_file); throws Input_error for another extension.
  void write(const std::string& path) const;

 private:
  enum class Kind { disc, line, polyline };
  struct Shape {
    Kind kind;
    std::vector<std::array<double, 2>> points;  // disc: the centre; line: two points
    double size;                                // disc: radius; line, polyline: width
    std::string colour;
  };
  double m_width, m_height;
  std::vector<Shape> m_shapes;
};

}  // namespace io
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_IO_PICTURE_H
