// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "skeleton_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "featurerecon_io.h"
#include "picture.h"

namespace FeatureRecon {
namespace io {
namespace {
using skeleton::Skeleton_graph;

/// Data values (GraphML, GeoJSON, PLY, CSV): every bit kept.
std::string number(double x) { return format_double(x); }

/// A picture frame: the bounding box of what is added, scaled to `size` pixels on its longer side, y upwards.
class Picture_frame {
 public:
  void extend(double x, double y) {
    if (!(std::isfinite(x) && std::isfinite(y))) return;  // not drawn (Picture leaves such shapes out)
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  /// The page (white), `size` pixels on the longer side of the box plus a margin; call after the last
  /// extend(). Differences are taken of halves (x / 2 - x0 / 2): a box from -1e308 to 1e308 is wider than the
  /// largest double. A box of one position (or of a span below the denormals) gets a square page with that
  /// position in its centre.
  Picture open(double size) {
    if (!(x0 <= x1)) x0 = y0 = 0, x1 = y1 = 1;
    double half = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
    if (!(half > 0) || !std::isfinite(size / half)) {
      scale = 0;  // every position drawn at the centre
      centre = size / 2;
      return Picture(2 * margin + size, 2 * margin + size);
    }
    scale = size / half;
    return Picture(2 * margin + (x1 / 2 - x0 / 2) * scale, 2 * margin + (y1 / 2 - y0 / 2) * scale);
  }
  double X(double x) const { return margin + centre + (x / 2 - x0 / 2) * scale; }
  double Y(double y) const { return margin + centre + (y1 / 2 - y / 2) * scale; }
  /// The longer side of the box (infinite beyond the largest double; 0 for one point or nothing added).
  double long_side() const { return x0 <= x1 ? std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2) * 2 : 0.0; }
  /// Pixels per data unit; valid after open() (`scale` is per half unit).
  double pixels_per_unit() const { return scale / 2; }

