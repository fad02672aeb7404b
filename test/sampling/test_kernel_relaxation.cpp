// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Kernel relaxation: the closed-form gradient against finite differences (box ghosts, bilateral features,
// adaptive scales), monotone energy and rising relative radius from white noise and from darts, the box
// boundary, features following the positions, adaptive density, snapping to items in 3D, coincident and
// degenerate starts, determinism, bad input.
#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/image_domain.h>
#include <FeatureRecon/sampling/kernel_relaxation.h>

#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sampling/sampling_test_utilities.h"

namespace {
using namespace FeatureRecon;
using namespace FeatureRecon::sampling;
using Site = Bilateral_site<Grey_pixel_traits>;

std::vector<Grey_pixel> image(int w, int h, const std::function<int(int, int)>& value) {
  std::vector<std::uint8_t> v(std::size_t(w * h));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) v[std::size_t(r * w + c)] = static_cast<std::uint8_t>(value(c, r));
  return image_pixels<Grey_pixel>(w, h, v);
}

std::vector<Site> random_sites(std::size_t n, const std::vector<Grey_pixel>& px, int w, int h,
                               unsigned seed) {
  std::mt19937_64 rng(seed);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Site> s(n);
  for (auto& x : s) {
    x.position = {u() * w, u() * h};
    const int c = std::min(w - 1, int(x.position[0])), r = std::min(h - 1, int(x.position[1]));
    x.feature = {px[std::size_t(r * w + c)].value};
  }
  return s;
}

// Central differences of kernel_energy() against its gradient, every coordinate of every site.
template <class Items, class Sites, class Options>
void expect_gradient(const Items& items, const Sites& sites, const Options& o) {
  const auto e = kernel_energy(items, sites, o);
  ASSERT_EQ(e.gradient.size(), sites.size());
  ASSERT_GT(e.pairs, sites.size());
  double largest = 0;
  for (const auto& g : e.gradient)
    for (const double x : g) largest = std::max(largest, std::abs(x));
  const double h = 1e-6;
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (std::size_t k = 0; k < sites[i].position.size(); ++k) {
      auto plus = sites, minus = sites;
      plus[i].position[k] += h;
      minus[i].position[k] -= h;
      const double fd =
          (kernel_energy(items, plus, o).energy - kernel_energy(items, minus, o).energy) / (2 * h);
      EXPECT_NEAR(e.gradient[i][k], fd, 1e-6 * largest + 1e-12) << "site " << i << " coordinate " << k;
    }
}

TEST(Kernel_relaxation, GradientMatchesFiniteDifferences) {
  const auto px = image(24, 20, [](int c, int r) { return c < 11 ? 30 : 200 + (r % 3); });
  const auto sites = random_sites(25, px, 24, 20, 3);
  Kernel_relaxation_options<2> o;
  o.kernel_width = 4.0;  // wide: many pairs and ghosts within the cut-off
  o.cutoff = 50;         // nothing cut: the energy is smooth
  expect_gradient(px, sites, o);
  o.sigma_feature = 0.3;  // bilateral: features held fixed
  expect_gradient(px, sites, o);
  o.sigma_position = 2;
  o.kernel_width = 2.0;
  o.density.assign(px.size(), 1.0);
  for (std::size_t i = 0; i < px.size(); ++i)
    o.density[i] = px[i].value < 100 ? 4.0 : 1.0;  // adaptive scales
  expect_gradient(px, sites, o);
  // Ghosts count: a single site near a face feels its mirror image.
  Kernel_relaxation_options<2> one;
  one.kernel_width = 3;
  const std::vector<Site> lone{{{1.0, 10.0}, {30}}, {{20.0, 10.0}, {30}}};
  const auto e = kernel_energy(px, lone, one);
  // Site 0 at x = 1: its ghost across x = 0 at distance 2; site 1 at x = 20, ghost across x = 24 at distance
  // 8 (within 3 * 3 = 9); the pair itself is 19 apart (cut off at 9); y faces are 10 away (cut off).
  EXPECT_NEAR(e.energy, (std::exp(-4.0 / 9) + std::exp(-64.0 / 9) - 2 * std::exp(-9.0)) / 2, 1e-15);
  EXPECT_EQ(e.pairs, 2u);
  EXPECT_LT(e.gradient[0][0], 0);  // the energy falls as site 0 moves away from the face at x = 0
  EXPECT_GT(e.gradient[1][0], 0);  // and as site 1 moves away from the face at x = 24
  EXPECT_EQ(e.gradient[0][1], 0.0);
}

TEST(Kernel_relaxation, EnergyFallsAndSitesSpreadFromWhiteNoise) {
  const auto px = image(64, 64, [](int, int) { return 128; });
  const auto start = random_sites(150, px, 64, 64, 7);
  Kernel_relaxation_options<2> o;
  o.max_iterations = 60;
  o.energy_tolerance = 0;
  const auto r = kernel_relaxation(px, start, o);
  ASSERT_GE(r.history.size(), 30u);
  for (std::size_t i = 1; i < r.history.size(); ++i)
    EXPECT_LT(r.history[i].energy, r.history[i - 1].energy) << "iteration " << i + 1;
  EXPECT_LT(r.history.front().relative_radius, 0.2);
  Kernel_relaxation_options<2> probe = o;
  const double final_energy = kernel_energy(px, r.sites, probe).energy;
  EXPECT_LT(final_energy, 0.5 * r.history.front().energy);  // white noise has many close pairs
  // Spread: the relative radius of the final sites.
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.sites.size(); ++i)
    for (std::size_t j = i + 1; j < r.sites.size(); ++j) {
      const double dx = r.sites[i].position[0] - r.sites[j].position[0];
      const double dy = r.sites[i].position[1] - r.sites[j].position[1];
      dmin = std::min(dmin, std::sqrt(dx * dx + dy * dy));
    }
  const double d_hex = std::sqrt(2 * 64.0 * 64.0 / (std::sqrt(3.0) * 150));
  EXPECT_GT(dmin / d_hex, 0.6);
  // Inside the box [0, 64]^2, and not piled up on its faces: the band within d_hex / 4 of a face holds about
  // its share of the area (~3%), far from all sites.
  std::size_t band = 0;
  for (const auto& s : r.sites) {
    for (const double x : s.position) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 64.0);
    }
    const double m = std::min({s.position[0], s.position[1], 64 - s.position[0], 64 - s.position[1]});
    band += m < d_hex / 4;
  }
  EXPECT_LE(band, 15u);
}

TEST(Kernel_relaxation, RelaxesDartThrowing) {
  const auto px = image(80, 60, [](int, int) { return 90; });
  std::vector<std::size_t> start;
  Dart_throwing_count_options d;
  d.darts.seed = 5;
  bilateral_dart_throwing_count(px, 200, std::back_inserter(start), d);
  Kernel_relaxation_options<2> o;
  o.max_iterations = 40;
  std::vector<double> rho;
  o.on_iteration = [&](Lloyd_iteration_statistics& s, const std::vector<std::array<double, 2>>&) {
    rho.push_back(s.relative_radius);
    return true;
  };
  const auto r = kernel_relaxation(px, start, o);
  ASSERT_FALSE(rho.empty());
  EXPECT_EQ(r.status, Status::success);
  // Darts on pixels start around 0.5-0.7; the relaxation pushes rho up.
  EXPECT_GT(rho.back(), rho.front());
  EXPECT_GT(rho.back(), 0.8);
}

