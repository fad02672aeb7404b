// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <FeatureRecon/skeleton/geodesic_function.h>
#include <FeatureRecon/skeleton/repair_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>
#include <FeatureRecon/skeleton/simplify_by_persistence.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <random>
#include <string>

#include "reeb_graph_builders.h"
#include "skeleton_test_utilities.h"
#include "test_utilities.h"

using namespace FeatureRecon;
using namespace FeatureRecon::skeleton;
using namespace FeatureRecon::test;

namespace {
/// Points on the x axis (or a circle) with f = the first coordinate.
using Line = Planar_points;
/// Appends the path of vertices 0..10 at (i, 0) with f = i (the street that others meet).
void add_horizontal_street(Line& pts, std::vector<Edge>& edges, std::vector<double>& f) {
  for (int i = 0; i <= 10; ++i) {
    pts.p.push_back({double(i), 0.0});
    f.push_back(double(i));
    if (i > 0) edges.push_back({Vertex_index(i - 1), Vertex_index(i)});
  }
}
/// Repair options with `bounded` bounds (0, 1 or 2): coordinate `axis` of `pts` as Reeb_repair_options::bound
/// and with 2 the other coordinate as second_bound (1-Lipschitz, so the result must not change). `pts` must
/// outlive the options.
Reeb_repair_options bound_option(const Planar_points& pts, int bounded, std::size_t axis = 0) {
  Reeb_repair_options x;
  if (bounded >= 1) x.bound = [&pts, axis](Vertex_index v) { return pts.p[v][axis]; };
  if (bounded == 2) x.second_bound = [&pts, axis](Vertex_index v) { return pts.p[v][1 - axis]; };
  return x;
}
/// The street of add_horizontal_street() and a vertical segment of `length` from (5, 1.5) (vertices 11 and
/// 12, f 20 and 20 + length): `pts` gets the points; returns the complex.
Complex_with_function street_and_segment(Line& pts, double length) {
  std::vector<Edge> edges;
  std::vector<double> f;
  add_horizontal_street(pts, edges, f);
  pts.p.push_back({5.0, 1.5});
  pts.p.push_back({5.0, 1.5 + length});
  f.push_back(20);
  f.push_back(20 + length);
  edges.push_back({11, 12});
  return make(pts.p.size(), edges, {}, f);
}
}  // namespace

TEST(RepairReebGraph, JoinsABrokenPathAndSimplifies) {
  // Path 0..9 along x with the edge 4-5 missing: two components.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  for (int i = 0; i < 10; ++i) {
    pts.p.push_back({double(i), 0.0});
    f.push_back(double(i));
    if (i + 1 < 10 && i != 4) edges.push_back({Vertex_index(i), Vertex_index(i + 1)});
  }
  const auto c = make(10, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  const Reeb_graph R = A.reeb_graph();
  ASSERT_EQ(R.components, 2u);
  EXPECT_EQ(repair_reeb_graph(R, 0.5, pts).joined, 0u);             // too far
  const Reeb_repair_result fixed = repair_reeb_graph(R, 1.0, pts);  // inclusive
  EXPECT_EQ(fixed.joined, 1u);
  EXPECT_EQ(fixed.graph.components, 1u);
  // Simplifying (even with delta 0) absorbs the nodes that became regular: one arc through every vertex.
  const Reeb_simplification_result S = simplify_by_persistence(fixed.graph, A.values(), 0.0);
  EXPECT_EQ(S.graph.nodes.size(), 2u);
  ASSERT_EQ(S.graph.arcs.size(), 1u);
  EXPECT_EQ(S.graph.arcs[0].vertices.size(), 8u);
  EXPECT_EQ(S.graph.components, 1u);
}

TEST(RepairReebGraph, ClosesABrokenCircleIntoALoop) {
  // A 16-gon of radius 5 with one edge missing: a path; repair closes the loop, persistence keeps it.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  for (int i = 0; i < 16; ++i) {
    const double a = 2 * std::acos(-1.0) * i / 16;
    pts.p.push_back({5 * std::cos(a), 5 * std::sin(a)});
    f.push_back(5 * std::sin(a) + 0.01 * i);
    if (i < 15) edges.push_back({Vertex_index(i), Vertex_index(i + 1)});
  }
  const auto c = make(16, edges, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  EXPECT_EQ(A.reeb_graph().loops(), 0u);
  const Reeb_repair_result fixed = repair_reeb_graph(A.reeb_graph(), 2.5, pts);
  EXPECT_EQ(fixed.joined, 1u);
  EXPECT_EQ(fixed.graph.loops(), 1u);
  const Reeb_simplification_result S = simplify_by_persistence(fixed.graph, A.values(), 1.0);
  EXPECT_EQ(S.graph.loops(), 1u);  // the loop is tall (about 10): it survives
  const Reeb_simplification_result T = simplify_by_persistence(fixed.graph, A.values(), 20.0);
  EXPECT_EQ(T.graph.loops(), 0u);
  EXPECT_THROW(repair_reeb_graph(A.reeb_graph(), -1.0, pts), std::invalid_argument);
}

TEST(RepairReebGraph, NeverJoinsTheEndsOfOneSegment) {
  // Points 0, 0.5, 1 form a short isolated segment and 10, 30 another: the segment's two ends are within the
  // distance but joining them would make a loop of two arcs. Pairs of different segments still join.
  Line pts;
  for (const double x : {0.0, 0.5, 1.0, 10.0, 30.0, 1.5, 2.5}) pts.p.push_back({x, 0.0});
  std::vector<double> f;
  for (const auto& p : pts.p) f.push_back(p[0]);
  const auto c = make(7, {{0, 1}, {1, 2}, {3, 4}}, {}, f);
  const Augmented_reeb_graph A = compute_augmented_reeb_graph(c.complex, c.f);
  const Reeb_repair_result fixed = repair_reeb_graph(A.reeb_graph(), 2.0, pts);
  EXPECT_EQ(fixed.joined, 0u);
  EXPECT_EQ(fixed.graph.loops(), 0u);
  EXPECT_EQ(fixed.graph.arcs.size(), A.reeb_graph().arcs.size());
  // With the segment 5-6 (1.5 to 2.5) beside it, the closest ends of the two segments join (2 and 5, 0.5
  // apart) and then no other pair is free.
  const auto c2 = make(7, {{0, 1}, {1, 2}, {3, 4}, {5, 6}}, {}, f);
  const Augmented_reeb_graph B = compute_augmented_reeb_graph(c2.complex, c2.f);
  const Reeb_repair_result two = repair_reeb_graph(B.reeb_graph(), 2.0, pts);
  ASSERT_EQ(two.joined, 1u);
  EXPECT_EQ(two.graph.loops(), 0u);
  const auto& joined = two.graph.arcs.back();
  EXPECT_EQ(two.graph.nodes[joined.lower].vertex, 2u);
  EXPECT_EQ(two.graph.nodes[joined.upper].vertex, 5u);
}

namespace {
/// A "lollipop": a stub 0-1-2 from the minimum (f = 0, 0.1, 0.2) into a cycle 2..9 (f rising to 1 at vertex
/// 6), plus a separate short path 10-11 (f = 5, 5.25: its height 0.25 is exact in binary, so that the pruning
/// test below checks the boundary; 5.3 - 5 rounds to 0.29999999999999982).
Complex_with_function lollipop() {
  std::vector<Edge> e{{0, 1}, {1, 2}};
  std::vector<double> f{0.0, 0.1, 0.2};
  const double up[] = {0.4, 0.6, 0.8, 1.0, 0.7, 0.5, 0.3};  // vertices 3..9
  for (double x : up) f.push_back(x);
  for (Vertex_index v = 2; v < 9; ++v) e.push_back({v, Vertex_index(v + 1)});
  e.push_back({9, 2});
  e.push_back({10, 11});
  f.push_back(5.0);
  f.push_back(5.25);
  return make(12, e, {}, f);
}
}  // namespace

