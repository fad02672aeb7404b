// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_AUGMENTED_REEB_GRAPH_H
#define FEATURERECON_SKELETON_AUGMENTED_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Large_array_allocator.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/internal/Link_cut_tree.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

class Augmented_reeb_graph;
template <class FunctionRange>
Augmented_reeb_graph compute_augmented_reeb_graph(const Simplicial_complex_2& K, const FunctionRange& f,
                                                  const Reeb_graph_options& options = {});

struct Reeb_graph;
namespace internal {
std::size_t count_components(const Reeb_graph& G);
}  // namespace internal

/// Criticality of a node of a Reeb graph, as a bit set: a node can carry several flags (degenerate
/// nodes, e.g. an isolated vertex is a minimum and a maximum; a node with two arcs below and two
/// above is a down-fork and an up-fork). A regular node (one arc below, one above) has no flag.
enum Node_type : unsigned {
  regular = 0,
  minimum = 1,    ///< no arc below
  maximum = 2,    ///< no arc above
  up_fork = 4,    ///< two or more arcs above
  down_fork = 8   ///< two or more arcs below
};

/// Node type from the numbers of arcs below and above a node.
inline unsigned node_type_from_degrees(std::size_t down_degree, std::size_t up_degree) {
  unsigned t = regular;
  if (down_degree == 0) t |= minimum;
  if (up_degree == 0) t |= maximum;
  if (up_degree >= 2) t |= up_fork;
  if (down_degree >= 2) t |= down_fork;
  return t;
}

/// The Reeb graph proper: critical nodes only; regular vertices lie inside arcs.
/// \note `lower`/`upper` of an arc are node indices with value(lower) < value(upper) in the
/// simulation-of-simplicity order (f, then vertex index); an arc may join the same two nodes as another.
struct Reeb_graph {
  /// A critical node: the image of one input vertex, with the vertices simplification identified with it.
  struct Node {
    Vertex_index vertex = 0;  ///< input vertex whose image is this node
    double value = 0;         ///< f(vertex)
    unsigned type = regular;  ///< Node_type flags
    std::vector<Vertex_index> members;  ///< other input vertices identified with this node (after simplification)
  };
  /// An arc between two nodes, with the regular input vertices mapped into it.
  struct Arc {
    std::size_t lower = 0;                ///< index into `nodes`
    std::size_t upper = 0;                ///< index into `nodes`
    std::vector<Vertex_index> vertices;  ///< regular input vertices mapped into the arc, in increasing order
  };
  std::vector<Node> nodes;          ///< critical nodes, by increasing (f, vertex index)
  std::vector<Arc> arcs;            ///< arcs, by (lower, upper, first interior vertex)
  std::size_t components = 0;       ///< connected components of the graph
  std::size_t loops() const { return arcs.size() + components - nodes.size(); }  ///< first Betti number
  std::size_t count(Node_type flag) const {  ///< number of nodes carrying `flag`
    return static_cast<std::size_t>(
        std::count_if(nodes.begin(), nodes.end(), [flag](const Node& n) { return (n.type & flag) != 0; }));
  }
};

/// The augmented Reeb graph of a PL function f on a simplicial 2-complex K: one node per vertex of K
/// (the image of the vertex) and the arcs between them. Ties in f are broken by vertex index
/// (simulation of simplicity), so the graph is well defined for any finite f.
/// Built by compute_augmented_reeb_graph().
class Augmented_reeb_graph {
 public:
  /// An arc of the augmented graph, from a vertex's image to a higher vertex's image.
  struct Arc {
    Vertex_index lower = 0;  ///< lower endpoint (input vertex)
    Vertex_index upper = 0;  ///< upper endpoint (input vertex)
  };

  Augmented_reeb_graph() = default;