TEST(Kernel_relaxation, FeaturesFollowAndEdgesAttract) {
  // Dark left of column 30, bright right: with a small sigma_feature, pairs across the edge hardly repel.
  const auto px = image(60, 40, [](int c, int) { return c < 30 ? 20 : 235; });
  const auto start = random_sites(120, px, 60, 40, 9);
  Kernel_relaxation_options<2> o;
  o.max_iterations = 50;
  const auto euclidean = kernel_relaxation(px, start, o);
  o.sigma_feature = 0.2;
  const auto bilateral = kernel_relaxation(px, start, o);
  auto min_across = [&](const auto& sites) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& a : sites)
      for (const auto& b : sites)
        if (a.position[0] < 30 && b.position[0] >= 30)
          best = std::min(best, std::hypot(a.position[0] - b.position[0], a.position[1] - b.position[1]));
    return best;
  };
  // Pairs across the edge hardly repel, so sites crowd against it from both sides as against a free face.
  auto near_edge = [&](const auto& sites) {
    std::size_t n = 0;
    for (const auto& a : sites) n += std::abs(a.position[0] - 30) < 1.0;
    return n;
  };
  EXPECT_GE(near_edge(bilateral.sites), 2 * near_edge(euclidean.sites));       // 8 and 3 here
  EXPECT_LT(min_across(bilateral.sites), 0.85 * min_across(euclidean.sites));  // 3.1 and 4.0
  for (const auto* r : {&euclidean, &bilateral})
    for (const auto& s : r->sites) {
      const int c = std::min(59, int(s.position[0]));
      const int want = c < 30 ? 20 : 235;
      if (std::abs(s.position[0] - 30) > 1e-9) {
        EXPECT_EQ(int(s.feature[0]), want) << s.position[0];
      }
    }
}

TEST(Kernel_relaxation, DensityAdaptsTheSpacing) {
  // Density 4 on the left half, 1 on the right: the left half ends with about four times the sites.
  const auto px = image(64, 32, [](int, int) { return 0; });
  Kernel_relaxation_options<2> o;
  o.density.resize(px.size());
  for (std::size_t i = 0; i < px.size(); ++i) o.density[i] = px[i].column < 32 ? 4.0 : 1.0;
  o.max_iterations = 500;  // sites migrate slowly across the domain from white noise
  o.energy_tolerance = 0;
  const auto r = kernel_relaxation(px, random_sites(160, px, 64, 32, 21), o);
  std::size_t left = 0;
  for (const auto& s : r.sites) left += s.position[0] < 32;
  const double ratio = double(left) / double(r.sites.size() - left);
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 6.0);
}

TEST(Kernel_relaxation, DensityFinerThanTheKernelCountsByItsMean) {
  // Every other column dark: the kernel (about 4.7 pixels wide) sees a uniform half-density, so 40 sites
  // spread over the picture. With the density of the one pixel under each site the scale switched between 0.7
  // and 8 from column to column, the energy jumped from 0.23 to 150 and 24 of the 40 sites ended in the
  // corners.
  const int w = 64, h = 48;
  const auto px = image(w, h, [](int c, int) { return c % 2 == 0 ? 0 : 255; });
  Kernel_relaxation_options<2> o;
  o.density.resize(px.size());
  for (std::size_t i = 0; i < px.size(); ++i) o.density[i] = px[i].column % 2 == 0 ? 1.0 : 0.0;
  std::vector<Site> start;
  for (const auto& s : random_sites(40, px, w, h, 3)) {
    Site t = s;
    t.position[0] = 2 * std::floor(t.position[0] / 2) + 0.5;  // on a dark column
    start.push_back(t);
  }
  const auto r = kernel_relaxation(px, start, o);
  ASSERT_EQ(r.status, Status::success);
  ASSERT_FALSE(r.history.empty());
  for (const auto& s : r.history) EXPECT_LT(s.energy, 2 * r.history.front().energy) << "step " << s.iteration;
  const double d_hex = std::sqrt(2.0 * w * h / (std::sqrt(3.0) * 40));
  std::size_t cornered = 0;
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.sites.size(); ++i) {
    const auto& p = r.sites[i].position;
    cornered += std::min(p[0], w - p[0]) < d_hex / 4 && std::min(p[1], h - p[1]) < d_hex / 4;
    for (std::size_t j = i + 1; j < r.sites.size(); ++j)
      dmin = std::min(dmin, std::hypot(p[0] - r.sites[j].position[0], p[1] - r.sites[j].position[1]));
  }
  EXPECT_EQ(cornered, 0u);
  EXPECT_GT(dmin, 0.5 * d_hex);  // d_hex = 9.4
}

TEST(Kernel_relaxation, SitesOutsideTheBoxAreReflectedNotStacked) {
  // Distinct sites beyond a corner of the box come back reflected across its faces, distinct, and spread
  // (clamped they all landed on the corner point, where copies have no gradient between them, and stayed:
  // no_descent).
  const auto px = image(16, 16, [](int, int) { return 0; });
  const std::vector<Site> start{Site{{-0.2, -0.3}, {0}}, Site{{-0.4, -0.1}, {0}}, Site{{-0.6, -0.6}, {0}},
                                Site{{16.3, -0.2}, {0}}, Site{{16.1, -0.5}, {0}}};
  Kernel_relaxation_options<2> o;
  o.max_iterations = 300;
  const auto r = kernel_relaxation(px, start, o);
  ASSERT_EQ(r.status, Status::success);
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.sites.size(); ++i) {
    for (const double x : r.sites[i].position) EXPECT_TRUE(x >= 0 && x <= 16) << x;
    for (std::size_t j = i + 1; j < r.sites.size(); ++j)
      dmin = std::min(dmin, std::hypot(r.sites[i].position[0] - r.sites[j].position[0],
                                       r.sites[i].position[1] - r.sites[j].position[1]));
  }
  EXPECT_GT(dmin, 3.0);  // d_hex = 7.7 for 5 sites on 16 x 16
  // Far outside (many box widths): folded back as often as it takes, still distinct (reflected once and then
  // clamped, all five landed on the opposite corner and stopped without descent).
  std::vector<Site> far;
  for (int k = 0; k < 5; ++k) far.push_back(Site{{-100.0 - 7 * k, -100.0 - 3 * k}, {0}});
  const auto f = kernel_relaxation(px, far, o);
  ASSERT_EQ(f.status, Status::success);
  EXPECT_NE(f.stop, Lloyd_stop::no_descent);
  dmin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < f.sites.size(); ++i)
    for (std::size_t j = i + 1; j < f.sites.size(); ++j)
      dmin = std::min(dmin, std::hypot(f.sites[i].position[0] - f.sites[j].position[0],
                                       f.sites[i].position[1] - f.sites[j].position[1]));
  EXPECT_GT(dmin, 3.0);
}

TEST(Kernel_relaxation, AveragingTheDensityCanBeStopped) {
  // The density is averaged before the first step (on a large image the longest part before the steps): the
  // progress callback is asked there, and a stop returns the sites as given.
  const auto px = image(64, 64, [](int c, int) { return c % 2 == 0 ? 0 : 255; });
  Kernel_relaxation_options<2> o;
  o.density.resize(px.size());
  for (std::size_t i = 0; i < px.size(); ++i) o.density[i] = px[i].column % 2 == 0 ? 1.0 : 0.0;
  std::size_t calls = 0;
  o.progress = [&calls](double f) {
    ++calls;
    EXPECT_EQ(f, 0.0);
    return false;
  };
  const auto start = random_sites(20, px, 64, 64, 9);
  const auto r = kernel_relaxation(px, start, o);
  EXPECT_EQ(r.status, Status::interrupted);
  EXPECT_EQ(r.stop, Lloyd_stop::interrupted);
  EXPECT_EQ(calls, 1u);
  ASSERT_EQ(r.sites.size(), start.size());
  for (std::size_t i = 0; i < start.size(); ++i) EXPECT_EQ(r.sites[i].position, start[i].position);
}

