// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H
#define FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/internal/random.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Options of embed_reeb_graph().
struct Embedding_options {
  /// Width of the function-value bins that cut an arc's points into level-set pieces (same unit as f; > 0,
  /// infinity: one piece per arc). Automatic (default): 1/64 of the range of f over the graph
  /// (extract_reeb_skeleton(): the median edge length of the complex). 0 or negative: refused (before
  /// FeatureRecon::automatic, 0 asked for the automatic width).
  std::optional<double> level_width = FeatureRecon::automatic;
  /// How a polyline is smoothed (endpoints fixed). Taubin (default): each round moves every interior point
  /// towards the mean of its two neighbours by smoothing_weight (lambda), then away from it by mu = 1 / (0.1
  /// - 1 / lambda) (the pass band of Taubin's lambda|mu filter at 0.1): the jitter of level-set centroids
  /// goes, the shape stays. Laplacian: the first step only; it also shrinks, pulling a coarse arc onto the
  /// chord between its ends (a loop of 8 vertices on a circle keeps 0.21 of its half-width after 10 Laplacian
  /// rounds, 0.86 after 10 Taubin rounds). Taubin's filter gains slightly below its pass band (up to about
  /// 1 + 0.026 k per round at frequency k < 0.1 with the default lambda): tens of rounds are what it is for;
  /// thousands let the slowest bends of a long polyline grow without bound (100,000 rounds: coordinates near
  /// 1e26), so heavy smoothing should be Laplacian.
  enum class Smoothing {
    taubin,    ///< lambda step, then mu step (no shrinking)
    laplacian  ///< lambda step only (shrinks)
  };
  Smoothing smoothing = Smoothing::taubin;  ///< how the polylines are smoothed; default Taubin
  std::size_t smoothing_iterations = 10;    ///< smoothing rounds of each polyline; default 10
  /// Move towards the neighbours' mean per round: in [0, 1] for Laplacian rounds, [0, 2/3] for Taubin rounds
  /// (above, the inflating step makes the zigzag of a polyline grow); default 0.5.
  double smoothing_weight = 0.5;
  /// With a graph: where two consecutive points of a polyline lie farther apart than this (distance in the
  /// embedding space), the polyline follows the graph's shortest path between their input points (a node's
  /// vertex; the point of a level-set piece closest to its centroid), each path vertex drawn at the mean of
  /// itself and its graph neighbours. Simplification can leave an arc with few or no points of its own
  /// between nodes far apart; it is then drawn through the data instead of straight across. Automatic
  /// (default): twice the median edge length of the graph; 0 (or infinity): off, straight segments. Negative:
  /// refused (before FeatureRecon::automatic, 0 asked for the automatic gap and a negative one turned it
  /// off).
  std::optional<double> max_gap = FeatureRecon::automatic;
  /// Called with the fraction of the work done (an arc of k points counts k + 1 to draw and k + 1 per
  /// smoothing round), every 65,536 units; returning false stops: the arcs not finished yet are straight
  /// segments between their nodes, and the embedding's status is Status::interrupted.
  Progress_callback progress;
};

/// A Reeb graph drawn in space: node positions and one polyline per arc (from its lower to its upper node).
struct Reeb_graph_embedding {
  std::size_t dimension = 0;                          ///< 1, 2 or 3: min(input dimension, 3)
  std::vector<std::array<double, 3>> node_positions;  ///< per node (unused coordinates 0)
  /// per arc, first and last = node positions
  std::vector<std::vector<std::array<double, 3>>> arc_polylines;
  /// Gaps of a polyline wider than this were bridged through the graph (Embedding_options::max_gap, or the
  /// value the automatic setting chose); infinity when nothing was bridged (no graph, or max_gap 0).
  double max_gap = std::numeric_limits<double>::infinity();
  Status status = Status::success;  ///< interrupted when the progress callback stopped the drawing
};

/// Coordinates of the points in at most 3 dimensions: unchanged up to 3D, else the projection onto the three
/// principal axes (PCA with Eigen, centred at the mean). Row-major, 3 columns (zero-padded).
/// \throws std::invalid_argument when the matrix is inconsistent or has a non-finite coordinate.
inline std::vector<std::array<double, 3>> project_to_3d(const Point_matrix& m) {
  internal::check_point_matrix(m, "project_to_3d");
  std::vector<std::array<double, 3>> out(m.rows, {0.0, 0.0, 0.0});
  if (m.dimension <= 3) {
    for (std::size_t i = 0; i < m.rows; ++i)
      for (std::size_t c = 0; c < m.dimension; ++c) out[i][c] = m.row(i)[c];
    return out;
  }
  const Eigen::Index d = static_cast<Eigen::Index>(m.dimension);
  // Coordinates are scaled by a power of two (exact) to a largest magnitude in [0.5, 1): the covariance of
  // coordinates near 1e-170 or 1e200 would underflow or overflow (every projection 0), the mean near the
  // largest doubles too.
  double largest = 0;
  for (const double c : m.data) largest = std::max(largest, std::fabs(c));
  int exponent = 0;
  if (largest > 0) std::frexp(largest, &exponent);
  const Eigen::Map<const Eigen::MatrixXd> X(m.data.data(), d, static_cast<Eigen::Index>(m.rows));
  auto row = [&](std::size_t i) -> Eigen::VectorXd {
    Eigen::VectorXd x = X.col(static_cast<Eigen::Index>(i));
    for (Eigen::Index c = 0; c < d; ++c) x[c] = std::ldexp(x[c], -exponent);
    return x;
  };
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  for (std::size_t i = 0; i < m.rows; ++i) mean += row(i);
  if (m.rows > 0) mean /= static_cast<double>(m.rows);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < m.rows; ++i) {
    const Eigen::VectorXd x = row(i) - mean;
    cov.noalias() += x * x.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);  // ascending eigenvalues
  for (std::size_t i = 0; i < m.rows; ++i) {
    const Eigen::VectorXd x = row(i) - mean;
    for (int c = 0; c < 3; ++c) {
      Eigen::VectorXd axis = eig.eigenvectors().col(d - 1 - c);
      // Deterministic sign: the largest component of each axis is positive.
      Eigen::Index k = 0;
      axis.cwiseAbs().maxCoeff(&k);
      if (axis[k] < 0) axis = -axis;
      out[i][static_cast<std::size_t>(c)] = std::ldexp(axis.dot(x), exponent);
    }
  }
  return out;
}

