// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/map_comparison.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "io/featurerecon_io.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using FeatureRecon::test::throws_with;

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;

namespace {
Embedded_graph_2 grid_map(int n, double spacing, double dx = 0, double dy = 0) {
  Embedded_graph_2 g;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) g.positions.push_back({i * spacing + dx, j * spacing + dy});
  for (Vertex_index i = 0; i < Vertex_index(n); ++i)
    for (Vertex_index j = 0; j < Vertex_index(n); ++j) {
      if (i + 1 < Vertex_index(n)) g.edges.push_back({i * n + j, (i + 1) * n + j});
      if (j + 1 < Vertex_index(n)) g.edges.push_back({i * n + j, i * n + j + 1});
    }
  return g;
}

Embedded_graph_2 load(const std::string& name) {
  const std::string dir = std::string(FEATURERECON_TEST_DATA_DIR) + "/chicago_maps/chicago_";
  const io::Map_file m = io::read_map(dir + name + "_vertices.txt", dir + name + "_edges.txt");
  Embedded_graph_2 g;
  g.positions = m.positions;
  for (const auto& e : m.edges) g.edges.push_back({e[0], e[1]});
  return g;
}
}  // namespace

TEST(MapComparison, SamplingSpacingAndCounts) {
  // A single 100 m segment: 21 samples every 5 m (root at its middle), bearing 90 degrees (east).
  Embedded_graph_2 seg;
  seg.positions = {{0, 0}, {100, 0}};
  seg.edges = {{0, 1}, {1, 0}, {0, 0}};  // the repeated reversed edge and the self-loop are ignored
  const auto s = sample_map(seg, 5.0);
  EXPECT_EQ(s.size(), 21u);
  for (const auto& x : s) {
    const double rem = std::fmod(x.position[0], 5.0);
    EXPECT_LT(std::min(rem, 5.0 - rem), 1e-9) << x.position[0];
  }
  EXPECT_DOUBLE_EQ(s[0].bearing, 90.0);
  // A grid of 4x4 blocks of 100 m: total length 4000 m, about one sample per 5 m.
  const auto g = sample_map(grid_map(5, 100.0), 5.0);
  EXPECT_NEAR(static_cast<double>(g.size()), 800.0, 40.0);
  EXPECT_THROW(sample_map(seg, 0.0), std::invalid_argument);
  // Infinity is > 0: the message says the rule the check applies.
  EXPECT_EQ(FeatureRecon::test::invalid_argument_message(
                [&] { sample_map(seg, std::numeric_limits<double>::infinity()); }),
            "sample_map: interval must be finite and > 0, got inf");
  Embedded_graph_2 bad = seg;
  bad.edges = {{0, 5}};
  EXPECT_THROW(sample_map(bad, 5.0), std::invalid_argument);
}

TEST(MapComparison, EdgesOfLengthZeroGiveNoSample) {
  // Vertices 1 and 2 share a position: the edge between them has no bearing. The walk passes it (the 5 m
  // spacing continues onto the north-going edge) and every sample carries the bearing of a real edge.
  Embedded_graph_2 g;
  g.positions = {{0, 0}, {20, 0}, {20, 0}, {20, 20}};
  g.edges = {{0, 1}, {1, 2}, {2, 3}};
  const auto s = sample_map(g, 5.0);
  ASSERT_EQ(s.size(), 9u);  // 40 m of edges, samples 5 m apart along the path (the corner once)
  std::size_t east = 0, north = 0;
  for (const auto& x : s) {
    if (x.bearing == 90.0) {
      ++east;
      EXPECT_EQ(x.position[1], 0.0);
    } else {
      EXPECT_EQ(x.bearing, 0.0);
      EXPECT_EQ(x.position[0], 20.0);
      EXPECT_GT(x.position[1], 0.0);
      ++north;
    }
  }
  EXPECT_EQ(east, 5u);
  EXPECT_EQ(north, 4u);
  // A component of length 0 gives nothing (it gave one sample of heading 0, north), so a map of it matches
  // nothing, not even a north-south street through it.
  Embedded_graph_2 point;
  point.positions = {{0, 0}, {0, 0}};
  point.edges = {{0, 1}};
  EXPECT_TRUE(sample_map(point, 5.0).empty());
  Embedded_graph_2 street;
  street.positions = {{0, -50}, {0, 50}};
  street.edges = {{0, 1}};
  const Map_comparison_result r = compare_maps(street, point);
  EXPECT_EQ(r.reconstruction_samples, 0u);
  EXPECT_EQ(r.matched, 0u);
}

TEST(MapComparison, IdenticalShiftedAndPerpendicularMaps) {
  const Embedded_graph_2 a = grid_map(5, 100.0);
  const Map_comparison_result same = compare_maps(a, a);
  EXPECT_EQ(same.matched, same.ground_truth_samples);
  EXPECT_DOUBLE_EQ(same.precision, 1.0);
  EXPECT_DOUBLE_EQ(same.recall, 1.0);
  EXPECT_DOUBLE_EQ(same.f_score, 1.0);
  // Shifted diagonally by 20 m: every sample is more than 15 m from the other map's parallel streets.
  EXPECT_EQ(compare_maps(a, grid_map(5, 100.0, 20.0, 20.0)).matched, 0u);
  // Shifted by 10 m: within the threshold.
  EXPECT_GT(compare_maps(a, grid_map(5, 100.0, 10.0, 0.0)).recall, 0.8);
  // Same place, perpendicular direction: a north-south segment against an east-west one crossing it.
  Embedded_graph_2 ns, ew;
  ns.positions = {{0, -50}, {0, 50}};
  ns.edges = {{0, 1}};
  ew.positions = {{-50, 0}, {50, 0}};
  ew.edges = {{0, 1}};
  EXPECT_EQ(compare_maps(ns, ew).matched, 0u);
  // Half the map: recall about one half, precision 1.
  Embedded_graph_2 half = a;
  half.edges.resize(a.edges.size() / 2);
  const Map_comparison_result h = compare_maps(a, half);
  EXPECT_NEAR(h.precision, 1.0, 0.02);
  EXPECT_NEAR(h.recall, 0.5, 0.05);
  // Empty reconstruction.
  const Map_comparison_result none = compare_maps(a, Embedded_graph_2{});
  EXPECT_EQ(none.matched, 0u);
  EXPECT_EQ(none.precision, 0.0);
  EXPECT_EQ(none.f_score, 0.0);
  Map_comparison_options bad;
  bad.match_distance = -1;
  EXPECT_THROW(compare_maps(a, a, bad), std::invalid_argument);
}

TEST(MapComparison, KeptSamplesShowWhatMatched) {
  // A 300 m street against a reconstruction of its first 150 m plus a parallel 150 m line 40 m away: the kept
  // samples say which truth samples were missed (the second half) and which reconstruction samples are
  // spurious (the far line); partners are one to one, within the threshold and agree with the counts.
  Embedded_graph_2 truth, rec;
  truth.positions = {{0, 0}, {300, 0}};
  truth.edges = {{0, 1}};
  rec.positions = {{0, 2}, {150, 2}, {0, 40}, {150, 40}};
  rec.edges = {{0, 1}, {2, 3}};
  Map_comparison_options o;
  EXPECT_TRUE(compare_maps(truth, rec, o).ground_truth_partner.empty());  // nothing kept unless asked
  o.keep_samples = true;
  const Map_comparison_result r = compare_maps(truth, rec, o);
  ASSERT_EQ(r.ground_truth_sample_list.size(), r.ground_truth_samples);
  ASSERT_EQ(r.reconstruction_sample_list.size(), r.reconstruction_samples);
  ASSERT_EQ(r.ground_truth_partner.size(), r.ground_truth_samples);
  std::vector<char> used(r.reconstruction_samples, 0);
  std::size_t matched = 0;
  for (std::size_t h = 0; h < r.ground_truth_partner.size(); ++h) {
    const std::int64_t g = r.ground_truth_partner[h];
    const auto& p = r.ground_truth_sample_list[h].position;
    if (g < 0) {
      EXPECT_GT(p[0], 140.0) << "truth sample " << h << " on the reconstructed half was missed";
      continue;
    }
    ++matched;
    EXPECT_FALSE(used[static_cast<std::size_t>(g)]) << "reconstruction sample " << g << " matched twice";
    used[static_cast<std::size_t>(g)] = 1;
    const auto& q = r.reconstruction_sample_list[static_cast<std::size_t>(g)].position;
    EXPECT_LE(std::hypot(p[0] - q[0], p[1] - q[1]), o.match_distance);
    EXPECT_LT(q[1], 10.0) << "a sample of the far line matched";
  }
  EXPECT_EQ(matched, r.matched);
  EXPECT_NEAR(r.recall, 0.5, 0.03);
  EXPECT_NEAR(r.precision, 0.5, 0.03);
}

