// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_UNIFORM_GRID_H
#define FEATURERECON_INTERNAL_UNIFORM_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <FeatureRecon/assertions.h>

namespace FeatureRecon {
namespace internal {

/// \cond
/// The frame of a grid over points of dimension D (2 or 3, doubles): cubic cells of side `cell` keyed by
/// their integer coordinates relative to the bounding box. When the box holds at most 2^20 cells per axis the
/// key packs the coordinates (21 bits per axis, keys ordered like the cells); beyond that (one far outlier, a
/// tiny radius) the key is a 64-bit mix of the coordinates, so the cells keep their side (the side used to
/// grow to extent / 2^20, putting a unit square's points in one cell beside an outlier at 1e7: quadratic).
/// Keys of distinct cells may then collide: a cell's list may hold points of another cell, which callers drop
/// by their exact distance test, and for_each_neighbor_key() visits each key once.
///
/// A frame can also number the cells of a box densely (dense_index(), nested over the axes: the order of
/// packed keys), so that a grid keeps them in an array instead of a hash map: the bounding box when it has
/// few cells (use_dense_cells()), else, when a few points lie far from the others (an outlier at 1e7 beside a
/// unit square; a stray point of a scan), a core box around the bulk (use_core_cells()): the grid keeps the
/// cells of the core in an array and the few others in a hash map (dart throwing beside such an outlier ran
/// at a third of its speed).
template <int D>
class Grid_frame {
 public:
  using Point = std::array<double, D>;
  using Cell = std::array<std::int64_t, D>;

