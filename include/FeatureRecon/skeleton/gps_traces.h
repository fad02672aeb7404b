// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_GPS_TRACES_H
#define FEATURERECON_SKELETON_GPS_TRACES_H

// GPS traces as input of the skeleton pipeline (dissertation Ch. 3.4, road maps): densify each trip along its
// segments (those the other traces confirm), sample the result at a spacing (greedy, in trip order, so
// deterministic), and build the proximity graph of the samples from Rips edges plus links between consecutive
// samples of a trip.

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// One GPS fix: planar position (metres) and time (seconds; only the order matters).
struct Gps_fix {
  double x = 0;     ///< easting (metres)
  double y = 0;     ///< northing (metres)
  double time = 0;  ///< seconds
};

/// A trip: fixes of one vehicle; sample_gps_traces() sorts them by time (stable, so equal times keep file
/// order).
using Gps_trip = std::vector<Gps_fix>;

/// Options of sample_gps_traces(). An automatic value (FeatureRecon::automatic, the default of the optional
/// fields) asks for the rule given on the field, 0 turns a stage off where the field says so, and a negative
/// value is refused (before FeatureRecon::automatic, 0 asked for the rule and a negative value turned the
/// stage off); the values used are returned in Gps_trace_sample.
struct Gps_trace_options {
  /// Greedy thinning in trip order: a trace point joins the first sample created less than this far from it
  /// (the samples' creation points are this far apart; see mean_positions); > 0. Automatic (default): half
  /// the Rips radius.
  std::optional<double> sample_spacing = FeatureRecon::automatic;
  /// Consecutive fixes of a trip at most this far apart are linked: points are inserted along the segment
  /// every half sample spacing, and consecutive samples become graph edges. Automatic (default): four times
  /// the median step of the data, at least twice the Rips radius. 0: no linking.
  std::optional<double> max_link_gap = FeatureRecon::automatic;
  /// Rips edges join samples whose travel directions (modulo 180 degrees) differ by at most this angle.
  /// Samples of crossing streets then touch only where vehicles turn. 180 (default): directions are ignored.
  double heading_tolerance = 180;
  /// Headings are driving directions in [0, 360) (true, default: opposite carriageways of a divided road and
  /// the two directions of a street stay apart under a heading tolerance), or undirected lines in [0, 180)
  /// (false).
  bool directed = true;
  /// Each sample is moved, after sampling and the density filter, to the mean of the fixes that joined it
  /// (true, default), or stays at the first trace point that created it (false). Points inserted along a
  /// trip's segments do not count (they cut corners); a sample that only inserted points joined stays where
  /// it was created.
  bool mean_positions = true;
  /// Drops samples that stand for fewer trace points than this fraction of the most any sample within
  /// `density_radius` stands for: scattered fixes (multipath next to tall buildings) away from the dense band
  /// of the street they belong to. A lone street keeps its samples (its own maximum). 0 (default): keep all.
  /// In [0, 1] (1 keeps only local maxima).
  double min_relative_density = 0;
  /// Drops samples that stand for fewer trace points than this fraction of the most any sample beside them
  /// stands for: within `density_radius`, travelling within `density_heading_tolerance` of the same
  /// direction, and lying at least 45 degrees off the sample's direction (the offset across it at least the
  /// offset along it). Scatter lies beside the band of its street, and it is sparse there relative to the
  /// band (multipath zones of Chicago drew loops through such fixes; benchmark/README.md, "Scatter beside a
  /// street"). A quiet street that continues a busy one, or crosses it, has the busy samples behind it or
  /// travelling another way and is judged by `min_relative_density` alone; one that forks off a busy street
  /// at an acute angle (within `density_heading_tolerance`: a slip road) has busy samples beside it near the
  /// fork and loses them. Samples that only fixes of trips that never move joined (parked vehicles, one-fix
  /// trips: no direction, they point east) are neither judged nor count as heavy neighbours. 0 (default):
  /// off; road maps use 0.3. In [0, 1].
  double min_lateral_density = 0;
  /// Radius of the local maxima above (> 0). Automatic (default): twice the Rips radius.
  std::optional<double> density_radius = FeatureRecon::automatic;
  /// A sample is compared only with samples whose travel directions differ from its own by at most this angle
  /// (degrees; directed as sampled): the lightly used carriageway of a divided road next to a busy opposite
  /// one, or a side street crossing a main road, is not mistaken for scatter. 180 or more: all samples within
  /// `density_radius` (directions ignored). Default 45.
  double density_heading_tolerance = 45;
  /// A segment between consecutive fixes is densified only where the traces confirm it: every point inserted
  /// along it lies within this distance of some fix (of any trip), or the trip drives straight through it
  /// (see segment_turn_tolerance). Between sparse fixes (tens of seconds apart) a vehicle that turned cuts
  /// the corner, and the segment crosses a block where no fix lies. An unconfirmed segment up to four times
  /// this long still links its two ends (no points inserted: the vehicle went from one to the other, the way
  /// is unknown); a longer one breaks the trip like a gap. Segments up to twice this long are confirmed by
  /// their own ends. Automatic (default): two thirds of the Rips radius, at least 20 m (GPS scatter across a
  /// street plus half the gap between the fixes of light traffic along it; thinned Chicago traces lose recall
  /// below 20 m). 0: no check, every segment up to the link gap is used (`featurerecon skeleton
  /// --segment-support 0`).
  std::optional<double> segment_support = FeatureRecon::automatic;
  /// An unconfirmed segment is still used when the trip does not turn there: the directions in which it
  /// arrives at the segment and leaves it (each from the nearest fix at least segment_support away, so that a
  /// vehicle wobbling at a stop does not turn, and not across a gap; those that exist, at least one) lie
  /// within this angle of the segment (degrees). A street driven by one trip is confirmed by no other.
  /// Default 30.
  double segment_turn_tolerance = 30;
  /// Where fixes lie densely, a chord that cuts a block still passes within segment_support of the fixes on
  /// the streets around it (a taxi-like city at 42 s with 8 m of noise confirmed 0.56 of its segments, most
  /// of them diagonals). A segment longer than 4 segment_support is therefore confirmed at a local distance:
  /// from each end, the distance to the local_support_fixes-th nearest distinct fix position (the end's own
  /// counted), the larger of the two, at least min_local_support times segment_support; segment_support where
  /// fewer than local_support_fixes positions lie within it. On a street the fixes lie about that far apart,
  /// so a point of a driven street is within it of one. Shorter segments, whose unconfirmed ones still link
  /// their ends, keep segment_support. The turn rule's evidence (Gps_trace_sample::straight_confirmed) counts
  /// confirmation at the local distance; the stand-down of min_confirmed_fraction counts it at
  /// segment_support (dense traces whose chords fail are not too sparse to judge). Default 8; 0:
  /// segment_support everywhere. At most 1024.
  std::size_t local_support_fixes = 8;
  /// Lower bound of the local distance above, as a fraction of segment_support, in (0, 1]. Default 0.6 (12 m
  /// at the automatic 20 m: GPS scatter across a street).
  double min_local_support = 0.6;
  /// Traces too sparse to confirm one another: when fewer than this fraction of the segments that need a
  /// check are confirmed, the check stands down (Gps_trace_sample::all_segments_used) and every segment is
  /// densified, except those whose ends the fixes alone already join (stand_down_path_factor). Default 0.2;
  /// 0: never.
  double min_confirmed_fraction = 0.2;
  /// Where the check stands down, a segment it did not confirm keeps the check's verdict (link its ends or
  /// break the trip) when the fixes of the traces, without it, already join its two ends: a path through the
  /// cells of side sample_spacing that hold a fix, each cell joined to its 8 neighbours, at most this many
  /// times the segment long plus two cells (measured between cell centres, the bound rounded down to whole
  /// cells). Few confirmed segments then
  /// mean chords across blocks between fixes far apart in time, not traces too sparse to judge: a fleet of
  /// 4,000 vehicles logging every 60 to 120 s on a grid city confirmed 16 % of its segments, and densifying
  /// all of them drew 116,000 chords across its blocks (F 0.23 in 27 s and 1.1 GB; F 0.96 in 4 s with the
  /// rule). Where the fixes do not join the ends, no other trip passed there and the segment is densified as
  /// before (small cities of 150 trips logging every 30 to 45 s: no segment was joined). The search for a
  /// path gives up, and the segment is densified, after visiting 32 cells per cell of the length allowed
  /// (a failing search would otherwise visit every cell within that length: quadratic; the searches that
  /// succeeded on the cities measured visited at most 16.3 per cell). Default 2.5 (benchmark/README.md,
  /// "Segment check: the stand-down"); 0: the stand-down densifies every segment.
  double stand_down_path_factor = 2.5;
  /// The turn rule is trusted only where the traces show that it tells streets: a segment the trip drives
  /// straight through must be confirmed by fixes at least this often among the checked segments (the 95 %
  /// Wilson upper bound of the share confirmed reaches it; Gps_trace_sample::turn_rule_used). Bus routes
  /// follow long straight streets and their straight segments are confirmed (Chicago's traces thinned to
  /// every 3rd to 12th fix: 0.83 to 0.99 of them, counted at the local distance); random routes between fixes
  /// hundreds of metres apart run straight for kilometres while their segments cut blocks, and there
  /// straightness says little (a synthetic taxi city at 42 s: 0.26 of the straight segments confirmed; 0.54
  /// to 0.62 in the synthetic cities of 600 and 3000 trips at 20 s, which lose 0.01 to 0.07 in F with the
  /// rule): the rule drew lines across blocks. The unconfirmed straight segments count against the rule too,
  /// so few checked segments with none confirmed distrust it, and where most streets are driven by one or two
  /// trips the rule, though often wrong, adds streets no other trip draws (synthetic cities of 150 trips lose
  /// up to 0.19 in F without it). Default 0.75 (0.9 until session 39: set when confirmation was counted at
  /// segment_support, it distrusted the rule on Chicago's every 10th fix from its first, F 0.46 instead of
  /// 0.62); 0: always trusted.
  double min_straight_confirmed_fraction = 0.75;
  /// Where the turn rule is not trusted, an unconfirmed segment the trip drives straight through is still
  /// used when both its ends are quiet: fewer than this many distinct fix positions (the end's own counted)
  /// lie within segment_support of each. The rule is distrusted because many trips' fixes leave chords
  /// unconfirmed; where hardly any other fix is around, no other trip could have confirmed the segment, and
  /// it is a street one trip drives as often as a chord (Chicago's traces thinned to every 15th or 20th fix:
  /// F 0.43 / 0.40 without, 0.57 / 0.52 with, above the rule always trusted; synthetic cities of 150 trips at
  /// 20 s +0.02 to +0.16, the others within -0.007 and +0.003, the taxi-like city -0.001; 8 cost the 600-trip
  /// cities up to 0.04). Default 4 (session 39); 0: never. At most 1024.
  std::size_t quiet_end_fixes = 4;
  /// Refuse (std::invalid_argument, before any is made) linking that would insert more points than this along
  /// the segments: one jump of 1,000 km between two fixes within a generous max_link_gap asked for 10^8
  /// points at a spacing of 10 m. Default 2^26 (the traces of Chicago need about 500,000); 0: no limit.
  std::size_t max_inserted_points = std::size_t(1) << 26;
  /// Refuse (std::invalid_argument, before comparing any) a density filter that would compare more pairs of
  /// samples than this (every sample with the samples in the grid cells of side density_radius around it): a
  /// sample spacing far below the radius fills the scatter around the streets with samples (Chicago: 0.8
  /// million pairs at the default spacing, 12 m; 3.2 * 10^8 at 2 m; 2.7 * 10^10 at 0.5 m, which ran 6 minutes
  /// and took 8 GB before the complex's triangle limit refused it). The pairs are counted as the samples are
  /// made, and the sampling stops as soon as they pass the limit (3,000 Chicago fixes at spacing 0.01
  /// made 7.3 million samples in 38 s and 1 GB before they were counted; now 73,000 samples, 0.3 s), so the
  /// refusal can come before a stop that the progress callback would have asked for later in the sampling.
  /// Default 2^30; 0: no limit.
  std::size_t max_density_pairs = std::size_t(1) << 30;
  /// Called with the fraction done: before each trip and every 4,096 fixes within one during the segment
  /// check (0 to 0.25), its stand-down (0.25 to 0.3; also every 2^20 cells its searches visit) and the
  /// sampling (0.3 to 0.8), and every 4,096 samples of the density filter; returning false stops the sampling
  /// (Gps_trace_sample::status interrupted).
  Progress_callback progress;
};

