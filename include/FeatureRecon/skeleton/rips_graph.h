// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_RIPS_GRAPH_H
#define FEATURERECON_SKELETON_RIPS_GRAPH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/Large_array_allocator.h>
#include <FeatureRecon/point_traits.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>
#include <FeatureRecon/skeleton/internal/exact_distance.h>
#include <FeatureRecon/skeleton/skeleton_options.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// Points as a dense row-major n x d matrix of doubles (the form every neighbour search works on).
struct Point_matrix {
  std::size_t rows = 0;                                                           ///< number of points
  std::size_t dimension = 0;                                                      ///< coordinates per point
  std::vector<double> data;                                                       ///< row-major coordinates
  const double* row(std::size_t i) const { return data.data() + i * dimension; }  ///< coordinates of point i
};

/// Copies the coordinates of `points` through `traits` into a Point_matrix.
/// \throws std::invalid_argument naming the first point whose dimension differs from the first point's,
/// that has dimension 0, or that has a NaN or infinite coordinate.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Point_matrix make_point_matrix(const PointRange& points, const Traits& traits = Traits(),
                               const char* caller = "make_point_matrix") {
  static_assert(
      FeatureRecon::internal::Is_point_coordinate_traits<Traits>::value,
      "FeatureRecon: Traits must model PointCoordinateTraits (doc/concepts/PointCoordinateTraits.h)");
  Point_matrix m;
  std::size_t i = 0;
  for (const auto& p : points) {
    const std::size_t d = traits.dimension(p);
    if (i == 0) {
      if (d == 0) FeatureRecon::internal::throw_invalid_argument(caller, "point 0 has dimension 0");
      m.dimension = d;
    } else if (d != m.dimension) {
      FeatureRecon::internal::throw_invalid_argument(caller, "point ", i, " has dimension ", d,
                                                     " but point 0 has dimension ", m.dimension);
    }
    for (std::size_t c = 0; c < d; ++c) {
      const double x = traits.coordinate(p, c);
      if (!std::isfinite(x))
        FeatureRecon::internal::throw_invalid_argument(caller, "point ", i, " has a non-finite coordinate ",
                                                       c, " (", x, ")");
      m.data.push_back(x);
    }
    ++i;
  }
  m.rows = i;
  return m;
}

namespace internal {

/// Checks a Point_matrix built by hand: rows * dimension values, dimension >= 1 when there are rows, every
/// coordinate finite (naming the point and coordinate).
inline void check_point_matrix(const Point_matrix& m, const char* fn, const char* name = "points") {
  const bool consistent = m.dimension == 0
                              ? m.data.empty()
                              : m.data.size() % m.dimension == 0 && m.data.size() / m.dimension == m.rows;
  if (!consistent)
    FeatureRecon::internal::throw_invalid_argument(fn, name, " has ", m.rows, " rows of dimension ",
                                                   m.dimension, " but ", m.data.size(), " values");
  if (m.rows > 0 && m.dimension == 0)
    FeatureRecon::internal::throw_invalid_argument(fn, name, " has dimension 0");
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t c = 0; c < m.dimension; ++c)
      if (!std::isfinite(m.row(i)[c]))
        FeatureRecon::internal::throw_invalid_argument(
            fn, name, ": point ", i, " has a non-finite coordinate ", c, " (", m.row(i)[c], ")");
}

/// \cond
using Kd_kernel = CGAL::Simple_cartesian<double>;
using Kd_point = Kd_kernel::Point_3;
using Kd_traits = CGAL::Search_traits_adapter<std::uint32_t, CGAL::Pointer_property_map<Kd_point>::type,
                                              CGAL::Search_traits_3<Kd_kernel>>;
using Kd_tree = CGAL::Kd_tree<Kd_traits>;

/// kd-tree over the first three coordinates (zero-padded) of a matrix of dimension <= 3, scaled by a power of
/// two (`unit`, exact) so that the largest has magnitude in [2^30, 2^31): CGAL's squared distances neither
/// overflow nor sink into subnormals (where their rounding is absolute and a pair within r could fall outside
/// the query ball). Radii and distances of the tree are in these units.
struct Kd_index {
  std::vector<Kd_point> points;
  std::vector<std::uint32_t> keys;
  std::unique_ptr<Kd_tree> tree;
  double unit = 1;
  explicit Kd_index(const Point_matrix& m) {
    double largest = 0;
    for (const double x : m.data) largest = std::max(largest, std::abs(x));
    unit = largest > 0 ? std::ldexp(1.0, std::clamp(30 - std::ilogb(largest), -1000, 1000)) : 1.0;
    points.reserve(m.rows);
    for (std::size_t i = 0; i < m.rows; ++i) {
      const double* r = m.row(i);
      points.emplace_back(r[0] * unit, m.dimension > 1 ? r[1] * unit : 0.0,
                          m.dimension > 2 ? r[2] * unit : 0.0);
    }
    keys.resize(m.rows);
    for (std::size_t i = 0; i < m.rows; ++i) keys[i] = static_cast<std::uint32_t>(i);
    tree = std::make_unique<Kd_tree>(keys.begin(), keys.end(), Kd_tree::Splitter(),
                                     Kd_traits(CGAL::make_property_map(points)));
    tree->build();
  }
  /// Candidates within (slightly more than) r of point i, r in the tree's units (`unit` times the points').
  /// CGAL's squared distances (to points and to the boxes of the tree's nodes, whose sides are coordinates of
  /// points or cut values that separate them) round each difference of two coordinates relative to that
  /// difference, whatever the coordinates' magnitude, and their squares and sums relative to the result: a
  /// relative 1e-9 covers them. The absolute 1e-150 covers coordinates that vanished in the scaling (a range
  /// beyond 2^1000).
  void ball(std::uint32_t i, double r, std::vector<std::uint32_t>& out) const {
    out.clear();
    CGAL::Fuzzy_sphere<Kd_traits> query(i, ball_radius(r), 0.0, tree->traits());
    tree->search(std::back_inserter(out), query);
  }
  /// The radius ball(i, r) searches. It does not grow with the coordinates: a slack of 1e-9 times the point's
  /// coordinates made the ball of a point at 1e12 two kilometres wide for a radius of metres (every point of
  /// a city a candidate of the exact test).
  static double ball_radius(double r) { return r * (1 + 1e-9) + 1e-150; }
};

