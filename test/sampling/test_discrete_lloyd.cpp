// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Discrete bilateral Lloyd: the bilateral Voronoi assignment against brute force (both forms, ties), steps
// against weighted k-means, monotone Euclidean energy, feature update and snapping, stopping rules,
// degenerate sites and domains, bad input.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/discrete_lloyd.h>
#include <FeatureRecon/sampling/image_domain.h>

#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sampling/sampling_test_utilities.h"

namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using Site = Bilateral_site<Grey_pixel_traits>;

// A grey image with a vertical step (dark left of `edge`, bright right) plus seeded noise of +-noise.
std::vector<Grey_pixel> step_image(int w, int h, int edge, int noise, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> v(std::size_t(w * h));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int base = c < edge ? 40 : 210;
      const int n = noise == 0 ? 0 : int(rng() % std::uint64_t(2 * noise + 1)) - noise;
      v[std::size_t(r * w + c)] = static_cast<std::uint8_t>(base + n);
    }
  return image_pixels<Grey_pixel>(w, h, v);
}

std::vector<Site> random_sites(std::size_t n, int w, int h, unsigned seed) {
  std::mt19937_64 rng(seed);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Site> s(n);
  for (auto& x : s) {
    x.position = {u() * w, u() * h};
    x.feature = {static_cast<std::uint8_t>(rng() % 256)};
  }
  return s;
}

// Brute-force assignment: every site, smallest xi, ties to the lowest index.
template <class Metric>
std::vector<std::uint32_t> brute_force(const std::vector<Grey_pixel>& px, const std::vector<Site>& sites,
                                       Metric m) {
  std::vector<std::uint32_t> out;
  const Grey_pixel_traits t;
  for (const auto& p : px) {
    const double x = p.column + 0.5, y = p.row + 0.5;
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = 0;
    for (std::size_t j = 0; j < sites.size(); ++j) {
      const double dx = x - sites[j].position[0], dy = y - sites[j].position[1];
      const double xi =
          m(dx * dx + dy * dy, t.compute_feature_distance_object()({p.value}, sites[j].feature));
      if (xi < best) {
        best = xi;
        arg = static_cast<std::uint32_t>(j);
      }
    }
    out.push_back(arg);
  }
  return out;
}

TEST(Discrete_lloyd, AssignmentMatchesBruteForceInBothForms) {
  const auto px = step_image(37, 23, 15, 30, 1);
  for (const std::size_t n : {1u, 2u, 7u, 60u}) {
    const auto sites = random_sites(n, 37, 23, unsigned(n));
    for (const double sf : {std::numeric_limits<double>::infinity(), 0.3, 0.02}) {
      Discrete_lloyd_options<2> o;
      o.sigma_position = 1.5;
      o.sigma_feature = sf;
      o.form = Bilateral_form::gaussian;
      EXPECT_EQ(bilateral_voronoi_assignment(px, sites, o).site,
                brute_force(px, sites, Gaussian_bilateral_metric{1.5, sf}))
          << n << " sites, sigma_feature " << sf;
      o.form = Bilateral_form::exponential;
      EXPECT_EQ(bilateral_voronoi_assignment(px, sites, o).site,
                brute_force(px, sites, Exponential_bilateral_metric{1.5, sf}))
          << n << " sites, sigma_feature " << sf << " (exponential)";
    }
  }
}

TEST(Discrete_lloyd, GridOfANearlyFlatPatchStaysSmall) {
  // A 100 x 100 patch 1e-12 thick (rounding noise on a plane in 3-D): the thin axis gets one cell and the
  // grid about the cells asked for (it used to count the thin axis in the cell size: about n^2 cells, 784
  // MB).
  using Grid = FeatureRecon::sampling::internal::Ring_grid<3>;
  const Grid flat({0, 0, 0.1}, {100, 100, 0.1 + 1e-12}, 10000);
  EXPECT_LE(flat.number_of_cells(), 4u * 10000u);
  EXPECT_GE(flat.number_of_cells(), 10000u / 4);
  const Grid exactly_flat({0, 0, 0.1}, {100, 100, 0.1}, 10000);
  EXPECT_EQ(flat.number_of_cells(), exactly_flat.number_of_cells());
  // A needle: two thin axes.
  const Grid needle({0, 0, 0}, {1000, 1e-9, 1e-9}, 500);
  EXPECT_LE(needle.number_of_cells(), 4u * 500u);
  // A solid cube is unchanged: about the target.
  const Grid cube({0, 0, 0}, {10, 10, 10}, 1000);
  EXPECT_LE(cube.number_of_cells(), 4u * 1000u);
  EXPECT_GE(cube.number_of_cells(), 1000u / 4);
  // Cubes whose volume leaves the normal range: about the target too (a side 1e-110 made 1001^3 cells, 1e110
  // one).
  for (const double side : {1e-110, 1e-200, 1e-300, 1e110, 1e300}) {
    const Grid scaled({0, 0, 0}, {10 * side, 10 * side, 10 * side}, 1000);
    EXPECT_LE(scaled.number_of_cells(), 4u * 1000u) << "side " << side;
    EXPECT_GE(scaled.number_of_cells(), 1000u / 4) << "side " << side;
  }
}

TEST(Discrete_lloyd, TiesGoToTheLowestSiteIndex) {
  // Sites symmetric about pixel columns: the pixels on the bisector are equidistant from two sites.
  const auto px = step_image(9, 9, 100, 0, 0);
  std::vector<Site> sites{{{6.5, 4.5}, {40}}, {{2.5, 4.5}, {40}}, {{4.5, 0.5}, {40}}, {{2.5, 4.5}, {40}}};
  const auto a = bilateral_voronoi_assignment(px, sites);
  EXPECT_EQ(a.site, brute_force(px, sites, Gaussian_bilateral_metric{}));
  // The pixel centre (4.5, 4.5) is at distance 2 from sites 0, 1, 2 and 3: site 0 wins.
  EXPECT_EQ(a.site[4 * 9 + 4], 0u);
  // Site 3 duplicates site 1: it never gets a pixel.
  EXPECT_EQ(a.mass[3], 0.0);
  EXPECT_GT(a.mass[1], 0.0);
}

TEST(Discrete_lloyd, EuclideanStepIsWeightedKMeans) {
  const auto px = step_image(30, 20, 12, 20, 3);
  const auto sites = random_sites(9, 30, 20, 4);
  Discrete_lloyd_options<2> o;
  for (const auto& p : px) o.density.push_back(1.0 + p.value / 50.0);
  const auto step = discrete_lloyd_step(px, sites, o);
  const auto a = brute_force(px, sites, Gaussian_bilateral_metric{});
  ASSERT_EQ(step.assignment.site, a);
  for (std::size_t s = 0; s < sites.size(); ++s) {
    double m = 0, x = 0, y = 0;
    for (std::size_t i = 0; i < px.size(); ++i)
      if (a[i] == s) {
        m += o.density[i];
        x += o.density[i] * (px[i].column + 0.5);
        y += o.density[i] * (px[i].row + 0.5);
      }
    ASSERT_GT(m, 0);
    EXPECT_NEAR(step.sites[s].position[0], x / m, 1e-9);
    EXPECT_NEAR(step.sites[s].position[1], y / m, 1e-9);
    EXPECT_NEAR(step.assignment.mass[s], m, 1e-9);
    // The feature is that of the pixel containing the centroid.
    const int c = int(std::floor(x / m)), r = int(std::floor(y / m));
    EXPECT_EQ(step.sites[s].feature[0], px[std::size_t(r * 30 + c)].value);
  }
}

TEST(Discrete_lloyd, EuclideanEnergyDecreasesAndSitesSpreadOut) {
  std::vector<std::uint8_t> flat(64 * 64, 128);
  const auto px = image_pixels<Grey_pixel>(64, 64, flat);
  // Start from uniformly random (clumpy) sites.
  std::vector<Site> sites = random_sites(40, 64, 64, 5);
  Discrete_lloyd_options<2> o;
  o.max_iterations = 40;
  const auto r = discrete_bilateral_lloyd(px, sites, o);
  ASSERT_EQ(r.history.size(), 40u);
  for (std::size_t i = 1; i < r.history.size(); ++i)
    EXPECT_LE(r.history[i].energy, r.history[i - 1].energy * (1 + 1e-12)) << "iteration " << i + 1;
  EXPECT_LT(r.history.back().energy, 0.7 * r.history.front().energy);
  EXPECT_LT(r.history.front().relative_radius, 0.3);  // random sites clump
  EXPECT_GT(r.history.back().relative_radius, 0.6);   // evenly spread over the image
  for (const double m : r.mass) EXPECT_GT(m, 40.0);   // every cell holds a fair share of the 4096 pixels
  EXPECT_EQ(r.stop, Lloyd_stop::iteration_cap);
  EXPECT_EQ(r.status, Status::success);
}

