// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_IO_SKELETON_IO_H
#define FEATURERECON_SRC_IO_SKELETON_IO_H

// Writers of a skeleton graph: GraphML, GeoJSON (2D), PLY polylines (3D) and an SVG picture with the input
// points.

#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/map_comparison.h>

#include <array>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace io {

/// GraphML: nodes with x, y, z, value and type; edges with the polyline as "x y z;x y z;..." and the member
/// count.
void write_skeleton_graphml(const std::string& path, const skeleton::Skeleton_graph& g);
/// GeoJSON FeatureCollection: one LineString per arc (its polyline, x y) and one Point per node (properties
/// type and value). Coordinates are written as given (e.g. UTM metres; longitude and latitude, as RFC 7946
/// asks, with skeleton --lonlat). With `lonlat` (x, y are longitude and latitude in degrees) an arc that
/// crosses the antimeridian (a step of more than 180 degrees of longitude) is cut there into a
/// MultiLineString, as RFC 7946 (3.1.9) asks: viewers draw the step round the globe.
void write_skeleton_geojson(const std::string& path, const skeleton::Skeleton_graph& g, bool lonlat = false);
/// ASCII PLY: the polyline points as vertices and consecutive pairs as edges (3D).
void write_skeleton_ply(const std::string& path, const skeleton::Skeleton_graph& g);
/// Scale of a skeleton picture.
struct Skeleton_picture_options {
  /// The length at which the data's structure shows, in data units (the Rips radius): the page is sized to
  /// draw it 3 pixels long within 1000 to 4000 pixels (skeleton_picture_long_side), and the marks are scaled
  /// to it: dots a fifth, arcs and nodes a half of it in pixels, at most 1, 2 and 3. 0 (or not finite): a
  /// 1000-pixel page and marks of 1, 2 and 3.
  double feature_size = 0;
  /// The page's longer side in pixels, plus a margin of 10 on each side; 0: automatic.
  double long_side = 0;
};
/// The automatic page size: 3 pixels per feature size, at least 1000 and at most 4000 pixels on the longer
/// side (beyond 1333 feature sizes across, the feature size is drawn shorter than 3 pixels); 1000 when either
/// length is 0 or not finite. The ink of 1,000 handwritten digits (1994 pixels across) at radius 1.5 gets
/// 3988 (2 pixels a pixel); 4 km of GPS traces at radius 24 m, 1000.
double skeleton_picture_long_side(double data_long_side, double feature_size);
/// Picture of the input points (grey) and the skeleton (arcs as coloured polylines, nodes black), in x y:
/// SVG, or PNG, JPEG, PGM, PPM by the extension (the same drawing rasterised; about 15 bytes a pixel). Points
/// are discs of radius 1 pixel, arcs 2 pixels wide and nodes discs of radius 3 pixels, each at most a fifth,
/// a half and a half of the feature size in pixels (at least 0.3, 0.5 and 0.75).
void write_skeleton_picture(const std::string& path, const std::vector<std::array<double, 2>>& points,
                            const skeleton::Skeleton_graph& g, const Skeleton_picture_options& options = {});

/// Picture of a map comparison (needs a result computed with keep_samples): ground-truth samples green when
/// matched and red when missed, reconstruction samples blue when matched and orange when spurious; a thin
/// line joins each matched pair. SVG, or PNG, JPEG, PGM, PPM by the extension.
void write_map_comparison_picture(const std::string& path, const skeleton::Map_comparison_result& r);
/// CSV of a map comparison (needs keep_samples): 'map,index,x,y,bearing,partner' with map 'truth' or
/// 'reconstruction' and partner the index of the matched sample in the other map, or -1.
void write_map_comparison_csv(const std::string& path, const skeleton::Map_comparison_result& r);

}  // namespace io
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_IO_SKELETON_IO_H