 private:
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  double x0 = infinity, y0 = infinity, x1 = -infinity, y1 = -infinity, scale = 1, margin = 10, centre = 0;
};
}  // namespace

void write_skeleton_graphml(const std::string& path, const Skeleton_graph& g) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\">\n"
        "  <key id=\"x\" for=\"node\" attr.name=\"x\" attr.type=\"double\"/>\n"
        "  <key id=\"y\" for=\"node\" attr.name=\"y\" attr.type=\"double\"/>\n"
        "  <key id=\"z\" for=\"node\" attr.name=\"z\" attr.type=\"double\"/>\n"
        "  <key id=\"value\" for=\"node\" attr.name=\"value\" attr.type=\"double\"/>\n"
        "  <key id=\"type\" for=\"node\" attr.name=\"type\" attr.type=\"string\"/>\n"
        "  <key id=\"polyline\" for=\"edge\" attr.name=\"polyline\" attr.type=\"string\"/>\n"
        "  <key id=\"members\" for=\"edge\" attr.name=\"members\" attr.type=\"int\"/>\n"
        "  <graph id=\"skeleton\" edgedefault=\"undirected\">\n";
  for (auto v : boost::make_iterator_range(vertices(g))) {
    const auto& n = g[v];
    os << "    <node id=\"n" << v << "\"><data key=\"x\">" << number(n.position[0])
       << "</data><data key=\"y\">" << number(n.position[1]) << "</data><data key=\"z\">"
       << number(n.position[2]) << "</data><data key=\"value\">" << number(n.value)
       << "</data><data key=\"type\">" << skeleton::node_type_name(n.type) << "</data></node>\n";
  }
  std::size_t k = 0;
  for (auto e : boost::make_iterator_range(edges(g))) {
    os << "    <edge id=\"e" << k++ << "\" source=\"n" << source(e, g) << "\" target=\"n" << target(e, g)
       << "\"><data key=\"polyline\">";
    bool first = true;
    for (const auto& p : g[e].polyline) {
      os << (first ? "" : ";") << number(p[0]) << " " << number(p[1]) << " " << number(p[2]);
      first = false;
    }
    os << "</data><data key=\"members\">" << g[e].members.size() << "</data></edge>\n";
  }
  os << "  </graph>\n</graphml>\n";
  write_text_file(path, os.str());
}

namespace {

/// The parts of a polyline of (longitude, latitude) in degrees cut where a step crosses the antimeridian
/// (changes longitude by more than 180 degrees: the short way round goes across +-180). Each cut ends one
/// part at +-180 and starts the next at -+180, at the latitude interpolated along the step.
std::vector<std::vector<std::array<double, 2>>> cut_at_antimeridian(
    const std::vector<std::array<double, 3>>& line) {
  std::vector<std::vector<std::array<double, 2>>> parts(1);
  for (std::size_t i = 0; i < line.size(); ++i) {
    const std::array<double, 2> p{line[i][0], line[i][1]};
    if (i > 0 && std::fabs(p[0] - line[i - 1][0]) > 180) {
      const double from = line[i - 1][0], side = from > 0 ? 180.0 : -180.0;  // the side the step leaves from
      const double to = p[0] + 2 * side;                                     // p's longitude on that side
      const double t = (side - from) / (to - from);
      const double latitude = line[i - 1][1] + t * (p[1] - line[i - 1][1]);
      if (parts.back().back()[0] != side) parts.back().push_back({side, latitude});
      parts.emplace_back();
      if (p[0] != -side) parts.back().push_back({-side, latitude});
    }
    parts.back().push_back(p);
  }
  // A part of one position (a line starting or ending on the antimeridian) is not a line.
  parts.erase(std::remove_if(parts.begin(), parts.end(), [](const auto& part) { return part.size() < 2; }),
              parts.end());
  if (parts.empty()) {  // only steps from +180 to -180 or back: the line as it is
    parts.emplace_back();
    for (const auto& p : line) parts.back().push_back({p[0], p[1]});
  }
  return parts;
}

void write_positions(std::ostream& os, const std::vector<std::array<double, 2>>& part) {
  os << "[";
  for (std::size_t i = 0; i < part.size(); ++i)
    os << (i ? ", " : "") << "[" << number(part[i][0]) << ", " << number(part[i][1]) << "]";
  os << "]";
}

}  // namespace

void write_skeleton_geojson(const std::string& path, const Skeleton_graph& g, bool lonlat) {
  std::ostringstream os;
  os << "{\"type\": \"FeatureCollection\", \"features\": [\n";
  bool first = true;
  for (auto e : boost::make_iterator_range(edges(g))) {
    std::vector<std::vector<std::array<double, 2>>> parts;
    if (lonlat) {
      parts = cut_at_antimeridian(g[e].polyline);
    } else {
      parts.emplace_back();
      for (const auto& p : g[e].polyline) parts.back().push_back({p[0], p[1]});
    }
    os << (first ? "" : ",\n") << "{\"type\": \"Feature\", \"geometry\": {\"type\": \""
       << (parts.size() == 1 ? "LineString" : "MultiLineString") << "\", \"coordinates\": ";
    first = false;
    if (parts.size() == 1) {
      write_positions(os, parts.front());
    } else {
      os << "[";
      for (std::size_t k = 0; k < parts.size(); ++k) {
        os << (k ? ", " : "");
        write_positions(os, parts[k]);
      }
      os << "]";
    }
    os << "}, \"properties\": {\"kind\": \"arc\", \"members\": " << g[e].members.size() << "}}";
  }
  for (auto v : boost::make_iterator_range(vertices(g))) {
    const auto& n = g[v];
    os << (first ? "" : ",\n")
       << "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": ["
       << number(n.position[0]) << ", " << number(n.position[1])
       << "]}, \"properties\": {\"kind\": \"node\", \"type\": \"" << skeleton::node_type_name(n.type)
       << "\", \"value\": " << number(n.value) << "}}";
    first = false;
  }
  os << "\n]}\n";
  write_text_file(path, os.str());
}

void write_skeleton_ply(const std::string& path, const Skeleton_graph& g) {
  // The nodes first (PLY vertex i is node i), then the interior points of each arc's polyline: arcs meeting
  // at a node share its vertex, so the edges form the skeleton's graph. A polyline end away from its node's
  // position (not written by the embedding) gets a vertex of its own.
  std::vector<std::array<double, 3>> pts;
  std::vector<std::array<std::size_t, 2>> segs;
  for (auto v : boost::make_iterator_range(vertices(g))) pts.push_back(g[v].position);
  for (auto e : boost::make_iterator_range(edges(g))) {
    const auto& line = g[e].polyline;
    const std::size_t ends[2] = {static_cast<std::size_t>(source(e, g)),
                                 static_cast<std::size_t>(target(e, g))};
    std::size_t previous = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
      std::size_t index = pts.size();
      if (i == 0 || i + 1 == line.size())
        for (const std::size_t node : ends)
          if (pts[node] == line[i]) index = node;
      if (index == pts.size()) pts.push_back(line[i]);
      if (i > 0) segs.push_back({previous, index});
      previous = index;
    }
  }
  std::ostringstream os;
  os << "ply\nformat ascii 1.0\ncomment FeatureRecon skeleton: the first " << num_vertices(g)
     << " vertices are its nodes, the edges draw its arcs as polylines\nelement vertex " << pts.size()
     << "\nproperty double x\nproperty double y\nproperty double z\nelement edge " << segs.size()
     << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (const auto& p : pts) os << number(p[0]) << " " << number(p[1]) << " " << number(p[2]) << "\n";
  for (const auto& s : segs) os << s[0] << " " << s[1] << "\n";
  write_text_file(path, os.str());
}

double skeleton_picture_long_side(double data_long_side, double feature_size) {
  if (!(feature_size > 0 && std::isfinite(feature_size) && data_long_side > 0 &&
        std::isfinite(data_long_side)))
    return 1000.0;
  return std::clamp(3 * (data_long_side / feature_size), 1000.0,
                    4000.0);  // NaN-free: both finite and positive
}

void write_skeleton_picture(const std::string& path, const std::vector<std::array<double, 2>>& points,
                            const Skeleton_graph& g, const Skeleton_picture_options& options) {
  Picture_frame frame;
  for (const auto& p : points) frame.extend(p[0], p[1]);
  for (auto v : boost::make_iterator_range(vertices(g))) frame.extend(g[v].position[0], g[v].position[1]);
  for (auto e : boost::make_iterator_range(edges(g)))
    for (const auto& p : g[e].polyline) frame.extend(p[0], p[1]);
  const double feature_size = options.feature_size;
  const bool scaled = feature_size > 0 && std::isfinite(feature_size);
  Picture picture =
      frame.open(options.long_side > 0 ? options.long_side
                                       : skeleton_picture_long_side(frame.long_side(), feature_size));
  // Mark sizes in pixels: at most 1 (points), 2 (arc width) and 3 (nodes); a fifth, a half and a half of the
  // feature size drawn (finer below 5, 4 and 6 pixels), so that points a feature size apart and the arcs
  // between them stay apart.
  const double feature_pixels =
      scaled && frame.pixels_per_unit() > 0 ? feature_size * frame.pixels_per_unit() : 10.0;
  const double point_radius = std::clamp(feature_pixels / 5, 0.3, 1.0);
  const double arc_width = std::clamp(feature_pixels / 2, 0.5, 2.0);
  const double node_radius = std::clamp(feature_pixels / 2, 0.75, 3.0);
  for (const auto& p : points) picture.disc(frame.X(p[0]), frame.Y(p[1]), point_radius, "#c0c0c0");
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                           "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  std::size_t k = 0;
  for (auto e : boost::make_iterator_range(edges(g))) {
    std::vector<std::array<double, 2>> line;
    for (const auto& p : g[e].polyline) line.push_back({frame.X(p[0]), frame.Y(p[1])});
    picture.polyline(line, arc_width, colours[k++ % 8]);
  }
  for (auto v : boost::make_iterator_range(vertices(g)))
    picture.disc(frame.X(g[v].position[0]), frame.Y(g[v].position[1]), node_radius, "black");
  picture.write(path);
}

void write_map_comparison_picture(const std::string& path, const skeleton::Map_comparison_result& r) {
  const auto& H = r.ground_truth_sample_list;
  const auto& G = r.reconstruction_sample_list;
  Picture_frame frame;
  for (const auto* list : {&H, &G})
    for (const auto& s : *list) frame.extend(s.position[0], s.position[1]);
  Picture picture = frame.open(1600.0);
  for (std::size_t h = 0; h < H.size(); ++h) {
    const std::int64_t g = r.ground_truth_partner[h];
    const double x = frame.X(H[h].position[0]), y = frame.Y(H[h].position[1]);
    if (g >= 0) {
      const auto& q = G[static_cast<std::size_t>(g)].position;
      picture.line(x, y, frame.X(q[0]), frame.Y(q[1]), 0.5, "#b0b0b0");
    }
    picture.disc(x, y, 1.5, g >= 0 ? "#2ca02c" : "#d62728");
  }
  for (std::size_t g = 0; g < G.size(); ++g)
    picture.disc(frame.X(G[g].position[0]), frame.Y(G[g].position[1]), 1,
                 r.reconstruction_partner[g] >= 0 ? "#1f77b4" : "#ff7f0e");
  picture.write(path);
}

void write_map_comparison_csv(const std::string& path, const skeleton::Map_comparison_result& r) {
  std::ostringstream os;
  os << "map,index,x,y,bearing,partner\n";
  auto rows = [&](const char* name, const std::vector<skeleton::Map_sample>& list,
                  const std::vector<std::int64_t>& partner) {
    for (std::size_t i = 0; i < list.size(); ++i)
      os << name << ',' << i << ',' << number(list[i].position[0]) << ',' << number(list[i].position[1])
         << ',' << number(list[i].bearing) << ',' << partner[i] << '\n';
  };
  rows("truth", r.ground_truth_sample_list, r.ground_truth_partner);
  rows("reconstruction", r.reconstruction_sample_list, r.reconstruction_partner);
  write_text_file(path, os.str());
}

}  // namespace io
}  // namespace FeatureRecon
