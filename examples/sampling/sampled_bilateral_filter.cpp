// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Image subsampling for bilateral filtering (dissertation Sec. 2.2.3, doc/sampling.md): a grey image of dark
// strokes on textured paper (a stand-in for the sheet music of the dissertation's Fig. 2.7), filtered exactly
// and on a quarter of the taps, uniform and bilateral, with global patterns (one pattern made once by
// bilateral_tap_pattern() and reused: the stage-by-stage use) and local ones. Prints the quality of each
// against the exact filter; with a directory argument it also writes the pictures as PGM files.
//
// usage: sampled_bilateral_filter [OUTPUT_DIRECTORY]
#include <FeatureRecon/sampling/image_quality.h>
#include <FeatureRecon/sampling/sampled_bilateral_filter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {
/// Writes a grey picture; exits with a message when the file cannot be written.
void write_pgm(const std::string& path, int width, int height, const std::vector<float>& values) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << width << " " << height << "\n255\n";
  for (float v : values) out.put(char(std::uint8_t(std::lround(std::clamp(double(v), 0.0, 255.0)))));
  out.close();
  if (!out) {
    std::fprintf(stderr, "sampled_bilateral_filter: cannot write '%s'\n", path.c_str());
    std::exit(1);
  }
}
}  // namespace

int main(int argc, char** argv) {
  namespace fs = FeatureRecon::sampling;
  if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
    std::fprintf(stderr, "usage: %s [OUTPUT_DIRECTORY]\n", argv[0]);
    return argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") ? 0 : 2;
  }
  const int width = 320, height = 120;
  // Paper: light grey with noise of +-12 levels (within the range sigma). Strokes: five staff lines two
  // pixels thick and a few slanted note stems, near black.
  std::mt19937_64 rng(7);
  std::vector<std::uint8_t> image(std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool staff = y >= 30 && y < 90 && (y - 30) % 14 < 2;
      const bool stem = (x % 45 < 3 && y > 20 && y < 100) || std::abs((x - 2 * y) % 90) < 2;
      const int paper = 215 + int(rng() % 25) - 12;
      image[std::size_t(y) * width + std::size_t(x)] =
          std::uint8_t(staff || stem ? 25 + int(rng() % 10) : paper);
    }

  fs::Bilateral_filter_options exact_options;  // sigma_spatial 3 (13 x 13 window), sigma_range 0.1
  const fs::Bilateral_filter_result exact = fs::bilateral_filter(width, height, 1, image, exact_options);
  std::printf("image %dx%d, exact filter: %zu taps\n", width, height, exact.taps);

  fs::Sampled_bilateral_filter_options o;
  o.budget = 0.25;  // a quarter of the window's pixels
  o.seed = 3;
  for (const fs::Tap_mode mode : {fs::Tap_mode::global, fs::Tap_mode::local})
    for (const fs::Tap_sampling sampling : {fs::Tap_sampling::uniform, fs::Tap_sampling::bilateral}) {
      o.mode = mode;
      o.sampling = sampling;
      fs::Bilateral_filter_result r;
      if (mode == fs::Tap_mode::global) {
        const fs::Tap_pattern pattern = fs::bilateral_tap_pattern(width, height, 1, image, o);  // stage 1
        r = fs::sampled_bilateral_filter(width, height, 1, image, pattern, o);                  // stage 2
      } else {
        r = fs::sampled_bilateral_filter(width, height, 1, image, o);
      }
      const char* name = sampling == fs::Tap_sampling::uniform ? "uniform" : "bilateral";
      const char* where = mode == fs::Tap_mode::global ? "global" : "local";
      std::printf("%-9s %-6s: %.2f taps per kernel pixel, PSNR %.1f dB, SSIM %.3f\n", name, where,
                  r.taps_per_kernel_pixel, fs::psnr(exact.values, r.values),
                  fs::ssim(width, height, 1, exact.values, r.values));
      if (argc > 1)
        write_pgm(std::string(argv[1]) + "/sampled_bilateral_filter_" + name + "_" + where + ".pgm", width,
                  height, r.values);
    }
  if (argc > 1) {
    write_pgm(std::string(argv[1]) + "/sampled_bilateral_filter_exact.pgm", width, height, exact.values);
    write_pgm(std::string(argv[1]) + "/sampled_bilateral_filter_input.pgm", width, height,
              std::vector<float>(image.begin(), image.end()));
  }
  return 0;
}
