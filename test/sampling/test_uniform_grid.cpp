// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/internal/Uniform_grid.h>
#include <FeatureRecon/sampling/internal/nearest_tree.h>
#include <FeatureRecon/sampling/internal/ring_grid.h>
#include <FeatureRecon/sampling/internal/sample_set.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using FeatureRecon::internal::Dynamic_grid;
using FeatureRecon::internal::Grid_frame;
using FeatureRecon::internal::Uniform_grid;

namespace {
// Brute force: the points within `r` of q, sorted.
template <int D>
std::vector<std::uint32_t> within(const std::vector<std::array<double, D>>& p, const std::array<double, D>& q,
                                  double r) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += (p[i][k] - q[k]) * (p[i][k] - q[k]);
    if (d2 <= r * r) out.push_back(i);
  }
  return out;
}

// Every point within the cell size of a query is a candidate exactly once, for both grids.
template <int D>
void expect_exact_candidates(const std::vector<std::array<double, D>>& p, double r,
                             std::size_t max_candidates) {
  const Uniform_grid<D> grid(p, r);
  Dynamic_grid<D> dynamic(p, r);
  for (std::uint32_t i = 0; i < p.size(); ++i) dynamic.insert(i);
  EXPECT_EQ(grid.cell_size(), r);
  for (std::size_t i = 0; i < p.size(); i += 7) {
    for (int which = 0; which < 2; ++which) {
      std::vector<std::uint32_t> candidates, near;
      auto take = [&](std::uint32_t j) { candidates.push_back(j); };
      if (which == 0)
        grid.for_each_candidate(p[i], take);
      else
        dynamic.for_each_candidate(p[i], take);
      std::sort(candidates.begin(), candidates.end());
      EXPECT_TRUE(std::adjacent_find(candidates.begin(), candidates.end()) == candidates.end())
          << "point " << i;
      EXPECT_LE(candidates.size(), max_candidates) << "point " << i;
      for (std::uint32_t j : candidates) {
        double d2 = 0;
        for (int k = 0; k < D; ++k) d2 += (p[j][k] - p[i][k]) * (p[j][k] - p[i][k]);
        if (d2 <= r * r) near.push_back(j);
      }
      EXPECT_EQ(near, within<D>(p, p[i], r)) << "point " << i;
    }
  }
}
}  // namespace

TEST(UniformGrid, AFarOutlierKeepsTheCellSize) {
  // 4,000 points in the unit square and one at 1e7: the cells used to grow to 1e7 / 2^20 = 9.5, one cell for
  // the whole square (dart throwing and elimination became quadratic). Now hashed cells keep the side 0.01.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 2>> p(4000);
  for (auto& q : p) q = {u(rng), u(rng)};
  expect_exact_candidates<2>(p, 0.01, 60);  // packed keys (the square alone)
  p.push_back({1e7, 0});
  EXPECT_GT(Grid_frame<2>(p, 0.01).cell_size(), 0.0);
  expect_exact_candidates<2>(p, 0.01, 60);
  // 3-D, with the outlier far along every axis, and a cloud 1e-9 wide at 1e6 (cells of 1e-11).
  std::vector<std::array<double, 3>> s(3000);
  for (auto& q : s) q = {u(rng), u(rng), u(rng)};
  s.push_back({-3e8, 2e9, 5e7});
  expect_exact_candidates<3>(s, 0.05, 200);
  for (auto& q : s) q = {1e6 + 1e-9 * u(rng), 1e6 + 1e-9 * u(rng), 1e6};
  s.push_back({0, 0, 0});
  expect_exact_candidates<3>(s, 1e-11, 200);
}

// The dense array of cells (a small box: at most four cells per point) visits the same candidates in the same
// order as the hash map of packed keys: cells in key order (nested over the axes), points by index within a
// cell. Checked against that order built by brute force, with queries inside, on the border and outside the
// box, in 2D and 3D, for the grid built at once and the one filled point by point (with a hint of many
// points).
template <int D>
void expect_key_order(const std::vector<std::array<double, D>>& p, double r) {
  const Grid_frame<D> frame(p, r);
  ASSERT_TRUE(FeatureRecon::internal::use_dense_cells(frame, p.size()));
  const Uniform_grid<D> grid(p, r);
  Dynamic_grid<D> dynamic(p, r, 1000000);
  for (std::uint32_t i = 0; i < p.size(); ++i) dynamic.insert(i);
  std::vector<std::array<double, D>> queries(p.begin(), p.begin() + 40);
  std::array<double, D> outside{}, corner{};
  for (int k = 0; k < D; ++k) {
    outside[k] = -0.6 * r;
    corner[k] = 1.0 + 0.4 * r;
  }
  queries.push_back(outside);
  queries.push_back(corner);
  for (const auto& q : queries) {
    std::vector<std::uint64_t> keys;
    frame.for_each_neighbor_key(q, [&](std::uint64_t k) { keys.push_back(k); });
    std::vector<std::uint32_t> expected;
    for (const std::uint64_t k : keys)
      for (std::uint32_t j = 0; j < p.size(); ++j)
        if (frame.key(frame.cell_of(p[j])) == k) expected.push_back(j);
    std::vector<std::uint32_t> got, got_dynamic;
    grid.for_each_candidate(q, [&](std::uint32_t j) { got.push_back(j); });
    dynamic.for_each_candidate(q, [&](std::uint32_t j) { got_dynamic.push_back(j); });
    EXPECT_EQ(got, expected);
    EXPECT_EQ(got_dynamic, expected);
  }
}