TEST(TrimEssentialStubs, ContractsTheSpurAtTheMinimumOnly) {
  const Reeb_graph R = reeb_graph_of(lollipop());
  ASSERT_EQ(R.loops(), 1u);
  // Stub height 0.2: kept at 0.1, contracted at 0.2 (inclusive). The maximum (vertex 6) closes the loop
  // (degree 2): not a stub. The path 10-11 has no fork: untouched.
  EXPECT_EQ(trim_essential_stubs(R, 0.1).trimmed, 0u);
  const Reeb_trim_result t = trim_essential_stubs(R, 0.2);
  EXPECT_EQ(t.trimmed, 1u);
  EXPECT_EQ(t.graph.nodes.size(), R.nodes.size() - 1);
  EXPECT_EQ(t.graph.arcs.size(), R.arcs.size() - 1);
  EXPECT_EQ(t.graph.loops(), 1u);
  EXPECT_EQ(t.graph.components, 2u);
  // The fork (vertex 2) became the minimum of its component and holds the stub's points.
  const auto fork =
      std::find_if(t.graph.nodes.begin(), t.graph.nodes.end(), [](const auto& n) { return n.vertex == 2; });
  ASSERT_NE(fork, t.graph.nodes.end());
  EXPECT_TRUE(fork->type & minimum);
  std::vector<Vertex_index> m = fork->members;
  std::sort(m.begin(), m.end());
  EXPECT_EQ(m, (std::vector<Vertex_index>{0, 1}));
  EXPECT_EQ(invalid_argument_message([&] { trim_essential_stubs(R, -1); }),
            "trim_essential_stubs: max_height must be >= 0, got -1");
}

TEST(TrimEssentialStubs, AYLosesOneStubNotItsBranch) {
  // Minimum 0 (f 0) -> fork 1 (f 1) -> maxima 2 (f 1.5) and 3 (f 1.8): both ends are stubs of the fork.
  // Trimming both contracted the branch (1.5, 1) too; now the minimum goes and the fork, left with two arcs,
  // stays.
  Reeb_graph R;
  for (const auto& [v, f] :
       std::vector<std::pair<Vertex_index, double>>{{0, 0}, {1, 1}, {2, 1.5}, {3, 1.8}}) {
    Reeb_graph::Node n;
    n.vertex = v;
    n.value = f;
    R.nodes.push_back(n);
  }
  R.arcs = {{0, 1, {}}, {1, 2, {}}, {1, 3, {}}};
  FeatureRecon::skeleton::internal::refresh_node_types(R);
  R.components = 1;
  const Reeb_trim_result t = trim_essential_stubs(R, 1.0);
  EXPECT_EQ(t.trimmed, 1u);
  EXPECT_EQ(t.graph.nodes.size(), 3u);
  EXPECT_EQ(t.graph.arcs.size(), 2u);
  EXPECT_EQ(t.graph.nodes[0].vertex, 1u);
  EXPECT_EQ(t.graph.nodes[0].members, (std::vector<Vertex_index>{0}));
}

TEST(PruneReebGraphComponents, RemovesLowComponentsAndReportsTheirPoints) {
  const Reeb_graph R = reeb_graph_of(lollipop());
  ASSERT_EQ(R.components, 2u);
  EXPECT_EQ(prune_reeb_graph_components(R, 0.24).removed_components, 0u);  // 10-11 has height 0.25
  const Reeb_prune_result p = prune_reeb_graph_components(R, 0.25);        // at most: inclusive
  EXPECT_EQ(p.removed_components, 1u);
  EXPECT_EQ(p.removed_vertices, (std::vector<Vertex_index>{10, 11}));
  EXPECT_EQ(p.graph.components, 1u);
  EXPECT_EQ(p.graph.loops(), 1u);
  for (const auto& a : p.graph.arcs) {
    EXPECT_LT(a.lower, p.graph.nodes.size());
    EXPECT_LT(a.upper, p.graph.nodes.size());
  }
  // Everything goes at a large height; nothing at 0 (no single-vertex component here).
  EXPECT_EQ(prune_reeb_graph_components(R, 10).graph.nodes.size(), 0u);
  EXPECT_EQ(prune_reeb_graph_components(R, 0).removed_components, 0u);
  EXPECT_EQ(invalid_argument_message([&] { prune_reeb_graph_components(R, -1); }),
            "prune_reeb_graph_components: max_height must be >= 0, got -1");
  // A graph whose components field was never set (built by hand): the count is the pruned graph's own (it was
  // 0 - removed, wrapped to 2^64 - 1), and loops() counts the components itself (it gave 0 for the lollipop's
  // loop; it never wraps).
  Reeb_graph unset = R;
  unset.components = 0;
  EXPECT_EQ(unset.loops(), 1u);
  Reeb_graph bad_arc = unset;  // an arc to a node that does not exist is not counted (it was read)
  bad_arc.arcs.push_back({0, 99, {}});
  EXPECT_EQ(bad_arc.loops(), 2u);  // one more arc, the same components
  EXPECT_EQ(prune_reeb_graph_components(unset, 0.25).graph.components, 1u);
  EXPECT_EQ(prune_reeb_graph_components(unset, 0.25).graph.loops(), 1u);
}

namespace {
/// Whether two Reeb graphs have the same nodes (vertex, value, type, members), arcs and component count.
bool same_graph(const Reeb_graph& a, const Reeb_graph& b) {
  if (a.nodes.size() != b.nodes.size() || a.arcs.size() != b.arcs.size() || a.components != b.components)
    return false;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (a.nodes[i].vertex != b.nodes[i].vertex || a.nodes[i].value != b.nodes[i].value ||
        a.nodes[i].type != b.nodes[i].type || a.nodes[i].members != b.nodes[i].members)
      return false;
  for (std::size_t k = 0; k < a.arcs.size(); ++k)
    if (a.arcs[k].lower != b.arcs[k].lower || a.arcs[k].upper != b.arcs[k].upper ||
        a.arcs[k].vertices != b.arcs[k].vertices)
      return false;
  return true;
}
}  // namespace

TEST(PruneAndTrim, ReportProgressAndAStopLeavesTheInput) {
  // 700 combs: every 7th with a spine of 5 nodes (height 4, a stub of height 1 below its first fork), the
  // others two nodes (height 1): 2,000 nodes, so both stages also report inside their pass over the nodes.
  std::vector<std::size_t> spines(700, 2);
  for (std::size_t c = 0; c < spines.size(); c += 7) spines[c] = 5;
  const Reeb_graph R = reeb_combs(spines);
  ASSERT_EQ(R.nodes.size(), 2000u);
  struct Stage {
    const char* name;
    std::function<std::pair<Reeb_graph, std::size_t>(const Progress_callback&, Status&)> run;
    std::size_t expected;  // components removed or stubs trimmed
  };
  const std::vector<Stage> stages = {
      {"prune",
       [&R](const Progress_callback& p, Status& status) {
         Reeb_prune_options o;
         o.progress = p;
         Reeb_prune_result r = prune_reeb_graph_components(R, 2.0, o);
         status = r.status;
         EXPECT_TRUE(r.status == Status::success || r.removed_vertices.empty());
         return std::make_pair(std::move(r.graph), r.removed_components);
       },
       600},
      {"trim",
       [&R](const Progress_callback& p, Status& status) {
         Reeb_trim_options o;
         o.progress = p;
         Reeb_trim_result r = trim_essential_stubs(R, 1.0, o);
         status = r.status;
         return std::make_pair(std::move(r.graph), r.trimmed);
       },
       100}};
  for (const Stage& stage : stages) {
    Status status = Status::interrupted;
    const auto [plain, count] = stage.run(nullptr, status);
    EXPECT_EQ(status, Status::success) << stage.name;
    EXPECT_EQ(count, stage.expected) << stage.name;
    std::vector<double> seen;
    const auto [watched, watched_count] = stage.run(recording_progress(seen), status);
    EXPECT_EQ(status, Status::success) << stage.name;
    EXPECT_EQ(watched_count, count) << stage.name;
    EXPECT_TRUE(same_graph(watched, plain)) << stage.name;
    ASSERT_GE(seen.size(), 3u) << stage.name;
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << stage.name;
    EXPECT_EQ(seen.front(), 0.0) << stage.name;
    EXPECT_EQ(seen.back(), 1.0) << stage.name;
    EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double t) { return t > 0.2 && t < 0.8; }))
        << stage.name;
    // A stop at any report but the last: interrupted, the input unchanged, nothing counted, no later report.
    for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
      std::size_t calls = 0;
      const auto [stopped, stopped_count] = stage.run([&calls, i](double) { return calls++ != i; }, status);
      EXPECT_EQ(status, Status::interrupted) << stage.name << " stopped at " << seen[i];
      EXPECT_TRUE(same_graph(stopped, R)) << stage.name << " stopped at " << seen[i];
      EXPECT_EQ(stopped_count, 0u) << stage.name << " stopped at " << seen[i];
      EXPECT_EQ(calls, i + 1) << stage.name << " stopped at " << seen[i];
    }
  }
}

