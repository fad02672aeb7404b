// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Subcommands of the skeleton subsystem: rips, reeb.

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/extract_reeb_skeleton.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/gps_traces.h>
#include <FeatureRecon/skeleton/reeb_graph_persistence.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/road_map.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <boost/graph/connected_components.hpp>

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "../io/featurerecon_io.h"
#include "../io/image_io.h"
#include "../io/skeleton_io.h"
#include "cli_common.h"
#include "commands.h"
#include "rips_thinning.h"

namespace FeatureRecon {
namespace cli {

using namespace FeatureRecon::skeleton;

namespace {
/// --max-triangles N (an integer >= 0), or the library's default limit of the skeleton pipeline.
std::size_t max_triangles_option(const Arguments& args) {
  if (!args.has("max-triangles")) return Skeleton_options().max_triangles;
  const long long n = args.get_int("max-triangles");
  if (n < 0)
    throw Usage_error("--max-triangles must be an integer >= 0 (0: no limit), got '" +
                      args.get("max-triangles") + "'");
  return static_cast<std::size_t>(n);
}
}  // namespace

int run_rips(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"quiet"}, {"points", "radius", "knn", "out", "search", "max-triangles"});
  const std::string points_path = args.get("points");
  const std::string out_path = args.get("out");
  if (args.has("radius") == args.has("knn")) throw Usage_error("give exactly one of --radius R and --knn K");
  Outputs outputs(args, {"out"});
  Proximity_graph_options options;
  const std::string search = args.get_or("search", "auto");
  if (search == "auto")
    options.search = Neighbor_search::automatic;
  else if (search == "kd-tree")
    options.search = Neighbor_search::kd_tree;
  else if (search == "brute-force")
    options.search = Neighbor_search::brute_force;
  else
    throw Usage_error("--search must be auto, kd-tree or brute-force, got '" + search + "'");
  double radius = 0;
  long long k = 0;
  if (args.has("radius")) {
    radius = args.get_double("radius");
    if (radius < 0) throw Usage_error("--radius must be >= 0, got '" + args.get("radius") + "'");
  } else {
    k = args.get_int("knn");
    if (k < 1) throw Usage_error("--knn must be an integer >= 1, got '" + args.get("knn") + "'");
  }
  const bool quiet = args.has("quiet");
  const std::size_t max_triangles = max_triangles_option(args);  // checked before any work

  const io::Point_file pf = io::read_points(points_path);
  if (pf.size() == 0)
    std::fprintf(stderr, "featurerecon rips: warning: %s holds no points\n", points_path.c_str());
  Point_matrix m;
  m.rows = pf.size();
  m.dimension = pf.dimension;
  m.data = pf.coordinates;
  if (m.dimension > 3 && options.search == Neighbor_search::kd_tree)
    throw Usage_error("--search kd-tree supports dimension <= 3; the points have dimension " +
                      std::to_string(m.dimension));

  Progress graph_progress(args.has("radius") ? "rips graph" : "knn graph", quiet);
  options.progress = std::ref(graph_progress);
  const Proximity_graph g = args.has("radius") ? build_rips_graph(m, radius, options)
                                               : build_knn_graph(m, static_cast<std::size_t>(k), options);
  graph_progress.done(std::to_string(g.number_of_edges()) + " edges");

  Progress complex_progress("triangles", quiet);
  // build_flag_complex_2() with the limit named as the command line spells it.
  const Simplicial_complex_2 K = skeleton::internal::flag_complex_2(
      g, max_triangles > 0 ? max_triangles : std::numeric_limits<std::size_t>::max(),
      std::ref(complex_progress), "build_flag_complex_2", "--max-triangles");
  complex_progress.done(std::to_string(K.number_of_triangles()) + " triangles");

  Progress geodesic_progress("geodesic function", quiet);
  Geodesic_options gopt;
  gopt.progress = std::ref(geodesic_progress);
  const Geodesic_result geo = compute_geodesic_function(K, gopt);
  geodesic_progress.done(std::to_string(geo.base_points.size()) + " components");

  std::vector<std::array<double, 3>> positions(m.rows, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t c = 0; c < std::min<std::size_t>(3, m.dimension); ++c) positions[i][c] = m.row(i)[c];
  io::write_complex(outputs.path("out"), K, positions,
                    geo.values.empty() ? std::vector<double>(m.rows, 0.0) : geo.values);
  outputs.commit();
  std::fprintf(outputs.summary_stream(),
               "wrote %s: %zu vertices, %zu edges, %zu triangles, %zu components (dimension %zu)\n",
               out_path.c_str(), K.number_of_vertices, K.number_of_edges(), K.number_of_triangles(),
               geo.base_points.size(), m.dimension);
  return 0;
}

