// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_AUGMENTED_REEB_GRAPH_H
#define FEATURERECON_SKELETON_AUGMENTED_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Compressed_lists.h>
#include <FeatureRecon/internal/Large_array_allocator.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/internal/Link_cut_tree.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

class Augmented_reeb_graph;
template <class FunctionRange>
Augmented_reeb_graph compute_augmented_reeb_graph(const Simplicial_complex_2& K, const FunctionRange& f,
                                                  const Reeb_graph_options& options = {});

struct Reeb_graph;
namespace internal {
inline std::size_t count_components(const Reeb_graph& G);
}  // namespace internal

/// Criticality of a node of a Reeb graph, as a bit set: a node can carry several flags (degenerate
/// nodes, e.g. an isolated vertex is a minimum and a maximum; a node with two arcs below and two
/// above is a down-fork and an up-fork). A regular node (one arc below, one above) has no flag.
enum Node_type : unsigned {
  regular = 0,
  minimum = 1,   ///< no arc below
  maximum = 2,   ///< no arc above
  up_fork = 4,   ///< two or more arcs above
  down_fork = 8  ///< two or more arcs below
};

/// A readable name of a node type (a Node_type bit set): "regular", "minimum", "maximum", "up-fork",
/// "down-fork", "isolated" (minimum and maximum), "minimum+up-fork", "maximum+down-fork",
/// "up-fork+down-fork"; the names the GraphML, GeoJSON and PLY writers of the command line use.
inline const char* node_type_name(unsigned t) {
  if ((t & minimum) && (t & maximum)) return "isolated";
  if (t & minimum) return (t & up_fork) ? "minimum+up-fork" : "minimum";
  if (t & maximum) return (t & down_fork) ? "maximum+down-fork" : "maximum";
  if ((t & up_fork) && (t & down_fork)) return "up-fork+down-fork";
  if (t & up_fork) return "up-fork";
  if (t & down_fork) return "down-fork";
  return "regular";
}

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
    /// other input vertices identified with this node (after simplification)
    std::vector<Vertex_index> members;
  };
  /// An arc between two nodes, with the regular input vertices mapped into it.
  struct Arc {
    std::size_t lower = 0;               ///< index into `nodes`
    std::size_t upper = 0;               ///< index into `nodes`
    std::vector<Vertex_index> vertices;  ///< regular input vertices mapped into the arc, in increasing order
  };
  std::vector<Node> nodes;  ///< critical nodes, by increasing (f, vertex index)
  /// Arcs of reeb_graph() by lower node; the arcs out of one node by the (f, vertex index) order of the first
  /// vertex each reaches (its first interior vertex, or its upper node when it has none). The graphs that
  /// simplification, repair and trimming return do not keep this order.
  std::vector<Arc> arcs;
  /// Connected components of the graph: set by every function that returns a Reeb_graph. A graph built by
  /// hand may leave it 0 (no graph with nodes has none): loops() then counts them.
  std::size_t components = 0;
  /// First Betti number: arcs + components - nodes, with the components counted when `components` is 0 and
  /// there are nodes (arcs joining nodes out of range are not counted; 0 when `components` is too small for
  /// that to be one).
  std::size_t loops() const {
    const std::size_t c = components != 0 || nodes.empty() ? components : internal::count_components(*this);
    return arcs.size() + c >= nodes.size() ? arcs.size() + c - nodes.size() : 0;
  }
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
  std::size_t up_degree(Vertex_index v) const { return m_up_offset[m_rank[v] + 1] - m_up_offset[m_rank[v]]; }
  /// Node_type flags of the image of v.
  unsigned type(Vertex_index v) const { return node_type_from_degrees(down_degree(v), up_degree(v)); }
  /// Indices into arcs() of the arcs leaving v upwards (consecutive: arcs() is sorted by its lower ends'
  /// ranks).
  std::vector<std::size_t> up_arcs(Vertex_index v) const {
    std::vector<std::size_t> k(up_degree(v));
    std::iota(k.begin(), k.end(), m_up_offset[m_rank[v]]);
    return k;
  }
  /// Completed, interrupted by the progress callback (arcs still open are missing; no arc at all after a stop
  /// in the set-up passes), or degenerate (empty input).
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
  // by rank r: the arcs whose lower end has rank r, [m_up_offset[r], [r + 1])
  std::vector<std::size_t> m_up_offset;
  Status m_status = Status::success;
};