namespace internal {

/// Adjacency of a proximity graph in compressed rows (both directions).
struct Adjacency {
  std::vector<std::size_t> offsets;
  std::vector<Vertex_index> targets;
};

inline Adjacency make_adjacency(const Proximity_graph& g, const char* fn = "embed_reeb_graph") {
  for (std::size_t k = 0; k < g.edges.size(); ++k)
    if (g.edges[k][0] >= g.number_of_vertices || g.edges[k][1] >= g.number_of_vertices)
      FeatureRecon::internal::throw_invalid_argument(fn, "graph edge ", k, " (", g.edges[k][0], ", ",
                                                     g.edges[k][1], ") has a vertex out of range [0, ",
                                                     g.number_of_vertices, ")");
  Adjacency a;
  a.offsets.assign(g.number_of_vertices + 1, 0);
  for (const auto& e : g.edges) {
    ++a.offsets[e[0] + 1];
    ++a.offsets[e[1] + 1];
  }
  for (std::size_t i = 0; i < g.number_of_vertices; ++i) a.offsets[i + 1] += a.offsets[i];
  a.targets.resize(a.offsets.back());
  std::vector<std::size_t> fill(a.offsets.begin(), a.offsets.end() - 1);
  for (const auto& e : g.edges) {
    a.targets[fill[e[0]]++] = e[1];
    a.targets[fill[e[1]]++] = e[0];
  }
  return a;
}

/// Shortest paths in a graph with Euclidean edge lengths (Dijkstra, ties by vertex index), reusing its
/// arrays.
class Graph_path_finder {
 public:
  Graph_path_finder(const Adjacency& adjacency, const Point_matrix& P)
      : m_adjacency(adjacency), m_P(P), m_distance(P.rows), m_previous(P.rows), m_stamp(P.rows, 0) {}

  double length(Vertex_index a, Vertex_index b) const {
    // Scaled where the squares overflow: edges 1e200 long made the automatic max_gap infinite (nothing
    // bridged).
    return point_distance(m_P.row(a), m_P.row(b), m_P.dimension);
  }

  /// Median edge length (0 without edges).
  double median_edge_length() const {
    std::vector<double> lengths;
    for (std::size_t v = 0; v < m_P.rows; ++v)
      for (std::size_t k = m_adjacency.offsets[v]; k < m_adjacency.offsets[v + 1]; ++k)
        if (m_adjacency.targets[k] > v)
          lengths.push_back(length(static_cast<Vertex_index>(v), m_adjacency.targets[k]));
    if (lengths.empty()) return 0;
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                     lengths.end());
    return lengths[lengths.size() / 2];
  }

  /// The interior vertices of a shortest path from a to b no longer than `limit`; false when there is none.
  bool path(Vertex_index a, Vertex_index b, double limit, std::vector<Vertex_index>& interior) {
    interior.clear();
    if (a == b) return true;
    ++m_search;
    using Entry = std::pair<double, Vertex_index>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    m_distance[a] = 0;
    m_stamp[a] = m_search;
    queue.push({0.0, a});
    bool found = false;
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > m_distance[v]) continue;
      if (v == b) {
        found = true;
        break;
      }
      for (std::size_t k = m_adjacency.offsets[v]; k < m_adjacency.offsets[v + 1]; ++k) {
        const Vertex_index w = m_adjacency.targets[k];
        const double dw = d + length(v, w);
        // Written so that a NaN length is never taken (it made every test false: vertices entered the queue
        // again and again, and the search never ended).
        if (!(dw <= limit) || (m_stamp[w] == m_search && !(dw < m_distance[w]))) continue;
        m_stamp[w] = m_search;
        m_distance[w] = dw;
        m_previous[w] = v;
        queue.push({dw, w});
      }
    }
    if (!found) return false;
    for (Vertex_index v = m_previous[b]; v != a; v = m_previous[v]) interior.push_back(v);
    std::reverse(interior.begin(), interior.end());
    return true;
  }

 private:
  const Adjacency& m_adjacency;
  const Point_matrix& m_P;
  std::vector<double> m_distance;
  std::vector<Vertex_index> m_previous;
  std::vector<std::size_t> m_stamp;
  std::size_t m_search = 0;
};

/// The mean of the `count` finite numbers x(0), ..., x(count - 1): their sum in that order divided by count,
/// or, when the sum overflows (numbers near the largest double), the sum of each divided by count. 0 when
/// count = 0; the sum starts from x(0), so that the mean of -0.0s is -0.0.
template <class X>
double mean_of(std::size_t count, const X& x) {
  if (count == 0) return 0.0;
  const double n = static_cast<double>(count);
  double sum = x(0);
  for (std::size_t i = 1; i < count; ++i) sum += x(i);
  if (std::isfinite(sum)) return sum / n;
  sum = x(0) / n;
  for (std::size_t i = 1; i < count; ++i) sum += x(i) / n;
  return sum;
}

/// Node positions and arc polylines in the space of P (any dimension), flat row-major; with a second matrix
/// Q of the same points (another space: the projection of P), the same centroids, bridges and smoothing
/// drawn in Q too, point for point (every choice made in P).
struct Flat_embedding {
  std::vector<std::vector<double>> nodes;       ///< per node, P.dimension coordinates
  std::vector<std::vector<double>> arcs;        ///< per arc, P.dimension coordinates per polyline vertex
  std::vector<std::vector<double>> also_nodes;  ///< per node, Q.dimension coordinates (empty without Q)
  std::vector<std::vector<double>> also_arcs;   ///< per arc, the polyline in Q (empty without Q)
  double max_gap = std::numeric_limits<double>::infinity();  ///< see Reeb_graph_embedding::max_gap
  Status status = Status::success;                           ///< see Reeb_graph_embedding::status
};

