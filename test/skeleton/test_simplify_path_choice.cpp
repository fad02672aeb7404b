// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// simplify_by_persistence(): the path a merged branch is glued onto, as its documentation states it (a path
// from the fork into the sibling component that holds the elder, entered by the first such arc of the fork,
// to the nearest node beyond e's level in the elder's part; the route of another merged branch taken only
// when its fork is strictly nearer and its route is one this search could take). The guarantees (features
// above 2 delta survive, bottleneck bounds) hold whichever path is chosen: these small graphs, whose result
// is derived by hand from the rule, pin the choice itself (each test fails when the part of the rule it names
// is changed). All are graphs with a maximum e of a short spur at the fork s (vertex 1, f 0) above the
// minimum (vertex 0, f -1); the spur's vertices are 2 (f 0.5) and e = 3 (f 1); the elder is the maximum at
// f 10.
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "skeleton_test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
/// An arc as (lower node's vertex, upper node's vertex, its vertices in increasing value order).
using Arc_by_vertices = std::tuple<Vertex_index, Vertex_index, std::vector<Vertex_index>>;

/// The arcs of G by their nodes' vertices, sorted.
std::vector<Arc_by_vertices> arcs_by_vertices(const Reeb_graph& G) {
  std::vector<Arc_by_vertices> arcs;
  for (const auto& a : G.arcs)
    arcs.emplace_back(G.nodes[a.lower].vertex, G.nodes[a.upper].vertex, a.vertices);
  std::sort(arcs.begin(), arcs.end());
  return arcs;
}

/// The vertices of G's nodes, in G's (value) order.
std::vector<Vertex_index> node_vertices(const Reeb_graph& G) {
  std::vector<Vertex_index> v;
  for (const auto& node : G.nodes) v.push_back(node.vertex);
  return v;
}

/// The simplification of the Reeb graph of the graph with these edges and values.
Reeb_simplification_result simplified(std::vector<Edge> edges, std::vector<double> f, double delta) {
  const std::size_t n = f.size();
  const auto c = make(n, std::move(edges), {}, std::move(f));
  return simplify_by_persistence(compute_augmented_reeb_graph(c.complex, c.f), delta);
}
}  // namespace

// "the first such arc of the fork": the sibling component is entered by two arcs of s, a loop s - 4 - 6 and
// s - 5 - 6 (kept, height 2), 6 going on to the elder 7. The arcs of s go in the order of the first vertex
// each reaches, 4 (f 0.3) before 5 (f 0.4): the spur is glued onto the arc through 4 up to its level, so it
// lies on that arc afterwards and the arc through 5 keeps only 5.
TEST(SimplifyPathChoice, TheBranchEntersTheElderComponentByTheFirstArcOfTheFork) {
  const Reeb_simplification_result S =
      simplified({{0, 1}, {1, 2}, {2, 3}, {1, 4}, {4, 6}, {1, 5}, {5, 6}, {6, 7}},
                 {-1, 0, 0.5, 1, 0.3, 0.4, 2, 10}, 1.5);
  EXPECT_EQ(S.removed_branches, 1u);
  EXPECT_EQ(S.removed_loops, 0u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 1, 6, 7}));
  EXPECT_EQ(arcs_by_vertices(S.graph),
            (std::vector<Arc_by_vertices>{{0, 1, {}}, {1, 6, {4, 2, 3}}, {1, 6, {5}}, {6, 7, {}}}));
}

// "strictly nearer than such a node": from a = 4 (f 0.2) the search meets, in its first layer, the fork x =
// 5 (f 0.3) of the merged spur 5 - 6 (f 0.9, same elder) and then the node y = 7 (f 3, beyond e's level, in
// the elder's part) over the arc 4 - 8 - 7. x is as near as y, not nearer: the path runs s - a - y, and the
// spur lies on that arc (with 8); the spur of x is glued onto its own path x - 9 - 7, so x becomes regular on
// the other arc from a to y.
TEST(SimplifyPathChoice, ATargetAsNearAsAJoinableForkIsTaken) {
  const Reeb_simplification_result S =
      simplified({{0, 1}, {1, 2}, {2, 3}, {1, 4}, {4, 5}, {5, 6}, {4, 8}, {8, 7}, {5, 9}, {9, 7}, {7, 10}},
                 {-1, 0, 0.5, 1, 0.2, 0.3, 0.9, 3, 0.7, 0.8, 10}, 1.2);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 7, 10}));
  EXPECT_EQ(arcs_by_vertices(S.graph),
            (std::vector<Arc_by_vertices>{{0, 4, {1}}, {4, 7, {2, 8, 3}}, {4, 7, {5, 9, 6}}, {7, 10, {}}}));
}

