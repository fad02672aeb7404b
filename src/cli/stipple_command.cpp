// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// featurerecon stipple: dots whose density follows the darkness of a picture, placed by Euclidean adaptive
// Lloyd (the reference), discrete bilateral Lloyd, bilateral dart throwing or kernel relaxation, with the
// colour as the feature (dissertation Sec. 2.2.3, "Stippling").
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/discrete_lloyd.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/kernel_relaxation.h>
#include <FeatureRecon/sampling/lloyd_relaxation.h>
#include <FeatureRecon/sampling/pixel_density.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/dot_pictures.h"
#include "io/featurerecon_io.h"
#include "io/image_io.h"

namespace FeatureRecon {
namespace cli {
namespace {
namespace fs = FeatureRecon::sampling;

/// A dot: position in pixels and the index of its palette colour.
struct Dot {
  std::array<double, 2> position{};
  std::size_t colour = 0;
};

struct Stipple_settings {
  std::string method;
  std::size_t count = 0;
  double sigma_feature = 0.3;
  std::size_t iterations = 0;
  std::size_t palette = 0;
  std::uint64_t seed = 0;
  double gamma = 1;
  bool periodic = false;  ///< a tile: every method on the torus of the picture's rectangle
};

/// Darkness 1 - luma / 255 (ITU-R BT.601), raised to gamma: the density of the dots.
std::vector<double> darkness(const io::Image& image, double gamma) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &image.data[i * std::size_t(image.channels)];
    const double y = image.channels == 3 ? 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2] : double(p[0]);
    d[i] = std::pow(1 - y / 255.0, gamma);
  }
  return d;
}

/// A small palette of the image's colours: k-means (Lloyd on the colour cube, 20 iterations) started from k
/// pixels picked by k-means++ with the seed; deterministic. Grey images: black only.
std::vector<std::array<double, 3>> make_palette(const io::Image& image, std::size_t k, std::uint64_t seed) {
  if (image.channels == 1 || k <= 1) return {{0.0, 0.0, 0.0}};
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  // Every pixel on small images, a fixed stride on large ones.
  const std::size_t stride = std::max<std::size_t>(1, n / 65536);
  std::vector<std::array<double, 3>> colours;
  for (std::size_t i = 0; i < n; i += stride)
    colours.push_back(
        {image.data[3 * i] / 255.0, image.data[3 * i + 1] / 255.0, image.data[3 * i + 2] / 255.0});
  auto d2 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  };
  std::mt19937_64 rng(seed);
  std::vector<std::array<double, 3>> centres{colours[rng() % colours.size()]};
  std::vector<double> best(colours.size(), std::numeric_limits<double>::infinity());
  while (centres.size() < k) {
    double total = 0;
    for (std::size_t i = 0; i < colours.size(); ++i) {
      best[i] = std::min(best[i], d2(colours[i], centres.back()));
      total += best[i];
    }
    if (!(total > 0)) break;  // fewer distinct colours than k
    double u = double(rng() >> 11) * 0x1.0p-53 * total;
    std::size_t pick = 0;
    for (; pick + 1 < colours.size() && u >= best[pick]; ++pick) u -= best[pick];
    centres.push_back(colours[pick]);
  }
  for (int it = 0; it < 20; ++it) {
    std::vector<std::array<double, 4>> sum(centres.size(), std::array<double, 4>{});
    for (const auto& c : colours) {
      std::size_t arg = 0;
      for (std::size_t j = 1; j < centres.size(); ++j)
        if (d2(c, centres[j]) < d2(c, centres[arg])) arg = j;
      for (int q = 0; q < 3; ++q) sum[arg][q] += c[q];
      sum[arg][3] += 1;
    }
    for (std::size_t j = 0; j < centres.size(); ++j)
      if (sum[j][3] > 0)
        for (int q = 0; q < 3; ++q) centres[j][q] = sum[j][q] / sum[j][3];
  }
  return centres;
}