TEST(Kernel_relaxation, SnapsToItemsOnSurfaces) {
  // A 40 x 40 grid of points with normals on the plane z = 0: snapped sites are distinct items.
  using K = test::K;
  std::vector<std::pair<K::Point_3, K::Vector_3>> items;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) items.push_back({K::Point_3(i, j, 0), K::Vector_3(0, 0, 1)});
  std::vector<std::size_t> start;
  for (std::size_t k = 0; k < 60; ++k) start.push_back((k * 7919) % 400);  // crowded in the first 10 rows
  start.push_back(start[0]);                                               // and one duplicate
  Kernel_relaxation_options<3> o;
  EXPECT_EQ(o.constraint, Kernel_constraint::snap_to_item);
  o.max_iterations = 80;
  const auto r = kernel_relaxation(items, start, o);
  std::set<std::array<double, 3>> distinct;
  for (const auto& s : r.sites) {
    distinct.insert(s.position);
    EXPECT_EQ(s.position[0], std::round(s.position[0]));
    EXPECT_EQ(s.position[2], 0.0);
  }
  EXPECT_EQ(distinct.size(), r.sites.size());
  ASSERT_FALSE(r.history.empty());
  EXPECT_GT(r.history.back().relative_radius, r.history.front().relative_radius);
}

TEST(Kernel_relaxation, DeterministicAndStoppingRules) {
  const auto px = image(40, 40, [](int c, int r) { return (c * 7 + r * 3) % 256; });
  const auto start = random_sites(60, px, 40, 40, 2);
  Kernel_relaxation_options<2> o;
  o.sigma_feature = 0.5;
  o.max_iterations = 20;
  o.energy_tolerance = 0;
  const auto a = kernel_relaxation(px, start, o), b = kernel_relaxation(px, start, o);
  ASSERT_EQ(a.sites.size(), b.sites.size());
  for (std::size_t i = 0; i < a.sites.size(); ++i) {
    EXPECT_EQ(a.sites[i].position, b.sites[i].position);
    EXPECT_EQ(a.sites[i].feature, b.sites[i].feature);
  }
  EXPECT_EQ(a.stop, Lloyd_stop::iteration_cap);
  EXPECT_EQ(a.history.size(), 20u);
  o.energy_tolerance = 1e-2;
  const auto t = kernel_relaxation(px, start, o);
  EXPECT_EQ(t.stop, Lloyd_stop::energy_tolerance);
  EXPECT_LT(t.history.size(), 20u);
  o.energy_tolerance = 0;
  o.move_tolerance = 0.05;
  o.max_iterations = 500;
  o.sigma_feature = std::numeric_limits<double>::infinity();  // bilateral sites may jitter as features flip
  const auto m = kernel_relaxation(px, start, o);
  EXPECT_EQ(m.stop, Lloyd_stop::move_tolerance);
  EXPECT_LE(m.history.back().max_move, 0.05);
  o.move_tolerance = 0;
  o.on_iteration = [](Lloyd_iteration_statistics& s, const std::vector<std::array<double, 2>>&) {
    return s.iteration < 3;
  };
  const auto c = kernel_relaxation(px, start, o);
  EXPECT_EQ(c.stop, Lloyd_stop::callback);
  EXPECT_EQ(c.history.size(), 3u);
  o.on_iteration = nullptr;
  o.progress = [](double f) { return f < 0.01; };
  const auto p = kernel_relaxation(px, start, o);
  EXPECT_EQ(p.stop, Lloyd_stop::interrupted);
  EXPECT_EQ(p.status, Status::interrupted);
}

TEST(Kernel_relaxation, DegenerateStarts) {
  const auto px = image(16, 16, [](int, int) { return 50; });
  Kernel_relaxation_options<2> o;
  // No items, no sites, one site: nothing to do.
  EXPECT_EQ(kernel_relaxation(std::vector<Grey_pixel>{}, random_sites(3, px, 16, 16, 1), o).status,
            Status::degenerate_input);
  EXPECT_EQ(kernel_relaxation(px, std::vector<Site>{}, o).status, Status::degenerate_input);
  const auto one = kernel_relaxation(px, random_sites(1, px, 16, 16, 1), o);
  EXPECT_EQ(one.status, Status::degenerate_input);
  EXPECT_EQ(one.sites.size(), 1u);
  // Every site at the same point: they separate (deterministically) and spread.
  std::vector<Site> same(12, Site{{8.0, 8.0}, {50}});
  o.max_iterations = 200;
  const auto r = kernel_relaxation(px, same, o);
  EXPECT_EQ(r.status, Status::success);
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.sites.size(); ++i)
    for (std::size_t j = i + 1; j < r.sites.size(); ++j)
      dmin = std::min(dmin, std::hypot(r.sites[i].position[0] - r.sites[j].position[0],
                                       r.sites[i].position[1] - r.sites[j].position[1]));
  EXPECT_GT(dmin, 2.0);  // d_hex = 4.9 for 12 sites on 16 x 16
  // A single pixel: sites collapse onto its box and stop without descent or stay.
  const auto tiny = image(1, 1, [](int, int) { return 9; });
  const auto t = kernel_relaxation(tiny, std::vector<Site>(3, Site{{0.5, 0.5}, {9}}), o);
  for (const auto& s : t.sites)
    for (const double x : s.position) EXPECT_TRUE(x >= 0 && x <= 1) << x;
  // Points in 3-D that all sit at one place (and a cloud 1e-300 wide) have no extent to relax on: degenerate
  // input with the sites unchanged (the snapped sites used to become NaN and read past the items).
  using K = test::K;
  const std::vector<K::Point_3> one_place(40, K::Point_3(1, 1, 1));
  const auto p = kernel_relaxation(one_place, std::vector<std::size_t>{0, 1, 2, 3});
  EXPECT_EQ(p.status, Status::degenerate_input);
  ASSERT_EQ(p.sites.size(), 4u);
  for (const auto& s : p.sites) EXPECT_EQ(s.position, (std::array<double, 3>{1, 1, 1}));
  std::vector<K::Point_3> speck;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) speck.emplace_back(1e-300 * i, 1e-300 * j, 0);
  const auto q = kernel_relaxation(speck, std::vector<std::size_t>{0, 31, 62, 93});
  for (const auto& s : q.sites)
    for (const double x : s.position) EXPECT_TRUE(std::isfinite(x));
}

TEST(Kernel_relaxation, BadInputNamesTheProblem) {
  const auto px = image(6, 6, [](int, int) { return 1; });
  const auto sites = random_sites(3, px, 6, 6, 1);
  Kernel_relaxation_options<2> o;
  o.kernel_width = -1;
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "kernel_width"));
  o.kernel_width = 0;
  o.cutoff = 0;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_energy(px, sites, o); }, "cutoff"));
  o.cutoff = 3;
  o.initial_step = std::nan("");
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "initial_step"));
  o.initial_step = 0.25;
  o.density.assign(36, 0.0);  // degenerate, not an error (AllZeroDensityIsDegenerateInBothRelaxations)
  EXPECT_EQ(kernel_relaxation(px, sites, o).status, Status::degenerate_input);
  o.density[4] = -2;
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "density[4]"));
  o.density.assign(7, 1.0);
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); },
                                                       "density has 7 values for 36 items"));
  o.density.clear();
  o.sigma_position = 0;
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "sigma_position"));
  o.sigma_position = 1;
  auto bad = sites;
  bad[1].position[0] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, bad, o); }, "site 1"));
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] {
        kernel_relaxation(px, std::vector<std::size_t>{0, 99}, o);
      },
      "indices[1] = 99"));
  o.energy_tolerance = std::numeric_limits<double>::infinity();  // stopped every run after two iterations
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); },
                                                       "energy_tolerance and move_tolerance must be finite"));
  o.energy_tolerance = 0;
  // A tiny kernel width and a far site are accepted and need no more grid cells than points (both threw
  // std::bad_alloc: volume / (cutoff width)^2 cells).
  o.kernel_width = 1e-4;
  EXPECT_EQ(kernel_relaxation(px, sites, o).status, Status::success);
  o.kernel_width = 0;
  auto far = sites;
  far[0].position = {1e6, 1e6};
  EXPECT_TRUE(std::isfinite(kernel_energy(px, far, o).energy));
}

}  // namespace