/// Samples of GPS traces with the parameters used.
struct Gps_trace_sample {
  Point_matrix points;           ///< sample positions (dimension 2; see Gps_trace_options::mean_positions)
  std::vector<double> headings;  ///< travel direction of each sample: [0, 360) degrees, or [0, 180)
  bool directed = true;          ///< which of the two (Gps_trace_options::directed)
  /// Gps_trace_options::heading_tolerance (degrees): build_gps_trace_graph() uses it unless told otherwise
  double heading_tolerance = 180;
  std::vector<std::uint32_t> weights;  ///< trace points (fixes and inserted points) each sample stands for
  std::vector<Edge> trip_links;        ///< consecutive samples of a trip (sorted, unique, u < v)
  std::vector<std::uint32_t> sample_of_fix;  ///< per input fix (trips concatenated in order): its sample
  std::size_t fixes = 0;                     ///< number of input fixes
  double sample_spacing = 0;                 ///< value used
  double max_link_gap = 0;                   ///< value used (0: no linking)
  double median_step = 0;                    ///< median distance between consecutive fixes of a trip
  double density_radius = 0;                 ///< value used
  double density_heading_tolerance = 0;      ///< value used
  std::size_t dropped = 0;                   ///< samples dropped as sparse (their fixes map to no sample: -1)
  std::size_t dropped_lateral = 0;           ///< ... of which only min_lateral_density dropped
  double segment_support = 0;                ///< value used (0: no check)
  double segment_turn_tolerance = 0;         ///< value used
  /// segments within the link gap, longer than 2 segment_support, with points to insert
  std::size_t checked_segments = 0;
  std::size_t confirmed_segments = 0;  ///< ... of which every inserted point lies near a fix
  /// checked segments confirmed at a local distance below segment_support
  /// (Gps_trace_options::local_support_fixes)
  std::size_t locally_checked = 0;
  std::size_t locally_rejected = 0;   ///< ... of which confirmed at segment_support but not at that distance
  std::size_t straight_segments = 0;  ///< ... of the others, driven straight through (used)
  /// ... of which used for their quiet ends alone (the turn rule not trusted;
  /// Gps_trace_options::quiet_end_fixes)
  std::size_t quiet_segments = 0;
  std::size_t straight_checked = 0;    ///< checked segments driven straight through (confirmed or not)
  std::size_t straight_confirmed = 0;  ///< ... of which confirmed by fixes
  /// straight unconfirmed segments kept (min_straight_confirmed_fraction); false when the segment check did
  /// not run (segment_support or max_link_gap 0), true when it ran and no segment needed it
  bool turn_rule_used = false;
  /// ... of the rest, up to 4 segment_support: ends linked only (after a stand-down, those it left to the
  /// check's verdict)
  std::size_t linked_segments = 0;
  /// the check was off or stood down (too few confirmed: Gps_trace_options::min_confirmed_fraction); every
  /// segment is then densified, except the joined_segments
  bool all_segments_used = false;
  /// segments the stand-down left to the check's verdict because the fixes alone join their ends
  /// (Gps_trace_options::stand_down_path_factor)
  std::size_t joined_segments = 0;
  /// success, or interrupted when Gps_trace_options::progress returned false (the sample is then incomplete:
  /// not to be used)
  Status status = Status::success;
};