namespace internal {
/// \cond
// Per key 0..n-1 (a sweep step) the values emitted with it, in emit order, in large arrays.
template <class T>
using Buckets = FeatureRecon::internal::Compressed_lists<T, FeatureRecon::internal::Large_array_allocator<T>>;
/// \endcond
}  // namespace internal

/// Computes the augmented Reeb graph of the PL function `f` on the complex `K`.
///
/// Method: a sweep in increasing (f, index) order (Parsa's algorithm). The level set between two
/// consecutive vertex values is a graph whose nodes are the edges of K it crosses and whose edges come
/// from the triangles it crosses. Its connectivity is maintained as a maximum spanning forest keyed by
/// deletion time in a link-cut tree, which makes every deletion final (an offline dynamic-connectivity
/// structure). Each component of the level set is an arc of the augmented Reeb graph; an arc ends at the
/// first vertex whose star touches it. Two union-finds keep most triangles out of the link-cut tree: a
/// local Kruskal over the lower halves born at a vertex, and the "fan" of each vertex c (edges of K into c
/// joined by upper halves with c on top, which all live until c) for the upper halves. O((n + m) log m)
/// time for m simplices, O(n + m) memory. Any simplicial 2-complex is handled: dangling edges, non-manifold
/// vertices and edges, isolated vertices, several components.
///
/// \param K a canonical complex (see Simplicial_complex_2).
/// \param f one finite value per vertex (any random-access range convertible to double).
/// \pre K is canonical. Its simplices are checked (sorted, unique, in range; throws); its edge lengths are
/// not
///      used and not checked. f has K.number_of_vertices finite values (checked; throws, naming the first bad
///      index). Fewer than 2^31 - 1 vertices, 2^30 edges and 2^31 - 1 edges and triangles together (checked).
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
  if (const std::string problem = internal::canonical_order_problem(K); !problem.empty())
    FeatureRecon::internal::throw_invalid_argument(fn, "the complex is not canonical: ", problem,
                                                   "; build it with make_simplicial_complex_2()");
  // 32-bit indices: the link-cut forest has 2E nodes; arcs and triangles are counted in int32 too.
  const std::size_t index_limit = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (K.number_of_edges() + K.number_of_triangles() >= index_limit ||
      2 * K.number_of_edges() >= index_limit || n >= index_limit)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the complex is too large (", n, " vertices, ", K.number_of_edges(), " edges, ",
        K.number_of_triangles(),
        " triangles; fewer than 2^31 - 1 vertices, 2^30 edges and 2^31 - 1 "
        "edges and triangles together are supported)");

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
  // Progress: the set-up passes (sorting, bucketing, two passes over the triangles) report up to 0.4, the
  // sweep from 0.4 to 1; on a dense Rips complex the set-up takes about two thirds of the time. A stop in the
  // set-up returns the graph without arcs.
  const double sweep_start = 0.4;
  auto interrupt = [&R]() {
    R.m_status = Status::interrupted;
    R.m_arcs.clear();
    R.finish();
  };
  auto stop_here = [&options, &interrupt](double fraction) {
    if (FeatureRecon::internal::report_progress(options.progress, fraction)) return false;
    interrupt();
    return true;
  };
  {
    // contiguous keys sort faster than indirection
    FeatureRecon::internal::Large_vector<std::pair<double, Vertex_index>> keyed(n);
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
  if (stop_here(0.0)) return R;

  // Per vertex: edges whose lower / upper end it is (by rank). Buckets are keyed by sweep step (rank), not by
  // vertex: the sweep then reads them sequentially. The edges leaving a vertex are listed by decreasing rank
  // of their upper end (the order of the local Kruskal below).
  const std::size_t E = K.number_of_edges(), T = K.number_of_triangles();
  auto lower_of = [&](std::size_t e) { return std::min(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  auto upper_of = [&](std::size_t e) { return std::max(rank[K.edges[e][0]], rank[K.edges[e][1]]); };
  internal::Buckets<std::uint32_t> up_edges, down_edges;
  down_edges.build(n, [&](auto emit) {
    for (std::size_t e = 0; e < E; ++e) emit(upper_of(e), static_cast<std::uint32_t>(e));
  });
  up_edges.build(n, [&](auto emit) {
    for (std::size_t step = n; step-- > 0;)
      for (const std::uint32_t* e = down_edges.begin(step); e != down_edges.end(step); ++e)
        emit(lower_of(*e), *e);
  });

  // Sweep numbering: edges are renumbered in the order of up_edges, so that the level-set nodes alive at one
  // time sit close together in memory (this matters for large complexes).
  FeatureRecon::internal::Large_vector<std::uint32_t> edge_new(E);
  for (std::size_t i = 0; i < E; ++i) edge_new[up_edges.items[i]] = static_cast<std::uint32_t>(i);
  for (std::uint32_t& e : up_edges.items) e = edge_new[e];
  for (std::uint32_t& e : down_edges.items) e = edge_new[e];
  if (stop_here(0.05)) return R;

  // Visits the triangles u < v < w in their canonical (sorted) order with the sweep numbers of their edges
  // uv, vw, uw, found by a merge walk over the sorted edge list (edges starting at u are contiguous).
  FeatureRecon::internal::Large_vector<std::size_t> first_edge(n + 1, 0);
  for (const Edge& e : K.edges) ++first_edge[e[0] + 1];
  for (std::size_t v = 0; v < n; ++v) first_edge[v + 1] += first_edge[v];
  // Galloping search from i: O(log) of the distance walked, so that a vertex of high degree whose triangles'
  // third vertices lie far apart in its edge list costs O(deg log deg), not O(deg^2).
  auto seek = [&](std::size_t i, Vertex_index u, Vertex_index v) {
    const std::size_t end = first_edge[u + 1];
    std::size_t step = 1;
    while (i + step < end && K.edges[i + step][1] < v) {
      i += step;
      step *= 2;
    }
    while (step > 1) {  // K.edges[i][1] < v or i is the start; K.edges[i + step][1] >= v or i + step >= end
      step /= 2;
      if (i + step < end && K.edges[i + step][1] < v) i += step;
    }
    while (i < end && K.edges[i][1] < v) ++i;
    if (i == end || K.edges[i][1] != v)
      FeatureRecon::internal::throw_invalid_argument(fn, "the complex is not canonical: edge (", u, ", ", v,
                                                     ") of a triangle is missing");
    return i;
  };
  // Reports every 2^20 triangles, from `from` to `to`; false when the callback asked to stop (the walk ends
  // there).
  auto for_each_triangle = [&](double from, double to, auto&& visit) {
    constexpr Vertex_index none = std::numeric_limits<Vertex_index>::max();
    Vertex_index u = none, v = none;
    std::size_t uv = 0, uw = 0, vw = 0;
    for (std::size_t i = 0; i < T; ++i) {
      if ((i & ((std::size_t(1) << 20) - 1)) == 0 && i > 0 &&
          !FeatureRecon::internal::report_progress(options.progress,
                                                   from + (to - from) * static_cast<double>(i) / T))
        return false;
      const Triangle& t = K.triangles[i];
      if (t[0] != u) {
        u = t[0];
        v = none;
        uv = first_edge[u];
      }
      if (t[1] != v) {
        v = t[1];
        uv = seek(uv, u, v);
        uw = uv;
        vw = first_edge[v];
      }
      uw = seek(uw, u, t[2]);
      vw = seek(vw, v, t[2]);
      visit(t, edge_new[uv], edge_new[vw], edge_new[uw]);
    }
    return true;
  };

  // Per triangle, with its vertices by rank a < b < c: its edges ab, bc, ac. The deletion times of its lower
  // and upper halves, the ranks of b and c, are the upper ends of ab and ac. Triangles are sorted by their
  // edge ab in sweep numbering (a counting sort): by the rank of a, then by decreasing rank of b. The lower
  // halves born at one step are then contiguous and in the order of the local Kruskal below.
  struct Tri {
    std::uint32_t ab, bc, ac;
  };
  FeatureRecon::internal::Large_vector<Vertex_index> upper_rank(E);  // by sweep number
  for (std::size_t e = 0; e < E; ++e) upper_rank[edge_new[e]] = upper_of(e);
  auto roles = [&](const Triangle& t, std::uint32_t uv, std::uint32_t vw, std::uint32_t uw) {
    const Vertex_index ru = rank[t[0]], rv = rank[t[1]], rw = rank[t[2]];
    if (ru < rv) {
      if (rv < rw) return Tri{uv, vw, uw};  // u v w
      if (ru < rw) return Tri{uw, vw, uv};  // u w v
      return Tri{uw, uv, vw};               // w u v
    }
    if (ru < rw) return Tri{uv, uw, vw};  // v u w
    if (rv < rw) return Tri{vw, uw, uv};  // v w u
    return Tri{vw, uv, uw};               // w v u
  };
  FeatureRecon::internal::Large_vector<Tri> tri(T);
  // triangles [by_min[s], by_min[s + 1]) have a at step s
  FeatureRecon::internal::Large_vector<std::size_t> by_min(n + 1);
  internal::Buckets<std::uint32_t> by_mid;  // triangles by the step of b
  {
    FeatureRecon::internal::Large_vector<std::size_t> first_tri(E + 1, 0);
    if (!for_each_triangle(0.05, 0.2,
                           [&](const Triangle& t, std::uint32_t uv, std::uint32_t vw, std::uint32_t uw) {
                             ++first_tri[roles(t, uv, vw, uw).ab + 1];
                           })) {
      interrupt();
      return R;
    }
    if (stop_here(0.2)) return R;
    for (std::size_t e = 0; e < E; ++e) first_tri[e + 1] += first_tri[e];
    for (std::size_t step = 0; step <= n; ++step) by_min[step] = first_tri[up_edges.offset[step]];
    if (!for_each_triangle(0.2, 0.35,
                           [&](const Triangle& t, std::uint32_t uv, std::uint32_t vw, std::uint32_t uw) {
                             const Tri r = roles(t, uv, vw, uw);
                             tri[first_tri[r.ab]++] = r;
                           })) {
      interrupt();
      return R;
    }
    if (stop_here(0.35)) return R;
    // Two passes (count, fill) that report every 2^20 triangles. After a stop nothing more is emitted: the
    // fill then writes fewer items than were counted, never more, and the lists are dropped.
    bool stopped = false;
    int pass = 0;
    by_mid.build(n, [&](auto emit) {
      for (std::size_t t = 0; t < T && !stopped; ++t) {
        if ((t & ((std::size_t(1) << 20) - 1)) == 0 && t > 0)
          stopped = !FeatureRecon::internal::report_progress(
              options.progress, 0.35 + 0.025 * (pass + static_cast<double>(t) / static_cast<double>(T)));
        if (!stopped) emit(upper_rank[tri[t].ab], static_cast<std::uint32_t>(t));
      }
      ++pass;
    });
    if (stopped) {
      interrupt();
      return R;
    }
  }
  edge_new.clear();
  edge_new.shrink_to_fit();

  // Link-cut forest: nodes [0, E) are level-set vertices (edges of K); nodes [E, 2E) are a pool for the
  // level-set edges in the forest (a triangle's lower half, then its upper half), recycled when they
  // leave it: a forest on at most E vertices has fewer than E edges, so the pool never runs dry, and the
  // nodes in use stay few and hot in cache. Key of a level-set edge = rank of the vertex at which it is
  // deleted. Every tree root is a level-set vertex.
  using LCT = internal::Link_cut_tree;
  LCT forest(2 * E);
  // Per pool node E + i: the ends of its level-set edge and its place in the list of the forest edges deleted
  // at its key (doubly linked: an edge also leaves the forest early when a longer-lived one replaces it).
  struct Forest_edge {
    std::int32_t ends[2];
    std::int32_t prev, next;
  };
  FeatureRecon::internal::Large_vector<Forest_edge> forest_edge(E);
  FeatureRecon::internal::Large_vector<std::int32_t> deleted_at(n, LCT::null);  // head of each step's list
  auto edge_of = [&](std::int32_t x) -> Forest_edge& { return forest_edge[static_cast<std::size_t>(x) - E]; };
  std::vector<std::int32_t> free_nodes;
  free_nodes.reserve(E);
  for (std::size_t i = E; i-- > 0;) free_nodes.push_back(static_cast<std::int32_t>(E + i));
  FeatureRecon::internal::Large_vector<std::int32_t> arc_of_root(E, -1);
  // 2*step+1: seen below the vertex; 2*step+2: above
  FeatureRecon::internal::Large_vector<std::uint32_t> stamp(E, 0);

  // Number of forest edges at each level-set vertex: a vertex without any is its own tree, which lets
  // most links skip the connectivity query (every edge of K starts isolated).
  FeatureRecon::internal::Large_vector<std::uint32_t> forest_degree(E, 0);
  auto remove_forest_edge = [&](std::int32_t x) {
    Forest_edge& fe = edge_of(x);
    forest.cut_middle(x, fe.ends[0], fe.ends[1]);
    --forest_degree[fe.ends[0]];
    --forest_degree[fe.ends[1]];
    if (fe.prev != LCT::null)
      edge_of(fe.prev).next = fe.next;
    else
      deleted_at[forest.key(x)] = fe.next;
    if (fe.next != LCT::null) edge_of(fe.next).prev = fe.prev;
    free_nodes.push_back(x);
  };
  auto insert_level_edge = [&](std::int32_t p, std::int32_t q, LCT::Key key, bool known_disconnected) {
    if (forest_degree[p] != 0 && forest_degree[q] == 0) std::swap(p, q);
    if (forest_degree[p] != 0 && !known_disconnected) {
      const std::int32_t m = forest.connected_path_min(p, q);
      if (m != LCT::null) {
        if (forest.key(m) >= key) return;  // the new edge closes a cycle and dies first: not in the forest
        remove_forest_edge(m);
        forest.evert(p);
      }
    } else if (forest_degree[p] != 0) {
      forest.evert(p);
    }
    FEATURERECON_assertion(!free_nodes.empty());
    const std::int32_t x = free_nodes.back();
    free_nodes.pop_back();
    forest.set_key(x, key);
    const std::int32_t head = deleted_at[key];
    edge_of(x) = Forest_edge{{p, q}, LCT::null, head};
    if (head != LCT::null) edge_of(head).prev = x;
    deleted_at[key] = x;
    // p is a tree of its own or the root of its tree (and a splay root): hang x below q and p below x.
    forest.attach_isolated(x, q);
    if (forest_degree[p] == 0)
      forest.attach_isolated(p, x);
    else
      forest.attach_root(p, x);
    ++forest_degree[p];
    ++forest_degree[q];
  };

  // Union-find over the up-edges of the current vertex, joined by the lower halves born there: slot[e] is
  // the edge's index in the vertex's up_edges.
  FeatureRecon::internal::Large_vector<std::int32_t> slot(E, -1);
  FeatureRecon::internal::Union_find<std::int32_t> groups;
  // Union-find over the edges of K, joining two edges into the same vertex c by the upper halves with c on
  // top (the "fan" of c below the sweep level). At step c its classes are the down-edges of c joined by
  // triangles with c on top: the parts of the star below c that lie in one level-set component.
  FeatureRecon::internal::Union_find<std::uint32_t,
                                     FeatureRecon::internal::Large_array_allocator<std::uint32_t>>
      fans(E);

  if (stop_here(sweep_start)) return R;
  for (std::size_t step = 0; step < n; ++step) {
    if ((step & 1023) == 0 && step > 0 &&
        !FeatureRecon::internal::report_progress(
            options.progress, sweep_start + (1 - sweep_start) * static_cast<double>(step) / n)) {
      R.m_status = Status::interrupted;
      break;
    }
    const Vertex_index x = R.m_order[step];
    const std::uint32_t below = static_cast<std::uint32_t>(2 * step + 1), above = below + 1;
    // 1. The level-set components just below x that x touches: each is an arc ending at x. Edges into x
    //    in one fan class are in one component: one root query per class.
    for (const std::uint32_t* e = down_edges.begin(step); e != down_edges.end(step); ++e) {
      if (fans.find(*e) != *e) continue;
      const std::int32_t r = forest.find_root(static_cast<std::int32_t>(*e));
      FEATURERECON_assertion(static_cast<std::size_t>(r) < E);
      if (stamp[r] == below) continue;
      stamp[r] = below;
      const std::int32_t a = arc_of_root[r];
      FEATURERECON_assertion(a >= 0 && R.m_arcs[a].upper == R.m_arcs[a].lower);
      R.m_arcs[a].upper = x;
    }
    // 2. Level-set edges deleted at x (the forest's): lower halves of triangles with x in the middle, upper
    //    halves of triangles with x on top.
    while (deleted_at[step] != LCT::null) remove_forest_edge(deleted_at[step]);
    // 3. Level-set edges born at x. First the lower halves (ab, ac) of triangles with x at the bottom
    //    (deleted at b): both ends are edges of K born at x, still isolated, so their maximum spanning forest
    //    is local to the star of x: Kruskal by decreasing deletion time with a union-find over the new edges.
    //    A half it rejects closes a cycle of halves that live at least as long, so the global forest would
    //    reject it too: it never enters the link-cut tree (in dense Rips complexes most halves are rejected).
    const std::uint32_t* const up_begin = up_edges.begin(step);
    const std::size_t k = static_cast<std::size_t>(up_edges.end(step) - up_begin);
    groups.reset(k);
    for (std::size_t i = 0; i < k; ++i) slot[up_begin[i]] = static_cast<std::int32_t>(i);
    for (std::size_t t = by_min[step]; t != by_min[step + 1]; ++t) {
      const Tri& tr = tri[t];
      if (!groups.unite(slot[tr.ab], slot[tr.ac])) continue;
      insert_level_edge(static_cast<std::int32_t>(tr.ab), static_cast<std::int32_t>(tr.ac), upper_rank[tr.ab],
                        true);
    }
    //    Then the upper halves (bc, ac) of triangles with x in the middle (deleted at c). Both ends are edges
    //    of K into c, and so are the ends of every upper half with c on top. Those halves all live until c,
    //    so two edges that such halves already joined are connected by a path that lives at least as long as
    //    the new half: the forest rejects it (a tie), and the fan union-find skips the query.
    for (const std::uint32_t* t = by_mid.begin(step); t != by_mid.end(step); ++t) {
      const Tri& tr = tri[*t];
      if (!fans.unite(tr.bc, tr.ac)) continue;
      insert_level_edge(static_cast<std::int32_t>(tr.bc), static_cast<std::int32_t>(tr.ac), upper_rank[tr.ac],
                        false);
    }
    // 4. The components just above x that contain an edge leaving x: each starts an arc at x. Edges out
    //    of x joined by a triangle (x, b, c), one class of the Kruskal above, are in one component.
    for (std::size_t i = 0; i < k; ++i) {
      if (groups.find(static_cast<std::int32_t>(i)) != static_cast<std::int32_t>(i)) continue;
      const std::int32_t r = forest.find_root(static_cast<std::int32_t>(up_begin[i]));
      FEATURERECON_assertion(static_cast<std::size_t>(r) < E);
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
    ++m_up_offset[m_rank[a.lower] + 1];
  }
  for (std::size_t r = 0; r < n; ++r) m_up_offset[r + 1] += m_up_offset[r];
}

namespace internal {
/// Number of connected components of a Reeb graph (union-find over its nodes).
inline std::size_t count_components(const Reeb_graph& G) {
  FeatureRecon::internal::Union_find<std::size_t> sets(G.nodes.size());
  std::size_t components = G.nodes.size();
  for (const Reeb_graph::Arc& a : G.arcs) {
    if (a.lower >= G.nodes.size() || a.upper >= G.nodes.size()) continue;  // a hand-built graph's bad arc
    if (sets.unite(a.lower, a.upper)) --components;
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
    G.nodes.push_back(Reeb_graph::Node{v, m_values[v], t, {}});
  }
  for (const Reeb_graph::Node& node : G.nodes) {
    const std::size_t r = m_rank[node.vertex];
    for (std::size_t k = m_up_offset[r]; k < m_up_offset[r + 1]; ++k) {
      Reeb_graph::Arc arc;
      arc.lower = node_of[node.vertex];
      Vertex_index w = m_arcs[k].upper;
      while (type(w) == regular) {
        arc.vertices.push_back(w);
        w = m_arcs[m_up_offset[m_rank[w]]].upper;
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