TEST(KernelRelaxation, AnyRangeOfIndicesStartsBothRelaxations) {
  // The index-start overloads took only std::vector<std::size_t>: a sampler writing through its output
  // iterator into 32-bit or signed indices, or a deque, needed a copy first.
  const auto px = image(40, 30, [](int x, int) { return 40 + 4 * x; });
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> start32;
  std::deque<int> start_int;
  Dart_throwing_count_options d;
  d.darts.seed = 9;
  bilateral_dart_throwing_count(px, 60, std::back_inserter(start), d);
  bilateral_dart_throwing_count(px, 60, std::back_inserter(start32), d);
  bilateral_dart_throwing_count(px, 60, std::back_inserter(start_int), d);
  ASSERT_EQ(start.size(), 60u);
  Kernel_relaxation_options<2> k;
  k.max_iterations = 3;
  Discrete_lloyd_options<2> l;
  l.max_iterations = 3;
  const auto kr = kernel_relaxation(px, start, k);
  const auto lr = discrete_bilateral_lloyd(px, start, l);
  for (const auto& r : {kernel_relaxation(px, start32, k), kernel_relaxation(px, start_int, k)}) {
    ASSERT_EQ(r.sites.size(), kr.sites.size());
    for (std::size_t i = 0; i < r.sites.size(); ++i) EXPECT_EQ(r.sites[i].position, kr.sites[i].position);
  }
  for (const auto& r :
       {discrete_bilateral_lloyd(px, start32, l), discrete_bilateral_lloyd(px, start_int, l)}) {
    EXPECT_EQ(r.items, lr.items);
    EXPECT_EQ(r.assignment, lr.assignment);
  }
  // A braced list is a list of indices; a bad index is named with its place, whatever the index type, by the
  // function called (it was named by sites_at_items(), which the user did not call).
  EXPECT_EQ(kernel_relaxation(px, {start[0], start[1]}, k).sites.size(), 2u);
  EXPECT_EQ(discrete_bilateral_lloyd(px, {3, 7, 11}, l).sites.size(), 3u);
  start_int[4] = -1;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] { kernel_relaxation(px, start_int, k); },
      "kernel_relaxation: indices[4] = -1 is not an item index (1200 items)"));
  start32[2] = 1200;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>(
      [&] { discrete_bilateral_lloyd(px, start32, l); },
      "discrete_bilateral_lloyd: indices[2] = 1200 is not an item index (1200 items)"));
}

TEST(KernelRelaxation, AllZeroDensityIsDegenerateInBothRelaxations) {
  // A density 0 on every item (a white picture to stipple) threw in kernel_relaxation(), ran to success in
  // discrete_bilateral_lloyd() and was degenerate_input in lloyd_relaxation(): now degenerate_input in all
  // three, the sites as given, no progress asked.
  const auto px = image(20, 15, [](int, int) { return 255; });
  const auto sites = random_sites(12, px, 20, 15, 4);
  int calls = 0;
  Kernel_relaxation_options<2> k;
  k.density.assign(px.size(), 0.0);
  k.progress = [&calls](double) { return ++calls > 0; };
  const auto kr = kernel_relaxation(px, sites, k);
  EXPECT_EQ(kr.status, Status::degenerate_input);
  EXPECT_TRUE(kr.history.empty());
  ASSERT_EQ(kr.sites.size(), sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) EXPECT_EQ(kr.sites[i].position, sites[i].position);
  // The energy is still defined: every site at the widest scale, as where the density is low.
  const auto e = kernel_energy(px, sites, k);
  EXPECT_TRUE(std::isfinite(e.energy));
  EXPECT_GT(e.energy, kernel_energy(px, sites, Kernel_relaxation_options<2>()).energy);
  Discrete_lloyd_options<2> l;
  l.density.assign(px.size(), 0.0);
  l.progress = k.progress;
  const auto lr = discrete_bilateral_lloyd(px, sites, l);
  EXPECT_EQ(lr.status, Status::degenerate_input);
  EXPECT_TRUE(lr.history.empty());
  ASSERT_EQ(lr.sites.size(), sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) EXPECT_EQ(lr.sites[i].position, sites[i].position);
  EXPECT_EQ(lr.mass, std::vector<double>(sites.size(), 0.0));
  // The Voronoi sets and nearest items of the sites as given, as a run without iterations reports them.
  EXPECT_EQ(calls, 0);
  l.density.clear();
  l.max_iterations = 0;
  const auto none = discrete_bilateral_lloyd(px, sites, l);
  EXPECT_EQ(lr.assignment, none.assignment);
  EXPECT_EQ(lr.items, none.items);
  // One item of positive density is enough to relax.
  k.density[7] = 1;
  EXPECT_NE(kernel_relaxation(px, sites, k).status, Status::degenerate_input);
  l.density.assign(px.size(), 0.0);
  l.density[7] = 1;
  l.max_iterations = 2;
  EXPECT_EQ(discrete_bilateral_lloyd(px, sites, l).status, Status::success);
}

TEST(KernelRelaxation, StartingFeaturesAreTakenFromTheItems) {
  // The sites' features are replaced by their items' before they are read: placeholder zero normals are fine
  // here (refused by discrete Lloyd and kernel_energy, which read them).
  using SK = CGAL::Simple_cartesian<double>;
  using Tr = FeatureRecon::Point_with_normal_traits<SK>;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<SK::Point_3, SK::Vector_3>> items;
  for (int i = 0; i < 2000; ++i) items.push_back({SK::Point_3(u(rng), u(rng), 0), SK::Vector_3(0, 0, 1)});
  std::vector<Bilateral_site<Tr>> sites;
  for (int i = 0; i < 50; ++i) sites.push_back({{u(rng), u(rng), 0.0}, SK::Vector_3(0, 0, 0)});
  Kernel_relaxation_options<3> o;
  o.sigma_feature = 0.5;
  o.max_iterations = 5;
  const auto r = kernel_relaxation(items, sites, o);
  EXPECT_EQ(r.status, FeatureRecon::Status::success);
  EXPECT_EQ(r.sites.at(0).feature, SK::Vector_3(0, 0, 1));
}

namespace {
// Tests from a mutation audit of kernel_relaxation.h: documented boundaries and rules the tests above leave
// open.

TEST(Kernel_relaxation, NonFiniteSettingsAndZeroInitialStepAreRefused) {
  const auto px = image(6, 6, [](int, int) { return 1; });
  const auto sites = random_sites(3, px, 6, 6, 1);
  Kernel_relaxation_options<2> o;
  o.kernel_width = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "kernel_width"));
  o.kernel_width = 0;
  o.initial_step = 0;  // a step of length 0 can never lower the energy
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "initial_step"));
  o.initial_step = 0.25;
  o.domain_measure = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, o); }, "domain_measure"));
}