TEST(Discrete_lloyd, BilateralCellsRespectTheEdge) {
  const auto px = step_image(48, 32, 20, 8, 6);
  // Start from darts on the pixels.
  std::vector<std::size_t> start;
  Dart_throwing_count_options d;
  d.darts.seed = 11;
  bilateral_dart_throwing_count(px, 40, std::back_inserter(start), d, Grey_pixel_traits());
  Discrete_lloyd_options<2> o;
  o.max_iterations = 15;
  o.sigma_feature = 0.05;  // colour differences of 170/255 cost 13 pixels
  const auto r = discrete_bilateral_lloyd(px, start, o);
  std::size_t crossing = 0;
  for (std::size_t i = 0; i < px.size(); ++i) {
    const bool dark_pixel = px[i].value < 128, dark_site = r.sites[r.assignment[i]].feature[0] < 128;
    crossing += dark_pixel != dark_site;
  }
  EXPECT_EQ(crossing, 0u);
  // Sites keep the feature of the nearest pixel (ties to the lowest index).
  for (const auto& s : r.sites) {
    std::size_t near = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < px.size(); ++i) {
      const double dx = px[i].column + 0.5 - s.position[0], dy = px[i].row + 0.5 - s.position[1];
      if (dx * dx + dy * dy < best) {
        best = dx * dx + dy * dy;
        near = i;
      }
    }
    EXPECT_EQ(s.feature[0], px[near].value);
  }
  // Result::items names that pixel: the brute-force nearest, whose value the site carries.
  ASSERT_EQ(r.items.size(), r.sites.size());
  for (std::size_t k = 0; k < r.sites.size(); ++k) {
    const auto& s = r.sites[k];
    for (std::size_t i = 0; i < px.size(); ++i) {
      const double dx = px[i].column + 0.5 - s.position[0], dy = px[i].row + 0.5 - s.position[1];
      const double dk = px[r.items[k]].column + 0.5 - s.position[0],
                   dyk = px[r.items[k]].row + 0.5 - s.position[1];
      ASSERT_TRUE(dk * dk + dyk * dyk < dx * dx + dy * dy ||
                  (dk * dk + dyk * dyk == dx * dx + dy * dy && r.items[k] <= i))
          << "site " << k << ", pixel " << i;
    }
    EXPECT_EQ(s.feature[0], px[r.items[k]].value);
  }
  // Euclidean cells do cross the edge.
  o.sigma_feature = std::numeric_limits<double>::infinity();
  const auto e = discrete_bilateral_lloyd(px, start, o);
  std::size_t e_crossing = 0;
  for (std::size_t i = 0; i < px.size(); ++i)
    e_crossing += (px[i].value < 128) != (e.sites[e.assignment[i]].feature[0] < 128);
  EXPECT_GT(e_crossing, 0u);
}

TEST(Discrete_lloyd, SnapKeepsSitesOnItems) {
  const auto px = step_image(25, 25, 10, 10, 7);
  Discrete_lloyd_options<2> o;
  o.update = Site_update::snap_to_item;
  o.sigma_feature = 0.2;
  o.max_iterations = 8;
  const auto r = discrete_bilateral_lloyd(px, random_sites(12, 25, 25, 8), o);
  for (const auto& s : r.sites) {
    EXPECT_EQ(s.position[0] - std::floor(s.position[0]), 0.5);
    EXPECT_EQ(s.position[1] - std::floor(s.position[1]), 0.5);
  }
  // Result::items: the pixel each site sits on, and whose value it carries.
  ASSERT_EQ(r.items.size(), r.sites.size());
  for (std::size_t k = 0; k < r.sites.size(); ++k) {
    const Grey_pixel& p = px[r.items[k]];
    EXPECT_EQ(r.sites[k].position[0], p.column + 0.5) << k;
    EXPECT_EQ(r.sites[k].position[1], p.row + 0.5) << k;
    EXPECT_EQ(r.sites[k].feature[0], p.value) << k;
  }
  // No items: none named.
  EXPECT_TRUE(
      discrete_bilateral_lloyd(std::vector<Grey_pixel>{}, random_sites(3, 25, 25, 8), o).items.empty());
}

TEST(Discrete_lloyd, DeterministicAndStoppingRules) {
  const auto px = step_image(40, 30, 17, 25, 9);
  const auto sites = random_sites(25, 40, 30, 10);
  Discrete_lloyd_options<2> o;
  o.sigma_feature = 0.1;
  o.max_iterations = 30;
  const auto a = discrete_bilateral_lloyd(px, sites, o), b = discrete_bilateral_lloyd(px, sites, o);
  ASSERT_EQ(a.sites.size(), b.sites.size());
  for (std::size_t i = 0; i < a.sites.size(); ++i) EXPECT_EQ(a.sites[i].position, b.sites[i].position);
  EXPECT_EQ(a.assignment, b.assignment);

  o.move_tolerance = 0.05;
  const auto m = discrete_bilateral_lloyd(px, sites, o);
  EXPECT_EQ(m.stop, Lloyd_stop::move_tolerance);
  EXPECT_LE(m.history.back().max_move, 0.05);
  for (std::size_t i = 0; i + 1 < m.history.size(); ++i) EXPECT_GT(m.history[i].max_move, 0.05);

  o.move_tolerance = 0;
  std::size_t calls = 0;
  o.on_iteration = [&](Lloyd_iteration_statistics& s, const std::vector<std::array<double, 2>>& p) {
    EXPECT_EQ(p.size(), sites.size());
    s.oscillation = 42;
    return ++calls < 3;
  };
  const auto c = discrete_bilateral_lloyd(px, sites, o);
  EXPECT_EQ(c.stop, Lloyd_stop::callback);
  ASSERT_EQ(c.history.size(), 3u);
  EXPECT_EQ(c.history[2].oscillation, 42);
  o.on_iteration = nullptr;
  o.progress = [](double f) { return f < 0.1; };
  const auto i = discrete_bilateral_lloyd(px, sites, o);
  EXPECT_EQ(i.status, Status::interrupted);
  EXPECT_EQ(i.history.size(), 3u);  // stopped before the 4th iteration (3/30 >= 0.1)
}

TEST(Discrete_lloyd, DegenerateInput) {
  const std::vector<Grey_pixel> none;
  const auto px = step_image(5, 4, 2, 0, 0);
  const auto r0 = discrete_bilateral_lloyd(none, random_sites(3, 5, 4, 1));
  EXPECT_EQ(r0.status, Status::degenerate_input);
  EXPECT_EQ(r0.sites.size(), 3u);
  const auto r1 = discrete_bilateral_lloyd(px, std::vector<Site>{});
  EXPECT_EQ(r1.status, Status::degenerate_input);
  // One site goes to the centroid of the whole image.
  const auto one = discrete_bilateral_lloyd(px, std::vector<Site>{{{0.5, 0.5}, {0}}});
  EXPECT_DOUBLE_EQ(one.sites[0].position[0], 2.5);
  EXPECT_DOUBLE_EQ(one.sites[0].position[1], 2.0);
  // Every site on the same pixel: the lowest index takes everything, the others stay.
  std::vector<Site> same(4, Site{{1.5, 1.5}, {40}});
  const auto s = discrete_lloyd_step(px, same);
  EXPECT_EQ(s.assignment.mass[0], 20.0);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_EQ(s.sites[k].position, same[k].position);
  // One pixel.
  const auto single = image_pixels<Grey_pixel>(1, 1, {7});
  const auto r2 = discrete_bilateral_lloyd(single, random_sites(2, 1, 1, 2));
  EXPECT_EQ(r2.assignment, std::vector<std::uint32_t>(1, r2.assignment[0]));
  // Zero density: nothing moves.
  Discrete_lloyd_options<2> o;
  o.density.assign(px.size(), 0.0);
  const auto sites = random_sites(3, 5, 4, 3);
  const auto z = discrete_lloyd_step(px, sites, o);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(z.sites[k].position, sites[k].position);
}

TEST(Discrete_lloyd, PointsWithNormalsIn3D) {
  // Two parallel sheets 0.1 apart with opposite normals: bilateral cells never mix the sheets.
  using K = test::K;
  std::vector<std::pair<K::Point_3, K::Vector_3>> items;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) {
      items.push_back({K::Point_3(i / 29.0, j / 29.0, 0), K::Vector_3(0, 0, 1)});
      items.push_back({K::Point_3(i / 29.0, j / 29.0, 0.1), K::Vector_3(0, 0, -1)});
    }
  std::vector<std::size_t> start;
  for (std::size_t k = 0; k < 40; ++k) start.push_back((k * 977) % items.size());
  Discrete_lloyd_options<3> o;
  o.sigma_feature = 0.2;
  o.max_iterations = 10;
  const auto r = discrete_bilateral_lloyd(items, start, o);
  for (std::size_t i = 0; i < items.size(); ++i)
    EXPECT_EQ(items[i].second.z(), r.sites[r.assignment[i]].feature.z()) << "item " << i;
  EXPECT_GT(r.history.back().relative_radius, 0.0);
}

TEST(Discrete_lloyd, ExponentialFormWithCopiesOfFarFeatures) {
  // Two items at one place with opposite normals: exp(4 / 0.05^2) overflows, and 0 * inf was NaN, which no
  // site's score beat (site index 2^32 - 1 written to). Identical positions are at distance 0: site 0 takes
  // both.
  using K = test::K;
  const std::vector<std::pair<K::Point_3, K::Vector_3>> items{{K::Point_3(0, 0, 0), K::Vector_3(0, 0, 1)},
                                                              {K::Point_3(0, 0, 0), K::Vector_3(0, 0, -1)},
                                                              {K::Point_3(5, 0, 0), K::Vector_3(0, 0, 1)}};
  Discrete_lloyd_options<3> o;
  o.form = Bilateral_form::exponential;
  o.sigma_feature = 0.05;
  const auto a =
      bilateral_voronoi_assignment(items, sites_at_items(items, std::vector<std::size_t>{0, 2}), o);
  EXPECT_EQ(a.site, (std::vector<std::uint32_t>{0, 0, 1}));
  EXPECT_EQ(a.mass, (std::vector<double>{2, 1}));
  // Dart throwing: the copy conflicts with the first (it was kept: NaN < r is false).
  Dart_throwing_options d;
  d.form = Bilateral_form::exponential;
  d.sigma_feature = 0.05;
  std::vector<std::size_t> kept;
  bilateral_dart_throwing(items, 1.0, std::back_inserter(kept), d);
  EXPECT_EQ(kept.size(), 2u);
}