std::size_t nearest_colour(const std::vector<std::array<double, 3>>& palette,
                           const std::array<double, 3>& c) {
  std::size_t arg = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < palette.size(); ++j) {
    const double d = (palette[j][0] - c[0]) * (palette[j][0] - c[0]) +
                     (palette[j][1] - c[1]) * (palette[j][1] - c[1]) +
                     (palette[j][2] - c[2]) * (palette[j][2] - c[2]);
    if (d < best) {
      best = d;
      arg = j;
    }
  }
  return arg;
}

/// `count` distinct pixels drawn with probability proportional to the density (weighted sampling without
/// replacement, Efraimidis-Spirakis keys u^(1/w) from the seed; ties by index): the start of the Lloyd
/// methods.
std::vector<std::size_t> weighted_pixels(const std::vector<double>& density, std::size_t count,
                                         std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::pair<double, std::size_t>> key;
  key.reserve(density.size());
  for (std::size_t i = 0; i < density.size(); ++i) {
    const double u = (double(rng() >> 11) + 0.5) * 0x1.0p-53;
    // log(u) / w orders like u^(1/w); zero density last.
    key.push_back({density[i] > 0 ? std::log(u) / density[i] : -std::numeric_limits<double>::infinity(), i});
  }
  count = std::min(count, key.size());
  std::partial_sort(key.begin(), key.begin() + std::ptrdiff_t(count), key.end(),
                    [](const auto& a, const auto& b) {
                      return a.first != b.first ? a.first > b.first : a.second < b.second;
                    });
  std::vector<std::size_t> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = key[i].second;
  return out;
}

/// Bilateral dart throwing over the pixels of positive darkness (white ones take no dot) with radii r_i = t
/// min(8, sqrt(mean / rho_i)) (mean over those pixels), on the torus of `period` when it is given (a tile:
/// the picture's width and height): bilateral_dart_throwing_count() searches the factor t until a throw keeps
/// `count` to 1 % more pixels, or the count jumps over that (as over areas of one grey, by up to 20 %), and
/// the surplus of that throw is dropped at random (seeded). Pixels are visited in a seeded random order
/// weighted by darkness (keys u^(1 / rho_i), largest first: Efraimidis and Spirakis): a light pixel's wide
/// disc, visited first, would otherwise keep dark pixels around it empty.
template <class Pixel>
std::vector<std::size_t> adaptive_darts(const std::vector<Pixel>& all_pixels,
                                        const std::vector<double>& density, std::size_t count,
                                        double sigma_position, double sigma_feature, std::uint64_t seed,
                                        const std::vector<double>& period, Progress& progress) {
  std::vector<Pixel> pixels;
  std::vector<std::size_t> index;  // of each inked pixel among all
  for (std::size_t i = 0; i < density.size(); ++i)
    if (density[i] > 0) {
      pixels.push_back(all_pixels[i]);
      index.push_back(i);
    }
  double mean = 0;
  for (const std::size_t i : index) mean += density[i];
  mean /= double(index.size());
  fs::Dart_throwing_count_options o;
  o.darts.radii.resize(index.size());  // the shape; the search finds the factor
  for (std::size_t k = 0; k < index.size(); ++k)
    o.darts.radii[k] = std::min(8.0, std::sqrt(mean / density[index[k]]));
  o.darts.sigma_position = sigma_position;
  o.darts.sigma_feature = sigma_feature;
  o.darts.periodic = !period.empty();
  o.darts.period = period;
  o.darts.priority.resize(index.size());
  {
    std::mt19937_64 rng(seed);
    for (std::size_t k = 0; k < index.size(); ++k) {
      const double u = (static_cast<double>(rng() >> 11) + 0.5) * 0x1p-53;  // in (0, 1)
      o.darts.priority[k] = std::log(u) / density[index[k]];                // log of u^(1 / rho)
    }
  }
  o.count_tolerance = 0.01;
  // The shape is in units of d_hex for the mean density: about count dots at 1, fewer at 2 (an upper end
  // to interpolate from).
  o.initial_radius = 2;
  o.darts.progress = [&progress](double f) { return progress(0.5 * f); };  // the kernel's steps take the rest
  o.cut = false;  // the surplus is dropped at random below, not the last accepted (light) pixels
  std::vector<std::size_t> kept;
  fs::bilateral_dart_throwing_count(pixels, count, std::back_inserter(kept), o);
  if (kept.size() > count) {
    std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
    for (std::size_t i = kept.size() - 1; i > 0; --i) std::swap(kept[i], kept[std::size_t(rng() % (i + 1))]);
    kept.resize(count);
    std::sort(kept.begin(), kept.end());
  }
  for (std::size_t& k : kept) k = index[k];
  return kept;
}