namespace internal {

/// Upper end of the 95 % Wilson score interval of a share of `successes` in `trials` (1 without trials).
inline double wilson_upper_bound(std::size_t successes, std::size_t trials) {
  if (trials == 0) return 1.0;
  const double z = 1.959963984540054, n = static_cast<double>(trials), p = static_cast<double>(successes) / n;
  const double z2n = z * z / n;
  return std::min(1.0, (p + z2n / 2 + z * std::sqrt(p * (1 - p) / n + z2n / (4 * n))) / (1 + z2n));
}

/// Angle between two headings in degrees: directions in [0, 360) when `directed`, else lines in [0, 180).
inline double heading_difference(double a, double b, bool directed = false) {
  const double d = std::fabs(a - b);
  return directed ? std::min(d, 360.0 - d) : std::min(d, 180.0 - d);
}

struct Cell_hash {
  std::size_t operator()(const std::array<std::int64_t, 2>& c) const {
    // Unsigned: the products wrap instead of overflowing.
    return static_cast<std::size_t>(static_cast<std::uint64_t>(c[0]) * 73856093u ^
                                    static_cast<std::uint64_t>(c[1]) * 19349663u);
  }
};

/// Indices of a trip's fixes by time (stable: equal times keep their order; a NaN time sorts last).
inline std::vector<std::size_t> time_order(const Gps_trip& trip) {
  std::vector<std::size_t> o(trip.size());
  for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
  std::stable_sort(o.begin(), o.end(), [&trip](std::size_t a, std::size_t b) {
    const double s = trip[a].time, t = trip[b].time;
    return std::isnan(s) ? false : (std::isnan(t) || s < t);
  });
  return o;
}

/// Buckets of sample indices on a square grid over a bounding box: a dense array of cells when there are at
/// most 2^24 of them and at most 16 per expected item (`expected_items`), a hash map otherwise (sparse data
/// over a large extent: two trips 40 km apart must not allocate millions of empty cells).
class Planar_grid {
 public:
  Planar_grid(double xmin, double ymin, double xmax, double ymax, double cell, std::size_t expected_items)
      : m_cell(cell) {
    m_x0 = std::floor(xmin / cell);
    m_y0 = std::floor(ymin / cell);
    const double w = std::floor(xmax / cell) - m_x0 + 1, h = std::floor(ymax / cell) - m_y0 + 1;
    if (w * h <= double(1 << 24) && w * h <= 16.0 * (static_cast<double>(expected_items) + 64) && w >= 1 &&
        h >= 1) {
      m_w = static_cast<std::int64_t>(w);
      m_h = static_cast<std::int64_t>(h);
      m_dense.resize(static_cast<std::size_t>(m_w * m_h));
    }
  }
  std::array<std::int64_t, 2> cell_of(double x, double y) const {
    return {static_cast<std::int64_t>(std::floor(x / m_cell) - m_x0),
            static_cast<std::int64_t>(std::floor(y / m_cell) - m_y0)};
  }
  const std::vector<std::uint32_t>* find(std::int64_t i, std::int64_t j) const {
    if (!m_dense.empty()) {
      if (i < 0 || j < 0 || i >= m_w || j >= m_h) return nullptr;
      const auto& b = m_dense[static_cast<std::size_t>(j * m_w + i)];
      return b.empty() ? nullptr : &b;
    }
    const auto it = m_sparse.find({i, j});
    return it == m_sparse.end() ? nullptr : &it->second;
  }
  void push(const std::array<std::int64_t, 2>& c, std::uint32_t id) {
    if (!m_dense.empty())
      m_dense[static_cast<std::size_t>(c[1] * m_w + c[0])].push_back(id);
    else
      m_sparse[c].push_back(id);
  }

 private:
  double m_cell, m_x0 = 0, m_y0 = 0;
  std::int64_t m_w = 0, m_h = 0;
  std::vector<std::vector<std::uint32_t>> m_dense;
  std::unordered_map<std::array<std::int64_t, 2>, std::vector<std::uint32_t>, Cell_hash> m_sparse;
};

/// Paths through the fixes alone (Gps_trace_options::stand_down_path_factor): the cells of side `cell` that
/// hold a fix, each joined to its 8 neighbours. joined() tells whether such a path leads from one place's
/// cell to another's within a length (between cell centres). Different connected components answer at once;
/// otherwise a best-first search bounded by the octile distance (a lower bound of the length on this grid)
/// answers, exactly but for searches that give up (see joined()).
class Fix_paths {
 public:
  /// Searches give up after this many cells per cell of their length bound: those that succeeded on the 41
  /// cities of benchmark/README.md ("Segment check: the stand-down") took at most 16.3 (a synthetic city of
  /// 5,000 trips every 90 s; 5.4 in the fleet, 2.4 in Chicago thinned to every 40th fix).
  static constexpr double kMaxVisitsPerCell = 32;
  /// Cells taken from the queues of all searches so far (for the progress callback: the work done).
  std::uint64_t visits() const { return m_visits; }

  Fix_paths(const std::vector<std::array<double, 2>>& places, double cell) : m_cell(cell) {
    for (const auto& p : places) m_cells.push_back(key(p[0], p[1]));
    std::sort(m_cells.begin(), m_cells.end());  // ids by position: no dependence on the order of the fixes
    m_cells.erase(std::unique(m_cells.begin(), m_cells.end()), m_cells.end());
    m_id.reserve(m_cells.size());
    for (std::uint32_t i = 0; i < m_cells.size(); ++i) m_id.emplace(m_cells[i], i);
    m_first.assign(m_cells.size() + 1, 0);
    for (std::uint32_t i = 0; i < m_cells.size(); ++i) {
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          if (dx == 0 && dy == 0) continue;
          const auto it = m_id.find({m_cells[i][0] + dx, m_cells[i][1] + dy});
          if (it != m_id.end()) m_next.push_back(it->second);
        }
      m_first[i + 1] = static_cast<std::uint32_t>(m_next.size());
    }
    FeatureRecon::internal::Union_find<std::uint32_t> sets(m_cells.size());  // the smaller id the root
    for (std::uint32_t i = 0; i < m_cells.size(); ++i)
      for (std::uint32_t k = m_first[i]; k < m_first[i + 1]; ++k) sets.unite(i, m_next[k]);
    m_component = sets.labels();
    m_cost.assign(m_cells.size(), 0);
    m_round_of.assign(m_cells.size(), 0);
  }

  /// Whether a path of cells holding fixes, at most L cells long, joins the cells of (ax, ay) and (bx, by),
  /// L = floor(length / cell) (false when either cell holds no fix, or `length` is negative or NaN), found
  /// within kMaxVisitsPerCell (L + 2) cells taken from the search's queue. The same both ways.
  bool joined(double ax, double ay, double bx, double by, double length) {
    if (!(length >= 0)) return false;  // NaN too
    const auto ia = m_id.find(key(ax, ay)), ib = m_id.find(key(bx, by));
    if (ia == m_id.end() || ib == m_id.end()) return false;
    // From the lower cell id to the higher: the same answer both ways (a search that gives up depends on
    // where it starts), and traffic in both directions shares the memo below.
    const std::uint32_t from = std::min(ia->second, ib->second), to = std::max(ia->second, ib->second);
    if (m_component[from] != m_component[to]) return false;
    if (from == to) return true;
    // The bound in whole cells (rounded down: fixes a few metres apart ask the same question), at most the
    // longest path without a repeated cell (a huge length would make the give-up below never come).
    const double limit =
        std::floor(std::min(length / m_cell, std::sqrt(2.0) * static_cast<double>(m_cells.size())));
    const auto& target = m_cells[to];
    auto octile = [&](std::uint32_t i) {
      const double dx = std::fabs(double(m_cells[i][0] - target[0])),
                   dy = std::fabs(double(m_cells[i][1] - target[1]));
      return std::max(dx, dy) + (std::sqrt(2.0) - 1) * std::min(dx, dy);
    };
    if (octile(from) > limit) return false;
    // The same query again (a route driven by many trips): the answer found before.
    const std::array<std::uint64_t, 3> query{from, to, static_cast<std::uint64_t>(limit)};
    const auto known = m_known.find(query);
    if (known != m_known.end()) return known->second;
    const bool found = [&] {
      if (++m_round == 0) {  // the round counter wrapped: forget every mark
        std::fill(m_round_of.begin(), m_round_of.end(), 0);
        m_round = 1;
      }
      // Best first by cost so far + 2 x the octile distance: a path is found after few steps where one exists
      // (most queries). Cells are pruned by the exact bound (cost + octile distance > limit) and reopened
      // when reached more cheaply, so the answer is exact unless the search gives up (below): any cell
      // reached lies on a path within the limit, and when none leads to the target every cell within the
      // bound is tried at its least cost.
      using Entry =
          std::tuple<double, double, std::uint32_t>;  // (order, cost so far, cell): ties by cost, id
      std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
      m_round_of[from] = m_round;
      m_cost[from] = 0;
      open.push({2 * octile(from), 0.0, from});
      // A search that fails within one component would visit every cell of the ellipse the bound leaves,
      // quadratic in the length: it gives up (no path) after taking kMaxVisitsPerCell (limit + 2) cells from
      // the queue, linear like the points a densified segment inserts.
      const double max_visits = kMaxVisitsPerCell * (limit + 2);
      double visits = 0;
      while (!open.empty()) {
        if (++visits > max_visits) return false;
        ++m_visits;
        const auto [order, cost, i] = open.top();
        open.pop();
        if (cost > m_cost[i]) continue;  // reached more cheaply since it was queued
        for (std::uint32_t k = m_first[i]; k < m_first[i + 1]; ++k) {
          const std::uint32_t j = m_next[k];
          const bool diagonal = m_cells[j][0] != m_cells[i][0] && m_cells[j][1] != m_cells[i][1];
          const double g = cost + (diagonal ? std::sqrt(2.0) : 1.0), h = octile(j);
          if ((m_round_of[j] == m_round && m_cost[j] <= g) || g + h > limit) continue;
          if (j == to) return true;
          m_round_of[j] = m_round;
          m_cost[j] = g;
          open.push({g + 2 * h, g, j});
        }
      }
      return false;
    }();
    m_known.emplace(query, found);
    return found;
  }

