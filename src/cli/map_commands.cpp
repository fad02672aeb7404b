// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Subcommand evaluate-map: the graph-sampling metric of a reconstructed road map against a ground truth.

#include <FeatureRecon/skeleton/map_comparison.h>
#include <FeatureRecon/skeleton/road_map.h>
#include <FeatureRecon/skeleton/synthetic_city.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../io/featurerecon_io.h"
#include "../io/skeleton_io.h"
#include "cli_common.h"
#include "commands.h"

namespace FeatureRecon {
namespace cli {

using namespace FeatureRecon::skeleton;

namespace {
Embedded_graph_2 to_graph(const io::Map_file& m) {
  Embedded_graph_2 g;
  g.positions = m.positions;
  for (const auto& e : m.edges) g.edges.push_back({e[0], e[1]});
  return g;
}

}  // namespace

int run_evaluate_map(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"explain", "lonlat", "quiet"},
                       {"threshold", "interval", "bearing", "crop-to-tracks", "crop-radius", "crop-gap",
                        "samples-out", "svg", "tracks", "matching"},
                       4);
  if (args.positional().size() != 4)
    throw Usage_error("expected four files: GT_VERTICES GT_EDGES REC_VERTICES REC_EDGES");
  Map_comparison_options options;
  if (args.has("threshold")) {
    options.match_distance = args.get_positive_double("threshold");
    if (!(options.match_distance >= skeleton::internal::min_metric_distance &&
          options.match_distance <= skeleton::internal::max_metric_distance))
      throw Usage_error(
          "--threshold must be within [2^-450, 2^450] (about 3e-136 to 3e135: squares of distances "
          "near it stay normal doubles), got '" +
          args.get("threshold") + "'");
  }
  if (args.has("interval")) options.interval = args.get_positive_double("interval");
  if (args.has("bearing")) options.bearing_limit = args.get_positive_double("bearing");
  const std::string matching = args.get_or("matching", "greedy");
  if (matching != "greedy" && matching != "optimal")
    throw Usage_error("--matching must be greedy or optimal, got '" + matching + "'");
  options.matching = matching == "optimal" ? Map_matching::optimal : Map_matching::greedy;
  for (const char* crop : {"crop-radius", "crop-gap"})
    if (args.has(crop) && !args.has("crop-to-tracks"))
      throw Usage_error(std::string("--") + crop + " goes with --crop-to-tracks");
  Map_crop_options crop_options;
  if (args.has("crop-radius")) crop_options.radius = args.get_positive_double("crop-radius");
  if (args.has("crop-gap")) {
    crop_options.max_gap = args.get_double("crop-gap");
    if (!(crop_options.max_gap >= 0 && std::isfinite(crop_options.max_gap)))
      throw Usage_error("--crop-gap must be finite and >= 0, got '" + args.get("crop-gap") + "'");
  }
  Outputs outputs(args, {"samples-out", "svg"});
  outputs.require_extension("svg", {"svg", "png", "jpg", "jpeg", "pgm", "ppm"}, "a picture");
  const auto& p = args.positional();
  std::vector<std::size_t> gt_lines, rec_lines;  // of each position, for --lonlat
  auto read = [&](const std::string& vertices, const std::string& edges, std::vector<std::size_t>& lines) {
    io::Map_file m = io::read_map(vertices, edges);
    lines = std::move(m.vertex_lines);
    if (m.self_loops > 0)
      std::fprintf(
          stderr,
          "featurerecon evaluate-map: warning: %s line %zu: an edge joins a vertex to itself; %zu such "
          "edge%s no length and %s ignored\n",
          edges.c_str(), m.first_self_loop_line, m.self_loops, m.self_loops == 1 ? " has" : "s have",
          m.self_loops == 1 ? "is" : "are");
    if (m.zero_length_edges > 0)
      std::fprintf(stderr,
                   "featurerecon evaluate-map: warning: %s line %zu: an edge joins two vertices at one "
                   "position; %zu such edge%s no length and %s no sample\n",
                   edges.c_str(), m.first_zero_length_line, m.zero_length_edges,
                   m.zero_length_edges == 1 ? " has" : "s have", m.zero_length_edges == 1 ? "gives" : "give");
    return to_graph(m);
  };
  Embedded_graph_2 gt = read(p[0], p[1], gt_lines);
  Embedded_graph_2 rec = read(p[2], p[3], rec_lines);
  std::size_t gt_edges_before = gt.edges.size();
  // Trips with their points and where each fix was read (for --lonlat's checks and messages).
  Track_input crop_input, track_input;
  if (args.has("crop-to-tracks")) {
    crop_input = read_tracks(args.get("crop-to-tracks"));
    warn_few_fixes_per_trip("evaluate-map", args.get("crop-to-tracks"), crop_input);
  }
  if (args.has("tracks")) {
    track_input = read_tracks(args.get("tracks"));
    warn_few_fixes_per_trip("evaluate-map", args.get("tracks"), track_input);
  }
  std::vector<Gps_trip>& trips = track_input.trips;
  std::vector<Gps_trip>& crop_trips = crop_input.trips;
  const std::vector<std::array<double, 2>>& crop_points = crop_input.points;
  // --lonlat: every file in degrees; all projected to metres with one projection centred on them.
  const bool lonlat = args.has("lonlat");
  if (!lonlat)  // degrees read as metres: the whole map shrinks to a few samples and everything matches
    for (const auto& [file, graph] : {std::make_pair(p[0], &gt), std::make_pair(p[2], &rec)}) {
      std::vector<double> lengths;
      bool degrees = true;
      for (const auto& q : graph->positions)
        degrees = degrees && std::abs(q[0]) <= 180 && std::abs(q[1]) <= 90;
      for (const Edge& e : graph->edges)
        lengths.push_back(std::hypot(graph->positions[e[1]][0] - graph->positions[e[0]][0],
                                     graph->positions[e[1]][1] - graph->positions[e[0]][1]));
      if (!degrees || lengths.empty()) continue;
      std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
      const double median = lengths[lengths.size() / 2];
      if (median > 0 && median < 0.01)
        throw io::Input_error(file +
                              ": the vertices look like longitude and latitude in degrees (median edge " +
                              json_number(median) +
                              ", all within +-180 and +-90), but the maps are read in metres: "
                              "give --lonlat, or project them to metres first");
    }
  if (!lonlat)  // tracks in degrees: no truth sample lies near a fix (every sample "driven by 0 trips")
    for (const auto& [flag, input] :
         {std::make_pair("crop-to-tracks", &crop_input), std::make_pair("tracks", &track_input)})
      if (args.has(flag))
        refuse_degree_tracks(args.get(flag), input->trips,
                             median_gps_step(input->trips, 0, std::numeric_limits<double>::infinity()));
  Transverse_mercator projection;
  if (lonlat) {
    projection = lonlat_projection({{p[0], &gt.positions, &gt_lines},
                                    {p[2], &rec.positions, &rec_lines},
                                    crop_input.lonlat_source(args.get_or("crop-to-tracks", "")),
                                    track_input.lonlat_source(args.get_or("tracks", ""))});
    for (auto* points : {&gt.positions, &rec.positions})
      for (auto& q : *points) q = projection.forward(q[0], q[1]);
    project_trips(trips, projection);
    project_trips(crop_trips, projection);
  }
  std::size_t crop_trace_points = 0;
  if (args.has("crop-to-tracks")) {
    Progress cropping("cropping the ground truth", args.has("quiet"));
    crop_options.progress = std::ref(cropping);
    Cropped_map cropped = crop_map_to_trips(gt, crop_trips, crop_options);
    cropping.done(std::to_string(cropped.map.edges.size()) + " of " + std::to_string(gt.edges.size()) +
                  " edges");
    if (crop_points.empty())
      std::fprintf(
          stderr,
          "featurerecon evaluate-map: warning: %s holds no fixes: the crop keeps no ground-truth edge\n",
          args.get("crop-to-tracks").c_str());
    else if (cropped.map.edges.empty() && !gt.edges.empty())
      std::fprintf(
          stderr,
          "featurerecon evaluate-map: warning: the crop keeps none of the %zu ground-truth edges (none lies "
          "within --crop-radius %s m of the %zu fix%s of %s: are they in the maps' coordinates?)\n",
          gt.edges.size(), json_number(crop_options.radius).c_str(), crop_points.size(),
          crop_points.size() == 1 ? "" : "es", args.get("crop-to-tracks").c_str());
    gt = std::move(cropped.map);
    crop_trace_points = cropped.trace_points;
  }
  options.keep_samples =
      args.has("samples-out") || args.has("svg") || args.has("explain") || args.has("tracks");
  Progress matching_progress("matching samples", args.has("quiet"));
  options.progress = std::ref(matching_progress);
  const Map_comparison_result r = compare_maps(gt, rec, options);
  matching_progress.done(std::to_string(r.matched) + " pairs of " + std::to_string(r.ground_truth_samples) +
                         " and " + std::to_string(r.reconstruction_samples) + " samples");
  if (args.has("samples-out")) {
    if (lonlat) {  // the samples' positions in degrees, as the maps were
      Map_comparison_result in_degrees = r;
      for (auto* list : {&in_degrees.ground_truth_sample_list, &in_degrees.reconstruction_sample_list})
        for (Map_sample& m : *list) {
          const auto ll = projection.inverse(m.position[0], m.position[1]);
          m.position[0] = ll[0];
          m.position[1] = ll[1];
        }
      io::write_map_comparison_csv(outputs.path("samples-out"), in_degrees);
    } else {
      io::write_map_comparison_csv(outputs.path("samples-out"), r);
    }
  }
  if (args.has("svg")) io::write_map_comparison_picture(outputs.path("svg"), r);
  outputs.commit();
  std::ostringstream os;
  // A ratio over no samples is undefined: null (the library reports 0).
  const double undefined = std::numeric_limits<double>::quiet_NaN();
  os << "{\"precision\": " << json_number(r.reconstruction_samples > 0 ? r.precision : undefined)
     << ", \"recall\": " << json_number(r.ground_truth_samples > 0 ? r.recall : undefined)
     << ", \"f_score\": "
     << json_number(r.reconstruction_samples + r.ground_truth_samples > 0 ? r.f_score : undefined)
     << ", \"matched\": " << r.matched << ", \"ground_truth_samples\": " << r.ground_truth_samples
     << ", \"reconstruction_samples\": " << r.reconstruction_samples
     << ", \"ground_truth_edges\": " << gt.edges.size()
     << ", \"ground_truth_edges_before_crop\": " << gt_edges_before
     << ", \"threshold\": " << json_number(options.match_distance)
     << ", \"interval\": " << json_number(options.interval)
     << ", \"bearing\": " << json_number(options.bearing_limit) << ", \"matching\": \"" << matching << "\"";
  if (args.has("crop-to-tracks"))
    os << ", \"crop\": {\"radius\": " << json_number(crop_options.radius)
       << ", \"sample_interval\": " << json_number(crop_options.sample_interval)
       << ", \"trace_step\": " << json_number(crop_options.trace_step)
       << ", \"max_gap\": " << json_number(crop_options.max_gap)
       << ", \"trace_points\": " << crop_trace_points << "}";
  if (lonlat)
    os << ", \"lonlat\": true, \"central_meridian\": " << json_number(projection.central_meridian)
       << ", \"origin_latitude\": " << json_number(projection.origin_latitude);
  if (args.has("explain")) {
    const Unmatched_samples_breakdown b = explain_unmatched_samples(r, options);
    auto counts = [&os](const char* name, const Unmatched_sample_counts& c) {
      os << ", \"" << name << "\": {\"taken\": " << c.taken << ", \"offset\": " << c.offset
         << ", \"crossing\": " << c.crossing << ", \"absent\": " << c.absent << "}";
    };
    counts("missed", b.missed);
    counts("spurious", b.spurious);
  }
  if (args.has("tracks")) {
    const Trace_support_breakdown b = explain_trace_support(r, trips, trace_support_options(options));
    auto list = [&os](const char* name, const std::array<std::size_t, 4>& c) {
      os << "\"" << name << "\": [" << c[0] << ", " << c[1] << ", " << c[2] << ", " << c[3] << "], ";
    };
    os << ", \"trace_support\": {\"trips\": " << trips.size() << ", ";
    list("ground_truth_by_trips", b.ground_truth_by_trips);
    list("missed_by_trips", b.missed_by_trips);
    list("spurious_by_trips", b.spurious_by_trips);
    os << "\"ground_truth_driven\": " << b.ground_truth_driven << ", \"matched_driven\": " << b.matched_driven
       << ", \"recall_of_driven\": "
       << json_number(b.ground_truth_driven > 0 ? b.recall_of_driven : undefined) << "}";
  }
  os << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

int run_synthetic_city(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"quiet"},
                       {"layout",
                        "columns",
                        "rows",
                        "block-width",
                        "block-height",
                        "rotation",
                        "jitter",
                        "missing",
                        "curvature",
                        "trips",
                        "speed",
                        "interval",
                        "noise",
                        "bias",
                        "lane-offset",
                        "seed",
                        "out-tracks",
                        "out-vertices",
                        "out-edges",
                        "out-streets-vertices",
                        "out-streets-edges"});
  for (const char* required : {"out-tracks", "out-vertices", "out-edges"})
    if (!args.has(required)) throw Usage_error(std::string("--") + required + " is required");
  if (args.has("out-streets-vertices") != args.has("out-streets-edges"))
    throw Usage_error("--out-streets-vertices and --out-streets-edges go together");
  Outputs outputs(args,
                  {"out-tracks", "out-vertices", "out-edges", "out-streets-vertices", "out-streets-edges"});
  Synthetic_city_options o;
  const std::string layout = args.get_or("layout", "grid");
  if (layout == "organic")
    o.layout = Synthetic_city_layout::organic;
  else if (layout != "grid")
    throw Usage_error("--layout must be grid or organic, got '" + layout + "'");
  if (o.layout == Synthetic_city_layout::organic && args.has("jitter"))
    throw Usage_error(
        "--jitter applies to --layout grid only (the organic layout places its intersections "
        "by dart throwing and does not jitter them)");
  // Ranges are checked here so that the message names the option (the library names its fields).
  auto count = [&](const char* name, std::size_t& field, long long least, long long most) {
    if (!args.has(name)) return;
    const long long v = args.get_int(name);
    if (v < least) throw Usage_error(std::string("--") + name + " must be >= " + std::to_string(least));
    if (v > most)
      throw Usage_error(std::string("--") + name + " must be at most " + std::to_string(most) + ", got " +
                        args.get(name));
    field = static_cast<std::size_t>(v);
  };
  const long long any_count = std::numeric_limits<long long>::max();
  count("columns", o.columns, 2, any_count);  // with rows: at most 2^24 intersections, below
  count("rows", o.rows, 2, any_count);
  count("trips", o.trips, 0, 1LL << 26);  // the library's limit (the most fixes the trips may record)
  if (o.columns > (std::size_t(1) << 24) / o.rows)
    throw Usage_error("--columns x --rows must be at most 2^24 intersections");
  // A value in [low, high]; `open_low`: strictly above low.
  auto number = [&](const char* name, double& field, double low, bool open_low, double high) {
    if (!args.has(name)) return;
    const double v = args.get_double(name);
    if (open_low ? !(v > low) : !(v >= low))
      throw Usage_error(std::string("--") + name + " must be " + (open_low ? "> " : ">= ") +
                        json_number(low) + ", got '" + args.get(name) + "'");
    if (v > high)
      throw Usage_error(std::string("--") + name + " must be <= " + json_number(high) + ", got '" +
                        args.get(name) + "'");
    field = v;
  };
  const double any = std::numeric_limits<double>::max();
  number("block-width", o.block_width, 0, true, any);
  number("block-height", o.block_height, 0, true, any);
  number("rotation", o.rotation, -any, false, any);
  number("jitter", o.jitter, 0, false, any);
  number("missing", o.missing_streets, 0, false, 1);
  number("curvature", o.curvature, 0, false, 0.5);
  number("speed", o.speed, 0, true, any);
  number("interval", o.sampling_interval, 0, true, any);
  number("noise", o.noise, 0, false, any);
  number("bias", o.trip_bias, 0, false, any);
  number("lane-offset", o.lane_offset, 0, false, any);
  if (args.has("seed")) {
    const long long seed = args.get_int("seed");
    if (seed < 0) throw Usage_error("--seed must be >= 0");
    o.seed = static_cast<std::uint64_t>(seed);
  }
  // The defaults (jitter 10 m, lane offset 2 m) are lowered for small blocks when they were not given: small
  // blocks are no reason to refuse options the user did not set. The jitter to its limit (no street crosses
  // another there), the lane offset to half its limit (at the limit, half a block, the lanes of two parallel
  // streets would share the line between them).
  if (!args.has("jitter")) o.jitter = std::min(o.jitter, skeleton::synthetic_city_max_jitter(o));
  if (!args.has("lane-offset"))
    o.lane_offset = std::min(o.lane_offset, skeleton::synthetic_city_max_lane_offset(o) / 2);
  Progress progress("driving trips", args.has("quiet"));
  o.progress = std::ref(progress);
  // Every value comes from an option: the library's refusal of a combination is a usage error, named by flag.
  Synthetic_city city;
  try {
    city = make_synthetic_city(o);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(name_option_flags(e.what()));
  }
  progress.done(std::to_string(city.trips.size()) + " trips");
  std::string tracks = "# trip_id x y t  (synthetic city, metres and seconds)\n";
  std::size_t fixes = 0;
  for (std::size_t t = 0; t < city.trips.size(); ++t)
    for (const Gps_fix& f : city.trips[t]) {
      tracks += std::to_string(t) + " " + io::format_double(f.x) + " " + io::format_double(f.y) + " " +
                io::format_double(f.time) + "\n";
      ++fixes;
    }
  io::write_text_file(outputs.path("out-tracks"), tracks);
  io::write_map(outputs.path("out-vertices"), outputs.path("out-edges"), city.driven.positions,
                city.driven.edges);
  if (args.has("out-streets-vertices"))
    io::write_map(outputs.path("out-streets-vertices"), outputs.path("out-streets-edges"),
                  city.streets.positions, city.streets.edges);
  outputs.commit();
  if (fixes == 0 && !city.trips.empty())
    std::fprintf(stderr,
                 "featurerecon synthetic-city: warning: no trip lasted one sampling interval, no fix was "
                 "recorded (--interval %g s, --speed %g m/s)\n",
                 o.sampling_interval, o.speed);
  auto length = [](const Embedded_graph_2& g) {
    return skeleton::internal::map_length(g.positions, g.edges);
  };
  std::ostringstream os;
  os << "{\"layout\": \"" << layout << "\", \"intersections\": " << o.columns * o.rows
     << ", \"vertices\": " << city.streets.positions.size()
     << ", \"street_edges\": " << city.streets.edges.size()
     << ", \"driven_edges\": " << city.driven.edges.size()
     << ", \"street_length\": " << json_number(length(city.streets))
     << ", \"driven_length\": " << json_number(length(city.driven)) << ", \"trips\": " << city.trips.size()
     << ", \"fixes\": " << fixes << ", \"interval\": " << json_number(o.sampling_interval)
     << ", \"noise\": " << json_number(o.noise) << ", \"curvature\": " << json_number(o.curvature)
     << ", \"jitter\": "
     << (o.layout == skeleton::Synthetic_city_layout::grid ? json_number(o.jitter) : std::string("null"))
     << ", \"lane_offset\": " << json_number(o.lane_offset) << ", \"seed\": " << o.seed << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