/// The level width used when Embedding_options::level_width is automatic: 1/64 of the range of the node
/// values (1 when the range is empty).
inline double automatic_level_width(const Reeb_graph& G) {
  if (G.nodes.empty()) return 1.0;
  double fmin = G.nodes.front().value, fmax = fmin;
  for (const auto& node : G.nodes) {
    fmin = std::min(fmin, node.value);
    fmax = std::max(fmax, node.value);
  }
  return fmax > fmin ? (fmax - fmin) / 64 : 1.0;
}

/// Checks the values of Embedding_options (throws naming `fn`).
inline void check_embedding_options(const Embedding_options& options, const char* fn) {
  FeatureRecon::internal::check_optional_length(  // infinity: one piece per arc
      fn, options.level_width, "embedding level_width",
      "1/64 of the range of f; in extract_reeb_skeleton(), the median edge length of the complex", nullptr,
      true);
  if (options.smoothing != Embedding_options::Smoothing::taubin &&
      options.smoothing != Embedding_options::Smoothing::laplacian)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "embedding smoothing must be taubin or laplacian, got ", static_cast<int>(options.smoothing));
  if (options.smoothing == Embedding_options::Smoothing::taubin &&
      !(options.smoothing_weight >= 0 && options.smoothing_weight <= 2.0 / 3))
    FeatureRecon::internal::throw_invalid_argument(
        fn, "embedding smoothing_weight must lie in [0, 2/3] for Taubin ",
        "smoothing (Laplacian: [0, 1]), got ", options.smoothing_weight);
  if (!(options.smoothing_weight >= 0 && options.smoothing_weight <= 1))
    FeatureRecon::internal::throw_invalid_argument(fn, "embedding smoothing_weight must lie in [0, 1], got ",
                                                   options.smoothing_weight);
  FeatureRecon::internal::check_optional_length(fn, options.max_gap, "embedding max_gap",
                                                "twice the median edge length", "off", true);
}