int run_reeb(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"json", "quiet", "persistence"}, {"complex", "simplify"});
  double delta = -1;
  if (args.has("simplify")) {
    delta = args.get_double("simplify");
    if (delta < 0) throw Usage_error("--simplify must be >= 0, got '" + args.get("simplify") + "'");
  }
  if (args.has("persistence") && !args.has("json")) throw Usage_error("--persistence goes with --json");
  const io::Complex_file cf = io::read_complex(args.get("complex"));
  // Progress goes to standard error, so --json keeps standard output to the one object (like evaluate-map).
  const bool quiet = args.has("quiet");
  Progress progress("reeb graph", quiet);
  Reeb_graph_options options;
  options.progress = std::ref(progress);
  const auto t0 = std::chrono::steady_clock::now();
  const Augmented_reeb_graph augmented = compute_augmented_reeb_graph(cf.complex, cf.values, options);
  std::size_t removed_branches = 0, removed_loops = 0;
  Reeb_graph R;
  if (delta >= 0) {
    progress.done();
    Progress simplification("simplification", quiet);
    Simplification_options simplification_options;
    simplification_options.progress = std::ref(simplification);
    Reeb_simplification_result S = simplify_by_persistence(augmented, delta, simplification_options);
    simplification.done();
    R = std::move(S.graph);
    removed_branches = S.removed_branches;
    removed_loops = S.removed_loops;
  } else {
    R = augmented.reeb_graph();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (delta < 0) progress.done();  // with --simplify: done before the simplification
  Reeb_graph_persistence P;
  if (args.has("persistence")) {
    Progress persistence_progress("persistence", quiet);
    Reeb_persistence_options persistence_options;
    persistence_options.progress = std::ref(persistence_progress);
    P = compute_reeb_graph_persistence(R, persistence_options);
    persistence_progress.done(std::to_string(P.sublevel_branches.size() + P.superlevel_branches.size()) +
                              " branch and " + std::to_string(P.loops.size()) + " loop pairs");
  }
  const Simplicial_complex_2& K = cf.complex;
  std::ostringstream os;
  if (args.has("json")) {
    os << "{\"vertices\": " << K.number_of_vertices << ", \"edges\": " << K.number_of_edges()
       << ", \"triangles\": " << K.number_of_triangles() << ", \"nodes\": " << R.nodes.size()
       << ", \"arcs\": " << R.arcs.size() << ", \"loops\": " << R.loops()
       << ", \"minima\": " << R.count(minimum) << ", \"maxima\": " << R.count(maximum)
       << ", \"up_forks\": " << R.count(up_fork) << ", \"down_forks\": " << R.count(down_fork)
       << ", \"components\": " << R.components << ", \"augmented_arcs\": " << augmented.number_of_arcs()
       << ", \"seconds\": " << json_number(seconds);
    if (delta >= 0)
      os << ", \"simplified_by\": " << json_number(delta) << ", \"removed_branches\": " << removed_branches
         << ", \"removed_loops\": " << removed_loops;
    if (args.has("persistence")) {
      auto list = [&os](const char* name,
                        std::initializer_list<const std::vector<Reeb_persistence_pair>*> parts) {
        os << ", \"" << name << "\": [";
        bool first = true;
        for (const auto* part : parts)
          for (const Reeb_persistence_pair& p : *part) {
            os << (first ? "" : ", ") << "[" << json_number(p.birth) << ", " << json_number(p.death) << "]";
            first = false;
          }
        os << "]";
      };
      list("branch_pairs", {&P.sublevel_branches, &P.superlevel_branches});
      list("loop_pairs", {&P.loops});
    }
    os << "}\n";
  } else {
    os << "complex: " << K.number_of_vertices << " vertices, " << K.number_of_edges() << " edges, "
       << K.number_of_triangles() << " triangles\n"
       << "Reeb graph: " << R.nodes.size() << " nodes, " << R.arcs.size() << " arcs, " << R.loops()
       << " loops, " << R.components << " components\n"
       << "nodes: " << R.count(minimum) << " minima, " << R.count(maximum) << " maxima, " << R.count(up_fork)
       << " up-forks, " << R.count(down_fork) << " down-forks\n"
       << "time: " << seconds << " s\n";
  }
  std::fputs(os.str().c_str(), stdout);
  return 0;
}

namespace {
/// Greedy thinning in input order: a point is kept when no kept point lies within `spacing`. Kept points are
/// hashed by the cells of their first (up to) three coordinates: points within `spacing` lie in neighbouring
/// cells of any projection, so 27 cells are probed in any dimension (not 3^d), and the distance is checked in
/// full.
std::vector<std::size_t> thin_points(const Point_matrix& m, double spacing) {
  std::vector<std::size_t> kept;
  if (spacing <= 0) {
    for (std::size_t i = 0; i < m.rows; ++i) kept.push_back(i);
    return kept;
  }
  const std::size_t hashed = std::min<std::size_t>(m.dimension, 3);
  std::size_t probes = 1;
  for (std::size_t c = 0; c < hashed; ++c) probes *= 3;
  std::map<std::array<long long, 3>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < m.rows; ++i) {
    std::array<long long, 3> cell{0, 0, 0};
    for (std::size_t c = 0; c < hashed; ++c) {
      // Clamped so that far-out coordinates cannot overflow the cast (they only share cells, checked
      // exactly).
      const double q = std::floor(m.row(i)[c] / spacing);
      cell[c] = static_cast<long long>(std::max(-4e18, std::min(4e18, q)));
    }
    bool close = false;
    for (std::size_t k = 0; k < probes && !close; ++k) {
      std::array<long long, 3> probe = cell;
      std::size_t r = k;
      for (std::size_t c = 0; c < hashed; ++c, r /= 3) probe[c] = cell[c] + static_cast<long long>(r % 3) - 1;
      const auto it = grid.find(probe);
      if (it == grid.end()) continue;
      for (const std::size_t j : it->second) {
        // Scaled where squares would underflow or overflow (a spacing of 1e-200 kept copies, of 1e190 points
        // 1e185 apart).
        if (FeatureRecon::skeleton::internal::point_distance(m.row(i), m.row(j), m.dimension) < spacing) {
          close = true;
          break;
        }
      }
    }
    if (!close) {
      grid[cell].push_back(i);
      kept.push_back(i);
    }
  }
  return kept;
}

/// The median of the distances from each point to its nearest other point (NaN for fewer than two points):
/// the spacing that a Rips radius must exceed to join the points to their neighbours.
double median_of(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
/// Above `most` points, over `most` of them evenly spread by index (each against all): a warning needs no
/// more, and the exact graph costs as much as the Rips search above 3-D.
double median_nearest_distance(const Point_matrix& m, std::size_t most = 2000) {
  if (m.rows < 2) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> nearest;
  if (m.rows <= most) {
    const Proximity_graph g = build_knn_graph(m, 1);
    nearest.assign(m.rows, std::numeric_limits<double>::infinity());
    for (std::size_t e = 0; e < g.edges.size(); ++e)
      for (const Vertex_index v : g.edges[e]) nearest[v] = std::min(nearest[v], g.edge_lengths[e]);
  } else {
    for (std::size_t t = 0; t < most; ++t) {
      const std::size_t i = t * m.rows / most;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < m.rows; ++j)
        if (j != i)
          best = std::min(best, skeleton::internal::point_distance(m.row(i), m.row(j), m.dimension));
      nearest.push_back(best);
    }
  }
  return median_of(nearest);
}
double median_nearest_distance(const std::vector<double>& D, std::size_t n) {  // a distance matrix, row-major
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) nearest[i] = std::min(nearest[i], D[i * n + j]);
  return median_of(nearest);
}
}  // namespace