TEST(ConnectDeadEnds, ClosesATJunctionGap) {
  // A horizontal path 0..10 (vertices 0..10 at (i, 0)) and a vertical one (vertices 11..19 at (5, 1.5 + i))
  // that stops 1.5 short of it; f = x + y (the first path) and a separate rising f on the second.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  add_horizontal_street(pts, edges, f);
  for (int i = 0; i < 9; ++i) {
    pts.p.push_back({5.0, 1.5 + i});
    f.push_back(6.5 + i);
    if (i > 0) edges.push_back({Vertex_index(10 + i), Vertex_index(11 + i)});
  }
  const Complex_with_function c = make(pts.p.size(), edges, {}, f);
  const Reeb_graph R = reeb_graph_of(c);
  ASSERT_EQ(R.components, 2u);
  // 1.4 is too short; 1.5 reaches vertex 5 (at (5, 0)), an interior vertex of the horizontal arc: it is
  // split.
  EXPECT_EQ(connect_dead_ends(R, c.f, 1.4, pts).connected, 0u);
  const Reeb_dead_end_result joined = connect_dead_ends(R, c.f, 1.5, pts);
  EXPECT_EQ(joined.connected, 1u);
  const Reeb_graph& G = joined.graph;
  EXPECT_EQ(G.components, 1u);
  EXPECT_EQ(G.loops(), 0u);
  std::size_t degree_three = 0;
  std::vector<std::size_t> degree(G.nodes.size(), 0);
  for (const auto& a : G.arcs) {
    ++degree[a.lower];
    ++degree[a.upper];
    EXPECT_LT(a.lower, a.upper);
    for (const Vertex_index v : a.vertices) {
      EXPECT_GE(c.f[v], G.nodes[a.lower].value);
      EXPECT_LE(c.f[v], G.nodes[a.upper].value);
    }
  }
  for (std::size_t i = 0; i < G.nodes.size(); ++i) {
    if (i > 0) {
      EXPECT_LE(G.nodes[i - 1].value, G.nodes[i].value);
    }
    if (degree[i] == 3) {
      ++degree_three;
      EXPECT_EQ(G.nodes[i].vertex, 5u);
    }
  }
  EXPECT_EQ(degree_three, 1u);
  // Arcs in the order of Reeb_graph::arcs: by lower node, then by the (f, index) order of the first vertex
  // each reaches. At the split node (vertex 5) the horizontal arc's first vertex 6 (f 6) comes before the
  // link to the dead end at vertex 11 (f 6.5), although the link's upper node has the smaller index.
  auto first_reached = [&G](const Reeb_graph::Arc& a) {
    return a.vertices.empty() ? G.nodes[a.upper].vertex : a.vertices.front();
  };
  for (std::size_t k = 1; k < G.arcs.size(); ++k) {
    const Vertex_index p = first_reached(G.arcs[k - 1]), q = first_reached(G.arcs[k]);
    EXPECT_LE(std::make_tuple(G.arcs[k - 1].lower, c.f[p], p), std::make_tuple(G.arcs[k].lower, c.f[q], q))
        << k;
  }
  // The dead end of the horizontal path at vertex 0 or 10 has nothing else in reach; the result is the same
  // whatever order the ends come in (deterministic), and simplification accepts it.
  const Reeb_graph S = simplify_by_persistence(G, c.f, 0.5).graph;
  EXPECT_EQ(S.components, 1u);
  EXPECT_THROW(connect_dead_ends(R, c.f, -1, pts), std::invalid_argument);
}

TEST(ConnectDeadEnds, LeavesShortIsolatedSegmentsAlone) {
  // A horizontal path 0..10 and a short vertical segment (vertices 11, 12 at (5, 1.5) and (5, 2.5)): its ends
  // are 1 apart, within the distance 2, so it is a blob rather than a street that stops short, and stays
  // apart. A segment of length 3 (ends 3 apart) is a street end: its lower end connects.
  for (const double length : {1.0, 3.0}) {
    Line pts;
    const Complex_with_function c = street_and_segment(pts, length);
    const Reeb_graph R = reeb_graph_of(c);
    ASSERT_EQ(R.components, 2u);
    const Reeb_dead_end_result joined = connect_dead_ends(R, c.f, 2.0, pts);
    EXPECT_EQ(joined.connected, length < 2 ? 0u : 1u) << length;
    EXPECT_EQ(joined.graph.components, length < 2 ? 2u : 1u) << length;
    // repair_reeb_graph() does not join the segment's two ends either.
    EXPECT_EQ(repair_reeb_graph(R, 2.0, pts).joined, 0u);
  }
}

namespace {
std::string error_of(const std::function<void()>& call) { return test::invalid_argument_message(call); }
}  // namespace

TEST(RepairReebGraph, ADistanceThatIsNotOneIsNamed) {
  // Two segments, four dead ends. A user's distance returning NaN joined nothing and a negative one joined
  // any pair, silently.
  const std::vector<double> f = {0, 1, 3, 4};
  const Reeb_graph R = reeb_graph_of(make(4, {{0, 1}, {2, 3}}, {}, f));
  ASSERT_EQ(R.arcs.size(), 2u);
  for (const double bad : {std::nan(""), -1.0}) {
    auto distance = [bad](Vertex_index a, Vertex_index b) {
      return (a == 1 && b == 2) || (a == 2 && b == 1) ? bad : 20.0;  // the segments' own ends: not joined
    };
    const std::string value = std::isnan(bad) ? "nan" : "-1";
    for (const std::string& e : {error_of([&] { repair_reeb_graph(R, 10.0, distance); }),
                                 error_of([&] { connect_dead_ends(R, f, 10.0, distance); })}) {
      EXPECT_TRUE(contains(e, ": the distance between vertices "));
      EXPECT_TRUE(contains(e, " is " + value + " (the distance callable must return a number >= 0)"));
    }
  }
}

TEST(RepairReebGraph, BadGraphsAreNamedByEveryRepairFunction) {
  // Path 0 - 1 - 2 - 3 (f = x): one arc between nodes 0 and 1; then broken on purpose.
  Line pts;
  std::vector<Edge> edges;
  std::vector<double> f;
  for (int i = 0; i < 4; ++i) {
    pts.p.push_back({double(i), 0.0});
    f.push_back(double(i));
    if (i > 0) edges.push_back({Vertex_index(i - 1), Vertex_index(i)});
  }
  const Reeb_graph R = reeb_graph_of(make(4, edges, {}, f));
  ASSERT_EQ(R.nodes.size(), 2u);
  ASSERT_EQ(R.arcs.size(), 1u);
  auto all = [&](const Reeb_graph& G, const std::vector<double>& values) {
    return std::vector<std::string>{error_of([&] { repair_reeb_graph(G, 1.0, pts); }),
                                    error_of([&] { connect_dead_ends(G, values, 1.0, pts); }),
                                    error_of([&] { prune_reeb_graph_components(G, 1.0); }),
                                    error_of([&] { trim_essential_stubs(G, 1.0); })};
  };
  for (const std::string& e : all(R, f)) EXPECT_EQ(e, "no exception");
  Reeb_graph bad = R;
  bad.arcs[0].upper = 7;  // was a heap overflow in all four
  for (const std::string& e : all(bad, f))
    EXPECT_TRUE(contains(e, "arc 0 joins nodes 0 and 7: it must go up between nodes in [0, 2)"));
  bad = R;
  std::swap(bad.arcs[0].lower, bad.arcs[0].upper);
  for (const std::string& e : all(bad, f)) EXPECT_TRUE(contains(e, "arc 0 joins nodes 1 and 0"));
  bad = R;
  bad.nodes[1].value = std::nan("");
  for (const std::string& e : all(bad, f)) EXPECT_TRUE(contains(e, "node 1 has value nan"));
  bad = R;
  std::swap(bad.nodes[0], bad.nodes[1]);
  for (const std::string& e : all(bad, f))
    EXPECT_TRUE(contains(e, "nodes 0 and 1 are not in increasing (value, vertex) order"));
  bad = R;
  bad.arcs[0].vertices.push_back(9);  // connect_dead_ends reads the values of the vertices it splits at
  EXPECT_TRUE(contains(error_of([&] { connect_dead_ends(bad, f, 1.0, pts); }),
                       "arc 0 has vertex 9 out of range [0, 4)"));
  // An arc vertex of value NaN would become a node of value NaN (out of order) where a dead end joins it.
  std::vector<double> nan_at_1 = f;
  nan_at_1[1] = std::nan("");
  EXPECT_TRUE(contains(error_of([&] { connect_dead_ends(R, nan_at_1, 1.0, pts); }),
                       "arc 0 has vertex 1 of value nan"));
}