TEST(Discrete_lloyd, VolumesZeroNormalsAndNoIteration) {
  using K = test::K;
  // Items filling the unit cube (21^3 grid), sites on a 5^3 cubic lattice of spacing 0.25: rho against the
  // FCC packing, as sampling_quality() measures it (the hexagonal formula with the volume gave 2.60).
  std::vector<K::Point_3> cube;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      for (int k = 0; k <= 20; ++k) cube.emplace_back(i / 20.0, j / 20.0, k / 20.0);
  std::vector<std::size_t> lattice;
  for (int i = 0; i <= 20; i += 5)
    for (int j = 0; j <= 20; j += 5)
      for (int k = 0; k <= 20; k += 5) lattice.push_back(std::size_t(i * 441 + j * 21 + k));
  Discrete_lloyd_options<3> o;
  o.max_iterations = 1;
  o.domain_measure = 1;
  const double rho = discrete_bilateral_lloyd(cube, lattice, o).history.at(0).relative_radius;
  EXPECT_NEAR(rho, 0.25 / std::cbrt(std::sqrt(2.0) / 125), 1e-12);  // 1.1136
  o.domain_measure = 0;  // estimated as a volume: the box widened by the item spacing, (21/20)^3
  EXPECT_NEAR(discrete_bilateral_lloyd(cube, lattice, o).history.at(0).relative_radius,
              0.25 / std::cbrt(std::sqrt(2.0) * std::pow(1.05, 3) / 125), 1e-9);
  o.intrinsic_dimension = 4;
  EXPECT_THROW(discrete_bilateral_lloyd(cube, lattice, o), std::invalid_argument);
  // A zero normal is refused only where normals are compared (finite sigma_feature), as by the other
  // samplers.
  std::vector<std::pair<K::Point_3, K::Vector_3>> sheet;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) sheet.push_back({K::Point_3(i, j, 0), K::Vector_3(0, 0, 1)});
  sheet[5].second = K::Vector_3(0, 0, 0);
  Discrete_lloyd_options<3> e;
  e.max_iterations = 2;
  const auto r = discrete_bilateral_lloyd(sheet, std::vector<std::size_t>{0, 50, 99}, e);
  EXPECT_EQ(r.history.size(), 2u);
  e.sigma_feature = 0.5;
  EXPECT_THROW(discrete_bilateral_lloyd(sheet, std::vector<std::size_t>{0, 50, 99}, e),
               std::invalid_argument);
  // A site with a zero normal is refused as such an item is, naming the site (it silently got no item, or
  // alone an infinite energy).
  sheet[5].second = K::Vector_3(0, 0, 1);
  auto sites = sites_at_items(sheet, std::vector<std::size_t>{0, 77});
  sites[1].feature = K::Vector_3(0, 0, 0);
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(sheet, sites, e); },
                                                       "site 1 has a feature at distance NaN from itself"));
  e.sigma_feature = std::numeric_limits<double>::infinity();  // Euclidean: features are not compared
  EXPECT_NO_THROW(discrete_bilateral_lloyd(sheet, sites, e));
  sheet[5].second = K::Vector_3(0, 0, 0);
  // No iteration: the assignment is that of the starting sites (it came back empty).
  e.sigma_feature = std::numeric_limits<double>::infinity();
  e.max_iterations = 0;
  const auto z = discrete_bilateral_lloyd(sheet, std::vector<std::size_t>{0, 99}, e);
  ASSERT_EQ(z.assignment.size(), sheet.size());
  EXPECT_EQ(z.assignment[0], 0u);
  EXPECT_EQ(z.assignment[99], 1u);
  EXPECT_EQ(z.mass[0] + z.mass[1], 100.0);
}

TEST(Discrete_lloyd, BadInputNamesTheProblem) {
  const auto px = step_image(6, 6, 3, 0, 0);
  const auto sites = random_sites(3, 6, 6, 1);
  Discrete_lloyd_options<2> o;
  o.density.assign(5, 1.0);
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(px, sites, o); },
                                                       "density has 5 values for 36 items"));
  o.density.assign(36, 1.0);
  o.density[17] = -1;
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { discrete_lloyd_step(px, sites, o); }, "density[17]"));
  o.density.clear();
  o.sigma_feature = 0;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { bilateral_voronoi_assignment(px, sites, o); },
                                                       "sigma_feature"));
  o.sigma_feature = 1;
  auto bad = sites;
  bad[2].position[1] = std::nan("");
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(px, bad, o); }, "site 2"));
  // Sites are held to the items' bounds: a site at 1e200 overflowed the grid's cell arithmetic (an undefined
  // float-to-integer cast).
  bad = sites;
  bad[1].position[0] = 1e200;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(px, bad, o); },
                                                       "site 1 has coordinate 1e+200 beyond +-1e100"));
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { bilateral_voronoi_assignment(px, bad, o); },
                                                       "site 1 has coordinate 1e+200 beyond +-1e100"));
  bad[1].position[0] = -1e100;  // the bound itself is allowed
  EXPECT_NO_THROW(discrete_lloyd_step(px, bad, o));
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        sites_at_items(px, std::vector<int>{0, 5, 36});
      },
      "indices[2] = 36"));
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { sites_at_items(px, std::vector<int>{-1}); },
                                                       "indices[0] = -1"));
  o.domain_measure = -1;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(px, sites, o); },
                                                       "domain_measure"));
  o.domain_measure = 0;
  o.energy_tolerance = std::numeric_limits<double>::infinity();  // stopped every run after two iterations
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { discrete_bilateral_lloyd(px, sites, o); },
                                                       "energy_tolerance and move_tolerance must be finite"));
}

}  // namespace

namespace {
// Tests from a mutation audit of discrete_lloyd.h: documented boundaries and rules the tests above leave
// open.

TEST(Discrete_lloyd, RelativeRadiusIsZeroWhenTwoSitesMeetOnAnItem) {
  // A 2 x 2 image. Site 1 holds the pixels (1.5, 0.5) and (0.5, 1.5): its centroid (1, 1) is equally near all
  // four pixels and snaps to the lowest-indexed one, (0.5, 0.5), where site 0 already is. The next
  // iteration's statistics (taken at the sites before they move) see two sites at one position: rho = 0.
  const auto px = step_image(2, 2, 100, 0, 0);
  const std::vector<Site> sites{{{0.4, 0.4}, {40}}, {{1.0, 1.0}, {40}}, {{1.6, 1.6}, {40}}};
  Discrete_lloyd_options<2> o;
  o.update = Site_update::snap_to_item;
  o.max_iterations = 2;
  std::vector<std::vector<std::array<double, 2>>> seen;
  o.on_iteration = [&seen](Lloyd_iteration_statistics&, const std::vector<std::array<double, 2>>& p) {
    seen.push_back(p);
    return true;
  };
  const auto r = discrete_bilateral_lloyd(px, sites, o);
  ASSERT_EQ(r.history.size(), 2u);
  ASSERT_EQ(seen.size(), 2u);
  ASSERT_EQ(seen[0][0], (std::array<double, 2>{0.5, 0.5}));
  ASSERT_EQ(seen[0][1], (std::array<double, 2>{0.5, 0.5}));
  EXPECT_GT(r.history[0].relative_radius, 0.0);
  EXPECT_EQ(r.history[1].relative_radius, 0.0);
}

TEST(Discrete_lloyd, RequestedIntrinsicDimensionChoosesThePacking) {
  // Items filling a cube would be read as a volume; intrinsic_dimension 2 measures rho against the hexagonal
  // packing of the given area instead: rho = d_min / sqrt(2 A / (sqrt(3) N)).
  using K = test::K;
  std::vector<K::Point_3> cube;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int k = 0; k <= 10; ++k) cube.emplace_back(i / 10.0, j / 10.0, k / 10.0);
  std::vector<std::size_t> lattice;
  for (int i = 0; i <= 10; i += 5)
    for (int j = 0; j <= 10; j += 5)
      for (int k = 0; k <= 10; k += 5) lattice.push_back(std::size_t(i * 121 + j * 11 + k));
  Discrete_lloyd_options<3> o;
  o.max_iterations = 1;
  o.domain_measure = 6;
  o.intrinsic_dimension = 2;
  const auto r = discrete_bilateral_lloyd(cube, lattice, o);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_NEAR(r.history[0].relative_radius, 0.5 / std::sqrt(2 * 6.0 / (std::sqrt(3.0) * 27)), 1e-12);
}

TEST(Discrete_lloyd, MovesAreThoseOfTheSitesAlsoWhenSnapping) {
  // max_move and mean_move are the distances from the sites before the step to the sites after it (with
  // snapping: to their items, not to the centroids).
  const auto px = step_image(20, 16, 8, 20, 2);
  const auto start = random_sites(9, 20, 16, 3);
  for (const Site_update update : {Site_update::nearest_item, Site_update::snap_to_item}) {
    Discrete_lloyd_options<2> o;
    o.update = update;
    o.max_iterations = 3;
    std::vector<std::vector<std::array<double, 2>>> seen;
    o.on_iteration = [&seen](Lloyd_iteration_statistics&, const std::vector<std::array<double, 2>>& p) {
      seen.push_back(p);
      return true;
    };
    const auto r = discrete_bilateral_lloyd(px, start, o);
    ASSERT_EQ(r.history.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      double largest = 0, total = 0;
      for (std::size_t s = 0; s < start.size(); ++s) {
        const auto& before = k == 0 ? start[s].position : seen[k - 1][s];
        const double d = std::hypot(seen[k][s][0] - before[0], seen[k][s][1] - before[1]);
        largest = std::max(largest, d);
        total += d;
      }
      EXPECT_NEAR(r.history[k].max_move, largest, 1e-12) << "iteration " << k + 1;
      EXPECT_NEAR(r.history[k].mean_move, total / double(start.size()), 1e-12) << "iteration " << k + 1;
    }
  }
}

TEST(Discrete_lloyd, CopiesMoveApartByAHundredthOfThePackingAndOnlyWhenIterating) {
  const auto px = step_image(12, 12, 100, 0, 0);
  const std::vector<Site> sites{
      {{2.5, 2.5}, {40}}, {{8.5, 3.5}, {40}}, {{2.5, 2.5}, {40}}, {{5.5, 9.5}, {40}}};
  Discrete_lloyd_options<2> o;
  o.max_iterations = 1;
  const auto r = discrete_bilateral_lloyd(px, sites, o);
  ASSERT_EQ(r.history.size(), 1u);
  // rho at the sites before the first move: the copy's distance d_hex / 100 over d_hex.
  EXPECT_NEAR(r.history[0].relative_radius, 0.01, 1e-12);
  // No iteration: the sites as given, copies included.
  o.max_iterations = 0;
  const auto none = discrete_bilateral_lloyd(px, sites, o);
  ASSERT_EQ(none.sites.size(), sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) EXPECT_EQ(none.sites[i].position, sites[i].position) << i;
  EXPECT_TRUE(none.history.empty());
}

