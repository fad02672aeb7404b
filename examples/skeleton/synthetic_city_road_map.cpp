// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// A road map from GPS traces where the true streets are known: make_synthetic_city() lays out a perturbed
// grid and simulates trips on it; extract_road_map() builds the map with every parameter derived from the
// traces; compare_maps() scores it against the streets that were driven (graph-sampling metric, 15 m), before
// and after the last stage merges the two directions of each street into one line. The same city recorded
// every 1, 3.6 and 7 seconds shows how the derived parameters follow the sampling rate. Then a city of
// another shape with the same defaults: random intersections joined by bent streets (the organic layout,
// curvature 0.15). With --svg FILE: a picture of the 3.6 s grid city (traces, true streets, map);
// doc/images/synthetic_city_road_map.png is that picture converted with rsvg-convert. With --svg-organic
// FILE: the same for the organic city (doc/images/synthetic_city_organic.png).
#include <FeatureRecon/skeleton/road_map.h>
#include <FeatureRecon/skeleton/synthetic_city.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace sk = FeatureRecon::skeleton;

namespace {
/// The fixes, the streets driven and the map; exits with a message when the file cannot be written.
void write_svg(const std::string& path, const sk::Synthetic_city& city, const sk::Road_map& m) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : city.streets.positions) {
    x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]);
    x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
  }
  const double margin = 40, s = 1.0;
  auto X = [&](double x) { return margin + (x - x0) * s; };
  auto Y = [&](double y) { return margin + (y1 - y) * s; };
  std::ofstream out(path);
  const double width = 2 * margin + (x1 - x0) * s, height = 2 * margin + (y1 - y0) * s + 20;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& trip : city.trips)
    for (const auto& f : trip)
      out << "<circle cx=\"" << X(f.x) << "\" cy=\"" << Y(f.y) << "\" r=\"1\" fill=\"#bbbbbb\"/>\n";
  auto lines = [&](const sk::Embedded_graph_2& g, const char* colour, double width) {
    for (const auto& e : g.edges)
      out << "<line x1=\"" << X(g.positions[e[0]][0]) << "\" y1=\"" << Y(g.positions[e[0]][1]) << "\" x2=\""
          << X(g.positions[e[1]][0]) << "\" y2=\"" << Y(g.positions[e[1]][1]) << "\" stroke=\"" << colour
          << "\" stroke-width=\"" << width << "\" stroke-opacity=\"0.6\"/>\n";
  };
  lines(city.driven, "#2ca02c", 5);
  lines(m.map, "#1f4fbf", 1.5);
  out << "<text x=\"" << margin << "\" y=\"" << 2 * margin + (y1 - y0) * s + 5
      << "\" font-size=\"14\">grey: fixes; green: streets driven; blue: road map</text>\n</svg>\n";
  out.close();
  if (!out) {
    std::fprintf(stderr, "synthetic_city_road_map: cannot write '%s'\n", path.c_str());
    std::exit(1);
  }
}

// Builds and scores the map of one city; prints what the skeleton and the merged map are worth.
sk::Road_map run(const sk::Synthetic_city& city, double interval) {
  std::size_t fixes = 0;
  for (const auto& t : city.trips) fixes += t.size();
  const sk::Road_map m = sk::extract_road_map(city.trips);
  const sk::Map_comparison_result score = sk::compare_maps(city.driven, m.map);
  // The same skeleton before its last stage, merge_road_lines(): both directions of every street drawn.
  const sk::Map_comparison_result unmerged =
      sk::compare_maps(city.driven, sk::skeleton_to_road_map(m.skeleton.graph));
  std::printf("every %.1f s: %zu fixes, median step %.1f m -> radius %.1f m, delta %.1f m; %zu samples\n",
              interval, fixes, m.sample.median_step, *m.used.rips_radius, *m.used.delta,
              m.sample.points.rows);
  std::printf("  skeleton: %zu nodes, %zu arcs, %.0f m of lines; P %.2f R %.2f F %.2f\n",
              num_vertices(m.skeleton.graph), num_edges(m.skeleton.graph), m.merged.length_before,
              unmerged.precision, unmerged.recall, unmerged.f_score);
  std::printf("  merged at %.0f m: %zu nodes, %zu arcs, %.0f m of lines; P %.2f R %.2f F %.2f\n",
              *m.used.merge_distance, num_vertices(m.merged.skeleton), num_edges(m.merged.skeleton),
              m.merged.length_after, score.precision, score.recall, score.f_score);
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  std::string svg, svg_organic;
  for (int i = 1; i < argc; i += 2) {
    if (i + 1 < argc && std::strcmp(argv[i], "--svg") == 0) {
      svg = argv[i + 1];
    } else if (i + 1 < argc && std::strcmp(argv[i], "--svg-organic") == 0) {
      svg_organic = argv[i + 1];
    } else {
      std::fprintf(stderr, "usage: %s [--svg FILE] [--svg-organic FILE]\n", argv[0]);
      return std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0 ? 0 : 2;
    }
  }
  for (const double interval : {1.0, 3.6, 7.0}) {
    sk::Synthetic_city_options o;  // 8 x 6 intersections, 120 x 90 m blocks, noise 4 m, bias 2 m
    o.sampling_interval = interval;
    o.trips = 600;
    const sk::Synthetic_city city = sk::make_synthetic_city(o);
    const sk::Road_map m = run(city, interval);
    if (!svg.empty() && interval == 3.6) write_svg(svg, city, m);
  }
  sk::Synthetic_city_options o;  // 48 random intersections in the same rectangle, Gabriel graph, bent streets
  o.layout = sk::Synthetic_city_layout::organic;
  o.curvature = 0.15;
  o.trips = 600;
  std::printf("organic city, bent streets:\n");
  const sk::Synthetic_city city = sk::make_synthetic_city(o);
  const sk::Road_map m = run(city, o.sampling_interval);
  if (!svg_organic.empty()) write_svg(svg_organic, city, m);
  return 0;
}