TEST(UniformGrid, DenseCellsVisitInKeyOrder) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 2>> p2(600);
  for (auto& x : p2) x = {std::round(20 * u(rng)) / 20, u(rng)};  // ties on cell borders along x
  p2.push_back({1, 1});
  expect_key_order<2>(p2, 0.05);
  std::vector<std::array<double, 3>> p3(800);
  for (auto& x : p3) x = {u(rng), std::round(10 * u(rng)) / 10, u(rng)};
  p3.push_back({1, 1, 1});
  expect_key_order<3>(p3, 0.1);
}

// Queries far outside the box: cells more than 2^63 away (a map compared at a tiny threshold with one far
// away) were converted from double to int64 unclamped, which is undefined behaviour (-fsanitize=undefined
// reports it). They find nothing and a query inside still finds its points, for packed, dense and hashed
// frames.
TEST(UniformGrid, QueriesFarOutsideTheBoxAreClamped) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const bool outlier : {false, true}) {
    std::vector<std::array<double, 2>> p{{0, 0}, {0.5, 0.5}, {1, 1}};
    if (outlier) p.push_back({1e7, 0});  // 10^10 cells: hashed
    const Uniform_grid<2> grid(p, 1e-3);
    for (const std::array<double, 2> q : std::vector<std::array<double, 2>>{
             {1e300, 0.5}, {-1e300, 0.5}, {0.5, 1e300}, {0.5, -1e300}, {inf, -inf}, {1e300, 1e300}}) {
      std::vector<std::uint32_t> got;
      grid.for_each_candidate(q, [&](std::uint32_t j) { got.push_back(j); });
      EXPECT_TRUE(got.empty()) << q[0] << " " << q[1] << (outlier ? " hashed" : "");
    }
    std::vector<std::uint32_t> got;
    grid.for_each_candidate({0.5, 0.5}, [&](std::uint32_t j) { got.push_back(j); });
    EXPECT_EQ(got, (std::vector<std::uint32_t>{1}));
  }
  const Grid_frame<2> tiny(std::vector<std::array<double, 2>>{{0, 0}, {1, 1}}, 1e-300);  // hashed: cell 2^-60
  EXPECT_TRUE(tiny.hashed());
  EXPECT_EQ(tiny.cell_of({1e300, -1e300})[0], std::int64_t(1) << 62);
  EXPECT_EQ(tiny.cell_of({1e300, -1e300})[1], -(std::int64_t(1) << 62));
}

// A dense grid filled point by point refuses a point outside the box of its frame (the hash map took it).
TEST(UniformGrid, DenseDynamicGridRefusesAPointOutsideItsBox) {
  std::vector<std::array<double, 2>> p{{0, 0}, {1, 1}};
  Dynamic_grid<2> grid(p, 0.1, 100);
  p.push_back({0.5, 0.5});
  grid.insert(2);
  p.push_back({-0.05, 0.5});
  EXPECT_THROW(grid.insert(3), std::out_of_range);
  std::vector<std::uint32_t> got;
  grid.for_each_candidate({0.5, 0.5}, [&](std::uint32_t j) { got.push_back(j); });
  EXPECT_EQ(got, (std::vector<std::uint32_t>{2}));
}

TEST(UniformGrid, TorusLookUpFindsEveryPairWithinReachOnceFromEachSide) {
  // for_each_torus_candidate() with the reach of torus_search_reach(): every pair whose nearest-image
  // distance, as computed, lies below the reach (one to four ulps above it) is found from both sides, on the
  // unit torus and on the tori of boxes, some far from the origin (the grid framed by the box's corners, as
  // continuous dart throwing has it). Three pairs in four straddle a seam (one in two both) at a scale from
  // 1 down to 1e-15 of the period: there the rounding of the nearest-image difference is a large part of the
  // reach. A margin relative to the reach alone missed about a tenth of such pairs (the plain reach more);
  // far from the origin the rounding is that of the coordinates' magnitude, which the absolute margin scales
  // with (fixed at 2^-48 it missed 739 of 200,000 pairs in [-1e6, 1e6) x [0, 1): a review's measurement).
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const std::array<std::array<double, 4>, 5> boxes{{{0, 0, 1, 1},
                                                    {-3, 2, 5, 2.5},
                                                    {1e6, -5e5, 1e6 + 1, -5e5 + 3},
                                                    {-1e6, 0, 1e6, 1},
                                                    {1e-3, -7, 1e6, -7 + 1e-9}}};
  for (const auto& b : boxes) {
    const std::array<double, 2> low{b[0], b[1]}, period{b[2] - b[0], b[3] - b[1]};
    const double extent = std::max({std::abs(b[0]), std::abs(b[1]), std::abs(b[2]), std::abs(b[3])});
    std::size_t cases = 0, misses = 0;
    for (int t = 0; t < 100000; ++t) {
      std::array<double, 2> p, q;
      for (std::size_t k = 0; k < 2; ++k) {
        p[k] = low[k] + period[k] * u(rng);
        q[k] = low[k] + period[k] * u(rng);
      }
      const double scale = std::pow(10.0, -double(rng() % 16));
      for (std::size_t k = 0; k < 2; ++k)
        if (int(k) < t % 4) {  // straddling the seam of axis k
          p[k] = low[k] + period[k] * scale * u(rng);
          q[k] = b[2 + k] - period[k] * scale * u(rng);
        }
      for (std::size_t k = 0; k < 2; ++k) {  // into [low, low + period): the end is the start
        p[k] = p[k] >= b[2 + k] ? low[k] : std::max(p[k], low[k]);
        q[k] = q[k] >= b[2 + k] ? low[k] : std::max(q[k], low[k]);
      }
      double d2 = 0;
      for (std::size_t k = 0; k < 2; ++k) {
        double d = std::abs(p[k] - q[k]);
        d = std::min(d, period[k] - d);
        d2 += d * d;
      }
      double reach = std::sqrt(d2);
      for (int k = 0, m = int(rng() % 4); k <= m; ++k) reach = std::nextafter(reach, 1e300);
      if (!(reach * reach >= 0x1p-960)) continue;  // no prefilter then: the metric decides
      const double look = si::torus_search_reach(reach, extent);
      const std::vector<std::array<double, 2>> v{{b[0], b[1]}, {b[2], b[3]}, p, q};
      FeatureRecon::internal::Dynamic_grid<2> grid(v, look, 4);
      grid.insert(2);
      grid.insert(3);
      for (std::uint32_t i = 2; i < 4; ++i) {
        int found = 0;
        si::for_each_torus_candidate(
            grid, v[i], look,
            [&](std::uint32_t j, int) {
              if (j == 5 - i) ++found;
            },
            low, period);
        misses += found == 0 ? 1 : 0;
      }
      ++cases;
    }
    EXPECT_EQ(misses, 0u) << "of " << cases << " pairs, box [" << b[0] << ", " << b[2] << ") x [" << b[1]
                          << ", " << b[3] << ")";
  }
}