TEST(Discrete_lloyd, EnergyToleranceStopsOnTheRelativeDecrease) {
  std::vector<std::uint8_t> flat(32 * 32, 128);
  const auto px = image_pixels<Grey_pixel>(32, 32, flat);
  Discrete_lloyd_options<2> o;
  o.max_iterations = 200;
  o.energy_tolerance = 1e-3;
  const auto r = discrete_bilateral_lloyd(px, random_sites(20, 32, 32, 5), o);
  ASSERT_EQ(r.stop, Lloyd_stop::energy_tolerance);
  test::expect_energy_rule_holds_at_the_stop(r.history, 1e-3);
}

TEST(Discrete_lloyd, MoveToleranceIsInclusive) {
  // "stop when no site moved farther than this": one site on a 4 x 1 image snaps from the first pixel to the
  // pixel nearest the centroid (2, 0.5), the lower-indexed of the two at 0.5: a move of exactly 1.
  const auto px = step_image(4, 1, 100, 0, 0);
  Discrete_lloyd_options<2> o;
  o.update = Site_update::snap_to_item;
  o.move_tolerance = 1;
  const auto r = discrete_bilateral_lloyd(px, std::vector<std::size_t>{0}, o);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_EQ(r.history[0].max_move, 1.0);
  EXPECT_EQ(r.stop, Lloyd_stop::move_tolerance);
  EXPECT_EQ(r.sites[0].position, (std::array<double, 2>{1.5, 0.5}));
}

// The torus [0, W) x [0, H) of a W x H picture: the shift (a multiple of W, H) that brings site position p
// nearest to x, and the squared distance to that image.
double torus_squared(double x, double y, const std::array<double, 2>& p, double w, double h,
                     std::array<double, 2>* shift = nullptr) {
  double best = std::numeric_limits<double>::infinity();
  for (int a = -2; a <= 2; ++a)
    for (int b = -2; b <= 2; ++b) {
      const double dx = x - (p[0] + a * w), dy = y - (p[1] + b * h), d = dx * dx + dy * dy;
      if (d < best) {
        best = d;
        if (shift) *shift = {a * w, b * h};
      }
    }
  return best;
}

// Brute force on the torus: each pixel's site (smallest xi through the nearest image, ties to the lowest
// index) and, per site, the density-weighted centroid of its pixels taken at their images nearest it,
// wrapped into [0, W) x [0, H).
struct Torus_oracle {
  std::vector<std::uint32_t> site;
  double energy = 0;
  std::vector<std::array<double, 2>> centroid;
  std::vector<double> mass;
};
Torus_oracle torus_brute_force(const std::vector<Grey_pixel>& px, std::vector<Site> sites, int w, int h,
                               double sigma_position, double sigma_feature, const std::vector<double>& rho) {
  for (auto& s : sites)
    for (int k = 0; k < 2; ++k) {
      const double period = k == 0 ? w : h;
      s.position[k] = std::fmod(std::fmod(s.position[k], period) + period, period);
    }
  Torus_oracle o;
  std::vector<std::array<double, 2>> sum(sites.size(), {0.0, 0.0});
  o.mass.assign(sites.size(), 0.0);
  const Grey_pixel_traits t;
  const Gaussian_bilateral_metric metric{sigma_position, sigma_feature};
  for (std::size_t i = 0; i < px.size(); ++i) {
    const double x = px[i].column + 0.5, y = px[i].row + 0.5;
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = 0;
    for (std::size_t j = 0; j < sites.size(); ++j) {
      const double xi = metric(torus_squared(x, y, sites[j].position, w, h),
                               t.compute_feature_distance_object()({px[i].value}, sites[j].feature));
      if (xi < best) {
        best = xi;
        arg = static_cast<std::uint32_t>(j);
      }
    }
    o.site.push_back(arg);
    const double r = rho.empty() ? 1.0 : rho[i];
    o.energy += r * best * best;
    std::array<double, 2> shift{};
    torus_squared(x, y, sites[arg].position, w, h, &shift);
    sum[arg][0] += r * (x - shift[0]);
    sum[arg][1] += r * (y - shift[1]);
    o.mass[arg] += r;
  }
  for (std::size_t j = 0; j < sites.size(); ++j) {
    std::array<double, 2> c = sites[j].position;
    if (o.mass[j] > 0)
      for (int k = 0; k < 2; ++k) {
        const double period = k == 0 ? w : h;
        c[k] = std::fmod(std::fmod(sum[j][k] / o.mass[j], period) + period, period);
      }
    o.centroid.push_back(c);
  }
  return o;
}

TEST(Discrete_lloyd, TorusAssignmentAndStepMatchBruteForce) {
  // Pixels go to the site nearest on the torus of the picture, sites move to the centroid of their pixels
  // taken across the faces: against brute force, Euclidean and bilateral, with a density, sites anywhere
  // (some outside the picture, wrapped).
  const int w = 29, h = 17;
  const auto px = step_image(w, h, 12, 30, 4);
  std::vector<double> rho;
  for (const auto& p : px) rho.push_back(1 - p.value / 255.0);
  for (const std::size_t n : {1u, 3u, 12u, 40u}) {
    auto sites = random_sites(n, w, h, unsigned(10 + n));
    if (n > 2) {
      sites[0].position = {-3.25, 5.5};
      sites[1].position = {w + 7.5, -h + 0.25};
    }
    for (const double sf : {std::numeric_limits<double>::infinity(), 0.3}) {
      Discrete_lloyd_options<2> o;
      o.periodic = true;
      o.sigma_position = 1.5;
      o.sigma_feature = sf;
      o.density = rho;
      const auto want = torus_brute_force(px, sites, w, h, 1.5, sf, rho);
      const auto a = bilateral_voronoi_assignment(px, sites, o);
      EXPECT_EQ(a.site, want.site) << n << " sites, sigma_feature " << sf;
      EXPECT_NEAR(a.energy, want.energy, 1e-12 * want.energy);
      const auto step = discrete_lloyd_step(px, sites, o);
      for (std::size_t j = 0; j < n; ++j)
        for (int k = 0; k < 2; ++k)
          EXPECT_NEAR(step.sites[j].position[k], want.centroid[j][k], 1e-9)
              << n << " sites, sigma_feature " << sf << ", site " << j;
      // The step's moves are the torus's: never more than half the diagonal.
      EXPECT_LE(step.max_move, 0.5 * std::sqrt(double(w * w + h * h)) + 1e-12);
    }
  }
}

TEST(Discrete_lloyd, SitesOnASmallPartOfThePictureMatchBruteForce) {
  // Sites in an 8 x 6 corner of a 64 x 48 picture (a dark logo on white): most pixels lie many empty cells
  // away from every site, where the assignment's ring search stops and its kd-tree answers. Against brute
  // force in the plane and on the torus (the corner straddles a face there), Euclidean and bilateral, and
  // with copies of sites (ties to the lowest index).
  const int w = 64, h = 48;
  const auto px = step_image(w, h, 30, 30, 8);
  for (const std::size_t n : {1u, 9u, 40u}) {
    auto sites = random_sites(n, 8, 6, unsigned(20 + n));
    if (n == 40)
      for (std::size_t j = 30; j < n; ++j) sites[j] = sites[j - 30];
    for (const double sf : {std::numeric_limits<double>::infinity(), 0.3, 0.02}) {
      Discrete_lloyd_options<2> o;
      o.sigma_position = 1.5;
      o.sigma_feature = sf;
      for (const Bilateral_form form : {Bilateral_form::gaussian, Bilateral_form::exponential}) {
        o.form = form;
        const auto a = bilateral_voronoi_assignment(px, sites, o);
        if (form == Bilateral_form::gaussian)
          EXPECT_EQ(a.site, brute_force(px, sites, Gaussian_bilateral_metric{1.5, sf}))
              << n << " sites, sigma_feature " << sf;
        else
          EXPECT_EQ(a.site, brute_force(px, sites, Exponential_bilateral_metric{1.5, sf}))
              << n << " sites, sigma_feature " << sf;
      }
      o.form = Bilateral_form::gaussian;
      o.periodic = true;
      auto shifted = sites;  // the corner around the picture's corner: across both faces
      for (auto& site : shifted) site.position = {site.position[0] - 4, site.position[1] - 3};
      const auto want = torus_brute_force(px, shifted, w, h, 1.5, sf, {});
      const auto a = bilateral_voronoi_assignment(px, shifted, o);
      EXPECT_EQ(a.site, want.site) << n << " sites on the torus, sigma_feature " << sf;
      EXPECT_NEAR(a.energy, want.energy, 1e-12 * want.energy);
    }
  }
}

