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