TEST(Kernel_relaxation, ScaleIsClampedToEightWhereTheDensityIsLow) {
  // Density 1 in the last column of a 64 x 64 image and 0 or 1e-4 elsewhere: around (5, 32) the density
  // averages 0 or 1e-4, far below the mean (mean / rho > 64), so the site's scale is the upper clamp s = 8.
  // Its mirror image across x = 0 (10 away) lies within the ghosts' reach cutoff * w0 * s = 24, and the
  // pair's kernel is s^2 exp(-d^2 / (tau s)^2) shifted by its value at the cut-off.
  const auto px = image(64, 64, [](int, int) { return 0; });
  for (const double background : {0.0, 1e-4}) {
    Kernel_relaxation_options<2> o;
    o.kernel_width = 1;
    o.density.assign(px.size(), background);
    for (std::size_t i = 0; i < px.size(); ++i)
      if (px[i].column == 63) o.density[i] = 1;
    const auto e = kernel_energy(px, std::vector<Site>{{{5.0, 32.0}, {0}}}, o);
    EXPECT_EQ(e.pairs, 1u) << background;
    EXPECT_NEAR(e.energy, 64 * (std::exp(-100.0 / 64) - std::exp(-9.0)), 1e-12) << background;
  }
}

TEST(Kernel_relaxation, ScaleIsClampedToAnEighthWhereTheDensityIsHigh) {
  // A 3 x 3 block of density 1 in a 64 x 64 image of zeros: at its centre (mean / rho)^(1/2) = 3 / 64, below
  // the lower clamp, so s = 1/8 (the block does not fit in that kernel: the item keeps its own density).
  const auto px = image(64, 64, [](int, int) { return 0; });
  Kernel_relaxation_options<2> o;
  o.kernel_width = 1;
  o.density.assign(px.size(), 0.0);
  for (std::size_t i = 0; i < px.size(); ++i)
    if (px[i].column >= 30 && px[i].column <= 32 && px[i].row >= 30 && px[i].row <= 32) o.density[i] = 1;
  const std::vector<Site> pair{{{31.5, 31.5}, {0}}, {{31.7, 31.5}, {0}}};
  const auto e = kernel_energy(px, pair, o);
  const double dx = 31.5 - 31.7, s = 0.125;
  EXPECT_EQ(e.pairs, 2u);
  EXPECT_NEAR(e.energy, s * s * (std::exp(-dx * dx / (s * s)) - std::exp(-9.0)), 1e-12);
}

TEST(Kernel_relaxation, DensityBlockThatJustFitsTheKernelIsAveraged) {
  // Columns with density 0, 1.5, 1.5, 0, 1.5, 1.5, ... (mean 1) and a kernel exactly three item spacings
  // wide: every 3 x 3 block of pixels inside the image averages 1, which gives s = 1, and 3 c_1 <= w0 s holds
  // with equality: the block fits in the kernel, so the items take its mean (the next level, blocks of side
  // 2, does not fit). Sites on a 0 and on a 1.5 column then both have s = 1, as without a density.
  // The item spacing of a W x H image is exactly 1 (the root search ended 2-4e-16 above it for 8, 16, 30
  // and 100 pixels a side, and this block was refused at a kernel width of 3).
  for (const int w : {8, 16, 17, 30, 100})
    for (const int h : {1, 7, w})
      EXPECT_EQ(sampling::internal::Item_domain<Grey_pixel_traits>(image(w, h, [](int, int) { return 0; }),
                                                                   Grey_pixel_traits(), 0, "test", false)
                    .grid_spacing(),
                1.0)
          << w << " x " << h;
  const auto px = image(30, 30, [](int, int) { return 0; });
  Kernel_relaxation_options<2> o;
  o.kernel_width = 3;
  const std::vector<Site> pair{{{10.5, 15.5}, {0}}, {{12.5, 15.5}, {0}}};
  const auto plain = kernel_energy(px, pair, o);
  EXPECT_EQ(plain.pairs, 2u);
  o.density.assign(px.size(), 0.0);
  for (std::size_t i = 0; i < px.size(); ++i) o.density[i] = px[i].column % 3 == 0 ? 0.0 : 1.5;
  const auto e = kernel_energy(px, pair, o);
  EXPECT_EQ(e.pairs, 2u);
  EXPECT_NEAR(e.energy, plain.energy, 1e-15);
}

TEST(Kernel_relaxation, PairsExactlyAtTheCutOffCountAndAddNoEnergy) {
  // "Pairs farther apart than cutoff kernel widths are ignored": a pair exactly 3 widths apart is not, and
  // the kernel, shifted to vanish there with the pair's features, gives it no energy (E is continuous).
  const auto px = image(64, 64, [](int c, int) { return c < 32 ? 0 : 255; });
  Kernel_relaxation_options<2> o;
  o.kernel_width = 1;
  const std::vector<Site> same{{{20.0, 32.0}, {0}}, {{23.0, 32.0}, {0}}};
  const auto e = kernel_energy(px, same, o);
  EXPECT_EQ(e.pairs, 2u);
  EXPECT_NEAR(e.energy, 0.0, 1e-15);
  EXPECT_GT(e.gradient[0][0], 0.0);  // the one-sided derivative of the kernel inside the cut-off
  EXPECT_LT(e.gradient[1][0], 0.0);
  o.sigma_feature = 0.5;  // features 0 and 255: f^2 = 4
  const std::vector<Site> across{{{30.0, 32.0}, {0}}, {{33.0, 32.0}, {255}}};
  const auto b = kernel_energy(px, across, o);
  EXPECT_EQ(b.pairs, 2u);
  EXPECT_NEAR(b.energy, 0.0, 1e-15);
  // Just inside the cut-off the energy is just above 0.
  const std::vector<Site> inside{{{30.0, 32.0}, {0}}, {{32.999, 32.0}, {255}}};
  const double near = kernel_energy(px, inside, o).energy;
  EXPECT_GT(near, 0.0);
  EXPECT_LT(near, 1e-6);
}

TEST(Kernel_relaxation, NoDescentAfterThirtyHalvings) {
  // Two sites farther apart than the cut-off and far from the faces: no pair, no gradient, no step lowers E
  // (a step that only keeps it is not taken). The step is halved 30 times, then the run stops.
  const auto px = image(64, 64, [](int, int) { return 0; });
  Kernel_relaxation_options<2> o;
  o.kernel_width = 1;
  const auto r = kernel_relaxation(px, std::vector<Site>{{{20.0, 32.0}, {0}}, {{40.0, 32.0}, {0}}}, o);
  EXPECT_EQ(r.status, Status::success);
  EXPECT_EQ(r.stop, Lloyd_stop::no_descent);
  EXPECT_TRUE(r.history.empty());
  EXPECT_EQ(r.step, 0.25 * 0x1p-30);
  EXPECT_EQ(r.sites[0].position, (std::array<double, 2>{20.0, 32.0}));
}

TEST(Kernel_relaxation, StepGrowsByAQuarterAndMovesAtMostAKernelWidth) {
  // A close pair with a huge first step: each site moves by at most a kernel width (w0 = 2), the step is
  // accepted and the next one is 1.25 times longer.
  const auto px = image(64, 64, [](int, int) { return 0; });
  Kernel_relaxation_options<2> o;
  o.kernel_width = 2;
  o.initial_step = 0.5;
  o.max_iterations = 1;
  const std::vector<Site> pair{{{30.0, 32.0}, {0}}, {{30.1, 32.0}, {0}}};
  const auto r = kernel_relaxation(px, pair, o);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_EQ(r.step, 0.5 * 1.25);
  o.initial_step = 100;
  const auto big = kernel_relaxation(px, pair, o);
  ASSERT_EQ(big.history.size(), 1u);
  EXPECT_GT(big.history[0].max_move, 1.9);
  EXPECT_LE(big.history[0].max_move, 2 * (1 + 1e-12));
}

