// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Skeletons of handwriting (dissertation Fig. 3.5, a hand-written character): 1,000 handwritten digits, 100
// of each, 20 x 20 pixels (a crop of OpenCV's digits.png, data/images/). The ink pixels of each digit (grey
// >= 128) are a point set on the pixel grid, a degenerate input full of equal distances;
// extract_reeb_skeleton() with a Rips radius of 1.5 pixels (each pixel's 8 neighbours) and delta 3 pixels
// gives its skeleton. The program checks the skeleton's topology against the ink's own: one component per
// 8-connected piece of ink, and one loop per hole (4-connected background not reaching the border) of at
// least 3 pixels, where holes of 2 pixels may stay and single pixels go (their loops have persistence below
// delta). It prints a table per digit; with --svg FILE it draws the first 10 digits of each kind with their
// skeletons (doc/images/handwriting_skeleton.svg).
//
// usage: handwriting_skeleton [--svg FILE]

#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace sk = FeatureRecon::skeleton;

namespace {

constexpr int cell = 20;  // pixels per digit, each way

/// A binary PGM (P5, 8 bits); empty when the file cannot be read.
struct Grey_image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> grey;
};

Grey_image read_pgm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0, maximum = 0;
  in >> magic >> width >> height >> maximum;
  in.get();  // the single white space after the header
  Grey_image image;
  if (!in || magic != "P5" || width <= 0 || height <= 0 || maximum != 255) return image;
  image.grey.resize(std::size_t(width) * std::size_t(height));
  in.read(reinterpret_cast<char*>(image.grey.data()), static_cast<std::streamsize>(image.grey.size()));
  if (!in) image.grey.clear();
  image.width = width;
  image.height = height;
  return image;
}

/// One digit: which of its pixels are ink, row by row.
using Ink = std::array<bool, cell * cell>;

/// The topology of the ink itself: 8-connected pieces of ink and the sizes of its holes (4-connected pieces
/// of background that do not reach the border), by flood fill.
struct Ink_topology {
  std::size_t pieces = 0;
  std::vector<std::size_t> holes;
};

Ink_topology ink_topology(const Ink& ink) {
  Ink_topology t;
  std::array<bool, cell * cell> seen{};
  for (int start = 0; start < cell * cell; ++start) {
    if (seen[start]) continue;
    const bool is_ink = ink[start];
    std::vector<int> stack{start};
    seen[start] = true;
    std::size_t size = 0;
    bool border = false;
    while (!stack.empty()) {
      const int p = stack.back(), x = p % cell, y = p / cell;
      stack.pop_back();
      ++size;
      border = border || x == 0 || y == 0 || x == cell - 1 || y == cell - 1;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (!is_ink && dx != 0 && dy != 0))
            continue;  // ink: 8 neighbours; background: 4
          const int u = x + dx, v = y + dy, q = v * cell + u;
          if (u < 0 || v < 0 || u >= cell || v >= cell || seen[q] || ink[q] != is_ink) continue;
          seen[q] = true;
          stack.push_back(q);
        }
    }
    if (is_ink)
      ++t.pieces;
    else if (!border)
      t.holes.push_back(size);
  }
  return t;
}

struct Digit_skeleton {
  sk::Reeb_skeleton skeleton;
  std::size_t points = 0, components = 0, loops = 0;
};

Digit_skeleton skeleton_of(const Ink& ink) {
  std::vector<std::array<double, 2>> points;  // pixel centres (column, row)
  for (int p = 0; p < cell * cell; ++p)
    if (ink[p]) points.push_back({p % cell + 0.5, p / cell + 0.5});
  sk::Skeleton_options options;
  options.delta = 3;  // persistence in pixels of geodesic distance: spurs at stroke ends and pinholes go
  Digit_skeleton d;
  d.skeleton = sk::extract_reeb_skeleton(points, 1.5, options);
  d.points = points.size();
  const sk::Skeleton_graph& g = d.skeleton.graph;
  std::vector<int> component(num_vertices(g));
  d.components =
      num_vertices(g) == 0 ? 0 : static_cast<std::size_t>(boost::connected_components(g, component.data()));
  d.loops = num_edges(g) + d.components - num_vertices(g);
  return d;
}

