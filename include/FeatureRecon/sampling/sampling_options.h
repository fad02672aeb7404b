// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_SAMPLING_OPTIONS_H
#define FEATURERECON_SAMPLING_SAMPLING_OPTIONS_H

// Options and results of the sampling subsystem. Deliberately free of CGAL and Eigen (cheap to include).

#include <FeatureRecon/config.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// Which form of the bilateral distance the samplers use (dissertation Eqns 2.4 and 2.5).
enum class Bilateral_form {
  gaussian,  ///< xi = sqrt(|dp|^2 / sigma_p^2 + |deta|^2 / sigma_eta^2): Euclidean in the stacked space
  /// xi = |dp| / sigma_p * exp(|deta|^2 / sigma_eta^2): the spatial distance over the feature similarity
  exponential
};

/// Gaussian bilateral distance (Eqn 2.4): xi = sqrt(|dp|^2 / sigma_position^2 + |deta|^2 / sigma_feature^2).
/// A model of BilateralMetric: xi >= |dp| / sigma_position. sigma_feature = infinity gives |dp| /
/// sigma_position.
struct Gaussian_bilateral_metric {
  double sigma_position = 1;                                       ///< spatial scale (> 0); default 1
  double sigma_feature = std::numeric_limits<double>::infinity();  ///< feature scale (> 0); default infinity
  /// xi from the squared spatial and squared feature distances.
  double operator()(double squared_position_distance, double squared_feature_distance) const {
    const double f =
        std::isinf(sigma_feature) ? 0.0 : squared_feature_distance / (sigma_feature * sigma_feature);
    return std::sqrt(squared_position_distance / (sigma_position * sigma_position) + f);
  }
  /// The scale s of the lower bound xi >= |dp| / s.
  double spatial_scale() const { return sigma_position; }
  /// Whether xi(a, b) > slack for a squared spatial distance a and a squared feature distance b, and by
  /// more than the roundings (true: xi of any larger pair exceeds slack as computed); compares squares
  /// while slack^2 keeps its digits.
  bool exceeds(double a, double b, double slack) const {
    const double s2 = slack * slack;
    if (!(s2 >= 0x1p-900 && s2 < 0x1p900)) return (*this)(a, b) > slack * (1 + 1e-15);
    const double f = std::isinf(sigma_feature) ? 0.0 : b / (sigma_feature * sigma_feature);
    return a / (sigma_position * sigma_position) + f > s2 * (1 + 1e-13);
  }
};

/// Exponential bilateral distance (Eqn 2.5 as the original GPU code computes it):
/// xi = |dp| / sigma_position * exp(|deta|^2 / sigma_feature^2), the spatial distance divided by the feature
/// similarity exp(-|deta|^2 / sigma_feature^2). (The dissertation prints the factor with a negative exponent,
/// which would make different features closer; the code and the paper's text mean the opposite.) A model of
/// BilateralMetric: xi >= |dp| / sigma_position; identical positions are at distance 0 whatever the features.
struct Exponential_bilateral_metric {
  double sigma_position = 1;                                       ///< spatial scale (> 0); default 1
  double sigma_feature = std::numeric_limits<double>::infinity();  ///< feature scale (> 0); default infinity
  /// xi from the squared spatial and squared feature distances.
  double operator()(double squared_position_distance, double squared_feature_distance) const {
    if (squared_position_distance == 0) return 0;  // not 0 * exp(f) = 0 * infinity = NaN for far features
    const double f =
        std::isinf(sigma_feature) ? 0.0 : squared_feature_distance / (sigma_feature * sigma_feature);
    return std::sqrt(squared_position_distance) / sigma_position * std::exp(f);
  }
  /// The scale s of the lower bound xi >= |dp| / s.
  double spatial_scale() const { return sigma_position; }
  /// Whether xi(a, b) > slack for a squared spatial distance a and a squared feature distance b, and by
  /// more than the roundings (true: xi of any larger pair exceeds slack as computed).
  bool exceeds(double a, double b, double slack) const { return (*this)(a, b) > slack * (1 + 1e-15); }
};