TEST(MapComparison, UnmatchedSamplesAreExplained) {
  // Truth: two parallel streets 10 m apart (y = 0 and y = 10, x in [0, 300]). Reconstruction: one line along
  // y = 0 for x in [0, 300] (the second street is 'taken'), a line 20 m off the truth for x in [400, 500]
  // next to a truth street there ('offset'), a north-south line crossing the truth at x = 250 ('crossing'),
  // and a line far away
  // ('absent'). Truth x in [600, 700] has no reconstruction near it ('absent').
  Embedded_graph_2 truth, rec;
  truth.positions = {{0, 0}, {300, 0}, {0, 10}, {300, 10}, {400, 0}, {500, 0}, {600, 0}, {700, 0}};
  truth.edges = {{0, 1}, {2, 3}, {4, 5}, {6, 7}};
  rec.positions = {{0, 0}, {300, 0}, {400, 20}, {500, 20}, {250, -40}, {250, 40}, {0, 1000}, {100, 1000}};
  rec.edges = {{0, 1}, {2, 3}, {4, 5}, {6, 7}};
  Map_comparison_options o;
  EXPECT_THROW(explain_unmatched_samples(compare_maps(truth, rec, o), o), std::invalid_argument);
  o.keep_samples = true;
  const Map_comparison_result r = compare_maps(truth, rec, o);
  const Unmatched_samples_breakdown b = explain_unmatched_samples(r, o);
  const Unmatched_sample_counts& m = b.missed;
  const Unmatched_sample_counts& s = b.spurious;
  EXPECT_EQ(m.taken + m.offset + m.crossing + m.absent, r.ground_truth_samples - r.matched);
  EXPECT_EQ(s.taken + s.offset + s.crossing + s.absent, r.reconstruction_samples - r.matched);
  EXPECT_NEAR(static_cast<double>(m.taken), 61, 2);   // the y = 10 street
  EXPECT_NEAR(static_cast<double>(m.offset), 21, 2);  // x in [400, 500]
  EXPECT_NEAR(static_cast<double>(m.absent), 21, 2);  // x in [600, 700]
  EXPECT_EQ(s.taken, 0u);
  EXPECT_NEAR(static_cast<double>(s.offset), 21, 2);
  EXPECT_GE(s.crossing, 5u);  // the crossing line's samples near the streets (the rest are 'absent')
  EXPECT_NEAR(static_cast<double>(s.absent), 21 + 17 - static_cast<double>(s.crossing), 3);
}

TEST(MapComparison, UnmatchedSamplesAgreeWithBruteForce) {
  // Random road-like maps (segments at random angles, some near-parallel copies): every unmatched sample's
  // class equals the one found by checking all samples of the other map (brute force instead of the grid).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-200, 200), a(0, 6.283185307179586), len(20, 120), off(-35, 35);
  Embedded_graph_2 truth, rec;
  for (int k = 0; k < 40; ++k) {
    const double x = u(rng), y = u(rng), t = a(rng), l = len(rng);
    const std::uint32_t i = static_cast<std::uint32_t>(truth.positions.size());
    truth.positions.push_back({x, y});
    truth.positions.push_back({x + l * std::cos(t), y + l * std::sin(t)});
    truth.edges.push_back({i, i + 1});
    if (k % 2 == 0) {  // a copy moved sideways and turned a little, or a crossing line
      const double d = off(rng), s = k % 4 == 0 ? 0.1 : 1.6;
      const std::uint32_t j = static_cast<std::uint32_t>(rec.positions.size());
      rec.positions.push_back({x - d * std::sin(t), y + d * std::cos(t)});
      rec.positions.push_back(
          {x - d * std::sin(t) + l * std::cos(t + s), y + d * std::cos(t) + l * std::sin(t + s)});
      rec.edges.push_back({j, j + 1});
    }
  }
  Map_comparison_options o;
  o.keep_samples = true;
  const Map_comparison_result r = compare_maps(truth, rec, o);
  const Unmatched_samples_breakdown b = explain_unmatched_samples(r, o);
  ASSERT_GT(r.matched, 0u);
  std::vector<std::int64_t> g_partner(r.reconstruction_samples, -1);
  for (std::size_t h = 0; h < r.ground_truth_partner.size(); ++h)
    if (r.ground_truth_partner[h] >= 0) g_partner[std::size_t(r.ground_truth_partner[h])] = std::int64_t(h);
  EXPECT_EQ(r.reconstruction_partner, g_partner);  // the two partner lists are inverse to each other
  auto brute = [&](const std::vector<Map_sample>& from, const std::vector<std::int64_t>& partner,
                   const std::vector<Map_sample>& to) {
    Unmatched_sample_counts c;
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (partner[i] >= 0) continue;
      double aligned = 1e300;
      bool any = false;
      for (const Map_sample& q : to) {
        const double d = std::hypot(q.position[0] - from[i].position[0], q.position[1] - from[i].position[1]);
        if (d > 2 * o.match_distance) continue;
        any = true;
        double diff = std::fabs(q.bearing - from[i].bearing);
        diff = std::min({diff, std::fabs(180 - diff), std::fabs(360 - diff)});
        if (diff < o.bearing_limit) aligned = std::min(aligned, d);
      }
      skeleton::internal::count_unmatched(aligned, any, o.match_distance, c);
    }
    return c;
  };
  const Unmatched_sample_counts m =
      brute(r.ground_truth_sample_list, r.ground_truth_partner, r.reconstruction_sample_list);
  const Unmatched_sample_counts s =
      brute(r.reconstruction_sample_list, g_partner, r.ground_truth_sample_list);
  EXPECT_EQ(b.missed.taken, m.taken);
  EXPECT_EQ(b.missed.offset, m.offset);
  EXPECT_EQ(b.missed.crossing, m.crossing);
  EXPECT_EQ(b.missed.absent, m.absent);
  EXPECT_EQ(b.spurious.taken, s.taken);
  EXPECT_EQ(b.spurious.offset, s.offset);
  EXPECT_EQ(b.spurious.crossing, s.crossing);
  EXPECT_EQ(b.spurious.absent, s.absent);
  // Every class occurs, so the comparison is not vacuous.
  EXPECT_GT(m.offset + s.offset, 0u);
  EXPECT_GT(m.crossing + s.crossing, 0u);
  EXPECT_GT(m.absent, 0u);
}

TEST(MapComparison, ReproducesPublishedChicagoScores) {
  // Graph-sampling scores of two published maps against the map-matched OSM ground truth (test data README).
  const Embedded_graph_2 gt = load("gt_crp");
  struct Row {
    const char* map;
    double threshold, p, r, f;
  };
  const Row rows[] = {{"james", 10, .887, .465, .610},   {"james", 15, .931, .489, .641},
                      {"james", 25, .967, .508, .666},   {"kharita", 10, .643, .707, .674},
                      {"kharita", 15, .706, .777, .740}, {"kharita", 25, .735, .808, .770}};
  for (const Row& row : rows) {
    Map_comparison_options o;
    o.match_distance = row.threshold;
    const Map_comparison_result r = compare_maps(gt, load(row.map), o);
    EXPECT_NEAR(r.precision, row.p, 0.01) << row.map << " at " << row.threshold << " m";
    EXPECT_NEAR(r.recall, row.r, 0.01) << row.map << " at " << row.threshold << " m";
    EXPECT_NEAR(r.f_score, row.f, 0.01) << row.map << " at " << row.threshold << " m";
  }
}