  /// Number of nodes: every input vertex has one.
  std::size_t number_of_nodes() const { return m_values.size(); }
  /// Number of arcs.
  std::size_t number_of_arcs() const { return m_arcs.size(); }
  /// Arcs sorted by (rank of lower, rank of upper).
  const std::vector<Arc>& arcs() const { return m_arcs; }
  /// f, copied from the input.
  const std::vector<double>& values() const { return m_values; }
  /// Vertices in increasing (f, index) order: the sweep order.
  const std::vector<Vertex_index>& order() const { return m_order; }
  /// Position of each vertex in order().
  const std::vector<Vertex_index>& rank() const { return m_rank; }
  /// Number of arcs below the image of v.
  std::size_t down_degree(Vertex_index v) const { return m_down_degree[v]; }
  /// Number of arcs above the image of v.
  std::size_t up_degree(Vertex_index v) const { return m_up_offset[v + 1] - m_up_offset[v]; }
  /// Node_type flags of the image of v.
  unsigned type(Vertex_index v) const { return node_type_from_degrees(down_degree(v), up_degree(v)); }
  /// Indices into arcs() of the arcs leaving v upwards.
  std::vector<std::size_t> up_arcs(Vertex_index v) const {
    return std::vector<std::size_t>(m_up_arcs.begin() + m_up_offset[v], m_up_arcs.begin() + m_up_offset[v + 1]);
  }
  /// Completed, interrupted by the progress callback (arcs still open are missing), or degenerate (empty input).
  Status status() const { return m_status; }

  /// Derives the Reeb graph (critical nodes only; chains of regular nodes become arcs). O(n + arcs).
  Reeb_graph reeb_graph() const;

 private:
  template <class FunctionRange>
  friend Augmented_reeb_graph compute_augmented_reeb_graph(const Simplicial_complex_2&, const FunctionRange&,
                                                           const Reeb_graph_options&);
  void finish();

  std::vector<double> m_values;
  std::vector<Vertex_index> m_order, m_rank;
  std::vector<Arc> m_arcs;
  std::vector<std::uint32_t> m_down_degree;
  std::vector<std::size_t> m_up_offset, m_up_arcs;
  Status m_status = Status::success;
};

namespace internal {
/// Compressed lists: for each key 0..n-1 the values pushed with it, in push order.
template <class T>
struct Buckets {
  FeatureRecon::internal::Large_vector<std::size_t> offset;
  FeatureRecon::internal::Large_vector<T> items;
  template <class KeyOf>
  void build(std::size_t n, std::size_t count, KeyOf key_of) {
    offset.assign(n + 1, 0);
    for (std::size_t i = 0; i < count; ++i) ++offset[key_of(i) + 1];
    for (std::size_t k = 0; k < n; ++k) offset[k + 1] += offset[k];
    items.resize(count);
    FeatureRecon::internal::Large_vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for (std::size_t i = 0; i < count; ++i) items[fill[key_of(i)]++] = static_cast<T>(i);
  }
  const T* begin(std::size_t k) const { return items.data() + offset[k]; }
  const T* end(std::size_t k) const { return items.data() + offset[k + 1]; }
};
}  // namespace internal

