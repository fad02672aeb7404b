// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_IO_POINT_CLOUD_IO_H
#define FEATURERECON_SRC_IO_POINT_CLOUD_IO_H

// 3D point clouds with optional normals: PLY (ASCII or binary), OFF (vertices; NOFF for normals) and XYZ
// (x y z [nx ny nz] per line), read through CGAL's point-set I/O and written as ASCII with the shortest
// round-trip digits.

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace io {

struct Point_cloud {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<double, 3>> normals;  ///< empty when the file has none
  /// red, green, blue; empty when the file has none (PLY only)
  std::vector<std::array<unsigned char, 3>> colors;
  bool colors_ignored = false;  ///< the file has colours that are not read (COFF, CNOFF)
  /// the line of each point in a text file (XYZ, OFF); empty for PLY
  std::vector<std::size_t> lines;
  bool has_normals() const { return !normals.empty(); }
  bool has_colors() const { return !colors.empty(); }
  /// "path:LINE: point i" (text files) or "path: point i" (PLY), to begin a message about point i.
  std::string locate(const std::string& path, std::size_t i) const {
    return path + (i < lines.size() ? ":" + std::to_string(lines[i]) : std::string()) + ": point " +
           std::to_string(i);
  }
};

/// Reads PLY, OFF or XYZ by extension (case-insensitive). Normals are read when the file has them (PLY
/// properties nx ny nz, an NOFF header, six numbers per XYZ line), colours from PLY (red green blue, uchar).
/// Throws Input_error naming the file and the problem (unknown extension, unreadable, empty unless
/// `allow_empty`, non-finite coordinates with the point's index, colour properties partial or not uchar).
Point_cloud read_point_cloud(const std::string& path, bool allow_empty = false);

/// Writes the points `indices` of `cloud` (with normals when it has them, and colours in PLY) as PLY (ASCII),
/// OFF (NOFF with normals) or XYZ by the extension of `path`, each number with the fewest significant digits
/// (15 to 17) that read back as the same double.
void write_point_cloud(const std::string& path, const Point_cloud& cloud,
                       const std::vector<std::size_t>& indices);

/// Estimates unit normals (jet fitting over `neighbors` nearest neighbours, then orientation along a
/// minimum spanning tree, CGAL); normals that cannot be oriented keep the fitted direction.
void estimate_normals(Point_cloud& cloud, unsigned neighbors = 18,
                      const std::function<void(double)>& progress = nullptr);

}  // namespace io
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_IO_POINT_CLOUD_IO_H