TEST(Discrete_lloyd, AFarSiteAndTinyCoordinatesMatchBruteForce) {
  // From a review: one site far outside the picture (1e6 away) made the grid of the sites one cell for all
  // the others (every pixel scored all of them); the rings now stop after 64 sites and the kd-tree answers.
  const auto px = step_image(48, 40, 20, 30, 9);
  auto sites = random_sites(60, 48, 40, 31);
  sites[7].position = {1e6, 1e6};
  for (const double sf : {std::numeric_limits<double>::infinity(), 0.3}) {
    Discrete_lloyd_options<2> o;
    o.sigma_position = 1.5;
    o.sigma_feature = sf;
    EXPECT_EQ(bilateral_voronoi_assignment(px, sites, o).site,
              brute_force(px, sites, Gaussian_bilateral_metric{1.5, sf}))
        << "sigma_feature " << sf;
  }
  // Items on a lattice of step 1e-160 (squared distances below the normal range: scores of 0 tie) keep the
  // full ring search, whose answers are those of brute force with the same scores (the tree's exact box
  // distances parted from them for 124 of these 1200 items).
  using P2 = test::K::Point_2;
  using Point_site = Bilateral_site<Point_traits<P2>>;
  std::vector<P2> items;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) items.emplace_back(x * 1e-160, y * 1e-160);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point_site> tiny(50);
  for (auto& s : tiny) s.position = {u(rng) * 4e-160, u(rng) * 3e-160};
  Discrete_lloyd_options<2> o;
  o.sigma_position = 1000;
  const auto got = bilateral_voronoi_assignment(items, tiny, o).site;
  const Gaussian_bilateral_metric metric{1000, std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < items.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = 0;
    for (std::uint32_t j = 0; j < tiny.size(); ++j) {
      const double dx = items[i].x() - tiny[j].position[0], dy = items[i].y() - tiny[j].position[1];
      const double xi = metric(dx * dx + dy * dy, 0.0);
      if (xi < best) {
        best = xi;
        arg = j;
      }
    }
    EXPECT_EQ(got[i], arg) << "item " << i;
  }
}

// Brute force of any metric over items with positions and features, through a traits class: every site,
// smallest xi, ties to the lowest index; on the torus of a w x h picture (w > 0) the nearest image of each
// site.
template <class Traits, class ItemRange, class Metric>
std::vector<std::uint32_t> generic_brute_force(const ItemRange& items,
                                               const std::vector<Bilateral_site<Traits>>& sites,
                                               const Metric& metric, const Traits& traits = Traits(),
                                               double w = 0, double h = 0) {
  std::vector<std::uint32_t> out;
  const auto point = traits.construct_point_object();
  const auto feature = traits.construct_feature_object();
  const auto fd = traits.compute_feature_distance_object();
  for (const auto& item : items) {
    const auto p = point(item);
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = 0;
    for (std::uint32_t j = 0; j < sites.size(); ++j) {
      double sq = 0;
      if constexpr (Traits::dimension == 2) {
        if (w > 0) {
          std::array<double, 2> q = sites[j].position;
          q[0] = std::fmod(std::fmod(q[0], w) + w, w);
          q[1] = std::fmod(std::fmod(q[1], h) + h, h);
          sq = torus_squared(CGAL::to_double(p.x()), CGAL::to_double(p.y()), q, w, h);
        } else {
          const double dx = CGAL::to_double(p.x()) - sites[j].position[0],
                       dy = CGAL::to_double(p.y()) - sites[j].position[1];
          sq = dx * dx + dy * dy;
        }
      } else {
        const double dx = CGAL::to_double(p.x()) - sites[j].position[0],
                     dy = CGAL::to_double(p.y()) - sites[j].position[1],
                     dz = CGAL::to_double(p.z()) - sites[j].position[2];
        sq = dx * dx + dy * dy + dz * dz;
      }
      const double xi = metric(sq, CGAL::to_double(fd(feature(item), sites[j].feature)));
      if (xi < best) {
        best = xi;
        arg = j;
      }
    }
    out.push_back(arg);
  }
  return out;
}

// A scalar feature compared by its squared difference, declared a metric (Property_map_traits takes its
// feature_metric_error), or not.
struct Declared_metric {
  static constexpr double feature_metric_error = 0;
  double operator()(double a, double b) const { return (a - b) * (a - b); }
};
struct Undeclared_metric {
  double operator()(double a, double b) const { return (a - b) * (a - b); }
};

TEST(Discrete_lloyd, FeatureBallsMatchBruteForce) {
  // Searches that run past 64 nodes of the kd-tree start again with balls of the sites' features (traits
  // that declare the feature distance's square root a metric): a node whose features all lie far from the
  // item's is ruled out as a whole. Where every site's feature is far (white pixels against the sites of a
  // dark logo), the exponential form scored every site before. The answers must stay those of brute force:
  // pictures with a logo and sites of mixed greys, plane and torus, both forms, sharp and soft features;
  // points with normals on two crossing sheets (oriented and unoriented); users' scalar features declared a
  // metric or not.
  const int w = 80, h = 64;
  std::mt19937_64 rng(41);
  std::vector<std::uint8_t> grey(std::size_t(w * h), 235);
  for (int y = 20; y < 44; ++y)
    for (int x = 24; x < 56; ++x) grey[std::size_t(y * w + x)] = std::uint8_t(10 + rng() % 20);
  for (int x = 0; x < w; ++x) grey[std::size_t(60 * w + x)] = std::uint8_t(x * 3);  // a gradient row
  const auto px = image_pixels<Grey_pixel>(w, h, grey);
  std::vector<Site> sites(700);
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const double x = 24 + double(rng() % 3200) / 100, y = 20 + double(rng() % 2400) / 100;
    // Mostly dark sites in the logo, every 10th of any grey, every 50th a copy of the one before (ties).
    sites[j] = Site{{x, y}, {std::uint8_t(j % 10 == 9 ? rng() % 256 : 10 + rng() % 20)}};
    if (j % 50 == 49) sites[j] = sites[j - 1];
  }
  for (const double sf : {0.3, 0.05}) {
    Discrete_lloyd_options<2> o;
    o.sigma_position = 0.8;
    o.sigma_feature = sf;
    for (const Bilateral_form form : {Bilateral_form::gaussian, Bilateral_form::exponential}) {
      o.form = form;
      const Gaussian_bilateral_metric g{0.8, sf};
      const Exponential_bilateral_metric e{0.8, sf};
      for (const bool periodic : {false, true}) {
        o.periodic = periodic;
        const auto got = bilateral_voronoi_assignment(px, sites, o).site;
        const auto want = form == Bilateral_form::gaussian
                              ? generic_brute_force(px, sites, g, Grey_pixel_traits(), periodic ? w : 0, h)
                              : generic_brute_force(px, sites, e, Grey_pixel_traits(), periodic ? w : 0, h);
        EXPECT_EQ(got, want) << "sigma_feature " << sf
                             << (form == Bilateral_form::gaussian ? " gaussian" : " exponential")
                             << (periodic ? " on the torus" : "");
      }
    }
  }
  // Normals: the sheets z = 0 (normal +z) and x = 0 (normal +x, every 7th point -x), sites at 500 items.
  using K = test::K;
  std::vector<std::pair<K::Point_3, K::Vector_3>> items;
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 3000; ++i) {
    const double a = u(rng), b = u(rng);
    if (i % 2 == 0)
      items.push_back({K::Point_3(a, b, 0), K::Vector_3(0.01 * u(rng), 0, 1)});
    else
      items.push_back({K::Point_3(0, a, b), K::Vector_3(i % 7 == 0 ? -1 : 1, 0.01 * u(rng), 0)});
  }
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < 500; ++k) at.push_back((k * 7919) % items.size());
  const auto normal_sites = sites_at_items(items, at);
  for (const Normal_orientation orientation :
       {Normal_orientation::oriented, Normal_orientation::unoriented}) {
    Point_with_normal_traits<K> traits;
    traits.orientation = orientation;
    for (const double sf : {0.3, 0.05}) {
      Discrete_lloyd_options<3> o;
      o.sigma_position = 0.02;
      o.sigma_feature = sf;
      o.intrinsic_dimension = 2;
      const Gaussian_bilateral_metric g{0.02, sf};
      const Exponential_bilateral_metric e{0.02, sf};
      EXPECT_EQ(bilateral_voronoi_assignment(items, normal_sites, o, traits).site,
                generic_brute_force(items, normal_sites, g, traits))
          << "normals, sigma_feature " << sf << ", orientation " << int(orientation);
      o.form = Bilateral_form::exponential;
      EXPECT_EQ(bilateral_voronoi_assignment(items, normal_sites, o, traits).site,
                generic_brute_force(items, normal_sites, e, traits))
          << "normals, exponential, sigma_feature " << sf << ", orientation " << int(orientation);
    }
  }
  // Users' scalar features: declared a metric (balls) or not (positions only), the same answers.
  struct Item {
    double x, y, f;
  };
  std::vector<Item> user;
  for (int i = 0; i < 4000; ++i) user.push_back({u(rng) * 50, u(rng) * 40, i % 5 == 0 ? u(rng) : 0.9});
  auto position = [](const Item& i) { return K::Point_2(i.x, i.y); };
  auto value = [](const Item& i) { return i.f; };
  const auto declared = make_property_map_traits<K, 2, Item>(position, value, Declared_metric());
  const auto undeclared = make_property_map_traits<K, 2, Item>(position, value, Undeclared_metric());
  static_assert(decltype(declared)::feature_metric_error == 0, "declared through metric_error");
  static_assert(decltype(undeclared)::feature_metric_error == -1, "not declared");
  std::vector<std::size_t> user_at;
  for (std::size_t k = 0; k < 600; ++k) user_at.push_back(k * 5);  // features all in [0, 1): far from 0.9
  const auto s1 = sites_at_items(user, user_at, declared);
  const auto s2 = sites_at_items(user, user_at, undeclared);
  Discrete_lloyd_options<2> o;
  o.sigma_feature = 0.1;
  o.form = Bilateral_form::exponential;
  const auto want = generic_brute_force(user, s1, Exponential_bilateral_metric{1, 0.1}, declared);
  EXPECT_EQ(bilateral_voronoi_assignment(user, s1, o, declared).site, want);
  EXPECT_EQ(bilateral_voronoi_assignment(user, s2, o, undeclared).site, want);
}

