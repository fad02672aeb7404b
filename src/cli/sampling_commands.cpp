// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// featurerecon sample, sample-stats: feature-aware downsampling of point clouds and spacing statistics.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/discrete_samplers.h"
#include "io/featurerecon_io.h"
#include "io/point_cloud_io.h"

namespace FeatureRecon {
namespace cli {
namespace {

/// --period X[,Y[,Z]]: the periods of the torus the samples live on, one value for every axis or one per axis
/// of the `dimension`-D input, each a scale in [1e-150, 1e150] (dimension 0, an empty file: as given); empty
/// when the option is not given.
std::vector<double> period_of(const Arguments& args, std::size_t dimension) {
  if (!args.has("period")) return {};
  const std::string text = args.get("period");
  std::vector<double> period;
  std::size_t from = 0;
  while (true) {
    const std::size_t comma = text.find(',', from);
    const std::string part = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    double x = 0;
    if (!io::parse_decimal(part, x) || !(x >= 1e-150 && x <= 1e150))
      throw Usage_error(
          "--period takes one length or one per axis, each a number in [1e-150, 1e150] "
          "separated by commas, got '" +
          text + "'");
    period.push_back(x);
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  if (dimension == 0) return period;
  if (period.size() == 1) period.assign(dimension, period[0]);
  if (period.size() != dimension)
    throw Usage_error("--period has " + std::to_string(period.size()) + " lengths for " +
                      std::to_string(dimension) + "-D points (give one, or one per axis)");
  return period;
}

/// The periods as a JSON array, or null.
std::string json_period(const std::vector<double>& period) {
  if (period.empty()) return "null";
  std::string out = "[";
  for (std::size_t k = 0; k < period.size(); ++k) out += (k ? ", " : "") + json_number(period[k]);
  return out + "]";
}

using K = CGAL::Epick;
using Pwn = std::pair<K::Point_3, K::Vector_3>;
namespace fs = FeatureRecon::sampling;

double sigma_feature_of(const Arguments& args) {
  const double euclidean = std::numeric_limits<double>::infinity();  // the default, also given as `inf`
  double x = 0;
  if (!args.has("sigma-feature") || (io::parse_decimal(args.get("sigma-feature"), x) && x == euclidean))
    return euclidean;
  return args.get_scale("sigma-feature");
}

/// Intrinsic dimension and measure of a 3D cloud, as the elimination derives them: on its distinct positions
/// (copies would be neighbours at distance 0, and a kd-tree peels one copy per level: 40,000 copies of a
/// point overflowed the stack).
std::pair<int, double> domain_of(const std::vector<std::array<double, 3>>& cloud) {
  const std::vector<std::array<double, 3>> p = fs::internal::distinct_positions(cloud);
  const fs::internal::Knn_3 knn(p);
  const int dim = fs::internal::estimate_intrinsic_dimension(p, knn);
  return {dim,
          dim == 2 ? fs::internal::estimate_surface_area(p, knn) : fs::internal::bounding_box_measure<3>(p)};
}
/// The points of a text file (`sample`, `sample-stats`: any file but PLY, OFF and XYZ). A file that is no
/// such text and does not end in .txt or .xyz (an OBJ mesh, a compressed or binary cloud) is said to have
/// been read as text, with the formats that are clouds.
io::Point_file read_text_points(const std::string& input) {
  try {
    return io::read_points(input);
  } catch (const io::Input_error& e) {
    // Only what the content says ("FILE:LINE: ..."): a missing file or a directory is no matter of format.
    const std::string extension = io::file_extension(input), message = e.what(), located = input + ":";
    const bool content = message.compare(0, located.size(), located) == 0 &&
                         message.size() > located.size() &&
                         std::isdigit(static_cast<unsigned char>(message[located.size()]));
    if (!content || extension == "txt" || extension == "xyz") throw;
    throw io::Input_error(
        std::string(e.what()) + " (" +
        (extension.empty() ? std::string("a file without an extension") : "a file ending in ." + extension) +
        " is read as text: 2 or 3 numbers per line, or 6 with normals; point clouds are PLY, OFF "
        "or XYZ)");
  }
}

/// `sample` on points in the plane (a text file of lines `x y`): Euclidean spacing, written as `x y` lines.
int sample_plane(const Arguments& args, const io::Point_file& file, Sampler_request request,
                 Outputs& outputs) {
  const std::string input = args.get("input");
  request.period = period_of(args, 2);
  if (io::file_extension(outputs.target("out")) != "txt")
    throw Usage_error(input +
                      " holds points in the plane (2 numbers per line), written as lines 'x y': give "
                      "--out FILE.txt");
  if (std::isfinite(request.sigma_feature))
    throw Usage_error("--sigma-feature needs normals, which points in the plane (" + input + ") do not have");
  std::vector<K::Point_2> points;
  for (std::size_t i = 0; i < file.size(); ++i)
    points.emplace_back(file.coordinates[2 * i], file.coordinates[2 * i + 1]);
  if (request.count > points.size())
    throw Usage_error("--count " + std::to_string(request.count) + " exceeds the " +
                      std::to_string(points.size()) + " points of " + input);
  if (points.empty())
    std::fprintf(stderr, "featurerecon sample: warning: %s holds no points: the sample is empty\n",
                 input.c_str());
  Progress progress("sampling", args.has("quiet"));
  double used_radius = 0;
  const std::vector<std::size_t> kept = run_sampler(
      points, FeatureRecon::Default_traits_t<std::vector<K::Point_2>>(), request, progress, used_radius);
  progress.done(std::to_string(kept.size()) + " of " + std::to_string(points.size()) + " points kept");
  const double seconds = progress.seconds();
  std::string text;
  for (const std::size_t i : kept)
    text += io::format_double(points[i].x()) + " " + io::format_double(points[i].y()) + "\n";
  io::write_text_file(outputs.path("out"), text);
  outputs.commit();
  // Spacing of the result on the domain the elimination derives: the torus, or the input's bounding box.
  fs::Sampling_quality_options q;
  q.periodic = request.periodic;
  q.period = request.period;
  if (!request.periodic) {
    std::vector<std::array<double, 2>> positions;
    for (const K::Point_2& p : points) positions.push_back({p.x(), p.y()});
    q.domain_measure = fs::internal::bounding_box_measure<2>(positions);
  }
  std::vector<K::Point_2> kept_points;
  for (const std::size_t i : kept) kept_points.push_back(points[i]);
  const fs::Sampling_quality quality = fs::sampling_quality(kept_points, q);
  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"points\": " << points.size()
     << ", \"kept\": " << kept.size() << ", \"method\": \"" << request.method
     << "\", \"radius\": " << json_number(used_radius)
     << ", \"sigma_position\": " << json_number(request.sigma_position) << ", \"seed\": " << request.seed
     << ", \"dimension\": 2, \"periodic\": " << (request.periodic ? "true" : "false")
     << ", \"period\": " << json_period(request.period)
     << ", \"intrinsic_dimension\": 2, \"domain_measure\": " << json_number(quality.domain_measure)
     << ", \"relative_radius\": " << json_statistic(quality.relative_radius, quality.status)
     << ", \"average_minimum_distance\": " << json_statistic(quality.average_minimum_distance, quality.status)
     << ", \"seconds\": " << json_number(seconds) << ", \"output\": " << json_string(args.get("out"))
     << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}
}  // namespace

int run_sample(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"unoriented", "periodic", "quiet"},
                       {"input", "count", "radius", "method", "sigma-position", "sigma-feature", "seed",
                        "out", "normal-neighbors", "period"});
  const std::string input = args.get("input"), output = args.get("out");
  Outputs outputs(args, {"out"});
  outputs.require_extension("out", {"ply", "off", "xyz", "txt"},
                            "a point cloud (or, for points in the plane, text)");
  const std::string method = args.get_or("method", "elimination");
  if (method != "elimination" && method != "darts")
    throw Usage_error("--method must be elimination or darts, got '" + method + "'");
  if (!args.has("count") && !args.has("radius"))
    throw Usage_error("give --count M (exact count) or --radius R");
  if (method == "elimination" && !args.has("count"))
    throw Usage_error("--method elimination needs --count M");
  long long count = 0;
  if (args.has("count")) {
    count = args.get_int("count");
    if (count < 1) throw Usage_error("--count must be >= 1, got " + std::to_string(count));
  }
  const double radius = args.has("radius") ? args.get_positive_double("radius") : 0.0;
  const double sigma_position = args.has("sigma-position") ? args.get_scale("sigma-position") : 1.0;
  const double sigma_feature = sigma_feature_of(args);
  for (const char* normal_option : {"unoriented", "normal-neighbors"})  // refused, not ignored
    if (args.has(normal_option) && !std::isfinite(sigma_feature))
      throw Usage_error(
          std::string("--") + normal_option +
          " goes with --sigma-feature (without it the spacing is Euclidean: normals are neither "
          "compared nor estimated)");
  const long long seed = args.has("seed") ? args.get_int("seed") : 0;
  if (seed < 0) throw Usage_error("--seed must be >= 0");
  const long long neighbors = args.has("normal-neighbors") ? args.get_int("normal-neighbors") : 18;
  // K neighbours of every point are held at once: beyond a million that is no longer a neighbourhood (and
  // 2^32 wrapped to 0 in the estimator's unsigned count).
  if (neighbors < 3 || neighbors > 1000000) throw Usage_error("--normal-neighbors must be in [3, 1000000]");
  const bool quiet = args.has("quiet");
  Sampler_request request;
  request.method = method;
  request.count = static_cast<std::size_t>(count);
  request.radius = radius;
  request.sigma_position = sigma_position;
  request.sigma_feature = sigma_feature;
  request.seed = static_cast<std::uint64_t>(seed);
  request.periodic = args.has("periodic") || args.has("period");  // --period: a torus of other lengths