/// Result of the discrete samplers (indices into the input go to the output iterator).
template <class OutputIterator>
struct Sampling_result {
  OutputIterator out;        ///< the output iterator, advanced past the selected indices
  std::size_t selected = 0;  ///< number of indices written
  /// the bilateral radius used (elimination: r_max in xi units; per-item radii: the largest; with a target
  /// count and per-item radii: their factor)
  double radius = 0;
  Status status = Status::success;  ///< degenerate_input for an empty input; interrupted when stopped
};

/// Statistics of one Lloyd iteration, taken at the sites before they move: energy and relative radius are
/// those of the sites the iteration started from (whose cells it computed), the moves those it made. The
/// first entry measures the starting sites; sampling_quality() measures the final ones.
struct Lloyd_iteration_statistics {
  std::size_t iteration = 0;  ///< 1 for the first iteration
  /// CVT energy: sum_i integral (or sum) over cell i of rho(x) d(x, p_i)^2, with d the Euclidean or the
  /// bilateral distance (decreases monotonically under Euclidean Lloyd).
  double energy = 0;
  double max_move = 0;   ///< largest distance a site moved in this iteration (units of the positions)
  double mean_move = 0;  ///< mean distance the sites moved (units of the positions)
  /// Relative radius rho = d_min / d_hex of the sites over the domain (in 2D d_hex = sqrt(2 A / (sqrt(3) N))
  /// for area A; on surfaces the same with the surface area; in volumes d_fcc = cbrt(sqrt(2) V / N)): the
  /// packing quality for a constant density (1 for the hexagonal lattice).
  double relative_radius = 0;
  /// Oscillation of the sites' spectrum (Heck et al., positions scaled to the unit square), measured when
  /// the caller's on_iteration callback computes it; NaN otherwise. See sampling_spectrum().
  double oscillation = std::numeric_limits<double>::quiet_NaN();
};

/// Why an iterative sampler (lloyd_relaxation(), discrete_bilateral_lloyd(), kernel_relaxation()) stopped.
enum class Lloyd_stop {
  iteration_cap,     ///< max_iterations were done
  energy_tolerance,  ///< the relative energy decrease fell below energy_tolerance
  move_tolerance,    ///< the largest move fell below move_tolerance
  callback,          ///< on_iteration returned false (early stopping on the caller's quality rule)
  interrupted,       ///< the progress callback returned false
  no_descent         ///< kernel_relaxation(): no step along the gradient lowered the energy (a local minimum)
};

/// The name of a stopping reason as written in the source ("iteration_cap", "energy_tolerance", ...), as the
/// command line's JSON writes it.
inline const char* to_string(Lloyd_stop s) {
  switch (s) {
    case Lloyd_stop::iteration_cap:
      return "iteration_cap";
    case Lloyd_stop::energy_tolerance:
      return "energy_tolerance";
    case Lloyd_stop::move_tolerance:
      return "move_tolerance";
    case Lloyd_stop::callback:
      return "callback";
    case Lloyd_stop::interrupted:
      return "interrupted";
    case Lloyd_stop::no_descent:
      return "no_descent";
  }
  return "unknown";
}

/// Writes to_string(s).
inline std::ostream& operator<<(std::ostream& os, Lloyd_stop s) { return os << to_string(s); }

namespace internal {
/// \cond
/// The stopping rules of the iterative samplers, checked after an iteration in this order: the answer of
/// on_iteration (false stops), the largest move (at most move_tolerance, when that is > 0), the energy
/// decrease (below energy_tolerance times the previous energy, when that tolerance is > 0 and the previous
/// energy is finite and positive). Sets `stop` and returns true when the run ends.
inline bool iteration_stops(bool keep_going, double max_move, double move_tolerance, double previous_energy,
                            double decrease, double energy_tolerance, Lloyd_stop& stop) {
  if (!keep_going) {
    stop = Lloyd_stop::callback;
    return true;
  }
  if (move_tolerance > 0 && max_move <= move_tolerance) {
    stop = Lloyd_stop::move_tolerance;
    return true;
  }
  if (energy_tolerance > 0 && std::isfinite(previous_energy) && previous_energy > 0 &&
      decrease < energy_tolerance * previous_energy) {
    stop = Lloyd_stop::energy_tolerance;
    return true;
  }
  return false;
}
/// \endcond
}  // namespace internal

