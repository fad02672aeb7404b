// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Must not compile (CTest compile_fail_lloyd_traits): lloyd_relaxation() reads its sites through a
// PointCoordinateTraits model, and the samplers' FeaturePointTraits (here the pixels') is refused by one
// static_assert that names the concept, without the errors from deep inside the header that it gave before.
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/lloyd_relaxation.h>

#include <cstdint>
#include <vector>

int main() {
  namespace fs = FeatureRecon::sampling;
  const std::vector<std::uint8_t> grey(16, 100);
  const auto pixels = fs::image_pixels<FeatureRecon::Grey_pixel>(4, 4, grey);
  fs::lloyd_relaxation(pixels, fs::Pixel_density::uniform(4, 4), {}, FeatureRecon::Grey_pixel_traits());
}