 private:
  std::array<std::int64_t, 2> key(double x, double y) const {
    return {static_cast<std::int64_t>(std::floor(x / m_cell)),
            static_cast<std::int64_t>(std::floor(y / m_cell))};
  }
  double m_cell;
  std::vector<std::array<std::int64_t, 2>> m_cells;  // sorted
  std::unordered_map<std::array<std::int64_t, 2>, std::uint32_t, Cell_hash> m_id;
  std::vector<std::uint32_t> m_first, m_next, m_component;  // neighbours of cell i: m_next[m_first[i] ..]
  std::vector<double> m_cost;
  std::vector<std::uint32_t> m_round_of;  // the search that last reached each cell
  std::uint32_t m_round = 0;
  struct Query_hash {
    std::size_t operator()(const std::array<std::uint64_t, 3>& q) const {
      return static_cast<std::size_t>((q[0] * 0x9E3779B97F4A7C15ull) ^ (q[1] * 0xC2B2AE3D27D4EB4Full) ^ q[2]);
    }
  };
  std::unordered_map<std::array<std::uint64_t, 3>, bool, Query_hash> m_known;  // (from, to, limit): found
  std::uint64_t m_visits = 0;
};

inline std::array<double, 4> bounding_box(const Point_matrix& m) {
  std::array<double, 4> b{0, 0, 0, 0};
  for (std::size_t i = 0; i < m.rows; ++i) {
    const double x = m.row(i)[0], y = m.row(i)[1];
    if (i == 0) b = {x, y, x, y};
    b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
  }
  return b;
}

/// Removes samples lighter than `fraction` times the heaviest sample within S.density_radius that travels
/// within `heading_tolerance` degrees of the same direction, or lighter than `lateral_fraction` times the
/// heaviest such sample beside them (the offset across the sample's direction at least the offset along it;
/// samples without a direction, per `has_direction`, neither judged nor counted); re-indexes.
inline void drop_sparse_samples(Gps_trace_sample& S, double fraction, double lateral_fraction,
                                double heading_tolerance, const std::vector<bool>& has_direction,
                                const Progress_callback& progress = {}) {
  const double R = S.density_radius, R2 = R * R;
  constexpr double degree = 3.14159265358979323846 / 180.0;
  const std::array<double, 4> box = bounding_box(S.points);
  Planar_grid grid(box[0], box[1], box[2], box[3], R, S.points.rows);
  for (std::uint32_t i = 0; i < S.points.rows; ++i)
    grid.push(grid.cell_of(S.points.row(i)[0], S.points.row(i)[1]), i);
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> new_index(S.points.rows, none);
  Gps_trace_sample T;
  T.points.dimension = 2;
  for (std::uint32_t i = 0; i < S.points.rows; ++i) {
    if (i % 4096 == 0 &&
        !FeatureRecon::internal::report_progress(progress, double(i) / double(S.points.rows))) {
      S.status = Status::interrupted;  // S unfiltered
      return;
    }
    const double x = S.points.row(i)[0], y = S.points.row(i)[1];
    const double ux = std::cos(S.headings[i] * degree), uy = std::sin(S.headings[i] * degree);
    const auto c = grid.cell_of(x, y);
    std::uint32_t heaviest = 0, heaviest_beside = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::vector<std::uint32_t>* bucket = grid.find(c[0] + dx, c[1] + dy);
        if (bucket == nullptr) continue;
        for (const std::uint32_t j : *bucket) {
          const double ex = S.points.row(j)[0] - x, ey = S.points.row(j)[1] - y;
          if (ex * ex + ey * ey <= R2 &&
              heading_difference(S.headings[i], S.headings[j], S.directed) <= heading_tolerance) {
            heaviest = std::max(heaviest, S.weights[j]);
            if (has_direction[j] && std::fabs(ex * uy - ey * ux) >= std::fabs(ex * ux + ey * uy))
              heaviest_beside = std::max(heaviest_beside, S.weights[j]);
          }
        }
      }
    const double w = static_cast<double>(S.weights[i]);
    if (w < fraction * static_cast<double>(heaviest)) continue;
    if (has_direction[i] && w < lateral_fraction * static_cast<double>(heaviest_beside)) {
      ++S.dropped_lateral;
      continue;
    }
    new_index[i] = static_cast<std::uint32_t>(T.headings.size());
    T.points.data.push_back(x);
    T.points.data.push_back(y);
    T.headings.push_back(S.headings[i]);
    T.weights.push_back(S.weights[i]);
  }
  S.dropped = S.points.rows - T.headings.size();
  S.points = std::move(T.points);
  S.points.rows = T.headings.size();
  S.headings = std::move(T.headings);
  S.weights = std::move(T.weights);
  for (auto& s : S.sample_of_fix) s = new_index[s];
  std::vector<Edge> links;
  for (const Edge& e : S.trip_links)
    if (new_index[e[0]] != none && new_index[e[1]] != none)
      links.push_back(
          {std::min(new_index[e[0]], new_index[e[1]]), std::max(new_index[e[0]], new_index[e[1]])});
  S.trip_links = std::move(links);
}

/// The graph on planar points with the given edges, sorted and made unique, and their Euclidean lengths.
inline Proximity_graph planar_graph(const Point_matrix& points, std::vector<Edge> edges) {
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Proximity_graph g;
  g.number_of_vertices = points.rows;
  g.edges = std::move(edges);
  g.edge_lengths.reserve(g.edges.size());
  for (const Edge& e : g.edges)
    g.edge_lengths.push_back(
        std::hypot(points.row(e[0])[0] - points.row(e[1])[0], points.row(e[0])[1] - points.row(e[1])[1]));
  return g;
}

}  // namespace internal