TEST(Kernel_relaxation, HistoryIsTakenBeforeEachStep) {
  // history[k] holds the energy and rho of the sites before step k + 1: the starting sites first, then the
  // sites on_iteration saw after step k.
  const auto px = image(32, 32, [](int, int) { return 0; });
  const auto start = random_sites(30, px, 32, 32, 13);
  Kernel_relaxation_options<2> o;
  o.max_iterations = 4;
  o.energy_tolerance = 0;
  std::vector<std::vector<std::array<double, 2>>> seen;
  o.on_iteration = [&seen](Lloyd_iteration_statistics&, const std::vector<std::array<double, 2>>& p) {
    seen.push_back(p);
    return true;
  };
  std::vector<double> fractions;
  o.progress = [&fractions](double f) {
    fractions.push_back(f);
    return true;
  };
  const auto r = kernel_relaxation(px, start, o);
  ASSERT_EQ(r.history.size(), 4u);
  EXPECT_EQ(fractions, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  Kernel_relaxation_options<2> probe;
  EXPECT_NEAR(r.history[0].energy, kernel_energy(px, start, probe).energy, 1e-12);
  for (std::size_t k = 1; k < 4; ++k) {
    std::vector<Site> before;
    for (const auto& p : seen[k - 1]) before.push_back({p, {0}});
    EXPECT_NEAR(r.history[k].energy, kernel_energy(px, before, probe).energy, 1e-12) << k;
  }
}

TEST(Kernel_relaxation, CopiesMoveApartByAHundredthOfTheKernelWidth) {
  // Default width: w0 = d_hex / 2, so the copy's distance w0 / 100 gives rho = 1 / 200 at the first step.
  const auto px = image(16, 16, [](int, int) { return 0; });
  const std::vector<Site> sites{{{4.0, 4.0}, {0}}, {{12.0, 5.0}, {0}}, {{4.0, 4.0}, {0}}, {{8.0, 12.0}, {0}}};
  Kernel_relaxation_options<2> o;
  o.max_iterations = 1;
  const auto r = kernel_relaxation(px, sites, o);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_NEAR(r.history[0].relative_radius, 0.005, 1e-12);
}

// The torus energy by brute force: every pair of distinct sites through every image s = (a W, b H) with
// |a|, |b| <= 4, the kernel minus its value at the cut-off (scales 1: no density; sigma_position 1).
// Sites without features (Point_traits) take sigma_feature infinity.
template <class S>
double torus_energy(const std::vector<S>& sites, double w, double h, double tau, double cutoff,
                    double sigma_feature) {
  double total = 0;
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (std::size_t j = 0; j < sites.size(); ++j) {
      if (j == i) continue;
      double f2 = 0;
      if constexpr (std::is_same_v<S, Site>) {
        const double df = (sites[i].feature[0] - sites[j].feature[0]) / 255.0;  // Pixel_traits' distance
        f2 = std::isinf(sigma_feature) ? 0.0 : df * df / (sigma_feature * sigma_feature);
      }
      for (int a = -4; a <= 4; ++a)
        for (int b = -4; b <= 4; ++b) {
          const double dx = sites[i].position[0] - sites[j].position[0] - a * w;
          const double dy = sites[i].position[1] - sites[j].position[1] - b * h;
          const double d2 = dx * dx + dy * dy;
          if (d2 > cutoff * cutoff * tau * tau) continue;
          total += std::exp(-(d2 + f2) / (tau * tau)) - std::exp(-(cutoff * cutoff + f2 / (tau * tau)));
        }
    }
  return total / double(sites.size());
}

// Smallest distance between two sites on the W x H torus, brute force (own images excluded).
double torus_spacing(const std::vector<std::array<double, 2>>& p, double w, double h) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      double dx = std::fmod(std::abs(p[i][0] - p[j][0]), w), dy = std::fmod(std::abs(p[i][1] - p[j][1]), h);
      dx = std::min(dx, w - dx);
      dy = std::min(dy, h - dy);
      best = std::min(best, std::sqrt(dx * dx + dy * dy));
    }
  return best;
}

TEST(Kernel_relaxation, TorusEnergyIsTheSumOverEveryImage) {
  // 24 x 20 pixels: the torus [0, 24) x [0, 20). Sites anywhere, two outside the box (wrapped), kernels that
  // reach less than a period (width 2, cut-off 3) and more than one (width 9: images two periods away).
  const auto px = image(24, 20, [](int c, int) { return c < 11 ? 30 : 200; });
  auto sites = random_sites(14, px, 24, 20, 11);
  sites[3].position = {-2.5, 7};
  sites[4].position = {30.25, -19.5};
  sites[5].position = {0.2, 19.9};  // across the corner from site 6
  sites[6].position = {23.7, 0.1};
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  for (const double sigma_feature : {std::numeric_limits<double>::infinity(), 0.3})
    for (const double tau : {2.0, 9.0}) {
      o.kernel_width = tau;
      o.sigma_feature = sigma_feature;
      const auto e = kernel_energy(px, sites, o);
      const double want = torus_energy(sites, 24, 20, tau, 3, sigma_feature);
      EXPECT_NEAR(e.energy, want, 1e-12 * std::abs(want)) << "tau " << tau << " sigma " << sigma_feature;
      ASSERT_GT(want, 0);
    }
  // Sites 5 and 6 are (0.5, 0.2) apart across the corner, the only pair within a narrow kernel's reach.
  o.kernel_width = 0.5;
  o.sigma_feature = std::numeric_limits<double>::infinity();
  const std::vector<Site> corner{sites[5], sites[6]};
  const auto c = kernel_energy(px, corner, o);
  EXPECT_NEAR(c.energy, std::exp(-0.29 / 0.25) - std::exp(-9.0), 1e-14);
  EXPECT_EQ(c.pairs, 2u);
  // Site 1's image sits at (-0.3, 20.1): the energy falls as site 0 moves right and down, away from it.
  EXPECT_LT(c.gradient[0][0], 0);
  EXPECT_GT(c.gradient[0][1], 0);
  EXPECT_NEAR(c.gradient[0][0], -c.gradient[1][0], 1e-13);
  // In the box they are 23.5 apart and feel only their mirrors.
  o.periodic = false;
  EXPECT_NE(kernel_energy(px, corner, o).pairs, 2u);
}

TEST(Kernel_relaxation, TorusGradientMatchesFiniteDifferences) {
  const auto px = image(24, 20, [](int c, int r) { return c < 11 || r > 17 ? 30 : 200 + (r % 3); });
  auto sites = random_sites(25, px, 24, 20, 3);
  sites[0].position = {0.3, 10};  // near the faces
  sites[1].position = {23.6, 10.4};
  sites[2].position = {5, 19.8};
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.kernel_width = 4.0;
  o.cutoff = 50;  // nothing cut: the energy is smooth; many images (a reach of 200)
  expect_gradient(px, sites, o);
  o.sigma_feature = 0.3;
  expect_gradient(px, sites, o);
  o.sigma_position = 2;
  o.kernel_width = 2.0;
  o.cutoff = 3;
  o.density.assign(px.size(), 1.0);
  for (std::size_t i = 0; i < px.size(); ++i) o.density[i] = px[i].value < 100 ? 4.0 : 1.0;
  expect_gradient(px, sites, o);
}