  // PLY, OFF and XYZ are point clouds; other text files hold points in the plane (2 numbers per line) or
  // clouds (3, or 6 with normals), as `sample-stats` reads them.
  const std::string extension = io::file_extension(input);
  io::Point_cloud cloud;
  // An empty cloud is degenerate, not an error: --count refuses it as any count above the points, darts at a
  // --radius keep nothing.
  if (extension == "ply" || extension == "off" || extension == "xyz") {
    cloud = io::read_point_cloud(input, true);
  } else if (const io::Point_file text = read_text_points(input);
             text.dimension == 2 ||
             (text.size() == 0 && io::file_extension(outputs.target("out")) == "txt")) {
    return sample_plane(args, text, request, outputs);  // an empty text file is what the output says
  } else if (text.size() > 0) {
    if (text.dimension != 3 && text.dimension != 6)
      throw io::Input_error(input +
                            ": expected 2 numbers per line (points in the plane), 3 (a cloud) or 6 (a "
                            "cloud with normals), got " +
                            std::to_string(text.dimension));
    for (std::size_t i = 0; i < text.size(); ++i) {
      const double* x = text.coordinates.data() + i * text.dimension;
      cloud.points.push_back({x[0], x[1], x[2]});
      cloud.lines.push_back(text.lines[i]);
      if (text.dimension == 6) cloud.normals.push_back({x[3], x[4], x[5]});
    }
  }
  if (io::file_extension(outputs.target("out")) == "txt")
    throw Usage_error(input +
                      " is a point cloud, written as PLY, OFF or XYZ: give --out FILE.ply, .off or .xyz "
                      "(.txt is for points in the plane)");
  request.period = period_of(args, 3);
  if (count > static_cast<long long>(cloud.points.size()))
    throw Usage_error("--count " + std::to_string(count) + " exceeds the " +
                      std::to_string(cloud.points.size()) + " points of " + input);
  if (cloud.points.empty())
    std::fprintf(stderr, "featurerecon sample: warning: %s holds no points: the sample is empty\n",
                 input.c_str());
  std::string normals = cloud.has_normals() ? "file" : "none";
  if (!cloud.has_normals() && std::isfinite(sigma_feature)) {
    Progress p("estimating normals", quiet);
    io::estimate_normals(cloud, static_cast<unsigned>(neighbors), [&p](double t) { p(t); });
    p.done(std::to_string(cloud.points.size()) + " points");
    normals = "estimated";
  }
  std::vector<Pwn> items;
  items.reserve(cloud.points.size());
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const auto& p = cloud.points[i];
    const auto n = cloud.has_normals() ? cloud.normals[i] : std::array<double, 3>{0, 0, 1};
    items.push_back({K::Point_3(p[0], p[1], p[2]), K::Vector_3(n[0], n[1], n[2])});
  }
  for (std::size_t i = 0; i < items.size(); ++i)
    if (std::isfinite(sigma_feature) && items[i].second.squared_length() == 0)
      throw io::Input_error(cloud.locate(input, i) + " has a zero normal");
  FeatureRecon::Point_with_normal_traits<K> traits;
  if (args.has("unoriented")) traits.orientation = FeatureRecon::Normal_orientation::unoriented;

