// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Subcommands of the skeleton subsystem: rips, reeb.

#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/reeb_graph_persistence.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <chrono>
#include <cstdio>
#include <sstream>

#include "../io/featurerecon_io.h"
#include "cli_common.h"
#include "commands.h"

namespace FeatureRecon {
namespace cli {

using namespace FeatureRecon::skeleton;

int run_rips(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"quiet"}, {"points", "radius", "knn", "out", "search"});
  const std::string points_path = args.get("points");
  const std::string out_path = args.get("out");
  if (args.has("radius") == args.has("knn")) throw Usage_error("give exactly one of --radius R and --knn K");
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

  const io::Point_file pf = io::read_points(points_path);
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
  const Simplicial_complex_2 K = build_flag_complex_2(g, std::ref(complex_progress));
  complex_progress.done(std::to_string(K.number_of_triangles()) + " triangles");

  Progress geodesic_progress("geodesic function", quiet);
  Geodesic_options gopt;
  gopt.progress = std::ref(geodesic_progress);
  const Geodesic_result geo = compute_geodesic_function(K, gopt);
  geodesic_progress.done(std::to_string(geo.base_points.size()) + " components");

  std::vector<std::array<double, 3>> positions(m.rows, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t c = 0; c < std::min<std::size_t>(3, m.dimension); ++c) positions[i][c] = m.row(i)[c];
  io::write_complex(out_path, K, positions, geo.values.empty() ? std::vector<double>(m.rows, 0.0) : geo.values);
  std::printf("wrote %s: %zu vertices, %zu edges, %zu triangles, %zu components (dimension %zu)\n", out_path.c_str(),
              K.number_of_vertices, K.number_of_edges(), K.number_of_triangles(), geo.base_points.size(),
              m.dimension);
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
  const bool quiet = args.has("quiet") || args.has("json");
  Progress progress("reeb graph", quiet);
  Reeb_graph_options options;
  options.progress = std::ref(progress);
  const auto t0 = std::chrono::steady_clock::now();
  const Augmented_reeb_graph augmented = compute_augmented_reeb_graph(cf.complex, cf.values, options);
  std::size_t removed_branches = 0, removed_loops = 0;
  Reeb_graph R;
  if (delta >= 0) {
    Reeb_simplification_result S = simplify_by_persistence(augmented, delta);
    R = std::move(S.graph);
    removed_branches = S.removed_branches;
    removed_loops = S.removed_loops;
  } else {
    R = augmented.reeb_graph();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.done();
  const Simplicial_complex_2& K = cf.complex;
  std::ostringstream os;
  if (args.has("json")) {
    os << "{\"vertices\": " << K.number_of_vertices << ", \"edges\": " << K.number_of_edges()
       << ", \"triangles\": " << K.number_of_triangles() << ", \"nodes\": " << R.nodes.size()
       << ", \"arcs\": " << R.arcs.size() << ", \"loops\": " << R.loops() << ", \"minima\": " << R.count(minimum)
       << ", \"maxima\": " << R.count(maximum) << ", \"up_forks\": " << R.count(up_fork)
       << ", \"down_forks\": " << R.count(down_fork) << ", \"components\": " << R.components
       << ", \"augmented_arcs\": " << augmented.number_of_arcs() << ", \"seconds\": " << json_number(seconds);
    if (delta >= 0)
      os << ", \"simplified_by\": " << json_number(delta) << ", \"removed_branches\": " << removed_branches
         << ", \"removed_loops\": " << removed_loops;
    if (args.has("persistence")) {
      const Reeb_graph_persistence P = compute_reeb_graph_persistence(R);
      auto list = [&os](const char* name, std::initializer_list<const std::vector<Reeb_persistence_pair>*> parts) {
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
       << "Reeb graph: " << R.nodes.size() << " nodes, " << R.arcs.size() << " arcs, " << R.loops() << " loops, "
       << R.components << " components\n"
       << "nodes: " << R.count(minimum) << " minima, " << R.count(maximum) << " maxima, " << R.count(up_fork)
       << " up-forks, " << R.count(down_fork) << " down-forks\n"
       << "time: " << seconds << " s\n";
  }
  std::fputs(os.str().c_str(), stdout);
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
