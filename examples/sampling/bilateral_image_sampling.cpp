// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Feature-aware sampling of an image (dissertation Fig. 2.3): a light image crossed by a dark "river" three
// pixels wide, narrower than the sampling radius. Euclidean blue noise (weighted sample elimination) puts the
// same density everywhere and leaves gaps along the river; the bilateral distance, with the grey value as the
// feature, keeps samples along it. Prints how many samples land on the river; with a directory argument it
// also draws both samplings as SVG (doc/images/bilateral_image_sampling_*.svg).
//
// usage: bilateral_image_sampling [OUTPUT_DIRECTORY]
#include <FeatureRecon/sampling/sampling_quality.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace FeatureRecon;
  if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
    std::fprintf(stderr, "usage: %s [OUTPUT_DIRECTORY]\n", argv[0]);
    return argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") ? 0 : 2;
  }
  namespace fs = FeatureRecon::sampling;
  const int width = 256, height = 256;
  std::vector<Grey_pixel> image;
  std::vector<bool> river;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const double centre = 128 + 60 * std::sin(column / 40.0);  // the river's middle at this column
      const bool on_river = std::abs(row - centre) < 1.5;
      const double shade = 170 + 60.0 * column / width;  // a gentle gradient elsewhere
      image.push_back(Grey_pixel{column, row, static_cast<std::uint8_t>(on_river ? 20 : shade)});
      river.push_back(on_river);
    }
  std::size_t river_pixels = 0;
  for (bool r : river) river_pixels += r;

  const std::size_t count = 1500;  // about 1 pixel in 44: a sample spacing of about 6 pixels
  std::printf("image %dx%d, river %zu pixels (%.1f %%), keeping %zu samples\n", width, height, river_pixels,
              100.0 * double(river_pixels) / double(image.size()), count);
  for (const bool bilateral : {false, true}) {
    fs::Elimination_options o;
    o.seed = 1;
    if (bilateral) o.sigma_feature = 0.05;  // grey distances are in [0, 1]: the river is far from its banks
    std::vector<std::size_t> kept;
    const auto r =
        fs::weighted_sample_elimination(image, count, std::back_inserter(kept), o, Grey_pixel_traits());
    std::size_t on_river = 0;
    for (std::size_t i : kept) on_river += river[i];
    std::vector<Grey_pixel> samples;
    for (std::size_t i : kept) samples.push_back(image[i]);
    fs::Sampling_quality_options q;
    q.domain_measure = double(width) * height;
    const double rho = fs::sampling_quality(samples, q, Grey_pixel_traits()).relative_radius;
    const char* name = bilateral ? "bilateral" : "euclidean";
    std::printf("%-9s: %zu samples, %zu on the river (%.1f %%), r_max %.2f px, spatial rho %.2f\n", name,
                kept.size(), on_river, 100.0 * double(on_river) / double(kept.size()), r.radius, rho);
    if (argc > 1) {
      const std::string path = std::string(argv[1]) + "/bilateral_image_sampling_" + name + ".svg";
      std::ofstream svg(path);
      svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * width << "\" height=\"" << 2 * height
          << "\" viewBox=\"0 0 " << width << ' ' << height
          << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
      for (const Grey_pixel& p : samples)
        svg << "<circle cx=\"" << p.column + 0.5 << "\" cy=\"" << p.row + 0.5 << "\" r=\"1.3\" fill=\"rgb("
            << int(p.value) << ',' << int(p.value) << ',' << int(p.value)
            << ")\" stroke=\"black\" stroke-width=\"0.3\"/>\n";
      svg << "</svg>\n";
      svg.close();
      if (!svg) {
        std::fprintf(stderr, "%s: cannot write '%s'\n", argv[0], path.c_str());
        return 1;
      }
      std::printf("wrote %s\n", path.c_str());
    }
  }
  return 0;
}