/// Options of weighted_sample_elimination().
struct Elimination_options {
  double sigma_position = 1;  ///< spatial scale of the metric; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  Bilateral_form form = Bilateral_form::gaussian;  ///< form of the bilateral distance
  /// r_max, the neighbourhood is 2 r_max, in units of the bilateral distance. Default 0: from the domain
  /// measure and the intrinsic dimension (hexagonal packing in 2D, r_max = sqrt(A / (2 sqrt(3) M)); FCC in
  /// 3D, r_max = cbrt(V / (4 sqrt(2) M))), divided by sigma_position.
  double max_radius = 0;
  /// Area (intrinsic dimension 2) or volume (3) of the sampled domain. Default 0: estimated from the input
  /// (bounding box for 2D input and 3D volumes; for surfaces, the sum over points of the area of a disc of
  /// the distance to the 8th nearest neighbour, divided by 8).
  double domain_measure = 0;
  /// 2 (images, surfaces) or 3 (volumes). Default 0: 2 for 2D positions; for 3D positions, 2 when at least
  /// half of up to 1,000 evenly spread points have a flat neighbourhood (local PCA of 12 neighbours), else 3.
  int intrinsic_dimension = 0;
  double alpha = 8;  ///< exponent of the weight (1 - d / (2 r_max))^alpha (Yuksel 2015); default 8
  /// clamp d below d_min = 2 r_max beta (1 - (M/N)^gamma), beta 0.65, gamma 1.5
  bool weight_limiting = true;
  /// Refuse (std::invalid_argument) neighbour lists of more entries than this, found while they are counted
  /// and before they are stored (4 bytes an entry): a max_radius far above the packing radius makes every
  /// item a neighbour of every other (a 512 x 480 image at r_max 100,000 asks for 6e10; 30,000 points of a
  /// unit sphere at r_max 100 took 50 s and 3.5 GB). Default 0: automatic, per stage of m items down to t, 64
  /// times the entries the automatic r_max needs (about c m^2 / t, c = 3.6 on surfaces and images, 5.9 in
  /// volumes), at least 2^29 (2 GB): a max_radius up to 8 times the automatic one in 2D (4 times in 3D)
  /// always passes.
  std::size_t max_neighbor_entries = 0;
  std::uint64_t seed = 0;  ///< breaks ties between equal weights (grids, images): a seeded permutation
  /// Positions on the unit torus: taken modulo 1, the distance of two positions is that of their nearest
  /// images (each coordinate difference d counts as min(|d|, 1 - |d|); each pair is weighed once, also when
  /// 2 r_max exceeds 1/2), and without domain_measure the domain is the torus (measure 1 and the positions'
  /// dimension, unless a lower intrinsic_dimension is given: a surface in the 3D torus has its area estimated
  /// as without `periodic`, on the positions modulo 1, which does not look across the faces). For sets that
  /// tile space (Yuksel's tileable sets), as the periodogram of sampling_spectrum() and the periodic measures
  /// of sampling_quality() take them. Default false.
  bool periodic = false;
  /// With `periodic`, the torus [0, period[0]) x [0, period[1]) (x [0, period[2])) instead of the unit one:
  /// one value per axis of the positions, each in [1e-150, 1e150] and their product a finite normal number
  /// (the pixels of a W x H picture tile with {W, H}); without domain_measure its measure is the product of
  /// the periods. Default empty: the unit torus. Given without `periodic`, refused.
  std::vector<double> period;
  /// fraction of the eliminations done; returning false stops (nothing is output)
  Progress_callback progress;
};