/// Median distance between consecutive fixes (by time) of moving vehicles: the scale the automatic parameters
/// of the GPS pipeline derive from (0 when no trip has two fixes). Non-finite values are skipped. A step
/// does not count while its vehicle stays (a taxi at a rank, a parked car, a long red light): when it starts
/// at most `stay_duration` before its end fix (time t) and the fixes of its trip `stay_duration` before and
/// after that fix (the earliest at or after t - stay_duration and the latest at or before t +
/// stay_duration, at least stay_duration apart in time) both lie within `stay_radius` of it. (Not a bound on
/// the step's own length: GPS jitter of 5 m has a tail of steps beyond 20 m, which made the median.) Waiting
/// vehicles recorded every few seconds otherwise made the median their GPS jitter: 150 taxis waiting 25 to 67
/// minutes beside 400 trips every 10 s moved it from 87 m to 5.6 m, the radius and link gap with it, and the
/// map fell into 20 pieces (F 0.90 -> 0.76; 0.89 now). A vehicle moving steadily faster than 2 stay_radius /
/// stay_duration (1.33 m/s) never stays, nor does a stop shorter than stay_duration; only the window's two
/// ends are compared (a vehicle back at the same place after stay_duration, as on a loop, stays). When every
/// step is a stay, or with an infinite stay_duration, the median of all steps (the command line judges the
/// units of the coordinates by that one: in degrees every fix lies within 20 of every other).
inline double median_gps_step(const std::vector<Gps_trip>& trips, double stay_radius = 20,
                              double stay_duration = 30) {
  std::vector<double> steps, moving;
  for (const Gps_trip& trip : trips) {
    const std::vector<std::size_t> o = internal::time_order(trip);
    const auto distance = [&](std::size_t i, std::size_t j) {
      return std::hypot(trip[o[i]].x - trip[o[j]].x, trip[o[i]].y - trip[o[j]].y);
    };
    const auto time = [&](std::size_t i) { return trip[o[i]].time; };
    std::size_t before = 0, after = 0;  // the window's ends (indices into o), moving forward with k
    for (std::size_t k = 1; k < o.size(); ++k) {
      const double d = distance(k, k - 1);
      if (!std::isfinite(d)) continue;
      steps.push_back(d);
      const double t = time(k);
      bool stays = false;
      if (std::isfinite(t)) {  // NaN times sort last: the window's fixes before k then have finite times
        while (before < k && !(time(before) >= t - stay_duration)) ++before;
        after = std::max(after, k);
        while (after + 1 < o.size() && time(after + 1) <= t + stay_duration) ++after;
        stays = before < k && time(after) - time(before) >= stay_duration &&
                distance(before, k) <= stay_radius && distance(after, k) <= stay_radius;
      }
      if (!stays) moving.push_back(d);
    }
  }
  std::vector<double>& v = moving.empty() ? steps : moving;
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// Densifies and samples GPS traces (see Gps_trace_options). Each sample carries the direction of the segment
/// it came from (for a fix, the segment to the next fix at another place, or from the last one at the end of
/// the trip, so that fixes of a waiting vehicle point the way it drives; a trip that never moves points
/// east); a trace point joins the first earlier sample within the spacing whose direction differs by at most
/// the heading tolerance, so opposite sides of a crossing stay apart when directions are used. Segments are
/// checked first (Gps_trace_options::segment_support): one that leaves the traces where the trip turns (a
/// corner cut between sparse fixes) is not densified. Time O(F + P) grid look-ups for F fixes and P inserted
/// points, plus a kd-tree of the distinct fix positions and a k-nearest query per position that ends a long
/// segment where fixes lie densely (Gps_trace_options::local_support_fixes): O(F log F).
/// \param rips_radius the radius the samples will be joined at (for the automatic rules).
/// \throws std::invalid_argument naming the trip and fix with a non-finite coordinate or time, or a
///   non-positive or non-finite rips_radius, or the option out of range (a sample spacing or density radius
///   that is not positive and finite, a negative or non-finite link gap or segment support, a negative
///   heading tolerance, a turn tolerance outside [0, 180], a confirmed fraction or a density fraction outside
///   [0, 1]), fixes beyond 2^50 sample spacings (or radii, or density radii) from the origin, linking that
///   would insert more than options.max_inserted_points points, or a density filter that would compare more
///   than options.max_density_pairs pairs of samples.
inline Gps_trace_sample sample_gps_traces(const std::vector<Gps_trip>& trips, double rips_radius,
                                          const Gps_trace_options& options = {}) {
  const char* fn = "sample_gps_traces";
  if (!(rips_radius > 0 && std::isfinite(rips_radius)))
    FeatureRecon::internal::throw_invalid_argument(fn, "rips_radius must be positive and finite, got ",
                                                   rips_radius);
  // Lengths with a rule of their own: unset (automatic), a value, 0 (off) only where it turns a stage off.
  using FeatureRecon::internal::check_optional_length;
  check_optional_length(fn, options.sample_spacing, "sample_spacing", "half the Rips radius");
  check_optional_length(fn, options.max_link_gap, "max_link_gap",
                        "max(4 x the median step, 2 x the Rips radius)", "no linking");
  if (!(options.heading_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "heading_tolerance must be >= 0 degrees, got ",
                                                   options.heading_tolerance);
  check_optional_length(fn, options.density_radius, "density_radius", "twice the Rips radius");
  auto check_fraction = [fn](const char* name, double value) {  // in [0, 1], NaN refused
    if (!(value >= 0 && value <= 1))
      FeatureRecon::internal::throw_invalid_argument(fn, name, " must be in [0, 1], got ", value);
  };
  check_fraction("min_relative_density", options.min_relative_density);
  check_fraction("min_lateral_density", options.min_lateral_density);
  if (!(options.density_heading_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "density_heading_tolerance must be >= 0 degrees, got ",
                                                   options.density_heading_tolerance);
  check_optional_length(fn, options.segment_support, "segment_support", "max(20, 2/3 x the Rips radius)",
                        "no check");
  if (!(options.segment_turn_tolerance >= 0 && options.segment_turn_tolerance <= 180))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "segment_turn_tolerance must be in [0, 180] degrees, got ", options.segment_turn_tolerance);
  auto check_fix_count = [&](const char* name, std::size_t value) {  // counts of nearest fixes looked up
    if (value > 1024)
      FeatureRecon::internal::throw_invalid_argument(fn, name, " must be at most 1024, got ", value);
  };
  check_fix_count("local_support_fixes", options.local_support_fixes);
  check_fix_count("quiet_end_fixes", options.quiet_end_fixes);
  if (!(options.min_local_support > 0 && options.min_local_support <= 1))
    FeatureRecon::internal::throw_invalid_argument(fn, "min_local_support must be in (0, 1], got ",
                                                   options.min_local_support);
  check_fraction("min_confirmed_fraction", options.min_confirmed_fraction);
  check_fraction("min_straight_confirmed_fraction", options.min_straight_confirmed_fraction);
  if (!(options.stand_down_path_factor >= 0 && std::isfinite(options.stand_down_path_factor)))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "stand_down_path_factor must be >= 0 and finite (0: off), got ", options.stand_down_path_factor);
  Gps_trace_sample S;
  // Progress through the fixes: `done` of S.fixes at the stage [from, from + width]; true (status
  // interrupted) when the callback says stop. Asked before each trip and every `progress_stride` fixes within
  // one.
  constexpr std::size_t progress_stride = 4096;
  auto stop_at = [&](double from, double width, std::size_t done) {
    const double fraction = from + width * double(done) / double(std::max<std::size_t>(S.fixes, 1));
    if (FeatureRecon::internal::report_progress(options.progress, fraction)) return false;
    S.status = Status::interrupted;
    return true;
  };
  S.points.dimension = 2;
  // Sorted copies of the trips; the median step.
  std::vector<std::vector<std::size_t>> order(trips.size());
  for (std::size_t t = 0; t < trips.size(); ++t) {
    for (std::size_t i = 0; i < trips[t].size(); ++i) {
      const Gps_fix& f = trips[t][i];
      for (const auto& [value, name] :
           {std::pair<double, const char*>{f.x, "x"}, {f.y, "y"}, {f.time, "time"}})
        if (!std::isfinite(value))
          FeatureRecon::internal::throw_invalid_argument(fn, "trip ", t, ", fix ", i, " has a non-finite ",
                                                         name, " (", value, ")");
    }
    order[t] = internal::time_order(trips[t]);
    S.fixes += trips[t].size();
  }
  S.median_step = median_gps_step(trips);
  S.sample_spacing = options.sample_spacing.value_or(rips_radius / 2);
  S.max_link_gap = options.max_link_gap.value_or(std::max(4 * S.median_step, 2 * rips_radius));
  S.density_radius = options.density_radius.value_or(2 * rips_radius);
  // Grid cells are 64-bit integers of position / spacing (or density radius, when that filter is on): beyond
  // 2^50 cells from the origin they would overflow.
  // Points are inserted every half spacing: a spacing whose half is 0 (a denormal, or half of a denormal
  // radius) would never advance.
  if (!(S.sample_spacing / 2 > 0)) {
    if (options.sample_spacing)
      FeatureRecon::internal::throw_invalid_argument(fn, "sample_spacing ", S.sample_spacing,
                                                     " is too small: half of it must be a positive double");
    FeatureRecon::internal::throw_invalid_argument(
        fn, "rips_radius ", rips_radius,
        " is too small: the automatic sample_spacing, half of it, must have a positive half");
  }
  const bool density_filter = options.min_relative_density > 0 || options.min_lateral_density > 0;
  const double finest =
      std::min({S.sample_spacing, rips_radius, density_filter ? S.density_radius : HUGE_VAL});
  const char* finest_name = finest == S.sample_spacing
                                ? (options.sample_spacing ? "sample_spacing" : "sample_spacing (automatic)")
                            : finest == rips_radius  ? "rips_radius"
                            : options.density_radius ? "density_radius"
                                                     : "density_radius (automatic)";
  for (std::size_t t = 0; t < trips.size(); ++t)
    for (std::size_t i = 0; i < trips[t].size(); ++i)
      if (std::max(std::fabs(trips[t][i].x), std::fabs(trips[t][i].y)) / finest > 0x1p50)
        FeatureRecon::internal::throw_invalid_argument(
            fn, "trip ", t, ", fix ", i, " at (", trips[t][i].x, ", ", trips[t][i].y,
            ") lies more than 2^50 times the ", finest_name, " (", finest,
            ") from the origin; shift or scale the traces, or raise that length");
  const double insert_step = S.sample_spacing / 2;
  if (S.max_link_gap > 0 && options.max_inserted_points > 0) {  // the most points linking could insert
    double inserted = 0, longest = 0;
    std::size_t longest_trip = 0, longest_fix = 0;
    for (std::size_t t = 0; t < trips.size(); ++t)
      for (std::size_t i = 0; i + 1 < order[t].size(); ++i) {
        const Gps_fix &a = trips[t][order[t][i]], &b = trips[t][order[t][i + 1]];
        const double d = std::hypot(b.x - a.x, b.y - a.y);
        if (!(d <= S.max_link_gap && d > insert_step)) continue;
        inserted += std::floor(d / insert_step) - 1;  // as the densification below: j = 1 .. n - 1
        if (d > longest) {
          longest = d;
          longest_trip = t;
          longest_fix = order[t][i];
        }
      }
    if (inserted > static_cast<double>(options.max_inserted_points))
      FeatureRecon::internal::throw_invalid_argument(
          fn, "linking consecutive fixes would insert about ", inserted,
          " points along the segments (more than ", "max_inserted_points, ", options.max_inserted_points,
          "; the longest linked segment, from trip ", longest_trip, ", fix ", longest_fix, ", is ", longest,
          " long): lower max_link_gap (", S.max_link_gap, ") or raise sample_spacing (", S.sample_spacing,
          ")");
  }
  const double spacing2 = S.sample_spacing * S.sample_spacing;
  const double cell = S.sample_spacing;
  Point_matrix fixes;
  fixes.dimension = 2;
  for (const Gps_trip& trip : trips)
    for (const Gps_fix& f : trip) {
      fixes.data.push_back(f.x);
      fixes.data.push_back(f.y);
      ++fixes.rows;
    }
  const std::array<double, 4> box = internal::bounding_box(fixes);  // inserted points lie inside it too
  // Which segments the traces confirm (Gps_trace_options::segment_support): use[t][i] for the segment from
  // the i-th to the (i+1)-th fix of trip t in time order.
  enum Segment_use : char { break_trip, densify, link_ends };
  S.segment_support = options.segment_support.value_or(std::max(20.0, 2 * rips_radius / 3));
  S.segment_turn_tolerance = options.segment_turn_tolerance;
  std::vector<std::vector<char>> use(trips.size());
  for (std::size_t t = 0; t < trips.size(); ++t) use[t].assign(trips[t].size(), densify);
  std::vector<std::array<double, 2>> places;  // the distinct fix positions, when the check runs
  if (S.segment_support > 0 && S.max_link_gap > 0) {
    const double support = S.segment_support, support2 = support * support;
    // The distinct fix positions (a parked vehicle logs one place many times) on a grid of cells at least
    // `support` wide and at most about 2^20 across the extent (a tiny support must not overflow the indices).
    places.resize(fixes.rows);
    for (std::size_t i = 0; i < fixes.rows; ++i) places[i] = {fixes.row(i)[0], fixes.row(i)[1]};
    std::sort(places.begin(), places.end());
    places.erase(std::unique(places.begin(), places.end()), places.end());
    const double extent = std::max(box[2] - box[0], box[3] - box[1]);
    const double fix_cell = std::max(
        support, std::isfinite(extent) ? std::ldexp(extent, -20) : std::numeric_limits<double>::max());
    internal::Planar_grid fix_grid(box[0], box[1], box[2], box[3], fix_cell, places.size());
    for (std::uint32_t i = 0; i < places.size(); ++i)
      fix_grid.push(fix_grid.cell_of(places[i][0], places[i][1]), i);
    // The local distance at a fix (Gps_trace_options::local_support_fixes): the distance to the k-th nearest
    // distinct fix position, its own counted; `support` where that is farther (or there are fewer positions).
    std::unique_ptr<internal::Kd_index> place_index;
    const std::size_t local_k = options.local_support_fixes;
    if (local_k > 0 && local_k <= places.size()) {
      Point_matrix m;
      m.dimension = 2;
      m.rows = places.size();
      for (const auto& q : places) m.data.insert(m.data.end(), q.begin(), q.end());
      place_index = std::make_unique<internal::Kd_index>(m);
    }
    // How many distinct fix positions lie within sqrt(r2) <= support of (x, y), counting up to `limit` (the
    // point's own cell first).
    auto fixes_within = [&](double x, double y, double r2, std::size_t limit) {
      std::size_t count = 0;
      const auto c = fix_grid.cell_of(x, y);
      for (std::int64_t k = 0; k < 9; ++k) {
        const std::int64_t dx = (k + 4) % 9 / 3 - 1, dy = (k + 4) % 3 - 1;
        const std::vector<std::uint32_t>* bucket = fix_grid.find(c[0] + dx, c[1] + dy);
        if (bucket == nullptr) continue;
        for (const std::uint32_t j : *bucket) {
          const double ex = places[j][0] - x, ey = places[j][1] - y;
          if (ex * ex + ey * ey <= r2 && ++count == limit) return count;
        }
      }
      return count;
    };
    auto near_a_fix = [&](double x, double y, double within2) { return fixes_within(x, y, within2, 1) == 1; };
    const double min_local = options.min_local_support * support;
    // Once per position (ends of long segments only): where fewer than k positions lie within `support`
    // (counted on the grid, stopping at k) no search is needed.
    std::vector<double> local_at(place_index ? places.size() : 0, -1.0);
    auto local_support = [&](const Gps_fix& f) {
      if (!place_index) return support;
      const std::array<double, 2> at{f.x, f.y};
      // f is one of the places
      const std::size_t q =
          static_cast<std::size_t>(std::lower_bound(places.begin(), places.end(), at) - places.begin());
      if (local_at[q] >= 0) return local_at[q];
      double result = support;
      if (fixes_within(f.x, f.y, support2, local_k) == local_k) {
        using Knn = CGAL::Orthogonal_k_neighbor_search<internal::Kd_traits>;
        const double u = place_index->unit;
        Knn search(*place_index->tree, place_index->points[q], static_cast<unsigned>(local_k), 0.0, true,
                   Knn::Distance(place_index->tree->traits().point_property_map()));
        double kth2 = -1;
        std::size_t found = 0;
        for (auto it = search.begin(); it != search.end(); ++it, ++found) kth2 = it->second;
        const double kth = std::sqrt(kth2) / u;
        if (found == local_k && kth <= support) result = std::max(min_local, kth);
      }
      local_at[q] = result;
      return result;
    };
    // Does trip t go straight through its segment i (from the i-th to the (i+1)-th fix in time order)? The
    // directions it arrives in and leaves by are taken over at least `support` (a vehicle wobbling while it
    // waits does not turn) and never across a gap longer than the link gap; at least one must exist.
    auto drives_straight = [&](std::size_t t, std::size_t i) {
      const auto& o = order[t];
      auto at = [&](std::size_t k) -> const Gps_fix& { return trips[t][o[k]]; };
      auto far_enough = [&](const Gps_fix& p, const Gps_fix& q) {
        return std::hypot(q.x - p.x, q.y - p.y) >= support;
      };
      auto linked_step = [&](std::size_t k) {  // the segment from the k-th fix to the next is not a gap
        return std::hypot(at(k + 1).x - at(k).x, at(k + 1).y - at(k).y) <= S.max_link_gap;
      };
      auto bearing = [](const Gps_fix& p, const Gps_fix& q) {
        return std::atan2(q.y - p.y, q.x - p.x) * 180.0 / 3.14159265358979323846;
      };
      const double own = bearing(at(i), at(i + 1));
      auto turns = [&](double b) {
        const double e = std::fmod(std::fabs(b - own), 360.0);
        return std::min(e, 360.0 - e) > options.segment_turn_tolerance;
      };
      bool neighbour = false;
      for (std::size_t k = i; k-- > 0 && linked_step(k);)  // arriving at fix i
        if (far_enough(at(k), at(i))) {
          if (turns(bearing(at(k), at(i)))) return false;
          neighbour = true;
          break;
        }
      for (std::size_t k = i + 2; k < o.size() && linked_step(k - 1); ++k)  // leaving fix i + 1
        if (far_enough(at(i + 1), at(k))) {
          if (turns(bearing(at(i + 1), at(k)))) return false;
          neighbour = true;
          break;
        }
      return neighbour;
    };
    // The unconfirmed segments wait until the turn rule is judged on all checked ones.
    struct Unconfirmed {
      std::size_t trip, segment;
      double length;
      bool straight;
    };
    std::vector<Unconfirmed> unconfirmed;
    std::size_t checked_fixes = 0;
    for (std::size_t t = 0; t < trips.size(); ++t) {
      if (stop_at(0.0, 0.25, checked_fixes)) return S;
      const auto& o = order[t];
      for (std::size_t i = 0; i + 1 < o.size(); ++i) {
        if (i % progress_stride == progress_stride - 1 && stop_at(0.0, 0.25, checked_fixes + i)) return S;
        const Gps_fix& a = trips[t][o[i]];
        const Gps_fix& b = trips[t][o[i + 1]];
        const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
        if (!(d > 2 * support && d <= S.max_link_gap)) continue;
        // The points inserted below, every insert_step (none: nothing to confirm).
        const std::size_t n = static_cast<std::size_t>(std::floor(d / insert_step));
        if (n < 2) continue;
        ++S.checked_segments;
        auto all_near = [&](double within2) {
          for (std::size_t j = 1; j < n; ++j) {
            const double u = static_cast<double>(j) / static_cast<double>(n);
            if (!near_a_fix(a.x + u * dx, a.y + u * dy, within2)) return false;
          }
          return true;
        };
        const double local = d > 4 * support ? std::max(local_support(a), local_support(b)) : support;
        bool confirmed = all_near(local < support ? local * local : support2);
        if (local < support) {
          ++S.locally_checked;
          if (!confirmed && all_near(support2)) ++S.locally_rejected;
        }
        const bool straight = drives_straight(t, i);
        S.straight_checked += straight ? 1 : 0;
        if (confirmed) {
          ++S.confirmed_segments;
          S.straight_confirmed += straight ? 1 : 0;
        } else {
          unconfirmed.push_back({t, i, d, straight});
        }
      }
      checked_fixes += o.size();
    }
    S.turn_rule_used = internal::wilson_upper_bound(S.straight_confirmed, S.straight_checked) >=
                       options.min_straight_confirmed_fraction;
    // Both ends quiet (Gps_trace_options::quiet_end_fixes): asked only where the turn rule is not trusted.
    auto quiet = [&](const Unconfirmed& u) {
      const std::size_t q = options.quiet_end_fixes;
      const Gps_fix& a = trips[u.trip][order[u.trip][u.segment]];
      const Gps_fix& b = trips[u.trip][order[u.trip][u.segment + 1]];
      return q > 0 && fixes_within(a.x, a.y, support2, q) < q && fixes_within(b.x, b.y, support2, q) < q;
    };
    for (const Unconfirmed& u : unconfirmed) {
      if (u.straight && (S.turn_rule_used || quiet(u))) {
        ++S.straight_segments;
        S.quiet_segments += S.turn_rule_used ? 0 : 1;
      } else if (u.length <= 4 * support) {
        use[u.trip][u.segment] = link_ends;
        ++S.linked_segments;
      } else {
        use[u.trip][u.segment] = break_trip;
      }
    }
  }
  if (!(S.segment_support > 0 && S.max_link_gap > 0)) {
    S.all_segments_used = true;
  } else if (static_cast<double>(S.confirmed_segments + S.locally_rejected) <
             options.min_confirmed_fraction * static_cast<double>(S.checked_segments)) {
    // The check stands down: every segment is densified, except those whose ends the fixes join without it
    // (Gps_trace_options::stand_down_path_factor), which keep the check's verdict.
    S.all_segments_used = true;
    std::unique_ptr<internal::Fix_paths> paths;
    if (options.stand_down_path_factor > 0)
      paths = std::make_unique<internal::Fix_paths>(places, S.sample_spacing);  // of the check's positions
    // The callback is asked before each trip, and within one every 4,096 fixes or 2^20 cells searched.
    std::size_t done = 0;
    std::uint64_t asked_at = 0;
    for (std::size_t t = 0; t < trips.size(); ++t) {
      if (stop_at(0.25, 0.05, done)) return S;
      asked_at = paths ? paths->visits() : 0;
      const auto& o = order[t];
      for (std::size_t i = 0; i + 1 < o.size(); ++i) {
        const bool searched = paths && paths->visits() - asked_at >= (std::uint64_t(1) << 20);
        if (i % progress_stride == progress_stride - 1 || searched) {
          if (stop_at(0.25, 0.05, done + i)) return S;
          asked_at = paths ? paths->visits() : 0;
        }
        if (use[t][i] == densify) continue;
        const Gps_fix& a = trips[t][o[i]];
        const Gps_fix& b = trips[t][o[i + 1]];
        if (paths && paths->joined(a.x, a.y, b.x, b.y,
                                   options.stand_down_path_factor * std::hypot(b.x - a.x, b.y - a.y) +
                                       2 * S.sample_spacing))
          ++S.joined_segments;
        else {
          if (use[t][i] == link_ends) --S.linked_segments;  // counted as linked by the check
          use[t][i] = densify;
        }
      }
      done += o.size();
    }
  }
  std::vector<std::array<double, 2>>().swap(places);  // not needed by the sampling
  internal::Planar_grid grid(box[0], box[1], box[2], box[3], cell, fixes.rows);
  std::vector<bool> has_direction;  // per sample: a point of a moving trip joined it
  // The pairs the density filter will compare (every sample with the samples in the 3 x 3 cells of side
  // density_radius around it), counted as samples are made, so that a spacing far below the radius is refused
  // before it makes millions of samples (3,000 Chicago fixes at spacing 0.01 made 7.3 million samples in 38 s
  // and 1 GB when the filter counted them afterwards).
  const bool count_pairs = density_filter && options.max_density_pairs > 0;
  std::unordered_map<std::array<std::int64_t, 2>, std::uint64_t, internal::Cell_hash> per_cell;
  double density_pairs = 0;
  // The sample a trace point joins (creating one if none is close): first in creation order.
  auto join = [&](double x, double y, double heading, bool moving = true) -> std::uint32_t {
    const auto c = grid.cell_of(x, y);
    std::uint32_t best = std::numeric_limits<std::uint32_t>::max();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::vector<std::uint32_t>* bucket = grid.find(c[0] + dx, c[1] + dy);
        if (bucket == nullptr) continue;
        for (const std::uint32_t s : *bucket) {
          if (s >= best) break;  // cells hold samples in creation order
          const double ex = S.points.data[2 * s] - x, ey = S.points.data[2 * s + 1] - y;
          if (ex * ex + ey * ey < spacing2 &&
              internal::heading_difference(S.headings[s], heading, options.directed) <=
                  options.heading_tolerance)
            best = s;
        }
      }
    if (best == std::numeric_limits<std::uint32_t>::max()) {
      best = static_cast<std::uint32_t>(S.headings.size());
      S.points.data.push_back(x);
      S.points.data.push_back(y);
      S.headings.push_back(heading);
      S.weights.push_back(0);
      has_direction.push_back(false);
      grid.push(c, best);
      if (count_pairs) {
        const std::array<std::int64_t, 2> d{static_cast<std::int64_t>(std::floor(x / S.density_radius)),
                                            static_cast<std::int64_t>(std::floor(y / S.density_radius))};
        std::uint64_t around = 0;  // samples in the 3 x 3 cells, before this one
        for (std::int64_t dx = -1; dx <= 1; ++dx)
          for (std::int64_t dy = -1; dy <= 1; ++dy) {
            const auto it = per_cell.find({d[0] + dx, d[1] + dy});
            if (it != per_cell.end()) around += it->second;
          }
        ++per_cell[d];
        density_pairs += 2 * static_cast<double>(around) + 1;  // both orders with each of them, and itself
        if (density_pairs > static_cast<double>(options.max_density_pairs))
          FeatureRecon::internal::throw_invalid_argument(
              fn, "the density filter would compare at least ", density_pairs, " pairs of the first ",
              S.headings.size(), " samples (more than max_density_pairs, ", options.max_density_pairs,
              "; counted ", "while the samples were made): the sample spacing (sample_spacing ",
              S.sample_spacing, ") is small ", "for the density radius (density_radius ", S.density_radius,
              "); raise the spacing, lower the radius, ",
              "or turn the filter off (min_relative_density and min_lateral_density 0)");
      }
    }
    ++S.weights[best];
    if (moving) has_direction[best] = true;
    return best;
  };
  S.directed = options.directed;
  S.heading_tolerance = options.heading_tolerance;
  const double period = options.directed ? 360.0 : 180.0;
  auto heading_of = [period](double dx, double dy) {
    if (dx == 0 && dy == 0) return 0.0;
    double h = std::atan2(dy, dx) * 180.0 / 3.14159265358979323846;
    while (h < 0) h += period;
    while (h >= period) h -= period;
    return h;
  };
  S.sample_of_fix.assign(S.fixes, 0);
  std::size_t first_fix = 0;
  for (std::size_t t = 0; t < trips.size(); ++t) {
    if (stop_at(0.3, 0.5, first_fix)) return S;
    const auto& o = order[t];
    std::uint32_t previous = std::numeric_limits<std::uint32_t>::max();
    auto link = [&](std::uint32_t s) {
      if (previous != std::numeric_limits<std::uint32_t>::max() && previous != s)
        S.trip_links.push_back({std::min(previous, s), std::max(previous, s)});
      previous = s;
    };
    // Direction of a fix: towards the next fix at another place; at the end of the trip, from the last fix at
    // another place. A vehicle waiting at a light keeps the direction it drives off in.
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    auto same_place = [&](std::size_t i, std::size_t j) {
      return trips[t][o[i]].x == trips[t][o[j]].x && trips[t][o[i]].y == trips[t][o[j]].y;
    };
    std::vector<std::size_t> next_move(o.size(), none), previous_move(o.size(), none);
    for (std::size_t i = o.size(); i-- > 1;) next_move[i - 1] = same_place(i - 1, i) ? next_move[i] : i;
    for (std::size_t i = 1; i < o.size(); ++i)
      previous_move[i] = same_place(i - 1, i) ? previous_move[i - 1] : i - 1;
    for (std::size_t i = 0; i < o.size(); ++i) {
      if (i % progress_stride == progress_stride - 1 && stop_at(0.3, 0.5, first_fix + i)) return S;
      const Gps_fix& f = trips[t][o[i]];
      double hx = 0, hy = 0;
      if (next_move[i] != none) {
        hx = trips[t][o[next_move[i]]].x - f.x;
        hy = trips[t][o[next_move[i]]].y - f.y;
      } else if (previous_move[i] != none) {
        hx = f.x - trips[t][o[previous_move[i]]].x;
        hy = f.y - trips[t][o[previous_move[i]]].y;
      }
      const double h = heading_of(hx, hy);
      double dx = 0, dy = 0;  // the segment to the next fix, densified below
      if (i + 1 < o.size()) {
        dx = trips[t][o[i + 1]].x - f.x;
        dy = trips[t][o[i + 1]].y - f.y;
      }
      const std::uint32_t s = join(f.x, f.y, h, next_move[i] != none || previous_move[i] != none);
      S.sample_of_fix[first_fix + o[i]] = s;
      if (i > 0) {
        const Gps_fix& p = trips[t][o[i - 1]];
        if (!(S.max_link_gap > 0 && std::hypot(f.x - p.x, f.y - p.y) <= S.max_link_gap) ||
            use[t][i - 1] == break_trip)
          // a gap or a corner cut: the trip restarts here
          previous = std::numeric_limits<std::uint32_t>::max();
      }
      link(s);
      if (i + 1 < o.size() && S.max_link_gap > 0) {
        const double d = std::hypot(dx, dy);
        if (d <= S.max_link_gap && d > insert_step && use[t][i] == densify) {
          const std::size_t n = static_cast<std::size_t>(std::floor(d / insert_step));
          for (std::size_t j = 1; j < n; ++j) {
            const double u = static_cast<double>(j) / static_cast<double>(n);
            link(join(f.x + u * dx, f.y + u * dy, h));
          }
        }
      }
    }
    first_fix += trips[t].size();
  }
  S.points.rows = S.headings.size();
  S.density_heading_tolerance = options.density_heading_tolerance;
  if ((options.min_relative_density > 0 || options.min_lateral_density > 0) && S.points.rows > 0) {
    Progress_callback filter_progress;
    if (options.progress) filter_progress = [&options](double f) { return options.progress(0.8 + 0.2 * f); };
    internal::drop_sparse_samples(S, options.min_relative_density, options.min_lateral_density,
                                  options.density_heading_tolerance, has_direction, filter_progress);
    if (S.status == Status::interrupted) return S;
  }
  if (options.mean_positions) {  // each sample at the mean of its fixes
    std::vector<double> sum(2 * S.points.rows, 0.0);
    std::vector<std::uint32_t> count(S.points.rows, 0);
    // Summed in time order (ties by line), as the trips are read: in file order, lines of a trip given out of
    // order moved a sample by a rounding (13 vertices of the Chicago map with each trip's lines shuffled).
    std::size_t first = 0;
    for (std::size_t t = 0; t < trips.size(); ++t) {
      for (const std::size_t i : order[t]) {
        const std::uint32_t s = S.sample_of_fix[first + i];
        if (s >= S.points.rows) continue;  // dropped as sparse
        sum[2 * s] += trips[t][i].x;
        sum[2 * s + 1] += trips[t][i].y;
        ++count[s];
      }
      first += trips[t].size();
    }
    for (std::size_t s = 0; s < S.points.rows; ++s)
      if (count[s] > 0) {
        S.points.data[2 * s] = sum[2 * s] / count[s];
        S.points.data[2 * s + 1] = sum[2 * s + 1] / count[s];
      }
  }
  std::sort(S.trip_links.begin(), S.trip_links.end());
  S.trip_links.erase(std::unique(S.trip_links.begin(), S.trip_links.end()), S.trip_links.end());
  return S;
}