// From a mutation audit of sample_set.h: the intrinsic dimension of 3D positions is 2 "when at least half"
// of the probes have a flat neighbourhood (12 neighbours). Clusters of 13 points, far apart, so that the 12
// neighbours of each point are the rest of its cluster: a flat one (13 points of a plane) and a solid one (a
// cuboctahedron and its centre, whose neighbourhoods are far from flat). Exactly half the probes flat is 2;
// a third of them is 3.
TEST(SampleSet, IntrinsicDimensionIsTwoWhenExactlyHalfTheProbesAreFlat) {
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  auto flat = [&](double at) {
    std::vector<std::array<double, 3>> c;
    for (int i = 0; i < 13; ++i) c.push_back({at + u(rng), u(rng), 0.25});
    return c;
  };
  auto solid = [](double at) {
    std::vector<std::array<double, 3>> c{{at, 0, 0}};
    for (const double a : {-1.0, 1.0})
      for (const double b : {-1.0, 1.0}) {
        c.push_back({at + a, b, 0});
        c.push_back({at + a, 0, b});
        c.push_back({at, a, b});
      }
    return c;
  };
  auto dimension = [](const std::vector<std::vector<std::array<double, 3>>>& clusters) {
    std::vector<std::array<double, 3>> p;
    for (const auto& c : clusters) p.insert(p.end(), c.begin(), c.end());
    return si::estimate_intrinsic_dimension(p, si::Knn_3(p));
  };
  EXPECT_EQ(dimension({flat(0), solid(1000)}), 2);
  EXPECT_EQ(dimension({solid(0), flat(1000)}), 2);
  EXPECT_EQ(dimension({flat(0), solid(1000), solid(2000)}), 3);
  EXPECT_EQ(dimension({flat(0), flat(1000), solid(2000)}), 2);
  EXPECT_EQ(dimension({solid(0), solid(1000)}), 3);
}

// The j < n of least score(j), ties to the lowest j, NaN counted as infinity; best receives the score.
template <class Score>
std::uint32_t brute_force_minimum(std::size_t n, Score&& score, double& best) {
  best = std::numeric_limits<double>::infinity();
  std::uint32_t arg = std::numeric_limits<std::uint32_t>::max();
  for (std::uint32_t j = 0; j < n; ++j) {
    double s = score(j);
    if (std::isnan(s)) s = std::numeric_limits<double>::infinity();
    if (s < best || (s == best && j < arg)) {
      best = s;
      arg = j;
    }
  }
  return arg;
}

// A query of the brute-force tests below: query t is a random point of [-0.5, 1.5]^D times unit, every 4th
// one a copy of a point of p; its score of point j is distance(x, p[j]) / scale + extra[j], NaN at every 7th
// point in every 5th query.
template <int D, class Distance>
struct Random_query {
  using Point = std::array<double, D>;
  Point x;
  bool with_nan;
  const std::vector<Point>* p;
  const std::vector<double>* extra;
  const Distance* distance;
  double scale;

  template <class Rng>
  Random_query(const std::vector<Point>& points, const std::vector<double>& extras, const Distance& d,
               double scale_, double unit, int t, Rng& rng)
      : with_nan(t % 5 == 0), p(&points), extra(&extras), distance(&d), scale(scale_) {
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < D; ++k) x[k] = (-0.5 + 2 * u(rng)) * unit;
    if (t % 4 == 0) x = points[std::size_t(rng() % points.size())];
  }
  double operator()(std::uint32_t j) const {
    if (with_nan && j % 7 == 0) return std::numeric_limits<double>::quiet_NaN();
    return (*distance)(x, (*p)[j]) / scale + (*extra)[j];
  }
};