/// All-pairs squared distances with Eigen, blockwise, from a single-precision Gram matrix (twice the SIMD
/// width of double). Each pair comes with a rigorous enclosure [lo, hi] of its true squared distance (derived
/// below), so that candidates can be filtered safely and then decided on the original doubles: by refine(), a
/// direct sum in double with its own enclosure, and where that cannot tell either, exactly.
///
/// The coordinates are centred at their coordinate-wise median: the Gram matrix's error grows with the
/// squared distance from the centre, and one outlier at 1e7 moved the mean by 1e3 for 10,000 points, which
/// made every pair of the others a candidate for the exact predicate (18x slower). Points more than 2^15
/// times the median point's distance (max-norm) from the centre are "far": they are left out of the float
/// matrix (zero columns), as they would set a scale at which the other coordinates lose their digits or
/// underflow in float; their pairs get the enclosure [-inf, inf] for the caller to refine(). The centred
/// halves (no overflow even next to the largest doubles) of the other points are scaled by a power of two so
/// that the largest has magnitude in [2^30, 2^31). Values are in scaled units: a true squared distance times
/// unit^2.
struct Brute_force_index {
  const Point_matrix& m;
  const std::uint32_t* rows = nullptr;  // the points indexed: rows[i] of m (nullptr: all, in order)
  std::size_t size = 0;                 // how many
  /// Coordinates of indexed point i.
  const double* point(std::size_t i) const { return m.row(rows ? rows[i] : i); }
  Eigen::MatrixXf centred;     // d x n, (halves minus the centre's half) * scale, rounded to float; 0 if far
  Eigen::VectorXd norms;       // squared norms of the float columns, in double (exact products)
  std::vector<double> weight;  // per point i, its part w_i of the Gram error bound (see block()); inf if far
  std::vector<char> far;       // 1 for a point left out of the float matrix
  std::vector<double> half_centre;                  // the coordinate-wise median, halved
  double scale = 1;                                 // applied to the centred halves (a power of two)
  double unit = 1;                                  // scale / 2: applied to differences of whole coordinates
  double pair_constant = 0;                         // the part of the Gram error bound common to all pairs
  double refine_relative = 0, refine_absolute = 0;  // refine()'s error bound
  mutable std::vector<float> gram_buffer;           // gram()'s products
  mutable std::size_t gram_columns = 0;             // per row of gram_buffer
  /// Indexes every point of `pm`, or the `subset` rows of it (ascending; the index numbers them 0, 1, ...).
  explicit Brute_force_index(const Point_matrix& pm, const std::vector<std::uint32_t>* subset = nullptr)
      : m(pm), rows(subset ? subset->data() : nullptr), size(subset ? subset->size() : pm.rows) {
    const std::size_t n = size, d = m.dimension;
    centred.resize(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(n));
    far.assign(n, 0);
    half_centre.assign(d, 0.0);
    std::vector<double> column(n);
    if (n > 0)
      for (std::size_t c = 0; c < d; ++c) {
        for (std::size_t i = 0; i < n; ++i) column[i] = point(i)[c];
        std::nth_element(column.begin(), column.begin() + static_cast<std::ptrdiff_t>(n / 2), column.end());
        half_centre[c] = column[n / 2] / 2;
      }
    const auto half_offset = [&](std::size_t i, std::size_t c) { return point(i)[c] / 2 - half_centre[c]; };
    for (std::size_t i = 0; i < n; ++i) {
      column[i] = 0;
      for (std::size_t c = 0; c < d; ++c) column[i] = std::max(column[i], std::abs(half_offset(i, c)));
    }
    const std::vector<double> reach = column;  // max-norm distance of each point from the centre, halved
    double typical = 0;
    if (n > 0) {
      std::nth_element(column.begin(), column.begin() + static_cast<std::ptrdiff_t>(n / 2), column.end());
      typical = column[n / 2];
    }
    const double u = std::ldexp(1.0, -24), v = std::ldexp(1.0, -53), eta = std::ldexp(1.0, -150);
    const double dd = static_cast<double>(d);
    // With 2^23 coordinates or more the float dot products carry no digit: every pair is refined in double.
    const bool float_useless = dd * u >= 0.5;
    const double far_limit = typical > 0 ? std::ldexp(typical, 15) : std::numeric_limits<double>::infinity();
    double largest = 0;
    for (std::size_t i = 0; i < n; ++i) {
      far[i] = float_useless || reach[i] > far_limit;
      if (!far[i]) largest = std::max(largest, reach[i]);
    }
    const int exponent = largest > 0 ? std::clamp(30 - std::ilogb(largest), -1000, 1000) : 0;
    scale = std::ldexp(1.0, exponent);
    unit = std::ldexp(1.0, exponent - 1);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < d; ++c)
        centred(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(i)) =
            far[i] ? 0.0f : static_cast<float>(half_offset(i, c) * scale);
    norms = centred.cast<double>().colwise().squaredNorm().transpose();
    // The float enclosure. Notation: u = 2^-24 and v = 2^-53 the unit roundoffs of float and double, eta =
    // 2^-150 half the smallest float (the absolute error of a float rounding in the subnormal range), a =
    // (x_i - x_j) unit the true scaled difference, f_i the float column of point i, s_i = |f_i|, N_i = s_i^2,
    // gamma_k = k u / (1 - k u). Every constant below is at least twice what the step needs; the slack also
    // covers the roundings of computing the bound, d2 - err and d2 + err (relative 2^-53 of values at most 2
    // (N_i + N_j), while err >= 2^-21 (N_i + N_j)).
    // 1. Coordinates: f = float(y), |f - y| <= u |y| + eta, where y = (x / 2 - h) scale is computed in
    // double: the
    //    subtraction (relative v; the centre h is common to both points and cancels), x / 2 (absolute 2^-1075
    //    for subnormal x) and the scaling (absolute 2^-1075 if it underflows). So per coordinate
    //    |(f_i - f_j) - a| <= alpha (|f_i| + |f_j|) + beta, alpha = 2^-23 >= (u + v) / (1 - u), and
    //    beta = 4 eta + 2^-1072 max(scale, 1); over all coordinates (Minkowski) the error e = f_i - f_j - a
    //    has E = |e| <= alpha (s_i + s_j) + b, b = beta sqrt(d).
    // 2. Gram: d2 = (n_i + n_j) - 2 g with n_i the double sum of exact squares (error <= (d - 1) v N_i), g
    // the float
    //    dot product (error <= gamma_d s_i s_j + (1 + gamma_d) d eta: d roundings, each relative or,
    //    underflowing, at most eta) and two double roundings: |d2 - |f_i - f_j|^2| <= G = g_rel (N_i + N_j) +
    //    g_abs, g_rel = 2 (gamma_d + (d + 5) v), g_abs = 4 d eta. Without the absolute terms, products of
    //    coordinates near the centre that underflow in float (data spread 2^100 times their spacing) made d2
    //    overestimate a pair at exactly the radius, and it was rejected before the exact test.
    // 3. |a|^2 - |f_i - f_j|^2 = -(2 a.e + |e|^2), |a| <= s_i + s_j + E: the difference is at most
    //    2 (s_i + s_j) E + 3 E^2 <= 4 alpha (N_i + N_j) + 2 b (s_i + s_j) + 12 alpha^2 (N_i + N_j) + 6 b^2
    //    (using (s_i + s_j)^2 <= 2 (N_i + N_j) and (p + q)^2 <= 2 p^2 + 2 q^2).
    // Altogether |true - d2| <= err = w_i + w_j + pair_constant, w_i = K N_i + 2 b s_i, K = g_rel + 4 alpha +
    // 12 alpha^2, pair_constant = g_abs + 6 b^2.
    const double gamma_d = float_useless ? 0.0 : dd * u / (1 - dd * u);
    const double alpha = std::ldexp(1.0, -23);
    const double beta = 4 * eta + std::ldexp(1.0, -1072 + std::max(exponent, 0));
    const double b = beta * std::sqrt(dd);
    const double K = 2 * (gamma_d + (dd + 5) * v) + 4 * alpha + 12 * alpha * alpha;
    pair_constant = 4 * dd * eta + 6 * b * b;
    weight.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double ni = norms[static_cast<Eigen::Index>(i)];
      // A far point's pairs have no float enclosure: an infinite weight makes every bound of its pairs
      // infinite.
      weight[i] = far[i] ? std::numeric_limits<double>::infinity() : K * ni + 2 * b * std::sqrt(ni);
    }
    // refine() sums t_c^2, t_c = (x_i / 2 - x_j / 2) scale in double, scaled so that neither the squares of
    // far pairs overflow nor those of near ones underflow. t_c = a_c (1 + delta) + kappa_c with |delta| <= v
    // (the subtraction) and |kappa_c| <= kappa = 2^-1073 max(scale, 1) (the halvings, and the scaling if it
    // underflows), so |t| differs from |a| by at most v |a| + k, k = kappa sqrt(d) <= 2^-72 sqrt(d); each
    // square has an absolute error up to 2^-1075 if it underflows and the sum a relative gamma_(d-1). With 2
    // k |t| <= k (1 + |t|^2): |true - s| <= refine_relative s + refine_absolute, refine_relative = 2 (d + 5)
    // v, refine_absolute = d 2^-1074 + 4 k (twice what is needed, which covers computing s (1 +-
    // refine_relative)).
    refine_relative = 2 * (dd + 5) * v;
    refine_absolute =
        dd * std::ldexp(1.0, -1074) + 4 * std::ldexp(1.0, -1073 + std::max(exponent, 0)) * std::sqrt(dd);
  }
  /// Computes the float Gram products of the indexed points [b, e) with [from, size) into gram_buffer: the
  /// products of point b + r start at gram_row(r), one float per point from `from` on (contiguous, so that a
  /// row's pairs are read in order). One buffer for every block (the first is the largest): a fresh 5 MB
  /// matrix per block of 5,000 points in 50-D went back to the system and was faulted in again whenever the
  /// allocator trimmed its heap.
  void gram(std::size_t b, std::size_t e, std::size_t from) const {
    const Eigen::Index nb = static_cast<Eigen::Index>(e - b);
    const Eigen::Index nc = static_cast<Eigen::Index>(size - from);
    const std::size_t cells = static_cast<std::size_t>(nb) * static_cast<std::size_t>(nc);
    if (gram_buffer.size() < cells) gram_buffer.resize(cells);
    gram_columns = static_cast<std::size_t>(nc);
    Eigen::Map<Eigen::MatrixXf> g(gram_buffer.data(), nc, nb);
    g.noalias() = centred.middleCols(static_cast<Eigen::Index>(from), nc).transpose() *
                  centred.middleCols(static_cast<Eigen::Index>(b), nb);
  }
  /// gram() for the indexed points rows[0, count) (any order) against all: the products of rows[r] start at
  /// gram_row(r).
  void gram_of(const std::uint32_t* list, std::size_t count) const {
    Eigen::MatrixXf gathered(centred.rows(), static_cast<Eigen::Index>(count));
    for (std::size_t r = 0; r < count; ++r)
      gathered.col(static_cast<Eigen::Index>(r)) = centred.col(static_cast<Eigen::Index>(list[r]));
    const std::size_t cells = count * size;
    if (gram_buffer.size() < cells) gram_buffer.resize(cells);
    gram_columns = size;
    Eigen::Map<Eigen::MatrixXf> g(gram_buffer.data(), static_cast<Eigen::Index>(size),
                                  static_cast<Eigen::Index>(count));
    g.noalias() = centred.transpose() * gathered;
  }
  /// The products of the r-th point of the last gram() block with the points from its `from` on.
  const float* gram_row(std::size_t r) const { return gram_buffer.data() + r * gram_columns; }
  /// Calls visit(i, j, lo, hi), lo <= the true squared distance (scaled) <= hi, for every i in [b, e) and
  /// every j >= from. Pairs with a far point get [-inf, inf].
  template <class Visit>
  void block(std::size_t b, std::size_t e, std::size_t from, Visit visit) const {
    gram(b, e, from);
    const double inf = std::numeric_limits<double>::infinity();
    for (std::size_t i = b; i < e; ++i) {
      const float* g = gram_row(i - b);
      const double ni = norms[static_cast<Eigen::Index>(i)], wi = weight[i] + pair_constant;
      for (std::size_t j = from; j < size; ++j) {
        if (far[i] || far[j]) {
          visit(i, j, -inf, inf);
          continue;
        }
        const double d2 = ni + norms[static_cast<Eigen::Index>(j)] - 2 * static_cast<double>(g[j - from]);
        const double err = wi + weight[j];
        visit(i, j, d2 - err, d2 + err);
      }
    }
  }
  /// Narrows the enclosure [lo, hi] of the squared distance of points i and j (scaled) by one from a direct
  /// sum in double: about 2 d 2^-53 wide relative to it, where the float one is wide relative to the data's
  /// spread.
  void refine(std::size_t i, std::size_t j, double& lo, double& hi) const {
    const double *p = point(i), *q = point(j);
    double s = 0;
    for (std::size_t c = 0; c < m.dimension; ++c) {
      const double t = (p[c] / 2 - q[c] / 2) * scale;
      s += t * t;
    }
    if (!(s <
          std::numeric_limits<double>::infinity())) {  // the true value is about the largest double or more
      lo = std::max(lo, std::numeric_limits<double>::max() / 2);
      return;
    }
    const double err = refine_relative * s + refine_absolute;
    lo = std::max(lo, s - err);
    hi = std::min(hi, s + err);
  }
};