namespace {
/// A comb: a street of `length` vertices on the x axis (one arc) and, over every other street vertex, a
/// vertical stub from y = 0.5 (its dead end, 0.5 above the street) to y = 5. f = x + y / 1000 on the street;
/// on the stubs the same (their dead ends come in node order from the bottom of the street up) or its
/// negative (top down).
struct Comb {
  Line pts;
  std::vector<double> f;
  Reeb_graph R;
};
Comb comb(std::size_t length, bool top_down) {
  Comb c;
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < length; ++i) {
    c.pts.p.push_back({double(i), 0.0});
    if (i > 0) edges.push_back({Vertex_index(i - 1), Vertex_index(i)});
  }
  for (std::size_t j = 1; j + 1 < length; j += 2) {
    const Vertex_index a = Vertex_index(c.pts.p.size());
    c.pts.p.push_back({double(j), 0.5});
    c.pts.p.push_back({double(j), 5.0});
    edges.push_back({a, Vertex_index(a + 1)});
  }
  for (std::size_t v = 0; v < c.pts.p.size(); ++v) {
    const double g = c.pts.p[v][0] + 1e-3 * c.pts.p[v][1];
    c.f.push_back(top_down && v >= length ? -g : g);
  }
  c.R = reeb_graph_of(make(c.pts.p.size(), edges, {}, c.f));
  return c;
}
}  // namespace

TEST(ConnectDeadEnds, SplitsMoveTheShorterSideAndKeepNoSpareCapacity) {
  // Every stub splits the street. Each split copied the rest of the street into a new arc and left the old
  // vector's capacity in place: from the bottom up, about length^2 / 8 vertices copied (quadratic time, with
  // the bound too) and a result holding 25 million vertices of capacity for 5000 at length 10000. A split now
  // moves its shorter side (here the one street vertex since the previous stub's split, in either direction),
  // and the result's vectors hold their vertices only. Counts, not times.
  for (const bool top_down : {false, true}) {
    for (const std::size_t length : {std::size_t(2000), std::size_t(20000)}) {
      const Comb c = comb(length, top_down);
      ASSERT_EQ(c.R.arcs.size(), length / 2);
      Reeb_repair_options x;
      x.bound = [&c](Vertex_index v) { return c.pts.p[v][0]; };
      std::size_t moved = 0;
      const Reeb_dead_end_result r =
          skeleton::internal::connect_dead_ends_counting(c.R, c.f, 1.0, c.pts, x, moved);
      EXPECT_EQ(r.connected, length / 2 - 1) << top_down << " " << length;
      EXPECT_LE(moved, length / 2) << top_down << " " << length;
      std::size_t size = 0, capacity = 0;
      for (const auto& a : r.graph.arcs) {
        size += a.vertices.size();
        capacity += a.vertices.capacity();
      }
      EXPECT_EQ(size, length / 2 - 1) << top_down << " " << length;  // the street vertices between the stubs
      EXPECT_LE(capacity, 2 * size) << top_down << " " << length;
      if (length == 2000) {  // the all-pairs search (quadratic by design) gives the same graph
        EXPECT_TRUE(same_graph(connect_dead_ends(c.R, c.f, 1.0, c.pts).graph, r.graph)) << top_down;
        EXPECT_TRUE(same_graph(connect_dead_ends(c.R, c.f, 1.0, c.pts, x).graph, r.graph)) << top_down;
      }
    }
  }
}

TEST(ConnectDeadEnds, ADeadEndNeverClosesItsOwnStreetWhateverTheOrder) {
  // A U-shaped street (one arc): from (-5, 3) right to (10, 3), down to (10, 0) and back left to its dead end
  // u at (0, 0), 3 below its own far part. A stub (5, -1.5) to (5, -8) ends 1.5 below the street's (5, 0): it
  // splits the street there. Only the piece of the street at u was excluded, so u joined (0, 3) across the
  // split, closing a loop of the street itself, when the stub came first in node order (low f) and not when
  // it came after u (high f). Now u's whole input arc is its own street, split or not.
  for (const double stub_f : {0.0, 1000.0}) {
    Line pts;
    std::vector<Edge> edges;
    std::vector<double> f;
    std::vector<std::array<double, 2>> street;
    for (int x = -5; x <= 10; ++x) street.push_back({double(x), 3.0});
    for (int y = 2; y >= 0; --y) street.push_back({10.0, double(y)});
    for (int x = 9; x >= 0; --x) street.push_back({double(x), 0.0});
    for (std::size_t i = 0; i < street.size(); ++i) {
      pts.p.push_back(street[i]);
      f.push_back(100.0 + double(i));  // rising along the street: u, its last vertex, is the maximum
      if (i > 0) edges.push_back({Vertex_index(i - 1), Vertex_index(i)});
    }
    const Vertex_index u = Vertex_index(street.size() - 1), stub = Vertex_index(pts.p.size()), split = u - 5;
    ASSERT_EQ(pts.p[split], (std::array<double, 2>{5.0, 0.0}));
    for (int k = 0; k < 8; ++k) {
      pts.p.push_back({5.0, -1.5 - k});
      f.push_back(stub_f + 7 - k);
      if (k > 0) edges.push_back({Vertex_index(stub + k - 1), Vertex_index(stub + k)});
    }
    const Reeb_graph R = reeb_graph_of(make(pts.p.size(), edges, {}, f));
    ASSERT_EQ(R.arcs.size(), 2u);
    for (const int bounded : {0, 1, 2}) {
      const Reeb_repair_options x = bound_option(pts, bounded);
      const Reeb_dead_end_result r = connect_dead_ends(R, f, 3.5, pts, x);
      EXPECT_EQ(r.connected, 1u) << stub_f << " " << bounded;
      EXPECT_EQ(r.graph.loops(), 0u) << stub_f << " " << bounded;
      for (const auto& a : r.graph.arcs)  // the one link: the stub's end to the street
        if (a.vertices.empty()) {
          const Vertex_index p = r.graph.nodes[a.lower].vertex, q = r.graph.nodes[a.upper].vertex;
          EXPECT_EQ(std::min(p, q), split) << stub_f << " " << bounded;
          EXPECT_EQ(std::max(p, q), stub) << stub_f << " " << bounded;
        }
    }
  }
}