  Grid_frame(const std::vector<Point>& points, double cell) {
    if (points.empty()) return;
    m_low = points[0];
    Point high = points[0];
    for (const Point& p : points)
      for (int k = 0; k < D; ++k) {
        m_low[k] = std::min(m_low[k], p[k]);
        high[k] = std::max(high[k], p[k]);
      }
    double extent = 0;
    for (int k = 0; k < D; ++k) extent = std::max(extent, high[k] - m_low[k]);
    m_cell = std::max(cell, std::numeric_limits<double>::min());
    m_hashed = extent / m_cell > double(1 << 20);
    // Hashed: cell coordinates stay far inside 64-bit integers.
    if (m_hashed) m_cell = std::max(m_cell, extent / 0x1p60);
    m_cells = 1;
    for (int k = 0; k < D; ++k) {
      m_count[k] = m_hashed ? 0 : std::min<std::int64_t>(cell_of(high)[k] + 1, kLimit);
      m_cells *= m_hashed ? 0.0 : double(m_count[k]);
    }
  }
  double cell_size() const { return m_cell; }
  bool hashed() const { return m_hashed; }
  /// Number of cells of the box that dense_index() numbers: the points' bounding box (0 when hashed), or the
  /// core box after set_core(). A dense array of that many cells can stand for the key map (of the core's
  /// cells); dense_index() orders them as the packed keys.
  double cells() const { return m_cells; }
  /// Whether set_core() chose a core box: cells outside it may hold points.
  bool has_core() const { return m_core; }
  /// Whether `other` numbers the same cells the same way (the same origin, cell size, box and core).
  bool same_box(const Grid_frame& other) const {
    return m_low == other.m_low && m_cell == other.m_cell && m_hashed == other.m_hashed &&
           m_core == other.m_core && m_origin == other.m_origin && m_count == other.m_count &&
           m_cells == other.m_cells;
  }
  /// Index of cell c in a dense array of cells(), or -1 when c lies outside the box (the bounding box: no
  /// point there; the core box: see has_core()).
  std::int64_t dense_index(const Cell& c) const {
    std::int64_t i = 0;
    for (int k = 0; k < D; ++k) {
      const std::int64_t d = c[k] - m_origin[k];
      if (d < 0 || d >= m_count[k]) return -1;
      i = i * m_count[k] + d;
    }
    return i;
  }
  /// Calls f(dense index) for each cell of the 3^D around p inside the box that dense_index() numbers (packed
  /// frames, or after set_core()), nested over the axes (the first outermost): for packed keys the order of
  /// for_each_neighbor_key().
  template <class F>
  void for_each_neighbor_index(const Point& p, F&& f) const {
    Cell c = cell_of(p);
    for (int k = 0; k < D; ++k) c[k] -= m_origin[k];
    Cell q;
    visit<0>(c, q, &m_count, [&](const Cell& r) {
      std::int64_t i = 0;
      for (int k = 0; k < D; ++k) i = i * m_count[k] + r[k];
      f(i);
    });
  }
  /// Chooses a core box for a dense array of at most `max_cells` cells where the bounding box has more (a
  /// few points far from the others): per axis the cells from the 1/16 to the 15/16 quantile of the points'
  /// cells, widened on both sides by half that width, a quarter, ... (within the bounding box), the widest
  /// that fits: a uniform or Gaussian bulk lies inside (the Gaussian but 0.2 % beyond 3 sigma), a far cluster
  /// of fewer than 1/16 of the points outside. Holds at least 1 - 2 D / 16 of the points. Returns false (the
  /// frame unchanged) for fewer than 64 points, when even the quantiles' box has more cells, or when the
  /// points occupy fewer than 1/64 of every such core's cells (a curve: the hash map of its cells costs
  /// less).
  bool set_core(const std::vector<Point>& points, double max_cells) {
    const std::size_t n = points.size();
    if (n < 64) return false;
    Cell low, high, first, last;
    std::vector<std::int64_t> v(n);
    for (int k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < n; ++i) v[i] = cell_coordinate(points[i], k);
      const auto a = v.begin() + std::ptrdiff_t(n / 16), b = v.begin() + std::ptrdiff_t(n - 1 - n / 16);
      std::nth_element(v.begin(), a, v.end());
      low[k] = *a;
      std::nth_element(a, b, v.end());
      high[k] = *b;
      first[k] = *std::min_element(v.begin(), v.end());
      last[k] = *std::max_element(v.begin(), v.end());
    }
    const Cell full_count = m_count;
    const double full_cells = m_cells;
    for (const double widen : {0.5, 0.25, 0.125, 0.0625, 0.0}) {
      Cell origin, count;
      double cells = 1;
      for (int k = 0; k < D; ++k) {
        const double width = double(high[k] - low[k] + 1);
        const std::int64_t margin = static_cast<std::int64_t>(std::min(std::ceil(widen * width), 0x1p61));
        origin[k] = std::max(first[k], low[k] - margin);
        count[k] = std::min(last[k], high[k] + margin) - origin[k] + 1;
        cells *= double(count[k]);
      }
      if (cells > max_cells) continue;
      m_origin = origin;
      m_count = count;
      m_cells = cells;
      m_core = true;
      // The bulk must fill the core: a curve beside an outlier (1M points on a diagonal, cells of 5e-4)
      // occupies one cell in 1,400 of it, and 4 million empty cells cost a dart throwing 0.3 s where the hash
      // map of the occupied ones cost 1 ms. At least 1/64 of the cells hold a point (else a narrower core).
      std::vector<bool> occupied(static_cast<std::size_t>(cells), false);
      std::size_t filled = 0;
      for (const Point& p : points) {
        const std::int64_t i = dense_index(cell_of(p));
        if (i >= 0 && !occupied[std::size_t(i)]) {
          occupied[std::size_t(i)] = true;
          ++filled;
        }
      }
      if (64 * double(filled) >= cells) return true;
    }
    m_origin = Cell{};
    m_count = full_count;
    m_cells = full_cells;
    m_core = false;
    return false;
  }
  /// Whether some of the 3^D cells around p lie outside the core box (false without one).
  bool reaches_beyond_core(const Point& p) const {
    if (!m_core) return false;
    const Cell c = cell_of(p);
    for (int k = 0; k < D; ++k)
      if (c[k] - 1 < m_origin[k] || c[k] + 1 >= m_origin[k] + m_count[k]) return true;
    return false;
  }
  /// Calls f(key) once for each key of the 3^D cells around p that lie outside the core box (in key order).
  template <class F>
  void for_each_key_beyond_core(const Point& p, F&& f) const {
    const Cell c = cell_of(p);
    Cell q;
    std::array<std::uint64_t, 27> keys;
    std::size_t count = 0;
    visit<0>(c, q, m_hashed ? nullptr : &m_key_limit, [&](const Cell& r) {
      if (dense_index(r) < 0) keys[count++] = key(r);
    });
    std::sort(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count));
    count = static_cast<std::size_t>(
        std::unique(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count)) - keys.begin());
    for (std::size_t i = 0; i < count; ++i) f(keys[i]);
  }
  /// A key that orders cells as a grid over this frame stores them: the cells of the core box by dense index
  /// (below 2^26), then the others by key with its top bit set (packed keys have 63 bits: exact; hashed keys
  /// may share it as they may share the key); without a core, the key.
  std::uint64_t order_key(const Cell& c) const {
    if (!m_core) return key(c);
    const std::int64_t i = dense_index(c);
    return i >= 0 ? static_cast<std::uint64_t>(i) : (std::uint64_t(1) << 63) | key(c);
  }
  /// The cell of p; a query point far outside the box (more cells away than a 64-bit integer holds: a map
  /// compared at a tiny threshold with one far away, a NaN) is clamped before the conversion, which would be
  /// undefined behaviour: to a cell below the box with no neighbour in it (packed) or at most 2^62 away
  /// (hashed: its neighbours' coordinates cannot overflow).
  Cell cell_of(const Point& p) const {
    Cell c;
    for (int k = 0; k < D; ++k) c[k] = cell_coordinate(p, k);
    return c;
  }
  /// Coordinate k of cell_of(p).
  std::int64_t cell_coordinate(const Point& p, int k) const {
    const double lo = m_hashed ? -0x1p62 : -2.0, hi = m_hashed ? 0x1p62 : double(kLimit - 1);
    const double t = std::floor((p[k] - m_low[k]) / m_cell);
    return static_cast<std::int64_t>(t >= lo ? (t <= hi ? t : hi) : lo);  // NaN: lo
  }
  std::uint64_t key(const Cell& c) const {
    std::uint64_t k = 0;
    if (!m_hashed) {
      for (int i = 0; i < D; ++i) k = (k << 21) | static_cast<std::uint64_t>(c[i]);
      return k;
    }
    for (int i = 0; i < D; ++i) {  // splitmix64 steps over the coordinates
      k += static_cast<std::uint64_t>(c[i]) + 0x9e3779b97f4a7c15ull;
      k = (k ^ (k >> 30)) * 0xbf58476d1ce4e5b9ull;
      k = (k ^ (k >> 27)) * 0x94d049bb133111ebull;
      k ^= k >> 31;
    }
    return k;
  }
  /// Calls f(key) once for each key of the 3^D cells around p (inside the key range when packed).
  template <class F>
  void for_each_neighbor_key(const Point& p, F&& f) const {
    const Cell c = cell_of(p);
    Cell q;
    if (!m_hashed) {  // packed keys are distinct
      visit<0>(c, q, &m_key_limit, [&](const Cell& r) { f(key(r)); });
      return;
    }
    std::array<std::uint64_t, 27> keys;
    std::size_t count = 0;
    visit<0>(c, q, nullptr, [&](const Cell& r) { keys[count++] = key(r); });
    std::sort(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count));
    count = static_cast<std::size_t>(
        std::unique(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count)) - keys.begin());
    for (std::size_t i = 0; i < count; ++i) f(keys[i]);
  }

 private:
  static constexpr std::int64_t kLimit = std::int64_t(1) << 21;
  static std::array<std::int64_t, D> filled(std::int64_t v) {
    std::array<std::int64_t, D> a;
    a.fill(v);
    return a;
  }
  /// Calls f(q) for the 3^D cells q around c, nested over the axes (the first outermost: the order of packed
  /// keys), skipping those with a coordinate outside [0, limit[k]) when `limit` is given.
  template <int K, class F>
  void visit(const Cell& c, Cell& q, const std::array<std::int64_t, D>* limit, F&& f) const {
    for (std::int64_t d = -1; d <= 1; ++d) {
      q[K] = c[K] + d;
      if (limit != nullptr && (q[K] < 0 || q[K] >= (*limit)[K])) continue;
      if constexpr (K + 1 < D)
        visit<K + 1>(c, q, limit, f);
      else
        f(q);
    }
  }
  Point m_low{};
  double m_cell = 1;
  bool m_hashed = false;
  std::array<std::int64_t, D> m_count{};   // cells per axis of the box that dense_index() numbers
  std::array<std::int64_t, D> m_origin{};  // its first cell (0 but for a core box)
  bool m_core = false;
  std::array<std::int64_t, D> m_key_limit = filled(kLimit);  // packed keys: coordinates in [0, kLimit)
  double m_cells = 0;
};

