// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_NEAREST_TREE_H
#define FEATURERECON_SAMPLING_INTERNAL_NEAREST_TREE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {
namespace internal {

/// \cond
/// A kd-tree over points in D dimensions with the nearest search of Ring_grid::nearest(): the index j
/// minimising a score s(j) bounded below by (spatial distance) / scale, ties to the lowest index whatever the
/// visiting order, NaN counted as infinity. Unlike a uniform grid its cost does not depend on how the points
/// fill the box of the queries: sites covering a small part of an image (a dark logo on white) left most
/// queries of a grid scanning rings of empty cells, O(cells) each. Nodes hold the tight bounding box of
/// their points and split at the median of the box's widest axis (coordinate, then index), so the tree is a
/// function of the points alone; leaves hold at most 4 points (fewer scores per query than 8 or 16, at the
/// same time per box). Coordinates must be finite.
template <int D>
class Nearest_tree {
 public:
  using Point = std::array<double, D>;
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  Nearest_tree() = default;

  /// \pre fewer than 2^32 - 1 points, finite coordinates.
  explicit Nearest_tree(const std::vector<Point>& points) {
    const std::size_t n = points.size();
    if (n == 0) return;
    m_index.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_index[i] = static_cast<std::uint32_t>(i);
    m_nodes.reserve(2 * (n / leaf_size) + 1);
    m_nodes.push_back(Node{{}, {}, 0, static_cast<std::uint32_t>(n), 0});
    // Nodes are numbered in creation order; a node's children are made when it is split, right after it.
    for (std::size_t v = 0; v < m_nodes.size(); ++v) {
      const std::uint32_t begin = m_nodes[v].begin, end = m_nodes[v].end;
      Point lo = points[m_index[begin]], hi = lo;
      for (std::uint32_t t = begin + 1; t < end; ++t)
        for (int k = 0; k < D; ++k) {
          lo[k] = std::min(lo[k], points[m_index[t]][k]);
          hi[k] = std::max(hi[k], points[m_index[t]][k]);
        }
      m_nodes[v].lo = lo;
      m_nodes[v].hi = hi;
      if (end - begin <= leaf_size) continue;
      int axis = 0;
      for (int k = 1; k < D; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
      const std::uint32_t middle = begin + (end - begin) / 2;
      std::nth_element(m_index.begin() + begin, m_index.begin() + middle, m_index.begin() + end,
                       [&](std::uint32_t a, std::uint32_t b) {
                         return points[a][axis] < points[b][axis] ||
                                (points[a][axis] == points[b][axis] && a < b);
                       });
      m_nodes[v].left = static_cast<std::uint32_t>(m_nodes.size());
      m_nodes.push_back(Node{{}, {}, begin, middle, 0});
      m_nodes.push_back(Node{{}, {}, middle, end, 0});
    }
  }

  std::size_t number_of_nodes() const { return m_nodes.size(); }

  /// The points of node v (0: the root, holding all), [first, second): the first is the same for a node and
  /// its left child.
  std::pair<const std::uint32_t*, const std::uint32_t*> node_points(std::size_t v) const {
    return {m_index.data() + m_nodes[v].begin, m_index.data() + m_nodes[v].end};
  }

  /// The index j minimising score(j) (ties: lowest j) over the points, or none when there are none; best
  /// receives the score. A NaN score counts as infinity (a point is found whenever there are any).
  /// \param scale score(j) >= |x - point j| / scale for every j (scale > 0; infinity: every point scored).
  /// \param hint a point to score first (none: no hint), say the answer of a query nearby: its score bounds
  /// the search from the start. The answer does not depend on it.
  template <class Score>
  std::uint32_t nearest(const Point& x, double scale, Score&& score, double& best,
                        std::uint32_t hint = none) const {
    bool complete = true;
    No_refusal refuse;
    return search<false>(x, scale, score, best, hint, refuse, 0, complete);
  }

  /// Refuses nothing (see below).
  struct No_refusal {
    bool operator()(std::uint32_t, double, double) const { return false; }  ///< false
  };
  static constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

  /// The same, with a further bound: refuse(v, squared_box_distance, slack) may return true when no point of
  /// node v scores at most slack (the best score so far, widened by Ring_grid's margin), say from the
  /// features of the node's points (node_points()); squared_box_distance is the squared distance from x to
  /// the node's box (a lower bound of every point's, possibly 0 where its square underflows). Asked only
  /// for nodes the spatial bound does not rule out, once a point has been scored. The search stops after
  /// node_limit nodes that neither bound rules out (complete receives false; the answer so far is the best
  /// of the points scored, a hint for another search); complete receives true when it ends by the bounds.
  template <class Score, class Refuse>
  std::uint32_t nearest(const Point& x, double scale, Score&& score, double& best_score, std::uint32_t hint,
                        Refuse&& refuse, std::size_t node_limit, bool& complete) const {
    return node_limit == unlimited
               ? search<false>(x, scale, score, best_score, hint, refuse, 0, complete)
               : search<true>(x, scale, score, best_score, hint, refuse, node_limit, complete);
  }

 private:
  // nearest(); the node count only where limited (unlimited, it cost 9 % more instructions).
  template <bool limited, class Score, class Refuse>
  std::uint32_t search(const Point& x, double scale, Score& score, double& best_score, std::uint32_t hint,
                       Refuse& refuse, std::size_t node_limit, bool& complete) const {
    double best = std::numeric_limits<double>::infinity();
    best_score = best;
    complete = true;
    std::uint32_t arg = none;
    if (m_nodes.empty()) return arg;
    auto offer = [&](std::uint32_t j) {
      double s = score(j);
      if (std::isnan(s)) s = std::numeric_limits<double>::infinity();
      if (s < best || (s == best && j < arg)) {
        best = s;
        arg = j;
      }
    };
    if (hint != none) offer(hint);
    // A node can hold a better point (or a tie of lower index) unless its box lies farther than the best
    // score allows: |box| / scale > best (1 + 1e-12) + min(), Ring_grid's rule, whose margin absorbs the
    // rounding of the box's distance against the points'. Compared squared (no square root per box; a third
    // of the time of a search), unless the square of the limit leaves the normal range: squares of gaps
    // below 1e-154 lose their digits, so the distance is then taken with the gaps scaled by 2^600 (exact).
    auto slack = [&] { return best * (1 + 1e-12) + std::numeric_limits<double>::min(); };
    auto hopeless = [&](const Node& node, double squared_bound) {
      if (arg == none) return false;
      const double limit = slack() * scale;
      if (limit * limit >= 0x1p-900) return squared_bound > limit * limit;  // also an infinite limit
      double s = 0;
      for (int k = 0; k < D; ++k) {
        const double gap = std::max({0.0, node.lo[k] - x[k], x[k] - node.hi[k]}) * 0x1p600;
        s += gap * gap;
      }
      return std::sqrt(s) * 0x1p-600 / scale > slack();  // a gap above 2^-88: infinity, hopeless indeed
    };
    // Depth-first, the nearer child first. The depth is below 64 (at most 2^32 points, halved per level),
    // and the stack holds at most one pending sibling per level.
    std::array<std::pair<std::uint32_t, double>, 2 * 64> stack;
    std::size_t top = 0;
    stack[top++] = {0, squared_box_distance(m_nodes[0], x)};
    [[maybe_unused]] std::size_t visited = 0;
    while (top > 0) {
      const auto [v, bound] = stack[--top];
      const Node& node = m_nodes[v];
      if (hopeless(node, bound) || (arg != none && refuse(v, bound, slack()))) continue;
      if constexpr (limited) {
        if (++visited > node_limit) {
          complete = false;
          break;
        }
      }
      if (node.left == 0) {
        for (std::uint32_t t = node.begin; t < node.end; ++t) offer(m_index[t]);
        continue;
      }
      const double a = squared_box_distance(m_nodes[node.left], x),
                   b = squared_box_distance(m_nodes[node.left + 1], x);
      const bool left_first = a <= b;
      stack[top++] = left_first ? std::make_pair(node.left + 1, b) : std::make_pair(node.left, a);
      stack[top++] = left_first ? std::make_pair(node.left, a) : std::make_pair(node.left + 1, b);
    }
    best_score = best;
    return arg;
  }

  struct Node {
    Point lo, hi;              // the bounding box of its points
    std::uint32_t begin, end;  // its points: m_index[begin, end)
    std::uint32_t left;        // its children left and left + 1; 0 for a leaf
  };
  static constexpr std::uint32_t leaf_size = 4;

  // The squared distance from x to the node's box.
  static double squared_box_distance(const Node& node, const Point& x) {
    double s = 0;
    for (int k = 0; k < D; ++k) {
      const double gap = std::max({0.0, node.lo[k] - x[k], x[k] - node.hi[k]});
      s += gap * gap;
    }
    return s;
  }

  std::vector<Node> m_nodes;
  std::vector<std::uint32_t> m_index;
};
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_NEAREST_TREE_H