/// The coordinate whose values over the points `set` of m have the widest range, and that range (0 for fewer
/// than two points, inf when it overflows). lo and hi are work space.
inline std::pair<std::size_t, double> widest_axis(const Point_matrix& m,
                                                  const std::vector<std::uint32_t>& set,
                                                  std::vector<double>& lo, std::vector<double>& hi) {
  const std::size_t d = m.dimension;
  std::size_t axis = 0;
  double widest = 0;
  if (set.size() < 2) return {axis, widest};
  lo.assign(m.row(set[0]), m.row(set[0]) + d);  // row by row: the matrix is row-major
  hi = lo;
  for (const std::uint32_t i : set)
    for (std::size_t c = 0; c < d; ++c) {
      lo[c] = std::min(lo[c], m.row(i)[c]);
      hi[c] = std::max(hi[c], m.row(i)[c]);
    }
  for (std::size_t c = 0; c < d; ++c)
    if (hi[c] - lo[c] > widest) {  // inf when the range overflows: still the widest
      widest = hi[c] - lo[c];
      axis = c;
    }
  return {axis, widest};
}

/// The points split into groups that no pair within `radius` crosses: a set is cut wherever its values of the
/// coordinate with the widest range leave a gap wider than the radius (two points on either side differ by
/// more than the radius in that coordinate alone), and each part is cut again the same way until nothing
/// cuts. Only that one axis is sorted per set, so the split costs O(n (d + log n)) per level and may miss
/// gaps on other axes (a search optimisation, not a clustering). For the brute force: its float filter
/// centres the Gram matrix at one point, and a second cluster far away made every pair of that cluster go to
/// the double stage. Groups hold ascending indices and come in the order of their first index; all points
/// form one group when nothing cuts.
inline std::vector<std::vector<std::uint32_t>> separated_groups(const Point_matrix& m, double radius) {
  const std::size_t n = m.rows;
  std::vector<std::vector<std::uint32_t>> done, todo(1);
  todo[0].resize(n);
  for (std::size_t i = 0; i < n; ++i) todo[0][i] = static_cast<std::uint32_t>(i);
  // A computed difference b - a (b >= a) rounds by a relative 2^-53 at most, and it is not 0 unless b == a:
  // when it exceeds radius (1 + 2^-50), the true difference exceeds the radius.
  const double gap_limit = radius * (1 + 0x1p-50);
  std::vector<std::pair<double, std::uint32_t>> key;
  std::vector<double> lo, hi;  // the coordinates' ranges over a set
  while (!todo.empty()) {
    std::vector<std::uint32_t> set = std::move(todo.back());
    todo.pop_back();
    const auto [axis, widest] = widest_axis(m, set, lo, hi);
    if (!(widest > gap_limit)) {  // no gap can be wider than the range
      done.push_back(std::move(set));
      continue;
    }
    key.clear();
    for (const std::uint32_t i : set) key.emplace_back(m.row(i)[axis], i);
    std::sort(key.begin(), key.end());
    std::vector<std::vector<std::uint32_t>> parts(1);
    for (std::size_t k = 0; k < key.size(); ++k) {
      if (k > 0 && key[k].first - key[k - 1].first > gap_limit) parts.emplace_back();
      parts.back().push_back(key[k].second);
    }
    if (parts.size() == 1) {
      done.push_back(std::move(set));
      continue;
    }
    for (std::vector<std::uint32_t>& part : parts) {
      std::sort(part.begin(), part.end());
      todo.push_back(std::move(part));
    }
  }
  std::sort(done.begin(), done.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });
  return done;
}

/// A group of isolated_groups(): its points (ascending) and a lower bound on the distance from any of them to
/// any point outside the group (the largest double when nothing is outside).
struct Isolated_group {
  std::vector<std::uint32_t> rows;
  double separation = std::numeric_limits<double>::max();
};

/// The points split for the k-nearest-neighbour brute force, which has no radius to cut at: a set is cut at
/// the gaps of the sorted values of its widest coordinate that exceed 1/16 of that coordinate's range and the
/// extent (widest coordinate range) of the parts on both sides, when both parts have at least `min_size`
/// points (k + 1: a smaller one could not answer for any of its points; parts between rejected gaps are one
/// part), and each part is cut again the same way. A part's separation is the smallest of its parent's and
/// its adjacent gaps. Clusters far apart relative to their own size end up in groups of their own, whose
/// float filters then have their own centres; grids, evenly spaced lines and spread-out data are not cut
/// (their gaps are not wider than the parts beside them, or those hold too few points). The cut is a
/// heuristic for speed (it looks at one axis per set, so it may miss gaps on others): the search keeps a
/// group's answer for a point only when its k-th nearest within the group lies within the separation, and
/// searches the other points among all. Groups hold ascending indices and come in the order of their first
/// index; each level sorts its sets once along one axis.
inline std::vector<Isolated_group> isolated_groups(const Point_matrix& m, std::size_t min_size) {
  const std::size_t n = m.rows;
  if (n == 0) return {};
  std::vector<Isolated_group> done, todo(1);
  todo[0].rows.resize(n);
  for (std::size_t i = 0; i < n; ++i) todo[0].rows[i] = static_cast<std::uint32_t>(i);
  std::vector<std::pair<double, std::uint32_t>> key;
  std::vector<double> lo, hi, gaps, extents;
  std::vector<std::size_t> starts;  // of the parts, in key
  std::vector<std::uint32_t> part;
  while (!todo.empty()) {
    Isolated_group set = std::move(todo.back());
    todo.pop_back();
    const std::size_t size = set.rows.size();
    if (size < 2 * min_size) {  // no cut leaves min_size on both sides
      done.push_back(std::move(set));
      continue;
    }
    const auto [axis, widest] = widest_axis(m, set.rows, lo, hi);
    key.clear();
    for (const std::uint32_t i : set.rows) key.emplace_back(m.row(i)[axis], i);
    std::sort(key.begin(), key.end());
    starts.assign(1, 0);
    gaps.clear();
    for (std::size_t t = 1; t < size; ++t)
      if (key[t].first - key[t - 1].first > widest / 16) {
        starts.push_back(t);
        gaps.push_back(key[t].first - key[t - 1].first);
      }
    starts.push_back(size);
    extents.clear();
    for (std::size_t q = 0; q + 1 < starts.size() && !gaps.empty(); ++q) {
      part.clear();
      for (std::size_t t = starts[q]; t < starts[q + 1]; ++t) part.push_back(key[t].second);
      extents.push_back(widest_axis(m, part, lo, hi).second);
    }
    bool cut = false;
    for (std::size_t q = 0; q < gaps.size(); ++q) {
      // The computed difference rounds by a relative 2^-53 at most: the true gap exceeds gap (1 - 2^-50)
      // (strictly).
      const bool kept = gaps[q] > std::max(extents[q], extents[q + 1]) &&
                        starts[q + 1] - starts[q] >= min_size && starts[q + 2] - starts[q + 1] >= min_size;
      // Subnormal gaps are exact and gap (1 - 2^-50) rounds back to them: one step down keeps the bound
      // strict.
      gaps[q] = kept ? std::nextafter(gaps[q] * (1 - 0x1p-50), 0.0) : 0.0;
      cut = cut || gaps[q] > 0;
    }
    if (!cut) {
      done.push_back(std::move(set));
      continue;
    }
    Isolated_group next;
    next.separation = set.separation;
    for (std::size_t q = 0; q + 1 < starts.size(); ++q) {
      for (std::size_t t = starts[q]; t < starts[q + 1]; ++t) next.rows.push_back(key[t].second);
      if (q < gaps.size() && gaps[q] == 0) continue;  // not cut here: the part goes on
      if (q < gaps.size()) next.separation = std::min(next.separation, gaps[q]);
      std::sort(next.rows.begin(), next.rows.end());
      todo.push_back(std::move(next));
      next = Isolated_group();
      next.separation = q < gaps.size() ? std::min(set.separation, gaps[q]) : set.separation;
    }
  }
  std::sort(done.begin(), done.end(),
            [](const auto& a, const auto& b) { return a.rows.front() < b.rows.front(); });
  return done;
}