// From a mutation audit of ring_grid.h: Ring_grid::nearest() against a brute-force minimum of the score
// (ties to the lowest index, NaN as infinity), for scores bounded below by distance / scale with scales far
// from 1 either way, queries inside and outside the frame, copies of points (ties) and a frame that does not
// hold every point; and for_each_within() against the points within the radius.
template <int D>
void expect_ring_grid_matches_brute_force(unsigned seed) {
  using Point = std::array<double, D>;
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p(400);
  for (auto& x : p)
    for (int k = 0; k < D; ++k) x[k] = u(rng);
  for (std::size_t i = 300; i < p.size(); ++i) p[i] = p[i - 300];  // copies of the first 100
  std::vector<double> extra(p.size());
  Point lo{}, hi{};
  for (int k = 0; k < D; ++k) hi[k] = k == 0 ? 0.8 : 1.0;  // points beyond the frame along x
  si::Ring_grid<D> grid(lo, hi, double(p.size()));
  grid.assign(p);
  auto distance = [](const Point& a, const Point& b) {
    double s = 0;
    for (int k = 0; k < D; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(s);
  };
  for (const double scale : {0.01, 1.0, 100.0}) {
    for (std::size_t i = 0; i < extra.size(); ++i) extra[i] = i % 3 == 0 ? 0.0 : 3 * u(rng);
    for (std::size_t i = 300; i < p.size(); ++i) extra[i] = extra[i - 300];  // equal scores: ties
    for (int t = 0; t < 200; ++t) {
      const Random_query<D, decltype(distance)> score(p, extra, distance, scale, 1.0, t, rng);
      const Point& x = score.x;
      double best_brute;
      const std::uint32_t arg_brute = brute_force_minimum(p.size(), score, best_brute);
      double best = 0;
      EXPECT_EQ(grid.nearest(x, scale, score, best), arg_brute) << "scale " << scale << ", query " << t;
      EXPECT_EQ(best, best_brute) << "scale " << scale << ", query " << t;
      const double radius = 0.05 + 0.2 * u(rng);
      std::vector<std::uint32_t> found, near;
      grid.for_each_within(x, radius, [&](std::uint32_t j) {
        if (distance(x, p[j]) <= radius) found.push_back(j);
      });
      std::sort(found.begin(), found.end());
      for (std::uint32_t j = 0; j < p.size(); ++j)
        if (distance(x, p[j]) <= radius) near.push_back(j);
      EXPECT_EQ(found, near) << "radius " << radius << ", query " << t;
    }
  }
  // Every score NaN (infinite): a point is still found, the lowest index.
  double best = 0;
  EXPECT_EQ(grid.nearest(
                p[5], 1.0, [](std::uint32_t) { return std::numeric_limits<double>::quiet_NaN(); }, best),
            0u);
  EXPECT_EQ(best, std::numeric_limits<double>::infinity());
}

TEST(RingGrid, NearestAndWithinMatchBruteForce) {
  expect_ring_grid_matches_brute_force<2>(3);
  expect_ring_grid_matches_brute_force<3>(4);
}

// Nearest_tree::nearest() against a brute-force minimum of the score (ties to the lowest index, NaN as
// infinity), without a hint and with hints anywhere (the answer must not depend on them), for points in a
// small cluster and a few far away (most queries far from most points), copies (ties), one point, points on
// a line and all points at one place; each also scaled by 2^-530 with scores that are distances (squared
// distances below the normal range: the tree then compares distances, not their squares). Also the ring
// search cut after 0, 1 or 2 rings or 0 or 5 scores and finished by the tree with the rings' answer as the
// hint, as the discrete Lloyd assignment does.
template <int D>
void expect_nearest_tree_matches_brute_force(unsigned seed) {
  using Point = std::array<double, D>;
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  enum Layout { cluster, one, line, one_place };
  for (const bool tiny : {false, true})
    for (const Layout layout : {cluster, one, line, one_place}) {
      const double unit = tiny ? 0x1p-530 : 1.0;  // 2^-530: about 3e-160
      // The distance, its squares taken in units of `unit` (exactly): they do not underflow.
      auto distance = [unit](const Point& a, const Point& b) {
        double s = 0;
        for (int k = 0; k < D; ++k) s += (a[k] - b[k]) / unit * ((a[k] - b[k]) / unit);
        return std::sqrt(s) * unit;
      };
      std::vector<Point> p(layout == one ? 1 : 300);
      for (std::size_t i = 0; i < p.size(); ++i)
        for (int k = 0; k < D; ++k) {
          switch (layout) {
            case cluster:  // a cluster in [0.4, 0.5]^D, every tenth point anywhere in [0, 1]^D
              p[i][k] = i % 10 == 0 ? u(rng) : 0.4 + 0.1 * u(rng);
              break;
            case line:  // on a line (the first axis), on a lattice of step 1/64
              p[i][k] = k == 0 ? double(rng() % 64) / 64 : 0.5;
              break;
            default:
              p[i][k] = 0.25;
          }
        }
      for (auto& x : p)
        for (int k = 0; k < D; ++k) x[k] *= unit;
      if (layout == cluster)
        for (std::size_t i = 250; i < p.size(); ++i) p[i] = p[i - 250];  // copies of the first 50
      const si::Nearest_tree<D> tree(p);
      Point lo{}, hi{};
      for (int k = 0; k < D; ++k) hi[k] = unit;
      si::Ring_grid<D> grid(lo, hi, double(p.size()));
      grid.assign(p);
      std::vector<double> extra(p.size());
      for (const double scale : {0.01, 1.0, 100.0}) {
        for (std::size_t i = 0; i < extra.size(); ++i) extra[i] = i % 3 == 0 || tiny ? 0.0 : 3 * u(rng);
        if (layout == cluster)
          for (std::size_t i = 250; i < p.size(); ++i) extra[i] = extra[i - 250];  // equal scores: ties
        for (int t = 0; t < 150; ++t) {
          const Random_query<D, decltype(distance)> score(p, extra, distance, scale, unit, t, rng);
          const Point& x = score.x;
          double best_brute;
          const std::uint32_t arg_brute = brute_force_minimum(p.size(), score, best_brute);
          const std::uint32_t random_hint = std::uint32_t(rng() % p.size());
          for (const std::uint32_t hint : {si::Nearest_tree<D>::none, random_hint, arg_brute}) {
            double best = 0;
            EXPECT_EQ(tree.nearest(x, scale, score, best, hint), arg_brute)
                << "layout " << layout << (tiny ? " (tiny)" : "") << ", scale " << scale << ", query " << t
                << ", hint " << hint;
            EXPECT_EQ(best, best_brute)
                << "layout " << layout << (tiny ? " (tiny)" : "") << ", scale " << scale << ", query " << t;
          }
          for (const std::int64_t rings : {0, 1, 2})
            for (const std::size_t most : {std::size_t(0), std::size_t(5), p.size()}) {
              double best = 0;
              bool complete = false;
              std::uint32_t j = grid.nearest(x, scale, score, best, rings, most, complete);
              if (!complete) j = tree.nearest(x, scale, score, best, j);
              EXPECT_EQ(j, arg_brute) << "layout " << layout << (tiny ? " (tiny)" : "") << ", " << rings
                                      << " rings, " << most << " scores, query " << t;
              EXPECT_EQ(best, best_brute) << "layout " << layout << (tiny ? " (tiny)" : "") << ", " << rings
                                          << " rings, " << most << " scores, query " << t;
            }
        }
      }
      // Every score NaN (infinite): a point is still found, the lowest index.
      double best = 0;
      EXPECT_EQ(tree.nearest(
                    p[0], 1.0, [](std::uint32_t) { return std::numeric_limits<double>::quiet_NaN(); }, best),
                0u);
      EXPECT_EQ(best, std::numeric_limits<double>::infinity());
    }
  // No points: none.
  const si::Nearest_tree<D> empty(std::vector<Point>{});
  double best = 0;
  EXPECT_EQ(empty.nearest(
                Point{}, 1.0, [](std::uint32_t) { return 0.0; }, best),
            si::Nearest_tree<D>::none);
  EXPECT_EQ(best, std::numeric_limits<double>::infinity());
}

TEST(NearestTree, NearestMatchesBruteForceWhateverTheHint) {
  expect_nearest_tree_matches_brute_force<2>(5);
  expect_nearest_tree_matches_brute_force<3>(6);
}

TEST(NearestTree, LeavesHoldAtMostFourPoints) {
  // 1000 points (also 1000 copies of one point): halving down to leaves of at most 4 gives 511 nodes
  // (256 leaves of 3 or 4); a tree of single points would have 1999.
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(7);
  std::vector<std::array<double, 2>> p(1000), same(1000, std::array<double, 2>{3, 4});
  for (auto& x : p) x = {double(rng() % 1000), double(rng() % 1000)};
  EXPECT_EQ(si::Nearest_tree<2>(p).number_of_nodes(), 511u);
  EXPECT_EQ(si::Nearest_tree<2>(same).number_of_nodes(), 511u);
  EXPECT_EQ(si::Nearest_tree<2>(std::vector<std::array<double, 2>>(4)).number_of_nodes(), 1u);
  EXPECT_EQ(si::Nearest_tree<2>(std::vector<std::array<double, 2>>(5)).number_of_nodes(), 3u);
}

// From a mutation audit of Uniform_grid.h. A packed frame over too many cells for a dense array (about 10^6
// cells for about 1,300 points) keeps its cells in a hash map of packed keys: the candidates of a query are
// the points of the 3^D cells around its cell, each once, cells in key order (the first axis outermost) and
// points by index within a cell, as the dense array has them; a query far outside the box (clamped to the
// border of the key range) finds nothing. Checked against cells computed by the test (floor(p / cell), a
// point at the origin), with clusters of points in one cell and the cells at the bottom of the last axis
// filled.
template <int D>
void expect_sparse_packed_candidates(unsigned seed) {
  using Point = std::array<double, D>;
  using Cell = std::array<std::int64_t, D>;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double r = D == 2 ? 1e-3 : 1e-2;
  std::vector<Point> p(1);  // the origin: the box's low corner
  for (int i = 0; i < 200; ++i) {
    Point x;
    for (int k = 0; k < D; ++k) x[k] = u(rng);
    p.push_back(x);
    if (i % 10 == 0)  // a cluster in one cell, interleaved with other points by index
      for (int c = 1; c < 4; ++c) {
        Point y = x;
        y[0] = std::min(y[0] + 1e-7 * c, 1.0);
        p.push_back(y);
      }
  }
  // One point in each cell (i, 0) (2D) or (i, j, 0) (3D, i and j near the middle) at the bottom of the last
  // axis.
  const int from = D == 2 ? 0 : 45, to = D == 2 ? 1000 : 56;
  for (int i = from; i < to; ++i)
    for (int j = D == 2 ? 0 : from; j < (D == 2 ? 1 : to); ++j) {
      Point x{};
      x[0] = (i + 0.5) * r;
      if (D == 3) x[1] = (j + 0.5) * r;
      x[D - 1] = 0.25 * r;
      p.push_back(x);
    }
  Point corner;
  corner.fill(1.0);
  p.push_back(corner);
  const Grid_frame<D> frame(p, r);
  ASSERT_FALSE(frame.hashed());
  ASSERT_FALSE(FeatureRecon::internal::use_dense_cells(frame, p.size()));
  const Uniform_grid<D> grid(p, r);
  auto cell_of = [&](const Point& x) {
    Cell c;
    for (int k = 0; k < D; ++k) c[k] = static_cast<std::int64_t>(std::floor(x[k] / r));
    return c;
  };
  std::vector<Point> queries(p.begin(), p.end());
  for (int k = 0; k < D; ++k)
    for (const double far : {1e300, -1e300, 1e9}) {
      Point q;
      q.fill(0.5);
      q[k] = far;
      queries.push_back(q);
    }
  for (std::size_t t = 0; t < queries.size(); ++t) {
    const Point& q = queries[t];
    bool inside = true;
    for (int k = 0; k < D; ++k) inside = inside && std::abs(q[k]) < 10;
    std::vector<std::uint32_t> expected, got;
    if (inside) {
      const Cell cq = cell_of(q);
      std::vector<std::pair<Cell, std::uint32_t>> near;
      for (std::uint32_t j = 0; j < p.size(); ++j) {
        const Cell cj = cell_of(p[j]);
        bool adjacent = true;
        for (int k = 0; k < D; ++k) adjacent = adjacent && std::abs(cj[k] - cq[k]) <= 1;
        if (adjacent) near.push_back({cj, j});
      }
      std::sort(near.begin(), near.end());  // cells lexicographically (the first axis outermost), then index
      for (const auto& cj : near) expected.push_back(cj.second);
    }
    grid.for_each_candidate(q, [&](std::uint32_t j) { got.push_back(j); });
    EXPECT_EQ(got, expected) << "query " << t;
  }
}

TEST(UniformGrid, SparsePackedCellsVisitInKeyOrderAndOnce) {
  expect_sparse_packed_candidates<2>(11);
  expect_sparse_packed_candidates<3>(12);
}

// Cells keep their side whenever the box holds more than 2^20 of them along an axis, along the last axis too
// (2,000 points in a 0.1 x 30,000 strip, 3 10^6 cells of side 0.01 along y; in 3D along z), and for a tiny
// cell (1e-300 over a unit square: cells of the box's extent / 2^60, still one point a cell). A cap on the
// cells per axis, or cells of 1e-300 clamped to 2^62, put most points in one row or one cell.
TEST(UniformGrid, CellsKeepTheirSideAlongTheLastAxisAndForATinyCell) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 2>> strip(2000);
  for (auto& q : strip) q = {0.1 * u(rng), 3e4 * u(rng)};
  expect_exact_candidates<2>(strip, 0.01, 20);
  std::vector<std::array<double, 3>> pillar(2000);
  for (auto& q : pillar) q = {0.1 * u(rng), 0.1 * u(rng), 3e4 * u(rng)};
  expect_exact_candidates<3>(pillar, 0.01, 20);
  std::vector<std::array<double, 2>> square(1000);
  for (auto& q : square) q = {u(rng), u(rng)};
  const Uniform_grid<2> grid(square, 1e-300);
  EXPECT_GT(grid.cell_size(), 0.0);
  std::size_t largest = 0;
  for (std::uint32_t i = 0; i < square.size(); ++i) {
    std::vector<std::uint32_t> got;
    grid.for_each_candidate(square[i], [&](std::uint32_t j) { got.push_back(j); });
    EXPECT_NE(std::find(got.begin(), got.end(), i), got.end()) << i;
    largest = std::max(largest, got.size());
  }
  EXPECT_LE(largest, 2u);
}

