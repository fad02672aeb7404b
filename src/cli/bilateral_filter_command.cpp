// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// featurerecon bilateral-filter: the bilateral filter of a picture evaluated on sampled taps (uniform or
// bilateral blue noise, local or global patterns; dissertation Sec. 2.2.3, "Image subsampling"), with its
// quality against the exact filter.
#include <FeatureRecon/sampling/image_quality.h>
#include <FeatureRecon/sampling/sampled_bilateral_filter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "io/featurerecon_io.h"
#include "io/image_io.h"

namespace FeatureRecon {
namespace cli {
namespace {
namespace fs = FeatureRecon::sampling;

io::Image rounded(const io::Image& like, const std::vector<float>& values) {
  io::Image out = like;
  for (std::size_t i = 0; i < values.size(); ++i)
    out.data[i] = static_cast<std::uint8_t>(std::lround(std::clamp(double(values[i]), 0.0, 255.0)));
  return out;
}
}  // namespace

int run_bilateral_filter(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"grey", "quiet", "no-compensation"},
                       {"sampling", "mode", "budget", "sigma-spatial", "sigma-range", "radius",
                        "sampling-sigma", "candidates", "seed", "out", "exact-out"},
                       1);
  if (args.positional().size() != 1)
    throw Usage_error("give the picture to filter: featurerecon bilateral-filter IMAGE ...");
  const std::string input = args.positional()[0];
  const std::string sampling = args.get_or("sampling", "bilateral");
  if (sampling != "uniform" && sampling != "bilateral" && sampling != "exact")
    throw Usage_error("--sampling must be uniform, bilateral or exact, got '" + sampling + "'");
  const std::string mode = args.get_or("mode", "global");
  if (mode != "local" && mode != "global")
    throw Usage_error("--mode must be local or global, got '" + mode + "'");
  // Options of the taps that the chosen sampling does not have: refused, not ignored.
  const std::vector<std::pair<const char*, std::vector<const char*>>> not_used{
      {"exact", {"mode", "budget", "sampling-sigma", "candidates", "seed", "no-compensation"}},
      {"uniform", {"sampling-sigma", "no-compensation"}}};
  for (const auto& [kind, options] : not_used)
    if (sampling == kind)
      for (const char* option : options)
        if (args.has(option))
          throw Usage_error(std::string("--") + option + " does not apply to --sampling " + sampling +
                            (sampling == "exact" ? " (every pixel of the window is a tap)"
                                                 : " (it sets the bilateral taps' distance and weights)"));
  fs::Sampled_bilateral_filter_options o;
  o.sampling = sampling == "uniform" ? fs::Tap_sampling::uniform : fs::Tap_sampling::bilateral;
  o.mode = mode == "local" ? fs::Tap_mode::local : fs::Tap_mode::global;
  if (args.has("budget")) o.budget = args.get_positive_double("budget");
  if (o.budget > 16)
    throw Usage_error("--budget must be in (0, 16] taps per kernel pixel, got " + args.get("budget"));
  if (args.has(
          "sigma-spatial")) {  // large with --radius: a flat spatial kernel; below 1e-150 its weights are NaN
    o.kernel.sigma_spatial = args.get_positive_double("sigma-spatial");
    if (o.kernel.sigma_spatial < 1e-150)
      throw Usage_error("--sigma-spatial must be at least 1e-150, got " + args.get("sigma-spatial"));
  }
  if (args.has("sigma-spatial") && !args.has("radius") && o.kernel.sigma_spatial > 2048)
    throw Usage_error(
        "--sigma-spatial must be at most 2048 without --radius (the radius 2 sigma would exceed 4096), "
        "got " +
        args.get("sigma-spatial"));
  if (args.has("sigma-range")) o.kernel.sigma_range = args.get_scale("sigma-range");
  if (args.has("radius")) {
    const long long r = args.get_int("radius");
    if (r < 1 || r > 4096)
      throw Usage_error("--radius must be between 1 and 4096 pixels, got " + std::to_string(r));
    o.kernel.radius = int(r);
  }
  if (args.has("sampling-sigma")) o.sampling_sigma_feature = args.get_scale("sampling-sigma");
  if (args.has("candidates")) o.candidates_per_tap = args.get_positive_double("candidates");
  if (o.candidates_per_tap < 2 || o.candidates_per_tap > 64)
    throw Usage_error("--candidates must be between 2 and 64 per tap, got " + args.get("candidates"));
  o.compensate_density = !args.has("no-compensation");
  const long long seed = args.has("seed") ? args.get_int("seed") : 0;
  if (seed < 0) throw Usage_error("--seed must be >= 0");
  o.seed = static_cast<std::uint64_t>(seed);
  if (!args.has("out"))
    throw Usage_error("give --out FILE.png (or .jpg, .pgm, .ppm) for the filtered picture");
  const std::string out = args.get("out");
  for (const std::string& file : {out, args.get_or("exact-out", out)}) {
    const std::string ext = io::file_extension(file);
    if (ext != "png" && ext != "jpg" && ext != "jpeg" && ext != "pgm" && ext != "ppm")
      throw Usage_error("pictures are written as PNG, JPEG, PGM or PPM, got '" + file + "'");
  }
  Outputs outputs(args, {"out", "exact-out"});