TEST(Discrete_lloyd, FeatureBallsOfFloatKernelsAndSubnormalSquares) {
  // From a review: two layouts where the ball bound exceeded a site's computed feature distance and ruled out
  // the node of the brute-force winner (O, the last site), behind 1019 distractors so that the search runs
  // past 64 nodes. (1) Pixels of a float kernel: FT(s) / FT(65025) rounds to 24 bits, so the ready traits do
  // not declare a metric there. (2) Users' features whose squared differences are subnormal (sigma_feature
  // 1e-150, differences of 1e-162): they round by an absolute amount, which the searches' 2^-1000 covers.
  using KF = CGAL::Simple_cartesian<float>;
  using Float_grey = Pixel_traits<Grey_pixel, KF>;
  static_assert(Float_grey::feature_metric_error == -1, "a float kernel declares no metric");
  static_assert(Point_with_normal_traits<KF>::feature_metric_error == -1,
                "a float kernel declares no metric");
  static_assert(Grey_pixel_traits::feature_metric_error == 0, "a double kernel declares one");
  {
    std::vector<Grey_pixel> items{{50, 0, 0}};  // centre (50.5, 0.5), grey 0
    const Float_grey::Compute_feature_distance fd;
    const double sf = 1e-3, d_o = CGAL::to_double(fd({0}, {1}));
    std::vector<Bilateral_site<Float_grey>> sites;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    for (int j = 0; j < 1019; ++j) sites.push_back({{47.5 + 2.9 * u(rng), 30.5}, {255}});
    const double x_w = 50.5 + std::sqrt(4.5 * 4.5 + 900 + d_o / (sf * sf) + 0.6e-6 - 900);
    sites.push_back({{x_w, 30.5}, {0}});                               // W: a little worse than O
    for (int c = 0; c < 3; ++c) sites.push_back({{45.9, 30.5}, {4}});  // P, the first site of O's leaf
    sites.push_back({{46.0, 30.5}, {1}});                              // O
    Discrete_lloyd_options<2> o;
    o.sigma_feature = sf;
    const auto want = generic_brute_force(items, sites, Gaussian_bilateral_metric{1, sf}, Float_grey());
    EXPECT_EQ(want, std::vector<std::uint32_t>{1023});
    EXPECT_EQ(bilateral_voronoi_assignment(items, sites, o, Float_grey()).site, want);
  }
  {
    struct Item {
      double x, y, z, f;
    };
    using K = test::K;
    auto position = [](const Item& i) { return K::Point_3(i.x, i.y, i.z); };
    auto value = [](const Item& i) { return i.f; };
    const auto traits = make_property_map_traits<K, 3, Item>(position, value, Declared_metric());
    using T = std::decay_t<decltype(traits)>;
    std::vector<Item> items{{0, 0, 0, 0}};
    std::vector<Bilateral_site<T>> sites;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    for (int j = 0; j < 1019; ++j)
      sites.push_back({{(u(rng) - 0.5) * 5e-12, (u(rng) - 0.5) * 1e-14, (u(rng) - 0.5) * 1e-14}, 1e-150});
    sites.push_back({{-std::sqrt(5e-24), 0, 0}, 3.85e-162});                                // W
    for (int c = 0; c < 3; ++c) sites.push_back({{3e-12, 0, 0}, 6.5961012615241331e-162});  // P
    sites.push_back({{3e-12 + 1e-15, 0, 0}, 3.3417273970192714e-162});                      // O
    Discrete_lloyd_options<3> o;
    o.sigma_feature = 1e-150;
    o.intrinsic_dimension = 2;
    const auto want = generic_brute_force(items, sites, Gaussian_bilateral_metric{1, 1e-150}, traits);
    EXPECT_EQ(want, std::vector<std::uint32_t>{1023});
    EXPECT_EQ(bilateral_voronoi_assignment(items, sites, o, traits).site, want);
  }
}

TEST(Discrete_lloyd, MetricsExceedOnlyWhatTheyExceed) {
  // exceeds(a, b, slack), the bound of a node from its lower bounds a and b: true only when xi(a, b), as
  // computed, is above slack, so that every pair at least as far is too; at slack = xi(a, b) false, a
  // hundredth below true; over squares of 1e-300 to 1e300 (the Gaussian form compares squares while the
  // slack's keeps its digits, else xi itself).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-300, 300), v(0, 1);
  for (int t = 0; t < 20000; ++t) {
    const double a = t % 10 == 0 ? 0.0 : std::pow(10.0, u(rng)), b = t % 7 == 0 ? 0.0 : v(rng);
    const double sp = std::pow(10.0, u(rng) / 3),
                 sf = t % 13 == 0 ? std::numeric_limits<double>::infinity() : 0.01 + v(rng);
    const Gaussian_bilateral_metric g{sp, sf};
    const Exponential_bilateral_metric e{sp, sf};
    for (const bool gaussian : {true, false}) {
      const double xi = gaussian ? g(a, b) : e(a, b);
      auto exceeds = [&](double slack) { return gaussian ? g.exceeds(a, b, slack) : e.exceeds(a, b, slack); };
      if (!(xi > 0 && std::isfinite(xi))) continue;
      const char* form = gaussian ? " gaussian" : " exponential";
      EXPECT_FALSE(exceeds(xi)) << "a " << a << ", b " << b << form;
      EXPECT_FALSE(exceeds(std::nextafter(xi, 2 * xi))) << "a " << a << ", b " << b << form;
      EXPECT_TRUE(exceeds(0.99 * xi)) << "a " << a << ", b " << b << form;
    }
  }
}

TEST(Discrete_lloyd, TorusRelaxationTilesAndIsTranslationInvariant) {
  const int w = 48, h = 40;
  const auto px = step_image(w, h, 0, 0, 1);  // uniform
  const auto start = random_sites(80, w, h, 6);
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  o.max_iterations = 40;
  const double d_hex = std::sqrt(2.0 * w * h / (std::sqrt(3.0) * 80));
  auto spacing = [&](const std::vector<std::array<double, 2>>& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j)
        best = std::min(best, torus_squared(p[i][0], p[i][1], p[j], w, h));
    return std::sqrt(best);
  };
  std::vector<double> reported, measured;
  o.on_iteration = [&](Lloyd_iteration_statistics& s, const std::vector<std::array<double, 2>>& p) {
    reported.push_back(s.relative_radius);
    measured.push_back(spacing(p) / d_hex);
    for (const auto& x : p)
      EXPECT_TRUE(x[0] >= 0 && x[0] < w && x[1] >= 0 && x[1] < h) << x[0] << ", " << x[1];
    return true;
  };
  const auto r = discrete_bilateral_lloyd(px, start, o);
  ASSERT_EQ(reported.size(), 40u);
  for (std::size_t i = 1; i < reported.size(); ++i)
    EXPECT_NEAR(reported[i], measured[i - 1], 1e-12) << "iteration " << i + 1;
  EXPECT_LT(reported.front(), 0.2);
  EXPECT_GT(measured.back(), 0.7);
  // Not pushed off the edges: the band within d_hex / 4 = 1.32 of an edge holds about its share of the sites
  // (11.7 % of the area, 9.4 sites); Lloyd in the box keeps it nearly empty.
  auto band = [&](const Discrete_lloyd_result<Grey_pixel_traits>& x) {
    std::size_t in = 0;
    for (const auto& s : x.sites)
      in += std::min({s.position[0], s.position[1], w - s.position[0], h - s.position[1]}) < d_hex / 4;
    return in;
  };
  EXPECT_GE(band(r), 4u);
  Discrete_lloyd_options<2> plain;
  plain.max_iterations = 40;
  EXPECT_LE(band(discrete_bilateral_lloyd(px, start, plain)), 1u);
  // The items each site ends nearest to, on the torus.
  for (std::size_t j = 0; j < r.sites.size(); ++j) {
    const auto& p = r.sites[j].position;
    std::size_t best = 0;
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < px.size(); ++i) {
      const double e = torus_squared(px[i].column + 0.5, px[i].row + 0.5, p, w, h);
      if (e < d) {
        d = e;
        best = i;
      }
    }
    EXPECT_EQ(r.items[j], best) << "site " << j;
  }
  // A picture rolled by (16, 8) with the sites moved along: the sites move along, one step after another.
  const auto bilateral_px = step_image(w, h, 20, 0, 1);
  std::vector<std::uint8_t> rolled_values(px.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      rolled_values[std::size_t(((y + 8) % h) * w + (x + 16) % w)] =
          bilateral_px[std::size_t(y * w + x)].value;
  const auto rolled = image_pixels<Grey_pixel>(w, h, rolled_values);
  auto moved = start;
  for (auto& s : moved)
    s.position = {std::fmod(s.position[0] + 16, double(w)), std::fmod(s.position[1] + 8, double(h))};
  Discrete_lloyd_options<2> b;
  b.periodic = true;
  b.sigma_position = d_hex;
  b.sigma_feature = 0.3;
  b.max_iterations = 5;
  const auto one = discrete_bilateral_lloyd(bilateral_px, start, b),
             two = discrete_bilateral_lloyd(rolled, moved, b);
  for (std::size_t j = 0; j < start.size(); ++j) {
    EXPECT_NEAR(std::fmod(one.sites[j].position[0] + 16, double(w)), two.sites[j].position[0], 1e-9) << j;
    EXPECT_NEAR(std::fmod(one.sites[j].position[1] + 8, double(h)), two.sites[j].position[1], 1e-9) << j;
    EXPECT_EQ(one.sites[j].feature, two.sites[j].feature);
  }
  // Bit for bit the same again.
  o.on_iteration = nullptr;
  const auto again = discrete_bilateral_lloyd(px, start, o);
  for (std::size_t j = 0; j < r.sites.size(); ++j) EXPECT_EQ(again.sites[j].position, r.sites[j].position);
}