int run_skeleton(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"quiet", "undirected", "first-point-positions", "lonlat"},
                       {"points",
                        "image",
                        "ink",
                        "ink-threshold",
                        "tracks",
                        "distance-matrix",
                        "graph",
                        "radius",
                        "delta",
                        "repair",
                        "sample-spacing",
                        "link-gap",
                        "heading-tolerance",
                        "min-density",
                        "min-lateral-density",
                        "density-radius",
                        "density-heading-tolerance",
                        "segment-support",
                        "segment-turn-tolerance",
                        "straight-confirmed",
                        "min-confirmed",
                        "stand-down-path",
                        "quiet-ends",
                        "local-support",
                        "min-local-support",
                        "prune",
                        "merge",
                        "branch-merge",
                        "level-width",
                        "smoothing",
                        "smoothing-method",
                        "max-gap",
                        "max-triangles",
                        "out-vertices",
                        "out-edges",
                        "graphml",
                        "geojson",
                        "ply",
                        "svg",
                        "picture-size"});
  const int inputs = int(args.has("points")) + int(args.has("image")) + int(args.has("tracks")) +
                     int(args.has("distance-matrix")) + int(args.has("graph"));
  if (inputs != 1)
    throw Usage_error(
        "give exactly one of --points FILE, --image FILE, --tracks FILE, --distance-matrix FILE and "
        "--graph FILE");
  const bool image = args.has("image");
  if (!image && (args.has("ink") || args.has("ink-threshold")))
    throw Usage_error("--ink and --ink-threshold apply to --image only");
  const std::string ink = args.get_or("ink", "dark");
  if (ink != "dark" && ink != "bright") throw Usage_error("--ink must be dark or bright, got '" + ink + "'");
  long long ink_threshold = 128;
  if (args.has("ink-threshold")) {
    ink_threshold = args.get_int("ink-threshold");
    if (ink_threshold < 1 || ink_threshold > 255)
      throw Usage_error("--ink-threshold must be an integer grey level in [1, 255], got '" +
                        args.get("ink-threshold") + "'");
  }
  if (args.has("graph") && args.has("radius"))
    throw Usage_error("--radius does not apply to --graph (the graph's edges are used as they are)");
  // --points and --distance-matrix without --radius: estimate_rips_radius() derives it (and from it delta
  // and, for points, the thinning spacing) once the input is read.
  const bool estimated_radius = (args.has("points") || args.has("distance-matrix")) && !args.has("radius");
  // With --tracks every unset parameter is derived from the data (extract_road_map(): the median step between
  // fixes gives the radius, the radius the rest).
  const bool gps = args.has("tracks");
  double radius = args.has("radius") ? args.get_positive_double("radius") : image ? 1.5 : 0.0;
  // Lengths derived from R and W go up to 5R (the prune height of tracks) and 2W (branch merging, the gap).
  if (radius > 1e300)
    throw Usage_error(
        "--radius must be at most 1e300 (lengths derived from it, up to 5R, must stay finite), got '" +
        args.get("radius") + "'");
  const std::string out_v = args.get("out-vertices"), out_e = args.get("out-edges");
  Outputs outputs(args, {"out-vertices", "out-edges", "graphml", "geojson", "ply", "svg"});
  outputs.require_extension("svg", {"svg", "png", "jpg", "jpeg", "pgm", "ppm"}, "a picture");
  outputs.require_extension("ply", {"ply"}, "PLY polylines");
  io::Skeleton_picture_options picture;
  if (args.has("picture-size")) {
    if (!args.has("svg")) throw Usage_error("--picture-size applies to the picture of --svg F");
    const long long size = args.get_int("picture-size");
    if (size < 100 || size > 8192)
      throw Usage_error("--picture-size must be an integer number of pixels in [100, 8192], got '" +
                        args.get("picture-size") + "'");
    picture.long_side = static_cast<double>(size);
  }
  Skeleton_options options;
  options.delta = args.has("delta") ? args.get_double("delta") : gps ? 0.0 : image ? 2 * radius : radius;
  if (!(*options.delta >= 0))
    throw Usage_error("--delta must be >= 0 (0: no simplification; unset: automatic), got '" +
                      args.get("delta") + "'");
  options.repair_distance = args.has("repair") ? args.get_double("repair") : 0.0;
  if (options.repair_distance < 0)
    throw Usage_error("--repair must be >= 0 (0: no repair; unset: 0, or 2.5R with --tracks), got '" +
                      args.get("repair") + "'");
  if (args.has("tracks")) options.embedding = road_map_embedding_options();  // road maps keep their corners
  // As in the library: unset is automatic, 0 turns bridging off.
  if (args.has("level-width")) {
    const double w = args.get_double("level-width");
    if (!(w > 0 && w <= 1e300))
      throw Usage_error(
          "--level-width must be > 0 and at most 1e300 (2W must stay finite; unset: automatic), "
          "got '" +
          args.get("level-width") + "'");
    options.embedding.level_width = w;
  }
  if (args.has("max-gap")) {
    const double g = args.get_double("max-gap");
    if (!(g >= 0))
      throw Usage_error("--max-gap must be >= 0 (0: straight segments; unset: automatic), got '" +
                        args.get("max-gap") + "'");
    options.embedding.max_gap = g;
  }
  if (args.has("smoothing")) {
    const long long it = args.get_int("smoothing");
    if (it < 0 || it > 1000000)
      throw Usage_error("--smoothing must be an integer in [0, 1000000], got " + args.get("smoothing"));
    options.embedding.smoothing_iterations = static_cast<std::size_t>(it);
  }
  if (args.has("smoothing-method")) {
    const std::string m = args.get("smoothing-method");
    if (m == "taubin")
      options.embedding.smoothing = Embedding_options::Smoothing::taubin;
    else if (m == "laplacian")
      options.embedding.smoothing = Embedding_options::Smoothing::laplacian;
    else
      throw Usage_error("--smoothing-method must be taubin or laplacian, got '" + m + "'");
  }
  options.prune_height = args.has("prune") ? args.get_double("prune") : 0.0;
  if (!(options.prune_height >= 0))
    throw Usage_error("--prune must be >= 0 (0: keep all; unset: 0, or 5R with --tracks), got '" +
                      args.get("prune") + "'");
  if (args.has("branch-merge")) {
    options.branch_merge_distance = args.get_double("branch-merge");
    if (!(*options.branch_merge_distance >= 0 && std::isfinite(*options.branch_merge_distance)))
      throw Usage_error("--branch-merge must be finite and >= 0 (0: off), got '" + args.get("branch-merge") +
                        "'");
  }
  options.max_triangles = max_triangles_option(args);
  double spacing = args.has("sample-spacing") ? args.get_double("sample-spacing") : 0.0;
  if (spacing < 0 && !gps) throw Usage_error("--sample-spacing must be >= 0 (0: no thinning)");
  const bool quiet = args.has("quiet");
  if (!gps && (args.has("link-gap") || args.has("heading-tolerance") || args.has("min-density") ||
               args.has("min-lateral-density") || args.has("density-radius") ||
               args.has("density-heading-tolerance") || args.has("undirected") || args.has("merge") ||
               args.has("first-point-positions") || args.has("segment-support") ||
               args.has("segment-turn-tolerance") || args.has("straight-confirmed") ||
               args.has("min-confirmed") || args.has("stand-down-path") || args.has("local-support") ||
               args.has("min-local-support") || args.has("quiet-ends")))
    throw Usage_error(
        "--link-gap, --heading-tolerance, --undirected, --min-density, --min-lateral-density, "
        "--density-radius, --density-heading-tolerance, --first-point-positions, --min-confirmed, "
        "--segment-support, "
        "--segment-turn-tolerance, --stand-down-path, --straight-confirmed, --quiet-ends, --local-support, "
        "--min-local-support "
        "and "
        "--merge apply to --tracks only");
  if (!gps && args.has("lonlat")) throw Usage_error("--lonlat applies to --tracks only");
  const bool lonlat = args.has("lonlat");
  Transverse_mercator projection;  // --lonlat: degrees <-> metres
  if ((args.has("graph") || args.has("distance-matrix")) && args.has("sample-spacing"))
    throw Usage_error("--sample-spacing applies to --points, --image and --tracks only");
  Point_matrix m;
  std::size_t input_points = 0;
  Progress progress("skeleton", quiet);
  options.progress = std::ref(progress);
  const auto t0 = std::chrono::steady_clock::now();
  Reeb_skeleton s;
  Skeleton_graph merged;  // --tracks with merging: the skeleton of the merged map, which is what is written
  bool use_merged = false;
  std::string input_json;  // the JSON summary's fields of the input kind (tracks, image)
  std::size_t sampled = 0;
  // Set when the Rips graph has fewer edges than half the points (a radius below their spacing): their median
  // nearest-neighbour distance, for the warning.
  double spacing_hint = std::numeric_limits<double>::quiet_NaN();
  // Without --radius: the estimate gives R and delta (max(R, 2.25 x its scale)), and for points the thinning
  // spacing (thinning_spacing(): none up to 32 neighbours within R, else about 32 left, within (R - gap) / 2
  // unless the complex would be too large there).
  auto use_estimate = [&](const Rips_radius_estimate& e, const std::string& what) {
    if (!(e.radius <= 1e300)) {
      char value[32];
      std::snprintf(value, sizeof value, "%.6g", e.radius);
      throw io::Input_error(
          what + ": the radius derived from the data, " + value +
          ", exceeds 1e300 (lengths derived from it, up to 5R, must stay finite): give --radius");
    }
    radius = e.radius;
    if (!args.has("delta")) options.delta = e.delta;
    input_json += ", \"radius_estimate\": {\"scale\": " + json_number(e.scale) +
                  ", \"intrinsic_dimension\": " + json_number(e.intrinsic_dimension) +
                  ", \"mean_neighbours\": " + json_number(e.mean_neighbours) +
                  ", \"gap_radius\": " + json_number(e.gap_radius) +
                  ", \"distinct_points\": " + std::to_string(e.distinct_points) +
                  ", \"reference_points\": " + std::to_string(e.reference_points) + "}";
  };
  if (args.has("points") || image) {
    Point_matrix all;
    if (image) {  // the ink pixels' centres, y up
      const io::Image picture = io::to_grey(io::read_image(args.get("image")));
      all.dimension = 2;
      for (int row = 0; row < picture.height; ++row)
        for (int column = 0; column < picture.width; ++column)
          if ((picture.at(column, row) < ink_threshold) == (ink == "dark")) {
            all.data.push_back(column + 0.5);
            all.data.push_back(picture.height - row - 0.5);
            ++all.rows;
          }
      input_json = ", \"image_width\": " + std::to_string(picture.width) +
                   ", \"image_height\": " + std::to_string(picture.height) + ", \"ink\": \"" + ink +
                   "\", \"ink_threshold\": " + std::to_string(ink_threshold);
    } else {
      const io::Point_file pf = io::read_points(args.get("points"));
      all.rows = pf.size();
      all.dimension = pf.dimension;
      all.data = pf.coordinates;
    }
    input_points = all.rows;
    if (estimated_radius) {
      Progress estimate_progress("radius estimate", quiet);
      Rips_radius_options ro;
      ro.progress = std::ref(estimate_progress);
      const Rips_radius_estimate e = estimate_rips_radius(all, ro);
      use_estimate(e, args.get("points"));
      estimate_progress.done("R " + json_number(radius));
      if (!args.has("sample-spacing")) {
        const Thinning thin = thinning_spacing(e, options.max_triangles);
        spacing = thin.spacing;
        if (thin.beyond_cap)
          std::fprintf(
              stderr,
              "featurerecon skeleton: warning: the points are thinned at %.4g, beyond (R - gap radius) / 2 = "
              "%.4g, where gaps between kept points stay below R: thinned that little, the complex would "
              "hold about %.3g triangles (a quarter of --max-triangles is %.3g); give --sample-spacing to "
              "choose\n",
              spacing, thin.cap, thin.triangles_at_cap, static_cast<double>(options.max_triangles) / 4);
      }
    }
    const std::vector<std::size_t> kept = thin_points(all, spacing);
    m.rows = kept.size();
    m.dimension = all.dimension;
    for (const std::size_t i : kept) m.data.insert(m.data.end(), all.row(i), all.row(i) + all.dimension);
    s = extract_reeb_skeleton(m, radius, options);
    if (2 * s.rips_edges < m.rows) spacing_hint = median_nearest_distance(m);
  } else if (args.has("distance-matrix")) {
    const io::Point_file pf = io::read_points(args.get("distance-matrix"), "row", "distance");
    const std::string& path = args.get("distance-matrix");
    if (pf.dimension != pf.size())
      throw io::Input_error(path + ": a distance matrix needs n rows of n numbers; got " +
                            std::to_string(pf.size()) + " rows of " + std::to_string(pf.dimension));
    // Checked here too (the library checks the same) so that the message names the line of the file.
    const std::size_t n = pf.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double* row = pf.coordinates.data() + i * n;
      const std::string at = path + ":" + std::to_string(pf.lines[i]) + ": ";
      if (row[i] != 0)
        throw io::Input_error(at + "the diagonal entry of row " + std::to_string(i) + " is not 0");
      for (std::size_t j = 0; j < n; ++j) {
        if (row[j] < 0)
          throw io::Input_error(at + "negative distance in column " + std::to_string(j) + " of row " +
                                std::to_string(i));
        if (j < i && row[j] != pf.coordinates[j * n + i])
          throw io::Input_error(at + "not symmetric: entry (" + std::to_string(i) + ", " + std::to_string(j) +
                                ") is " + json_number(row[j]) + ", entry (" + std::to_string(j) + ", " +
                                std::to_string(i) + ") on line " + std::to_string(pf.lines[j]) + " is " +
                                json_number(pf.coordinates[j * n + i]));
      }
    }
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> D(
        pf.coordinates.data(), static_cast<Eigen::Index>(pf.size()), static_cast<Eigen::Index>(pf.size()));
    input_points = pf.size();
    if (estimated_radius) {
      Progress estimate_progress("radius estimate", quiet);
      Rips_radius_options ro;
      ro.progress = std::ref(estimate_progress);
      use_estimate(estimate_rips_radius_from_distance_matrix(D, ro), path);
      estimate_progress.done("R " + json_number(radius));
    }
    s = extract_reeb_skeleton_from_distance_matrix(D, radius, options);
    if (2 * s.rips_edges < pf.size()) spacing_hint = median_nearest_distance(pf.coordinates, pf.size());
    m.dimension = 3;
    m.rows = 0;  // no coordinates to draw: the SVG shows the skeleton only
    sampled = pf.size();
  } else if (args.has("graph")) {
    const io::Complex_file cf = io::read_complex(args.get("graph"));
    Proximity_graph g;
    g.number_of_vertices = cf.complex.number_of_vertices;
    g.edges = cf.complex.edges;
    for (const Edge& e : g.edges) {
      // hypot scales: no overflow of the squares; a length beyond the largest double is refused naming its
      // points (the edge's place in the file is lost: the complex sorts its edges).
      const auto &a = cf.positions[e[0]], &b = cf.positions[e[1]];
      const double length = std::hypot(std::hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
      if (!std::isfinite(length))
        throw io::Input_error(args.get("graph") + ": the edge between points " + std::to_string(e[0]) +
                              " and " + std::to_string(e[1]) + " is longer than the largest double");
      g.edge_lengths.push_back(length);
    }
    m.rows = cf.positions.size();
    m.dimension = 3;
    for (const auto& p : cf.positions) m.data.insert(m.data.end(), p.begin(), p.end());
    input_points = m.rows;
    s = extract_reeb_skeleton(g, m, options);
  } else {
    Gps_trace_options go = road_map_trace_options();
    // As in the library: unset is automatic, 0 turns a stage off.
    if (args.has("sample-spacing")) {
      if (!(spacing > 0))
        throw Usage_error("--sample-spacing must be > 0 with --tracks (unset: R/2), got '" +
                          args.get("sample-spacing") + "'");
      go.sample_spacing = spacing;
    }
    auto length_or_off = [&args](const std::string& flag, const char* off) -> std::optional<double> {
      if (!args.has(flag)) return FeatureRecon::automatic;
      const double v = args.get_double(flag);
      if (!(v >= 0 && std::isfinite(v)))
        throw Usage_error("--" + flag + " must be >= 0 metres and finite (0: " + off +
                          "; unset: automatic), got '" + args.get(flag) + "'");
      return v;
    };
    go.max_link_gap = length_or_off("link-gap", "no linking");
    go.segment_support = length_or_off("segment-support", "no check");
    if (args.has("segment-turn-tolerance"))
      go.segment_turn_tolerance = args.get_double("segment-turn-tolerance");
    if (!(go.segment_turn_tolerance >= 0 && go.segment_turn_tolerance <= 180))
      throw Usage_error("--segment-turn-tolerance must be in [0, 180] degrees");
    auto fix_count = [&args](const std::string& flag, std::size_t& count) {  // a number of nearest fixes
      if (!args.has(flag)) return;
      const double v = args.get_double(flag);
      if (!(v >= 0 && v <= 1024 && v == std::floor(v)))
        throw Usage_error("--" + flag + " must be a whole number of fixes in [0, 1024] (0: off)");
      count = static_cast<std::size_t>(v);
    };
    fix_count("local-support", go.local_support_fixes);
    fix_count("quiet-ends", go.quiet_end_fixes);
    if (args.has("min-local-support")) go.min_local_support = args.get_double("min-local-support");
    if (!(go.min_local_support > 0 && go.min_local_support <= 1))
      throw Usage_error("--min-local-support must be in (0, 1] (a fraction of the segment support)");
    if (args.has("straight-confirmed"))
      go.min_straight_confirmed_fraction = args.get_double("straight-confirmed");
    if (!(go.min_straight_confirmed_fraction >= 0 && go.min_straight_confirmed_fraction <= 1))
      throw Usage_error("--straight-confirmed must be in [0, 1] (0: the turn rule always applies)");
    if (args.has("min-confirmed")) go.min_confirmed_fraction = args.get_double("min-confirmed");
    if (!(go.min_confirmed_fraction >= 0 && go.min_confirmed_fraction <= 1))
      throw Usage_error("--min-confirmed must be in [0, 1] (0: the segment check never stands down)");
    if (args.has("stand-down-path"))
      go.stand_down_path_factor = args.get_double("stand-down-path") + 0.0;  // -0 prints as 0
    if (!(go.stand_down_path_factor >= 0 && std::isfinite(go.stand_down_path_factor)))
      throw Usage_error(
          "--stand-down-path must be >= 0 and finite (a factor of a segment's length; 0: the stand-down "
          "densifies every segment)");
    if (args.has("heading-tolerance")) go.heading_tolerance = args.get_double("heading-tolerance");
    if (args.has("density-radius")) go.density_radius = args.get_positive_double("density-radius");
    if (args.has("min-density")) go.min_relative_density = args.get_double("min-density");
    if (args.has("min-lateral-density")) go.min_lateral_density = args.get_double("min-lateral-density");
    if (args.has("density-heading-tolerance"))
      go.density_heading_tolerance = args.get_double("density-heading-tolerance");
    if (!(go.density_heading_tolerance >= 0 && go.density_heading_tolerance <= 180))
      throw Usage_error("--density-heading-tolerance must be in [0, 180] degrees");
    go.directed = !args.has("undirected");
    go.mean_positions = !args.has("first-point-positions");
    if (!(go.min_relative_density >= 0 && go.min_relative_density <= 1))
      throw Usage_error("--min-density must be in [0, 1]");
    if (!(go.min_lateral_density >= 0 && go.min_lateral_density <= 1))
      throw Usage_error("--min-lateral-density must be in [0, 1]");
    if (!(go.heading_tolerance >= 0 && go.heading_tolerance <= 180))
      throw Usage_error("--heading-tolerance must be in [0, 180] degrees");
    // with where each fix was read, to name the file, line and trip id where the library names trip and fix
    // indices
    Track_input tracks = read_tracks(args.get("tracks"), lonlat);
    warn_few_fixes_per_trip("skeleton", args.get("tracks"), tracks);
    std::vector<Gps_trip>& trips = tracks.trips;
    if (lonlat) {  // x, y are longitude and latitude: to metres, centred on the traces
      projection = lonlat_projection({tracks.lonlat_source(args.get("tracks"))});
      project_trips(trips, projection);
    }
    // Fixes a centimetre apart are not GPS in metres; in degrees they are a few metres apart. Checked before
    // the pipeline runs (it ran first, minutes on a large file, to be refused).
    // Of the fixes as read (or projected), every step: the stay rule's 20 m and 30 s are metres and seconds,
    // and in degrees every fix lies within 20 of every other (tracks in degrees went unrefused).
    const double median_step = median_gps_step(trips, 0, std::numeric_limits<double>::infinity());
    if (!lonlat) refuse_degree_tracks(args.get("tracks"), trips, median_step);
    // Fixes kilometres apart are the other mistake of units (centimetres, a projection's map units): every
    // segment is then linked and sampled every few metres (100 km steps: about 13,000 samples each), which
    // took minutes and gigabytes without a word. Warned before the pipeline runs.
    if (const double step = median_step; !lonlat && step > 2000) {
      double length = 0;
      for (const Gps_trip& trip : trips)
        for (std::size_t i = 1; i < trip.size(); ++i)
          length += std::hypot(trip[i].x - trip[i - 1].x, trip[i].y - trip[i - 1].y);
      std::fprintf(
          stderr,
          "featurerecon skeleton: warning: %s: the median step between consecutive fixes of a trip is "
          "%.4g km, and the trips are %.4g km long; the tracks are read in metres and seconds. If "
          "the coordinates are in another unit (centimetres, millimetres), convert them first: fixes this "
          "far apart are joined by straight segments sampled every few metres, which takes long and "
          "needs about 1 GB per 2,000 km\n",
          args.get("tracks").c_str(), step / 1000, length / 1000);
    }
    // Several vehicles under one trip id: consecutive fixes by time then jump between vehicles, kilometres
    // apart within seconds, and every jump is linked and sampled (230,000 fixes of 4,000 vehicles under one
    // id: 44 s, 0.8 GB and a map of chords, without a word). Warned when the median speed between consecutive
    // fixes of a trip, where time advances, exceeds 70 m/s (252 km/h); trips read without times (a
    // fix's time is then its line number) are left out.
    {
      std::vector<double> speeds;
      for (std::size_t t = 0; t < trips.size(); ++t) {
        const std::vector<std::size_t> o = skeleton::internal::time_order(trips[t]);
        for (std::size_t i = 0; i < o.size(); ++i) {
          const Gps_fix& f = trips[t][o[i]];
          if (i == 0 || !tracks.origin.timed[t]) continue;
          const Gps_fix& e = trips[t][o[i - 1]];
          if (f.time > e.time) speeds.push_back(std::hypot(f.x - e.x, f.y - e.y) / (f.time - e.time));
        }
      }
      if (!speeds.empty()) {
        std::nth_element(speeds.begin(), speeds.begin() + std::ptrdiff_t(speeds.size() / 2), speeds.end());
        if (const double speed = speeds[speeds.size() / 2]; speed > 70)
          std::fprintf(stderr,
                       "featurerecon skeleton: warning: %s: the median speed between consecutive fixes of a "
                       "trip is %.4g m/s (%.4g km/h): do several vehicles share a trip id, or are the times "
                       "not in seconds? Consecutive fixes of a trip are joined by straight segments\n",
                       args.get("tracks").c_str(), speed, 3.6 * speed);
      }
    }
    Road_map_options ro;
    if (radius > 0) ro.rips_radius = radius;
    // As in the library, unset means automatic and 0 turns a stage off.
    auto value = [&](const char* name, const std::optional<double>& v) {
      return args.has(name) ? v : FeatureRecon::automatic;
    };
    ro.delta = value("delta", options.delta);
    ro.repair_distance = value("repair", options.repair_distance);
    ro.prune_height = value("prune", options.prune_height);
    if (args.has("merge") && !(args.get_double("merge") >= 0))
      throw Usage_error("--merge must be >= 0 (0: no merging; unset: 8 m), got '" + args.get("merge") + "'");
    if (args.has("merge")) ro.merge_distance = args.get_double("merge");
    ro.traces = go;
    ro.max_triangles = options.max_triangles;
    if (args.has("branch-merge")) ro.branch_merge_distance = options.branch_merge_distance;  // else off
    ro.embedding = options.embedding;
    ro.progress = options.progress;
    Road_map road;
    try {
      road = extract_road_map(trips, ro);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(tracks.origin.locate(e.what()));
    }
    const Gps_trace_sample& sample = road.sample;
    radius = *road.used.rips_radius;
    options.delta = road.used.delta;
    options.repair_distance = *road.used.repair_distance;
    options.prune_height = *road.used.prune_height;
    input_points = sample.fixes;
    spacing = sample.sample_spacing;
    m = sample.points;
    s = std::move(road.skeleton);
    // merge_road_lines() ran (a skeleton pruned empty leaves nothing to merge: it did not)
    use_merged = *road.used.merge_distance > 0 && road.merged.samples > 0;
    if (use_merged) merged = std::move(road.merged.skeleton);
    // Without merging the map is the skeleton itself: its length before and after.
    const double unmerged_length =
        use_merged ? 0.0 : skeleton::internal::map_length(road.map.positions, road.map.edges);
    input_json = ", \"trips\": " + std::to_string(trips.size()) +
                 ", \"median_step\": " + json_number(sample.median_step) +
                 ", \"link_gap\": " + json_number(sample.max_link_gap) +
                 ", \"segment_support\": " + json_number(sample.segment_support) +
                 ", \"segment_turn_tolerance\": " + json_number(sample.segment_turn_tolerance) +
                 ", \"checked_segments\": " + std::to_string(sample.checked_segments) +
                 ", \"confirmed_segments\": " + std::to_string(sample.confirmed_segments) +
                 ", \"straight_checked\": " + std::to_string(sample.straight_checked) +
                 ", \"straight_confirmed\": " + std::to_string(sample.straight_confirmed) +
                 ", \"min_straight_confirmed_fraction\": " + json_number(go.min_straight_confirmed_fraction) +
                 ", \"turn_rule_used\": " + (sample.turn_rule_used ? "true" : "false") +
                 ", \"straight_segments\": " + std::to_string(sample.straight_segments) +
                 ", \"linked_segments\": " + std::to_string(sample.linked_segments) +
                 ", \"all_segments_used\": " + (sample.all_segments_used ? "true" : "false") +
                 ", \"min_confirmed_fraction\": " + json_number(go.min_confirmed_fraction) +
                 ", \"local_support\": " + std::to_string(go.local_support_fixes) +
                 ", \"min_local_support\": " + json_number(go.min_local_support) +
                 ", \"locally_checked\": " + std::to_string(sample.locally_checked) +
                 ", \"locally_rejected\": " + std::to_string(sample.locally_rejected) +
                 ", \"quiet_ends\": " + std::to_string(go.quiet_end_fixes) +
                 ", \"quiet_segments\": " + std::to_string(sample.quiet_segments) +
                 ", \"stand_down_path\": " + json_number(go.stand_down_path_factor) +
                 ", \"joined_segments\": " + std::to_string(sample.joined_segments) +
                 ", \"min_density\": " + json_number(go.min_relative_density) +
                 ", \"min_lateral_density\": " + json_number(go.min_lateral_density) +
                 ", \"density_radius\": " + json_number(sample.density_radius) +
                 ", \"density_heading_tolerance\": " + json_number(sample.density_heading_tolerance) +
                 ", \"directed\": " + (go.directed ? "true" : "false") +
                 ", \"mean_positions\": " + (go.mean_positions ? "true" : "false") +
                 ", \"dropped\": " + std::to_string(sample.dropped) +  // by either filter
                 ", \"dropped_sparse\": " + std::to_string(sample.dropped - sample.dropped_lateral) +
                 ", \"dropped_lateral\": " + std::to_string(sample.dropped_lateral) +
                 ", \"trip_links\": " + std::to_string(sample.trip_links.size()) +
                 ", \"heading_tolerance\": " + json_number(go.heading_tolerance) +
                 ", \"merge_distance\": " + json_number(*road.used.merge_distance) +
                 ", \"length_before_merge\": " +
                 json_number(use_merged ? road.merged.length_before : unmerged_length) +
                 ", \"length\": " + json_number(use_merged ? road.merged.length_after : unmerged_length);
    // how the written lines were drawn (the fields below without merge_ drew the skeleton before)
    if (use_merged) {
      const Embedding_options& drawn = skeleton::road_map_merge_options(road.used).embedding;
      input_json +=
          std::string(", \"merge_smoothing\": \"") +
          (drawn.smoothing == Embedding_options::Smoothing::taubin ? "taubin" : "laplacian") +
          "\", \"merge_smoothing_rounds\": " + std::to_string(drawn.smoothing_iterations) +
          ", \"merge_level_width\": " + json_number(road.merged.level_width) +
          ", \"merge_max_gap\": " + json_number(std::isinf(road.merged.max_gap) ? 0.0 : road.merged.max_gap) +
          ", \"merge_spacing\": " + json_number(road.merged.spacing) +
          ", \"merge_samples\": " + std::to_string(road.merged.samples) +
          ", \"merge_rips_edges\": " + std::to_string(road.merged.rips_edges) +
          ", \"merge_rips_triangles\": " + std::to_string(road.merged.rips_triangles);
    }
    // The check of segments stood down (Gps_trace_options::min_confirmed_fraction): say so, since every
    // segment up to the link gap is then drawn (but those whose ends the fixes join), chords across blocks
    // where fixes lie far apart.
    if (sample.all_segments_used && go.min_confirmed_fraction > 0 && sample.segment_support > 0 &&
        sample.max_link_gap > 0 && sample.checked_segments > 0)
      std::fprintf(stderr,
                   "featurerecon skeleton: warning: %zu of %zu checked segments between fixes are confirmed "
                   "by other fixes at the segment support, below --min-confirmed %g: the check stands down, "
                   "taking the traces as too sparse to judge one another, and every segment up to the link "
                   "gap (%.4g m) is densified but the %zu whose ends the fixes alone join (--stand-down-path "
                   "%g); with fixes far apart (median step %.4g m) the densified lines may cut across blocks "
                   "(--min-confirmed 0 keeps the check, --link-gap bounds the segments used)\n",
                   sample.confirmed_segments + sample.locally_rejected, sample.checked_segments,
                   go.min_confirmed_fraction, sample.max_link_gap, sample.joined_segments,
                   go.stand_down_path_factor, sample.median_step);
    if (lonlat)
      input_json += ", \"lonlat\": true, \"central_meridian\": " + json_number(projection.central_meridian) +
                    ", \"origin_latitude\": " + json_number(projection.origin_latitude);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.done();
  if (m.rows > 0) sampled = m.rows;
  // Map output: nodes first, then the interior points of every arc's polyline.
  const Skeleton_graph& graph = use_merged ? merged : s.graph;
  // --lonlat: the files in degrees, as the tracks were; the picture stays in metres (undistorted).
  Skeleton_graph in_degrees;
  if (lonlat) {
    in_degrees = graph;
    auto to_degrees = [&projection](std::array<double, 3>& p) {
      const auto ll = projection.inverse(p[0], p[1]);
      p[0] = ll[0];
      p[1] = ll[1];
    };
    for (auto v : boost::make_iterator_range(vertices(in_degrees))) to_degrees(in_degrees[v].position);
    for (auto e : boost::make_iterator_range(edges(in_degrees)))
      for (auto& p : in_degrees[e].polyline) to_degrees(p);
  }
  const Skeleton_graph& written = lonlat ? in_degrees : graph;
  const Embedded_graph_2 map = skeleton_to_road_map(written);
  io::write_map(outputs.path("out-vertices"), outputs.path("out-edges"), map.positions, map.edges);
  if (args.has("graphml")) io::write_skeleton_graphml(outputs.path("graphml"), written);
  if (args.has("geojson")) io::write_skeleton_geojson(outputs.path("geojson"), written, lonlat);
  if (args.has("ply")) io::write_skeleton_ply(outputs.path("ply"), written);
  if (args.has("svg")) {
    // The points as the skeleton is drawn: their first two coordinates, above 3-D those of the PCA
    // projection.
    std::vector<std::array<double, 2>> xy;
    if (m.dimension > 3) {
      for (const auto& p : project_to_3d(m)) xy.push_back({p[0], p[1]});
    } else {
      for (std::size_t i = 0; i < m.rows; ++i)
        xy.push_back({m.row(i)[0], m.dimension > 1 ? m.row(i)[1] : 0.0});
    }
    // The radius used (derived from tracks); a graph has none: its level width (median edge length) stands
    // in.
    picture.feature_size = args.has("graph") ? s.level_width : radius;
    io::write_skeleton_picture(outputs.path("svg"), xy, graph, picture);
  }
  outputs.commit();
  if (input_points == 0) {
    const char* what = args.has("tracks")            ? "fixes"
                       : args.has("distance-matrix") ? "rows"
                       : args.has("graph")           ? "vertices"
                       : image                       ? "ink pixels (--ink, --ink-threshold)"
                                                     : "points";
    std::fprintf(stderr, "featurerecon skeleton: warning: the input holds no %s: the skeleton is empty\n",
                 what);
  } else if (num_vertices(graph) == 0) {  // every part removed: say by which stage
    std::string why;
    if (gps && m.rows == 0)
      why = "the density filter dropped every sample (--min-density 0 --min-lateral-density 0 keep them)";
    else if (s.pruned_components > 0)
      why = "pruning removed all " + std::to_string(s.pruned_components) +
            " component(s), each of height at most " + json_number(options.prune_height) +
            " (--prune 0 keeps them)";
    else
      why = "no part of it survived";
    std::fprintf(stderr, "featurerecon skeleton: warning: the skeleton is empty: %s\n", why.c_str());
  }
  if (!std::isnan(spacing_hint))
    std::fprintf(
        stderr,
        "featurerecon skeleton: warning: at radius %s the Rips graph has %zu edge%s for %zu points (fewer "
        "than one neighbour per point; %zu without any), so the skeleton is mostly single points; the median "
        "distance from a "
        "point to its nearest neighbour is %.3g%s: give --radius above it (a few times it joins each point "
        "to "
        "its neighbours)\n",
        json_number(radius).c_str(), s.rips_edges, s.rips_edges == 1 ? "" : "s", sampled, s.isolated_points,
        spacing_hint, sampled > 2000 && !args.has("distance-matrix") ? " (over 2,000 of them)" : "");
  std::size_t components = 0;
  {
    std::vector<int> comp(num_vertices(graph));
    if (!comp.empty()) components = static_cast<std::size_t>(boost::connected_components(graph, comp.data()));
  }
  std::fprintf(
      outputs.summary_stream(),
      "{\"points\": %zu, \"sampled\": %zu, \"radius\": %s, \"delta\": %s, \"repair\": %s, "
      "\"sample_spacing\": %s, "
      "\"rips_edges\": %zu, \"rips_triangles\": %zu, \"max_triangles\": %zu, \"isolated_points\": %zu, "
      "\"nodes\": %zu, \"arcs\": %zu, "
      "\"loops\": %zu, "
      "\"components\": %zu, \"removed_branches\": %zu, \"removed_loops\": %zu, \"repaired\": %zu, "
      "\"branch_merge\": %s, \"merged_branch_arcs\": %zu, \"prune\": %s, "
      "\"level_width\": %s, \"max_gap\": %s, \"smoothing\": \"%s\", \"smoothing_rounds\": %zu%s, "
      "\"seconds\": %s, "
      "\"vertices_file\": %s, \"edges_file\": %s}\n",
      input_points, sampled,
      json_number(args.has("graph") ? std::numeric_limits<double>::quiet_NaN() : radius).c_str(),
      json_number(*options.delta).c_str(), json_number(options.repair_distance).c_str(),
      json_number(spacing).c_str(), s.rips_edges, s.rips_triangles, options.max_triangles, s.isolated_points,
      num_vertices(graph), num_edges(graph), num_edges(graph) + components - num_vertices(graph), components,
      s.removed_branches, s.removed_loops, s.repaired, json_number(s.branch_merge_distance).c_str(),
      s.merged_branch_arcs, json_number(options.prune_height).c_str(), json_number(s.level_width).c_str(),
      json_number(std::isinf(s.max_gap) ? 0.0 : s.max_gap).c_str(),  // off as --max-gap takes it
      options.embedding.smoothing == Embedding_options::Smoothing::taubin ? "taubin" : "laplacian",
      options.embedding.smoothing_iterations, input_json.c_str(), json_number(seconds).c_str(),
      json_string(out_v).c_str(), json_string(out_e).c_str());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