/// Options of bilateral_dart_throwing().
struct Dart_throwing_options {
  double sigma_position = 1;  ///< spatial scale of the metric; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  Bilateral_form form = Bilateral_form::gaussian;  ///< form of the bilateral distance
  /// Per-item radius r(s) in bilateral units (adaptive sampling), aligned with the items; two items conflict
  /// when xi < max(r(s), r(t)). With bilateral_dart_throwing_count(), their shape: the radii are t r(s) for
  /// the factor t that keeps the count. Default empty: the uniform radius passed to the call.
  std::vector<double> radii;
  /// Visiting order: items by decreasing priority (ties by index), aligned with the items. Default empty: a
  /// random order drawn from `seed`.
  std::vector<double> priority;
  /// Stop after this many consecutive rejected items. Default 0: visit every item once, which makes the
  /// result maximal on the discrete domain (every rejected item conflicts with a kept one).
  std::size_t max_consecutive_failures = 0;
  /// Stop once this many items are kept: the first ones in the visiting order, spread over the whole domain
  /// (the result is then no longer maximal). Default 0: no cap.
  std::size_t max_accepted = 0;
  std::uint64_t seed = 0;  ///< the random visiting order (ignored when `priority` is given)
  /// Positions on the unit torus: taken modulo 1, the distance of two positions is that of their nearest
  /// images (each coordinate difference d counts as min(|d|, 1 - |d|)). For sets that tile space, as the
  /// periodogram of sampling_spectrum() and the periodic measures of sampling_quality() take them. Default
  /// false.
  bool periodic = false;
  /// With `periodic`, the torus [0, period[0]) x [0, period[1]) (x [0, period[2])) instead of the unit one:
  /// one value per axis of the positions, each in [1e-150, 1e150] and their product a finite normal number.
  /// Default empty: the unit torus. Given without `periodic`, refused.
  std::vector<double> period;
  Progress_callback progress;  ///< fraction of the items visited; returning false stops (nothing is output)
};

/// Options of bilateral_dart_throwing_count().
struct Dart_throwing_count_options {
  /// metric, order and seed of every throw; `radii`, when given, the shape of the radii (their factor is
  /// searched); `max_accepted` must be 0
  Dart_throwing_options darts;
  /// Search steps (interpolation or bisection) on the radius once it is bracketed (up to 64 steps that look
  /// for the bracket are not counted); default 60.
  std::size_t max_iterations = 60;
  /// A throw that keeps from count up to count + floor(count_tolerance count) items ends the search, cut to
  /// its first `count` accepted items (not maximal then): fewer throws where the count need not be hit by a
  /// maximal throw (stippling takes 0.01). In [0, 1]; default 0: only exactly `count` or a jump over it.
  double count_tolerance = 0;
  /// The radius (with `darts.radii`, the factor) to throw first when it is known roughly, finite and >= 0:
  /// the search then starts next to the answer instead of halving down from twice the largest distance (a
  /// few throws of every item less). Default 0: none.
  double initial_radius = 0;
  /// Cut the throw the search ends at to its first `count` accepted items (default). False: return the whole
  /// throw, `count` or more items, for a caller that drops the surplus its own way (the stippler drops it at
  /// random: with priorities the last accepted items are the least likely ones, light pixels, and a cut over
  /// a jump of 20 % thinned light areas).
  bool cut = true;
};

/// Options of continuous_bilateral_dart_throwing().
struct Continuous_dart_throwing_options {
  double sigma_position = 1;  ///< spatial scale of the metric; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  Bilateral_form form = Bilateral_form::gaussian;  ///< form of the bilateral distance
  /// Stop after this many consecutive rejected darts (the set is then close to maximal); at least 1, default
  /// 10000.
  std::size_t max_consecutive_failures = 10000;
  std::size_t max_samples = 0;  ///< stop after this many accepted samples; default 0: no limit
  std::uint64_t seed = 0;       ///< the random darts
  /// The box is a torus: each coordinate difference d counts as min(|d|, L - |d|) for the box's side L (the
  /// nearest images), so that the samples tile the plane; with the box {0, 0, 1, 1}, the unit torus of
  /// sampling_spectrum() and of the periodic measures of sampling_quality(). Default false.
  bool periodic = false;
  /// Called every 65536 darts with the largest fraction of the failure budget used so far (non-decreasing: a
  /// new sample resets the run of failures, not the report); false stops (samples so far are kept)
  Progress_callback progress;
};

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_SAMPLING_OPTIONS_H