template <class Pixel, std::size_t C>
std::array<double, 3> colour_of(const Pixel& p) {
  if constexpr (C == 3)
    return {p.rgb[0] / 255.0, p.rgb[1] / 255.0, p.rgb[2] / 255.0};
  else
    return {p.value / 255.0, p.value / 255.0, p.value / 255.0};
}

struct Stipple_report {
  std::size_t iterations = 0;
  std::string stop;
};

template <class Pixel, std::size_t C>
std::vector<Dot> stipple(const io::Image& image, const Stipple_settings& s,
                         const std::vector<std::array<double, 3>>& palette, Progress& progress,
                         Stipple_report& report) {
  const std::vector<Pixel> pixels = fs::image_pixels<Pixel>(image.width, image.height, image.data);
  const std::vector<double> density = darkness(image, s.gamma);
  const double area = double(pixels.size());
  const double d_hex = std::sqrt(2 * area / (std::sqrt(3.0) * double(s.count)));
  std::vector<Dot> dots;
  auto colour_at = [&](const std::array<double, 2>& p) {
    const int c = std::min(image.width - 1, std::max(0, int(std::floor(p[0]))));
    const int r = std::min(image.height - 1, std::max(0, int(std::floor(p[1]))));
    return nearest_colour(
        palette, colour_of<Pixel, C>(pixels[std::size_t(r) * std::size_t(image.width) + std::size_t(c)]));
  };
  if (s.method == "lloyd") {
    const std::vector<std::size_t> start = weighted_pixels(density, s.count, s.seed);
    std::vector<std::array<double, 2>> sites;
    for (const std::size_t i : start) sites.push_back({pixels[i].column + 0.5, pixels[i].row + 0.5});
    fs::Lloyd_options o;
    o.max_iterations = s.iterations;
    o.periodic = s.periodic;
    o.progress = std::ref(progress);
    const fs::Lloyd_result r =
        fs::lloyd_relaxation(sites, fs::Pixel_density(image.width, image.height, density), o);
    for (const auto& p : r.sites) dots.push_back({p, colour_at(p)});
    report.iterations = r.history.size();
    report.stop = fs::to_string(r.stop);
    return dots;
  }
  if (s.method == "bilateral-lloyd") {
    const std::vector<std::size_t> start = weighted_pixels(density, s.count, s.seed);
    fs::Discrete_lloyd_options<2> o;
    o.sigma_position = d_hex;
    o.sigma_feature = s.sigma_feature;
    o.density = density;
    o.max_iterations = s.iterations;
    o.periodic = s.periodic;
    o.progress = std::ref(progress);
    const auto r = fs::discrete_bilateral_lloyd(pixels, start, o);
    for (const auto& site : r.sites) dots.push_back({site.position, colour_at(site.position)});
    report.iterations = r.history.size();
    report.stop = fs::to_string(r.stop);
    return dots;
  }
  const std::vector<std::size_t> start = adaptive_darts(
      pixels, density, s.count, d_hex, s.sigma_feature, s.seed,
      s.periodic ? std::vector<double>{double(image.width), double(image.height)} : std::vector<double>(),
      progress);
  if (s.method == "darts") {
    for (const std::size_t i : start) {
      const std::array<double, 2> p{pixels[i].column + 0.5, pixels[i].row + 0.5};
      dots.push_back({p, colour_at(p)});
    }
    progress(1.0);
    return dots;
  }
  fs::Kernel_relaxation_options<2> o;
  o.sigma_position = d_hex;
  o.sigma_feature = s.sigma_feature;
  o.density = density;
  o.max_iterations = s.iterations;
  o.periodic = s.periodic;
  o.progress = [&](double f) { return progress(0.5 + 0.5 * f); };
  const auto r = fs::kernel_relaxation(pixels, start, o);
  for (const auto& site : r.sites) dots.push_back({site.position, colour_at(site.position)});
  report.iterations = r.history.size();
  report.stop = fs::to_string(r.stop);
  return dots;
}