/// Keeps in `cand` the `keep` points of m nearest to p (exact squared distances, ties by index), nearest
/// first (with `ordered` false, a list of at most `keep` is left as it is: all of it is kept). Each
/// candidate's squared distance is enclosed once in interval arithmetic (one rounding-mode switch for all);
/// sorted by the lower ends, only runs of overlapping enclosures that are not all the same exact value (a
/// tie, which the index decides) are ordered by the exact predicate. On integer grids every enclosure is
/// exact: no predicate runs at all, where ordering by the predicate took a rounding-mode switch per
/// comparison.
inline void keep_nearest_exactly(const Point_matrix& m, const double* p, std::vector<std::uint32_t>& cand,
                                 std::size_t keep, bool ordered = true) {
  if (!ordered && cand.size() <= keep) return;
  struct Key {
    double lo, hi;
    std::uint32_t j;
  };
  thread_local std::vector<Key> keys;
  keys.clear();
  {
    CGAL::Protect_FPU_rounding<true> protect;
    for (const std::uint32_t j : cand) {
      CGAL::Interval_nt<false> s(0);
      for (std::size_t c = 0; c < m.dimension; ++c)
        s += CGAL::square(CGAL::Interval_nt<false>(p[c]) - m.row(j)[c]);
      keys.push_back(Key{s.inf(), s.sup(), j});
    }
  }
  std::sort(keys.begin(), keys.end(),
            [](const Key& a, const Key& b) { return a.lo < b.lo || (a.lo == b.lo && a.j < b.j); });
  const std::size_t size = keys.size();
  for (std::size_t start = 0; start < size && start < keep;) {
    std::size_t end = start + 1;
    double reach = keys[start].hi;
    bool ties_only = keys[start].lo == keys[start].hi;
    while (end < size && keys[end].lo <= reach) {
      ties_only = ties_only && keys[end].lo == keys[end].hi && keys[end].lo == keys[start].lo;
      reach = std::max(reach, keys[end].hi);
      ++end;
    }
    if (end - start > 1 && !ties_only)
      std::sort(keys.begin() + static_cast<std::ptrdiff_t>(start),
                keys.begin() + static_cast<std::ptrdiff_t>(end), [&](const Key& a, const Key& b) {
                  const int c = compare_squared_distances(p, m.row(a.j), m.row(b.j), m.dimension);
                  return c < 0 || (c == 0 && a.j < b.j);
                });
    start = end;
  }
  cand.resize(std::min(keep, size));
  for (std::size_t t = 0; t < cand.size(); ++t) cand[t] = keys[t].j;
}

inline bool use_kd_tree(const Point_matrix& m, Neighbor_search s, const char* fn) {
  if (s == Neighbor_search::kd_tree && m.dimension > 3)
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the kd-tree search (options.search = Neighbor_search::kd_tree) supports dimension <= 3, got ",
        m.dimension, ": use automatic or brute_force");
  return s == Neighbor_search::kd_tree || (s == Neighbor_search::automatic && m.dimension <= 3);
}

/// Euclidean distance of two points of `dimension` coordinates, exact to rounding at every scale: when the
/// squares overflow or lose their digits, scaled by the largest difference, as hypot does (inf only when the
/// distance itself exceeds the largest double).
inline double point_distance(const double* p, const double* q, std::size_t dimension) {
  double s = 0;
  for (std::size_t c = 0; c < dimension; ++c) s += (p[c] - q[c]) * (p[c] - q[c]);
  if (s < std::numeric_limits<double>::infinity() && !(s < 1e-280)) return std::sqrt(s);
  double a = 0;
  for (std::size_t c = 0; c < dimension; ++c) a = std::max(a, std::fabs(p[c] - q[c]));
  s = 0;
  if (a > 0 && a < std::numeric_limits<double>::infinity()) {
    for (std::size_t c = 0; c < dimension; ++c) s += ((p[c] - q[c]) / a) * ((p[c] - q[c]) / a);
    return a * std::sqrt(s);
  }
  if (!(a > 0)) return 0;
  // A difference of two finite coordinates overflowed (1e308 and -1e308): the halves' differences do not.
  // This returned inf * sqrt(0), NaN, and a NaN edge length hung the embedding's shortest paths.
  a = 0;
  for (std::size_t c = 0; c < dimension; ++c) a = std::max(a, std::fabs(p[c] / 2 - q[c] / 2));
  for (std::size_t c = 0; c < dimension; ++c) s += ((p[c] / 2 - q[c] / 2) / a) * ((p[c] / 2 - q[c] / 2) / a);
  return 2 * (a * std::sqrt(s));  // inf when the distance exceeds the largest double
}

inline void add_edge_lengths(const Point_matrix& m, Proximity_graph& g, const char* fn) {
  g.edge_lengths.resize(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    g.edge_lengths[e] = point_distance(m.row(g.edges[e][0]), m.row(g.edges[e][1]), m.dimension);
    if (!(g.edge_lengths[e] < std::numeric_limits<double>::infinity()))
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", e, " (points ", g.edges[e][0], " and ",
                                                     g.edges[e][1], ") is longer than the largest double");
  }
}
/// \endcond

}  // namespace internal