TEST(RepairReebGraph, ANaNBoundIsNamedNotSorted) {
  // std::sort needs an order and the window a difference: a bound that is NaN or infinite somewhere (either
  // bound) throws, naming the bound and the vertex. repair_reeb_graph() reads the bounds at the dead ends
  // only, connect_dead_ends() at every vertex.
  Line pts;
  const Complex_with_function c = street_and_segment(pts, 3.0);
  const Reeb_graph R = reeb_graph_of(c);
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {std::nan(""), inf, -inf})
    for (const bool second : {false, true})
      for (const Vertex_index bad_at : {Vertex_index(5), Vertex_index(11)}) {
        Reeb_repair_options x;
        auto coordinate = [&pts, bad_at, bad](std::size_t axis) -> std::function<double(std::uint32_t)> {
          return [&pts, bad_at, bad, axis](Vertex_index v) { return v == bad_at ? bad : pts.p[v][axis]; };
        };
        x.bound = coordinate(0);
        if (second) {
          x.bound = [&pts](Vertex_index v) { return pts.p[v][0]; };
          x.second_bound = coordinate(1);
        }
        const std::string named = std::string("Reeb_repair_options::") + (second ? "second_bound" : "bound") +
                                  " of vertex " + std::to_string(bad_at) + " is " +
                                  (bad == inf    ? "inf"
                                   : bad == -inf ? "-inf"
                                                 : "nan");
        EXPECT_EQ(error_of([&] { connect_dead_ends(R, c.f, 2.0, pts, x); }),
                  "connect_dead_ends: " + named + " (a finite number needed)");
        if (bad_at == 11) {
          EXPECT_EQ(error_of([&] { repair_reeb_graph(R, 2.0, pts, x); }),
                    "repair_reeb_graph: " + named + " (a finite number needed)");
        } else {
          EXPECT_EQ(error_of([&] { repair_reeb_graph(R, 2.0, pts, x); }), "no exception");  // inside an arc
        }
      }
}

TEST(RepairReebGraph, ASecondBoundWithoutTheFirstIsRefused) {
  Line pts;
  const Complex_with_function c = street_and_segment(pts, 3.0);
  const Reeb_graph R = reeb_graph_of(c);
  Reeb_repair_options x;
  x.second_bound = [&pts](Vertex_index v) { return pts.p[v][1]; };
  const std::string why =
      "Reeb_repair_options::second_bound is set without bound (the first bound is needed)";
  EXPECT_EQ(error_of([&] { repair_reeb_graph(R, 2.0, pts, x); }), "repair_reeb_graph: " + why);
  EXPECT_EQ(error_of([&] { connect_dead_ends(R, c.f, 2.0, pts, x); }), "connect_dead_ends: " + why);
}

namespace {
/// 60 random dashes of 5 points in the plane (many dead ends, gaps of every size; on the integer lattice for
/// even seeds, so that distances tie).
Point_matrix random_dashes(std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 60);
  Point_matrix m;
  m.dimension = 2;
  for (int dash = 0; dash < 60; ++dash) {
    double x = u(rng), y = u(rng);
    const double a = u(rng), c = std::cos(a), s = std::sin(a);
    if (seed % 2 == 0) x = std::round(x), y = std::round(y);
    for (int k = 0; k < 5; ++k) m.data.insert(m.data.end(), {x + 0.8 * k * c, y + 0.8 * k * s});
  }
  m.rows = m.data.size() / 2;
  return m;
}
}  // namespace

TEST(RepairReebGraph, ABoundMeasuresFewerPairsWithTheSameResult) {
  // Random dashes in the plane (ties on a lattice in half the runs): repair and dead-end connection with the
  // x coordinate as a 1-Lipschitz bound, and with y as a second one, give exactly the graphs of the all-pairs
  // search, and measure far fewer pairs (two bounds fewer than one).
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const Point_matrix m = random_dashes(seed);
    const Proximity_graph g = build_rips_graph(m, 1.0);
    const Simplicial_complex_2 K = build_flag_complex_2(g);
    const Geodesic_result geo = compute_geodesic_function(K);
    const Reeb_graph R = simplify_by_persistence(compute_augmented_reeb_graph(K, geo.values), 0.5).graph;
    std::size_t all_pairs = 0, bounded_pairs = 0;
    auto distance = [&m](std::size_t* count) {
      return [&m, count](Vertex_index a, Vertex_index b) {
        ++*count;
        return std::hypot(m.row(a)[0] - m.row(b)[0], m.row(a)[1] - m.row(b)[1]);
      };
    };
    Reeb_repair_options x;
    x.bound = [&m](Vertex_index v) { return m.row(v)[0]; };
    Reeb_repair_options xy = x;
    xy.second_bound = [&m](Vertex_index v) { return m.row(v)[1]; };
    std::size_t grid_pairs = 0;
    for (const double reach : {1.5, 4.0, 10.0}) {
      const Reeb_repair_result plain = repair_reeb_graph(R, reach, distance(&all_pairs));
      const Reeb_repair_result fast = repair_reeb_graph(R, reach, distance(&bounded_pairs), x);
      EXPECT_EQ(plain.joined, fast.joined) << "seed " << seed << ", reach " << reach;
      EXPECT_TRUE(same_graph(plain.graph, fast.graph)) << "seed " << seed << ", reach " << reach;
      const Reeb_dead_end_result ends =
          connect_dead_ends(plain.graph, geo.values, reach, distance(&all_pairs));
      const Reeb_dead_end_result quick =
          connect_dead_ends(plain.graph, geo.values, reach, distance(&bounded_pairs), x);
      EXPECT_GT(ends.connected, 0u) << "seed " << seed << ", reach " << reach;
      EXPECT_EQ(ends.connected, quick.connected) << "seed " << seed << ", reach " << reach;
      EXPECT_TRUE(same_graph(ends.graph, quick.graph)) << "seed " << seed << ", reach " << reach;
      const Reeb_repair_result grid = repair_reeb_graph(R, reach, distance(&grid_pairs), xy);
      EXPECT_EQ(plain.joined, grid.joined) << "seed " << seed << ", reach " << reach;
      EXPECT_TRUE(same_graph(plain.graph, grid.graph)) << "seed " << seed << ", reach " << reach;
      const Reeb_dead_end_result cells =
          connect_dead_ends(plain.graph, geo.values, reach, distance(&grid_pairs), xy);
      EXPECT_EQ(ends.connected, cells.connected) << "seed " << seed << ", reach " << reach;
      EXPECT_TRUE(same_graph(ends.graph, cells.graph)) << "seed " << seed << ", reach " << reach;
    }
    EXPECT_LT(3 * bounded_pairs, all_pairs) << "seed " << seed;
    EXPECT_LT(grid_pairs, bounded_pairs) << "seed " << seed;
  }
}

TEST(RepairReebGraph, TheBoundIndexVisitsExactlyTheSlotsWithinTheWindow) {
  // Slots on a line with far outliers (up to 1e19, 1e300) and ties, at windows from the smallest subnormal to
  // 10: visit() returns exactly the slots whose bounds both differ by at most the window, for_each_pair()
  // exactly the pairs, each once (brute force). The columns stay at most a window wide: a column number
  // floor((x - least) / window) capped at 2^62 put every slot past an outlier, or every slot at a subnormal
  // window, into one column, which made each query a strip of the second bound.
  using skeleton::internal::Bound_index;
  using skeleton::internal::Bounded_slot;
  std::mt19937_64 rng(65);
  for (const double window : {std::numeric_limits<double>::denorm_min(), 1e-300, 0.5, 1.0, 10.0})
    for (const bool two : {false, true}) {
      std::vector<Bounded_slot> slots;
      for (std::size_t i = 0; i < 300; ++i) {
        const double x = double(rng() % 200) * 0.5, y = two ? double(rng() % 5) : x;
        slots.push_back({x, y, i});
      }
      for (const double far : {-1e19, 1e300}) slots.push_back({far, two ? 0.0 : far, slots.size()});
      const Bound_index index(slots, window, two);
      std::vector<double> xs;
      for (const Bounded_slot& t : slots) xs.push_back(t.first);
      std::sort(xs.begin(), xs.end());
      const auto distinct = static_cast<double>(std::unique(xs.begin(), xs.end()) - xs.begin());
      if (two) {  // distinct x 0.5 apart: a run of width w holds at most 2w + 1 of them
        EXPECT_GE(double(index.number_of_columns()), window < 0.5 ? distinct : distinct / (2 * window + 1))
            << window;
      } else {
        EXPECT_EQ(index.number_of_columns(), 1u);
      }
      auto near = [&](const Bounded_slot& a, const Bounded_slot& b) {
        return std::abs(a.first - b.first) <= window && std::abs(a.second - b.second) <= window;
      };
      std::vector<std::pair<std::size_t, std::size_t>> pairs, expected_pairs;
      for (const Bounded_slot& q : slots) {
        std::vector<std::size_t> seen, expected;
        index.visit(q.first, q.second, [&](std::size_t s) { seen.push_back(s); });
        for (const Bounded_slot& t : slots)
          if (near(q, t)) expected.push_back(t.slot);
        std::sort(seen.begin(), seen.end());
        EXPECT_EQ(seen, expected) << window << " " << two << " " << q.slot;
        for (const std::size_t t : expected)
          if (q.slot < t) expected_pairs.emplace_back(q.slot, t);
      }
      std::size_t afters = 0;
      EXPECT_TRUE(index.for_each_pair(
          [&](std::size_t a, std::size_t b) { pairs.emplace_back(std::min(a, b), std::max(a, b)); },
          [&](std::size_t k) { return ++afters, k + 1 > slots.size(); }));
      EXPECT_EQ(afters, slots.size());
      std::sort(pairs.begin(), pairs.end());
      std::sort(expected_pairs.begin(), expected_pairs.end());
      EXPECT_EQ(pairs, expected_pairs) << window << " " << two;
    }
}