void write_svg(const std::string& path, const std::vector<Dot>& dots,
               const std::vector<std::array<double, 3>>& palette, int width, int height, double dot,
               bool periodic) {
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\" viewBox=\"0 0 " << width << ' ' << height
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  char colour[8];
  for (std::size_t k = 0; k < palette.size(); ++k) {
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", to_byte(palette[k][0]), to_byte(palette[k][1]),
                  to_byte(palette[k][2]));
    os << "<g fill=\"" << colour << "\">\n";
    for (const Dot& d : dots)
      if (d.colour == k)
        for (const auto& p : drawn_at(d.position, dot, width, height, periodic))
          os << "<circle cx=\"" << json_number(p[0]) << "\" cy=\"" << json_number(p[1]) << "\" r=\""
             << json_number(dot) << "\"/>\n";
    os << "</g>\n";
  }
  os << "</svg>\n";
  io::write_text_file(path, os.str());
}

/// The same dots on white at the image's size, anti-aliased by 4 x 4 supersampling.
void write_raster(const std::string& path, const std::vector<Dot>& dots,
                  const std::vector<std::array<double, 3>>& palette, int width, int height, double dot,
                  bool periodic) {
  std::vector<double> rgb(std::size_t(width) * std::size_t(height) * 3, 1.0);
  for (const Dot& d : dots)
    for (const auto& [x, y] : drawn_at(d.position, dot, width, height, periodic))
      paint_dot(rgb, width, height, x, y, dot, palette[d.colour]);
  const io::Image picture = rgb_picture(rgb, width, height);
  io::write_image(path, picture);
}
}  // namespace