namespace internal {
/// What the Rips search left to its slower stages (for tests: the work an outlier or extreme coordinates
/// cause).
struct Rips_search_counts {
  /// pairs the brute force's float enclosure could not decide, computed again in double
  std::size_t refined = 0;
  std::size_t exact = 0;  ///< pairs decided by the exact predicate
};

/// build_rips_graph() of a Point_matrix, counting its slow stages into `counts` (if not null).
inline Proximity_graph rips_graph(const Point_matrix& m, double radius,
                                  const Proximity_graph_options& options, Rips_search_counts* counts) {
  const char* fn = "build_rips_graph";
  if (!(std::isfinite(radius) && radius >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and >= 0, got ", radius);
  internal::check_point_matrix(m, fn);
  Proximity_graph g;
  g.number_of_vertices = m.rows;
  if (m.rows > std::numeric_limits<Vertex_index>::max())
    FeatureRecon::internal::throw_invalid_argument(fn, "too many points (", m.rows, ")");
  const std::size_t n = m.rows;
  const std::size_t report_every = std::max<std::size_t>(1, n / 100);
  bool stopped = false;  // no report after the callback asked to stop
  Rips_search_counts count;
  if (counts) *counts = count;
  if (internal::use_kd_tree(m, options.search, fn)) {
    if (n == 0) return g;
    internal::Kd_index index(m);
    std::vector<std::uint32_t> found;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (i % report_every == 0 &&
          !FeatureRecon::internal::report_progress(options.progress, static_cast<double>(i) / n)) {
        stopped = true;
        break;
      }
      index.ball(i, radius * index.unit, found);  // infinity when that overflows: every point a candidate
      std::sort(found.begin(), found.end());
      for (std::uint32_t j : found)
        if (j > i && (++count.exact, internal::distance_at_most(m.row(i), m.row(j), m.dimension, radius)))
          g.edges.push_back(Edge{i, j});
    }
  } else {
    // Each group of points that no edge crosses is searched alone, with its own centre (separated_groups()).
    const std::vector<std::vector<std::uint32_t>> groups = internal::separated_groups(m, radius);
    double pairs = 0, pairs_done = 0;  // for the progress reports
    for (const auto& group : groups)
      pairs += static_cast<double>(group.size()) * static_cast<double>(group.size());
    // The edges among the points of a group (nullptr: all points).
    auto search = [&](const std::vector<std::uint32_t>* group) {
      internal::Brute_force_index index(m, group);
      const std::size_t k = index.size, block = 256;
      // The radius squared in the index's units, as an enclosure: radius * unit is exact unless it overflows
      // (then infinite, as when its square overflows, and so is r2_lo: every finite upper bound is within) or
      // underflows (absolute 2^-1075, far below the 2^-1074 added); the square rounds by a relative 2^-53.
      const double rs = radius * index.unit, r2 = rs * rs;
      const double r2_lo = r2 * (1 - 0x1p-50) - 0x1p-1074, r2_hi = r2 * (1 + 0x1p-50) + 0x1p-1074;
      for (std::size_t b = 0; b < k; b += block) {
        // Rows [b, b + block) of a group of k cost about (k - b) * block of its k^2 / 2 pairs.
        const double fraction =
            1 - static_cast<double>(k - b) * static_cast<double>(k - b) / (double(k) * double(k));
        if (!FeatureRecon::internal::report_progress(
                options.progress, (pairs_done + fraction * double(k) * double(k)) / pairs)) {
          stopped = true;
          return;
        }
        index.block(b, std::min(k, b + block), b, [&](std::size_t i, std::size_t j, double lo, double hi) {
          if (j <= i || lo > r2_hi) return;
          if (!(hi < r2_lo)) {  // the float enclosure straddles the radius: in double, then exactly
            ++count.refined;
            index.refine(i, j, lo, hi);
            if (lo > r2_hi) return;
            if (!(hi < r2_lo) && (++count.exact, !internal::distance_at_most(index.point(i), index.point(j),
                                                                             m.dimension, radius)))
              return;
          }
          // The group is ascending: i < j stays.
          g.edges.push_back(group ? Edge{(*group)[i], (*group)[j]}
                                  : Edge{static_cast<Vertex_index>(i), static_cast<Vertex_index>(j)});
        });
      }
      pairs_done += static_cast<double>(k) * static_cast<double>(k);
    };
    if (groups.size() == 1) {
      search(nullptr);
    } else {
      for (const auto& group : groups) {
        if (group.size() > 1) search(&group);
        if (stopped) break;
      }
      std::sort(g.edges.begin(), g.edges.end());
    }
  }
  internal::add_edge_lengths(m, g, fn);
  if (!stopped) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  if (stopped) g.status = Status::interrupted;
  if (counts) *counts = count;
  return g;
}
}  // namespace internal

/// Rips graph of the rows of a Point_matrix (see the range version of build_rips_graph()).
inline Proximity_graph build_rips_graph(const Point_matrix& m, double radius,
                                        const Proximity_graph_options& options = {}) {
  return internal::rips_graph(m, radius, options, nullptr);
}

namespace internal {
/// What the brute-force k-nearest-neighbour search left to its slower stages (for tests).
struct Knn_search_counts {
  std::size_t refined = 0;       ///< pairs whose float enclosure was too wide, computed again in double
  std::size_t unresolved = 0;    ///< points whose group could not answer alone, searched among all points
  std::size_t ball_queries = 0;  ///< kd-tree: positions whose k-th nearest had no clear gap after it (ties)
};

/// build_knn_graph() of a Point_matrix, counting its slow stages into `counts` (if not null).
inline Proximity_graph knn_graph(const Point_matrix& m, std::size_t k, const Proximity_graph_options& options,
                                 Knn_search_counts* counts) {
  const char* fn = "build_knn_graph";
  Knn_search_counts count;
  if (counts) *counts = count;
  if (k < 1) FeatureRecon::internal::throw_invalid_argument(fn, "k must be >= 1, got ", k);
  internal::check_point_matrix(m, fn);
  const std::size_t n = m.rows;
  Proximity_graph g;
  g.number_of_vertices = n;
  if (n > std::numeric_limits<Vertex_index>::max())
    FeatureRecon::internal::throw_invalid_argument(fn, "too many points (", n, ")");
  const std::size_t kk = std::min(k, n == 0 ? 0 : n - 1);
  std::vector<std::uint32_t> cand;
  // Keeps the kk nearest candidates of point i (exact distance, then index); nearest first if `ordered`.
  auto keep_nearest = [&](std::size_t i, bool ordered) {
    internal::keep_nearest_exactly(m, m.row(i), cand, kk, ordered);
  };
  auto add_edges = [&](std::size_t i) {
    for (const std::uint32_t j : cand) {
      const Vertex_index a = static_cast<Vertex_index>(i), b = j;
      g.edges.push_back(a < b ? Edge{a, b} : Edge{b, a});
    }
  };
  if (kk == 0) return g;
  g.edges.reserve(n * kk);  // each point adds its kk (the symmetric duplicates go at the end)
  bool stopped = false;     // no report after the callback asked to stop
  if (internal::use_kd_tree(m, options.search, fn)) {
    // Copies of a position are searched once: the kd-tree holds the distinct positions, each with its copies
    // (by index). A point's neighbours are the other copies of its position first (distance 0, by index),
    // then the nearest of the other positions, each contributing its lowest-index copies. A position with
    // more than k copies needs no search at all (D copies used to cost O(D^2)).
    std::vector<std::uint32_t> by_position(n);
    for (std::uint32_t i = 0; i < n; ++i) by_position[i] = i;
    std::sort(by_position.begin(), by_position.end(), [&m](std::uint32_t a, std::uint32_t b) {
      const double *p = m.row(a), *q = m.row(b);
      const auto [pa, qa] = std::mismatch(p, p + m.dimension, q);
      return pa != p + m.dimension ? *pa < *qa : a < b;  // by coordinates, copies by index
    });
    std::vector<std::size_t> first{0};  // group g holds by_position[first[g] .. first[g + 1])
    for (std::size_t t = 1; t < n; ++t)
      if (!std::equal(m.row(by_position[t]), m.row(by_position[t]) + m.dimension, m.row(by_position[t - 1])))
        first.push_back(t);
    first.push_back(n);
    const std::size_t groups = first.size() - 1;
    Point_matrix distinct;
    distinct.dimension = m.dimension;
    distinct.rows = groups;
    for (std::size_t q = 0; q < groups; ++q)
      distinct.data.insert(distinct.data.end(), m.row(by_position[first[q]]),
                           m.row(by_position[first[q]]) + m.dimension);
    internal::Kd_index index(distinct);
    using Knn = CGAL::Orthogonal_k_neighbor_search<internal::Kd_traits>;
    using Distance = Knn::Distance;
    Distance dist(index.tree->traits().point_property_map());
    const std::size_t report_groups = std::max<std::size_t>(1, groups / 100);
    std::vector<std::uint32_t> outside, near_groups;
    for (std::uint32_t q = 0; q < groups; ++q) {
      if (q % report_groups == 0 &&
          !FeatureRecon::internal::report_progress(options.progress, static_cast<double>(q) / groups)) {
        stopped = true;
        break;
      }
      const std::size_t copies = first[q + 1] - first[q];
      const std::size_t need = kk + 1 > copies ? kk + 1 - copies : 0;  // neighbours from other positions
      outside.clear();
      if (need > 0 && groups > 1) {
        // The nearest positions until their copies add up to `need`; their farthest distance bounds the ball
        // that holds every position tied with the last one needed. The search asks for one position more:
        // when it lies clearly beyond that ball (and so does every position not reported, no nearer than it),
        // the positions reported before it are exactly what the ball would hold, and the ball query is
        // skipped.
        double far = 0, next = -1;  // squared, in the tree's units; next: the position after them (-1: none)
        near_groups.clear();
        for (std::size_t K = std::min(groups, need + 2);; K = std::min(groups, 2 * K)) {
          Knn search(*index.tree, index.points[q], static_cast<unsigned>(K), 0.0, true, dist);
          std::size_t found = 0;
          far = 0;
          next = -1;
          near_groups.clear();
          for (const auto& nb : search) {
            if (nb.first == q) continue;
            if (found >= need) {
              next = nb.second;
              break;
            }
            found += first[nb.first + 1] - first[nb.first];
            far = std::max(far, nb.second);
            near_groups.push_back(nb.first);
          }
          if (found >= need || K == groups) break;
        }
        const double reach = internal::Kd_index::ball_radius(std::sqrt(far));
        if (!(next > reach * reach * (1 + 0x1p-40)) || !(far >= 0x1p-900)) {
          index.ball(q, std::sqrt(far), near_groups);
          ++count.ball_queries;
        }
        for (const std::uint32_t r : near_groups)
          if (r != q)
            for (std::size_t t = first[r]; t < std::min(first[r + 1], first[r] + need); ++t)
              outside.push_back(by_position[t]);
        cand = outside;
        internal::keep_nearest_exactly(m, m.row(by_position[first[q]]), cand, need, false);
      } else {
        cand.clear();
      }
      for (std::size_t t = first[q]; t < first[q + 1]; ++t) {
        const Vertex_index i = by_position[t];
        std::size_t taken = 0;
        for (std::size_t u = first[q]; u < first[q + 1] && taken < kk; ++u)  // other copies, by index
          if (by_position[u] != i) {
            g.edges.push_back(i < by_position[u] ? Edge{i, by_position[u]} : Edge{by_position[u], i});
            ++taken;
          }
        for (std::size_t u = 0; u < cand.size() && taken < kk; ++u, ++taken)
          g.edges.push_back(i < cand[u] ? Edge{i, cand[u]} : Edge{cand[u], i});
      }
    }
  } else {
    // Blocked all-pairs distances (Brute_force_index), a row at a time: the k-th smallest upper bound of a
    // row is at least the k-th smallest distance, so a point whose lower bound exceeds it has k points
    // strictly nearer and is no candidate; the few others are ordered exactly. Groups of points far from the
    // rest (isolated_groups()) are searched alone, each with its own float filter: one centre for two
    // clusters 1e7 apart made every pair of one of them too uncertain in float. A group's answer for a point
    // stands when the k-th nearest within the group lies within the group's separation (everything outside is
    // farther); other points are searched among all.
    struct Enclosure {
      double lo, hi;  // of the squared distance to j, in the index's units
      std::uint32_t j;
    };
    std::vector<Enclosure> row;
    std::vector<double> d2, hi, heap, upper;
    const double inf = std::numeric_limits<double>::infinity();
    const auto kth_upper = [&] {
      upper.clear();
      for (const Enclosure& x : row) upper.push_back(x.hi);
      std::nth_element(upper.begin(), upper.begin() + static_cast<std::ptrdiff_t>(kk - 1), upper.end());
      return upper[kk - 1];
    };
    // The candidates of indexed point i from its row of float Gram products `gp` (one per indexed point): the
    // k-th smallest upper bound by a heap of the k smallest, then every point whose lower bound is within it.
    const auto fill_row = [&](const internal::Brute_force_index& index, std::size_t i, const float* gp) {
      const std::size_t size = index.size;
      // A far point's weight is infinite: its pairs get [-inf, inf] from the same arithmetic, without a
      // branch.
      const double ni = index.norms[static_cast<Eigen::Index>(i)], wi = index.weight[i] + index.pair_constant;
      const double* norms = index.norms.data();
      const double* weight = index.weight.data();
      d2.resize(size);
      hi.resize(size);
      for (std::size_t j = 0; j < size; ++j) {
        d2[j] = ni + norms[j] - 2 * static_cast<double>(gp[j]);
        hi[j] = d2[j] + (wi + weight[j]);
      }
      hi[i] = inf;  // not its own neighbour (size > kk: the bound stays one of the others')
      heap.assign(hi.begin(), hi.begin() + static_cast<std::ptrdiff_t>(kk + 1));
      std::make_heap(heap.begin(), heap.end());
      std::pop_heap(heap.begin(), heap.end());
      heap.pop_back();  // the kk smallest of the first kk + 1 (one of which may be i's inf)
      for (std::size_t j = kk + 1; j < size; ++j)
        if (hi[j] < heap.front()) {
          std::pop_heap(heap.begin(), heap.end());
          heap.back() = hi[j];
          std::push_heap(heap.begin(), heap.end());
        }
      const double bound = heap.front();
      row.clear();
      for (std::size_t j = 0; j < size; ++j) {
        const double lo = d2[j] - (wi + weight[j]);
        if (lo <= bound && j != i) row.push_back(Enclosure{lo, hi[j], static_cast<std::uint32_t>(j)});
      }
    };
    // The kk nearest of indexed point i among the enclosures of `row` into cand (indices of m). Enclosures
    // too wide to exclude anything (a far point's, or the float one of a pair much closer than the data's
    // spread) are first narrowed in double; before session 15 one row's widest error bound was applied to the
    // whole row, so one outlier made every point a candidate of every row.
    bool need_order = false;  // in a group's rows: the k-th nearest is compared with its separation
    const auto choose = [&](const internal::Brute_force_index& index, std::size_t i) {
      double bound = kth_upper();
      bool narrowed = false;
      for (Enclosure& x : row)
        if (x.lo <= bound && !(x.hi < inf && x.hi - x.lo <= 0x1p-10 * x.hi)) {
          index.refine(i, x.j, x.lo, x.hi);
          ++count.refined;
          narrowed = true;
        }
      if (narrowed) bound = kth_upper();
      cand.clear();
      for (const Enclosure& x : row)
        if (x.lo <= bound) cand.push_back(index.rows ? index.rows[x.j] : x.j);
      keep_nearest(index.rows ? index.rows[i] : i, need_order);
    };
    std::size_t rows_done = 0;  // for the progress reports
    // with several groups their rows take [0, 0.9], the points searched among all the rest
    double progress_scale = 1;
    // Calls found(i) with the kk nearest of each indexed point i within the index in cand.
    const auto search = [&](const internal::Brute_force_index& index, auto&& found) {
      const std::size_t size = index.size, block = 256;
      for (std::size_t b = 0; b < size && !stopped; b += block) {
        if (!FeatureRecon::internal::report_progress(
                options.progress, progress_scale * static_cast<double>(rows_done + b) / n)) {
          stopped = true;
          break;
        }
        const std::size_t e = std::min(size, b + block);
        index.gram(b, e, 0);
        for (std::size_t i = b; i < e; ++i) {
          fill_row(index, i, index.gram_row(i - b));
          choose(index, i);
          found(index.rows ? index.rows[i] : i);
        }
      }
      rows_done += size;
    };
    const std::vector<internal::Isolated_group> groups = internal::isolated_groups(m, kk + 1);
    if (groups.size() == 1) {
      search(internal::Brute_force_index(m), add_edges);
    } else {
      std::vector<std::uint32_t> unresolved;
      need_order = true;
      progress_scale = 0.9;
      for (const internal::Isolated_group& group : groups) {
        if (group.rows.size() <= kk) {  // too few to hold anyone's k nearest
          unresolved.insert(unresolved.end(), group.rows.begin(), group.rows.end());
          rows_done += group.rows.size();
          continue;
        }
        search(internal::Brute_force_index(m, &group.rows), [&](std::size_t i) {
          const std::uint32_t kth = cand.back();  // the k-th nearest: cand is sorted
          if (internal::distance_at_most(m.row(i), m.row(kth), m.dimension, group.separation))
            add_edges(i);
          else
            unresolved.push_back(static_cast<std::uint32_t>(i));
        });
        if (stopped) break;
      }
      count.unresolved = unresolved.size();
      need_order = false;
      if (!stopped && !unresolved.empty()) {  // among all points, with the float filter of all of them
        const internal::Brute_force_index index(m);
        const std::size_t u = unresolved.size(), block = 256;
        for (std::size_t b = 0; b < u; b += block) {
          if (!FeatureRecon::internal::report_progress(options.progress,
                                                       0.9 + 0.1 * static_cast<double>(b) / u)) {
            stopped = true;
            break;
          }
          const std::size_t e = std::min(u, b + block);
          index.gram_of(unresolved.data() + b, e - b);
          for (std::size_t t = b; t < e; ++t) {
            fill_row(index, unresolved[t], index.gram_row(t - b));
            choose(index, unresolved[t]);
            add_edges(unresolved[t]);
          }
        }
      }
    }
  }
  internal::sort_unique_edges(g.edges, nullptr);
  internal::add_edge_lengths(m, g, fn);
  if (!stopped) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  if (stopped) g.status = Status::interrupted;
  if (counts) *counts = count;
  return g;
}
}  // namespace internal

/// Symmetrised k-nearest-neighbour graph of the rows of a Point_matrix (see the range version of
/// build_knn_graph()).
inline Proximity_graph build_knn_graph(const Point_matrix& m, std::size_t k,
                                       const Proximity_graph_options& options = {}) {
  return internal::knn_graph(m, k, options, nullptr);
}

/// Rips (r-neighbourhood) graph of points: an edge between every two points at distance <= radius
/// (inclusive, decided exactly on the double coordinates), weighted by the Euclidean distance.
///
/// Candidates come from a CGAL kd-tree (dimension <= 3) or from blocked all-pairs distances with Eigen
/// (higher dimension; groups of points that a gap wider than the radius separates on one axis are searched
/// each alone), and every candidate is decided by an exact predicate. Duplicate points are joined by edges of
/// length 0.
/// \tparam PointRange a range of points; \tparam Traits a model of PointCoordinateTraits.
/// \pre radius is finite and >= 0 (checked; throws). All points have the same positive dimension and finite
///      coordinates (checked; throws, naming the point).
/// \returns a canonical Proximity_graph on the points' indices.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Proximity_graph build_rips_graph(const PointRange& points, double radius,
                                 const Proximity_graph_options& options = {},
                                 const Traits& traits = Traits()) {
  const char* fn = "build_rips_graph";
  if (!(std::isfinite(radius) && radius >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and >= 0, got ", radius);
  const Point_matrix m = make_point_matrix(points, traits, fn);
  return build_rips_graph(m, radius, options);
}

/// Symmetrised k-nearest-neighbour graph: i and j are joined when j is among the k nearest neighbours of
/// i or i among those of j. Nearest is decided exactly; equal distances are ordered by index, so grids
/// and duplicates give a deterministic graph. Edge lengths are Euclidean distances.
///
/// Candidates come from a CGAL kd-tree over the distinct positions (dimension <= 3) or from blocked all-pairs
/// distances with Eigen (higher dimension: a float Gram filter with a rigorous error bound, then doubles,
/// then exact comparisons; clusters far apart relative to their size are searched each alone, see
/// isolated_groups()).
/// \pre k >= 1 (checked; throws). Points as for build_rips_graph(). With n <= k every pair is joined.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Proximity_graph build_knn_graph(const PointRange& points, std::size_t k,
                                const Proximity_graph_options& options = {},
                                const Traits& traits = Traits()) {
  const char* fn = "build_knn_graph";
  if (k < 1) FeatureRecon::internal::throw_invalid_argument(fn, "k must be >= 1, got ", k);
  const Point_matrix m = make_point_matrix(points, traits, fn);
  return build_knn_graph(m, k, options);
}

namespace internal {
/// \cond
template <class Matrix, class = void>
struct Is_eigen_like : std::false_type {};
template <class Matrix>
struct Is_eigen_like<Matrix, std::void_t<decltype(std::declval<const Matrix&>().rows()),
                                         decltype(std::declval<const Matrix&>()(0, 0))>> : std::true_type {};

/// Checks the entries of a flat row-major n x n distance matrix `a` (a.size() == n * n): finite, >= 0, 0 on
/// the diagonal, symmetric; throws naming the first entry (by row) that is not.
inline void check_distance_entries(const std::vector<double>& a, std::size_t n, const char* fn) {
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double x = a[i * n + j];
      if (!std::isfinite(x) || x < 0)
        FeatureRecon::internal::throw_invalid_argument(
            fn, "entry (", i, ", ", j, ") of the distance matrix is ", x, " (must be finite and >= 0)");
      if (i == j && x != 0)
        FeatureRecon::internal::throw_invalid_argument(fn, "diagonal entry (", i, ", ", i, ") is ", x,
                                                       " (must be 0)");
      if (j > i && x != a[j * n + i])
        FeatureRecon::internal::throw_invalid_argument(fn, "the distance matrix is not symmetric at (", i,
                                                       ", ", j, "): ", x, " vs ", a[j * n + i]);
    }
}

/// Checks a dense distance matrix and returns it as a flat row-major vector.
template <class Matrix>
std::vector<double> checked_distance_matrix(const Matrix& D, std::size_t& n, const char* fn) {
  std::vector<double> a;
  if constexpr (Is_eigen_like<Matrix>::value) {
    n = static_cast<std::size_t>(D.rows());
    if (static_cast<std::size_t>(D.cols()) != n)
      FeatureRecon::internal::throw_invalid_argument(fn, "the distance matrix is ", D.rows(), " x ", D.cols(),
                                                     ", not square");
    a.resize(n * n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) a[i * n + j] = static_cast<double>(D(i, j));
  } else {
    n = static_cast<std::size_t>(std::distance(std::begin(D), std::end(D)));
    a.reserve(n * n);
    std::size_t i = 0;
    for (const auto& row : D) {
      const std::size_t len = static_cast<std::size_t>(std::distance(std::begin(row), std::end(row)));
      if (len != n)
        FeatureRecon::internal::throw_invalid_argument(fn, "row ", i, " of the distance matrix has ", len,
                                                       " entries, expected ", n);
      for (const auto& x : row) a.push_back(static_cast<double>(x));
      ++i;
    }
  }
  check_distance_entries(a, n, fn);
  return a;
}
/// The Rips graph of a checked n x n distance matrix `a` (row-major): i < j joined when a(i, j) <= radius.
/// `progress` (if set) is asked every 4096 rows with the fraction of the pairs visited; false stops: the
/// graph holds the edges of the rows visited.
inline Proximity_graph rips_graph_of_distance_matrix(const std::vector<double>& a, std::size_t n,
                                                     double radius, const Progress_callback& progress = {}) {
  Proximity_graph g;
  g.number_of_vertices = n;
  const double pairs = 0.5 * double(n) * double(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 4096 == 0 && i > 0 && progress &&
        !progress(1 -
                  0.5 * double(n - i) * double(n - i) / pairs))  // rows 0..i-1 hold n^2/2 - (n-i)^2/2 pairs
      break;
    for (std::size_t j = i + 1; j < n; ++j)
      if (a[i * n + j] <= radius) {
        g.edges.push_back(Edge{static_cast<Vertex_index>(i), static_cast<Vertex_index>(j)});
        g.edge_lengths.push_back(a[i * n + j]);
      }
  }
  return g;
}
/// \endcond
}  // namespace internal