/// The most cells a grid over `expected_items` items keeps in a dense array: max(2^16, 4 expected_items),
/// never more than 2^26.
inline double dense_cell_limit(std::size_t expected_items) {
  return std::min(67108864.0, std::max(65536.0, 4.0 * double(expected_items)));
}

/// Whether a grid over `expected_items` items keeps the cells of the whole bounding box in a dense array
/// instead of a hash map: packed keys and at most dense_cell_limit() cells.
template <int D>
bool use_dense_cells(const Grid_frame<D>& frame, std::size_t expected_items) {
  return !frame.hashed() && frame.cells() <= dense_cell_limit(expected_items);
}

/// Whether a grid over `expected_items` items keeps cells in a dense array: those of the bounding box
/// (use_dense_cells()), or else those of a core box (Grid_frame::set_core(), within dense_cell_limit()), the
/// others in a hash map. Chosen from the positions alone: a grid of the same positions in another order
/// chooses the same.
template <int D>
bool use_core_cells(Grid_frame<D>& frame, const std::vector<typename Grid_frame<D>::Point>& points,
                    std::size_t expected_items) {
  if (points.empty()) return false;
  return use_dense_cells(frame, expected_items) || frame.set_core(points, dense_cell_limit(expected_items));
}

/// All points bucketed at once: the candidates within distance `cell` of a point are in the 3^D cells around
/// its cell. Within a cell, points keep their input order, so every traversal is deterministic. The cells are
/// a dense array (use_core_cells(): of the bounding box, or of a core box with the cells beyond it in a hash
/// map) or a hash map.
template <int D>
class Uniform_grid {
 public:
  using Point = std::array<double, D>;