int run_stipple(const std::vector<std::string>& argv) {
  const Arguments args(
      argv, {"grey", "periodic", "quiet"},
      {"count", "method", "sigma-feature", "iterations", "palette", "gamma", "seed", "out", "png"}, 1);
  if (args.positional().size() != 1)
    throw Usage_error("give the picture to stipple: featurerecon stipple IMAGE ...");
  const std::string input = args.positional()[0];
  Stipple_settings s;
  s.method = args.get_or("method", "lloyd");
  if (s.method != "lloyd" && s.method != "bilateral-lloyd" && s.method != "darts" && s.method != "kernel")
    throw Usage_error("--method must be lloyd, bilateral-lloyd, darts or kernel, got '" + s.method + "'");
  // Options the method does not have: refused, not ignored (the JSON printed sigma_feature null for Lloyd).
  if (s.method == "lloyd" && args.has("sigma-feature"))
    throw Usage_error(
        "--sigma-feature does not apply to --method lloyd (Euclidean); use bilateral-lloyd, darts "
        "or kernel");
  if (s.method == "darts" && args.has("iterations"))
    throw Usage_error("--iterations does not apply to --method darts (no iterations)");
  s.periodic = args.has("periodic");
  const long long count = args.get_int("count");
  if (count < 1) throw Usage_error("--count must be >= 1, got " + std::to_string(count));
  s.count = static_cast<std::size_t>(count);
  if (args.has("sigma-feature")) s.sigma_feature = args.get_scale("sigma-feature");
  const long long iterations =
      args.has("iterations") ? args.get_int("iterations") : (s.method == "kernel" ? 100 : 50);
  if (iterations < 0 || iterations > 1000000)
    throw Usage_error("--iterations must be in [0, 1000000], got " + std::to_string(iterations));
  s.iterations = static_cast<std::size_t>(iterations);
  const long long palette_size = args.has("palette") ? args.get_int("palette") : 6;
  if (palette_size < 1 || palette_size > 64)
    throw Usage_error("--palette must be between 1 and 64 colours, got " + std::to_string(palette_size));
  if (args.has("gamma")) s.gamma = args.get_positive_double("gamma");
  const long long seed = args.has("seed") ? args.get_int("seed") : 0;
  if (seed < 0) throw Usage_error("--seed must be >= 0");
  s.seed = static_cast<std::uint64_t>(seed);
  if (!args.has("out") && !args.has("png")) throw Usage_error("give --out FILE.svg and/or --png FILE.png");
  if (args.has("out") && io::file_extension(args.get("out")) != "svg")
    throw Usage_error("--out writes an SVG picture: give a file ending in .svg, got '" + args.get("out") +
                      "'");
  Outputs outputs(args, {"out", "png"});
  outputs.require_extension("png", {"png", "jpg", "jpeg", "pgm", "ppm"}, "a raster picture");

  io::Image image = io::read_image(input);
  if (args.has("grey")) image = io::to_grey(image);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  if (s.count > pixels)
    throw Usage_error("--count " + std::to_string(s.count) + " exceeds the " + std::to_string(pixels) +
                      " pixels of " + input);
  const std::vector<double> density = darkness(image, s.gamma);
  double total = 0, peak = 0;
  std::size_t inked = 0;
  for (const double d : density) {
    total += d;
    peak = std::max(peak, d);
    inked += d > 0;
  }
  if (!(total > 0)) {
    // the darkness itself: a large --gamma makes every power of a darkness below 1 underflow to 0
    double ink = 0;
    for (const double d : darkness(image, 1.0)) ink += d;
    if (ink > 0)
      throw Usage_error("--gamma " + json_number(s.gamma) + " makes the darkness of every pixel of " + input +
                        " underflow to 0 (darkness in [0, 1) raised to it); use a smaller --gamma");
  }
  // A white picture is degenerate, not an error: its stippling has no dot (written as an empty picture).
  const bool white = !(total > 0);
  if (white)
    std::fprintf(stderr, "featurerecon stipple: warning: %s is white everywhere: no dot to place\n",
                 input.c_str());
  // More dots than pixels with ink: the extra dots had nowhere to go (kernel relaxation pushed them into the
  // picture's white corners, Lloyd left them on white pixels).
  if (!white && s.count > inked)
    throw Usage_error("--count " + std::to_string(s.count) + " exceeds the " + std::to_string(inked) +
                      " pixels of " + input + " with any darkness (of " + std::to_string(pixels) + ")");

  const std::vector<std::array<double, 3>> palette = make_palette(image, std::size_t(palette_size), s.seed);
  Progress progress("stippling", args.has("quiet"));
  Stipple_report report;
  const std::vector<Dot> dots = white ? std::vector<Dot>()
                                : image.channels == 3
                                    ? stipple<Rgb_pixel, 3>(image, s, palette, progress, report)
                                    : stipple<Grey_pixel, 1>(image, s, palette, progress, report);
  progress.done(std::to_string(dots.size()) + " dots");
  const double seconds = progress.seconds();
  // Dots of one size: at the darkest density their spacing is d_hex sqrt(mean / peak); half of that covers
  // it.
  const double d_hex = std::sqrt(2.0 * double(pixels) / (std::sqrt(3.0) * double(dots.size())));
  const double dot = white ? 0.5 : std::max(0.5, 0.5 * d_hex * std::sqrt(total / double(pixels) / peak));
  if (args.has("out"))
    write_svg(outputs.path("out"), dots, palette, image.width, image.height, dot, s.periodic);
  if (args.has("png"))
    write_raster(outputs.path("png"), dots, palette, image.width, image.height, dot, s.periodic);
  outputs.commit();

  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"width\": " << image.width
     << ", \"height\": " << image.height << ", \"channels\": " << image.channels << ", \"method\": \""
     << s.method << "\", \"dots\": " << dots.size() << ", \"palette\": " << palette.size()
     << ", \"sigma_feature\": "
     << json_number(s.method == "lloyd" ? std::numeric_limits<double>::infinity() : s.sigma_feature)
     << ", \"periodic\": " << (s.periodic ? "true" : "false") << ", \"seed\": " << seed
     << ", \"iterations\": " << report.iterations << ", \"stop\": "
     << (report.stop.empty() ? "null" : "\"" + report.stop + "\"")  // darts: no iterations, no reason to stop
     << ", \"dot_radius\": " << json_number(dot) << ", \"seconds\": " << json_number(seconds) << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
