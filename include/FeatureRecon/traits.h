// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_TRAITS_H
#define FEATURERECON_TRAITS_H

// Ready-made models of the concept FeaturePointTraits (doc/concepts/FeaturePointTraits.h): a sample is a
// position (a CGAL 2D or 3D point of the user's kernel) plus a feature of any type with a feature distance.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>

namespace FeatureRecon {

namespace internal {
// Whether a number type holds a double's digits (double, long double, exact or interval types): the ready
// traits declare their feature distance a metric only then (a float kernel rounds the distances to 24 bits:
// the declared error would not hold).
template <class FT>
constexpr bool holds_double_digits() {
  if constexpr (std::is_floating_point<FT>::value)
    return std::numeric_limits<FT>::digits >= std::numeric_limits<double>::digits;
  else
    return true;
}

}  // namespace internal

/// The feature of a sample without one (plain Euclidean sampling).
struct No_feature {};

/// Positions only: `Item` is the kernel's `Point_2` or `Point_3`; every feature distance is zero.
/// \tparam Point_ `K::Point_2` or `K::Point_3` of a CGAL kernel K.
template <class Point_>
struct Point_traits {
  using Point = Point_;                                              ///< the position type
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;        ///< the point's CGAL kernel
  using FT = typename Kernel::FT;                                    ///< the kernel's number type
  using Feature = No_feature;                                        ///< no feature
  using Item = Point;                                                ///< the input range's value type
  static constexpr int dimension = Point::Ambient_dimension::value;  ///< 2 or 3
  static constexpr double feature_metric_error = 0;  ///< every feature distance is 0: a metric
  /// The position of an item.
  struct Construct_point {
    const Point& operator()(const Item& i) const { return i; }  ///< the item itself
  };
  /// The (empty) feature of an item.
  struct Construct_feature {
    Feature operator()(const Item&) const { return {}; }  ///< no feature
  };
  /// Squared feature distance: always zero.
  struct Compute_feature_distance {
    FT operator()(const Feature&, const Feature&) const { return FT(0); }  ///< zero
  };
  Construct_point construct_point_object() const { return {}; }                    ///< functor
  Construct_feature construct_feature_object() const { return {}; }                ///< functor
  Compute_feature_distance compute_feature_distance_object() const { return {}; }  ///< functor
};

/// How normals are compared by Point_with_normal_traits.
enum class Normal_orientation {
  oriented,   ///< |n_i - n_j|^2: opposite normals (the two sides of a thin wall) are far apart (the default)
  unoriented  ///< min(|n_i - n_j|^2, |n_i + n_j|^2): a normal and its opposite are the same feature
};

/// Point with normal: `Item` is `std::pair<Point_3, Vector_3>`; the feature is the normal, compared by the
/// squared distance of the unit normals (so it lies in [0, 4]). Normals need not be unit length; a zero
/// normal is rejected by the samplers and sampling_quality() when they compare features (finite
/// sigma_feature; checked; throws naming the item: every item's feature must then be at a finite distance
/// from itself).
/// \tparam K a CGAL kernel (Epick, Epeck, Simple_cartesian<double>, ...).
template <class K>
struct Point_with_normal_traits {
  using Kernel = K;                                               ///< the CGAL kernel
  using FT = typename K::FT;                                      ///< the kernel's number type
  using Point = typename K::Point_3;                              ///< the position type
  using Feature = typename K::Vector_3;                           ///< the normal
  using Item = std::pair<Point, Feature>;                         ///< the input range's value type
  static constexpr int dimension = 3;                             ///< positions are 3D
  Normal_orientation orientation = Normal_orientation::oriented;  ///< how normals are compared
  /// The square root of the feature distance is a metric (the chord between unit normals; unoriented: the
  /// shorter chord to n or -n); a computed squared distance is within 1e-14 of the true one (2 - 2 cos from
  /// a cosine of a few ulps of error), where FT holds a double's digits (else -1: not declared).
  static constexpr double feature_metric_error = internal::holds_double_digits<FT>() ? 1e-14 : -1;
  /// The position of an item.
  struct Construct_point {
    const Point& operator()(const Item& i) const { return i.first; }  ///< `i.first`
  };
  /// The normal of an item.
  struct Construct_feature {
    const Feature& operator()(const Item& i) const { return i.second; }  ///< `i.second`
  };
  /// Squared distance of the two normals scaled to unit length, in [0, 4] (oriented) or [0, 2] (unoriented).
  struct Compute_feature_distance {
    Normal_orientation orientation = Normal_orientation::oriented;  ///< how normals are compared
    /// -1 (not a distance: the samplers refuse the item, naming it) when a or b is zero or not finite.
    FT operator()(const Feature& a, const Feature& b) const {
      // |a/|a| - b/|b||^2 = 2 - 2 cos; computed in doubles (a square root is needed for the cosine), on the
      // vectors scaled by the power of two of their largest component (exact), so that lengths of 1e-170 or
      // 1e160 neither underflow nor overflow. A zero normal made the cosine NaN, and FT(NaN) failed inside an
      // exact kernel (Epeck: an assertion, or SIGFPE in GMP without assertions) before the samplers could
      // name the item.
      std::array<double, 3> u{CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())};
      std::array<double, 3> v{CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z())};
      for (auto* w : {&u, &v}) {
        // Each component checked (std::max skips a NaN after the first); then only a zero vector is left.
        if (!(std::isfinite((*w)[0]) && std::isfinite((*w)[1]) && std::isfinite((*w)[2]))) return FT(-1);
        const double m = std::max({std::fabs((*w)[0]), std::fabs((*w)[1]), std::fabs((*w)[2])});
        if (m == 0) return FT(-1);
        const int e = std::ilogb(m);
        for (double& x : *w) x = std::ldexp(x, -e);
      }
      const double la = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], lb = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      double c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / std::sqrt(la * lb);
      c = c > 1 ? 1 : (c < -1 ? -1 : c);
      if (orientation == Normal_orientation::unoriented && c < 0) c = -c;
      return FT(2 - 2 * c);
    }
  };
  Construct_point construct_point_object() const { return {}; }      ///< functor
  Construct_feature construct_feature_object() const { return {}; }  ///< functor
  /// Functor comparing normals as set by `orientation`.
  Compute_feature_distance compute_feature_distance_object() const { return {orientation}; }
};