TEST(Kernel_relaxation, TorusIsTranslationInvariant) {
  // A picture rolled by whole density cells (8 x 8 pixels: the widest block at this kernel width) and the
  // sites moved with it have the same energy and gradient: nothing marks the torus's faces, neither the
  // images, nor the nearest pixel, nor the density averaged across the faces. The box does mark them.
  auto value = [](int c, int r) { return (c < 3 || c > 21) && r < 9 ? 10 : (c + 2 * r) % 7 < 2 ? 60 : 230; };
  const int dx = 8, dy = 8;
  const auto px = image(24, 16, value);
  const auto rolled =
      image(24, 16, [&](int c, int r) { return value((c + 24 - dx) % 24, (r + 16 - dy) % 16); });
  auto sites = random_sites(100, px, 24, 16, 5);
  auto moved = sites;
  for (auto& s : moved) {
    s.position[0] = std::fmod(s.position[0] + dx, 24.0);
    s.position[1] = std::fmod(s.position[1] + dy, 16.0);
  }
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.kernel_width = 4.0;
  o.sigma_feature = 0.4;
  auto density = [](const std::vector<Grey_pixel>& p) {
    std::vector<double> d;
    for (const auto& x : p) d.push_back(1 - x.value / 255.0);
    return d;
  };
  o.density = density(px);
  Kernel_relaxation_options<2> r = o;
  r.density = density(rolled);
  const auto a = kernel_energy(px, sites, o), b = kernel_energy(rolled, moved, r);
  EXPECT_NEAR(a.energy, b.energy, 1e-12 * a.energy);
  EXPECT_EQ(a.pairs, b.pairs);
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(a.gradient[i][k], b.gradient[i][k], 1e-12 * a.energy);
  o.periodic = r.periodic = false;
  EXPECT_GT(std::abs(kernel_energy(px, sites, o).energy - kernel_energy(rolled, moved, r).energy),
            1e-3 * a.energy);
}

TEST(Kernel_relaxation, TorusRelaxationTilesAndReportsTorusSpacing) {
  const auto px = image(48, 40, [](int, int) { return 128; });
  const auto start = random_sites(80, px, 48, 40, 9);
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.max_iterations = 80;
  o.energy_tolerance = 0;
  const double d_hex = std::sqrt(2 * 48.0 * 40.0 / (std::sqrt(3.0) * 80));
  std::vector<double> reported, measured;
  o.on_iteration = [&](Lloyd_iteration_statistics& s, const std::vector<std::array<double, 2>>& p) {
    reported.push_back(s.relative_radius);
    measured.push_back(torus_spacing(p, 48, 40));
    for (const auto& x : p) {
      EXPECT_TRUE(x[0] >= 0 && x[0] < 48 && x[1] >= 0 && x[1] < 40) << x[0] << ", " << x[1];
    }
    // A move is measured on the torus: at most a kernel width, also for a site that crossed a face.
    EXPECT_LE(s.max_move, d_hex / 2 * (1 + 1e-12));
    return true;
  };
  const auto r = kernel_relaxation(px, start, o);
  EXPECT_EQ(r.status, Status::success);
  ASSERT_GE(reported.size(), 40u);
  EXPECT_DOUBLE_EQ(r.kernel_width, d_hex / 2);
  // Each step's statistics are taken before it: the spacing on the torus of the previous step's sites.
  for (std::size_t i = 1; i < reported.size(); ++i)
    EXPECT_NEAR(reported[i], measured[i - 1] / d_hex, 1e-12) << "iteration " << i + 1;
  std::vector<std::array<double, 2>> final;
  for (const auto& s : r.sites) final.push_back(s.position);
  // Spread on the torus: no close pair across the seams either.
  EXPECT_GT(torus_spacing(final, 48, 40) / d_hex, 0.7);
  EXPECT_LT(reported.front(), 0.2);
  // Not pushed off the faces (the box's mirrors keep a band empty): the band within d_hex / 4 of a face
  // holds about its share of the sites (15% of the area, 12 sites).
  std::size_t band = 0;
  for (const auto& p : final) band += std::min({p[0], p[1], 48 - p[0], 40 - p[1]}) < d_hex / 4;
  EXPECT_GE(band, 4u);
  // Bit for bit the same again.
  o.on_iteration = nullptr;
  const auto again = kernel_relaxation(px, start, o);
  ASSERT_EQ(again.sites.size(), r.sites.size());
  for (std::size_t i = 0; i < r.sites.size(); ++i) EXPECT_EQ(again.sites[i].position, r.sites[i].position);
}

TEST(Kernel_relaxation, TorusNearestItemLiesAcrossTheFaces) {
  // On the torus [-1, 11) x [-1, 8) of irregular_pixels() each site takes the feature of the pixel nearest to
  // it (brute force, ties to the lowest index), often across a face, and its position wrapped into the box.
  const std::vector<Grey_pixel> px = test::irregular_pixels();
  std::mt19937_64 rng(4);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Site> sites(400);
  for (auto& s : sites) s.position = {-13 + 38 * u(), -10 + 28 * u()};  // up to a period outside the box
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.sigma_feature = 0.5;
  o.max_iterations = 0;  // the sites as settled: wrapped, features from their items
  const auto r = kernel_relaxation(px, sites, o);
  std::size_t across = 0;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    std::array<double, 2> w;
    for (int k = 0; k < 2; ++k) {
      const double lo = -1, period = k == 0 ? 12 : 9;
      w[k] = lo + std::fmod(std::fmod(sites[i].position[k] - lo, period) + period, period);
      EXPECT_NEAR(r.sites[i].position[k], w[k], 1e-12) << "site " << i;
    }
    std::size_t best = 0, plain = 0;
    double best_d = std::numeric_limits<double>::infinity(), plain_d = best_d;
    for (std::size_t j = 0; j < px.size(); ++j) {
      double dx = std::abs(w[0] - (px[j].column + 0.5)), dy = std::abs(w[1] - (px[j].row + 0.5));
      const double direct = dx * dx + dy * dy;
      dx = std::min(dx, 12 - dx);
      dy = std::min(dy, 9 - dy);
      if (dx * dx + dy * dy < best_d) {
        best_d = dx * dx + dy * dy;
        best = j;
      }
      if (direct < plain_d) {
        plain_d = direct;
        plain = j;
      }
    }
    EXPECT_EQ(r.sites[i].feature[0], px[best].value) << "site " << i << " at " << w[0] << ", " << w[1];
    across += best != plain;
  }
  EXPECT_GT(across, 40u);  // the check tells
}