// From a mutation audit of Uniform_grid.h: a point beyond the top of the box along any axis is refused as one
// below it is (its cell index would alias a cell of the next row).
TEST(UniformGrid, DenseDynamicGridRefusesAPointBeyondTheTopOfItsBox) {
  for (const std::array<double, 2> outside :
       {std::array<double, 2>{0.5, 1.15}, std::array<double, 2>{1.15, 0.5}}) {
    std::vector<std::array<double, 2>> p{{0, 0}, {1, 1}, {0.65, 0.05}};
    Dynamic_grid<2> grid(p, 0.1, 100);
    grid.insert(2);
    p.push_back(outside);
    EXPECT_THROW(grid.insert(3), std::out_of_range) << outside[0] << " " << outside[1];
    std::vector<std::uint32_t> got;
    grid.for_each_candidate({0.65, 0.05}, [&](std::uint32_t j) { got.push_back(j); });
    EXPECT_EQ(got, (std::vector<std::uint32_t>{2}));
  }
}

namespace {
// Every point within `r` of each query is a candidate exactly once, of the grid built at once and of the one
// filled point by point (the far points last), and no candidate lies farther than the 3^D cells around the
// query.
template <int D>
void expect_candidates_at(const std::vector<std::array<double, D>>& p, double r,
                          const std::vector<std::array<double, D>>& queries) {
  const Uniform_grid<D> grid(p, r);
  Dynamic_grid<D> dynamic(p, r);
  for (std::uint32_t i = 0; i < p.size(); ++i) dynamic.insert(i);
  for (std::size_t t = 0; t < queries.size(); ++t) {
    const auto& q = queries[t];
    for (int which = 0; which < 2; ++which) {
      std::vector<std::uint32_t> candidates, near;
      auto take = [&](std::uint32_t j) { candidates.push_back(j); };
      if (which == 0)
        grid.for_each_candidate(q, take);
      else
        dynamic.for_each_candidate(q, take);
      std::sort(candidates.begin(), candidates.end());
      EXPECT_TRUE(std::adjacent_find(candidates.begin(), candidates.end()) == candidates.end())
          << "query " << t;
      for (std::uint32_t j : candidates) {
        double d2 = 0;
        for (int k = 0; k < D; ++k) d2 += (p[j][k] - q[k]) * (p[j][k] - q[k]);
        EXPECT_LT(d2, 4 * D * r * r) << "query " << t << " candidate " << j;  // within the 3^D cells
        if (d2 <= r * r) near.push_back(j);
      }
      EXPECT_EQ(near, within<D>(p, q, r)) << "query " << t << (which == 0 ? " (grid)" : " (dynamic)");
    }
  }
}

// The points and, beside each, points a little off it in every direction (across the cells' borders).
template <int D>
std::vector<std::array<double, D>> queries_around(const std::vector<std::array<double, D>>& p, double r,
                                                  std::size_t step) {
  std::vector<std::array<double, D>> q;
  for (std::size_t i = 0; i < p.size(); i += step) {
    q.push_back(p[i]);
    for (int k = 0; k < D; ++k)
      for (const double s : {-0.9, 0.9}) {
        q.push_back(p[i]);
        q.back()[k] += s * r;
      }
  }
  return q;
}
}  // namespace