/// A pixel of a grey image: integer column and row, value in [0, 255] (8 bits; the feature distance is the
/// squared difference of the values divided by 255^2, in [0, 1]).
struct Grey_pixel {
  int column = 0;          ///< x, from the left
  int row = 0;             ///< y, from the top
  std::uint8_t value = 0;  ///< grey value
};

/// A pixel of an RGB image.
struct Rgb_pixel {
  int column = 0;                     ///< x, from the left
  int row = 0;                        ///< y, from the top
  std::array<std::uint8_t, 3> rgb{};  ///< red, green, blue
};

/// Pixels of a grey or RGB image as samples: the position is the pixel centre (column + 1/2, row + 1/2) in
/// pixel units; the feature is the colour, compared by the mean squared channel difference scaled to [0, 1].
/// \tparam Pixel_ Grey_pixel or Rgb_pixel.
/// \tparam K the kernel of the positions (default Epick).
template <class Pixel_, class K = CGAL::Epick>
struct Pixel_traits {
  using Kernel = K;                   ///< the CGAL kernel
  using FT = typename K::FT;          ///< the kernel's number type
  using Point = typename K::Point_2;  ///< the pixel centre
  using Item = Pixel_;                ///< Grey_pixel or Rgb_pixel
  using Feature = std::array<std::uint8_t, std::is_same<Pixel_, Rgb_pixel>::value ? 3 : 1>;  ///< channels
  static constexpr int dimension = 2;  ///< positions are 2D
  /// The square root of the feature distance is a metric (Euclidean in the channels), computed with one
  /// rounding (a quotient of integers) where FT holds a double's digits (else -1: not declared).
  static constexpr double feature_metric_error = internal::holds_double_digits<FT>() ? 0 : -1;
  /// The pixel centre.
  struct Construct_point {
    Point operator()(const Item& p) const { return Point(p.column + 0.5, p.row + 0.5); }  ///< centre
  };
  /// The colour channels.
  struct Construct_feature {
    Feature operator()(const Item& p) const {  ///< channels
      if constexpr (std::is_same<Pixel_, Rgb_pixel>::value)
        return p.rgb;
      else
        return Feature{p.value};
    }
  };
  /// Mean squared channel difference, each channel scaled to [0, 1].
  struct Compute_feature_distance {
    FT operator()(const Feature& a, const Feature& b) const {  ///< in [0, 1]
      int s = 0;
      for (std::size_t c = 0; c < a.size(); ++c) {
        const int d = int(a[c]) - int(b[c]);
        s += d * d;
      }
      return FT(s) / FT(255 * 255 * static_cast<int>(a.size()));
    }
  };
  Construct_point construct_point_object() const { return {}; }                    ///< functor
  Construct_feature construct_feature_object() const { return {}; }                ///< functor
  Compute_feature_distance compute_feature_distance_object() const { return {}; }  ///< functor
};