inline Flat_embedding embed_flat(const Reeb_graph& G, const Adjacency* adjacency, const Point_matrix& P,
                                 const std::vector<double>& values, const Embedding_options& options,
                                 const Point_matrix* Q = nullptr) {
  const char* fn = "embed_reeb_graph";
  const std::size_t d = P.dimension;
  const std::size_t dq = Q != nullptr ? Q->dimension : 0;
  if (P.rows != values.size())
    FeatureRecon::internal::throw_invalid_argument(fn, "positions has ", P.rows, " points and values ",
                                                   values.size(),
                                                   " entries: one of each per vertex of the complex");
  if (adjacency != nullptr && adjacency->offsets.size() != P.rows + 1)
    FeatureRecon::internal::throw_invalid_argument(fn, "the graph has ", adjacency->offsets.size() - 1,
                                                   " vertices but there are ", P.rows, " positions");
  check_embedding_options(options, fn);
  auto check = [&](Vertex_index v) {
    if (v >= P.rows)
      FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " out of range [0, ", P.rows, ")");
    if (!std::isfinite(values[v]))
      FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " has value ", values[v],
                                                     " (finite needed)");
    for (std::size_t c = 0; c < d; ++c)
      if (!std::isfinite(P.row(v)[c]))
        FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " has coordinate ", P.row(v)[c],
                                                       " (finite needed)");
  };
  Flat_embedding E;
  for (const auto& node : G.nodes) {
    check(node.vertex);
    for (const Vertex_index v : node.members) check(v);
    for (const Point_matrix* M : {&P, Q}) {
      if (M == nullptr) continue;
      std::vector<double> c(M->dimension);
      for (std::size_t k = 0; k < M->dimension; ++k)
        c[k] = mean_of(1 + node.members.size(),
                       [&](std::size_t i) { return M->row(i == 0 ? node.vertex : node.members[i - 1])[k]; });
      (M == &P ? E.nodes : E.also_nodes).push_back(std::move(c));
    }
  }
  const double width = options.level_width ? *options.level_width : automatic_level_width(G);
  // Two values lie in one bin when floor(value / width) is the same. A width far below the values'
  // resolution (a denormal width, say) overflows the quotient: each value is then its own level, the limit
  // of ever finer bins, and not one bin of infinity for all.
  const auto same_level = [width](double a, double b) {
    const double qa = std::floor(a / width), qb = std::floor(b / width);
    return std::isinf(qa) || std::isinf(qb) ? a == b : qa == qb;
  };
  // Gaps wider than max_gap are bridged by shortest paths of the graph.
  std::unique_ptr<Graph_path_finder> finder;
  double max_gap = std::numeric_limits<double>::infinity();
  if (adjacency != nullptr && (!options.max_gap || (*options.max_gap > 0 && !std::isinf(*options.max_gap)))) {
    finder = std::make_unique<Graph_path_finder>(*adjacency, P);
    max_gap = options.max_gap ? *options.max_gap : 2 * finder->median_edge_length();
    if (!(max_gap > 0)) {
      finder.reset();
      max_gap = std::numeric_limits<double>::infinity();
    }
  }
  E.max_gap = max_gap;
  std::vector<Vertex_index> path;
  // Local index of each input vertex in the arc being drawn (stamped by arc), its run, and a union-find.
  std::vector<std::size_t> stamp(adjacency != nullptr ? P.rows : 0, static_cast<std::size_t>(-1));
  std::vector<std::size_t> local(stamp.size()), run_of, size;
  FeatureRecon::internal::Union_find<std::size_t> pieces;  // root = smallest index: deterministic
  std::vector<Vertex_index> piece;                         // the points of the piece whose centroid is drawn
  for (std::size_t a = 0; a < G.arcs.size(); ++a)
    if (!(G.arcs[a].lower < G.nodes.size() && G.arcs[a].upper < G.nodes.size()))
      FeatureRecon::internal::throw_invalid_argument(fn, "arc ", a, " joins nodes (", G.arcs[a].lower, ", ",
                                                     G.arcs[a].upper, ") out of range [0, ", G.nodes.size(),
                                                     ")");
  // Progress by work done, reported every 2^16 units: an arc of k points counts k + 1 to draw and k + 1 per
  // smoothing round (a million rounds of one arc took seconds without a report).
  const double rounds = static_cast<double>(options.smoothing_iterations);
  double total_work = 0, work = 0, reported = 0;
  for (const auto& arc : G.arcs) total_work += static_cast<double>(arc.vertices.size() + 1) * (1 + rounds);
  const auto keep_going = [&]() {  // false when the caller stops the run
    if (work - reported < 65536) return true;
    reported = work;
    return FeatureRecon::internal::report_progress(options.progress, work / total_work);
  };
  const auto stop_at = [&](std::size_t a) {  // arcs a and later drawn straight, node to node
    E.status = Status::interrupted;
    for (std::size_t b = a; b < G.arcs.size(); ++b)
      for (int m = 0; m < (Q != nullptr ? 2 : 1); ++m) {
        const auto& nodes = m == 0 ? E.nodes : E.also_nodes;
        std::vector<double> straight(nodes[G.arcs[b].lower]);
        straight.insert(straight.end(), nodes[G.arcs[b].upper].begin(), nodes[G.arcs[b].upper].end());
        (m == 0 ? E.arcs : E.also_arcs).push_back(std::move(straight));
      }
  };
  for (std::size_t a = 0; a < G.arcs.size(); ++a) {
    const auto& arc = G.arcs[a];
    const auto& vs = arc.vertices;
    if (!keep_going()) {
      stop_at(a);
      return E;
    }
    const double arc_work = static_cast<double>(vs.size() + 1);
    work += arc_work;
    for (const Vertex_index v : vs) check(v);
    // Runs of consecutive points (in f order) within one bin of width `width`.
    run_of.assign(vs.size(), 0);
    std::size_t runs = 0;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      if (i > 0 && !same_level(values[vs[i]], values[vs[i - 1]])) ++runs;
      run_of[i] = runs;
    }
    // Level-set pieces: connected components of a run in the graph (one piece per run without a graph).
    pieces.reset(vs.size());
    if (adjacency != nullptr) {
      for (std::size_t i = 0; i < vs.size(); ++i) {
        stamp[vs[i]] = a;
        local[vs[i]] = i;
      }
      for (std::size_t i = 0; i < vs.size(); ++i)
        for (std::size_t k = adjacency->offsets[vs[i]]; k < adjacency->offsets[vs[i] + 1]; ++k) {
          const Vertex_index w = adjacency->targets[k];
          if (stamp[w] != a || run_of[local[w]] != run_of[i]) continue;
          pieces.unite(i, local[w]);
        }
    } else {
      for (std::size_t i = 1; i < vs.size(); ++i)
        if (run_of[i] == run_of[i - 1]) pieces.unite(i - 1, i);
    }
    size.assign(vs.size(), 0);
    for (std::size_t i = 0; i < vs.size(); ++i) ++size[pieces.find(i)];
    std::vector<double> line(E.nodes[arc.lower]);
    std::vector<double> also_line(Q != nullptr ? E.also_nodes[arc.lower] : std::vector<double>());
    std::vector<Vertex_index> origin{
        G.nodes[arc.lower].vertex};  // the input point each polyline point stands for
    std::size_t i = 0;
    while (i < vs.size()) {
      // The largest piece of the run (ties: the one holding the earliest point) carries the polyline.
      std::size_t j = i, best = pieces.find(i);
      for (; j < vs.size() && run_of[j] == run_of[i]; ++j)
        if (size[pieces.find(j)] > size[best]) best = pieces.find(j);
      const std::size_t at = line.size();
      line.resize(at + d, 0.0);
      piece.clear();
      for (std::size_t t = i; t < j; ++t)
        if (pieces.find(t) == best) piece.push_back(vs[t]);
      for (std::size_t k = 0; k < d; ++k)
        line[at + k] = mean_of(piece.size(), [&](std::size_t q) { return P.row(piece[q])[k]; });
      for (std::size_t k = 0; k < dq; ++k)
        also_line.push_back(mean_of(piece.size(), [&](std::size_t q) { return Q->row(piece[q])[k]; }));
      // The piece's point closest to the centroid (ties: the earliest); only needed to bridge gaps.
      double closest = std::numeric_limits<double>::infinity();
      origin.push_back(vs[i]);
      for (std::size_t t = i; finder && t < j; ++t) {
        if (pieces.find(t) != best) continue;
        // Distances scaled as point_distance() scales them: squares underflowed below about 1e-160 (every
        // point tied at 0) and overflowed above about 1e154.
        const double s = point_distance(P.row(vs[t]), line.data() + at, d);
        if (s < closest) {
          closest = s;
          origin.back() = vs[t];
        }
      }
      i = j;
    }
    line.insert(line.end(), E.nodes[arc.upper].begin(), E.nodes[arc.upper].end());
    if (Q != nullptr)
      also_line.insert(also_line.end(), E.also_nodes[arc.upper].begin(), E.also_nodes[arc.upper].end());
    origin.push_back(G.nodes[arc.upper].vertex);
    if (finder) {  // bridge wide gaps through the graph
      std::vector<double> bridged(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(d));
      std::vector<double> also_bridged(also_line.begin(),
                                       also_line.begin() + static_cast<std::ptrdiff_t>(dq));
      // Appends a point (and its twin in Q), except where the polyline would go out and back to the same
      // point: a bridge's last vertex X, the piece's centroid B beside it, the next bridge leaving through X
      // again (X B X C becomes X B C; at the upper node, W X B X becomes W X, and X B X stays).
      auto append = [&](const double* p, const double* q, bool last) {
        const std::size_t n = bridged.size() / d;
        if (n >= 2 && std::equal(p, p + d, bridged.begin() + static_cast<std::ptrdiff_t>((n - 2) * d)) &&
            (!last || n >= 3)) {  // an arc between nodes at one place keeps its tip: a line has two points
          if (last) {
            bridged.resize((n - 1) * d);
            also_bridged.resize((n - 1) * dq);
          }
          return;
        }
        bridged.insert(bridged.end(), p, p + d);
        also_bridged.insert(also_bridged.end(), q, q + dq);
      };
      std::vector<double> mean(d), also_mean(dq);
      for (std::size_t t = 1; t < origin.size(); ++t) {
        // As the graph's edge lengths are measured (the squares made bridging depend on the scale: nothing
        // was bridged below about 1e-160, every gap above about 1e154).
        const double gap = point_distance(line.data() + (t - 1) * d, line.data() + t * d, d);
        if (gap > max_gap && origin[t] != origin[t - 1] &&
            finder->path(origin[t - 1], origin[t], 4 * gap + max_gap, path))
          for (const Vertex_index v : path) {
            const std::size_t first = adjacency->offsets[v], count = 1 + adjacency->offsets[v + 1] - first;
            for (std::size_t c = 0; c < d; ++c)  // the mean of v and its neighbours
              mean[c] = mean_of(count, [&](std::size_t q) {
                return P.row(q == 0 ? v : adjacency->targets[first + q - 1])[c];
              });
            for (std::size_t c = 0; c < dq; ++c)
              also_mean[c] = mean_of(count, [&](std::size_t q) {
                return Q->row(q == 0 ? v : adjacency->targets[first + q - 1])[c];
              });
            append(mean.data(), also_mean.data(), false);
          }
        append(line.data() + t * d, also_line.data() + t * dq, t + 1 == origin.size());
      }
      line.swap(bridged);
      also_line.swap(also_bridged);
    }
    const std::size_t n = d == 0 ? 0 : line.size() / d;
    const double lambda = options.smoothing_weight;
    const bool taubin = options.smoothing == Embedding_options::Smoothing::taubin && lambda > 0;
    const double mu = taubin ? 1 / (0.1 - 1 / lambda) : 0.0;
    std::vector<double> next;
    // Every interior point moves by w towards the mean of its neighbours (in P, and in Q alike).
    auto step_of = [&](std::vector<double>& points, std::size_t dim, double w) {
      next = points;
      for (std::size_t t = 1; t + 1 < n; ++t)
        for (std::size_t k = 0; k < dim; ++k) {
          const double x = points[t * dim + k];
          // a sum could overflow
          const double mean = 0.5 * points[(t - 1) * dim + k] + 0.5 * points[(t + 1) * dim + k];
          next[t * dim + k] = (1 - w) * x + w * mean;
          // Near the largest double, Taubin's (1 - w) x with w < 0 overflows: the same step as a move of x.
          if (!std::isfinite(next[t * dim + k])) next[t * dim + k] = x + w * (mean - x);
        }
      points.swap(next);
    };
    auto step = [&](double w) {
      step_of(line, d, w);
      if (Q != nullptr) step_of(also_line, dq, w);
    };
    if (n <= 2)  // nothing to smooth: its rounds count at once (the next arc's check reports them)
      work += arc_work * rounds;
    for (std::size_t it = 0; n > 2 && it < options.smoothing_iterations; ++it) {
      step(lambda);
      if (taubin) step(mu);
      work += arc_work;
      if (!keep_going()) {  // this arc is not finished: straight, as the rest
        stop_at(a);
        return E;
      }
    }
    E.arcs.push_back(std::move(line));
    if (Q != nullptr) E.also_arcs.push_back(std::move(also_line));
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return E;
}

