// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// An image as a sampling domain: pixels as items, and the continuous image with bilinear colours.
#include <FeatureRecon/sampling/continuous_dart_throwing.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "sampling/sampling_test_utilities.h"

using FeatureRecon::test::throws_with;

namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;

TEST(ImageDomain, PixelsInRowOrder) {
  const std::vector<std::uint8_t> grey{0, 10, 20, 30, 40, 50};  // 3 x 2
  const auto g = image_pixels<Grey_pixel>(3, 2, grey);
  ASSERT_EQ(g.size(), 6u);
  EXPECT_EQ(g[4].column, 1);
  EXPECT_EQ(g[4].row, 1);
  EXPECT_EQ(g[4].value, 40);
  const std::vector<std::uint8_t> rgb{1, 2, 3, 4, 5, 6};  // 2 x 1
  const auto c = image_pixels<Rgb_pixel>(2, 1, rgb);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[1].rgb[0], 4);
  EXPECT_EQ(c[1].rgb[2], 6);
  EXPECT_TRUE(image_pixels<Grey_pixel>(0, 5, {}).empty());
  EXPECT_TRUE(
      throws_with<std::invalid_argument>([&] { (void)image_pixels<Rgb_pixel>(2, 2, rgb); },
                                         "data has 6 values, a 2 x 2 image with 3 channel(s) needs 12"));
  EXPECT_THROW((void)image_pixels<Grey_pixel>(-1, 2, {}), std::invalid_argument);
}

TEST(ImageDomain, BilinearColours) {
  // 2 x 2 grey: 0 255 / 255 0.
  const Bilinear_image<1> g(2, 2, {0, 255, 255, 0});
  EXPECT_EQ(g.box(), (std::array<double, 4>{0, 0, 2, 2}));
  EXPECT_DOUBLE_EQ(g(0.5, 0.5)[0], 0.0);  // pixel centres give the pixel values
  EXPECT_DOUBLE_EQ(g(1.5, 0.5)[0], 1.0);
  EXPECT_DOUBLE_EQ(g(1.0, 0.5)[0], 0.5);    // halfway along the top row
  EXPECT_DOUBLE_EQ(g(1.0, 1.0)[0], 0.5);    // the middle: the mean of four
  EXPECT_DOUBLE_EQ(g(0.75, 0.5)[0], 0.25);  // linear in between
  EXPECT_DOUBLE_EQ(g(0.0, 0.0)[0], 0.0);    // constant beyond the outer centres
  EXPECT_DOUBLE_EQ(g(1.99, 0.1)[0], 1.0);
  // RGB keeps the channels apart.
  const Bilinear_image<3> c(2, 1, {255, 0, 0, 0, 0, 255});
  const auto mid = c(1.0, 0.5);
  EXPECT_DOUBLE_EQ(mid[0], 0.5);
  EXPECT_DOUBLE_EQ(mid[1], 0.0);
  EXPECT_DOUBLE_EQ(mid[2], 0.5);
  EXPECT_DOUBLE_EQ(Mean_squared_channel_distance()(c(0.5, 0.5), c(1.5, 0.5)), 2.0 / 3.0);
  EXPECT_THROW(Bilinear_image<1>(2, 2, {1, 2, 3}), std::invalid_argument);
  // The same scale as the pixel traits' feature distance.
  const auto px = image_pixels<Rgb_pixel>(2, 1, {255, 0, 0, 0, 0, 255});
  EXPECT_DOUBLE_EQ(Rgb_pixel_traits().compute_feature_distance_object()(
                       Rgb_pixel_traits().construct_feature_object()(px[0]),
                       Rgb_pixel_traits().construct_feature_object()(px[1])),
                   2.0 / 3.0);
}

// image_pixels() and Bilinear_image check their sizes: width and height >= 0 (either one negative is refused,
// not only the width) and exactly width * height * channels values (too many as well as too few).
TEST(ImageDomain, SizesAreCheckedBothWays) {
  EXPECT_TRUE(throws_with<std::invalid_argument>([] { (void)image_pixels<Grey_pixel>(0, -1, {}); },
                                                 "width and height must be >= 0, got 0 x -1"));
  EXPECT_TRUE(throws_with<std::invalid_argument>([] { (void)Bilinear_image<1>(0, -1, {}); },
                                                 "width and height must be >= 0, got 0 x -1"));
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [] {
        (void)image_pixels<Grey_pixel>(2, 1, {1, 2, 3});
      },
      "data has 3 values, a 2 x 1 image with 1 channel(s) needs 2"));
  EXPECT_TRUE(throws_with<std::invalid_argument>(
      [] {
        (void)Bilinear_image<3>(1, 1, {1, 2, 3, 4});
      },
      "data has 4 values, a 1 x 1 image with 3 channel(s) needs 3"));
}