/// Computes the augmented Reeb graph of the PL function `f` on the complex `K`.
///
/// Method: a sweep in increasing (f, index) order (Parsa's algorithm). The level set between two
/// consecutive vertex values is a graph whose nodes are the edges of K it crosses and whose edges come
/// from the triangles it crosses. Its connectivity is maintained as a maximum spanning forest keyed by
/// deletion time in a link-cut tree, which makes every deletion final (an offline dynamic-connectivity
/// structure). Each component of the level set is an arc of the augmented Reeb graph; an arc ends at the
/// first vertex whose star touches it. O((n + m) log m) time for m simplices, O(n + m) memory. Any
/// simplicial 2-complex is handled: dangling edges, non-manifold vertices and edges, isolated vertices,
/// several components.
///
/// \param K a canonical complex (see Simplicial_complex_2).
/// \param f one finite value per vertex (any random-access range convertible to double).
/// \pre K is canonical (checked; throws). f has K.number_of_vertices finite values (checked; throws,
///      naming the first bad index).
/// \returns the augmented Reeb graph; `status()` is `degenerate_input` for an empty complex and
///      `interrupted` when the progress callback returned false.
/// \param options progress callback (return false to stop: the result then has Status::interrupted).
template <class FunctionRange>
Augmented_reeb_graph compute_augmented_reeb_graph(const Simplicial_complex_2& K, const FunctionRange& f,
                                                  const Reeb_graph_options& options) {
  const char* fn = "compute_augmented_reeb_graph";
  const std::size_t n = K.number_of_vertices;
  if (static_cast<std::size_t>(std::distance(std::begin(f), std::end(f))) != n)
    FeatureRecon::internal::throw_invalid_argument(fn, "f has ", std::distance(std::begin(f), std::end(f)),
                                                   " values for ", n, " vertices");
  if (!internal::has_canonical_order(K))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the complex is not canonical (unsorted, repeated or out-of-range simplices); build it with "
            "make_simplicial_complex_2()");
  if (K.number_of_edges() + K.number_of_triangles() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) ||
      n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    FeatureRecon::internal::throw_invalid_argument(fn, "the complex is too large (", K.number_of_edges(),
                                                   " edges, ", K.number_of_triangles(), " triangles)");

  Augmented_reeb_graph R;
  R.m_values.reserve(n);
  {
    std::size_t i = 0;
    for (const auto& value : f) {
      const double x = static_cast<double>(value);
      if (!std::isfinite(x))
        FeatureRecon::internal::throw_invalid_argument(fn, "f at vertex ", i, " is not finite (", x, ")");
      R.m_values.push_back(x);
      ++i;
    }
  }
  const std::vector<double>& val = R.m_values;
  {
    FeatureRecon::internal::Large_vector<std::pair<double, Vertex_index>> keyed(n);  // contiguous keys sort faster than indirection
    for (std::size_t i = 0; i < n; ++i) keyed[i] = {val[i], static_cast<Vertex_index>(i)};
    std::sort(keyed.begin(), keyed.end());
    R.m_order.resize(n);
    for (std::size_t i = 0; i < n; ++i) R.m_order[i] = keyed[i].second;
  }
  R.m_rank.resize(n);
  for (std::size_t i = 0; i < n; ++i) R.m_rank[R.m_order[i]] = static_cast<Vertex_index>(i);
  const std::vector<Vertex_index>& rank = R.m_rank;
  if (n == 0) {
    R.m_status = Status::degenerate_input;
    R.finish();
    return R;
  }

  // Per vertex: edges whose lower / upper end it is (by rank).
  const std::size_t E = K.number_of_edges(), T = K.number_of_triangles();
  // Buckets are keyed by sweep step (rank), not by vertex: the sweep then reads them sequentially.
  auto lower_of = [&](std::size_t e) { return std::min(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  auto upper_of = [&](std::size_t e) { return std::max(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  internal::Buckets<std::uint32_t> up_edges, down_edges;
  up_edges.build(n, E, lower_of);
  down_edges.build(n, E, upper_of);

  // Edge lookup: edges starting at u (smaller index) are contiguous.
  FeatureRecon::internal::Large_vector<std::size_t> first_edge(n + 1, 0);
  for (const Edge& e : K.edges) ++first_edge[e[0] + 1];
  for (std::size_t v = 0; v < n; ++v) first_edge[v + 1] += first_edge[v];
  auto edge_id = [&](Vertex_index u, Vertex_index v) -> std::uint32_t {
    if (u > v) std::swap(u, v);
    const auto b = K.edges.begin() + first_edge[u], e = K.edges.begin() + first_edge[u + 1];
    const auto it = std::lower_bound(b, e, Edge{u, v});
    if (it == e || (*it)[1] != v)
      FeatureRecon::internal::throw_invalid_argument(fn, "the complex is not canonical: edge (", u, ", ", v,
                                                     ") of a triangle is missing");
    return static_cast<std::uint32_t>(it - K.edges.begin());
  };

  // Sweep numbering: edges and triangles are renumbered by the rank of their lowest vertex, so that the
  // level-set nodes alive at one time sit close together in memory (this matters for large complexes).
  FeatureRecon::internal::Large_vector<std::uint32_t> edge_new(E), tri_new(T);
  {
    std::uint32_t c = 0;
    for (std::size_t step = 0; step < n; ++step)
      for (const std::uint32_t* e = up_edges.begin(step); e != up_edges.end(step); ++e)
        edge_new[*e] = c++;
    for (std::uint32_t& e : up_edges.items) e = edge_new[e];
    for (std::uint32_t& e : down_edges.items) e = edge_new[e];
  }

  // Per triangle (in sweep numbering), with its vertices by rank a < b < c: its edges ab, bc, ac and the
  // ranks of b and c (the deletion times of its lower and upper halves).
  struct Tri {
    std::uint32_t ab, bc, ac, rank_b, rank_c;
  };
  FeatureRecon::internal::Large_vector<Tri> tri(T);
  internal::Buckets<std::uint32_t> by_min, by_mid, by_max;
  {
    FeatureRecon::internal::Large_vector<std::array<Vertex_index, 3>> sorted(T);
    for (std::size_t t = 0; t < T; ++t) {
      std::array<Vertex_index, 3> s = K.triangles[t];
      std::sort(s.begin(), s.end(), [&](Vertex_index x, Vertex_index y) { return rank[x] < rank[y]; });
      sorted[t] = s;
    }
    by_min.build(n, T, [&](std::size_t t) { return rank[sorted[t][0]]; });
    std::uint32_t c = 0;
    for (std::size_t step = 0; step < n; ++step)
      for (const std::uint32_t* t = by_min.begin(step); t != by_min.end(step); ++t)
        tri_new[*t] = c++;
    for (std::size_t t = 0; t < T; ++t) {
      const std::array<Vertex_index, 3>& s = sorted[t];
      tri[tri_new[t]] = Tri{edge_new[edge_id(s[0], s[1])], edge_new[edge_id(s[1], s[2])],
                            edge_new[edge_id(s[0], s[2])], rank[s[1]], rank[s[2]]};
    }
    by_mid.build(n, T, [&](std::size_t t) { return rank[sorted[t][1]]; });
    by_max.build(n, T, [&](std::size_t t) { return rank[sorted[t][2]]; });
    for (auto* b : {&by_min, &by_mid, &by_max})
      for (std::uint32_t& t : b->items) t = tri_new[t];
  }
  edge_new.clear();
  edge_new.shrink_to_fit();
  tri_new.clear();
  tri_new.shrink_to_fit();

  // Link-cut forest: nodes [0, E) are level-set vertices (edges of K), nodes [E, E+T) are level-set
  // edges (one per triangle: its lower half, then its upper half). Key of a level-set edge = rank of
  // the vertex at which it is deleted.
  using LCT = internal::Link_cut_tree;
  LCT forest(E + T);
  FeatureRecon::internal::Large_vector<std::uint8_t> in_tree(T, 0);
  FeatureRecon::internal::Large_vector<std::array<std::int32_t, 2>> ends(T);
  FeatureRecon::internal::Large_vector<std::int32_t> arc_of_root(E + T, -1);
  FeatureRecon::internal::Large_vector<std::uint32_t> stamp(E + T, 0);  // 2*step+1: seen below the vertex; 2*step+2: above

  // Number of forest edges at each level-set vertex: a vertex without any is its own tree, which lets
  // most links skip the connectivity query (every edge of K starts isolated).
  FeatureRecon::internal::Large_vector<std::uint32_t> forest_degree(E, 0);
  auto remove_level_edge = [&](std::uint32_t t) {
    if (!in_tree[t]) return;
    const std::int32_t p = ends[t][0], q = ends[t][1];
    forest.cut_middle(static_cast<std::int32_t>(E + t), p, q);
    --forest_degree[p];
    --forest_degree[q];
    in_tree[t] = 0;
  };
  auto insert_level_edge = [&](std::uint32_t t, std::int32_t p, std::int32_t q, LCT::Key key,
                               bool known_disconnected) {
    const std::int32_t x = static_cast<std::int32_t>(E + t);
    forest.set_key(x, key);
    ends[t] = {p, q};
    if (forest_degree[p] != 0 && forest_degree[q] == 0) std::swap(p, q);
    if (forest_degree[p] == 0) {
      // p is a tree of its own: hang x below q and p below x.
      forest.attach_isolated(x, q);
      forest.attach_isolated(p, x);
    } else if (known_disconnected) {
      forest.evert(p);
      forest.attach_isolated(x, q);
      forest.attach_root(p, x);
    } else {
      std::int32_t m = forest.connected_path_min(p, q);
      if (m != LCT::null) {
        if (forest.key(m) >= key) return;  // the new edge closes a cycle and dies first: not in the forest
        remove_level_edge(static_cast<std::uint32_t>(m - static_cast<std::int32_t>(E)));
        forest.evert(p);
      }
      // p is now the root of its tree (and a splay root): hang x below q and p below x.
      forest.attach_isolated(x, q);
      forest.attach_root(p, x);
    }
    ++forest_degree[p];
    ++forest_degree[q];
    in_tree[t] = 1;
  };

  // Groups the edges [eb, ee) of the star of a vertex into classes joined by the given triangles (whose two
  // edges at the vertex are ab/ac for triangles above it, bc/ac for triangles below it); one edge per class
  // goes to group_representatives.
  FeatureRecon::internal::Large_vector<std::int32_t> slot(E, -1);
  std::vector<std::int32_t> group_parent;
  std::vector<std::uint32_t> group_representatives, lower_halves;
  // Union-find over the edges [eb, ee) of a star: slot[e] is the edge's index there.
  auto reset_groups = [&](const std::uint32_t* eb, const std::uint32_t* ee) {
    const std::size_t k = static_cast<std::size_t>(ee - eb);
    group_parent.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      slot[eb[i]] = static_cast<std::int32_t>(i);
      group_parent[i] = static_cast<std::int32_t>(i);
    }
    return k;
  };
  auto find = [&](std::int32_t i) {
    while (group_parent[i] != i) i = group_parent[i] = group_parent[group_parent[i]];
    return i;
  };
  auto group_edges = [&](const std::uint32_t* eb, const std::uint32_t* ee, const std::uint32_t* tb,
                         const std::uint32_t* te, bool below_vertex) {
    const std::size_t k = reset_groups(eb, ee);
    for (const std::uint32_t* t = tb; t != te; ++t) {
      const Tri& tr = tri[*t];
      const std::int32_t i = find(slot[below_vertex ? tr.bc : tr.ab]), j = find(slot[tr.ac]);
      if (i != j) group_parent[std::max(i, j)] = std::min(i, j);
    }
    group_representatives.clear();
    for (std::size_t i = 0; i < k; ++i)
      if (find(static_cast<std::int32_t>(i)) == static_cast<std::int32_t>(i)) group_representatives.push_back(eb[i]);
  };

  for (std::size_t step = 0; step < n; ++step) {
    if ((step & 4095) == 0 &&
        !FeatureRecon::internal::report_progress(options.progress, static_cast<double>(step) / n)) {
      R.m_status = Status::interrupted;
      break;
    }
    const Vertex_index x = R.m_order[step];
    const std::uint32_t below = static_cast<std::uint32_t>(2 * step + 1), above = below + 1;
    // 1. The level-set components just below x that x touches: each is an arc ending at x. Edges into x
    //    joined by a triangle (a, b, x) are in one component: only one root query per such group.
    group_edges(down_edges.begin(step), down_edges.end(step), by_max.begin(step), by_max.end(step), true);
    for (const std::uint32_t e : group_representatives) {
      const std::int32_t r = forest.find_root(static_cast<std::int32_t>(e));
      if (stamp[r] == below) continue;
      stamp[r] = below;
      const std::int32_t a = arc_of_root[r];
      FEATURERECON_assertion(a >= 0 && R.m_arcs[a].upper == R.m_arcs[a].lower);
      R.m_arcs[a].upper = x;
    }
    // 2. Level-set edges deleted at x: lower halves of triangles with x in the middle, upper halves
    //    of triangles with x on top.
    for (const std::uint32_t* t = by_mid.begin(step); t != by_mid.end(step); ++t) remove_level_edge(*t);
    for (const std::uint32_t* t = by_max.begin(step); t != by_max.end(step); ++t) remove_level_edge(*t);
    // 3. Level-set edges born at x. First the lower halves (ab, ac) of triangles with x at the bottom
    //    (deleted at b): both ends are edges of K born at x, still isolated, so their maximum spanning forest
    //    is local to the star of x: Kruskal by decreasing deletion time with a union-find over the new edges.
    //    A half it rejects closes a cycle of halves that live at least as long, so the global forest would
    //    reject it too: it never enters the link-cut tree (in dense Rips complexes most halves are rejected).
    {
      reset_groups(up_edges.begin(step), up_edges.end(step));
      lower_halves.assign(by_min.begin(step), by_min.end(step));
      std::sort(lower_halves.begin(), lower_halves.end(), [&](std::uint32_t a, std::uint32_t b) {
        return tri[a].rank_b > tri[b].rank_b || (tri[a].rank_b == tri[b].rank_b && a < b);
      });
      for (const std::uint32_t t : lower_halves) {
        const Tri& tr = tri[t];
        const std::int32_t i = find(slot[tr.ab]), j = find(slot[tr.ac]);
        if (i == j) continue;
        group_parent[std::max(i, j)] = std::min(i, j);
        insert_level_edge(t, static_cast<std::int32_t>(tr.ab), static_cast<std::int32_t>(tr.ac), tr.rank_b, true);
      }
    }
    //    Then the upper halves (bc, ac) of triangles with x in the middle (deleted at c).
    for (const std::uint32_t* t = by_mid.begin(step); t != by_mid.end(step); ++t) {
      const Tri& tr = tri[*t];
      insert_level_edge(*t, static_cast<std::int32_t>(tr.bc), static_cast<std::int32_t>(tr.ac), tr.rank_c, false);
    }
    // 4. The components just above x that contain an edge leaving x: each starts an arc at x. Edges out
    //    of x joined by a triangle (x, b, c) are in one component.
    group_edges(up_edges.begin(step), up_edges.end(step), by_min.begin(step), by_min.end(step), false);
    for (const std::uint32_t e : group_representatives) {
      const std::int32_t r = forest.find_root(static_cast<std::int32_t>(e));
      if (stamp[r] == above) continue;
      stamp[r] = above;
      arc_of_root[r] = static_cast<std::int32_t>(R.m_arcs.size());
      R.m_arcs.push_back(Augmented_reeb_graph::Arc{x, x});
    }
  }
  if (R.m_status == Status::interrupted) {
    // Keep only closed arcs.
    R.m_arcs.erase(std::remove_if(R.m_arcs.begin(), R.m_arcs.end(),
                                  [](const Augmented_reeb_graph::Arc& a) { return a.upper == a.lower; }),
                   R.m_arcs.end());
  } else {
    (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  }
  R.finish();
  return R;
}

inline void Augmented_reeb_graph::finish() {
  const std::size_t n = m_values.size();
  std::sort(m_arcs.begin(), m_arcs.end(), [&](const Arc& a, const Arc& b) {
    return m_rank[a.lower] < m_rank[b.lower] || (a.lower == b.lower && m_rank[a.upper] < m_rank[b.upper]);
  });
  m_down_degree.assign(n, 0);
  m_up_offset.assign(n + 1, 0);
  for (const Arc& a : m_arcs) {
    ++m_down_degree[a.upper];
    ++m_up_offset[a.lower + 1];
  }
  for (std::size_t v = 0; v < n; ++v) m_up_offset[v + 1] += m_up_offset[v];
  m_up_arcs.resize(m_arcs.size());
  std::vector<std::size_t> fill(m_up_offset.begin(), m_up_offset.end() - 1);
  for (std::size_t i = 0; i < m_arcs.size(); ++i) m_up_arcs[fill[m_arcs[i].lower]++] = i;
}

namespace internal {
/// Number of connected components of a Reeb graph (union-find over its nodes).
inline std::size_t count_components(const Reeb_graph& G) {
  std::vector<std::size_t> parent(G.nodes.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t components = G.nodes.size();
  for (const Reeb_graph::Arc& a : G.arcs) {
    const std::size_t r = find(a.lower), s = find(a.upper);
    if (r != s) {
      parent[r] = s;
      --components;
    }
  }
  return components;
}
}  // namespace internal

inline Reeb_graph Augmented_reeb_graph::reeb_graph() const {
  Reeb_graph G;
  const std::size_t n = number_of_nodes();
  std::vector<std::size_t> node_of(n, std::numeric_limits<std::size_t>::max());
  for (Vertex_index v : m_order) {
    const unsigned t = type(v);
    if (t == regular) continue;
    node_of[v] = G.nodes.size();
    G.nodes.push_back(Reeb_graph::Node{v, m_values[v], t});
  }
  for (const Reeb_graph::Node& node : G.nodes) {
    for (std::size_t k = m_up_offset[node.vertex]; k < m_up_offset[node.vertex + 1]; ++k) {
      Reeb_graph::Arc arc;
      arc.lower = node_of[node.vertex];
      Vertex_index w = m_arcs[m_up_arcs[k]].upper;
      while (type(w) == regular) {
        arc.vertices.push_back(w);
        w = m_arcs[m_up_arcs[m_up_offset[w]]].upper;
      }
      arc.upper = node_of[w];
      G.arcs.push_back(std::move(arc));
    }
  }
  G.components = internal::count_components(G);
  return G;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_AUGMENTED_REEB_GRAPH_H
