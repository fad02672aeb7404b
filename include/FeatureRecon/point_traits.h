// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_POINT_TRAITS_H
#define FEATURERECON_POINT_TRAITS_H

// Access to the Cartesian coordinates of a point type of any dimension (concept PointCoordinateTraits,
// see doc/concepts/PointCoordinateTraits.h).

#include <CGAL/number_utils.h>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace FeatureRecon {

namespace internal {
template <class P, class = void>
struct Has_cartesian : std::false_type {};
template <class P>
struct Has_cartesian<P, std::void_t<decltype(std::declval<const P&>().dimension()),
                                    decltype(std::declval<const P&>().cartesian(0))>> : std::true_type {};
template <class P, class = void>
struct Is_indexable_range : std::false_type {};
template <class P>
struct Is_indexable_range<
    P, std::void_t<decltype(std::declval<const P&>().size()), decltype(std::declval<const P&>()[0])>>
    : std::true_type {};
}  // namespace internal

/// Default model of PointCoordinateTraits.
/// - CGAL points of any kernel (`Point_2`, `Point_3`, `Epick_d`/`Epeck_d` `Point_d` of fixed or dynamic
///   dimension): `dimension()` and `cartesian(i)`, converted with CGAL::to_double.
/// - Indexable ranges of numbers (`std::vector<double>`, `std::array<double, N>`, `Eigen::VectorXd`):
///   `size()` and `operator[]`.
/// Users with another point type write a traits class with the same two members.
template <class Point_>
struct Point_coordinate_traits {
  using Point = Point_;  ///< the user's point type
  static_assert(internal::Has_cartesian<Point>::value || internal::Is_indexable_range<Point>::value,
                "FeatureRecon: no default PointCoordinateTraits for this point type; pass a traits class "
                "with dimension(p) and coordinate(p, i) (see doc/concepts/PointCoordinateTraits.h)");
  /// Number of coordinates of p.
  std::size_t dimension(const Point& p) const {
    if constexpr (internal::Has_cartesian<Point>::value)
      return static_cast<std::size_t>(p.dimension());
    else
      return static_cast<std::size_t>(p.size());
  }
  /// Coordinate i of p as a double.
  double coordinate(const Point& p, std::size_t i) const {
    if constexpr (internal::Has_cartesian<Point>::value)
      return CGAL::to_double(p.cartesian(static_cast<int>(i)));
    else
      return static_cast<double>(p[i]);
  }
};

namespace internal {
template <class T, class = void>
struct Is_point_coordinate_traits : std::false_type {};
template <class T>
struct Is_point_coordinate_traits<
    T, std::void_t<typename T::Point,
                   decltype(std::declval<const T&>().dimension(std::declval<const typename T::Point&>())),
                   decltype(std::declval<const T&>().coordinate(std::declval<const typename T::Point&>(),
                                                                std::size_t(0)))>> : std::true_type {};
}  // namespace internal

}  // namespace FeatureRecon

#endif  // FEATURERECON_POINT_TRAITS_H
