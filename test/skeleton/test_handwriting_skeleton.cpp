// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Skeletons of handwriting: the 1,000 digits of data/images/digits_1000.pgm (the example
// handwriting_skeleton). The oracle is the ink's own topology, computed otherwise than the example's flood
// fill: the Euler characteristic of the union of the closed ink squares (its pieces are the 8-connected
// pieces of ink, its holes the 4-connected pieces of background inside), pieces by union-find, holes of one
// and two pixels by their local pattern.
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>

#include <boost/graph/connected_components.hpp>

#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image_io.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {

constexpr int cell = 20;

struct Ink_oracle {
  std::size_t pieces = 0;
  std::size_t holes = 0;       // all holes: pieces - Euler characteristic
  std::size_t one_pixel = 0;   // holes of one pixel
  std::size_t two_pixels = 0;  // holes of two pixels
};

Ink_oracle ink_oracle(const std::vector<bool>& ink) {
  auto at = [&](int x, int y) { return x >= 0 && y >= 0 && x < cell && y < cell && ink[y * cell + x]; };
  std::set<std::array<int, 2>> corners;
  std::set<std::array<int, 3>> sides;  // (x, y, 0): from (x, y) to (x + 1, y); (x, y, 1): to (x, y + 1)
  long squares = 0;
  std::vector<int> parent(cell * cell);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (int y = 0; y < cell; ++y)
    for (int x = 0; x < cell; ++x) {
      if (!at(x, y)) continue;
      ++squares;
      corners.insert({{x, y}}), corners.insert({{x + 1, y}}), corners.insert({{x, y + 1}}),
          corners.insert({{x + 1, y + 1}});
      sides.insert({{x, y, 0}}), sides.insert({{x, y + 1, 0}}), sides.insert({{x, y, 1}}),
          sides.insert({{x + 1, y, 1}});
      for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {0, 1}, {1, 1}, {-1, 1}})
        if (at(x + dx, y + dy)) parent[find(y * cell + x)] = find((y + dy) * cell + x + dx);
    }
  Ink_oracle o;
  for (int p = 0; p < cell * cell; ++p) o.pieces += ink[p] && find(p) == p;
  const long euler = static_cast<long>(corners.size()) - static_cast<long>(sides.size()) + squares;
  o.holes = static_cast<std::size_t>(static_cast<long>(o.pieces) - euler);
  auto closed = [&](int x, int y, int skip_x, int skip_y) {  // the 4 neighbours of (x, y) but one are ink
    int n = 0;
    for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
      n += (x + dx == skip_x && y + dy == skip_y) || at(x + dx, y + dy);
    return n == 4;
  };
  for (int y = 0; y < cell; ++y)
    for (int x = 0; x < cell; ++x) {
      if (at(x, y) || x == 0 || y == 0 || x == cell - 1 || y == cell - 1) continue;
      o.one_pixel += closed(x, y, -9, -9);
      for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {0, 1}})
        if (x + dx < cell - 1 && y + dy < cell - 1 && !at(x + dx, y + dy))
          o.two_pixels += closed(x, y, x + dx, y + dy) && closed(x + dx, y + dy, x, y);
    }
  return o;
}

}  // namespace

// Every digit's skeleton (Rips radius 1.5 pixels: the 8 neighbours; delta 3 pixels) has one component per
// piece of ink and one loop per hole of 3 or more pixels; holes of 2 pixels may stay (their loops'
// persistence is about delta), single pixels go. Its arcs stay within one pixel of the ink. The same holds
// for the transposed digit (another base point, other ties on the grid).
TEST(HandwritingSkeleton, TopologyOfTheInkOnAThousandDigits) {
  const io::Image image = io::read_image(std::string(FEATURERECON_DATA_DIR) + "/images/digits_1000.pgm");
  ASSERT_EQ(image.width, 100 * cell);
  ASSERT_EQ(image.height, 10 * cell);
  std::size_t loops_in_all = 0, two_pixel_holes = 0, one_pixel_holes = 0;
  for (int digit = 0; digit < 1000; ++digit)
    for (const bool transposed : {false, true}) {
      const int column0 = digit % 100 * cell, row0 = digit / 100 * cell;
      std::vector<bool> ink(cell * cell);
      std::vector<std::array<double, 2>> points;
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
          const int u = transposed ? y : x, v = transposed ? x : y;
          if (image.at(column0 + x, row0 + y) < 128) continue;
          ink[v * cell + u] = true;
        }
      for (int p = 0; p < cell * cell; ++p)
        if (ink[p]) points.push_back({p % cell + 0.5, p / cell + 0.5});
      const Ink_oracle o = ink_oracle(ink);
      Skeleton_options options;
      options.delta = 3;
      const Reeb_skeleton s = extract_reeb_skeleton(points, 1.5, options);
      const Skeleton_graph& g = s.graph;
      std::vector<int> component(num_vertices(g));
      const std::size_t components =
          static_cast<std::size_t>(boost::connected_components(g, component.data()));
      const std::size_t loops = num_edges(g) + components - num_vertices(g);
      SCOPED_TRACE("digit " + std::to_string(digit) + (transposed ? " transposed" : ""));
      EXPECT_EQ(components, o.pieces);
      EXPECT_GE(loops, o.holes - o.one_pixel - o.two_pixels);
      EXPECT_LE(loops, o.holes - o.one_pixel);
      for (auto e : boost::make_iterator_range(edges(g)))
        for (const auto& p : g[e].polyline) {
          double nearest = 1e300;
          for (const auto& q : points) nearest = std::min(nearest, std::hypot(p[0] - q[0], p[1] - q[1]));
          ASSERT_LE(nearest, 1.0 + 1e-9);
        }
      if (!transposed) {
        loops_in_all += loops;
        two_pixel_holes += o.two_pixels;
        one_pixel_holes += o.one_pixel;
      }
    }
  // What the example prints: the data have holes of every kind, so that each bound above is exercised.
  EXPECT_EQ(one_pixel_holes, 64u);
  EXPECT_EQ(two_pixel_holes, 19u);
  EXPECT_EQ(loops_in_all, 399u);
}