  io::Image image = io::read_image(input);
  if (args.has("grey")) image = io::to_grey(image);
  const bool quiet = args.has("quiet");

  Progress exact_progress("exact bilateral filter", quiet);
  fs::Bilateral_filter_options eo;
  eo.kernel = o.kernel;
  eo.progress = std::ref(exact_progress);
  const fs::Bilateral_filter_result exact =
      fs::bilateral_filter(image.width, image.height, image.channels, image.data, eo);
  exact_progress.done();
  const double exact_seconds = exact_progress.seconds();

  fs::Bilateral_filter_result sampled = exact;
  double seconds = exact_seconds;
  if (sampling != "exact") {
    Progress progress(sampling + " " + mode + " sampled bilateral filter", quiet);
    o.progress = std::ref(progress);
    sampled = fs::sampled_bilateral_filter(image.width, image.height, image.channels, image.data, o);
    char detail[64];
    std::snprintf(detail, sizeof detail, "%.3f taps per kernel pixel", sampled.taps_per_kernel_pixel);
    progress.done(detail);
    seconds = progress.seconds();
  }
  io::write_image(outputs.path("out"), rounded(image, sampled.values));
  if (args.has("exact-out")) io::write_image(outputs.path("exact-out"), rounded(image, exact.values));
  outputs.commit();

  const int radius =
      o.kernel.radius > 0 ? o.kernel.radius : std::max(1, int(std::ceil(2 * o.kernel.sigma_spatial)));
  std::ostringstream os;
  os << "{\"input\": " << json_string(input) << ", \"width\": " << image.width
     << ", \"height\": " << image.height << ", \"channels\": " << image.channels << ", \"sampling\": \""
     << sampling << "\", \"mode\": \"" << (sampling == "exact" ? "exact" : mode)
     << "\", \"budget\": " << json_number(sampling == "exact" ? 1 : o.budget)
     << ", \"taps_per_kernel_pixel\": " << json_number(sampled.taps_per_kernel_pixel)
     << ", \"sampling_radius\": " << json_number(sampled.sampling_radius)
     << ", \"density_compensation\": " << (o.compensate_density && sampling == "bilateral" ? "true" : "false")
     << ", \"sigma_spatial\": " << json_number(o.kernel.sigma_spatial)
     << ", \"sigma_range\": " << json_number(o.kernel.sigma_range) << ", \"radius\": " << radius
     << ", \"seed\": " << seed << ", \"psnr_db\": " << json_number(fs::psnr(exact.values, sampled.values))
     << ", \"ssim\": "
     << json_number(fs::ssim(image.width, image.height, image.channels, exact.values, sampled.values))
     << ", \"seconds\": " << json_number(seconds) << ", \"exact_seconds\": " << json_number(exact_seconds)
     << "}\n";
  std::fputs(os.str().c_str(), outputs.summary_stream());
  return 0;
}

}  // namespace cli
}  // namespace FeatureRecon