/// Options of build_gps_trace_graph().
struct Gps_trace_graph_options {
  /// Rips edges join samples whose travel directions differ by at most this angle (degrees; directed or not,
  /// as sampled), >= 0. Automatic (default): the sample's, Gps_trace_sample::heading_tolerance (the
  /// Gps_trace_options::heading_tolerance it was sampled with); 180 or more (90 or more for undirected
  /// samples): directions are ignored. Negative: refused (before FeatureRecon::automatic it asked for the
  /// sample's).
  std::optional<double> heading_tolerance = FeatureRecon::automatic;
  Neighbor_search search = Neighbor_search::automatic;  ///< neighbour search of the Rips edges
  /// Called with the fraction done; returning false stops (the graph is partial, with status interrupted; as
  /// build_rips_graph()).
  Progress_callback progress;
};

/// The proximity graph of GPS samples: Rips edges of length at most `rips_radius` between samples whose
/// headings differ by at most the heading tolerance (Gps_trace_graph_options::heading_tolerance; directed or
/// not, as sampled), plus the trip links; lengths are Euclidean.
/// \throws std::invalid_argument when the heading tolerance is negative or NaN (in the options or in S), when S is inconsistent
///         (points not planar or not one heading per point, a heading outside its range, a trip link naming a
///         missing sample or joining a sample to itself), or as build_rips_graph().
inline Proximity_graph build_gps_trace_graph(const Gps_trace_sample& S, double rips_radius,
                                             const Gps_trace_graph_options& options = {}) {
  const char* fn = "build_gps_trace_graph";
  if (options.heading_tolerance && !(*options.heading_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the option heading_tolerance must be >= 0 degrees (FeatureRecon::automatic: the sample's), got ",
        *options.heading_tolerance);
  const double heading_tolerance = options.heading_tolerance.value_or(S.heading_tolerance);
  if (!(heading_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the sample's heading_tolerance must be >= 0 degrees, got ", heading_tolerance);
  if (S.points.dimension != 2 || S.points.data.size() != 2 * S.points.rows)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the samples must be planar points (dimension 2, ", "2 coordinates per row), got dimension ",
        S.points.dimension, " with ", S.points.data.size(), " values for ", S.points.rows, " rows");
  if (S.headings.size() != S.points.rows)
    FeatureRecon::internal::throw_invalid_argument(fn, "there are ", S.points.rows, " samples but ",
                                                   S.headings.size(), " headings");
  const double period = S.directed ? 360 : 180;
  for (std::size_t i = 0; i < S.headings.size(); ++i)
    if (!(S.headings[i] >= 0 && S.headings[i] < period))
      FeatureRecon::internal::throw_invalid_argument(fn, "heading ", i, " (", S.headings[i],
                                                     ") is not in [0, ", period, ")");
  for (std::size_t k = 0; k < S.trip_links.size(); ++k)
    if (S.trip_links[k][0] >= S.points.rows || S.trip_links[k][1] >= S.points.rows ||
        S.trip_links[k][0] == S.trip_links[k][1])
      FeatureRecon::internal::throw_invalid_argument(fn, "trip link ", k, " (", S.trip_links[k][0], ", ",
                                                     S.trip_links[k][1],
                                                     ") is a loop or names a sample >= ", S.points.rows);
  Proximity_graph_options ro;
  ro.search = options.search;
  ro.progress = options.progress;
  Proximity_graph rips = build_rips_graph(S.points, rips_radius, ro);
  std::vector<Edge> edges;
  edges.reserve(rips.edges.size() + S.trip_links.size());
  for (const Edge& e : rips.edges)
    if (heading_tolerance >= (S.directed ? 180 : 90) ||
        internal::heading_difference(S.headings[e[0]], S.headings[e[1]], S.directed) <= heading_tolerance)
      edges.push_back(e);
  for (const Edge& link : S.trip_links)  // either order: a link is undirected in the graph
    edges.push_back({std::min(link[0], link[1]), std::max(link[0], link[1])});
  Proximity_graph g = internal::planar_graph(S.points, std::move(edges));
  g.status = rips.status;
  return g;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_GPS_TRACES_H
