// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_INTERNAL_LINK_CUT_TREE_H
#define FEATURERECON_SKELETON_INTERNAL_LINK_CUT_TREE_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Large_array_allocator.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace skeleton {
namespace internal {

/// \cond
/// Link-cut trees (Sleator--Tarjan) over nodes 0..n-1 with a key per node and path-minimum queries.
/// Used as the dynamic spanning forest of the level-set graph in the Reeb-graph sweep: graph vertices
/// have key `infinite_key`, graph edges are nodes of their own whose key is their deletion time.
/// All operations are amortised O(log n).
class Link_cut_tree {
 public:
  using Key = std::uint32_t;
  static constexpr std::int32_t null = -1;
  static constexpr Key infinite_key = std::numeric_limits<Key>::max();

  explicit Link_cut_tree(std::size_t n = 0) { resize(n); }

  void resize(std::size_t n) {
    m_nodes.assign(n, Node{});
    for (std::size_t i = 0; i < n; ++i) m_nodes[i].min_node = static_cast<std::int32_t>(i);
  }

  std::size_t size() const { return m_nodes.size(); }

  /// Sets the key of an isolated node (no links); a node cut loose by cut_middle() can be reused this way.
  void set_key(std::int32_t x, Key key) {
    Node& nx = m_nodes[x];
    FEATURERECON_precondition(nx.parent == null && nx.child[0] == null && nx.child[1] == null);
    nx.reversed = 0;
    nx.key = key;
    nx.min_key = key;
    nx.min_node = x;
  }

  Key key(std::int32_t x) const { return m_nodes[x].key; }

  /// Makes x the root of its represented tree.
  void evert(std::int32_t x) {
    access(x);
    m_nodes[x].reversed ^= 1;
    push(x);
  }

  /// Root of the represented tree of x (does not change the represented tree).
  std::int32_t find_root(std::int32_t x) {
    access(x);
    return splay_leftmost(x);
  }

  bool connected(std::int32_t x, std::int32_t y) { return x == y || find_root(x) == find_root(y); }

  /// Links the trees of x and y by the edge x-y. \pre x and y are in different trees.
  void link(std::int32_t x, std::int32_t y) {
    evert(x);
    m_nodes[x].parent = y;
  }

  /// Removes the edge x-y. \pre x-y is an edge of the forest.
  void cut(std::int32_t x, std::int32_t y) {
    evert(x);
    access(y);
    // Now y is the splay root, its left subtree is exactly {x}.
    FEATURERECON_assertion(m_nodes[y].child[0] == x && m_nodes[x].child[1] == null);
    m_nodes[y].child[0] = null;
    m_nodes[x].parent = null;
    pull(y);
  }

  /// Node of minimum key on the tree path x..y (ties: the one found first). \pre x, y connected.
  std::int32_t path_min(std::int32_t x, std::int32_t y) {
    evert(x);
    access(y);
    return m_nodes[y].min_node;
  }

  /// One pass for "are x and y connected, and if so which node has the minimum key on the path x..y":
  /// returns that node, or null when x and y are in different trees (x is then the root of its tree).
  /// \pre x != y.
  std::int32_t connected_path_min(std::int32_t x, std::int32_t y) {
    evert(x);
    access(y);
    // the root of y's tree, now the root of the splay of path root..y
    const std::int32_t r = splay_leftmost(y);
    // Not connected: x's tree was not touched since evert(x), so x is still its root and a splay root.
    return r == x ? m_nodes[r].min_node : null;
  }

  /// Calls f(node) for every node of the tree path x..y, in order from x to y. Makes x the root of its tree.
  /// O(path length) plus amortised O(log n). \pre x, y connected.
  template <class F>
  void for_each_on_path(std::int32_t x, std::int32_t y, F f) {
    evert(x);
    access(y);  // y's splay tree is the path x..y, in order
    m_stack.clear();
    std::int32_t c = y;
    while (c != null || !m_stack.empty()) {
      for (; c != null; c = m_nodes[c].child[0]) {
        push(c);
        m_stack.push_back(c);
      }
      c = m_stack.back();
      m_stack.pop_back();
      f(c);
      c = m_nodes[c].child[1];
    }
  }

  /// Makes x, a node without any link, a child of y. O(1).
  void attach_isolated(std::int32_t x, std::int32_t y) {
    FEATURERECON_precondition(m_nodes[x].parent == null && m_nodes[x].child[0] == null &&
                              m_nodes[x].child[1] == null);
    m_nodes[x].parent = y;
  }

  /// Makes x, the root of its tree and a splay root (as left by evert(x)), a child of y. O(1).
  void attach_root(std::int32_t x, std::int32_t y) {
    FEATURERECON_precondition(m_nodes[x].parent == null);
    m_nodes[x].parent = y;
  }

