// SPDX-License-Identifier: GPL-3.0-or-later
// Documentation only: the concept PointCoordinateTraits, as a pseudo-class.

/// \ingroup Concepts
/// The concept PointCoordinateTraits gives the skeleton subsystem (build_rips_graph(), build_knn_graph(),
/// make_point_matrix()) access to the Cartesian coordinates of a user's point type of any dimension.
///
/// Models: FeatureRecon::Point_coordinate_traits<P> for CGAL points of any kernel (Point_2, Point_3,
/// Epick_d / Epeck_d Point_d, fixed or dynamic dimension: through `dimension()` and `cartesian(i)`) and for
/// indexable ranges of numbers (std::vector<double>, std::array<double, N>, Eigen vectors).
///
/// Every point of one input must have the same dimension (> 0) and finite coordinates; the algorithms check
/// this and throw std::invalid_argument naming the first bad point.
class PointCoordinateTraits {
 public:
  /// The point type (the value type of the input range).
  typedef unspecified_type Point;

  /// Number of coordinates of p.
  std::size_t dimension(const Point& p) const;

  /// Coordinate i (0 <= i < dimension(p)) of p as a double. Exact predicates are evaluated on these
  /// doubles, so an exact-constructions kernel is rounded once here.
  double coordinate(const Point& p, std::size_t i) const;
};