  Uniform_grid(const std::vector<Point>& points, double cell) : m_frame(points, cell) {
    build(points, use_core_cells(m_frame, points, points.size()));
  }
  /// The same grid in a frame already chosen: `frame` made from the same positions (in any order: the frame
  /// and its core depend on the positions alone), and `dense_cells` what use_core_cells(frame, those
  /// positions, their number) returned (a caller that orders its points by the frame's cells first does not
  /// pay for the frame twice).
  /// With assertions on (FEATURERECON_assertion: unless NDEBUG, or with FEATURERECON_DEBUG), the frame is
  /// rebuilt from `points` and both are checked (the saving of a ready frame is then lost).
  Uniform_grid(const std::vector<Point>& points, const Grid_frame<D>& frame, bool dense_cells)
      : m_frame(frame) {
#if !defined(NDEBUG) || defined(FEATURERECON_DEBUG)
    Grid_frame<D> fresh(points, frame.cell_size());
    const bool fresh_dense = use_core_cells(fresh, points, points.size());
    FEATURERECON_assertion(fresh_dense == dense_cells);
    FEATURERECON_assertion(fresh.same_box(frame));
#endif
    build(points, dense_cells);
  }

  double cell_size() const { return m_frame.cell_size(); }
  /// The frame (its core box, if any: Grid_frame::order_key() orders points as the grid keeps them).
  const Grid_frame<D>& frame() const { return m_frame; }

  /// Calls f(j) for every point j in the 3^D cells around p (a superset of the points within cell_size()):
  /// the dense cells first (nested over the axes), then the hashed ones (by key).
  template <class F>
  void for_each_candidate(const Point& p, F&& f) const {
    if (m_dense)
      m_frame.for_each_neighbor_index(p, [&](std::int64_t c) {
        for (std::uint32_t i = m_offsets[std::size_t(c)]; i < m_offsets[std::size_t(c) + 1]; ++i)
          f(m_items[i]);
      });
    if (m_cells.empty()) return;
    const auto visit = [&](std::uint64_t k) {
      const auto it = m_cells.find(k);
      if (it == m_cells.end()) return;
      for (std::uint32_t i = m_key_offsets[it->second]; i < m_key_offsets[it->second + 1]; ++i) f(m_items[i]);
    };
    if (!m_dense)
      m_frame.for_each_neighbor_key(p, visit);
    else if (m_frame.reaches_beyond_core(p))
      m_frame.for_each_key_beyond_core(p, visit);
  }