namespace {
Map_sample sample_at(double x, double y, double bearing) { return Map_sample{{x, y}, bearing}; }
Gps_trip trip_of(std::initializer_list<std::array<double, 2>> points) {
  Gps_trip t;
  double time = 0;
  for (const auto& p : points) t.push_back({p[0], p[1], time += 5});
  return t;
}
}  // namespace

TEST(TraceSupport, PinnedCases) {
  // One sample at the origin on an east-west street (bearing 90).
  const std::vector<Map_sample> s{sample_at(0, 0, 90)};
  auto along = [&](std::vector<Gps_trip> trips, Trace_support_options o = {}) {
    return count_trips_along(s, trips, o)[0];
  };
  EXPECT_EQ(along({trip_of({{-100, 5}, {100, 5}})}), 1u);    // eastward, 5 m beside
  EXPECT_EQ(along({trip_of({{100, -5}, {-100, -5}})}), 1u);  // westward counts too: bearings ignore direction
  EXPECT_EQ(along({trip_of({{-100, 15}, {100, 15}})}), 1u);  // exactly at the radius
  EXPECT_EQ(along({trip_of({{-100, 15.01}, {100, 15.01}})}), 0u);
  EXPECT_EQ(along({trip_of({{-100, 0}, {-15, 0}})}), 1u);  // the segment's end point is the closest point
  EXPECT_EQ(along({trip_of({{-100, 0}, {-15.01, 0}})}), 0u);
  EXPECT_EQ(along({trip_of({{0, -100}, {0, 100}})}), 0u);       // a crossing street: bearing 0 against 90
  EXPECT_EQ(along({trip_of({{-100, -100}, {100, 100}})}), 0u);  // 45 degrees off: not below the limit
  EXPECT_EQ(along({trip_of({{-100, -80}, {100, 80}})}), 1u);    // 38.7 degrees off
  EXPECT_EQ(along({trip_of({{0, 0}, {0, 0}, {0, 0}})}), 0u);    // a parked car has no bearing
  EXPECT_EQ(along({trip_of({{0, 0}})}), 0u);                    // a single fix has no segment
  EXPECT_EQ(along({Gps_trip{}}), 0u);
  // One trip passing twice (there and back) counts once; two trips count twice.
  EXPECT_EQ(along({trip_of({{-100, 5}, {100, 5}, {100, -5}, {-100, -5}})}), 1u);
  EXPECT_EQ(along({trip_of({{-100, 5}, {100, 5}}), trip_of({{100, -5}, {-100, -5}})}), 2u);
  // The options: a larger radius reaches the far trip; a 90-degree limit accepts the crossing one.
  Trace_support_options wide;
  wide.radius = 20;
  EXPECT_EQ(along({trip_of({{-100, 15.01}, {100, 15.01}})}, wide), 1u);
  Trace_support_options any;
  // differences lie in [0, 90] and must be below the limit: perpendicular still fails
  any.bearing_limit = 90;
  EXPECT_EQ(along({trip_of({{0, -100}, {0, 100}})}, any), 0u);
  any.bearing_limit = 90.5;
  EXPECT_EQ(along({trip_of({{0, -100}, {0, 100}})}, any), 1u);
  // A glitch: a fix a million kilometres away costs nothing and counts where the segment passes.
  EXPECT_EQ(along({trip_of({{-1e9, 0}, {1e9, 3}})}), 1u);
  EXPECT_EQ(along({trip_of({{-1e12, -1e12}, {1e12, -1e12}})}), 0u);
  EXPECT_EQ(along({trip_of({{-1e150, 0}, {1e150, 1}})}), 1u);
  // Segments whose length overflows a double (b - a or its square): counted where they pass, in bounded time.
  EXPECT_EQ(along({trip_of({{-1e200, 0}, {1e200, 0}})}), 1u);
  EXPECT_EQ(along({trip_of({{-1e308, 5}, {1.7e308, 5}})}), 1u);
  EXPECT_EQ(along({trip_of({{-1e308, 16}, {1.7e308, 16}})}), 0u);
  EXPECT_EQ(along({trip_of({{1e155, 0}, {0, 0}})}),
            1u);  // the walk from the far end stops at the samples' box
  EXPECT_EQ(along({trip_of({{1e155, 0}, {15.5, 0}})}), 0u);
  // Sloped segments between far-off fixes (beyond 2^44 radii, where the sample's position is lost in p - a):
  // decided exactly. Slope 1/1000 through (0, 10) passes 9.999995 m from the sample; through (0, 15.0078125),
  // 15.007805 m (every coordinate is exact in doubles); the bearing is 89.94 degrees.
  EXPECT_EQ(along({trip_of({{-1e15, 10 - 1e12}, {1e15, 10 + 1e12}})}), 1u);
  EXPECT_EQ(along({trip_of({{-1e15, 15.0078125 - 1e12}, {1e15, 15.0078125 + 1e12}})}), 0u);
  EXPECT_EQ(along({trip_of({{-1e15, 15 - 1e12}, {1e15, 15 + 1e12}})}), 1u);  // 14.9999925 m
  {
    // Samples 50 m apart on the x axis and a trip between fixes 0.8e20 and 1.1e20 m away along the direction
    // (cos 1, sin 1), which passes 3.2-3.6 km from them (CGAL's exact kernel); in doubles p - a loses the
    // samples' positions and every one of them seemed on the line.
    const double bearing = std::atan2(std::cos(1.0), std::sin(1.0)) * 180 / std::acos(-1.0);
    std::vector<Map_sample> row;
    for (int i = -5; i <= 5; ++i) row.push_back(sample_at(50.0 * i, 0, bearing));
    const std::vector<std::size_t> c =
        count_trips_along(row, {trip_of({{-0.8e20 * std::cos(1.0), -0.8e20 * std::sin(1.0)},
                                         {1.1e20 * std::cos(1.0), 1.1e20 * std::sin(1.0)}})});
    EXPECT_EQ(c, std::vector<std::size_t>(11, 0));
  }
  EXPECT_EQ(along({trip_of({{-1.7e308, -1.7e305}, {1.7e308, 1.7e305}})}), 1u);  // through the origin
  EXPECT_EQ(along({trip_of({{-1.7e308, 1.7e305}, {1.7e308, -1.7e305}})}), 1u);
  EXPECT_TRUE(count_trips_along({}, {trip_of({{0, 0}, {1, 1}})}).empty());
  // Fixes are read by time, as sample_gps_traces() reads them, not in storage order: stored along the street
  // but driven through (0, 100) in between, the trip does not drive along the sample; stored through (0, 100)
  // but driven straight along, it does.
  EXPECT_EQ(along({Gps_trip{{-100, 5, 10}, {100, 5, 30}, {0, 100, 20}}}), 0u);
  EXPECT_EQ(along({Gps_trip{{-100, 5, 1}, {0, 100, 3}, {100, 5, 2}}}), 1u);
}

