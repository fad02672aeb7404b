// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_UNION_FIND_H
#define FEATURERECON_INTERNAL_UNION_FIND_H

#include <algorithm>
#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace FeatureRecon {
namespace internal {

/// Disjoint sets of the elements 0, ..., n - 1 (union-find with path halving). The root of a set is its
/// smallest element: find() names each set by its smallest member whatever the order of the unions, so
/// labels taken from it are deterministic. `Index` is an unsigned or signed integer type that holds n - 1;
/// `Allocator` lets a large instance use FeatureRecon::internal::Large_array_allocator.
template <class Index = std::size_t, class Allocator = std::allocator<Index>>
class Union_find {
 public:
  explicit Union_find(std::size_t n = 0) { reset(n); }

  /// n singletons again (the storage is kept).
  void reset(std::size_t n) {
    m_parent.resize(n);
    std::iota(m_parent.begin(), m_parent.end(), Index(0));
  }
  std::size_t size() const { return m_parent.size(); }

  /// The smallest element of x's set.
  Index find(Index x) {
    while (m_parent[static_cast<std::size_t>(x)] != x) {
      const Index up = m_parent[static_cast<std::size_t>(m_parent[static_cast<std::size_t>(x)])];
      m_parent[static_cast<std::size_t>(x)] = up;
      x = up;
    }
    return x;
  }
  /// Joins the sets of x and y; false when they were one already.
  bool unite(Index x, Index y) {
    x = find(x);
    y = find(y);
    if (x == y) return false;
    m_parent[static_cast<std::size_t>(std::max(x, y))] = std::min(x, y);
    return true;
  }
  bool same(Index x, Index y) { return find(x) == find(y); }

  /// find(i) for every element, as a vector (the union-find is left with every path of length one).
  std::vector<Index> labels() {
    std::vector<Index> label(m_parent.size());
    for (std::size_t i = 0; i < label.size(); ++i) label[i] = find(static_cast<Index>(i));
    return label;
  }
  /// Frees the storage (size() becomes 0).
  void release() { std::vector<Index, Allocator>().swap(m_parent); }

 private:
  std::vector<Index, Allocator> m_parent;
};

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_UNION_FIND_H