TEST(ConnectDeadEnds, TwoBoundsMeasureAFewCandidatesPerEndOnAPlane) {
  // k x k horizontal dashes of 3 points, 4 apart: no two within the distance 1, nothing is joined. With the x
  // coordinate as the only bound, a dead end measures the strip of its x: the 2 points of each dash of its
  // column that lie within 1 (about 2k); with y as the second bound too, only its own cell, where its own
  // dash is excluded: the one distance to its dash's other end (the isolated-segment check), whatever k.
  // repair_reeb_graph() measures the dead ends of the other rows with one bound and none with two.
  for (const int k : {10, 20, 40}) {
    Planar_points pts;
    std::vector<Edge> edges;
    std::vector<double> f;
    for (int row = 0; row < k; ++row)
      for (int column = 0; column < k; ++column)
        for (int i = 0; i < 3; ++i) {
          pts.p.push_back({4.0 * column + i, 4.0 * row});
          f.push_back(4.0 * column + i + 1e-3 * row);
          if (i > 0) edges.push_back({Vertex_index(pts.p.size() - 2), Vertex_index(pts.p.size() - 1)});
        }
    const Complex_with_function c = make(pts.p.size(), edges, {}, f);
    const Reeb_graph R = reeb_graph_of(c);
    const std::size_t ends = 2 * std::size_t(k) * std::size_t(k);
    ASSERT_EQ(R.arcs.size(), ends / 2);
    std::size_t strip = 0, cells = 0, strip_pairs = 0, cell_pairs = 0;
    auto counting = [&pts](std::size_t& count) {
      return [&pts, &count](Vertex_index a, Vertex_index b) {
        ++count;
        return pts(a, b);
      };
    };
    const Reeb_dead_end_result one = connect_dead_ends(R, c.f, 1.0, counting(strip), bound_option(pts, 1));
    const Reeb_dead_end_result two = connect_dead_ends(R, c.f, 1.0, counting(cells), bound_option(pts, 2));
    EXPECT_EQ(one.connected, 0u) << k;
    EXPECT_TRUE(same_graph(one.graph, two.graph)) << k;
    EXPECT_EQ(cells, ends) << k;
    EXPECT_EQ(strip, ends + ends * (2 * std::size_t(k) - 2)) << k;
    EXPECT_EQ(repair_reeb_graph(R, 1.0, counting(strip_pairs), bound_option(pts, 1)).joined, 0u) << k;
    EXPECT_EQ(repair_reeb_graph(R, 1.0, counting(cell_pairs), bound_option(pts, 2)).joined, 0u) << k;
    EXPECT_EQ(strip_pairs, ends * (std::size_t(k) - 1) / 2) << k;
    EXPECT_EQ(cell_pairs, 0u) << k;
  }
}