/// Grey pixels (Epick positions).
using Grey_pixel_traits = Pixel_traits<Grey_pixel>;
/// RGB pixels (Epick positions).
using Rgb_pixel_traits = Pixel_traits<Rgb_pixel>;

namespace internal {
// The static feature_metric_error of traits or of a feature distance where they declare one (>= 0: the
// square root of the feature distance is a metric, FeaturePointTraits), else -1.
template <class T, class = void>
struct Feature_metric_error {
  static constexpr double value = -1;
};
template <class T>
struct Feature_metric_error<T, std::void_t<decltype(T::feature_metric_error)>> {
  static constexpr double value = T::feature_metric_error;
};
}  // namespace internal

/// Users' own item types: the position and the feature are read through property maps (any callable
/// `item -> value`, including CGAL/Boost property maps wrapped in a lambda) and features are compared by a
/// user functor returning the squared feature distance.
/// \tparam K a CGAL kernel. \tparam Dimension 2 or 3.
/// \tparam Item_ the range's value type. \tparam PointMap callable `const Item& -> Point`.
/// \tparam FeatureMap callable `const Item& -> Feature`.
/// \tparam FeatureDistance callable `(const Feature&, const Feature&) -> double`, >= 0, symmetric, 0 on equal
///         features. A static member `feature_metric_error` (a double >= 0) declares that its square root
///         is a metric, each computed value within that of the true squared distance (the traits take it:
///         see FeaturePointTraits).
template <class K, int Dimension, class Item_, class PointMap, class FeatureMap, class FeatureDistance>
struct Property_map_traits {
  static_assert(Dimension == 2 || Dimension == 3, "FeatureRecon: Property_map_traits: Dimension is 2 or 3");
  using Kernel = K;           ///< the kernel
  using FT = typename K::FT;  ///< number type
  using Point = std::conditional_t<Dimension == 2, typename K::Point_2, typename K::Point_3>;  ///< position
  using Item = Item_;                                                                          ///< value type
  /// feature
  using Feature = std::decay_t<decltype(std::declval<const FeatureMap&>()(std::declval<const Item&>()))>;
  static constexpr int dimension = Dimension;  ///< 2 or 3
  /// FeatureDistance::feature_metric_error where it has one, else -1 (not declared a metric).
  static constexpr double feature_metric_error = internal::Feature_metric_error<FeatureDistance>::value;
  PointMap point_map;                ///< item -> position
  FeatureMap feature_map;            ///< item -> feature
  FeatureDistance feature_distance;  ///< squared feature distance
  /// The position of an item, through the point map.
  struct Construct_point {
    const PointMap* map;                                                ///< the traits' map
    Point operator()(const Item& i) const { return Point((*map)(i)); }  ///< position
  };
  /// The feature of an item, through the feature map.
  struct Construct_feature {
    const FeatureMap* map;                                         ///< the traits' map
    Feature operator()(const Item& i) const { return (*map)(i); }  ///< feature
  };
  /// The user's squared feature distance; -1 (not a distance: the samplers refuse it, naming the item, or
  /// both items when only their pair is NaN) when it is NaN (a NaN channel, acos of a cosine above 1), and
  /// the largest double when it overflows to infinity (never a conflict, as infinity is under a
  /// floating-point kernel). FT(NaN) and FT(inf) failed inside an exact kernel (Epeck: SIGFPE in GMP, or an
  /// assertion) before the samplers could name the item.
  struct Compute_feature_distance {
    const FeatureDistance* distance;  ///< the traits' functor
    /// The distance as FT.
    FT operator()(const Feature& a, const Feature& b) const {
      const double d = static_cast<double>((*distance)(a, b));
      if (std::isnan(d)) return FT(-1);
      return FT(std::min(d, std::numeric_limits<double>::max()));
    }
  };
  Construct_point construct_point_object() const { return {&point_map}; }        ///< functor
  Construct_feature construct_feature_object() const { return {&feature_map}; }  ///< functor
  Compute_feature_distance compute_feature_distance_object() const {
    return {&feature_distance};
  }  ///< functor
};