// A few points far from the others: the box of all points has too many cells for an array (hashed keys, or
// packed ones over too many cells), and the grids keep the cells of a core box around the bulk in an array,
// the others in a hash map (set_core(); before, all in the hash map: dart throwing beside an outlier at 1e7
// ran at a third of its speed). The core holds the bulk, and every point within the cell size of a query is a
// candidate exactly once: queries on every point of the bulk's border, inside it, among the far points (a
// single one, a cluster of 2 % of the points, one just beyond the bulk), and just off each of them.
TEST(UniformGrid, CoreCellsBesideFarOutliers) {
  using FeatureRecon::internal::use_core_cells;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  // 2-D, hashed keys: 4,000 points in the unit square; 80 (2 %) in a cluster 0.01 wide at (5e6, -2e6); single
  // ones at 1e7 and 3e6 along each axis and just beyond the square.
  std::vector<std::array<double, 2>> p(4000);
  for (auto& q : p) q = {u(rng), u(rng)};
  for (int i = 0; i < 80; ++i) p.push_back({5e6 + 0.01 * u(rng), -2e6 + 0.01 * u(rng)});
  p.push_back({1e7, 0});
  p.push_back({0.5, 3e6});
  p.push_back({1.3, 0.5});
  Grid_frame<2> frame(p, 0.01);
  ASSERT_TRUE(frame.hashed());
  ASSERT_TRUE(use_core_cells(frame, p, p.size()));
  ASSERT_TRUE(frame.has_core());
  EXPECT_LE(frame.cells(), 65536.0);
  std::size_t in_core = 0;
  for (const auto& q : p) in_core += frame.dense_index(frame.cell_of(q)) >= 0;
  EXPECT_EQ(in_core, 4001u);  // the square (widened by half its width, to about 1.37) and (1.3, 0.5)
  std::vector<std::array<double, 2>> border;
  for (const auto& q : p)
    if (std::min({q[0], q[1], 1 - q[0], 1 - q[1]}) < 0.02 || q[0] > 1) border.push_back(q);
  auto queries = queries_around<2>(border, 0.01, 1);
  for (const auto& q : queries_around<2>(p, 0.01, 11)) queries.push_back(q);
  expect_candidates_at<2>(p, 0.01, queries);
  // 3-D, packed keys over too many cells: 20,000 points in the unit cube with cells of 0.05 (8,000 cells) and
  // one at (50, 0, 0) (400,000 cells in the box of all).
  std::vector<std::array<double, 3>> s(20000);
  for (auto& q : s) q = {u(rng), u(rng), u(rng)};
  s.push_back({50, 0, 0});
  s.push_back({49.97, 0.01, 0.02});
  Grid_frame<3> packed(s, 0.05);
  ASSERT_FALSE(packed.hashed());
  ASSERT_FALSE(FeatureRecon::internal::use_dense_cells(packed, s.size()));
  ASSERT_TRUE(use_core_cells(packed, s, s.size()));
  in_core = 0;
  for (const auto& q : s) in_core += packed.dense_index(packed.cell_of(q)) >= 0;
  EXPECT_EQ(in_core, 20000u);
  expect_candidates_at<3>(s, 0.05, queries_around<3>(s, 0.05, 37));
  expect_candidates_at<3>(s, 0.05, queries_around<3>({s[20000], s[20001], {1, 1, 1}, {0, 0, 0}}, 0.05, 1));
  // No core: fewer than 64 points, a bulk whose own box has too many cells, or a curve that occupies fewer
  // than 1/64 of the cells of every core that fits (20,000 points on a diagonal, cells of 0.004: about 500 of
  // 63,000 cells), whose empty cells cost more than the hash map (the hash map alone).
  std::vector<std::array<double, 2>> curve(20000);
  for (std::size_t i = 0; i < curve.size(); ++i) curve[i] = {i / 20000.0, i / 20000.0 + 1e-3 * u(rng)};
  curve.push_back({1e7, 0});
  Grid_frame<2> curve_frame(curve, 0.004);
  EXPECT_FALSE(use_core_cells(curve_frame, curve, curve.size()));
  EXPECT_FALSE(curve_frame.has_core());
  expect_candidates_at<2>(curve, 0.004, queries_around<2>(curve, 0.004, 97));
  std::vector<std::array<double, 2>> few(p.begin(), p.begin() + 62);
  few.push_back({1e7, 0});
  Grid_frame<2> few_frame(few, 0.01);
  EXPECT_FALSE(use_core_cells(few_frame, few, few.size()));
  expect_candidates_at<2>(few, 0.01, queries_around<2>(few, 0.01, 1));
  std::vector<std::array<double, 2>> fine(p.begin(), p.begin() + 500);
  fine.push_back({1e7, 0});
  Grid_frame<2> fine_frame(fine, 1e-4);
  EXPECT_FALSE(use_core_cells(fine_frame, fine, fine.size()));
  EXPECT_FALSE(fine_frame.has_core());
  expect_candidates_at<2>(fine, 1e-4, queries_around<2>(fine, 1e-4, 3));
}