TEST(TraceSupport, AgreesWithBruteForce) {
  // Random samples and random trips with long chords, repeated fixes and far-off segments against a direct
  // check of every segment of every trip.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-150, 150), b(0, 360), step(-60, 60);
  std::vector<Map_sample> samples;
  for (int i = 0; i < 400; ++i) samples.push_back(sample_at(u(rng), u(rng), b(rng)));
  std::vector<Gps_trip> trips(60);
  for (Gps_trip& t : trips) {
    double x = u(rng), y = u(rng);
    const int n = int(rng() % 12);
    for (int k = 0; k < n; ++k) {
      t.push_back({x, y, double(k)});
      if (rng() % 5 == 0) continue;  // the same place again
      x += step(rng) * (rng() % 4 == 0 ? 4 : 1);
      y += step(rng);
    }
  }
  Trace_support_options o;
  o.radius = 12;
  o.bearing_limit = 30;
  const std::vector<std::size_t> fast = count_trips_along(samples, trips, o);
  std::size_t supported = 0, multiple = 0;
  for (std::size_t j = 0; j < samples.size(); ++j) {
    std::size_t n = 0;
    for (const Gps_trip& t : trips) {
      bool hit = false;
      for (std::size_t i = 0; i + 1 < t.size() && !hit; ++i) {
        const double ax = t[i].x, ay = t[i].y, bx = t[i + 1].x, by = t[i + 1].y;
        if (ax == bx && ay == by) continue;
        // every segment of every trip, without a grid: the projection onto the segment, clamped to its ends
        const double len2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
        double s =
            ((samples[j].position[0] - ax) * (bx - ax) + (samples[j].position[1] - ay) * (by - ay)) / len2;
        s = std::max(0.0, std::min(1.0, s));
        const double d = std::hypot(ax + s * (bx - ax) - samples[j].position[0],
                                    ay + s * (by - ay) - samples[j].position[1]);
        double bearing = std::atan2(bx - ax, by - ay) * 180 / std::acos(-1.0);
        if (bearing < 0) bearing += 360;
        double diff = std::fabs(bearing - samples[j].bearing);
        diff = std::min({diff, std::fabs(180 - diff), std::fabs(360 - diff)});
        hit = d <= o.radius && diff < o.bearing_limit;
      }
      n += hit;
    }
    EXPECT_EQ(fast[j], n) << "sample " << j;
    supported += n > 0;
    multiple += n > 1;
  }
  EXPECT_GT(supported, 20u);  // not vacuous
  EXPECT_GT(multiple, 2u);
}

TEST(TraceSupport, LongSegmentsAndTinyRadiiStayBounded) {
  // 1001 samples along an east-west street from x = 0 to 1000, and trips along it whose walk over the grid
  // would be long (a far-off fix, a radius of a millimetre or a micrometre): every sample is counted,
  // quickly, by the grid walk or by a scan of the samples, whichever is shorter.
  std::vector<Map_sample> s;
  for (int i = 0; i <= 1000; ++i) s.push_back(sample_at(i, 0, 90));
  for (const double radius : {15.0, 1e-3, 1e-6})
    for (const auto& ends :
         {std::array<double, 4>{1e155, 0, 0, 0}, std::array<double, 4>{-1e300, 0, 1e300, 0},
          std::array<double, 4>{-10, 0, 1010, 0}, std::array<double, 4>{-10, 0, 500, 0}}) {
      Trace_support_options o;
      o.radius = radius;
      const std::vector<std::size_t> c =
          count_trips_along(s, {trip_of({{ends[0], ends[1]}, {ends[2], ends[3]}})}, o);
      const std::size_t hit = static_cast<std::size_t>(std::count(c.begin(), c.end(), std::size_t(1)));
      const std::size_t expected = ends[2] != 500 ? 1001 : radius == 15 ? 516 : 501;  // x <= 500 + radius
      EXPECT_EQ(hit, expected) << radius << " " << ends[0] << " " << ends[2];
      EXPECT_EQ(static_cast<std::size_t>(std::count(c.begin(), c.end(), std::size_t(0))), 1001 - expected);
    }
  // A line of slope 1/1000 through the origin between fixes at +-1e300: sample i lies i / 1000 m from it
  // (times 0.9999995), decided exactly for each sample: all within 15 m, samples 0 and 1 within 1 mm, 0 alone
  // within 1 um.
  for (const auto& [radius, expected] : {std::pair{15.0, 1001}, std::pair{1e-3, 2}, std::pair{1e-6, 1}}) {
    Trace_support_options o;
    o.radius = radius;
    const std::vector<std::size_t> c = count_trips_along(s, {trip_of({{-1e300, -1e297}, {1e300, 1e297}})}, o);
    EXPECT_EQ(std::count(c.begin(), c.end(), std::size_t(1)), expected) << radius;
    EXPECT_EQ(c[0], 1u);
  }
}

TEST(TraceSupport, SplitsAComparisonByTheTripsAlongItsSamples) {
  // The truth: two parallel east-west streets 100 m apart, 200 m long; trips drive the southern one only
  // (three trips) and the reconstruction has the southern one plus a spur that a single trip drove.
  Embedded_graph_2 truth;
  truth.positions = {{0, 0}, {200, 0}, {0, 100}, {200, 100}};
  truth.edges = {{0, 1}, {2, 3}};
  Embedded_graph_2 rec;
  rec.positions = {{0, 1}, {200, 1}, {100, -60}, {100, -200}};
  rec.edges = {{0, 1}, {2, 3}};
  std::vector<Gps_trip> trips{trip_of({{-10, 2}, {210, 2}}), trip_of({{210, -2}, {-10, -2}}),
                              trip_of({{-10, 0}, {100, 0}, {210, 0}}), trip_of({{100, -40}, {100, -210}})};
  Map_comparison_options o;
  const Map_comparison_result plain = compare_maps(truth, rec, o);
  EXPECT_THROW(explain_trace_support(plain, trips), std::invalid_argument);
  o.keep_samples = true;
  const Map_comparison_result r = compare_maps(truth, rec, o);
  const Trace_support_breakdown b = explain_trace_support(r, trips);
  const std::size_t street = r.ground_truth_samples / 2;  // each street has the same number of samples
  ASSERT_EQ(r.ground_truth_samples % 2, 0u);
  EXPECT_EQ(b.ground_truth_by_trips[0], street);  // the northern street: nobody drove it
  EXPECT_EQ(b.ground_truth_by_trips[2], street);  // the southern one: three trips (bin 2-3)
  EXPECT_EQ(b.ground_truth_by_trips[1] + b.ground_truth_by_trips[3], 0u);
  EXPECT_EQ(b.missed_by_trips[0], street);
  EXPECT_EQ(b.missed_by_trips[1] + b.missed_by_trips[2] + b.missed_by_trips[3], 0u);
  EXPECT_EQ(b.ground_truth_driven, street);
  EXPECT_EQ(b.matched_driven, street);
  EXPECT_EQ(b.recall_of_driven, 1.0);
  EXPECT_DOUBLE_EQ(r.recall, 0.5);
  // The spur's samples are spurious and one trip drove them.
  EXPECT_GT(b.spurious_by_trips[1], 20u);
  EXPECT_EQ(b.spurious_by_trips[0] + b.spurious_by_trips[2] + b.spurious_by_trips[3], 0u);
  EXPECT_EQ(b.spurious_by_trips[1], r.reconstruction_samples - r.matched);
  // With a 1 m threshold the trips 2 m beside the southern street no longer drive along it: the options that
  // go with a comparison carry its threshold and bearing limit.
  Map_comparison_options tight = o;
  tight.match_distance = 1;
  tight.bearing_limit = 30;
  const Trace_support_options so = trace_support_options(tight);
  EXPECT_EQ(so.radius, 1.0);
  EXPECT_EQ(so.bearing_limit, 30.0);
  const Trace_support_breakdown t = explain_trace_support(compare_maps(truth, rec, tight), trips, so);
  EXPECT_EQ(t.ground_truth_by_trips[1], street);  // only the trip driving on the centre line (y = 0)
  EXPECT_EQ(t.ground_truth_driven, street);
}

TEST(TraceSupport, BadInputIsNamed) {
  const std::vector<Map_sample> s{sample_at(0, 0, 90)};
  auto message = [&](const std::vector<Gps_trip>& trips, Trace_support_options o) {
    return test::invalid_argument_message([&] { count_trips_along(s, trips, o); });
  };
  const Gps_trip ok = trip_of({{0, 0}, {1, 0}});
  Trace_support_options o;
  Gps_trip bad = ok;
  bad.push_back({std::nan(""), 0, 20});
  EXPECT_TRUE(contains(message({ok, ok, bad}, o), "trip 2, fix 2"));
  bad = ok;
  bad[1].time = std::nan("");
  EXPECT_TRUE(contains(message({ok, bad}, o), "trip 1, fix 1"));
  o.radius = 0;
  EXPECT_TRUE(contains(message({ok}, o), "radius"));
  o.radius = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(message({ok}, o), "radius"));
  o.radius = 15;
  o.bearing_limit = std::nan("");
  EXPECT_TRUE(contains(message({ok}, o), "bearing_limit"));
  o.bearing_limit = 0;
  EXPECT_TRUE(contains(message({ok}, o), "bearing_limit"));
  const std::vector<Map_sample> bad_samples{sample_at(0, 0, 90), sample_at(std::nan(""), 0, 90)};
  EXPECT_TRUE(throws_with<std::invalid_argument>([&] { count_trips_along(bad_samples, {ok}); }, "sample 1"));
}