/// The points as a 3-column Point_matrix.
inline Point_matrix matrix_of(const std::vector<std::array<double, 3>>& positions) {
  Point_matrix P;
  P.rows = positions.size();
  P.dimension = 3;
  P.data.reserve(3 * positions.size());
  for (const auto& p : positions) P.data.insert(P.data.end(), p.begin(), p.end());
  return P;
}

/// A Reeb_graph_embedding from flat 3-column node positions and polylines (of F's drawing: its max_gap and
/// status).
inline Reeb_graph_embedding embedding_3d(const std::vector<std::vector<double>>& nodes,
                                         const std::vector<std::vector<double>>& arcs, std::size_t dimension,
                                         const Flat_embedding& F) {
  Reeb_graph_embedding E;
  E.dimension = std::min<std::size_t>(dimension, 3);
  E.max_gap = F.max_gap;
  E.status = F.status;
  for (const auto& n : nodes) E.node_positions.push_back({n[0], n[1], n[2]});
  for (const auto& a : arcs) {
    std::vector<std::array<double, 3>> line;
    for (std::size_t t = 0; t + 2 < a.size(); t += 3) line.push_back({a[t], a[t + 1], a[t + 2]});
    E.arc_polylines.push_back(std::move(line));
  }
  return E;
}

inline Reeb_graph_embedding embed_reeb_graph(const Reeb_graph& G, const Adjacency* adjacency,
                                             const std::vector<std::array<double, 3>>& positions,
                                             const std::vector<double>& values, std::size_t dimension,
                                             const Embedding_options& options) {
  const Flat_embedding F = embed_flat(G, adjacency, matrix_of(positions), values, options);
  return embedding_3d(F.nodes, F.arcs, dimension, F);
}
}  // namespace internal