// A grid in a ready frame (the elimination's stages order their points by the frame's cells first) finds the
// same candidates as one that chooses its frame; with assertions on, a frame of other positions or a flag
// that is not use_core_cells()'s is refused.
TEST(UniformGrid, AReadyFrameMustBeTheFrameOfThePoints) {
  using FeatureRecon::internal::Uniform_grid;
  using FeatureRecon::internal::use_core_cells;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 2>> p(3000);
  for (auto& q : p) q = {u(rng), u(rng)};
  p.push_back({1e7, 0});
  Grid_frame<2> frame(p, 0.01);
  const bool dense = use_core_cells(frame, p, p.size());
  ASSERT_TRUE(dense);
  std::vector<std::array<double, 2>> reversed(p.rbegin(), p.rend());  // the frame depends on the set alone
  const Uniform_grid<2> ready(reversed, frame, dense), own(reversed, 0.01);
  for (const auto& q : queries_around<2>(p, 0.01, 13)) {
    std::vector<std::uint32_t> a, b;
    ready.for_each_candidate(q, [&](std::uint32_t j) { a.push_back(j); });
    own.for_each_candidate(q, [&](std::uint32_t j) { b.push_back(j); });
    ASSERT_EQ(a, b);
  }
  EXPECT_THROW(Uniform_grid<2>(p, frame, !dense), FeatureRecon::Precondition_error);
  std::vector<std::array<double, 2>> moved = p;
  moved[5][0] = -0.5;  // widens the bounding box
  EXPECT_THROW(Uniform_grid<2>(moved, frame, dense), FeatureRecon::Precondition_error);
}