TEST(MapComparison, BadMapsAreNamed) {
  Embedded_graph_2 good;
  good.positions = {{0, 0}, {100, 0}};
  good.edges = {{0, 1}};
  auto error_of = [&](const Embedded_graph_2& truth, const Embedded_graph_2& rec,
                      Map_comparison_options o = {}) {
    return test::invalid_argument_message([&] { compare_maps(truth, rec, o); });
  };
  // A non-finite vertex looped forever (inf) or silently dropped the samples behind it (NaN).
  Embedded_graph_2 bad = good;
  bad.positions[1][0] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(error_of(good, bad),
                       "compare_maps: reconstruction: sample_map: vertex 1 (of edge 0) has a non-finite"));
  bad.positions[1][0] = std::nan("");
  EXPECT_TRUE(contains(error_of(bad, good), "compare_maps: ground truth: "));
  // Finite but too far apart for the interval (t += interval stops moving).
  bad.positions[1][0] = 1e300;
  EXPECT_TRUE(contains(error_of(good, bad), "more than 2^25 samples"));
  // A vertex that no edge uses may be anything.
  bad = good;
  bad.positions.push_back({std::nan(""), 0});
  EXPECT_EQ(compare_maps(good, bad).f_score, 1.0);
  Map_comparison_options o;
  o.bearing_limit = -1;
  EXPECT_TRUE(contains(error_of(good, good, o), "bearing_limit must be > 0, got -1"));
  // More candidates than samples (2^32 wrapped to 0 in the cast and crashed in CGAL).
  o = {};
  o.candidates = std::size_t(1) << 32;
  EXPECT_EQ(compare_maps(good, good, o).f_score, 1.0);
  // explain_unmatched_samples checks its options too (a 0 threshold made cells of size 0).
  o = {};
  o.keep_samples = true;
  const Map_comparison_result r = compare_maps(good, good, o);
  o.match_distance = 0;
  EXPECT_THROW(explain_unmatched_samples(r, o), std::invalid_argument);
}

namespace {
// Total weight (threshold - distance) of a matching given as ground-truth partners; checks that every pair is
// admissible and the two partner lists are inverse to each other.
double matching_weight(const std::vector<Map_sample>& H, const std::vector<Map_sample>& G,
                       const Map_sample_matching& M, const Map_comparison_options& o) {
  EXPECT_EQ(M.ground_truth_partner.size(), H.size());
  EXPECT_EQ(M.reconstruction_partner.size(), G.size());
  double w = 0;
  std::size_t pairs = 0;
  for (std::size_t h = 0; h < H.size(); ++h) {
    const std::int64_t g = M.ground_truth_partner[h];
    if (g < 0) continue;
    ++pairs;
    EXPECT_EQ(M.reconstruction_partner[std::size_t(g)], std::int64_t(h));
    const double d = std::hypot(H[h].position[0] - G[std::size_t(g)].position[0],
                                H[h].position[1] - G[std::size_t(g)].position[1]);
    EXPECT_LE(d, o.match_distance);
    EXPECT_LT(skeleton::internal::bearing_difference(H[h].bearing, G[std::size_t(g)].bearing),
              o.bearing_limit);
    w += o.match_distance - d;
  }
  std::size_t back = 0;
  for (const std::int64_t h : M.reconstruction_partner) back += h >= 0;
  EXPECT_EQ(back, pairs);
  EXPECT_EQ(M.matched, pairs);
  return w;
}

// The largest total weight of any matching, by dynamic programming over the subsets of G (|G| <= 12).
double brute_force_weight(const std::vector<Map_sample>& H, const std::vector<Map_sample>& G,
                          const Map_comparison_options& o) {
  const std::size_t subsets = std::size_t(1) << G.size();
  std::vector<double> best(subsets, -1), next(subsets);
  best[0] = 0;
  for (const Map_sample& h : H) {
    next = best;  // h unmatched
    for (std::size_t used = 0; used < subsets; ++used) {
      if (best[used] < 0) continue;
      for (std::size_t g = 0; g < G.size(); ++g) {
        if (used >> g & 1) continue;
        const double d = std::hypot(h.position[0] - G[g].position[0], h.position[1] - G[g].position[1]);
        const double turn = skeleton::internal::bearing_difference(h.bearing, G[g].bearing);
        if (d > o.match_distance || !(turn < o.bearing_limit)) continue;
        const std::size_t to = used | std::size_t(1) << g;
        next[to] = std::max(next[to], best[used] + o.match_distance - d);
      }
    }
    best.swap(next);
  }
  return *std::max_element(best.begin(), best.end());
}
}  // namespace

TEST(MapComparison, OptimalMatchingPinned) {
  // Along a line (bearing 90): h0 at 0, h1 at 20; g0 at 11, g1 at 32. Greedy pairs the closest first, h1-g0
  // (9 m), after which h0 has nothing within 15 m (g1 is 32 m away): 1 pair. The optimal matching takes h0-g0
  // (11 m) and h1-g1 (12 m): weights 4 + 3 = 7 > 6.
  const std::vector<Map_sample> H = {{{0, 0}, 90}, {{20, 0}, 90}}, G = {{{11, 0}, 90}, {{32, 0}, 90}};
  Map_comparison_options o;
  const Map_sample_matching greedy = match_map_samples(H, G, o);
  EXPECT_EQ(greedy.matched, 1u);
  EXPECT_EQ(greedy.ground_truth_partner, (std::vector<std::int64_t>{-1, 0}));
  o.matching = Map_matching::optimal;
  const Map_sample_matching optimal = match_map_samples(H, G, o);
  EXPECT_EQ(optimal.matched, 2u);
  EXPECT_EQ(optimal.ground_truth_partner, (std::vector<std::int64_t>{0, 1}));
  EXPECT_EQ(optimal.reconstruction_partner, (std::vector<std::int64_t>{0, 1}));
  EXPECT_DOUBLE_EQ(matching_weight(H, G, optimal, o), 7.0);
  // A pair that would cost more than it brings is not made: h1 alone, g at 14 m (weight 1), nothing else.
  EXPECT_EQ(match_map_samples({{{0, 0}, 90}}, {{{14, 0}, 90}}, o).matched, 1u);
  EXPECT_EQ(match_map_samples({{{0, 0}, 90}}, {{{15.5, 0}, 90}}, o).matched, 0u);
  // Bearings: perpendicular samples never pair, opposite directions do (direction-insensitive).
  EXPECT_EQ(match_map_samples({{{0, 0}, 90}}, {{{1, 0}, 0}}, o).matched, 0u);
  EXPECT_EQ(match_map_samples({{{0, 0}, 90}}, {{{1, 0}, 270}}, o).matched, 1u);
  // A bearing difference of exactly the limit (45 degrees) does not pair, as in the greedy matching.
  EXPECT_EQ(match_map_samples({{{0, 0}, 0}}, {{{1, 0}, 45}}, o).matched, 0u);
  // Where both sides of a component are equally large the ground truth is assigned: its samples, in index
  // order, take their cheapest free partners (every perfect matching here costs the same, 7.07 + 5).
  EXPECT_EQ(
      match_map_samples({{{5, 5}, 0}, {{5, 0}, 0}}, {{{0, 0}, 0}, {{10, 0}, 0}}, o).ground_truth_partner,
      (std::vector<std::int64_t>{0, 1}));
  // Ties between coincident samples go to the smaller index.
  const Map_sample_matching tie =
      match_map_samples({{{0, 0}, 90}}, {{{5, 0}, 90}, {{5, 0}, 90}, {{-5, 0}, 90}}, o);
  EXPECT_EQ(tie.ground_truth_partner, (std::vector<std::int64_t>{0}));
  // Empty sides.
  EXPECT_EQ(match_map_samples({}, G, o).reconstruction_partner, (std::vector<std::int64_t>{-1, -1}));
  EXPECT_EQ(match_map_samples(H, {}, o).ground_truth_partner, (std::vector<std::int64_t>{-1, -1}));
}