  Progress progress("sampling", quiet);
  double used_radius = 0;
  const std::vector<std::size_t> kept = run_sampler(items, traits, request, progress, used_radius);
  progress.done(std::to_string(kept.size()) + " of " + std::to_string(items.size()) + " points kept");
  const double seconds = progress.seconds();
  io::write_point_cloud(outputs.path("out"), cloud, kept);
  outputs.commit();

  // Spacing of the result on the input's domain (surface area or volume as the elimination estimates it; the
  // torus, a volume, with --periodic or --period).
  const auto [dimension, measure] =
      request.periodic ? std::pair<int, double>(3, fs::internal::torus_measure(request.period))
                       : domain_of(cloud.points);
  fs::Sampling_quality_options q;
  q.periodic = request.periodic;
  q.period = request.period;
  q.intrinsic_dimension = dimension;
  q.domain_measure = measure;
  std::vector<K::Point_3> kept_points;
  for (const std::size_t i : kept) kept_points.push_back(items[i].first);
  const fs::Sampling_quality quality = fs::sampling_quality(kept_points, q);
  double bilateral_rho = quality.relative_radius;
  if (std::isfinite(sigma_feature)) {  // the same statistic in the metric the sampler used
    std::vector<Pwn> kept_items;
    for (const std::size_t i : kept) kept_items.push_back(items[i]);
    q.sigma_position = sigma_position;
    q.sigma_feature = sigma_feature;
    bilateral_rho = fs::sampling_quality(kept_items, q, traits).relative_radius;
  }
  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"points\": " << items.size()
     << ", \"kept\": " << kept.size() << ", \"method\": \"" << method
     << "\", \"radius\": " << json_number(used_radius)
     << ", \"sigma_position\": " << json_number(sigma_position)
     << ", \"sigma_feature\": " << json_number(sigma_feature) << ", \"normals\": \"" << normals
     << "\", \"colors\": \""
     << (!cloud.has_colors()                                  ? (cloud.colors_ignored ? "dropped" : "none")
         : io::file_extension(outputs.target("out")) == "ply" ? "file"
                                                              : "dropped")
     << "\", \"orientation\": \"" << (args.has("unoriented") ? "unoriented" : "oriented")
     << "\", \"seed\": " << seed
     << ", \"dimension\": 3, \"periodic\": " << (request.periodic ? "true" : "false")
     << ", \"period\": " << json_period(request.period) << ", \"intrinsic_dimension\": " << dimension
     << ", \"domain_measure\": " << json_number(measure)
     << ", \"relative_radius\": " << json_statistic(quality.relative_radius, quality.status)
     << ", \"bilateral_relative_radius\": " << json_statistic(bilateral_rho, quality.status)
     << ", \"average_minimum_distance\": " << json_statistic(quality.average_minimum_distance, quality.status)
     << ", \"seconds\": " << json_number(seconds) << ", \"output\": " << json_string(output) << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

int run_sample_stats(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"periodic", "quiet"},
                       {"input", "domain-measure", "intrinsic-dimension", "sigma-position", "sigma-feature",
                        "spectrum", "max-frequency", "spectrum-method", "period"});
  const bool periodic = args.has("periodic") || args.has("period");  // --period: a torus of other lengths
  if (args.has("spectrum") && !periodic)
    throw Usage_error("--spectrum needs --periodic (2D samples on a torus)");
  Outputs outputs(args, {"spectrum"});
  fs::Sampling_spectrum_options spectrum_options;
  if (args.has("max-frequency")) {
    if (!periodic) throw Usage_error("--max-frequency needs --periodic (2D samples on a torus)");
    const long long f = args.get_int("max-frequency");
    if (f < 1) throw Usage_error("--max-frequency must be >= 1");
    if (f > 16384)  // the library's limit, named here as the option
      throw Usage_error(
          "--max-frequency must be at most 16384 (the periodogram holds (2 F + 1)(F + 1) complex sums, "
          "8.6 GB at 16384), got " +
          args.get("max-frequency"));
    spectrum_options.max_frequency = static_cast<std::size_t>(f);
  }
  if (args.has("spectrum-method")) {
    if (!periodic) throw Usage_error("--spectrum-method needs --periodic (2D samples on a torus)");
    const std::string m = args.get("spectrum-method");
    if (m == "gridded")
      spectrum_options.method = fs::Spectrum_method::gridded;
    else if (m == "direct")
      spectrum_options.method = fs::Spectrum_method::direct;
    else if (m != "automatic")
      throw Usage_error("--spectrum-method must be automatic, gridded or direct, got '" + m + "'");
  }
  const std::string input = args.get("input");
  fs::Sampling_quality_options o;
  if (args.has("domain-measure")) o.domain_measure = args.get_positive_double("domain-measure");
  if (args.has("intrinsic-dimension")) {
    const long long d = args.get_int("intrinsic-dimension");
    if (d != 2 && d != 3) throw Usage_error("--intrinsic-dimension must be 2 or 3");
    o.intrinsic_dimension = static_cast<int>(d);
  }
  o.periodic = periodic;
  if (args.has("sigma-position")) o.sigma_position = args.get_scale("sigma-position");
  o.sigma_feature = sigma_feature_of(args);
  Progress measuring("nearest neighbours", args.has("quiet"));
  o.progress = std::ref(measuring);
  fs::Sampling_quality q;
  fs::Sampling_spectrum spectrum;
  bool has_spectrum = false;
  std::size_t dimension = 0;
  // PLY, OFF and XYZ (x y z [nx ny nz]) are point clouds, as `sample` reads them; other text files have 2 or
  // 3 columns (points in the plane or in a volume) or 6 (a cloud with normals).
  io::Point_file text;
  const std::string extension = io::file_extension(input);
  const bool cloud_format = extension == "ply" || extension == "off";
  if (!cloud_format) text = read_text_points(input);
  const std::size_t columns = cloud_format ? 3 : text.dimension;
  const bool cloud = cloud_format || text.dimension == 6 || (extension == "xyz" && text.dimension == 3);
  io::Point_cloud points;
  if (cloud_format) {
    points = io::read_point_cloud(input, true);  // no points: degenerate below, as for an empty text file
  } else if (cloud) {
    for (std::size_t i = 0; i < text.size(); ++i) {
      const double* x = text.coordinates.data() + i * text.dimension;
      points.points.push_back({x[0], x[1], x[2]});
      points.lines.push_back(text.lines[i]);
      if (text.dimension == 6) points.normals.push_back({x[3], x[4], x[5]});
    }
  }
  const bool empty = cloud ? points.points.empty() : text.size() == 0;
  if (!cloud && !empty && o.intrinsic_dimension > 0 && std::size_t(o.intrinsic_dimension) > columns)
    throw Usage_error("--intrinsic-dimension " + std::to_string(o.intrinsic_dimension) +
                      " exceeds the dimension of the points of " + input + " (" + std::to_string(columns) +
                      ")");
  const bool spectrum_asked =
      args.has("spectrum") || args.has("max-frequency") || args.has("spectrum-method");
  if (spectrum_asked && empty) throw io::Input_error(input + ": no samples to take the spectrum of");
  if (spectrum_asked && columns != 2)
    throw Usage_error("--spectrum, --max-frequency and --spectrum-method need 2-D samples on a torus; " +
                      input + " has " + std::to_string(columns) + " numbers per line");
  o.period = period_of(args, cloud ? 3 : columns);
  if (empty) {
    q.status = Status::degenerate_input;  // no samples: nothing to measure, and not an error
    q.domain_measure = o.domain_measure != 0 ? o.domain_measure
                       : o.periodic          ? fs::internal::torus_measure(o.period)
                                             : 0.0;
  } else if (cloud) {
    const io::Point_cloud& cloud = points;
    dimension = 3;
    // The dimension is estimated whenever it is not given, also with a given measure (an area given for a
    // surface measured as a volume put rho 3 times too low); the unit torus of --periodic is a volume.
    if (o.intrinsic_dimension == 0 && !o.periodic) {
      const auto [d, m] = domain_of(cloud.points);
      o.intrinsic_dimension = d;
      if (o.domain_measure == 0) o.domain_measure = m;
      // `sample` estimates both from the whole cloud; a few hundred samples of a surface can look like a
      // volume, and rho then differs from the one `sample` printed for the same samples.
      if (!args.has("quiet"))
        std::fprintf(
            stderr,
            "featurerecon sample-stats: note: intrinsic dimension %d%s estimated from the %zu samples "
            "alone; to compare with what `sample` printed for them, give its --intrinsic-dimension "
            "and --domain-measure\n",
            d, args.has("domain-measure") ? "" : " and domain measure", cloud.points.size());
    }
    if (std::isfinite(o.sigma_feature) && !cloud.has_normals())
      throw Usage_error("--sigma-feature needs normals in " + input);
    std::vector<Pwn> items;
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
      const auto& p = cloud.points[i];
      const auto n = cloud.has_normals() ? cloud.normals[i] : std::array<double, 3>{0, 0, 1};
      if (std::isfinite(o.sigma_feature) && n[0] == 0 && n[1] == 0 && n[2] == 0)  // as `sample` says it
        throw io::Input_error(cloud.locate(input, i) + " has a zero normal");
      items.push_back({K::Point_3(p[0], p[1], p[2]), K::Vector_3(n[0], n[1], n[2])});
    }
    q = fs::sampling_quality(items, o);
    measuring.done(std::to_string(q.samples) + " samples");
  } else {
    const io::Point_file& f = text;
    dimension = f.dimension;
    if (std::isfinite(o.sigma_feature))  // was silently ignored
      throw Usage_error("--sigma-feature needs normals in " + input +
                        " (lines 'x y z nx ny nz', or PLY / OFF)");
    if (f.dimension == 2) {
      std::vector<K::Point_2> p;
      for (std::size_t i = 0; i < f.size(); ++i)
        p.emplace_back(f.coordinates[2 * i], f.coordinates[2 * i + 1]);
      q = fs::sampling_quality(p, o);
      measuring.done(std::to_string(q.samples) + " samples");
      // On a torus of aspect ratio above 4 the sums cost more than 4 times the square's: only when asked.
      const double ratio =
          o.period.empty() ? 1.0 : std::max(o.period[0] / o.period[1], o.period[1] / o.period[0]);
      if (o.periodic && (spectrum_asked || ratio <= 4)) {
        Progress progress("spectrum", args.has("quiet"));
        spectrum_options.progress = std::ref(progress);
        spectrum_options.period = o.period;  // measured as on the torus scaled to area 1
        spectrum = fs::sampling_spectrum(p, spectrum_options);
        progress.done(std::to_string(spectrum.radial_power.size()) + " annuli");
        has_spectrum = true;
        if (args.has("spectrum")) {
          std::ostringstream csv;
          csv << "frequency,radial_power,anisotropy_db\n";
          for (std::size_t b = 0; b < spectrum.frequency.size(); ++b)
            csv << json_number(spectrum.frequency[b]) << ',' << json_number(spectrum.radial_power[b]) << ','
                << json_number(spectrum.anisotropy[b]) << '\n';
          io::write_text_file(outputs.path("spectrum"), csv.str());
          outputs.commit();
        }
      }
    } else if (f.dimension == 3) {
      std::vector<K::Point_3> p;
      for (std::size_t i = 0; i < f.size(); ++i)
        p.emplace_back(f.coordinates[3 * i], f.coordinates[3 * i + 1], f.coordinates[3 * i + 2]);
      q = fs::sampling_quality(p, o);
      measuring.done(std::to_string(q.samples) + " samples");
    } else {
      throw io::Input_error(input + ": expected 2 or 3 coordinates per line (or x y z nx ny nz), got " +
                            std::to_string(f.dimension));
    }
  }
  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"samples\": " << q.samples
     << ", \"dimension\": " << dimension
     << ", \"intrinsic_dimension\": " << (o.intrinsic_dimension == 0 ? int(dimension) : o.intrinsic_dimension)
     << ", \"domain_measure\": " << json_number(q.domain_measure)
     << ", \"periodic\": " << (o.periodic ? "true" : "false") << ", \"period\": " << json_period(o.period)
     << ", \"hexagonal_distance\": " << json_statistic(q.hexagonal_distance, q.status)
     << ", \"minimum_distance\": " << json_statistic(q.minimum_distance, q.status)
     << ", \"relative_radius\": " << json_statistic(q.relative_radius, q.status)
     << ", \"average_minimum_distance\": " << json_statistic(q.average_minimum_distance, q.status)
     << ", \"degenerate\": " << (q.status == Status::degenerate_input ? "true" : "false");
  if (has_spectrum)
    os << ", \"effective_nyquist\": " << json_number(spectrum.effective_nyquist)
       << ", \"oscillation\": " << json_number(spectrum.oscillation) << ", \"oscillation_band\": ["
       << json_number(spectrum.oscillation_from) << ", " << json_number(spectrum.oscillation_to)
       << "], \"spectrum_method\": "
       << (spectrum.method == fs::Spectrum_method::direct ? "\"direct\"" : "\"gridded\"");
  os << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