// A dynamic grid with a core box takes points beyond the core (into its hash map), and the torus look-up of a
// grid with a core finds the pairs across the seam whose other end lies beyond the core: a torus of periods
// (1e7, 1) whose points lie in [0, 1)^2 but for a few near x = 1e7, the nearest images of points near x = 0.
TEST(UniformGrid, CoreCellsOnATorusAndFilledPointByPoint) {
  namespace si = FeatureRecon::sampling::internal;
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(0, 1);
  const std::array<double, 2> period{1e7, 1};
  std::vector<std::array<double, 2>> p(3000);
  for (auto& q : p) q = {u(rng), u(rng)};
  for (int i = 0; i < 20; ++i) p.push_back({1e7 - 0.05 * u(rng), u(rng)});
  const double r = 0.03, look = si::torus_search_reach(r, 1e7);
  const Uniform_grid<2> grid(p, look);
  ASSERT_TRUE(grid.frame().has_core());
  Dynamic_grid<2> dynamic(p, look);
  for (std::uint32_t i = 0; i < p.size(); ++i) dynamic.insert(i);
  std::size_t across = 0;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    std::vector<std::uint32_t> expected, got, got_dynamic;
    for (std::uint32_t j = 0; j < p.size(); ++j)
      if (si::torus_squared_distance(p[i], p[j], period) < r * r) expected.push_back(j);
    auto take = [&](std::vector<std::uint32_t>& out) {
      return [&](std::uint32_t j, int shift) {
        if (shift == si::nearest_image_shift(p[i], p[j], period) &&
            si::torus_squared_distance(p[i], p[j], period) < r * r)
          out.push_back(j);
      };
    };
    si::for_each_torus_candidate(grid, p[i], look, take(got), {}, period);
    si::for_each_torus_candidate(dynamic, p[i], look, take(got_dynamic), {}, period);
    std::sort(got.begin(), got.end());
    std::sort(got_dynamic.begin(), got_dynamic.end());
    EXPECT_EQ(got, expected) << i;
    EXPECT_EQ(got_dynamic, expected) << i;
    for (const std::uint32_t j : expected) across += (i < 3000) != (j < 3000);
  }
  EXPECT_GT(across, 0u);  // pairs across the seam, found from both sides
}