TEST(MapComparison, OptimalMatchingAgreesWithBruteForce) {
  // Random small sample sets, some on a lattice (ties of distance) and with repeated points: the optimal
  // matching's weight equals the largest weight of any matching, found by dynamic programming over subsets,
  // and is never below the greedy matching's. Some draw must make greedy lose, or the test shows nothing.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 40);
  std::uniform_int_distribution<int> count(0, 9), lattice(0, 4), bearing(0, 7);
  std::size_t greedy_below = 0, repeated = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool on_lattice = trial % 3 == 0;
    auto draw = [&](std::size_t n) {
      std::vector<Map_sample> s;
      for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && trial % 5 == 0 && i % 3 == 0) {  // a copy of an earlier sample
          s.push_back(s[i / 2]);
          ++repeated;
          continue;
        }
        const double x = on_lattice ? 10.0 * lattice(rng) : u(rng),
                     y = on_lattice ? 10.0 * lattice(rng) : u(rng);
        s.push_back({{x, y}, 30.0 * bearing(rng)});
      }
      return s;
    };
    const std::vector<Map_sample> H = draw(std::size_t(count(rng))), G = draw(std::size_t(count(rng) + 1));
    Map_comparison_options o;
    o.bearing_limit = trial % 2 ? 45.0 : 100.0;
    const double greedy = matching_weight(H, G, match_map_samples(H, G, o), o);
    o.matching = Map_matching::optimal;
    const Map_sample_matching M = match_map_samples(H, G, o);
    const double optimal = matching_weight(H, G, M, o);
    const double brute = brute_force_weight(H, G, o);
    EXPECT_NEAR(optimal, brute, 1e-9) << "trial " << trial;
    EXPECT_GE(optimal, greedy - 1e-9) << "trial " << trial;
    greedy_below += greedy < optimal - 1e-9;
    // Deterministic: the same input gives the same pairs.
    EXPECT_EQ(match_map_samples(H, G, o).ground_truth_partner, M.ground_truth_partner);
  }
  EXPECT_GT(greedy_below, 10u);
  EXPECT_GT(repeated, 0u);
}

TEST(MapComparison, OptimalMatchingOnChicago) {
  // The published Kharita map against OSM cropped to the traces: the optimal matching pairs at least as many
  // samples as the greedy one, and not many more (greedy is close to optimal on road maps: 7,592 and 7,644).
  const Embedded_graph_2 gt = load("gt_trk25"), kharita = load("kharita");
  Map_comparison_options o;
  const Map_comparison_result greedy = compare_maps(gt, kharita, o);
  o.matching = Map_matching::optimal;
  o.keep_samples = true;
  const Map_comparison_result optimal = compare_maps(gt, kharita, o);
  EXPECT_EQ(optimal.ground_truth_samples, greedy.ground_truth_samples);
  EXPECT_GE(optimal.matched, greedy.matched);
  EXPECT_LE(optimal.matched, greedy.matched + greedy.matched / 100);
  EXPECT_NEAR(optimal.f_score, 0.675, 0.005);
  std::size_t partners = 0;
  for (const std::int64_t g : optimal.ground_truth_partner) partners += g >= 0;
  EXPECT_EQ(partners, optimal.matched);
}

TEST(MapComparison, BadSamplesAreNamed) {
  Map_comparison_options o;
  o.matching = Map_matching::optimal;
  const std::vector<Map_sample> good = {{{0, 0}, 90}};
  std::vector<Map_sample> bad = {{{0, 0}, 90}, {{1, 0}, 90}, {{std::nan(""), 0}, 90}};
  EXPECT_TRUE(
      throws_with<std::invalid_argument>([&] { match_map_samples(good, bad, o); },
                                         "match_map_samples: reconstruction sample 2 has a non-finite"));
  bad = {{{0, 0}, std::numeric_limits<double>::infinity()}};
  EXPECT_THROW(match_map_samples(bad, good, o), std::invalid_argument);
  o.matching = static_cast<Map_matching>(7);
  EXPECT_THROW(match_map_samples(good, good, o), std::invalid_argument);
  o = {};
  o.match_distance = std::numeric_limits<double>::infinity();
  EXPECT_THROW(match_map_samples(good, good, o), std::invalid_argument);
}

TEST(MapComparison, OptimalMatchingOfDenseClusters) {
  // Samples stacked on one point (a degenerate map): every sample of the smaller set pairs, whichever map is
  // larger. The larger set's surplus never searches (a search through the whole cluster per surplus sample
  // took 14 s at 3,000 against 1,500).
  Map_comparison_options o;
  o.matching = Map_matching::optimal;
  const std::vector<Map_sample> many(300, Map_sample{{1, 1}, 0}), few(120, Map_sample{{1, 1}, 180});
  const Map_sample_matching a = match_map_samples(many, few, o), b = match_map_samples(few, many, o);
  EXPECT_EQ(a.matched, 120u);
  EXPECT_EQ(b.matched, 120u);
  EXPECT_DOUBLE_EQ(matching_weight(many, few, a, o), 120 * 15.0);
  EXPECT_DOUBLE_EQ(matching_weight(few, many, b, o), 120 * 15.0);
  // The side assigned is chosen per connected component of the admissible pairs: here the cluster's smaller
  // side belongs to the map that is larger overall (1,000 samples elsewhere), and the surplus of the cluster
  // still never searches (chosen by the whole maps, each of the 180 surplus samples settled the 120 matched
  // ones: 21,600).
  std::vector<Map_sample> few_and_far = few;
  for (int i = 0; i < 1000; ++i) few_and_far.push_back(Map_sample{{1000.0 + 20 * i, 0}, 90});
  for (const bool swap : {false, true}) {
    Map_sample_matching P;
    const std::vector<Map_sample>& H = swap ? few_and_far : many;
    const std::vector<Map_sample>& G = swap ? many : few_and_far;
    P.ground_truth_partner.assign(H.size(), -1);
    P.reconstruction_partner.assign(G.size(), -1);
    std::size_t searched = 0;
    ASSERT_TRUE(
        skeleton::internal::match_optimal(H, G, o, P, "match_map_samples", std::size_t(1) << 26, &searched));
    EXPECT_EQ(P.matched, 120u);
    EXPECT_LT(searched, 1000u) << "swap " << swap;
  }
  // Components of different sizes, some with the ground truth smaller, some with the reconstruction smaller,
  // are each matched optimally (the weight of the whole equals the sum over the parts).
  std::vector<Map_sample> H2, G2;
  double by_parts = 0;
  for (int c = 0; c < 6; ++c) {
    std::vector<Map_sample> h, g;
    for (int i = 0; i < 2 + 3 * (c % 3); ++i) {
      (c % 2 ? h : g).push_back(Map_sample{{100.0 * c + i, 0.5 * i}, 0});
      if (i % 2 == 0) (c % 2 ? g : h).push_back(Map_sample{{100.0 * c + i + 0.25, 0}, 0});
    }
    by_parts += brute_force_weight(h, g, o);
    H2.insert(H2.end(), h.begin(), h.end());
    G2.insert(G2.end(), g.begin(), g.end());
  }
  const Map_sample_matching whole = match_map_samples(H2, G2, o);
  EXPECT_NEAR(matching_weight(H2, G2, whole, o), by_parts, 1e-9);
  // Too many admissible pairs for memory are refused, naming the remedy.
  Map_sample_matching M;
  M.ground_truth_partner.assign(many.size(), -1);
  M.reconstruction_partner.assign(few.size(), -1);
  try {
    skeleton::internal::match_optimal(many, few, o, M, "match_map_samples", 1000);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "more than 1000 sample pairs lie within match_distance (15 m)"));
    EXPECT_TRUE(contains(e.what(), "use the greedy one"));
  }
}