// A joinable route's last arc "ends beyond e's level only in the elder's part": the fork x = 5 (f 0.3) of
// the merged spur 5 - 6 (f 0.8) is nearer than any target, but its path x - 8 - 7 ends at the maximum z = 7
// (f 2.5), which joins the elder only at w = 9 (f 0.9), below e's level: z is not in the elder's part there.
// So x is not joined; the nearest node beyond e's level in the elder's part is the elder 10, over a = 4 - 11
// - w: the spur's 2 (f 0.5) lies on the arc a - w and e on the arc w - 10.
TEST(SimplifyPathChoice, ARouteEndingBeyondTheLevelOutsideTheEldersPartIsNotJoined) {
  const Reeb_simplification_result S = simplified(
      {{0, 1}, {1, 2}, {2, 3}, {1, 4}, {4, 5}, {5, 6}, {5, 8}, {8, 7}, {4, 11}, {11, 9}, {9, 7}, {9, 10}},
      {-1, 0, 0.5, 1, 0.2, 0.3, 0.8, 2.5, 0.6, 0.9, 10, 0.4}, 1.2);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 9, 7, 10}));
  EXPECT_EQ(arcs_by_vertices(S.graph),
            (std::vector<Arc_by_vertices>{
                {0, 4, {1}}, {4, 7, {5, 8, 6}}, {4, 9, {11, 2}}, {9, 7, {}}, {9, 10, {3}}}));
}

// A joinable route goes "between e's level and the fork's up to its last arc": the fork x = 6 (f 0.3) of
// the merged spur 6 - 7 (f 1.5) is nearer than any target, but its path x - 8 - p - 10 passes p = 9 (f 1.2),
// beyond e's level, before its last arc. So x is not joined; the search goes on from a = 4 through its first
// arc to w = 5 (f 0.25, the fork of the kept maximum 12) and on to the elder 10 over 13: the spur lies on the
// arc w - 10. The spur of x (7, above p) lies on the arc p - 10.
TEST(SimplifyPathChoice, ARoutePassingBeyondTheLevelIsNotJoined) {
  const Reeb_simplification_result S =
      simplified({{0, 1},
                  {1, 2},
                  {2, 3},
                  {1, 4},
                  {4, 5},
                  {4, 6},
                  {6, 7},
                  {6, 8},
                  {8, 9},
                  {9, 10},
                  {9, 11},
                  {5, 12},
                  {5, 13},
                  {13, 10}},
                 {-1, 0, 0.5, 1, 0.2, 0.25, 0.3, 1.5, 0.7, 1.2, 10, 4, 5, 0.6}, 1.25);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 5, 9, 11, 12, 10}));
  EXPECT_EQ(arcs_by_vertices(S.graph), (std::vector<Arc_by_vertices>{{0, 4, {1}},
                                                                     {4, 5, {}},
                                                                     {4, 9, {6, 8}},
                                                                     {5, 10, {2, 13, 3}},
                                                                     {5, 12, {}},
                                                                     {9, 10, {7}},
                                                                     {9, 11, {}}}));
}

// A joinable route went "towards the elder" ("else to the nearest node beyond it" does not count): the
// merged spur 6 - 7 (f 1.3) at x = 6 (f 0.3) finds no way to the elder's part at its level (its sibling goes
// x - b = 8 (f 0.4) - z = 9 (f 3), and z joins the elder only at the minimum 14, f 1.1), so its path is the
// fallback x - b - z. The spur's search meets x first but does not join it: it goes from a = 4 through w = 5
// (f 0.25, the fork of the kept maximum 12) to the elder 10 over 13, and the spur lies on the arc w - 10.
TEST(SimplifyPathChoice, AFallbackRouteIsNotJoined) {
  const Reeb_simplification_result S =
      simplified({{0, 1},
                  {1, 2},
                  {2, 3},
                  {1, 4},
                  {4, 5},
                  {4, 6},
                  {6, 7},
                  {6, 8},
                  {8, 9},
                  {8, 11},
                  {9, 14},
                  {14, 10},
                  {5, 12},
                  {5, 13},
                  {13, 10}},
                 {-1, 0, 0.5, 1, 0.2, 0.25, 0.3, 1.3, 0.4, 3, 10, 6, 5, 0.6, 1.1}, 1.1);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 5, 8, 14, 9, 12, 11, 10}));
  EXPECT_EQ(arcs_by_vertices(S.graph), (std::vector<Arc_by_vertices>{{0, 4, {1}},
                                                                     {4, 5, {}},
                                                                     {4, 8, {6}},
                                                                     {5, 10, {2, 13, 3}},
                                                                     {5, 12, {}},
                                                                     {8, 9, {7}},
                                                                     {8, 11, {}},
                                                                     {14, 9, {}},
                                                                     {14, 10, {}}}));
}

