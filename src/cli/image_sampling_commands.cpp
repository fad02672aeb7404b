// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// featurerecon sample-image: feature-aware blue-noise sampling of a picture, on its pixels or on the
// continuous image with interpolated colours.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/continuous_dart_throwing.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/discrete_samplers.h"
#include "cli/dot_pictures.h"
#include "io/featurerecon_io.h"
#include "io/image_io.h"

namespace FeatureRecon {
namespace cli {
namespace {
namespace fs = FeatureRecon::sampling;

/// A kept sample: position in pixels and colour channels in [0, 1].
struct Image_sample {
  double x = 0, y = 0;
  std::array<double, 3> colour{};
};

/// Runs the chosen sampler on the pixels (elimination, darts) or the continuous image (continuous).
/// \tparam Pixel Grey_pixel or Rgb_pixel; \tparam C its channel count.
template <class Pixel, std::size_t C>
std::vector<Image_sample> sample_image(const io::Image& image, const Sampler_request& s, Progress& progress,
                                       double& used_radius) {
  std::vector<Image_sample> out;
  if (s.method == "continuous") {
    const fs::Bilinear_image<C> domain(image.width, image.height, image.data);
    fs::Continuous_dart_throwing_options o;
    o.sigma_feature = s.sigma_feature;
    o.seed = s.seed;
    o.max_samples = s.count;
    o.periodic = s.periodic;  // the torus of the picture's rectangle
    o.progress = std::ref(progress);
    const auto r = fs::continuous_bilateral_dart_throwing(domain.box(), s.radius, domain,
                                                          fs::Mean_squared_channel_distance(), o);
    used_radius = s.radius;
    for (const auto& k : r.samples) {
      Image_sample x{k.position[0], k.position[1], {}};
      for (std::size_t c = 0; c < 3; ++c) x.colour[c] = k.feature[C == 3 ? c : 0];
      out.push_back(x);
    }
    return out;
  }
  const std::vector<Pixel> pixels = fs::image_pixels<Pixel>(image.width, image.height, image.data);
  const Pixel_traits<Pixel> traits;
  const std::vector<std::size_t> kept = run_sampler(pixels, traits, s, progress, used_radius);
  for (const std::size_t i : kept) {
    const Pixel& p = pixels[i];
    Image_sample x{p.column + 0.5, p.row + 0.5, {}};
    for (std::size_t c = 0; c < 3; ++c) {
      if constexpr (C == 3)
        x.colour[c] = p.rgb[c] / 255.0;
      else
        x.colour[c] = p.value / 255.0;
    }
    out.push_back(x);
  }
  return out;
}

/// Text samples: "x y value" (grey) or "x y r g b", channels in [0, 1]; with .csv a header and commas.
void write_samples(const std::string& path, const std::vector<Image_sample>& samples, std::size_t channels) {
  const bool csv = io::file_extension(path) == "csv";
  const char sep = csv ? ',' : ' ';
  std::ostringstream os;
  if (csv) os << (channels == 1 ? "x,y,value\n" : "x,y,r,g,b\n");
  for (const Image_sample& s : samples) {
    os << json_number(s.x) << sep << json_number(s.y);
    for (std::size_t c = 0; c < channels; ++c) os << sep << json_number(s.colour[c]);
    os << '\n';
  }
  io::write_text_file(path, os.str());
}

/// Background of the dot pictures: a mid grey, so that white and black samples both show.
constexpr double dot_background = 0.55;

/// SVG: each sample a dot of its colour on grey, in pixel coordinates (on a tile also its copies across the
/// edges it crosses).
void write_samples_svg(const std::string& path, const std::vector<Image_sample>& samples, int width,
                       int height, double dot, bool periodic) {
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\" viewBox=\"0 0 " << width << ' ' << height
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#8c8c8c\"/>\n";
  char colour[8];
  for (const Image_sample& s : samples) {
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", to_byte(s.colour[0]), to_byte(s.colour[1]),
                  to_byte(s.colour[2]));
    for (const auto& [x, y] : drawn_at({s.x, s.y}, dot, width, height, periodic))
      os << "<circle cx=\"" << json_number(x) << "\" cy=\"" << json_number(y) << "\" r=\"" << json_number(dot)
         << "\" fill=\"" << colour << "\"/>\n";
  }
  os << "</svg>\n";
  io::write_text_file(path, os.str());
}

/// Raster picture (PNG, JPEG, PGM/PPM) of the same dots at the input's size, anti-aliased by 4 x 4
/// supersampling of each pixel's coverage.
void write_samples_raster(const std::string& path, const std::vector<Image_sample>& samples, int width,
                          int height, double dot, bool periodic) {
  std::vector<double> rgb(std::size_t(width) * std::size_t(height) * 3, dot_background);
  for (const Image_sample& s : samples)
    for (const auto& [x, y] : drawn_at({s.x, s.y}, dot, width, height, periodic))
      paint_dot(rgb, width, height, x, y, dot, s.colour);
  io::write_image(path, rgb_picture(rgb, width, height));
}

/// Voronoi mosaic (PNG, JPEG, PGM/PPM): every pixel takes the colour of its nearest sample (ties: the lower
/// sample index), the simplest reconstruction of the image from its samples; on a tile (`periodic`) the
/// nearest on the torus of the picture's rectangle, so that the mosaic tiles too. Returns it.
io::Image make_mosaic(const std::vector<Image_sample>& samples, int width, int height, bool periodic) {
  using K = CGAL::Simple_cartesian<double>;
  using Point = K::Point_2;
  using Traits = CGAL::Search_traits_adapter<std::uint32_t, CGAL::Pointer_property_map<Point>::type,
                                             CGAL::Search_traits_2<K>>;
  using Knn = CGAL::Orthogonal_k_neighbor_search<Traits>;
  io::Image picture;
  picture.width = width;
  picture.height = height;
  picture.channels = 3;
  picture.data.assign(std::size_t(width) * std::size_t(height) * 3, 255);
  if (!samples.empty()) {
    std::vector<Point> points;
    for (const Image_sample& x : samples) points.emplace_back(x.x, x.y);
    std::vector<std::uint32_t> keys(samples.size());
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = static_cast<std::uint32_t>(i);
    typename Knn::Tree tree(keys.begin(), keys.end(), typename Knn::Tree::Splitter(),
                            Traits(CGAL::make_property_map(points)));
    tree.build();
    typename Knn::Distance distance(tree.traits().point_property_map());
    // The nearest sample to `query` (squared distance), ties by sample index, into best / best_d.
    const auto nearest_to = [&](const Point& query, std::uint32_t& best, double& best_d) {
      Knn search(tree, query, 4, 0.0, true, distance);
      for (const auto& nb : search)
        if (nb.second < best_d || (nb.second == best_d && nb.first < best)) {
          best = nb.first;
          best_d = nb.second;
        }
    };
    for (int r = 0; r < height; ++r)
      for (int c = 0; c < width; ++c) {
        const Point q(c + 0.5, r + 0.5);
        std::uint32_t best = 0;
        double best_d = std::numeric_limits<double>::infinity();
        nearest_to(q, best, best_d);
        // On a tile the nearest image of a sample may lie across an edge: the image s + t of s is as near q
        // as s is to q - t, so the query is repeated shifted by the picture's width and height wherever the
        // shifted query lies as near the picture (which holds every sample) as the nearest found so far.
        for (int a = -1; a <= 1 && periodic; ++a)
          for (int b = -1; b <= 1; ++b) {
            if (a == 0 && b == 0) continue;
            const double x = q.x() + double(a) * width, y = q.y() + double(b) * height;
            const double dx = x < 0       ? -x
                              : x > width ? x - width
                                          : 0.0,
                         dy = y < 0        ? -y
                              : y > height ? y - height
                                           : 0.0;
            if (dx * dx + dy * dy <= best_d) nearest_to(Point(x, y), best, best_d);
          }
        std::uint8_t* p = &picture.data[(std::size_t(r) * std::size_t(width) + std::size_t(c)) * 3];
        for (std::size_t k = 0; k < 3; ++k) p[k] = to_byte(samples[best].colour[k]);
      }
  }
  return picture;
}

/// Peak signal-to-noise ratio (dB) of an RGB picture against the image (grey images compared on channel 0 of
/// the picture); infinity when they are equal.
double psnr(const io::Image& image, const io::Image& picture) {
  double sum = 0;
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < image.channels; ++c) {
      const double d = double(image.data[i * std::size_t(image.channels) + std::size_t(c)]) -
                       double(picture.data[3 * i + std::size_t(c)]);
      sum += d * d;
    }
  const double mse = sum / double(n * std::size_t(image.channels));
  return mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
}
}  // namespace