TEST(MapComparison, PairsExactlyAtTheMatchDistanceAreSeenWhateverTheGridsCorner) {
  // h0 and g1 lie exactly match_distance apart: an admissible pair. The grid's rounding of (p - low) / cell
  // put them two cells apart, so whether the pair was seen depended on the grid's corner: with a far sample
  // g2 the optimal matching paired both ground-truth samples, without it only one (and before the pairs were
  // enumerated once, neither way round). Every pair at the limit is now a candidate.
  Map_comparison_options o;
  o.matching = Map_matching::optimal;
  o.match_distance = 2.5088616021043775;
  const double l = 2.5620754289283343, h = 5.0709370310327113, g1 = 7.5797986331370888;
  ASSERT_EQ(std::hypot(g1 - h, 0.0), o.match_distance);
  const std::vector<Map_sample> H{{{h, 0}, 0}, {{l, 0}, 0}};
  std::vector<Map_sample> G{{{l, 0}, 0}, {{g1, 0}, 0}, {{-100, 1000}, 0}};
  for (const bool far : {true, false}) {
    if (!far) G.pop_back();
    for (const Map_matching m : {Map_matching::optimal, Map_matching::greedy}) {
      o.matching = m;
      const Map_sample_matching M = match_map_samples(H, G, o);
      EXPECT_EQ(M.matched, 2u) << far << " " << int(m);
      EXPECT_EQ(M.ground_truth_partner, (std::vector<std::int64_t>{1, 0})) << far << " " << int(m);
    }
  }
}

TEST(MapComparison, TheLimitsOfTheRangesArePinned) {
  // match_distance and the trace radius may be exactly 2^-450 or 2^450 (the range is closed).
  for (const double limit : {0x1p-450, 0x1p450}) {
    for (const Map_matching m : {Map_matching::greedy, Map_matching::optimal}) {
      Map_comparison_options o;
      o.matching = m;
      o.match_distance = limit;
      Map_sample_matching M;
      ASSERT_NO_THROW(M = match_map_samples({{{0, 0}, 90}}, {{{0, 0}, 90}}, o)) << limit;
      EXPECT_EQ(M.matched, 1u) << limit;
    }
    Trace_support_options t;
    t.radius = limit;
    std::vector<std::size_t> trips;
    ASSERT_NO_THROW(trips = count_trips_along({{{0, 0}, 90}}, {{{-1, 0, 0}, {1, 0, 1}}}, t)) << limit;
    EXPECT_EQ(trips, (std::vector<std::size_t>{1})) << limit;
  }
  // explain_unmatched_samples(): a sample at exactly the bearing limit (45 degrees) is not aligned, so a
  // sample 5 m away is a crossing, not a taken one.
  Map_comparison_result r;
  r.ground_truth_samples = r.reconstruction_samples = 1;
  r.ground_truth_sample_list = {{{0, 0}, 0}};
  r.reconstruction_sample_list = {{{5, 0}, 45}};
  r.ground_truth_partner = r.reconstruction_partner = {-1};
  Unmatched_samples_breakdown b = explain_unmatched_samples(r);
  EXPECT_EQ(b.missed.crossing, 1u);
  EXPECT_EQ(b.spurious.crossing, 1u);
  EXPECT_EQ(b.missed.taken + b.spurious.taken, 0u);
  // ... and an aligned sample exactly two thresholds away is offset, whatever the rounding of its grid cell
  // (the positions of PairsExactlyAtTheMatchDistanceAreSeenWhateverTheGridsCorner, threshold halved).
  Map_comparison_options half;
  half.match_distance = 2.5088616021043775 / 2;
  const double l = 2.5620754289283343, h = 5.0709370310327113, g1 = 7.5797986331370888;
  r.ground_truth_sample_list = {{{h, 0}, 0}};
  r.reconstruction_samples = 2;
  r.reconstruction_sample_list = {{{g1, 0}, 0}, {{l, 0}, 90}};
  r.reconstruction_partner = {-1, -1};
  b = explain_unmatched_samples(r, half);
  EXPECT_EQ(b.missed.offset, 1u);
  EXPECT_EQ(b.missed.crossing, 0u);
}

TEST(MapComparison, ProgressIsReportedAndAStopLeavesNoPair) {
  // A grid of 30x30 blocks of 100 m (about 35,000 samples) against itself shifted by 3 m: both matchings
  // report increasing fractions ending at 1 (and below 1 before the end) and score what they score unwatched;
  // a stop at any report leaves the samples, no pair and status interrupted, and the callback is not asked
  // again.
  const Embedded_graph_2 gt = grid_map(31, 100.0), rec = grid_map(31, 100.0, 3.0, 0.0);
  for (const Map_matching matching : {Map_matching::greedy, Map_matching::optimal}) {
    Map_comparison_options options;
    options.matching = matching;
    const Map_comparison_result plain = compare_maps(gt, rec, options);
    ASSERT_GT(plain.ground_truth_samples, 30000u);
    ASSERT_GT(plain.matched, 30000u);
    std::vector<double> seen;
    options.progress = test::recording_progress(seen);
    const Map_comparison_result watched = compare_maps(gt, rec, options);
    EXPECT_EQ(watched.status, Status::success);
    EXPECT_EQ(watched.matched, plain.matched);
    EXPECT_EQ(watched.f_score, plain.f_score);
    ASSERT_GT(seen.size(), 4u) << "matching " << static_cast<int>(matching);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.front(), 0.1);  // both maps sampled
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_LT(seen[seen.size() - 2], 1.0);
    EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double t) { return t > 0.1 && t < 1; }));
    for (const std::size_t allowed : {std::size_t(0), std::size_t(1), std::size_t(2), seen.size() - 2}) {
      std::size_t asked = 0;
      options.progress = [&asked, allowed](double) { return asked++ < allowed; };
      options.keep_samples = true;
      const Map_comparison_result stopped = compare_maps(gt, rec, options);
      options.keep_samples = false;
      EXPECT_EQ(asked, allowed + 1) << allowed;
      EXPECT_EQ(stopped.status, Status::interrupted) << allowed;
      EXPECT_EQ(stopped.matched, 0u) << allowed;
      EXPECT_EQ(stopped.f_score, 0.0) << allowed;
      EXPECT_EQ(stopped.ground_truth_samples, plain.ground_truth_samples) << allowed;
      EXPECT_EQ(stopped.reconstruction_samples, plain.reconstruction_samples) << allowed;
      EXPECT_EQ(stopped.ground_truth_sample_list.size(), plain.ground_truth_samples) << allowed;
      EXPECT_EQ(stopped.reconstruction_sample_list.size(), plain.reconstruction_samples) << allowed;
      EXPECT_EQ(stopped.ground_truth_partner, std::vector<std::int64_t>(plain.ground_truth_samples, -1))
          << allowed;
      EXPECT_EQ(stopped.reconstruction_partner, std::vector<std::int64_t>(plain.reconstruction_samples, -1))
          << allowed;
    }
    // The matching alone stops the same way, its partner lists all -1.
    const std::vector<Map_sample> H = sample_map(gt, 5.0), G = sample_map(rec, 5.0);
    std::size_t asked = 0;
    options.progress = [&asked](double) { return asked++ < 1; };
    const Map_sample_matching M = match_map_samples(H, G, options);
    EXPECT_EQ(M.status, Status::interrupted);
    EXPECT_EQ(M.matched, 0u);
    EXPECT_EQ(M.ground_truth_partner, std::vector<std::int64_t>(H.size(), -1));
    EXPECT_EQ(M.reconstruction_partner, std::vector<std::int64_t>(G.size(), -1));
  }
}

TEST(MapComparison, GreedyProgressStaysBelowOneUntilTheEnd) {
  // 5,000 ground-truth samples in a cluster of 0.1 m against 10 reconstruction samples 1 to 10 m from it in a
  // row: every sample proposes to each of the 10 in turn, each taken before it comes back. The greedy
  // matching's fraction counts settled samples, not searches, and 1 comes only at the end (it reached 1
  // eleven times before the end when it counted searches).
  std::vector<Map_sample> H, G;
  for (int i = 0; i < 5000; ++i) H.push_back({{0.001 * (i % 100), 0.001 * (i / 100)}, 0.0});
  for (int i = 0; i < 10; ++i) G.push_back({{1.0 + i, 0.0}, 0.0});
  Map_comparison_options options;
  std::vector<double> seen;
  options.progress = test::recording_progress(seen);
  const Map_sample_matching M = match_map_samples(H, G, options);
  EXPECT_EQ(M.matched, 10u);
  ASSERT_GT(seen.size(), 2u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1.0), 1);
  EXPECT_EQ(seen.back(), 1.0);
}