  /// Removes a node t whose only two tree edges are t-x and t-y, without re-rooting: one access and two
  /// splays. O(log n) amortised.
  void cut_middle(std::int32_t t, std::int32_t x, std::int32_t y) {
    access(t);
    // t's left splay subtree is the path above t: detaching it cuts t from its parent (x, y or none).
    Node& nt = m_nodes[t];
    if (nt.child[0] != null) {
      m_nodes[nt.child[0]].parent = null;
      nt.child[0] = null;
      pull(t);
    }
    // A neighbour below t tops its own preferred path (t has no preferred child after access), so once
    // splayed its parent pointer is the path-parent t.
    for (const std::int32_t u : {x, y}) {
      splay(u);
      if (m_nodes[u].parent == t) m_nodes[u].parent = null;
    }
    FEATURERECON_assertion(m_nodes[t].child[0] == null && m_nodes[t].child[1] == null);
  }

 private:
  struct alignas(32) Node {
    std::int32_t parent = null;
    std::int32_t child[2] = {null, null};
    std::int32_t min_node = null;
    Key key = infinite_key;
    Key min_key = infinite_key;  // key of min_node, kept here to save a dependent load in pull()
    std::uint32_t reversed = 0;
    std::uint32_t padding = 0;  // 32 bytes: a node never straddles a cache line
  };

  /// The leftmost node of the splay tree rooted at x (the shallowest node of its path), splayed to the
  /// root: the splay keeps the walk amortised O(log n).
  std::int32_t splay_leftmost(std::int32_t x) {
    std::int32_t r = x;
    for (;;) {
      push(r);
      if (m_nodes[r].child[0] == null) break;
      r = m_nodes[r].child[0];
    }
    splay(r);
    return r;
  }

  bool is_splay_root(std::int32_t x) const {
    const std::int32_t p = m_nodes[x].parent;
    return p == null || (m_nodes[p].child[0] != x && m_nodes[p].child[1] != x);
  }

  void push(std::int32_t x) {
    Node& nx = m_nodes[x];
    if (nx.reversed) {
      std::swap(nx.child[0], nx.child[1]);
      if (nx.child[0] != null) m_nodes[nx.child[0]].reversed ^= 1;
      if (nx.child[1] != null) m_nodes[nx.child[1]].reversed ^= 1;
      nx.reversed = 0;
    }
  }

  void pull(std::int32_t x) {
    Node& nx = m_nodes[x];
    std::int32_t best = x;
    Key best_key = nx.key;
    for (int c = 0; c < 2; ++c) {
      const std::int32_t ch = nx.child[c];
      if (ch != null && m_nodes[ch].min_key < best_key) {
        best_key = m_nodes[ch].min_key;
        best = m_nodes[ch].min_node;
      }
    }
    nx.min_node = best;
    nx.min_key = best_key;
  }

  void rotate(std::int32_t x) {
    const std::int32_t p = m_nodes[x].parent;
    const std::int32_t g = m_nodes[p].parent;
    const int dx = (m_nodes[p].child[1] == x) ? 1 : 0;
    const std::int32_t b = m_nodes[x].child[dx ^ 1];
    if (!is_splay_root(p)) {
      Node& ng = m_nodes[g];
      ng.child[ng.child[1] == p ? 1 : 0] = x;
    }
    m_nodes[x].parent = g;
    m_nodes[x].child[dx ^ 1] = p;
    m_nodes[p].parent = x;
    m_nodes[p].child[dx] = b;
    if (b != null) m_nodes[b].parent = p;
    pull(p);  // x is pulled once, at the end of splay()
  }

  void splay(std::int32_t x) {
    // Push reversal flags down from the splay root to x.
    m_stack.clear();
    for (std::int32_t y = x;; y = m_nodes[y].parent) {
      m_stack.push_back(y);
      if (is_splay_root(y)) break;
    }
    for (auto it = m_stack.rbegin(); it != m_stack.rend(); ++it) push(*it);
    while (!is_splay_root(x)) {
      const std::int32_t p = m_nodes[x].parent;
      if (!is_splay_root(p)) {
        const std::int32_t g = m_nodes[p].parent;
        const bool zigzig = (m_nodes[g].child[0] == p) == (m_nodes[p].child[0] == x);
        rotate(zigzig ? p : x);
      }
      rotate(x);
    }
    pull(x);
  }

  void access(std::int32_t x) {
    std::int32_t last = null;
    for (std::int32_t y = x; y != null; y = m_nodes[y].parent) {
      splay(y);
      m_nodes[y].child[1] = last;
      pull(y);
      last = y;
    }
    splay(x);
  }

  FeatureRecon::internal::Large_vector<Node> m_nodes;
  std::vector<std::int32_t> m_stack;
};
/// \endcond

}  // namespace internal
}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_INTERNAL_LINK_CUT_TREE_H