// A route is joined only "coming to x from x's near side": the spur's search starts at u = 4 (f 0.6) and
// meets in its first layer the fork x = 5 (f 0.4) of the merged spur 5 - 6 (f 1.2), but from u, beyond x. So
// x is not joined; the path goes s - u - g - 8, g = 7 (f 0.8) the fork of the kept maximum 9 and 8 the elder:
// the spur's 2 lies on the arc from the minimum to u (s regular, with 1) and e on the arc g - 8, with x's
// spur (glued onto x - u - g - 8). x, regular, lies on the other arc of the kept loop 0 - u.
TEST(SimplifyPathChoice, AForkMetFromItsFarSideIsNotJoined) {
  const Reeb_simplification_result S =
      simplified({{0, 1}, {1, 2}, {2, 3}, {1, 4}, {0, 5}, {5, 4}, {5, 6}, {4, 7}, {7, 8}, {7, 9}},
                 {-1, 0, 0.5, 1, 0.6, 0.4, 1.2, 0.8, 10, 5}, 1.1);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(S.removed_loops, 0u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 7, 9, 8}));
  EXPECT_EQ(
      arcs_by_vertices(S.graph),
      (std::vector<Arc_by_vertices>{{0, 4, {1, 2}}, {0, 4, {5}}, {4, 7, {}}, {7, 8, {3, 6}}, {7, 9, {}}}));
}

// A route from a fork "where a kept loop ends" is not joined (two arcs there lead on into the elder's part):
// x = 6 (f 0.3), the fork of the merged spur 6 - 7 (f 0.9), is the bottom of the kept loop x - 8 - c and
// x - 9 - c (c = 10, f 3). The spur's search meets x first but goes on from a = 4 through w = 5 (f 0.25, the
// fork of the kept maximum 13) to the elder 11 over 12: the spur lies on the arc w - 11. x's spur lies on
// x's first arc (through 8, f 0.45).
TEST(SimplifyPathChoice, ARouteFromTheBottomOfAKeptLoopIsNotJoined) {
  const Reeb_simplification_result S =
      simplified({{0, 1},
                  {1, 2},
                  {2, 3},
                  {1, 4},
                  {4, 5},
                  {4, 6},
                  {6, 7},
                  {6, 8},
                  {8, 10},
                  {6, 9},
                  {9, 10},
                  {10, 11},
                  {5, 12},
                  {12, 11},
                  {5, 13}},
                 {-1, 0, 0.5, 1, 0.2, 0.25, 0.3, 0.9, 0.45, 0.5, 3, 10, 0.6, 5}, 1.2);
  EXPECT_EQ(S.removed_branches, 2u);
  EXPECT_EQ(S.removed_loops, 0u);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{0, 4, 5, 6, 10, 13, 11}));
  EXPECT_EQ(arcs_by_vertices(S.graph), (std::vector<Arc_by_vertices>{{0, 4, {1}},
                                                                     {4, 5, {}},
                                                                     {4, 6, {}},
                                                                     {5, 11, {2, 12, 3}},
                                                                     {5, 13, {}},
                                                                     {6, 10, {8, 7}},
                                                                     {6, 10, {9}},
                                                                     {10, 11, {}}}));
}