namespace {
// The trace points of crop_map_to_trips() made independently: every fix, and for consecutive fixes (by time)
// at most max_gap apart and more than trace_step apart, the points j / k of the way, k = ceil(d /
// trace_step).
std::vector<std::array<double, 2>> brute_trace_points(std::vector<Gps_trip> trips,
                                                      const Map_crop_options& o) {
  std::vector<std::array<double, 2>> p;
  for (Gps_trip& t : trips) {
    std::stable_sort(t.begin(), t.end(), [](const Gps_fix& a, const Gps_fix& b) { return a.time < b.time; });
    for (std::size_t i = 0; i < t.size(); ++i) {
      p.push_back({t[i].x, t[i].y});
      if (i + 1 == t.size()) continue;
      const double d = std::hypot(t[i + 1].x - t[i].x, t[i + 1].y - t[i].y);
      if (d > o.max_gap || d <= o.trace_step) continue;
      const int k = int(std::ceil(d / o.trace_step));
      for (int j = 1; j < k; ++j)
        p.push_back({t[i].x + j * (t[i + 1].x - t[i].x) / k, t[i].y + j * (t[i + 1].y - t[i].y) / k});
    }
  }
  return p;
}
}  // namespace

TEST(CropMapToTrips, MatchesABruteForceOnRandomTrips) {
  // A 6 x 6 grid of 40 m blocks and random trips wandering over it (fixes 5-60 m apart, some far jumps, times
  // shuffled within a trip): the edges kept are those whose 5 m samples all have a brute-force trace point
  // within the radius (samples a little inside or outside the radius decide the same: none lies within 1e-9
  // of it).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  const Embedded_graph_2 map = grid_map(6, 40);
  for (int round = 0; round < 40; ++round) {
    std::vector<Gps_trip> trips(1 + round % 4);
    for (Gps_trip& t : trips) {
      double x = 200 * u(rng), y = 200 * u(rng);
      for (int i = 0; i < 12; ++i) {
        t.push_back({x, y, double(i)});
        const double step = u(rng) < 0.1 ? 300 : 5 + 55 * u(rng), a = 6.283185307179586 * u(rng);
        x += step * std::cos(a);
        y += step * std::sin(a);
      }
      std::shuffle(t.begin(), t.end(), rng);  // the crop orders them by time
    }
    Map_crop_options o;
    o.radius = 8 + 10 * u(rng);
    o.max_gap = round % 5 == 0 ? 0 : 100 + 300 * u(rng);
    const auto points = brute_trace_points(trips, o);
    const Cropped_map c = crop_map_to_trips(map, trips, o);
    EXPECT_EQ(c.status, Status::success);
    EXPECT_EQ(c.trace_points, points.size());
    EXPECT_EQ(c.map.positions, map.positions);
    std::vector<Edge> expected;
    for (const Edge& e : map.edges) {
      const auto& a = map.positions[e[0]];
      const auto& b = map.positions[e[1]];
      bool keep = true;
      for (int i = 0; i <= 8 && keep; ++i) {  // 40 m edges: samples at 0, 5, ..., 40
        const double x = a[0] + (b[0] - a[0]) * i / 8, y = a[1] + (b[1] - a[1]) * i / 8;
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& p : points) nearest = std::min(nearest, std::hypot(p[0] - x, p[1] - y));
        ASSERT_GT(std::fabs(nearest - o.radius), 1e-9);
        keep = nearest <= o.radius;
      }
      if (keep) expected.push_back(e);
    }
    EXPECT_EQ(c.map.edges, expected) << "round " << round;
  }
}

TEST(CropMapToTrips, AStreetBetweenSparseFixesStays) {
  // One 60 m street driven by one trip with a fix at each end: its middle lies 30 m from both, beyond the 25
  // m radius, so with the fixes alone (max_gap 0; what evaluate-map did before) it was cropped away; the
  // interpolated points keep it. A gap above max_gap is not bridged; the samples are 5 m apart whatever else.
  Embedded_graph_2 street;
  street.positions = {{0, 0}, {60, 0}};
  street.edges = {{0, 1}};
  std::vector<Gps_trip> trips{{{60, 2, 1}, {0, 2, 0}}};  // in reverse file order: sorted by time
  Map_crop_options o;
  EXPECT_EQ(crop_map_to_trips(street, trips, o).map.edges.size(), 1u);
  EXPECT_EQ(crop_map_to_trips(street, trips, o).trace_points, 7u);  // 2 fixes, 5 inner points 10 m apart
  o.max_gap = 0;
  EXPECT_TRUE(crop_map_to_trips(street, trips, o).map.edges.empty());
  o.max_gap = 59.9;
  EXPECT_TRUE(crop_map_to_trips(street, trips, o).map.edges.empty());
  o.max_gap = 60;  // inclusive
  EXPECT_EQ(crop_map_to_trips(street, trips, o).map.edges.size(), 1u);
  // Nothing to crop to: every edge goes; an empty map stays empty.
  EXPECT_TRUE(crop_map_to_trips(street, {}, o).map.edges.empty());
  EXPECT_TRUE(crop_map_to_trips(Embedded_graph_2{}, trips, o).map.edges.empty());
}

TEST(CropMapToTrips, BadInputIsNamedAndProgressStops) {
  Embedded_graph_2 street;
  street.positions = {{0, 0}, {60, 0}};
  street.edges = {{0, 1}};
  const std::vector<Gps_trip> trips{{{0, 2, 0}, {60, 2, 1}}};
  auto message = [&](const Embedded_graph_2& m, const std::vector<Gps_trip>& t, const Map_crop_options& o) {
    return test::invalid_argument_message([&] { crop_map_to_trips(m, t, o); });
  };
  Map_crop_options o;
  o.radius = 0;
  EXPECT_EQ(message(street, trips, o), "crop_map_to_trips: radius must be positive and finite, got 0");
  o = {};
  o.trace_step = std::nan("");
  EXPECT_TRUE(contains(message(street, trips, o), "trace_step must be positive"));
  o = {};
  o.max_gap = -1;
  EXPECT_EQ(message(street, trips, o), "crop_map_to_trips: max_gap must be finite and >= 0, got -1");
  o = {};
  o.sample_interval = 1e-300;
  EXPECT_TRUE(contains(message(street, trips, o), "more than 2^25 samples"));
  o = {};
  std::vector<Gps_trip> bad = trips;
  bad[0][1].y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message(street, bad, o), "crop_map_to_trips: trip 0, fix 1 has a non-finite coordinate or time");
  Embedded_graph_2 out_of_range = street;
  out_of_range.edges.push_back({1, 2});
  EXPECT_EQ(message(out_of_range, trips, o), "crop_map_to_trips: edge 1 has a vertex out of range [0, 2)");
  o.trace_step = 1e-300;  // 60 m in pieces of 1e-300: refused before anything is made
  EXPECT_TRUE(contains(message(street, trips, o), "more than 2^27 trace points"));
  // Progress: 0, every 4096 edges, 1; a stop keeps the edges checked so far.
  const Embedded_graph_2 big = grid_map(60, 40);  // 7080 edges
  std::vector<Gps_trip> cover(1);
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) cover[0].push_back({i * 40.0, j * 40.0, double(i * 60 + j)});
  std::vector<double> seen;
  o = {};
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const Cropped_map all = crop_map_to_trips(big, cover, o);
  EXPECT_EQ(all.map.edges.size(), big.edges.size());
  EXPECT_EQ(seen, (std::vector<double>{0.0, 4095.0 / 7080, 1.0}));
  o.progress = [](double f) { return f == 0; };
  const Cropped_map part = crop_map_to_trips(big, cover, o);
  EXPECT_EQ(part.status, Status::interrupted);
  EXPECT_EQ(part.map.edges.size(), 4095u);
}