namespace internal {
/// Eigenpairs (descending algebraic eigenvalues, unit eigenvectors as columns) of the `count` largest
/// eigenvalues of the symmetric matrix B. Dense (Eigen's SelfAdjointEigenSolver, O(n^3)) when n <=
/// dense_limit or n < 64; otherwise a block Krylov subspace with full reorthogonalisation and Rayleigh-Ritz
/// (block Lanczos), a fixed seeded start block of 8 vectors (eigenvalues of multiplicity up to 8 are found),
/// grown until every wanted Ritz pair has residual |B v - theta v| <= max(1e-10 |theta|, 1e-14 |B|_inf);
/// O(n^2) per block. At 128 columns the basis restarts from its 64 best Ritz vectors and the next block
/// (thick restart), which bounds the memory and the Rayleigh-Ritz cost per block. Falls back to the dense
/// solver when that is not reached after n columns (products costing about what the dense solver costs). B
/// should be scaled so that |B|_inf is about 1 (residual norms are not rescaled). `progress` is asked after
/// each block with half the fraction of that n-column budget used, and with 0.5 before a dense fallback;
/// false sets `stopped` and returns what has been computed so far (maybe nothing).
inline void top_eigenpairs(const Eigen::MatrixXd& B, int count, std::size_t dense_limit,
                           const Progress_callback& progress, bool& stopped, Eigen::VectorXd& values,
                           Eigen::MatrixXd& vectors) {
  const Eigen::Index N = B.rows();
  const Eigen::Index wanted = std::min<Eigen::Index>(count, N);
  stopped = false;
  const auto dense = [&] {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(B);  // ascending eigenvalues
    values.resize(wanted);
    vectors.resize(N, wanted);
    for (Eigen::Index c = 0; c < wanted; ++c) {
      values[c] = eig.eigenvalues()[N - 1 - c];
      vectors.col(c) = eig.eigenvectors().col(N - 1 - c);
    }
  };
  if (static_cast<std::size_t>(N) <= dense_limit || wanted == 0 || N < 64) return dense();
  // The dense solver has no progress of its own: it is announced, and a stop there honoured, before it runs.
  const auto dense_fallback = [&] {
    if (!FeatureRecon::internal::report_progress(progress, 0.5)) {
      stopped = true;
      return;
    }
    dense();
  };
  // Unrestarted, Gaussian noise in R^1000 (n = 2000) needed 328 columns and a metric of entries uniform in
  // [1, 2] 568: past the old limit of 320, where the dense solver then took 7-26 s, and the Rayleigh-Ritz
  // step on 568 columns alone costs 5 s. Restarted at 128 columns they converge after 43 and 76 blocks of 8
  // (0.8 and 1.4 s).
  const Eigen::Index block = 8, basis = std::min<Eigen::Index>(N / 2, 128), keep = basis / 2, budget = N;
  const double scale = B.cwiseAbs().rowwise().sum().maxCoeff();  // |B|_inf >= |B|_2
  values = Eigen::VectorXd::Zero(wanted);
  vectors = Eigen::MatrixXd::Zero(N, wanted);
  if (!(scale > 0)) {  // B = 0: any orthonormal vectors, eigenvalue 0
    for (Eigen::Index c = 0; c < wanted; ++c) vectors(c, c) = 1;
    return;
  }
  FeatureRecon::internal::Unit_random random(0x6d6473ULL);
  Eigen::MatrixXd W(N, block);
  for (Eigen::Index j = 0; j < block; ++j)
    for (Eigen::Index i = 0; i < N; ++i) W(i, j) = random.normal();
  Eigen::MatrixXd Q(N, 0), BQ(N, 0), T(0, 0);
  // Orthonormalises the columns of X against Q and one another (two Gram-Schmidt passes), dropping columns
  // that vanish (the subspace is then invariant in that direction); returns how many are left (the first
  // columns of X).
  const auto orthonormalise = [&](Eigen::MatrixXd& X) {
    Eigen::Index kept = 0;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
      Eigen::VectorXd x = X.col(j);
      const double before = x.norm();
      for (int pass = 0; pass < 2; ++pass) {
        if (Q.cols() > 0) x -= Q * (Q.transpose() * x);
        for (Eigen::Index c = 0; c < kept; ++c) x -= X.col(c).dot(x) * X.col(c);
      }
      const double after = x.norm();
      if (!(after > 1e-10 * before) || !(after > 0)) continue;
      X.col(kept++) = x / after;
    }
    return kept;
  };
  const auto append = [&](const Eigen::MatrixXd& X, Eigen::Index columns) {
    const Eigen::Index old = Q.cols();
    Q.conservativeResize(N, old + columns);
    Q.rightCols(columns) = X.leftCols(columns);
  };
  Eigen::Index fresh = orthonormalise(W), used = 0;
  append(W, fresh);
  while (fresh > 0) {
    const Eigen::Index k = Q.cols();
    const Eigen::MatrixXd product = B * Q.rightCols(fresh);
    used += fresh;
    BQ.conservativeResize(N, k);
    BQ.rightCols(fresh) = product;
    // Rayleigh-Ritz: T = Q^T B Q, grown by the new columns (kept symmetric).
    T.conservativeResize(k, k);
    const Eigen::MatrixXd column = Q.transpose() * product;  // k x fresh
    T.rightCols(fresh) = column;
    T.bottomRows(fresh) = column.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(T);
    const Eigen::Index have = std::min(wanted, k);
    bool converged = have == wanted;
    for (Eigen::Index c = 0; c < have; ++c) {
      const Eigen::VectorXd s = ritz.eigenvectors().col(k - 1 - c);
      const double theta = ritz.eigenvalues()[k - 1 - c];
      values[c] = theta;
      vectors.col(c) = Q * s;
      const double residual = (BQ * s - theta * vectors.col(c)).norm();
      if (!(residual <= std::max(1e-10 * std::fabs(theta), 1e-14 * scale))) converged = false;
    }
    if (converged) return;
    if (used + block > budget) return dense_fallback();
    if (!FeatureRecon::internal::report_progress(progress, 0.5 * static_cast<double>(used) / budget)) {
      stopped = true;
      return;
    }
    W = product;
    fresh = orthonormalise(W);  // against the whole basis, also before a restart: B Q stays in span(Q, W)
    if (k + fresh > basis) {
      // Thick restart: the best Ritz vectors Y = Q S satisfy B Y = Y Theta + W R, so Y and the next block W
      // still span a Krylov subspace, and the search goes on in it.
      const Eigen::MatrixXd S = ritz.eigenvectors().rightCols(std::min(keep, k));
      Q = (Q * S).eval();
      BQ = (BQ * S).eval();
      T = (S.transpose() * T * S).eval();
    }
    append(W, fresh);
  }
  // The Krylov subspace stopped growing (invariant up to rounding) before the wanted pairs converged.
  dense_fallback();
}

/// Throws unless D has n * n entries (n * n may wrap: compared by division).
inline void check_mds_size(const std::vector<double>& D, std::size_t n) {
  if (n != 0 && (D.size() / n != n || D.size() % n != 0))
    FeatureRecon::internal::throw_invalid_argument("classical_mds_3d", "D has ", D.size(),
                                                   " entries, not n * n for n = ", n);
  if (n == 0 && !D.empty())
    FeatureRecon::internal::throw_invalid_argument("classical_mds_3d", "D has ", D.size(),
                                                   " entries for n = 0");
}