TEST(Discrete_lloyd, TorusNearestItemsAndSpacingLieAcrossTheFaces) {
  // On the torus [-1, 11) x [-1, 8) of irregular_pixels() `items` holds the pixel nearest each site (brute
  // force, ties to the lowest index), often across a face.
  const std::vector<Grey_pixel> px = test::irregular_pixels();
  std::mt19937_64 rng(4);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Site> sites(300);
  for (auto& s : sites) s.position = {-13 + 38 * u(), -10 + 28 * u()};
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  o.max_iterations = 0;  // the sites as given, and their nearest items
  const auto r = discrete_bilateral_lloyd(px, sites, o);
  std::size_t across = 0;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const std::array<double, 2> p{sites[j].position[0] + 1, sites[j].position[1] + 1};  // the box from 0
    std::size_t best = 0, plain = 0;
    double best_d = std::numeric_limits<double>::infinity(), plain_d = best_d;
    std::array<double, 2> w{std::fmod(std::fmod(p[0], 12.0) + 12, 12.0),
                            std::fmod(std::fmod(p[1], 9.0) + 9, 9.0)};
    for (std::size_t i = 0; i < px.size(); ++i) {
      const double x = px[i].column + 1.5, y = px[i].row + 1.5;
      const double d = torus_squared(x, y, p, 12, 9), e = (x - w[0]) * (x - w[0]) + (y - w[1]) * (y - w[1]);
      if (d < best_d) {
        best_d = d;
        best = i;
      }
      if (e < plain_d) {
        plain_d = e;
        plain = i;
      }
    }
    EXPECT_EQ(r.items[j], best) << "site " << j;
    across += best != plain;
  }
  EXPECT_GT(across, 30u);  // the check tells
  // Two sites 1 apart across the face x = 0 of a 48 x 40 picture: the relative radius of the first
  // iteration is that distance over the packing distance of 2 sites.
  const auto flat = step_image(48, 40, 0, 0, 1);
  Discrete_lloyd_options<2> one;
  one.periodic = true;
  one.max_iterations = 1;
  const auto q = discrete_bilateral_lloyd(flat, std::vector<Site>{{{0.5, 5}, {40}}, {{47.5, 5}, {40}}}, one);
  ASSERT_EQ(q.history.size(), 1u);
  EXPECT_NEAR(q.history[0].relative_radius, 1 / std::sqrt(2 * 48.0 * 40 / (std::sqrt(3.0) * 2)), 1e-12);
}

TEST(Discrete_lloyd, TorusTiesGoToTheLowestSite) {
  // On an 8 x 8 picture the pixel (0.5, 4.5) is 1 from site 1 at (1.5, 4.5) and 1 from site 0 at (7.5, 4.5)
  // across the face x = 0 (its image at -0.5): it goes to site 0, as every exact tie goes to the lowest site
  // whichever image wins it. Pixel (4.5, 4.5) is 3 from both, directly.
  const auto px = step_image(8, 8, 0, 0, 1);
  const std::vector<Site> sites{{{7.5, 4.5}, {40}}, {{1.5, 4.5}, {40}}};
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  const auto a = bilateral_voronoi_assignment(px, sites, o);
  EXPECT_EQ(a.site[4 * 8 + 0], 0u);
  EXPECT_EQ(a.site[4 * 8 + 4], 0u);
  EXPECT_EQ(a.site[4 * 8 + 1], 1u);
  EXPECT_EQ(a.site[4 * 8 + 7], 0u);
  // The other way round the ties go to the other site: the lowest index, not the nearest image.
  const std::vector<Site> swapped{sites[1], sites[0]};
  const auto b = bilateral_voronoi_assignment(px, swapped, o);
  EXPECT_EQ(b.site[4 * 8 + 0], 0u);
  EXPECT_EQ(b.site[4 * 8 + 4], 0u);
  EXPECT_EQ(b.site[4 * 8 + 7], 1u);
}

TEST(Discrete_lloyd, TorusDegenerateAndRefused) {
  // Two sites a whole period apart are one position on the torus: they move apart as copies do.
  const auto row = step_image(30, 1, 0, 0, 1);
  std::vector<Site> copies{{{3.0, 0.5}, {40}}, {{33.0, 0.5}, {40}}};
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  const auto c = discrete_bilateral_lloyd(row, copies, o);
  EXPECT_EQ(c.status, Status::success);
  EXPECT_NEAR(std::abs(c.sites[0].position[0] - c.sites[1].position[0]), 15.0, 1e-9);
  // One pixel: a box of width 0 does not wrap, the sites stay where they are.
  const auto dot = step_image(1, 1, 0, 0, 1);
  const auto d = discrete_bilateral_lloyd(dot, std::vector<Site>{{{0.5, 0.5}, {40}}, {{7.0, 3.0}, {40}}}, o);
  EXPECT_EQ(d.sites[1].position, (std::array<double, 2>{7.0, 3.0}));
  // Surfaces do not fill their box.
  std::vector<test::Point_3> plane;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) plane.emplace_back(i, j, 0);
  Discrete_lloyd_options<3> o3;
  o3.periodic = true;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        discrete_bilateral_lloyd(plane, std::vector<std::size_t>{0, 5}, o3);
      },
      "periodic needs items that fill their box: 2D items, or 3D items of intrinsic dimension 3 (estimated "
      "2)"));
  o3.intrinsic_dimension = 2;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        discrete_bilateral_lloyd(plane, std::vector<std::size_t>{0, 5}, o3);
      },
      "(intrinsic_dimension 2)"));
  o3.intrinsic_dimension = 0;
  // A volume does: 8 sites in a 6 x 6 x 6 lattice relax on its torus [-0.5, 5.5)^3.
  std::vector<test::Point_3> cube;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) cube.emplace_back(i, j, k);
  // intrinsic_dimension 0: estimated as 3, the same as given.
  const auto v0 =
      discrete_bilateral_lloyd(cube, std::vector<std::size_t>{0, 43, 86, 129, 172, 215, 50, 101}, o3);
  o3.intrinsic_dimension = 3;
  const auto v =
      discrete_bilateral_lloyd(cube, std::vector<std::size_t>{0, 43, 86, 129, 172, 215, 50, 101}, o3);
  EXPECT_EQ(v.status, Status::success);
  for (const auto& s : v.sites)
    for (const double x : s.position) EXPECT_TRUE(x >= -0.5 && x < 5.5) << x;
  for (std::size_t j = 0; j < v.sites.size(); ++j) EXPECT_EQ(v0.sites[j].position, v.sites[j].position);
  EXPECT_GT(v.history.back().relative_radius, v.history.front().relative_radius + 0.2)
      << v.history.front().relative_radius;
}

TEST(Discrete_lloyd, ItemSpacingPerAxisOfALattice) {
  // A full lattice has its own step along each axis; anything else keeps the one spacing estimated for all.
  using Point_2 = test::Point_2;
  using Point_3 = test::Point_3;
  auto spacing2 = [](const std::vector<Point_2>& items) {
    return sampling::internal::Item_domain<Point_traits<Point_2>>(items, Point_traits<Point_2>(), 0, "test",
                                                                  false)
        .axis_spacing();
  };
  auto single2 = [](const std::vector<Point_2>& items) {
    return sampling::internal::Item_domain<Point_traits<Point_2>>(items, Point_traits<Point_2>(), 0, "test",
                                                                  false)
        .grid_spacing();
  };
  std::vector<Point_2> lattice;  // 10 x 7, steps 1 x 2, listed column by column
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 7; ++j) lattice.emplace_back(0.5 + i, 1 + 2 * j);
  EXPECT_EQ(spacing2(lattice), (std::array<double, 2>{1.0, 2.0}));
  const double h = single2(lattice);  // (9 + h)(12 + h) = 70 h^2
  EXPECT_NEAR(h, (21 + std::sqrt(21.0 * 21 + 4 * 69 * 108)) / (2 * 69), 1e-12);
  // Not a lattice: one item moved off it, one item missing (a copy in its place), one row of 10.
  auto off = lattice;
  off[17] = Point_2(off[17].x() + 0.25, off[17].y());
  EXPECT_EQ(spacing2(off), (std::array<double, 2>{single2(off), single2(off)}));
  auto copy = lattice;
  copy[17] = copy[18];
  EXPECT_EQ(spacing2(copy), (std::array<double, 2>{single2(copy), single2(copy)}));
  auto uneven = lattice;  // the last column 1.5 from its neighbour: 10 x 7 coordinates, not equally spaced
  for (auto& p : uneven)
    if (p.x() == 9.5) p = Point_2(10, p.y());
  EXPECT_EQ(spacing2(uneven), (std::array<double, 2>{single2(uneven), single2(uneven)}));
  std::vector<Point_2> row;
  for (int i = 0; i < 10; ++i) row.emplace_back(3 * i, 4);
  EXPECT_EQ(spacing2(row), (std::array<double, 2>{3.0, 3.0}));
  // A square lattice 0.1 apart keeps the single spacing bit for bit, whatever its steps' last bits (here
  // 1.2000000000000002 / 12 = 0.10000000000000002 along x, 0.8 / 8 = 0.1 along y).
  std::vector<Point_2> fine;
  for (int i = 0; i < 13; ++i)
    for (int j = 0; j < 9; ++j) fine.emplace_back(0.1 * i, 0.1 * j);
  EXPECT_EQ(spacing2(fine), (std::array<double, 2>{single2(fine), single2(fine)}));
  // 3D: a 4 x 5 x 3 lattice of steps 1, 2, 3.
  std::vector<Point_3> block;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 4; ++i) block.emplace_back(i, 2 * j, 3 * k);
  EXPECT_EQ((sampling::internal::Item_domain<Point_traits<Point_3>>(block, Point_traits<Point_3>(), 0, "test",
                                                                    false)
                 .axis_spacing()),
            (std::array<double, 3>{1.0, 2.0, 3.0}));
}

