// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_RING_GRID_H
#define FEATURERECON_SAMPLING_INTERNAL_RING_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace sampling {
namespace internal {

/// \cond
/// A dense grid over points in D dimensions (2 or 3) with a nearest search by growing Chebyshev rings of
/// cells, for any score s(j) bounded below by (spatial distance) / scale: the search stops once no unvisited
/// cell can beat the best score. Ties of the score go to the lowest index, whatever the visiting order, so
/// results are deterministic. The frame is fixed at construction (a box holding every query and point);
/// points and queries outside are clamped to the border cells, which keeps the search exact because the
/// bound is then taken from the clamped cell's true box.
template <int D>
class Ring_grid {
 public:
  using Point = std::array<double, D>;

  Ring_grid() = default;

  /// \param lo, hi the frame. \param target_cells about how many cells (>= 1).
  Ring_grid(const Point& lo, const Point& hi, double target_cells) : m_lo(lo) {
    double extent_max = 0;
    std::array<bool, D> active{};
    for (int k = 0; k < D; ++k) {
      extent_max = std::max(extent_max, hi[k] - lo[k]);
      active[k] = hi[k] - lo[k] > 0;
    }
    m_side = 1;
    // The side that gives about target_cells cells over the axes that are at least a cell wide: an axis
    // thinner than the side (a nearly flat patch in 3-D) gets one cell and does not shrink the others' cells
    // (it used to make about n^2 cells for n points). At most D + 1 rounds.
    for (int round = 0; round <= D && extent_max > 0; ++round) {
      double measure = 1;
      int positive = 0;
      for (int k = 0; k < D; ++k)
        if (active[k]) {
          measure *= hi[k] - lo[k];
          ++positive;
        }
      if (positive == 0) break;
      m_side = std::pow(measure / std::max(1.0, target_cells), 1.0 / positive);
      if (!(measure >= std::numeric_limits<double>::min()) || std::isinf(measure)) {
        // The product left the normal range (extents of 1e-110 in 3-D: 0, and a side of extent / target,
        // target^D cells): the same side from the extents relative to the largest.
        double relative = 1;
        for (int k = 0; k < D; ++k)
          if (active[k]) relative *= (hi[k] - lo[k]) / extent_max;
        m_side = extent_max * std::pow(relative / std::max(1.0, target_cells), 1.0 / positive);
      }
      // No axis gets more than about target_cells cells, and the total stays bounded.
      m_side = std::max(m_side, extent_max / std::max(1.0, target_cells));
      bool dropped = false;
      for (int k = 0; k < D; ++k)
        if (active[k] && hi[k] - lo[k] < m_side) {
          active[k] = false;
          dropped = true;
        }
      if (!dropped) break;
    }
    if (!(m_side > 0) || !std::isfinite(m_side)) m_side = 1;
    m_count = 1;
    for (int k = 0; k < D; ++k) {
      m_cells[k] =
          std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor((hi[k] - lo[k]) / m_side)) + 1);
      m_count *= static_cast<std::size_t>(m_cells[k]);
    }
  }

  /// Buckets the points (indices kept in increasing order within a cell).
  void assign(const std::vector<Point>& points) {
    m_offsets.assign(m_count + 1, 0);
    std::vector<std::uint32_t> cell_of(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      cell_of[i] = static_cast<std::uint32_t>(linear(cell(points[i])));
      ++m_offsets[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < m_count; ++c) m_offsets[c + 1] += m_offsets[c];
    m_items.resize(points.size());
    std::vector<std::uint32_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
      m_items[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  }

  double side() const { return m_side; }
  std::size_t number_of_cells() const { return m_count; }

  /// The index j minimising score(j) (ties: lowest j) over the points, or max() when there are none. A NaN
  /// score counts as infinity (a point is found whenever there are any).
  /// \param scale score(j) >= |x - point j| / scale for every j (scale > 0; infinity: plain scan of all).
  template <class Score>
  std::uint32_t nearest(const Point& x, double scale, Score&& score, double& best) const {
    bool complete;
    return nearest(x, scale, score, best, std::numeric_limits<std::int64_t>::max(),
                   std::numeric_limits<std::size_t>::max(), complete);
  }

  /// nearest() over the rings 0 to ring_limit around x's cell and at most score_limit points: `complete`
  /// tells whether that settled the answer (no unvisited cell can beat it). If not, the answer is the best of
  /// the scored points (or max() for none), for a search that goes on elsewhere (Nearest_tree with it as the
  /// hint): where the points cover a small part of the frame, rings of empty cells made the search O(cells),
  /// and where they crowd into a few cells (one point far away, points on a surface in 3-D) the first rings
  /// scored most of them.
  template <class Score>
  std::uint32_t nearest(const Point& x, double scale, Score&& score, double& best, std::int64_t ring_limit,
                        std::size_t score_limit, bool& complete) const {
    best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = std::numeric_limits<std::uint32_t>::max();
    complete = true;
    std::size_t scored = 0;
    if (m_items.empty()) return arg;
    const std::array<std::int64_t, D> c = cell(x);
    std::int64_t max_ring = 0;
    for (int k = 0; k < D; ++k) max_ring = std::max({max_ring, c[k], m_cells[k] - 1 - c[k]});
    for (std::int64_t r = 0; r <= max_ring; ++r) {
      if (r > ring_limit) {
        complete = false;
        break;
      }
      visit_ring(c, r, [&](std::size_t cell_index) {
        for (std::uint32_t t = m_offsets[cell_index]; t < m_offsets[cell_index + 1]; ++t) {
          if (scored == score_limit) {
            complete = false;
            return;
          }
          ++scored;
          const std::uint32_t j = m_items[t];
          double s = score(j);
          if (std::isnan(s)) s = std::numeric_limits<double>::infinity();
          if (s < best || (s == best && j < arg)) {
            best = s;
            arg = j;
          }
        }
      });
      if (!complete) break;
      // Every unvisited cell lies beyond the faces of the block of rings 0..r that have cells behind them.
      double bound = std::numeric_limits<double>::infinity();
      for (int k = 0; k < D; ++k) {
        if (c[k] - r > 0) bound = std::min(bound, x[k] - (m_lo[k] + double(c[k] - r) * m_side));
        if (c[k] + r < m_cells[k] - 1)
          bound = std::min(bound, m_lo[k] + double(c[k] + r + 1) * m_side - x[k]);
      }
      if (std::isinf(bound)) break;
      if (arg != std::numeric_limits<std::uint32_t>::max() && bound > 0 &&
          bound / scale > best * (1 + 1e-12) + std::numeric_limits<double>::min())
        break;
    }
    return arg;
  }

  /// Calls f(j) for every point j in the cells meeting the ball of radius `radius` around x (a superset).
  template <class F>
  void for_each_within(const Point& x, double radius, F&& f) const {
    std::array<std::int64_t, D> a, b;
    for (int k = 0; k < D; ++k) {
      a[k] = clamp_cell(std::floor((x[k] - radius - m_lo[k]) / m_side), k);
      b[k] = clamp_cell(std::floor((x[k] + radius - m_lo[k]) / m_side), k);
    }
    std::array<std::int64_t, D> q = a;
    for (;;) {
      const std::size_t ci = linear(q);
      for (std::uint32_t t = m_offsets[ci]; t < m_offsets[ci + 1]; ++t) f(m_items[t]);
      int k = 0;
      while (k < D && ++q[k] > b[k]) {
        q[k] = a[k];
        ++k;
      }
      if (k == D) break;
    }
  }

 private:
  std::int64_t clamp_cell(double v, int k) const {
    if (!(v > 0)) return 0;  // also NaN
    return std::min<std::int64_t>(m_cells[k] - 1,
                                  v >= double(m_cells[k]) ? m_cells[k] - 1 : static_cast<std::int64_t>(v));
  }
  std::array<std::int64_t, D> cell(const Point& p) const {
    std::array<std::int64_t, D> c;
    for (int k = 0; k < D; ++k) c[k] = clamp_cell(std::floor((p[k] - m_lo[k]) / m_side), k);
    return c;
  }
  std::size_t linear(const std::array<std::int64_t, D>& c) const {
    std::size_t i = 0;
    for (int k = D - 1; k >= 0; --k)
      i = i * static_cast<std::size_t>(m_cells[k]) + static_cast<std::size_t>(c[k]);
    return i;
  }
  // Calls f(cell index) for the cells at Chebyshev distance exactly r from c, inside the grid.
  template <class F>
  void visit_ring(const std::array<std::int64_t, D>& c, std::int64_t r, F&& f) const {
    std::array<std::int64_t, D> a, b;
    for (int k = 0; k < D; ++k) {
      a[k] = std::max<std::int64_t>(0, c[k] - r);
      b[k] = std::min<std::int64_t>(m_cells[k] - 1, c[k] + r);
    }
    std::array<std::int64_t, D> q = a;
    for (;;) {
      bool on_ring = r == 0;
      for (int k = 0; k < D && !on_ring; ++k) on_ring = q[k] == c[k] - r || q[k] == c[k] + r;
      if (on_ring) {
        f(linear(q));
      } else {
        // Jump over the interior of the ring along axis 0.
        q[0] = std::min(b[0], c[0] + r);
        if (q[0] == c[0] + r) f(linear(q));
      }
      int k = 0;
      while (k < D && ++q[k] > b[k]) {
        q[k] = a[k];
        ++k;
      }
      if (k == D) break;
    }
  }

  Point m_lo{};
  double m_side = 1;
  std::array<std::int64_t, D> m_cells{};
  std::size_t m_count = 1;
  std::vector<std::uint32_t> m_offsets{0, 0}, m_items;
};
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_RING_GRID_H