 private:
  void build(const std::vector<Point>& points, bool dense_cells) {
    const std::size_t n = points.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;  // the points in hashed cells
    if (dense_cells) {  // a counting sort into a dense array of cells
      m_dense = true;
      m_offsets.assign(static_cast<std::size_t>(m_frame.cells()) + 1, 0);
      std::vector<std::int64_t> index(n);
      for (std::size_t i = 0; i < n; ++i) {
        const auto c = m_frame.cell_of(points[i]);
        index[i] = m_frame.dense_index(c);
        if (index[i] >= 0)
          ++m_offsets[std::size_t(index[i]) + 1];
        else
          keyed.push_back({m_frame.key(c), static_cast<std::uint32_t>(i)});
      }
      for (std::size_t c = 1; c < m_offsets.size(); ++c) m_offsets[c] += m_offsets[c - 1];
      m_items.resize(n);
      std::vector<std::uint32_t> fill(m_offsets.begin(), m_offsets.end() - 1);
      for (std::size_t i = 0; i < n; ++i)
        if (index[i] >= 0) m_items[fill[std::size_t(index[i])]++] = static_cast<std::uint32_t>(i);
    } else {
      keyed.resize(n);
      for (std::size_t i = 0; i < n; ++i)
        keyed[i] = {m_frame.key(m_frame.cell_of(points[i])), static_cast<std::uint32_t>(i)};
      m_items.resize(n);
    }
    if (keyed.empty()) return;
    std::sort(keyed.begin(), keyed.end());
    const std::size_t first = n - keyed.size();  // the hashed cells' points follow the dense cells' ones
    m_cells.reserve(keyed.size() / 2 + 1);
    for (std::size_t i = 0; i < keyed.size(); ++i) {
      m_items[first + i] = keyed[i].second;
      if (i == 0 || keyed[i].first != keyed[i - 1].first) {
        m_cells.emplace(keyed[i].first, m_key_offsets.size());
        m_key_offsets.push_back(static_cast<std::uint32_t>(first + i));
      }
    }
    m_key_offsets.push_back(static_cast<std::uint32_t>(n));
  }

  Grid_frame<D> m_frame;
  bool m_dense = false;                           // m_offsets per dense cell
  std::vector<std::uint32_t> m_items, m_offsets;  // the dense cells' points, then the hashed cells'
  std::vector<std::uint32_t> m_key_offsets;       // per hashed cell (the values of m_cells)
  std::unordered_map<std::uint64_t, std::size_t> m_cells;
};

/// Points inserted one by one (indices into a fixed array of positions), for dart throwing: only inserted
/// points are visited, so a large cell costs nothing for the points never inserted.
template <int D>
class Dynamic_grid {
 public:
  using Point = std::array<double, D>;

  /// `expected_items`: about how many points will be inserted (default: as many as `points` holds), which
  /// decides between a dense array of cells and a hash map (use_core_cells()). Inserted points must lie in
  /// the bounding box of `points`.
  Dynamic_grid(const std::vector<Point>& points, double cell, std::size_t expected_items = 0)
      : m_points(&points), m_frame(points, cell) {
    if (use_core_cells(m_frame, points, expected_items > 0 ? expected_items : points.size()))
      m_dense.resize(static_cast<std::size_t>(m_frame.cells()));
  }

  void insert(std::uint32_t i) {
    const auto c = m_frame.cell_of((*m_points)[i]);
    if (!m_dense.empty()) {
      const std::int64_t d = m_frame.dense_index(c);
      if (d >= 0) {
        m_dense[std::size_t(d)].push_back(i);
        return;
      }
      if (!m_frame.has_core())
        throw std::out_of_range("Dynamic_grid::insert: the point lies outside the frame's box");
    }
    m_cells[m_frame.key(c)].push_back(i);
  }

  /// Calls f(j) for every inserted point j in the 3^D cells around p, in insertion order per cell: the dense
  /// cells first (nested over the axes), then the hashed ones (by key).
  template <class F>
  void for_each_candidate(const Point& p, F&& f) const {
    if (!m_dense.empty())
      m_frame.for_each_neighbor_index(p, [&](std::int64_t c) {
        for (const std::uint32_t i : m_dense[std::size_t(c)]) f(i);
      });
    if (m_cells.empty()) return;
    const auto visit = [&](std::uint64_t k) {
      const auto it = m_cells.find(k);
      if (it == m_cells.end()) return;
      for (const std::uint32_t i : it->second) f(i);
    };
    if (m_dense.empty())
      m_frame.for_each_neighbor_key(p, visit);
    else if (m_frame.reaches_beyond_core(p))
      m_frame.for_each_key_beyond_core(p, visit);
  }

 private:
  const std::vector<Point>* m_points;
  Grid_frame<D> m_frame;
  std::vector<std::vector<std::uint32_t>> m_dense;                        // per dense cell (use_core_cells())
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;  // the other cells
};
/// \endcond

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_UNIFORM_GRID_H