namespace {
/// simplify_by_persistence() on a tree by brute force, from the documented rule alone. On a tree the path
/// from the fork s into the elder's component is the one tree path from s towards the elder; pi1 is that
/// path up to its first vertex at or beyond e's level, pi2 the tree path from s to e. Every point of a
/// merging set (pi1 and pi2 of one merged pair) is identified with every other point of the set at the same
/// height, all sets together. The quotient is computed on the tree subdivided at every vertex level: the
/// points at a level and the pieces between two consecutive levels are classes of a union-find; with distinct
/// values its graph is the Reeb graph once the regular classes (one piece above, one below) are chained into
/// arcs. Returns false (no oracle) when a pair's path to the elder first crosses e's level outside the
/// elder's part, where the documentation falls back on the nearest node beyond the level (a breadth-first
/// choice).
struct Tree_quotient {
  std::set<Vertex_index> nodes;
  /// (lower node, upper node, the vertices inside the arc)
  std::multiset<std::tuple<Vertex_index, Vertex_index, std::set<Vertex_index>>> arcs;
  std::size_t removed_branches = 0;
};

bool simplify_tree_by_brute_force(std::size_t n, const std::vector<Edge>& edges, const std::vector<double>& f,
                                  double delta, Tree_quotient& out) {
  std::vector<std::vector<Vertex_index>> adj(n);
  for (const Edge& e : edges) {
    adj[e[0]].push_back(e[1]);
    adj[e[1]].push_back(e[0]);
  }
  // The tree path from a to b (vertices, a first).
  auto tree_path = [&](Vertex_index a, Vertex_index b) {
    std::vector<Vertex_index> parent(n, static_cast<Vertex_index>(n)), queue{a};
    parent[a] = a;
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (const Vertex_index y : adj[queue[i]])
        if (parent[y] == n) parent[y] = queue[i], queue.push_back(y);
    std::vector<Vertex_index> path{b};
    while (path.back() != a) path.push_back(parent[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
  };
  std::vector<std::vector<Vertex_index>> merging_sets;  // as vertex paths: pi2 reversed, then pi1
  for (const double sign : {1.0, -1.0}) {               // maxima (superlevel sweep), then minima
    auto g = [&](Vertex_index v) { return sign * f[v]; };
    std::vector<Vertex_index> order(n), root(n), top(n);
    std::iota(order.begin(), order.end(), Vertex_index(0));
    std::sort(order.begin(), order.end(), [&](Vertex_index a, Vertex_index b) { return g(a) > g(b); });
    std::iota(root.begin(), root.end(), Vertex_index(0));
    top = root;  // the extreme of each component
    std::function<Vertex_index(Vertex_index)> find = [&](Vertex_index x) {
      return root[x] == x ? x : root[x] = find(root[x]);
    };
    std::vector<char> swept(n, 0);
    for (const Vertex_index s : order) {
      swept[s] = 1;
      std::vector<Vertex_index> parts;  // the components beyond s
      for (const Vertex_index y : adj[s])
        if (swept[y] && y != s) parts.push_back(find(y));
      if (parts.size() >= 2) {
        const Vertex_index elder =
            top[*std::max_element(parts.begin(), parts.end(),
                                  [&](Vertex_index a, Vertex_index b) { return g(top[a]) < g(top[b]); })];
        for (const Vertex_index c : parts) {
          const Vertex_index e = top[c];
          if (e == elder || !(g(e) - g(s) <= delta)) continue;
          ++out.removed_branches;
          const std::vector<Vertex_index> pi2 = tree_path(s, e), to_elder = tree_path(s, elder);
          std::size_t k = 1;
          while (g(to_elder[k]) < g(e)) ++k;
          for (std::size_t j = k; j < to_elder.size(); ++j)
            if (g(to_elder[j]) < g(e)) return false;  // crossed outside the elder's part: the fallback
          std::vector<Vertex_index> set(pi2.rbegin(), pi2.rend());
          set.insert(set.end(), to_elder.begin() + 1, to_elder.begin() + static_cast<std::ptrdiff_t>(k) + 1);
          merging_sets.push_back(std::move(set));
        }
      }
      for (const Vertex_index c : parts) {
        const Vertex_index r = find(c), t = find(s);
        if (r == t) continue;
        if (g(top[r]) > g(top[t])) top[t] = top[r];
        root[r] = t;
      }
    }
  }
  // Levels: the vertices by value. Points: vertex v is point v; edge k's point at level j (strictly
  // between its ends) is point n + ... Pieces: edge k between levels j and j + 1.
  std::vector<Vertex_index> by_value(n);
  std::iota(by_value.begin(), by_value.end(), Vertex_index(0));
  std::sort(by_value.begin(), by_value.end(), [&](Vertex_index a, Vertex_index b) { return f[a] < f[b]; });
  std::vector<std::size_t> rank(n);
  for (std::size_t j = 0; j < n; ++j) rank[by_value[j]] = j;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> point_id, piece_id;  // (edge, level)
  std::vector<std::size_t> point_parent(n), piece_parent;
  std::iota(point_parent.begin(), point_parent.end(), std::size_t(0));
  std::map<std::pair<Vertex_index, Vertex_index>, std::size_t> edge_index;
  std::vector<std::array<std::size_t, 2>> piece_ends;  // the points at its lower and upper level
  auto point = [&](std::size_t k, std::size_t level) {
    const Vertex_index a = edges[k][0], b = edges[k][1];
    if (rank[a] == level) return std::size_t(a);
    if (rank[b] == level) return std::size_t(b);
    const auto [it, added] = point_id.emplace(std::make_pair(k, level), point_parent.size());
    if (added) point_parent.push_back(it->second);
    return it->second;
  };
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Vertex_index a = edges[k][0], b = edges[k][1];
    edge_index[{std::min(a, b), std::max(a, b)}] = k;
    for (std::size_t j = std::min(rank[a], rank[b]); j < std::max(rank[a], rank[b]); ++j) {
      piece_id[{k, j}] = piece_parent.size();
      piece_parent.push_back(piece_parent.size());
      piece_ends.push_back({point(k, j), point(k, j + 1)});
    }
  }
  std::function<std::size_t(std::vector<std::size_t>&, std::size_t)> find =
      [&](std::vector<std::size_t>& parent, std::size_t x) {
        return parent[x] == x ? x : parent[x] = find(parent, parent[x]);
      };
  for (const std::vector<Vertex_index>& set : merging_sets) {
    std::map<std::size_t, std::size_t> point_at, piece_at;  // level -> the first point / piece of the set
    for (std::size_t i = 0; i + 1 < set.size(); ++i) {
      const std::size_t k = edge_index.at({std::min(set[i], set[i + 1]), std::max(set[i], set[i + 1])});
      const std::size_t lo = std::min(rank[set[i]], rank[set[i + 1]]),
                        hi = std::max(rank[set[i]], rank[set[i + 1]]);
      for (std::size_t j = lo; j <= hi; ++j) {
        const auto [it, added] = point_at.emplace(j, point(k, j));
        if (!added) point_parent[find(point_parent, point(k, j))] = find(point_parent, it->second);
        if (j == hi) continue;
        const auto [pt, new_piece] = piece_at.emplace(j, piece_id.at({k, j}));
        if (!new_piece)
          piece_parent[find(piece_parent, piece_id.at({k, j}))] = find(piece_parent, pt->second);
      }
    }
  }
  // The quotient graph: each piece class once, between the classes of its ends.
  std::map<std::size_t, std::pair<std::size_t, std::size_t>> class_ends;  // piece class -> (lower, upper)
  for (std::size_t p = 0; p < piece_parent.size(); ++p)
    class_ends[find(piece_parent, p)] = {find(point_parent, piece_ends[p][0]),
                                         find(point_parent, piece_ends[p][1])};
  std::map<std::size_t, std::vector<std::size_t>> up, down;  // point class -> piece classes above / below
  for (const auto& [piece, ends] : class_ends) {
    up[ends.first].push_back(piece);
    down[ends.second].push_back(piece);
  }
  std::map<std::size_t, Vertex_index> vertex_of;  // point class -> its input vertex (at most one)
  for (Vertex_index v = 0; v < n; ++v) EXPECT_TRUE(vertex_of.emplace(find(point_parent, v), v).second);
  auto regular = [&](std::size_t c) { return up[c].size() == 1 && down[c].size() == 1; };
  for (const auto& [c, v] : vertex_of)
    if (!regular(c)) out.nodes.insert(v);
  for (const auto& [c, v] : vertex_of) {
    if (regular(c)) continue;
    for (std::size_t piece : up[c]) {  // the arc that starts with this piece
      std::set<Vertex_index> inside;
      std::size_t end = class_ends[piece].second;
      while (regular(end)) {
        if (vertex_of.count(end)) inside.insert(vertex_of[end]);
        piece = up[end].front();
        end = class_ends[piece].second;
      }
      out.arcs.emplace(v, vertex_of.at(end), inside);
    }
  }
  return true;
}
}  // namespace

namespace {
/// Checks simplify_by_persistence() on a tree against simplify_tree_by_brute_force(); returns the number of
/// branches removed, or -1 when the brute force has no answer (the fallback).
int expect_tree_quotient(std::size_t n, const std::vector<Edge>& edges, const std::vector<double>& f,
                         double delta) {
  Tree_quotient expected;
  if (!simplify_tree_by_brute_force(n, edges, f, delta, expected)) return -1;
  const auto c = make(n, edges, {}, f);
  const Reeb_simplification_result S =
      simplify_by_persistence(compute_augmented_reeb_graph(c.complex, c.f), delta);
  Tree_quotient got;
  for (const auto& node : S.graph.nodes) {
    got.nodes.insert(node.vertex);
    EXPECT_TRUE(node.members.empty());  // distinct values: no two vertices are identified
  }
  for (const auto& a : S.graph.arcs)
    got.arcs.emplace(S.graph.nodes[a.lower].vertex, S.graph.nodes[a.upper].vertex,
                     std::set<Vertex_index>(a.vertices.begin(), a.vertices.end()));
  EXPECT_EQ(S.removed_branches, expected.removed_branches);
  EXPECT_EQ(got.nodes, expected.nodes);
  EXPECT_EQ(got.arcs, expected.arcs);
  return static_cast<int>(expected.removed_branches);
}
}  // namespace

// The documentation's claim "on a tree the result is that of the path through that fork": on random trees,
// whatever routes the searches join, the result is the quotient by the tree paths (brute force above).
// Distinct values; half of the vertices of each tree hang off a random earlier one, the rest make long
// paths, so that forks of merged branches lie on each other's way to their elders.
TEST(SimplifyPathChoice, OnTreesTheResultIsTheQuotientByTheTreePaths) {
  std::mt19937 rng(20261206);
  std::size_t compared = 0, joined_somewhere = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 14)(rng);
    std::vector<Edge> edges;
    for (Vertex_index v = 1; v < n; ++v) {
      const auto parent = std::bernoulli_distribution(0.5)(rng)
                              ? v - 1
                              : std::uniform_int_distribution<Vertex_index>(0, v - 1)(rng);
      edges.push_back({parent, v});
    }
    std::vector<double> f(n);
    std::vector<int> levels(40);
    std::iota(levels.begin(), levels.end(), 0);
    std::shuffle(levels.begin(), levels.end(), rng);
    for (std::size_t v = 0; v < n; ++v) f[v] = levels[v];
    const double delta = std::uniform_int_distribution<int>(0, 40)(rng) + 0.5;
    const int removed = expect_tree_quotient(n, edges, f, delta);
    if (::testing::Test::HasFailure()) FAIL() << "trial " << trial;
    if (removed < 0) continue;
    ++compared;
    joined_somewhere += removed >= 2;
  }
  EXPECT_GT(compared, 2500u);
  EXPECT_GT(joined_somewhere, 500u);
}

