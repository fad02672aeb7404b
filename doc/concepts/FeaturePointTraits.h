// SPDX-License-Identifier: GPL-3.0-or-later
// Documentation only: the concept FeaturePointTraits, as a pseudo-class.

/// \ingroup Concepts
/// The concept FeaturePointTraits tells the samplers (weighted_sample_elimination(), sampling_quality(), ...)
/// how to read a sample from an item of the input range: a position (a CGAL 2D or 3D point of any kernel)
/// and a feature of any type, with a feature distance.
///
/// Models: FeatureRecon::Point_traits (positions only), FeatureRecon::Point_with_normal_traits (normals,
/// oriented or unoriented), FeatureRecon::Grey_pixel_traits and FeatureRecon::Rgb_pixel_traits (pixels),
/// FeatureRecon::Property_map_traits (users' own structs through accessors). FeatureRecon::Default_traits_t
/// picks Point_traits for `Point_2`/`Point_3` items and Point_with_normal_traits for
/// `std::pair<Point_3, Vector_3>` items.
///
/// The samplers check a traits class at compile time (a static_assert naming this concept).
class FeaturePointTraits {
 public:
  typedef unspecified_type Kernel;     ///< a CGAL kernel (Epick, Epeck, Simple_cartesian<double>, ...)
  typedef unspecified_type FT;         ///< Kernel::FT
  typedef unspecified_type Point;      ///< Kernel::Point_2 or Kernel::Point_3
  typedef unspecified_type Feature;    ///< any copyable type
  typedef unspecified_type Item;       ///< the value type of the input range
  static constexpr int dimension = 2;  ///< 2 or 3, the dimension of Point
  /// Optional. A value e >= 0 declares that the square root of the feature distance is a metric (the
  /// triangle inequality holds) and that each computed squared distance lies within e (plus a relative
  /// 1e-12) of the true one. The discrete Lloyd assignment then bounds the feature term of a whole group of
  /// sites from one of its features (a logo's white pixels against black sites: the exponential form scored
  /// every site). Without it (or at -1) the searches bound by position alone: the same answers, slower
  /// where every site's feature is far. The ready models declare it: positions 0 (their feature distance is
  /// always 0), normals 1e-14 and pixels 0 where FT holds a double's digits (not for a float kernel: -1);
  /// Property_map_traits takes its feature distance's static `feature_metric_error`. Squared distances below
  /// 2^-1000 need not be covered (the searches add that much). A class derived from a ready model that
  /// replaces its feature distance must declare its own value (-1 if unsure): the inherited one would claim a
  /// metric it may not be.
  static constexpr double feature_metric_error = 0;

  /// Functor `Point operator()(const Item&) const` (may return a reference).
  typedef unspecified_type Construct_point;
  /// Functor `Feature operator()(const Item&) const` (may return a reference).
  typedef unspecified_type Construct_feature;
  /// Functor `FT operator()(const Feature& a, const Feature& b) const` returning the **squared** feature
  /// distance |eta_a - eta_b|^2: >= 0, symmetric, 0 for equal features. (Squared, so that models with exact
  /// number types need no square root; the bilateral metrics take squared distances.) Where features are
  /// compared, a feature not at a finite distance from itself is refused naming the item, and a NaN or
  /// negative distance between two features naming both (std::invalid_argument; the caller's data untouched).
  typedef unspecified_type Compute_feature_distance;

  Construct_point construct_point_object() const;                    ///< the functor
  Construct_feature construct_feature_object() const;                ///< the functor
  Compute_feature_distance compute_feature_distance_object() const;  ///< the functor
};

/// \ingroup Concepts
/// The concept BilateralMetric: the bilateral distance xi of two samples from their squared spatial and
/// squared feature distances. Models: FeatureRecon::sampling::Gaussian_bilateral_metric (Eqn 2.4) and
/// FeatureRecon::sampling::Exponential_bilateral_metric (Eqn 2.5), which the samplers choose between by their
/// options' `form` (Bilateral_form); they take no other model. A user adapts the metric through the feature
/// distance of the traits (FeaturePointTraits), which both models mix with the position.
///
/// Every model must satisfy xi >= |dp| / spatial_scale(): the samplers search neighbours spatially within
/// r * spatial_scale() for a bilateral radius r, and would miss neighbours of a metric that broke the bound.
class BilateralMetric {
 public:
  /// xi from |p_a - p_b|^2 and the squared feature distance; >= 0 and symmetric.
  double operator()(double squared_position_distance, double squared_feature_distance) const;
  /// The scale s of the lower bound xi >= |dp| / s (sigma_position for the ready models).
  double spatial_scale() const;
  /// Whether xi(a, b) as computed exceeds slack, with a margin above the roundings, so that every pair of
  /// squared distances at least a and b exceeds it too (the bound of a group of sites).
  bool exceeds(double a, double b, double slack) const;
};