int run_sample_image(const std::vector<std::string>& argv) {
  const Arguments args(
      argv, {"grey", "periodic", "quiet"},
      {"input", "count", "radius", "method", "sigma-feature", "seed", "out", "svg", "picture", "mosaic"});
  const std::string input = args.get("input");
  Sampler_request s;
  s.method = args.get_or("method", "elimination");
  if (s.method != "elimination" && s.method != "darts" && s.method != "continuous")
    throw Usage_error("--method must be elimination, darts or continuous, got '" + s.method + "'");
  if (args.has("count")) {
    const long long count = args.get_int("count");
    if (count < 1) throw Usage_error("--count must be >= 1, got " + std::to_string(count));
    s.count = static_cast<std::size_t>(count);
  }
  if (args.has("radius")) s.radius = args.get_positive_double("radius");
  if (s.method == "elimination" && s.count == 0) throw Usage_error("--method elimination needs --count M");
  if (s.method == "darts" && s.count == 0 && s.radius == 0)
    throw Usage_error("--method darts needs --count M or --radius R");
  if (s.method == "continuous" && s.radius == 0)
    throw Usage_error(
        "--method continuous needs --radius R (pixels); --count M then caps the number of samples");
  if (args.has("sigma-feature")) s.sigma_feature = args.get_scale("sigma-feature");
  const long long seed = args.has("seed") ? args.get_int("seed") : 0;
  if (seed < 0) throw Usage_error("--seed must be >= 0");
  s.seed = static_cast<std::uint64_t>(seed);
  s.periodic = args.has("periodic");
  if (!args.has("out") && !args.has("svg") && !args.has("picture") && !args.has("mosaic"))
    throw Usage_error("give at least one of --out FILE, --svg FILE, --picture FILE, --mosaic FILE");
  Outputs outputs(args, {"out", "svg", "picture", "mosaic"});
  outputs.require_extension("svg", {"svg"}, "an SVG picture");
  outputs.require_extension("picture", {"png", "jpg", "jpeg", "pgm", "ppm"}, "a raster picture");
  outputs.require_extension("mosaic", {"png", "jpg", "jpeg", "pgm", "ppm"}, "a raster picture");

  io::Image image = io::read_image(input);
  if (args.has("grey")) image = io::to_grey(image);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  if (s.periodic) s.period = {double(image.width), double(image.height)};  // the pixels' torus
  if (s.method != "continuous" && s.count > pixels)
    throw Usage_error("--count " + std::to_string(s.count) + " exceeds the " + std::to_string(pixels) +
                      " pixels of " + input);
  if (s.method == "continuous") {
    // Samples at least d apart in a W x H rectangle number at most 2 W H / (sqrt(3) d^2) + (W + H) / d + 1
    // (Groemer). Colours count in the distance: with --sigma-feature S two samples are at least
    // sqrt(R^2 - 1 / S^2) apart in the picture (colour distances lie in [0, 1]), and at least
    // R / sqrt(1 + 2 / S^2), as bilinear colours change by at most sqrt(2) per pixel.
    const double colour = std::isinf(s.sigma_feature) ? 0.0 : 1 / (s.sigma_feature * s.sigma_feature);
    const double d = std::max(std::sqrt(std::max(0.0, s.radius * s.radius - colour)),
                              s.radius / std::sqrt(1 + 2 * colour));
    const double w = image.width, h = image.height;
    const double bound = 2 * w * h / (std::sqrt(3.0) * d * d) + (w + h) / d + 1;
    const double most = 134217728.0;  // 2^27 samples, about 10 GB with the sampler's own copies
    if (bound > most && (s.count == 0 || double(s.count) > most)) {
      char up_to[32];
      std::snprintf(up_to, sizeof up_to, "%.3g", bound);
      throw Usage_error(
          "--radius " + args.get("radius") + " lets up to " + up_to + " samples into the " +
          std::to_string(image.width) + " x " + std::to_string(image.height) +
          " picture (more than 2^27 = 134217728): give --count M (at most 2^27) to cap them, or a "
          "larger radius" +
          std::string(std::isinf(s.sigma_feature) ? "" : " or --sigma-feature"));
    }
  }

  Progress progress("sampling", args.has("quiet"));
  double used_radius = 0;
  const std::vector<Image_sample> samples =
      image.channels == 3 ? sample_image<Rgb_pixel, 3>(image, s, progress, used_radius)
                          : sample_image<Grey_pixel, 1>(image, s, progress, used_radius);
  progress.done(std::to_string(samples.size()) + " samples");
  const double seconds = progress.seconds();

  // Spacing on the image rectangle (on its torus for a tile).
  std::vector<CGAL::Epick::Point_2> positions;
  for (const Image_sample& x : samples) positions.emplace_back(x.x, x.y);
  fs::Sampling_quality_options q;
  q.domain_measure = double(pixels);
  q.intrinsic_dimension = 2;
  q.periodic = s.periodic;
  if (s.periodic) q.period = s.period;
  // Fewer than two samples: degenerate_input, printed as null (a default Sampling_quality printed 0).
  const fs::Sampling_quality quality = fs::sampling_quality(positions, q);
  const double d_hex =
      samples.empty() ? 1.0 : std::sqrt(2.0 * double(pixels) / (std::sqrt(3.0) * double(samples.size())));
  const double dot = 0.3 * d_hex;
  if (args.has("out")) write_samples(outputs.path("out"), samples, std::size_t(image.channels));
  if (args.has("svg"))
    write_samples_svg(outputs.path("svg"), samples, image.width, image.height, dot, s.periodic);
  if (args.has("picture"))
    write_samples_raster(outputs.path("picture"), samples, image.width, image.height, dot, s.periodic);
  double mosaic_psnr = std::numeric_limits<double>::quiet_NaN();
  if (args.has("mosaic")) {
    const io::Image mosaic = make_mosaic(samples, image.width, image.height, s.periodic);
    mosaic_psnr = psnr(image, mosaic);
    io::write_image(outputs.path("mosaic"), mosaic);
  }
  outputs.commit();

  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"width\": " << image.width
     << ", \"height\": " << image.height << ", \"channels\": " << image.channels << ", \"method\": \""
     << s.method << "\", \"samples\": " << samples.size() << ", \"radius\": " << json_number(used_radius)
     << ", \"sigma_feature\": " << json_number(s.sigma_feature) << ", \"seed\": " << seed
     << ", \"periodic\": " << (s.periodic ? "true" : "false")
     << ", \"relative_radius\": " << json_statistic(quality.relative_radius, quality.status)
     << ", \"average_minimum_distance\": " << json_statistic(quality.average_minimum_distance, quality.status)
     << ", \"seconds\": " << json_number(seconds);
  if (args.has("mosaic")) os << ", \"mosaic_psnr_db\": " << json_number(mosaic_psnr);
  os << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