/// Rips graph of a dense distance matrix: i and j are joined when D(i, j) <= radius (inclusive).
/// \tparam Matrix an Eigen-like matrix (`rows()`, `cols()`, `D(i, j)`) or a range of rows.
/// \param options its `progress` is called with the fraction of the pairs visited (every 4096 rows, then 1);
///        returning false stops: the graph holds the edges of the rows visited (`search` is not used).
/// \pre D is square, symmetric, with a zero diagonal and finite entries >= 0; radius is finite and >= 0
///      (all checked; throws naming the offending entry).
template <class Matrix>
Proximity_graph build_rips_graph_from_distance_matrix(const Matrix& D, double radius,
                                                      const Proximity_graph_options& options = {}) {
  const char* fn = "build_rips_graph_from_distance_matrix";
  if (!(std::isfinite(radius) && radius >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "radius must be finite and >= 0, got ", radius);
  std::size_t n = 0;
  const std::vector<double> a = internal::checked_distance_matrix(D, n, fn);  // sets n
  bool stopped = false;
  Proximity_graph g = internal::rips_graph_of_distance_matrix(a, n, radius, [&](double f) {
    stopped = !FeatureRecon::internal::report_progress(options.progress, f);
    return !stopped;
  });
  if (!stopped) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  if (stopped) g.status = Status::interrupted;
  return g;
}

/// Symmetrised k-nearest-neighbour graph of a dense distance matrix (ties broken by index).
/// \param options its `progress` is called every 1024 rows with the fraction of the rows done, then with 1;
///        returning false stops: the graph holds the neighbours of the rows done (`search` is not used).
/// \pre as build_rips_graph_from_distance_matrix(), and k >= 1 (checked; throws).
template <class Matrix>
Proximity_graph build_knn_graph_from_distance_matrix(const Matrix& D, std::size_t k,
                                                     const Proximity_graph_options& options = {}) {
  const char* fn = "build_knn_graph_from_distance_matrix";
  if (k < 1) FeatureRecon::internal::throw_invalid_argument(fn, "k must be >= 1, got ", k);
  std::size_t n = 0;
  const std::vector<double> a = internal::checked_distance_matrix(D, n, fn);
  Proximity_graph g;
  g.number_of_vertices = n;
  const std::size_t kk = std::min(k, n == 0 ? 0 : n - 1);
  std::vector<std::uint32_t> cand;
  bool stopped = false;
  for (std::size_t i = 0; i < n && kk > 0; ++i) {
    if (i % 1024 == 0 && i > 0 &&
        !FeatureRecon::internal::report_progress(options.progress, double(i) / double(n))) {
      stopped = true;
      break;
    }
    cand.clear();
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) cand.push_back(static_cast<std::uint32_t>(j));
    std::nth_element(cand.begin(), cand.begin() + static_cast<std::ptrdiff_t>(kk - 1), cand.end(),
                     [&](std::uint32_t x, std::uint32_t y) {
                       return a[i * n + x] < a[i * n + y] || (a[i * n + x] == a[i * n + y] && x < y);
                     });
    for (std::size_t t = 0; t < kk; ++t) {
      const Vertex_index u = static_cast<Vertex_index>(i), v = cand[t];
      g.edges.push_back(u < v ? Edge{u, v} : Edge{v, u});
    }
  }
  internal::sort_unique_edges(g.edges, nullptr);
  g.edge_lengths.resize(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) g.edge_lengths[e] = a[g.edges[e][0] * n + g.edges[e][1]];
  if (!stopped) (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  if (stopped) g.status = Status::interrupted;
  return g;
}

/// Proximity graph from a user's Boost.Graph graph (VertexListGraph and EdgeListGraph, undirected or
/// directed; parallel edges keep the first weight seen, self-loops are dropped).
/// \param weight a readable property map from edge descriptors to lengths.
/// \pre every weight is finite and >= 0 (checked; throws naming the edge in edges(graph) order).
template <class Graph, class WeightMap>
Proximity_graph proximity_graph_from_boost_graph(const Graph& graph, WeightMap weight) {
  const char* fn = "proximity_graph_from_boost_graph";
  Proximity_graph g;
  g.number_of_vertices = static_cast<std::size_t>(num_vertices(graph));
  const auto index = get(boost::vertex_index, graph);
  std::vector<double> lengths;
  std::size_t k = 0;
  for (auto [it, end] = edges(graph); it != end; ++it, ++k) {
    const auto u = static_cast<Vertex_index>(get(index, source(*it, graph)));
    const auto v = static_cast<Vertex_index>(get(index, target(*it, graph)));
    const double w = static_cast<double>(get(weight, *it));
    if (!(std::isfinite(w) && w >= 0))
      FeatureRecon::internal::throw_invalid_argument(fn, "edge ", k, " (", u, ", ", v, ") has weight ", w,
                                                     " (must be finite and >= 0)");
    if (u == v) continue;
    g.edges.push_back(u < v ? Edge{u, v} : Edge{v, u});
    lengths.push_back(w);
  }
  internal::sort_unique_edges(g.edges, &lengths);
  g.edge_lengths = std::move(lengths);
  return g;
}

/// Options of build_flag_complex_2().
struct Flag_complex_options {
  /// Refuse a complex with more triangles than this (std::invalid_argument naming the limit), found while
  /// counting, before any triangle is stored: a radius too large for the data asks for billions of triangles.
  /// Default 0: no limit.
  std::size_t max_triangles = 0;
  /// Fraction done, asked during both passes (counting, then storing); returning false stops: the complex is
  /// returned without triangles, or with those stored so far, and with status interrupted.
  Progress_callback progress;
};

namespace internal {

/// build_flag_complex_2(); errors name `fn` and, for the triangle limit, `limit_name`.
inline Simplicial_complex_2 flag_complex_2(const Proximity_graph& g, std::size_t max_triangles,
                                           const Progress_callback& progress, const char* fn,
                                           const char* limit_name) {
  if (const std::string problem = internal::canonical_form_problem(g); !problem.empty())
    FeatureRecon::internal::throw_invalid_argument(
        fn, "the graph is not canonical (see Proximity_graph): ", problem);
  Simplicial_complex_2 k;
  k.number_of_vertices = g.number_of_vertices;
  FeatureRecon::internal::reserve_huge(k.edges, g.edges.size());
  k.edges.assign(g.edges.begin(), g.edges.end());
  FeatureRecon::internal::reserve_huge(k.edge_lengths, g.edge_lengths.size());
  k.edge_lengths.assign(g.edge_lengths.begin(), g.edge_lengths.end());
  const std::size_t n = g.number_of_vertices;
  // Forward adjacency: for each u, its neighbours v > u in increasing order (edges are sorted).
  std::vector<std::size_t> first(n + 1, 0);
  for (const Edge& e : g.edges) ++first[e[0] + 1];
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  const std::size_t report_every = std::max<std::size_t>(1, n / 100);
  // Two passes (count, then fill one exact huge-page buffer): cheaper than growing a vector of millions of
  // triangles on machines where first-touch page faults are expensive. Each pass is half of the progress.
  bool stopped = false;
  for (int pass = 0; pass < 2 && !stopped; ++pass) {
    std::size_t count = 0;
    for (std::size_t u = 0; u < n; ++u) {
      if (u % report_every == 0 &&
          !FeatureRecon::internal::report_progress(progress, 0.5 * pass + 0.5 * static_cast<double>(u) / n)) {
        stopped = true;
        break;
      }
      for (std::size_t a = first[u]; a < first[u + 1]; ++a) {
        const Vertex_index v = g.edges[a].at(1);
        // Intersect N+(u) after v with N+(v).
        std::size_t p = a + 1, q = first[v];
        while (p < first[u + 1] && q < first[v + 1]) {
          const Vertex_index x = g.edges[p][1], y = g.edges[q][1];
          if (x < y) {
            ++p;
          } else if (y < x) {
            ++q;
          } else {
            if (pass == 1)
              k.triangles.push_back(Triangle{static_cast<Vertex_index>(u), v, x});
            else if (++count > max_triangles)
              FeatureRecon::internal::throw_invalid_argument(
                  fn, "the flag complex has more than ", max_triangles, " triangles (", limit_name, "; ", n,
                  " vertices, ", g.edges.size(), " edges, the limit was passed at vertex ", u,
                  "): use a smaller radius or fewer points, or raise the limit");
            ++p;
            ++q;
          }
        }
      }
    }
    if (pass == 0 && !stopped) FeatureRecon::internal::reserve_huge(k.triangles, count);
  }
  if (!stopped) (void)FeatureRecon::internal::report_progress(progress, 1.0);
  if (stopped) k.status = Status::interrupted;
  return k;
}

}  // namespace internal

/// The flag (clique) complex of a proximity graph up to dimension 2: its vertices, edges and every
/// triangle whose three edges are in the graph. With a Rips graph this is the Rips 2-complex.
/// O(sum of squared degrees) time; triangles come out sorted. The triangles are counted first, then stored.
/// \pre g is canonical (checked; throws).
/// \throws std::invalid_argument for a graph that is not canonical, or more triangles than
///         `options.max_triangles` (found while counting, nothing stored).
inline Simplicial_complex_2 build_flag_complex_2(const Proximity_graph& g,
                                                 const Flag_complex_options& options = {}) {
  return internal::flag_complex_2(
      g, options.max_triangles > 0 ? options.max_triangles : std::numeric_limits<std::size_t>::max(),
      options.progress, "build_flag_complex_2", "Flag_complex_options::max_triangles");
}

/// build_flag_complex_2() without a triangle limit, with a progress callback: any callable taking the
/// fraction done and returning false to stop (a template, so that `build_flag_complex_2(g, {})` is the
/// options overload and not ambiguous).
template <class Callback,
          std::enable_if_t<std::is_invocable_r<bool, std::decay_t<Callback>&, double>::value, int> = 0>
Simplicial_complex_2 build_flag_complex_2(const Proximity_graph& g, Callback&& progress) {
  Flag_complex_options o;
  o.progress = std::forward<Callback>(progress);
  return build_flag_complex_2(g, o);
}

/// Options of build_rips_complex_2(): those of its two stages, build_rips_graph() and build_flag_complex_2().
/// Proximity_graph_options convert to it (no triangle limit).
struct Rips_complex_options {
  Neighbor_search search = Neighbor_search::automatic;  ///< neighbour search of the graph stage
  /// Flag_complex_options::max_triangles of the triangle stage (refused before any triangle is stored, with
  /// std::invalid_argument naming `Rips_complex_options::max_triangles`). Default 0: no limit.
  std::size_t max_triangles = 0;
  /// Fraction done: the graph up to 0.5, the triangles up to 1; returning false stops (see
  /// build_rips_complex_2()).
  Progress_callback progress;

  Rips_complex_options() = default;
  /// The graph stage's options, no triangle limit.
  Rips_complex_options(const Proximity_graph_options& graph)  // implicit: the one-call form took these
      : search(graph.search), progress(graph.progress) {}
};

/// One call: the Rips 2-complex of points at scale `radius` (build_rips_graph() then build_flag_complex_2()).
/// options.progress sees the graph up to 0.5 and the triangles up to 1; when it returns false the work stops
/// and the complex returned has the edges (and triangles) found so far, as the two stages document.
/// \throws std::invalid_argument as build_rips_graph() does, and for more triangles than
///         options.max_triangles (when set).
template <class PointRange, class Traits = Point_coordinate_traits<typename std::iterator_traits<
                                decltype(std::begin(std::declval<const PointRange&>()))>::value_type>>
Simplicial_complex_2 build_rips_complex_2(const PointRange& points, double radius,
                                          const Rips_complex_options& options = {},
                                          const Traits& traits = Traits()) {
  bool stopped = false;
  auto stage = [&](double from) -> Progress_callback {
    if (!options.progress) return {};
    return [&options, &stopped, from](double t) {
      if (!stopped && !options.progress(from + 0.5 * t)) stopped = true;
      return !stopped;
    };
  };
  Proximity_graph_options graph_options;
  graph_options.search = options.search;
  graph_options.progress = stage(0.0);
  Proximity_graph g = build_rips_graph(points, radius, graph_options, traits);
  if (stopped) {  // also when the graph stage's last report was refused: the complex has no triangles
    Simplicial_complex_2 k;
    static_cast<Proximity_graph&>(k) = std::move(g);
    k.status = Status::interrupted;
    return k;
  }
  return internal::flag_complex_2(
      g, options.max_triangles > 0 ? options.max_triangles : std::numeric_limits<std::size_t>::max(),
      stage(0.5), "build_rips_complex_2", "Rips_complex_options::max_triangles");
}

namespace internal {

/// first_copies() of n rows of length d given by row(i) (a pointer to d doubles).
template <class Row>
bool first_copies_of(std::size_t n, std::size_t d, const Row& row, std::vector<Vertex_index>& first) {
  first.clear();
  std::vector<Vertex_index> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<Vertex_index>(i);
  auto less = [&row, d](Vertex_index a, Vertex_index b) {
    return std::lexicographical_compare(row(a), row(a) + d, row(b), row(b) + d);
  };
  std::sort(order.begin(), order.end(),
            [&less](Vertex_index a, Vertex_index b) { return less(a, b) || (!less(b, a) && a < b); });
  bool any = false;
  for (std::size_t k = 1; k < n && !any; ++k) any = !less(order[k - 1], order[k]);
  if (!any) return false;
  first.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    first[order[k]] = (k > 0 && !less(order[k - 1], order[k])) ? first[order[k - 1]] : order[k];
  return true;
}

/// Exact copies among the rows of `m`: first[i] is the smallest index whose coordinates equal row i's (i for
/// the first copy). O(n log n) by a lexicographic sort. Returns false, leaving `first` empty, when every row
/// is distinct.
inline bool first_copies(const Point_matrix& m, std::vector<Vertex_index>& first) {
  return first_copies_of(
      m.rows, m.dimension, [&m](std::size_t i) { return m.row(i); }, first);
}

/// First copies of the rows of an n x n distance matrix `a` (row-major, zero diagonal): row i is a copy of
/// the smallest j with the same row (so at distance 0 from it). A row at distance 0 from another but with
/// other distances that differ is not a copy. O(n^2 log n) by a lexicographic sort of the rows. Returns
/// false, leaving `first` empty, when no row is a copy.
inline bool first_copies_of_rows(const std::vector<double>& a, std::size_t n,
                                 std::vector<Vertex_index>& first) {
  return first_copies_of(
      n, n, [&a, n](std::size_t i) { return a.data() + i * n; }, first);
}

}  // namespace internal

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_RIPS_GRAPH_H