TEST(RepairReebGraph, ProgressIsReportedAndAStopLeavesAValidGraph) {
  // Both repair functions report increasing fractions ending at 1 and return what they return unwatched; a
  // stop adds no arc in repair_reeb_graph() (the graph is the input) and keeps the dead ends connected before
  // it in connect_dead_ends(): a valid graph that simplifies, with fewer arcs added the earlier the stop.
  const Point_matrix m = random_dashes(3);
  const Simplicial_complex_2 K = build_flag_complex_2(build_rips_graph(m, 1.0));
  const Geodesic_result geo = compute_geodesic_function(K);
  const Reeb_graph R = simplify_by_persistence(compute_augmented_reeb_graph(K, geo.values), 0.5).graph;
  auto distance = [&m](Vertex_index a, Vertex_index b) {
    return std::hypot(m.row(a)[0] - m.row(b)[0], m.row(a)[1] - m.row(b)[1]);
  };
  const Reeb_repair_result plain = repair_reeb_graph(R, 4.0, distance);
  const Reeb_dead_end_result ends = connect_dead_ends(R, geo.values, 4.0, distance);
  ASSERT_GT(plain.joined, 2u);
  ASSERT_GT(ends.connected, 2u);
  for (const int bounded : {0, 1, 2}) {
    Reeb_repair_options options;
    if (bounded >= 1) options.bound = [&m](Vertex_index v) { return m.row(v)[1]; };
    if (bounded == 2) options.second_bound = [&m](Vertex_index v) { return m.row(v)[0]; };
    std::vector<double> seen;
    options.progress = test::recording_progress(seen);
    const Reeb_repair_result watched = repair_reeb_graph(R, 4.0, distance, options);
    EXPECT_EQ(watched.status, Status::success);
    EXPECT_TRUE(same_graph(watched.graph, plain.graph)) << bounded;
    ASSERT_GT(seen.size(), 2u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << bounded;
    EXPECT_EQ(seen.back(), 1.0) << bounded;
    seen.clear();
    const Reeb_dead_end_result connected = connect_dead_ends(R, geo.values, 4.0, distance, options);
    EXPECT_EQ(connected.status, Status::success);
    EXPECT_TRUE(same_graph(connected.graph, ends.graph)) << bounded;
    ASSERT_GT(seen.size(), 2u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << bounded;
    EXPECT_EQ(seen.back(), 1.0) << bounded;
    const std::size_t calls = seen.size();

    options.progress = [](double) { return false; };
    const Reeb_repair_result stopped = repair_reeb_graph(R, 4.0, distance, options);
    EXPECT_EQ(stopped.status, Status::interrupted);
    EXPECT_EQ(stopped.joined, 0u);
    EXPECT_TRUE(same_graph(stopped.graph, R)) << bounded;
    std::size_t previous = 0;
    for (std::size_t allowed = 0; allowed < calls; ++allowed) {
      std::size_t asked = 0;
      options.progress = [&asked, allowed](double) { return asked++ < allowed; };
      const Reeb_dead_end_result partial = connect_dead_ends(R, geo.values, 4.0, distance, options);
      EXPECT_EQ(partial.status, allowed + 1 < calls ? Status::interrupted : Status::success) << allowed;
      EXPECT_EQ(asked, allowed + 1) << "asked again after the stop, " << allowed;
      EXPECT_GE(partial.connected, previous) << allowed;
      EXPECT_LE(partial.connected, ends.connected) << allowed;
      previous = partial.connected;
      EXPECT_NO_THROW(skeleton::internal::check_reeb_graph(partial.graph, "partial", &geo.values)) << allowed;
      EXPECT_TRUE(std::is_sorted(
          partial.graph.arcs.begin(), partial.graph.arcs.end(),
          [](const Reeb_graph::Arc& a, const Reeb_graph::Arc& b) { return a.lower < b.lower; }))
          << allowed;
      EXPECT_NO_THROW(simplify_by_persistence(partial.graph, geo.values, 0.5)) << allowed;
    }
    EXPECT_EQ(previous, ends.connected);
  }
}

namespace {
/// A Reeb graph built by hand: nodes (vertex, value) in the given order, arcs (lower, upper, vertices); types
/// and components as the repair functions compute them.
Reeb_graph hand_graph(const std::vector<std::pair<Vertex_index, double>>& nodes,
                      const std::vector<Reeb_graph::Arc>& arcs) {
  Reeb_graph R;
  for (const auto& [v, f] : nodes) {
    Reeb_graph::Node n;
    n.vertex = v;
    n.value = f;
    R.nodes.push_back(n);
  }
  R.arcs = arcs;
  FeatureRecon::skeleton::internal::refresh_node_types(R);
  return R;
}
/// The input vertices of the ends of the arcs of G without interior vertices, sorted.
std::vector<std::pair<Vertex_index, Vertex_index>> bare_arcs(const Reeb_graph& G) {
  std::vector<std::pair<Vertex_index, Vertex_index>> out;
  for (const auto& a : G.arcs)
    if (a.vertices.empty()) {
      const Vertex_index p = G.nodes[a.lower].vertex, q = G.nodes[a.upper].vertex;
      out.emplace_back(std::min(p, q), std::max(p, q));
    }
  std::sort(out.begin(), out.end());
  return out;
}
/// The links added to R (arcs without interior vertices): G's bare arcs less R's, by their ends' vertices.
std::vector<std::pair<Vertex_index, Vertex_index>> links_added(const Reeb_graph& G, const Reeb_graph& R) {
  const auto g = bare_arcs(G), r = bare_arcs(R);
  std::vector<std::pair<Vertex_index, Vertex_index>> out;
  std::set_difference(g.begin(), g.end(), r.begin(), r.end(), std::back_inserter(out));
  return out;
}
}  // namespace

TEST(RepairReebGraph, RepeatedNodesAndArcsFromANodeToItselfAreRefused) {
  // Node values in strictly increasing (value, vertex) order and arcs going up (lower < upper): a node
  // repeated and an arc from a node to itself are refused like the other bad graphs.
  const Reeb_graph R = hand_graph({{0, 0.0}, {1, 1.0}}, {{0, 1, {}}});
  const std::vector<double> f{0.0, 1.0};
  const Planar_points pts{{{0.0, 0.0}, {1.0, 0.0}}};
  auto all = [&](const Reeb_graph& G) {
    return std::vector<std::string>{error_of([&] { repair_reeb_graph(G, 1.0, pts); }),
                                    error_of([&] { connect_dead_ends(G, f, 1.0, pts); }),
                                    error_of([&] { prune_reeb_graph_components(G, 1.0); }),
                                    error_of([&] { trim_essential_stubs(G, 1.0); })};
  };
  Reeb_graph repeated = R;
  repeated.nodes[1] = repeated.nodes[0];
  repeated.arcs.clear();
  for (const std::string& e : all(repeated))
    EXPECT_TRUE(contains(e, "nodes 0 and 1 are not in increasing (value, vertex) order"));
  Reeb_graph loop = R;
  loop.arcs[0].lower = 1;
  for (const std::string& e : all(loop)) EXPECT_TRUE(contains(e, "arc 0 joins nodes 1 and 1: it must go up"));
}

TEST(RepairReebGraph, EndsAtOnePointAreJoinedAtDistanceZero) {
  // Two segments along x whose facing dead ends (vertices 1 and 2) are two input points at one place: a
  // distance of 0 is a distance (>= 0), within max_distance 0.
  const Planar_points pts{{{0.0, 0.0}, {5.0, 0.0}, {5.0, 0.0}, {10.0, 0.0}}};
  const std::vector<double> f{0.0, 5.0, 5.5, 10.0};
  const Reeb_graph R = hand_graph({{0, 0.0}, {1, 5.0}, {2, 5.5}, {3, 10.0}}, {{0, 1, {}}, {2, 3, {}}});
  const Reeb_repair_result fixed = repair_reeb_graph(R, 0.0, pts);
  EXPECT_EQ(fixed.joined, 1u);
  EXPECT_EQ(fixed.graph.components, 1u);
  const Reeb_dead_end_result ends = connect_dead_ends(R, f, 0.0, pts);
  EXPECT_EQ(ends.connected, 1u);
  EXPECT_EQ(links_added(ends.graph, R), (std::vector<std::pair<Vertex_index, Vertex_index>>{{1, 2}}));
}

TEST(RepairReebGraph, ABoundThatRoundsUpFindsThePairsAtTheDistance) {
  // The bound x + 1000 is 1-Lipschitz, but its differences round: the dead ends 1 and 2 are exactly 1.3 apart
  // (the repair distance) and their bounds 1.3000000000000682. The bounded search gives the result of the
  // all-pairs search (the window has room for rounding).
  const double xa = 0.1 * 3, xb = xa + 1.3;
  const Planar_points pts{{{-10.0, 0.0}, {xa, 0.0}, {xb, 0.0}, {20.0, 0.0}}};
  const double reach = pts(1, 2);
  ASSERT_GT((xb + 1000.0) - (xa + 1000.0), reach);
  const std::vector<double> f{-10.0, xa, xb, 20.0};
  const Reeb_graph R = hand_graph({{0, -10.0}, {1, xa}, {2, xb}, {3, 20.0}}, {{0, 1, {}}, {2, 3, {}}});
  Reeb_repair_options x;
  x.bound = [&pts](Vertex_index v) { return pts.p[v][0] + 1000.0; };
  EXPECT_EQ(repair_reeb_graph(R, reach, pts).joined, 1u);
  EXPECT_EQ(repair_reeb_graph(R, reach, pts, x).joined, 1u);
  EXPECT_EQ(connect_dead_ends(R, f, reach, pts).connected, 1u);
  EXPECT_EQ(connect_dead_ends(R, f, reach, pts, x).connected, 1u);
}

TEST(ConnectDeadEnds, ADeadEndThatWasConnectedToIsNoLongerADeadEnd) {
  // Two streets end facing each other 1 apart (vertices 1 and 2). The first dead end in node order (1)
  // connects to the node 2, which then has two arcs: it is no dead end any more and adds nothing (a second
  // link 2-1 made a loop of two arcs).
  const Planar_points pts{{{-10.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {10.0, 0.0}}};
  const std::vector<double> f{-10.0, 0.0, 1.0, 10.0};
  const Reeb_graph R = hand_graph({{0, -10.0}, {1, 0.0}, {2, 1.0}, {3, 10.0}}, {{0, 1, {}}, {2, 3, {}}});
  for (const int bounded : {0, 1, 2}) {
    const Reeb_repair_options x = bound_option(pts, bounded);
    const Reeb_dead_end_result r = connect_dead_ends(R, f, 1.5, pts, x);
    EXPECT_EQ(r.connected, 1u) << bounded;
    EXPECT_EQ(r.graph.loops(), 0u) << bounded;
    EXPECT_EQ(links_added(r.graph, R), (std::vector<std::pair<Vertex_index, Vertex_index>>{{1, 2}}))
        << bounded;
  }
}

TEST(ConnectDeadEnds, AnIsolatedSegmentExactlyMaxDistanceLongStays) {
  // The street 0..10 and a vertical segment from (5, 1.5) to (5, 3.5): its ends are exactly 2 apart, within
  // the distance 2 (inclusive), so it stays apart although its lower end is 1.5 from the street.
  Line pts;
  const Complex_with_function c = street_and_segment(pts, 2.0);
  const Reeb_graph R = reeb_graph_of(c);
  ASSERT_EQ(pts(11, 12), 2.0);
  EXPECT_EQ(connect_dead_ends(R, c.f, 2.0, pts).connected, 0u);
  EXPECT_EQ(connect_dead_ends(R, c.f, 1.9, pts).connected, 1u);  // its ends now too far apart: a street end
}

TEST(ConnectDeadEnds, ADeadEndNeverJoinsTheFarEndOfItsOwnArc) {
  // A minimum F (vertex 0 at the origin) with two arcs: one curls out along x and back up to its dead end u
  // (vertex 8 at (0, 1)), 1 above F; the other runs left to the dead end w (vertex 11 at (-4, 0)). F is the
  // other end of u's own arc: not another part of the graph, so u stays as it is (nothing else in reach).
  const Planar_points pts{{{0.0, 0.0},
                           {1.0, 0.0},
                           {2.0, 0.0},
                           {3.0, 0.0},
                           {3.0, 1.0},
                           {3.0, 2.0},
                           {2.0, 2.0},
                           {1.0, 2.0},
                           {0.0, 1.0},
                           {-2.0, 0.0},
                           {-3.0, 0.0},
                           {-4.0, 0.0}}};
  const std::vector<double> f{0, 1, 2, 3, 4, 5, 6, 7, 8, 1.5, 2.5, 3.5};
  const Reeb_graph R =
      hand_graph({{0, 0.0}, {11, 3.5}, {8, 8.0}}, {{0, 2, {1, 2, 3, 4, 5, 6, 7}}, {0, 1, {9, 10}}});
  for (const int bounded : {0, 1, 2}) {
    const Reeb_repair_options x = bound_option(pts, bounded, 1);
    const Reeb_dead_end_result r = connect_dead_ends(R, f, 1.2, pts, x);
    EXPECT_EQ(r.connected, 0u) << bounded;
    EXPECT_EQ(r.graph.loops(), 0u) << bounded;
  }
}

TEST(PruneReebGraphComponents, ReportsMembersAndArcVerticesSorted) {
  // A low component (nodes of vertices 7 and 2, members 9 and 3, arc vertices 8 and 1) and a tall one: the
  // removed vertices are every input vertex of the low one, sorted.
  Reeb_graph R = hand_graph({{7, 0.0}, {2, 0.5}, {0, 10.0}, {4, 20.0}}, {{0, 1, {8, 1}}, {2, 3, {5}}});
  R.nodes[0].members = {9, 3};
  const Reeb_prune_result p = prune_reeb_graph_components(R, 1.0);
  EXPECT_EQ(p.removed_components, 1u);
  EXPECT_EQ(p.removed_vertices, (std::vector<Vertex_index>{1, 2, 3, 7, 8, 9}));
  ASSERT_EQ(p.graph.nodes.size(), 2u);
  ASSERT_EQ(p.graph.arcs.size(), 1u);
  EXPECT_EQ(p.graph.arcs[0].vertices, (std::vector<Vertex_index>{5}));
}

TEST(RepairReebGraph, NodeComponentsAreNamedByTheirSmallestNode) {
  // The component of each node is the smallest node index in it, whatever the order of the arcs.
  const Reeb_graph R =
      hand_graph({{0, 0.0}, {1, 1.0}, {2, 2.0}, {3, 3.0}, {4, 4.0}}, {{2, 3, {}}, {1, 3, {}}, {0, 4, {}}});
  EXPECT_EQ(FeatureRecon::skeleton::internal::node_components(R), (std::vector<std::size_t>{0, 1, 1, 1, 0}));
}

TEST(RepairReebGraph, EachEndIsJoinedAtMostOnce) {
  // The ends a (vertex 1 at (0, 0)) and b (vertex 2 at (1, 0)) of two streets join first (1 apart); the end c
  // (vertex 4 at (1, 1.2)) of a third street is 1.2 from b, which is taken: c stays free.
  const Planar_points pts{{{-20.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {20.0, 0.0}, {1.0, 1.2}, {1.0, 10.0}}};
  const Reeb_graph R = hand_graph({{0, -20.0}, {1, 0.0}, {4, 0.5}, {2, 1.0}, {5, 10.0}, {3, 20.0}},
                                  {{0, 1, {}}, {2, 4, {}}, {3, 5, {}}});
  for (const int bounded : {0, 1, 2}) {
    const Reeb_repair_options x = bound_option(pts, bounded);
    const Reeb_repair_result fixed = repair_reeb_graph(R, 1.3, pts, x);
    EXPECT_EQ(fixed.joined, 1u) << bounded;
    EXPECT_EQ(links_added(fixed.graph, R), (std::vector<std::pair<Vertex_index, Vertex_index>>{{1, 2}}))
        << bounded;
  }
}

TEST(RepairReebGraph, ProgressIsAskedAfterEachEndIsMeasured) {
  // Six dead ends: six reports after work was done (fractions above 0, increasing), then 1.
  const Planar_points pts{{{-20.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {20.0, 0.0}, {1.0, 1.2}, {1.0, 10.0}}};
  const Reeb_graph R = hand_graph({{0, -20.0}, {1, 0.0}, {4, 0.5}, {2, 1.0}, {5, 10.0}, {3, 20.0}},
                                  {{0, 1, {}}, {2, 4, {}}, {3, 5, {}}});
  std::vector<double> seen;
  Reeb_repair_options x;
  x.progress = test::recording_progress(seen);
  EXPECT_EQ(repair_reeb_graph(R, 1.3, pts, x).joined, 1u);
  ASSERT_EQ(seen.size(), 7u);
  EXPECT_GT(seen.front(), 0.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LT(seen[i - 1], seen[i]) << i;
  EXPECT_EQ(seen.back(), 1.0);
}

TEST(ConnectDeadEnds, ASegmentSplitByAnEarlierDeadEndIsNoLongerIsolated) {
  // A segment from s (vertex 0 at the origin) to u (vertex 5 at (2, 0)): its ends lie within the distance
  // 2.2 of each other. The dead end w of a stub (vertex 6 at (1.9, -1.2)) comes first in node order and
  // splits it at (1.9, 0) (u's side moves into a new arc). u's arc now leads to a fork, not to a dead end: u
  // sees the link added before it and joins w, 1.2 away. (The piece 4-5 of the street, split, has no vertices
  // left.)
  Planar_points pts{{{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0}, {1.5, 0.0}, {1.9, 0.0}, {2.0, 0.0}}};
  std::vector<double> f{0.0, 0.5, 1.0, 1.5, 1.9, 2.0};
  for (int k = 0; k < 5; ++k) {
    pts.p.push_back({1.9, -1.2 - k});
    f.push_back(-10.0 + k);
  }
  const Reeb_graph R =
      hand_graph({{6, -10.0}, {10, -6.0}, {0, 0.0}, {5, 2.0}}, {{0, 1, {7, 8, 9}}, {2, 3, {1, 2, 3, 4}}});
  for (const int bounded : {0, 1, 2}) {
    const Reeb_repair_options x = bound_option(pts, bounded);
    const Reeb_dead_end_result r = connect_dead_ends(R, f, 2.2, pts, x);
    EXPECT_EQ(r.connected, 2u) << bounded;
    EXPECT_EQ(links_added(r.graph, R),
              (std::vector<std::pair<Vertex_index, Vertex_index>>{{4, 5}, {4, 6}, {5, 6}}))
        << bounded;
  }
}

TEST(RepairReebGraph, EqualDistancesGoToThePairOfSmallerNodes) {
  // The end b (vertex 2 at (1, 0)) lies exactly 1 from the ends a (vertex 1 at (0, 0)) and c (vertex 4 at
  // (2, 0)) of two other streets; a and c are 2 apart. The documented tie rule: of pairs at equal distance
  // the one of smaller node indices (lexicographically) joins first, so the node order (by value) decides
  // whether b joins a or c.
  const Planar_points pts{{{-20.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {1.0, 20.0}, {2.0, 0.0}, {22.0, 0.0}}};
  // a below c: nodes v0, a, b, c, v3, v5.
  const Reeb_graph a_first = hand_graph({{0, -20.0}, {1, 0.0}, {2, 1.0}, {4, 2.0}, {3, 20.0}, {5, 22.0}},
                                        {{0, 1, {}}, {2, 4, {}}, {3, 5, {}}});
  // c below a: nodes v0, c, b, a, v3, v5.
  const Reeb_graph c_first = hand_graph({{0, -20.0}, {4, 0.0}, {2, 1.0}, {1, 2.0}, {3, 20.0}, {5, 22.0}},
                                        {{0, 3, {}}, {2, 4, {}}, {1, 5, {}}});
  for (const int bounded : {0, 1, 2}) {
    const Reeb_repair_options x = bound_option(pts, bounded);
    const Reeb_repair_result one = repair_reeb_graph(a_first, 1.5, pts, x);
    const Reeb_repair_result two = repair_reeb_graph(c_first, 1.5, pts, x);
    EXPECT_EQ(one.joined, 1u) << bounded;
    EXPECT_EQ(two.joined, 1u) << bounded;
    EXPECT_EQ(links_added(one.graph, a_first), (std::vector<std::pair<Vertex_index, Vertex_index>>{{1, 2}}))
        << bounded;
    EXPECT_EQ(links_added(two.graph, c_first), (std::vector<std::pair<Vertex_index, Vertex_index>>{{2, 4}}))
        << bounded;
  }
}
