// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H
#define FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/rips_graph.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Options of embed_reeb_graph().
struct Embedding_options {
  /// Width of the function-value bins that cut an arc's points into level-set pieces (same unit as f);
  /// 0 (default) means automatic: 1/64 of the range of f over the graph.
  double level_width = 0;
  std::size_t smoothing_iterations = 10;  ///< Laplacian smoothing rounds of each polyline, endpoints fixed; default 10
  double smoothing_weight = 0.5;          ///< move towards the neighbours' mean per round, in [0, 1]; default 0.5
};

/// A Reeb graph drawn in space: node positions and one polyline per arc (from its lower to its upper node).
struct Reeb_graph_embedding {
  std::size_t dimension = 0;                                    ///< 1, 2 or 3: min(input dimension, 3)
  std::vector<std::array<double, 3>> node_positions;            ///< per node (unused coordinates 0)
  std::vector<std::vector<std::array<double, 3>>> arc_polylines;  ///< per arc, first and last = node positions
};

/// Coordinates of the points in at most 3 dimensions: unchanged up to 3D, else the projection onto the three
/// principal axes (PCA with Eigen, centred at the mean). Row-major, 3 columns (zero-padded).
inline std::vector<std::array<double, 3>> project_to_3d(const Point_matrix& m) {
  std::vector<std::array<double, 3>> out(m.rows, {0.0, 0.0, 0.0});
  if (m.dimension <= 3) {
    for (std::size_t i = 0; i < m.rows; ++i)
      for (std::size_t c = 0; c < m.dimension; ++c) out[i][c] = m.row(i)[c];
    return out;
  }
  const Eigen::Index d = static_cast<Eigen::Index>(m.dimension);
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  for (std::size_t i = 0; i < m.rows; ++i) mean += Eigen::Map<const Eigen::VectorXd>(m.row(i), d);
  if (m.rows > 0) mean /= static_cast<double>(m.rows);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < m.rows; ++i) {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(m.row(i), d) - mean;
    cov.noalias() += x * x.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);  // ascending eigenvalues
  for (std::size_t i = 0; i < m.rows; ++i) {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(m.row(i), d) - mean;
    for (int c = 0; c < 3; ++c) {
      Eigen::VectorXd axis = eig.eigenvectors().col(d - 1 - c);
      // Deterministic sign: the largest component of each axis is positive.
      Eigen::Index k = 0;
      axis.cwiseAbs().maxCoeff(&k);
      if (axis[k] < 0) axis = -axis;
      out[i][static_cast<std::size_t>(c)] = axis.dot(x);
    }
  }
  return out;
}

/// Embeds a Reeb graph (dissertation Ch. 3.3.1): a node sits at the centroid of its points (its vertex and
/// members); an arc becomes a polyline from its lower node through the centroids of its level-set pieces (its
/// points cut into bins of function value) to its upper node, then smoothed by Laplacian rounds with fixed ends.
/// \param positions coordinates of the input points in at most 3D (see project_to_3d()); \param values f per point.
/// \pre every vertex of G indexes positions and values (checked; throws); level_width >= 0, weight in [0, 1]
///      (checked; throws).
inline Reeb_graph_embedding embed_reeb_graph(const Reeb_graph& G, const std::vector<std::array<double, 3>>& positions,
                                             const std::vector<double>& values, std::size_t dimension,
                                             const Embedding_options& options = {}) {
  const char* fn = "embed_reeb_graph";
  if (positions.size() != values.size())
    FeatureRecon::internal::throw_invalid_argument(fn, "positions and values differ in size");
  if (!(options.level_width >= 0) || !(options.smoothing_weight >= 0 && options.smoothing_weight <= 1))
    FeatureRecon::internal::throw_invalid_argument(fn, "level_width must be >= 0 and smoothing_weight in [0, 1]");
  auto check = [&](Vertex_index v) {
    if (v >= positions.size())
      FeatureRecon::internal::throw_invalid_argument(fn, "vertex ", v, " out of range [0, ", positions.size(), ")");
  };
  Reeb_graph_embedding E;
  E.dimension = std::min<std::size_t>(dimension, 3);
  double fmin = 0, fmax = 0;
  bool first = true;
  for (const auto& node : G.nodes) {
    check(node.vertex);
    std::array<double, 3> c = positions[node.vertex];
    for (const Vertex_index v : node.members) {
      check(v);
      for (int k = 0; k < 3; ++k) c[k] += positions[v][k];
    }
    for (int k = 0; k < 3; ++k) c[k] /= static_cast<double>(1 + node.members.size());
    E.node_positions.push_back(c);
    fmin = first ? node.value : std::min(fmin, node.value);
    fmax = first ? node.value : std::max(fmax, node.value);
    first = false;
  }
  const double width = options.level_width > 0 ? options.level_width : (fmax > fmin ? (fmax - fmin) / 64 : 1.0);
  for (const auto& arc : G.arcs) {
    std::vector<std::array<double, 3>> line{E.node_positions[arc.lower]};
    // Level-set pieces: consecutive points (in f order) within one bin of width `width`.
    std::size_t i = 0;
    while (i < arc.vertices.size()) {
      check(arc.vertices[i]);
      const double bin = std::floor(values[arc.vertices[i]] / width);
      std::array<double, 3> c{0.0, 0.0, 0.0};
      std::size_t count = 0;
      for (; i < arc.vertices.size() && std::floor(values[arc.vertices[i]] / width) == bin; ++i, ++count) {
        check(arc.vertices[i]);
        for (int k = 0; k < 3; ++k) c[k] += positions[arc.vertices[i]][k];
      }
      for (int k = 0; k < 3; ++k) c[k] /= static_cast<double>(count);
      line.push_back(c);
    }
    line.push_back(E.node_positions[arc.upper]);
    for (std::size_t it = 0; it < options.smoothing_iterations && line.size() > 2; ++it) {
      std::vector<std::array<double, 3>> next = line;
      for (std::size_t j = 1; j + 1 < line.size(); ++j)
        for (int k = 0; k < 3; ++k)
          next[j][k] = (1 - options.smoothing_weight) * line[j][k] +
                       options.smoothing_weight * 0.5 * (line[j - 1][k] + line[j + 1][k]);
      line.swap(next);
    }
    E.arc_polylines.push_back(std::move(line));
  }
  return E;
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_EMBED_REEB_GRAPH_H