inline std::vector<std::array<double, 3>> classical_mds_3d(const std::vector<double>& D, std::size_t n,
                                                           const Progress_callback& progress, bool& stopped,
                                                           std::size_t dense_limit = 300) {
  const char* fn = "classical_mds_3d";
  stopped = false;
  check_mds_size(D, n);
  for (std::size_t k = 0; k < D.size(); ++k)
    if (!(std::isfinite(D[k]) && D[k] >= 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "entry (", k / n, ", ", k % n, ") is ", D[k],
                                                     " (must be finite and >= 0)");
  std::vector<std::array<double, 3>> out(n, {0.0, 0.0, 0.0});
  if (n == 0) return out;
  const Eigen::Index N = static_cast<Eigen::Index>(n);
  // Distances are scaled by a power of two into [0, 2) and the centred matrix by another to a norm in [1, 2):
  // exact, so squares cannot overflow or underflow, and the solver's tolerances are relative to 1.
  const double largest = *std::max_element(D.begin(), D.end());
  if (!(largest > 0)) return out;  // one repeated point
  const int distance_exponent = std::ilogb(largest);
  Eigen::MatrixXd B(N, N);
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) {
      const double d =
          std::ldexp(D[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)], -distance_exponent);
      B(i, j) = -0.5 * d * d;
    }
  const Eigen::VectorXd row_mean = B.rowwise().mean();
  const double mean = row_mean.mean();
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) B(i, j) += mean - row_mean[i] - row_mean[j];
  const double norm = B.cwiseAbs().rowwise().sum().maxCoeff();
  if (!(norm > 0)) return out;
  const int norm_exponent = std::ilogb(norm);
  B *= std::ldexp(1.0, -norm_exponent);
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  top_eigenpairs(B, 3, dense_limit, progress, stopped, values, vectors);
  if (stopped) return out;
  for (Eigen::Index c = 0; c < values.size(); ++c) {
    // The eigenvalue of the scaled distances; coordinates get the distance scale back below.
    const double lambda = std::ldexp(values[c], norm_exponent);
    if (!(lambda > 0)) break;
    Eigen::VectorXd v = vectors.col(c);
    Eigen::Index k = 0;
    v.cwiseAbs().maxCoeff(&k);
    if (v[k] < 0) v = -v;
    const double length = std::sqrt(lambda);
    for (Eigen::Index i = 0; i < N; ++i)
      out[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] =
          std::ldexp(v[i] * length, distance_exponent);
  }
  return out;
}
}  // namespace internal

/// Classical multidimensional scaling of a dense distance matrix (row-major n x n) into at most 3 dimensions:
/// the eigenvectors of the double-centred squared distances for the three largest eigenvalues, scaled by
/// their square roots (negative eigenvalues give 0). Deterministic signs as in project_to_3d(). Up to n = 300
/// a dense eigendecomposition; above, a seeded block Krylov (Lanczos) solver for the three largest
/// eigenpairs, O(n^2) per step of 8 vectors, restarted at 128 vectors. n = 2000: 0.1-0.3 s in a few steps
/// when the top eigenvalues stand apart (points near a curve or surface; the dense solver needs 6-9 s); where
/// they crowd together (Gaussian noise in R^1000, a metric of entries uniform in [1, 2]) 43-76 steps, 0.8-1.4
/// s where the dense solver takes 8-15 s on them. The dense solver again, announced and stoppable, when the
/// Krylov one has not converged after n vectors (those two converge within a third of that). Eigenvalues of
/// multiplicity up to 8 are found. Coordinates inside an eigenspace of multiplicity above one are one
/// orthonormal basis of it (distances between the embedded points do not depend on which).
/// \throws std::invalid_argument when D does not have n * n entries, or names the first entry that is
///   negative or not finite, the first diagonal entry that is not 0, or the first pair (i, j), i < j, where D
///   is not symmetric.
inline std::vector<std::array<double, 3>> classical_mds_3d(const std::vector<double>& D, std::size_t n) {
  bool stopped = false;
  internal::check_mds_size(D, n);
  internal::check_distance_entries(D, n, "classical_mds_3d");
  return internal::classical_mds_3d(D, n, Progress_callback(), stopped);
}

/// Options of classical_mds_3d() with a progress callback.
struct Classical_mds_options {
  /// Called with 0 at the start, between the steps of the block Krylov solver (above 300 points) with half
  /// the fraction of its budget of n vectors, with 0.5 before the dense solver when the Krylov one falls back
  /// to it, and with 1 at the end; returning false stops: every position 0, status interrupted.
  Progress_callback progress;
};

/// Result of classical_mds_3d() with options.
struct Classical_mds {
  /// one per row of D, as the two-argument overload returns them
  std::vector<std::array<double, 3>> positions;
  /// interrupted when the progress callback stopped the run (positions all 0)
  Status status = Status::success;
};