// Brute force on the torus [0, P0) x [0, P1) for items without features: each item's site (nearest image,
// ties to the lowest index) and each site's centroid of its items at their images nearest it, modulo P.
struct Point_torus_oracle {
  std::vector<std::uint32_t> site;
  std::vector<std::array<double, 2>> centroid;
};
Point_torus_oracle point_torus_brute_force(const std::vector<test::Point_2>& items,
                                           const std::vector<std::array<double, 2>>& sites, double p0,
                                           double p1) {
  Point_torus_oracle o;
  std::vector<std::array<double, 2>> sum(sites.size(), {0.0, 0.0});
  std::vector<double> count(sites.size(), 0.0);
  for (const auto& item : items) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = 0;
    for (std::size_t j = 0; j < sites.size(); ++j) {
      const double d = torus_squared(item.x(), item.y(), sites[j], p0, p1);
      if (d < best) {
        best = d;
        arg = static_cast<std::uint32_t>(j);
      }
    }
    o.site.push_back(arg);
    std::array<double, 2> shift{};
    torus_squared(item.x(), item.y(), sites[arg], p0, p1, &shift);
    sum[arg][0] += item.x() - shift[0];
    sum[arg][1] += item.y() - shift[1];
    count[arg] += 1;
  }
  for (std::size_t j = 0; j < sites.size(); ++j)
    o.centroid.push_back(count[j] > 0 ? std::array<double, 2>{sum[j][0] / count[j], sum[j][1] / count[j]}
                                      : sites[j]);
  return o;
}

// n featureless sites uniform in [x0, x0 + w) x [y0, y0 + h), and their positions.
template <class Point_site>
std::vector<Point_site> random_point_sites(std::size_t n, double x0, double y0, double w, double h,
                                           std::mt19937_64& rng, std::vector<std::array<double, 2>>& where) {
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Point_site> sites(n);
  where.clear();
  for (auto& s : sites) {
    const double x = x0 + w * u();
    s.position = {x, y0 + h * u()};
    where.push_back(s.position);
  }
  return sites;
}

// The distance on the torus of periods p0, p1 between two positions given anywhere.
double torus_gap(const std::array<double, 2>& a, const std::array<double, 2>& b, double p0, double p1) {
  return std::sqrt(torus_squared(a[0], a[1], b, p0, p1));
}

TEST(Discrete_lloyd, TorusOfAnAnisotropicLatticeIsItsCells) {
  // A 10 x 7 lattice of steps 1 x 2 at (0.5 + i, 1 + 2 j): the torus [0, 10) x [0, 14), the box of its
  // cells (one spacing estimated for both axes gave periods 10.41 x 13.41, and the lattice did not tile).
  using Point_2 = test::Point_2;
  using Point_site = Bilateral_site<Point_traits<Point_2>>;
  std::vector<Point_2> items;
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 10; ++i) items.emplace_back(0.5 + i, 1 + 2 * j);
  std::mt19937_64 rng(9);
  std::vector<std::array<double, 2>> where;
  const auto sites = random_point_sites<Point_site>(9, -3, -4, 16, 22, rng, where);
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  const auto want = point_torus_brute_force(items, where, 10, 14);
  EXPECT_EQ(bilateral_voronoi_assignment(items, sites, o).site, want.site);
  const auto step = discrete_lloyd_step(items, sites, o);
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const auto& p = step.sites[j].position;
    EXPECT_TRUE(p[0] >= 0 && p[0] < 10 && p[1] >= 0 && p[1] < 14) << p[0] << ", " << p[1];
    EXPECT_LT(torus_gap(p, want.centroid[j], 10, 14), 1e-9) << "site " << j;
  }
  // The relative radius is measured on that torus, against its area 140.
  o.max_iterations = 1;
  const std::vector<Point_site> pair{{{0.5, 1}, {}}, {{9.5, 13}, {}}};  // 1 x 2 apart across the corner
  const auto r = discrete_bilateral_lloyd(items, pair, o);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_NEAR(r.history[0].relative_radius, std::sqrt(5.0) / std::sqrt(2 * 140.0 / (std::sqrt(3.0) * 2)),
              1e-12);
  // Without the torus too: the pair 1 x 2 apart directly, against the area of the cells, 140.
  Discrete_lloyd_options<2> plain;
  plain.max_iterations = 1;
  const std::vector<Point_site> near{{{0.5, 1}, {}}, {{1.5, 3}, {}}};
  const auto q = discrete_bilateral_lloyd(items, near, plain);
  ASSERT_EQ(q.history.size(), 1u);
  EXPECT_NEAR(q.history[0].relative_radius, std::sqrt(5.0) / std::sqrt(2 * 140.0 / (std::sqrt(3.0) * 2)),
              1e-12);
}

TEST(Discrete_lloyd, TorusOfAGivenPeriod) {
  // 150 white-noise items in [0, 1)^2 on the torus of periods 1 x 1 (the noise's own), and on a larger one,
  // 1.5 x 2: against brute force, whatever the origin (the box is centred on the items').
  using Point_2 = test::Point_2;
  using Point_site = Bilateral_site<Point_traits<Point_2>>;
  const std::vector<Point_2> items = test::white_noise(150, 3);
  double lo[2] = {1, 1}, hi[2] = {0, 0};
  for (const auto& p : items)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  std::mt19937_64 rng(5);
  for (const std::array<double, 2> period : {std::array<double, 2>{1, 1}, std::array<double, 2>{1.5, 2}}) {
    std::vector<std::array<double, 2>> where;
    const auto sites = random_point_sites<Point_site>(12, -1, -1, 3, 3, rng, where);
    Discrete_lloyd_options<2> o;
    o.periodic = true;
    o.period = {period[0], period[1]};
    const auto want = point_torus_brute_force(items, where, period[0], period[1]);
    EXPECT_EQ(bilateral_voronoi_assignment(items, sites, o).site, want.site) << period[0];
    const auto step = discrete_lloyd_step(items, sites, o);
    for (std::size_t j = 0; j < sites.size(); ++j) {
      const auto& p = step.sites[j].position;
      for (int k = 0; k < 2; ++k) {
        const double from = lo[k] - (period[k] - (hi[k] - lo[k])) / 2;
        EXPECT_TRUE(p[k] >= from && p[k] < from + period[k]) << p[k] << " axis " << k;
      }
      EXPECT_LT(torus_gap(p, want.centroid[j], period[0], period[1]), 1e-9) << "site " << j;
    }
    // The relative radius against the torus's area.
    o.max_iterations = 1;
    const auto r = discrete_bilateral_lloyd(items, sites, o);
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < where.size(); ++i)
      for (std::size_t j = i + 1; j < where.size(); ++j)
        shortest = std::min(shortest, torus_gap(where[i], where[j], period[0], period[1]));
    ASSERT_EQ(r.history.size(), 1u);
    EXPECT_NEAR(r.history[0].relative_radius,
                shortest / std::sqrt(2 * period[0] * period[1] / (std::sqrt(3.0) * 12)), 1e-12);
  }
  // A row of items has no extent across it; a given period wraps that axis too: a site at y = 3 is at
  // y = 1 on the torus of period 4, which is [-2, 2) across the row at y = 0.
  std::vector<Point_2> row;
  for (int i = 0; i < 10; ++i) row.emplace_back(i, 0);
  Discrete_lloyd_options<2> o;
  o.periodic = true;
  o.period = {10, 4};
  const auto s = discrete_lloyd_step(row, std::vector<Point_site>{{{4.2, 3}, {}}}, o);
  EXPECT_NEAR(s.sites[0].position[0], 4.5, 1e-12);  // the centroid of all ten, each nearest as it is
  EXPECT_EQ(s.sites[0].position[1], 0.0);
  EXPECT_NEAR(s.max_move, std::sqrt(0.09 + 1.0), 1e-12);  // from (4.2, -1) on the torus
  // Refused: without periodic, of the wrong length, out of range, shorter than the items' extent.
  auto refused = [&](std::vector<double> period, bool periodic, const std::string& message) {
    Discrete_lloyd_options<2> b;
    b.periodic = periodic;
    b.period = std::move(period);
    return test::throws_with<std::invalid_argument>(
        [&] {
          discrete_bilateral_lloyd(row, std::vector<std::size_t>{0, 5}, b);
        },
        message);
  };
  EXPECT_TRUE(refused({10, 4}, false, "period is given (2 values) but periodic is false"));
  EXPECT_TRUE(refused({10}, true, "period has 1 values for positions of dimension 2"));
  EXPECT_TRUE(refused({10, 0}, true, "period[1] must be in [1e-150, 1e150], got 0"));
  EXPECT_TRUE(
      refused({8.5, 4}, true,
              "period[0] = 8.5 is shorter than the items' extent along axis 0 (9): the items must fit "
              "in one period"));
  EXPECT_TRUE(refused({10, 1e101}, true, "period[1] = 1e+101 puts the torus's faces beyond +-1e100"));
  Discrete_lloyd_options<2> scale;
  scale.periodic = true;
  scale.period = {10, 1e100};
  scale.sigma_position = 1e-50;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        discrete_bilateral_lloyd(row, std::vector<std::size_t>{0, 5}, scale);
      },
      "sigma_position (1e-50) is too small for positions spanning 1e+100"));
  // No items: the period is still checked.
  Discrete_lloyd_options<2> lone;
  lone.period = {1, 1};
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        discrete_bilateral_lloyd(std::vector<Point_2>{}, std::vector<Point_site>{{{0, 0}, {}}}, lone);
      },
      "period is given (2 values) but periodic is false"));
  // A period of the extent itself: the end items (9, 0) and (0, 0) are one point of the torus [0, 9) x
  // [-2, 2), the first one (9, 0) nearest to a site there; a site snapped to it comes back in the box, at 0.
  const std::vector<Point_2> back(row.rbegin(), row.rend());
  Discrete_lloyd_options<2> tight;
  tight.periodic = true;
  tight.period = {9, 4};
  tight.max_iterations = 0;
  EXPECT_EQ(discrete_bilateral_lloyd(back, std::vector<Point_site>{{{0, 0}, {}}}, tight).items,
            std::vector<std::size_t>{0});
  tight.update = Site_update::snap_to_item;
  std::vector<Point_site> ends{{{8.9, 0.5}, {}}, {{3.3, -0.2}, {}}, {{5.8, 1}, {}}};
  for (int step = 0; step < 3; ++step) {
    ends = discrete_lloyd_step(back, ends, tight).sites;
    for (const auto& site : ends) {
      EXPECT_TRUE(site.position[0] >= 0 && site.position[0] < 9) << site.position[0];
      EXPECT_EQ(site.position[1], 0.0);
    }
  }
}

}  // namespace