TEST(Kernel_relaxation, TorusDegenerateAndRefused) {
  // One row of pixels: a torus of period 1 across it; the sites spread along it.
  const auto row = image(30, 1, [](int, int) { return 100; });
  std::vector<Site> two{{{3.0, 0.5}, {100}}, {{3.5, 0.5}, {100}}};
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  const auto r = kernel_relaxation(row, two, o);
  EXPECT_EQ(r.status, Status::success);
  std::vector<std::array<double, 2>> p{r.sites[0].position, r.sites[1].position};
  EXPECT_GT(torus_spacing(p, 30, 1), 5.0);
  // Two sites a whole period apart are one position on the torus: they move apart as copies do.
  std::vector<Site> copies{{{3.0, 0.5}, {100}}, {{33.0, 0.5}, {100}}};
  const auto c = kernel_relaxation(row, copies, o);
  EXPECT_EQ(c.status, Status::success);
  EXPECT_GT(torus_spacing({c.sites[0].position, c.sites[1].position}, 30, 1), 5.0);
  // One pixel: nothing to relax on. Its box has no width, so it does not wrap: the energy is that of the
  // sites where they are (every site was put on the box's corner, all pairs coincident).
  const auto dot = image(1, 1, [](int, int) { return 0; });
  EXPECT_EQ(kernel_relaxation(dot, two, o).status, Status::degenerate_input);
  Kernel_relaxation_options<2> wide = o;
  wide.kernel_width = 1;
  const auto e = kernel_energy(dot, two, wide);
  EXPECT_EQ(e.pairs, 2u);
  EXPECT_GT(e.gradient[0][0], 0);  // the energy falls as the two move apart
  EXPECT_LT(e.gradient[1][0], 0);
  // Snapping has no torus; a kernel whose reach holds more than 4,096 images of a site is refused.
  o.constraint = Kernel_constraint::snap_to_item;
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_relaxation(row, two, o); },
                                                       "periodic needs constraint bounding_box"));
  o.constraint = Kernel_constraint::bounding_box;
  o.kernel_width = 100;  // a reach of 300: 601 x 21 images
  EXPECT_TRUE(
      test::throws_with<std::invalid_argument>([&] { kernel_energy(row, two, o); },
                                               "the kernel reaches 300 (cutoff x kernel width x "
                                               "sigma_position x the largest scale; the shortest period "
                                               "is 1): up to 12621 images of a site, more than 4096"));
  o.kernel_width = 20;  // 121 x 5
  EXPECT_NO_THROW(kernel_energy(row, two, o));
}

TEST(Kernel_relaxation, TorusDensityBlocksWrapOnAnyLattice) {
  // A 12 x 12 lattice 0.1 apart: the torus's period, 1.2 but for rounding, holds whole numbers of the density
  // blocks' cells (0.1, 0.2, 0.4 at this kernel width), which must border across the faces as at spacing 1.
  // The density rolled by 4 items along x and 8 along y, with the sites moved along, gives the same energy
  // and gradient.
  using Point_2 = test::Point_2;
  std::vector<Point_2> items;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) items.emplace_back(0.1 * i, 0.1 * j);
  auto rho = [](int i, int j) { return (i < 2 || i > 10) && j < 5 ? 1.0 : (i + 2 * j) % 5 < 2 ? 0.3 : 0.05; };
  std::vector<double> density, rolled;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      density.push_back(rho(i, j));
      rolled.push_back(rho((i + 8) % 12, (j + 4) % 12));
    }
  using Point_site = Bilateral_site<Point_traits<Point_2>>;
  std::mt19937_64 rng(2);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Point_site> sites(40), moved(40);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    sites[i].position = {-0.05 + 1.2 * u(), -0.05 + 1.2 * u()};
    moved[i].position = {sites[i].position[0] + 0.4, sites[i].position[1] + 0.8};  // wrapped by the torus
  }
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.kernel_width = 0.2;
  o.density = density;
  Kernel_relaxation_options<2> r = o;
  r.density = rolled;
  const auto a = kernel_energy(items, sites, o), b = kernel_energy(items, moved, r);
  EXPECT_NEAR(a.energy, b.energy, 1e-12 * a.energy);
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(a.gradient[i][k], b.gradient[i][k], 1e-9 * a.energy) << i;
}

TEST(Kernel_relaxation, TorusOfAGivenPeriodAndOfAnAnisotropicLattice) {
  // The 12 irregular pixels (automatic torus 12 x 9) on the torus of a given period 15 x 11: the energy is
  // the sum over every image at those periods, whatever the origin, for kernels within and beyond a period.
  const std::vector<Grey_pixel> px = test::irregular_pixels();
  std::mt19937_64 rng(7);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<Site> sites(10);
  for (std::size_t i = 0; i < sites.size(); ++i)
    sites[i] = {{-3 + 21 * u(), -3 + 17 * u()}, {static_cast<std::uint8_t>(25 * i)}};
  Kernel_relaxation_options<2> o;
  o.periodic = true;
  o.period = {15, 11};
  for (const double sigma_feature : {std::numeric_limits<double>::infinity(), 0.3})
    for (const double tau : {1.5, 6.0}) {
      o.kernel_width = tau;
      o.sigma_feature = sigma_feature;
      const double want = torus_energy(sites, 15, 11, tau, 3, sigma_feature);
      ASSERT_GT(want, 0);
      EXPECT_NEAR(kernel_energy(px, sites, o).energy, want, 1e-12 * want)
          << "tau " << tau << " sigma_feature " << sigma_feature;
    }
  // The box is centred on the pixels' (their centres span [0.5, 9.5] x [0.5, 6.5]), and so is the torus.
  const sampling::internal::Kernel_engine<Grey_pixel_traits> given(px, o, Grey_pixel_traits(), 10, "test");
  EXPECT_EQ(given.box_lo, (std::array<double, 2>{-2.5, -2.0}));
  EXPECT_EQ(given.box_hi, (std::array<double, 2>{12.5, 9.0}));
  EXPECT_EQ(given.torus.period, (std::array<double, 2>{15.0, 11.0}));
  // Exactly the given periods also far from the origin, where the box's faces are rounded (1e6 + 0.1 +
  // [0, 1)^2 in 3.3 x 2.7: the faces lie 3.300000000046566 and 2.699999999953434 apart).
  std::vector<test::Point_2> far;
  for (const auto& p : test::white_noise(20, 1)) far.emplace_back(1e6 + 0.1 + p.x(), 1e6 + 0.1 + p.y());
  Kernel_relaxation_options<2> f;
  f.periodic = true;
  f.period = {3.3, 2.7};
  const sampling::internal::Kernel_engine<Point_traits<test::Point_2>> away(
      far, f, Point_traits<test::Point_2>(), 5, "test");
  EXPECT_EQ(away.torus.period, (std::array<double, 2>{3.3, 2.7}));
  // A 10 x 7 lattice of steps 1 x 2 at (0.5 + i, 1 + 2 j): its box is that of its cells, [0, 10] x [0, 14],
  // in the plain box as on the torus (one spacing for both axes gave [-0.21, 10.21] x [0.29, 13.71]).
  using Point_2 = test::Point_2;
  using Point_site = Bilateral_site<Point_traits<Point_2>>;
  std::vector<Point_2> lattice;
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 10; ++i) lattice.emplace_back(0.5 + i, 1 + 2 * j);
  std::vector<Point_site> points(12);
  for (auto& p : points) p.position = {-2 + 14 * u(), -2 + 18 * u()};
  Kernel_relaxation_options<2> a;
  for (const bool periodic : {false, true}) {
    a.periodic = periodic;
    const sampling::internal::Kernel_engine<Point_traits<Point_2>> e(lattice, a, Point_traits<Point_2>(), 12,
                                                                     "test");
    EXPECT_EQ(e.box_lo, (std::array<double, 2>{0.0, 0.0})) << periodic;
    EXPECT_EQ(e.box_hi, (std::array<double, 2>{10.0, 14.0})) << periodic;
  }
  a.kernel_width = 2.5;
  const double want = torus_energy(points, 10, 14, 2.5, 3, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(kernel_energy(lattice, points, a).energy, want, 1e-12 * want);
  // Refused without periodic, and shorter than the items' extent.
  Kernel_relaxation_options<2> b;
  b.period = {15, 11};
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_energy(px, sites, b); },
                                                       "period is given (2 values) but periodic is false"));
  b.periodic = true;
  b.period = {15};
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_energy(px, sites, b); },
                                                       "period has 1 values for positions of dimension 2"));
  b.period = {15, 5.5};
  EXPECT_TRUE(test::throws_with<std::invalid_argument>([&] { kernel_relaxation(px, sites, b); },
                                                       "period[1] = 5.5 is shorter than the items' extent "
                                                       "along axis 1 (6): the items must fit in one period"));
}

}  // namespace