namespace internal {
/// \cond
/// classical_mds_3d() with options of a checked flat n x n matrix.
inline Classical_mds classical_mds_of_checked(const std::vector<double>& a, std::size_t n,
                                              const Classical_mds_options& options) {
  Classical_mds result;
  bool stopped = !FeatureRecon::internal::report_progress(options.progress, 0.0);
  if (stopped)
    result.positions.assign(n, {0.0, 0.0, 0.0});
  else
    result.positions = classical_mds_3d(a, n, options.progress, stopped);
  if (stopped) {
    result.status = Status::interrupted;
    for (auto& p : result.positions) p = {0.0, 0.0, 0.0};
  } else {
    (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  }
  return result;
}

template <class Matrix, class = void>
struct Is_range_of_rows : std::false_type {};
template <class Matrix>
struct Is_range_of_rows<Matrix, std::void_t<decltype(std::begin(*std::begin(std::declval<const Matrix&>())))>>
    : std::true_type {};
/// \endcond
}  // namespace internal

/// classical_mds_3d() that reports progress and can be stopped; the same positions when it runs to the end.
/// \throws std::invalid_argument as the two-argument overload.
inline Classical_mds classical_mds_3d(const std::vector<double>& D, std::size_t n,
                                      const Classical_mds_options& options) {
  internal::check_mds_size(D, n);
  internal::check_distance_entries(D, n, "classical_mds_3d");
  return internal::classical_mds_of_checked(D, n, options);
}

/// classical_mds_3d() of a dense distance matrix as the other distance-matrix entry points take it
/// (build_rips_graph_from_distance_matrix(), extract_reeb_skeleton_from_distance_matrix()): the same
/// positions as the flat overloads of its entries.
/// \tparam Matrix an Eigen-like matrix (`rows()`, `cols()`, `D(i, j)`) or a range of rows.
/// \throws std::invalid_argument for a matrix that is not square (naming the first short row), and as the
///   flat overloads for its entries.
template <class Matrix,
          std::enable_if_t<
              internal::Is_eigen_like<Matrix>::value || internal::Is_range_of_rows<Matrix>::value, int> = 0>
Classical_mds classical_mds_3d(const Matrix& D, const Classical_mds_options& options = {}) {
  std::size_t n = 0;
  const std::vector<double> a = internal::checked_distance_matrix(D, n, "classical_mds_3d");
  return internal::classical_mds_of_checked(a, n, options);
}

/// Embeds a Reeb graph (dissertation Ch. 3.3.1): a node sits at the centroid of its points (its vertex and
/// members); an arc becomes a polyline from its lower node through the centroids of its level-set pieces (its
/// points cut into bins of function value) to its upper node, then smoothed with fixed ends (Taubin or
/// Laplacian rounds, Embedding_options::smoothing). Without a graph, all of an arc's points in one bin form
/// one piece.
/// \param positions coordinates of the input points in at most 3D (see project_to_3d()); \param values f per
///   point.
/// \pre every vertex of G indexes positions and values, with finite coordinates and value (checked; throws
///      naming the vertex); level_width automatic or > 0; smoothing_weight in [0, 2/3] for Taubin smoothing,
///      [0, 1] for Laplacian (checked; throws).
inline Reeb_graph_embedding embed_reeb_graph(const Reeb_graph& G,
                                             const std::vector<std::array<double, 3>>& positions,
                                             const std::vector<double>& values, std::size_t dimension,
                                             const Embedding_options& options = {}) {
  return internal::embed_reeb_graph(G, nullptr, positions, values, dimension, options);
}

/// A Reeb graph drawn in the space of its input points (any dimension), flat row-major coordinates.
struct Reeb_graph_input_embedding {
  std::size_t dimension = 0;                        ///< dimension of the input points
  std::vector<std::vector<double>> node_positions;  ///< per node, `dimension` coordinates
  std::vector<std::vector<double>> arc_polylines;   ///< per arc, `dimension` coordinates per polyline vertex
  Status status = Status::success;  ///< interrupted when the progress callback stopped the drawing
};

/// embed_reeb_graph() in the input space itself (no projection): the same centroids of level-set pieces and
/// the same smoothing, in any dimension. Used to measure how far arcs are from a true graph in R^d.
/// \pre graph.number_of_vertices == points.rows == values.size(); coordinates finite (checked; throws).
inline Reeb_graph_input_embedding embed_reeb_graph_in_input_space(const Reeb_graph& G,
                                                                  const Proximity_graph& graph,
                                                                  const Point_matrix& points,
                                                                  const std::vector<double>& values,
                                                                  const Embedding_options& options = {}) {
  internal::check_point_matrix(points, "embed_reeb_graph_in_input_space");
  const internal::Adjacency adjacency = internal::make_adjacency(graph, "embed_reeb_graph_in_input_space");
  internal::Flat_embedding F = internal::embed_flat(G, &adjacency, points, values, options);
  Reeb_graph_input_embedding E;
  E.dimension = points.dimension;
  E.status = F.status;
  E.node_positions = std::move(F.nodes);
  E.arc_polylines = std::move(F.arcs);
  return E;
}

namespace internal {
/// \cond
/// embed_reeb_graph_in_input_space() and embed_reeb_graph() on `projected` (the points' projection) drawn
/// together: every choice (which gaps are bridged, along which shortest paths) is made in the input space,
/// and the same centroids, bridges and smoothing are drawn in both, so that each 3D polyline is the
/// projection of its input polyline point for point (up to rounding: centroids, smoothing and the PCA
/// projection are all affine). Max_gap is in input units.
inline std::pair<Reeb_graph_embedding, Reeb_graph_input_embedding> embed_reeb_graph_with_projection(
    const Reeb_graph& G, const Proximity_graph& graph, const Point_matrix& points,
    const std::vector<std::array<double, 3>>& projected, const std::vector<double>& values,
    const Embedding_options& options) {
  check_point_matrix(points, "embed_reeb_graph_in_input_space");
  const Adjacency adjacency = make_adjacency(graph, "embed_reeb_graph_in_input_space");
  const Point_matrix Q = matrix_of(projected);
  Flat_embedding F = embed_flat(G, &adjacency, points, values, options, &Q);
  std::pair<Reeb_graph_embedding, Reeb_graph_input_embedding> out;
  out.first = embedding_3d(F.also_nodes, F.also_arcs, points.dimension, F);
  Reeb_graph_input_embedding& I = out.second;
  I.dimension = points.dimension;
  I.status = F.status;
  I.node_positions = std::move(F.nodes);
  I.arc_polylines = std::move(F.arcs);
  return out;
}
/// \endcond
}  // namespace internal

/// embed_reeb_graph() where a level-set piece is a connected component, in `graph` (the 1-skeleton of the
/// complex the Reeb graph was computed on), of an arc's points in one bin. When simplification merged several
/// pieces into one arc (a removed branch or the two sides of a thin loop), the polyline goes through the
/// largest piece, so removed features do not pull it off the surviving path. Where consecutive polyline
/// points lie farther apart than Embedding_options::max_gap, the polyline follows the graph's shortest path
/// between them.
/// \pre graph.number_of_vertices == positions.size() (checked; throws); max_gap automatic or >= 0 (checked;
///      throws; 0 and infinity: no bridging).
inline Reeb_graph_embedding embed_reeb_graph(const Reeb_graph& G, const Proximity_graph& graph,
                                             const std::vector<std::array<double, 3>>& positions,
                                             const std::vector<double>& values, std::size_t dimension,
                                             const Embedding_options& options = {}) {
  const internal::Adjacency adjacency = internal::make_adjacency(graph);
  return internal::embed_reeb_graph(G, &adjacency, positions, values, dimension, options);
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H