/// The first 10 digits of each kind, ink grey, arcs coloured, nodes black; false when the file cannot be
/// written.
bool write_svg(const std::string& path, const Grey_image& image,
               const std::vector<std::vector<sk::Skeleton_graph>>& g) {
  const double s = 8, gap = 12;  // SVG units per pixel, space between digits
  const double step = cell * s + gap, width = 10 * step + gap, height = 10 * step + gap + 28;
  std::ofstream out(path);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                           "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  for (std::size_t kind = 0; kind < g.size(); ++kind)
    for (std::size_t i = 0; i < g[kind].size(); ++i) {
      const double x0 = gap + i * step, y0 = 28 + gap + kind * step;
      out << "<g transform=\"translate(" << x0 << ' ' << y0 << ") scale(" << s << ")\">\n";
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
          const int grey = image.grey[std::size_t(kind * cell + y) * std::size_t(image.width) + i * cell + x];
          if (grey < 128) continue;
          const int shade = 255 - grey / 3;  // light grey, darker where the ink is brighter
          out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"1\" height=\"1\" fill=\"rgb(" << shade
              << ',' << shade << ',' << shade << ")\"/>\n";
        }
      std::size_t k = 0;
      for (auto e : boost::make_iterator_range(edges(g[kind][i]))) {
        out << "<polyline fill=\"none\" stroke-width=\"0.35\" stroke-linejoin=\"round\" stroke=\""
            << colours[k++ % 8] << "\" points=\"";
        for (const auto& p : g[kind][i][e].polyline) out << p[0] << ',' << p[1] << ' ';
        out << "\"/>\n";
      }
      for (auto v : boost::make_iterator_range(vertices(g[kind][i])))
        out << "<circle cx=\"" << g[kind][i][v].position[0] << "\" cy=\"" << g[kind][i][v].position[1]
            << "\" r=\"0.45\" fill=\"black\"/>\n";
      out << "</g>\n";
    }
  out << "<text x=\"" << gap
      << "\" y=\"22\" font-family=\"sans-serif\" font-size=\"15\">Skeletons of handwritten "
         "digits: ink pixels (grey), Rips radius 1.5, delta 3 pixels; arcs coloured, nodes "
         "black</text>\n</svg>\n";
  out.close();
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  std::string svg;
  if (argc == 3 && std::strcmp(argv[1], "--svg") == 0) {
    svg = argv[2];
  } else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [--svg FILE]\n", argv[0]);
    return std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ? 0 : 2;
  }
  const std::string path = std::string(FEATURERECON_DATA_DIR) + "/images/digits_1000.pgm";
  const Grey_image image = read_pgm(path);
  if (image.grey.empty() || image.width != 100 * cell || image.height != 10 * cell) {
    std::fprintf(stderr, "%s: cannot read '%s' (a 2000 x 200 binary PGM)\n", argv[0], path.c_str());
    return 1;
  }
  std::printf(
      "1000 handwritten digits (100 of each, 20 x 20 pixels), ink = grey >= 128; skeleton of the ink pixels\n"
      "with Rips radius 1.5 pixels and delta 3 pixels\n\n");
  std::printf(
      "per kind of digit: ink pixels, nodes and arcs (means), how many skeletons have 0, 1, 2, 3+ loops, "
      "and\n"
      "how many have the topology of the ink\n\n");
  std::printf("digit  ink pixels  nodes  arcs   loops 0    1    2   3+   as the ink\n");
  std::vector<std::vector<sk::Skeleton_graph>> pictured(10);
  std::size_t agree_all = 0, loops_all = 0;
  std::array<std::size_t, 3> holes_all{};  // holes of 1, 2, 3 or more pixels
  double farthest = 0;                     // from a polyline point to the nearest ink pixel centre
  for (int kind = 0; kind < 10; ++kind) {
    std::size_t ink_pixels = 0, nodes = 0, arcs = 0, agree = 0;
    std::array<std::size_t, 4> by_loops{};
    for (int i = 0; i < 100; ++i) {
      Ink ink{};
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x)
          ink[y * cell + x] =
              image.grey[std::size_t(kind * cell + y) * std::size_t(image.width) + i * cell + x] >= 128;
      const Ink_topology t = ink_topology(ink);
      Digit_skeleton d = skeleton_of(ink);
      ink_pixels += d.points;
      nodes += num_vertices(d.skeleton.graph);
      arcs += num_edges(d.skeleton.graph);
      ++by_loops[std::min<std::size_t>(d.loops, 3)];
      const auto holes_of = [&t](std::size_t size) {
        return static_cast<std::size_t>(
            std::count_if(t.holes.begin(), t.holes.end(), [size](std::size_t h) { return h >= size; }));
      };
      agree += d.components == t.pieces && holes_of(3) <= d.loops && d.loops <= holes_of(2);
      loops_all += d.loops;
      for (const std::size_t h : t.holes) ++holes_all[std::min<std::size_t>(h, 3) - 1];
      for (auto e : boost::make_iterator_range(edges(d.skeleton.graph)))
        for (const auto& p : d.skeleton.graph[e].polyline) {
          double nearest = 1e300;
          for (int q = 0; q < cell * cell; ++q)
            if (ink[q])
              nearest = std::min(nearest, std::hypot(p[0] - (q % cell + 0.5), p[1] - (q / cell + 0.5)));
          farthest = std::max(farthest, nearest);
        }
      if (i < 10) pictured[kind].push_back(std::move(d.skeleton.graph));
    }
    agree_all += agree;
    std::printf("%5d  %10.1f  %5.1f  %4.1f  %8zu %4zu %4zu %4zu   %3zu of 100\n", kind, ink_pixels / 100.0,
                nodes / 100.0, arcs / 100.0, by_loops[0], by_loops[1], by_loops[2], by_loops[3], agree);
  }
  std::printf(
      "\nskeleton topology as the ink's (components = 8-connected pieces; holes of >= 3 pixels <= loops <=\n"
      "holes of >= 2 pixels): %zu of 1000 digits\n",
      agree_all);
  std::printf("the ink's holes of 1 / 2 / 3+ pixels: %zu / %zu / %zu; the skeletons' loops: %zu\n",
              holes_all[0], holes_all[1], holes_all[2], loops_all);
  std::printf("every arc within %.2f pixels of an ink pixel centre\n", farthest);
  if (!svg.empty()) {
    if (!write_svg(svg, image, pictured)) {
      std::fprintf(stderr, "%s: cannot write '%s'\n", argv[0], svg.c_str());
      return 1;
    }
    std::printf("wrote %s\n", svg.c_str());
  }
  return 0;
}