/// Makes a Property_map_traits, deducing the map types.
template <class K, int Dimension, class Item, class PointMap, class FeatureMap, class FeatureDistance>
Property_map_traits<K, Dimension, Item, PointMap, FeatureMap, FeatureDistance> make_property_map_traits(
    PointMap point_map, FeatureMap feature_map, FeatureDistance feature_distance) {
  return {point_map, feature_map, feature_distance};
}

namespace internal {
template <class T, class = void>
struct Is_feature_point_traits : std::false_type {};
template <class T>
struct Is_feature_point_traits<
    T,
    std::void_t<typename T::Kernel, typename T::FT, typename T::Point, typename T::Feature, typename T::Item,
                decltype(T::dimension), decltype(std::declval<const T&>().construct_point_object()),
                decltype(std::declval<const T&>().construct_feature_object()),
                decltype(std::declval<const T&>().compute_feature_distance_object())>> : std::true_type {};

template <class Item, class = void>
struct Default_traits {
  static_assert(sizeof(Item) == 0,
                "FeatureRecon: no default FeaturePointTraits for this item type; pass a traits class (see "
                "doc/concepts/FeaturePointTraits.h), e.g. make_property_map_traits()");
};
template <class P>
struct Default_traits<
    P, std::enable_if_t<std::is_same<P, typename CGAL::Kernel_traits<P>::Kernel::Point_2>::value ||
                        std::is_same<P, typename CGAL::Kernel_traits<P>::Kernel::Point_3>::value>> {
  using type = Point_traits<P>;
};
template <class P, class V>
struct Default_traits<
    std::pair<P, V>,
    std::enable_if_t<std::is_same<P, typename CGAL::Kernel_traits<P>::Kernel::Point_3>::value &&
                     std::is_same<V, typename CGAL::Kernel_traits<P>::Kernel::Vector_3>::value>> {
  using type = Point_with_normal_traits<typename CGAL::Kernel_traits<P>::Kernel>;
};
template <>
struct Default_traits<Grey_pixel> {
  using type = Grey_pixel_traits;
};
template <>
struct Default_traits<Rgb_pixel> {
  using type = Rgb_pixel_traits;
};
}  // namespace internal

/// The traits used when none is given: Point_traits for CGAL `Point_2`/`Point_3` items,
/// Point_with_normal_traits for `std::pair<Point_3, Vector_3>` items, Pixel_traits for Grey_pixel and
/// Rgb_pixel items.
template <class ItemRange>
using Default_traits_t = typename internal::Default_traits<
    std::decay_t<decltype(*std::begin(std::declval<const ItemRange&>()))>>::type;

}  // namespace FeatureRecon

#endif  // FEATURERECON_TRAITS_H