// A joinable route is one "with the same elder": on the tree 8 - 2 - 4 - 7 - 0 - 1, 0 - 6, 7 - 5 - 3 - 9
// (f 0, 26, 11, 22, 7, 1, 12, 27, 25, 6), delta 24.5, the minimum 9 (f 6) dies at the down-fork 5 (f 27); its
// elder is 8 (f 0), by the tree path 5 - 7 - 4 - 2 - 8. The search from 5 meets 7 (f 22) first, the fork of
// the merged minimum 4 (f 11), whose route 7 - 0 (f 7) goes towards another elder, 1 (f 1). Joining it would
// glue 9 onto the far side of 0, into 1's part. The result is the quotient by the tree paths: the minima 8
// and 1 meet at 4, below the maximum 5.
TEST(SimplifyPathChoice, ARouteTowardsAnotherElderIsNotJoined) {
  const std::vector<Edge> edges{{0, 1}, {2, 4}, {3, 5}, {0, 6}, {5, 7}, {3, 9}, {7, 0}, {4, 7}, {2, 8}};
  const std::vector<double> f{7, 1, 26, 25, 11, 27, 12, 22, 0, 6};
  EXPECT_EQ(expect_tree_quotient(10, edges, f, 24.5), 4);
  const auto c = make(10, edges, {}, f);
  const Reeb_simplification_result S =
      simplify_by_persistence(compute_augmented_reeb_graph(c.complex, c.f), 24.5);
  EXPECT_EQ(node_vertices(S.graph), (std::vector<Vertex_index>{8, 1, 4, 5}));
  EXPECT_EQ(arcs_by_vertices(S.graph),
            (std::vector<Arc_by_vertices>{{1, 4, {0}}, {4, 5, {6, 7, 3, 2}}, {8, 4, {9}}}));
}