// A wider than high image: rows of `width` pixels from the top, the box [0, width) x [0, height), and pixel
// (column, row) centred at (column + 1/2, row + 1/2) with its own value there.
TEST(ImageDomain, BilinearColoursOfAWideImage) {
  const std::vector<std::uint8_t> grey{0, 51, 102, 153, 204, 255};  // 3 x 2
  const Bilinear_image<1> g(3, 2, grey);
  EXPECT_EQ(g.box(), (std::array<double, 4>{0, 0, 3, 2}));
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 3; ++column)
      EXPECT_DOUBLE_EQ(g(column + 0.5, row + 0.5)[0], grey[std::size_t(3 * row + column)] / 255.0)
          << column << " " << row;
  EXPECT_DOUBLE_EQ(g(2.0, 1.0)[0], (51 + 102 + 204 + 255) / 4.0 / 255.0);  // the mean of four centres
  const Bilinear_image<3> c(2, 1, {10, 20, 30, 40, 50, 60});               // 2 x 1, RGB
  EXPECT_EQ(c.box(), (std::array<double, 4>{0, 0, 2, 1}));
  EXPECT_DOUBLE_EQ(c(1.5, 0.5)[2], 60 / 255.0);
}

// A 96 x 96 light image crossed by a dark vertical line one pixel wide.
std::vector<std::uint8_t> line_image() {
  std::vector<std::uint8_t> data(96 * 96, 220);
  for (int row = 0; row < 96; ++row) data[std::size_t(row) * 96 + 48] = 10;
  return data;
}

TEST(ImageDomain, ContinuousDartsKeepAThinLine) {
  const Bilinear_image<1> image(96, 96, line_image());
  auto on_line = [](const auto& samples) {
    std::size_t n = 0;
    for (const auto& s : samples) n += std::abs(s.position[0] - 48.5) < 0.75;
    return n;
  };
  Continuous_dart_throwing_options o;
  o.seed = 5;
  const auto euclidean =
      continuous_bilateral_dart_throwing(image.box(), 4.0, image, Mean_squared_channel_distance(), o);
  o.sigma_feature = 0.1;
  const auto bilateral =
      continuous_bilateral_dart_throwing(image.box(), 4.0, image, Mean_squared_channel_distance(), o);
  // The line is narrower than the radius: Euclidean darts hit it by chance (~1.5 px of every 4-5 px column
  // spacing), bilateral darts fill it, because a dark sample is far from the light ones beside it.
  EXPECT_GE(on_line(bilateral.samples), 2 * on_line(euclidean.samples))
      << on_line(bilateral.samples) << " vs " << on_line(euclidean.samples);
  EXPECT_GE(on_line(bilateral.samples), 96 / 4 - 2);  // about one per radius along the line
  for (const auto& s : bilateral.samples) {
    EXPECT_GE(s.position[0], 0.0);
    EXPECT_LT(s.position[0], 96.0);
    EXPECT_EQ(s.feature, image(s.position[0], s.position[1]));
  }
  const auto again =
      continuous_bilateral_dart_throwing(image.box(), 4.0, image, Mean_squared_channel_distance(), o);
  ASSERT_EQ(again.samples.size(), bilateral.samples.size());
  for (std::size_t i = 0; i < again.samples.size(); ++i)
    EXPECT_EQ(again.samples[i].position, bilateral.samples[i].position);
}

TEST(ImageDomain, PixelEliminationKeepsAThinLine) {
  const auto pixels = image_pixels<Grey_pixel>(96, 96, line_image());
  auto on_line = [&](const std::vector<std::size_t>& kept) {
    std::size_t n = 0;
    for (std::size_t i : kept) n += pixels[i].column == 48;
    return n;
  };
  Elimination_options o;
  o.seed = 2;
  std::vector<std::size_t> euclidean, bilateral;
  weighted_sample_elimination(pixels, 400, std::back_inserter(euclidean), o, Grey_pixel_traits());
  o.sigma_feature = 0.1;
  weighted_sample_elimination(pixels, 400, std::back_inserter(bilateral), o, Grey_pixel_traits());
  ASSERT_EQ(bilateral.size(), 400u);
  EXPECT_GE(on_line(bilateral), 2 * on_line(euclidean)) << on_line(bilateral) << " vs " << on_line(euclidean);
}
}  // namespace
