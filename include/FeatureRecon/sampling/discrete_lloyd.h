// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_DISCRETE_LLOYD_H
#define FEATURERECON_SAMPLING_DISCRETE_LLOYD_H

/// \file
/// Discrete bilateral Lloyd relaxation (dissertation Sec. 2.1.2 and 2.2.2): the domain is a set of items
/// (pixels, points with normals, users' items through FeaturePointTraits) with a density; every item goes to
/// the site nearest in the bilateral distance xi (ties to the lowest site index), sites move to the
/// density-weighted centroid of their items' positions (Eqn 2.2), and their features are re-sampled at the
/// new position from the nearest item; optionally the site snaps to that item (the closest domain point to
/// the centroid, the equation after 2.2). With options.periodic the items' box is a torus (tiles). Stages:
/// bilateral_voronoi_assignment() (the discrete bilateral Voronoi sets), discrete_lloyd_step() (one
/// iteration), discrete_bilateral_lloyd() (iterations with the stopping rules and per-iteration statistics
/// of lloyd_relaxation()).

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/sampling/internal/nearest_tree.h>
#include <FeatureRecon/sampling/internal/ring_grid.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/sampling_options.h>
#include <FeatureRecon/traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// A site of a bilateral sampling: a position (not necessarily an item's) and a feature.
/// \tparam Traits a model of FeaturePointTraits (it gives the dimension and the feature type).
template <class Traits>
struct Bilateral_site {
  std::array<double, Traits::dimension> position;  ///< the position, in the items' coordinates
  typename Traits::Feature feature;                ///< the feature (of the item nearest to the position)
};

/// How a site's feature follows its move.
enum class Site_update {
  nearest_item,  ///< the site keeps the centroid; its feature is that of the item nearest to it (the default)
  snap_to_item   ///< the site moves to the item nearest to the centroid and takes its feature (Eqn after 2.2)
};

/// Options of discrete_bilateral_lloyd() and its stages.
/// \tparam Dimension the items' dimension (2 or 3), the dimension of the positions on_iteration sees.
template <int Dimension>
struct Discrete_lloyd_options {
  double sigma_position = 1;  ///< spatial scale of xi; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  Bilateral_form form = Bilateral_form::gaussian;  ///< form of xi
  /// Density rho of each item (>= 0, finite), aligned with the items: the weight in the centroids and the
  /// energy (for stippling, the darkness). Default empty: 1 for every item. A density 0 on every item has no
  /// centroids: the sites as given, status degenerate_input (as lloyd_relaxation() and kernel_relaxation()).
  std::vector<double> density;
  Site_update update = Site_update::nearest_item;  ///< how features follow the sites
  std::size_t max_iterations = 50;                 ///< iteration cap; default 50
  /// Stop when (E_prev - E) / E_prev < energy_tolerance after an iteration; default 0 (never). The bilateral
  /// energy need not decrease monotonically (features change with the positions); a rise also stops it then.
  double energy_tolerance = 0;
  /// stop when no site moved farther than this (units of the positions); default 0
  double move_tolerance = 0;
  /// Area (2D items, surfaces) or volume of the domain for the relative radius; default 0: the measure of the
  /// box of 2D items and of volume items (their bounding box widened by the item spacing of each axis, so a
  /// W x H image of pixels has area W H; with `period`, the torus's), the estimated surface area of 3D
  /// surface items.
  double domain_measure = 0;
  /// 2 (images, surfaces: rho against the hexagonal packing) or 3 (volumes: against the FCC packing). Default
  /// 0: 2 for 2D items; for 3D items, 2 when most have a flat neighbourhood (as
  /// weighted_sample_elimination()).
  int intrinsic_dimension = 0;
  /// The items fill a box that is a torus: their bounding box widened by half the item spacing of each axis
  /// (a W x H image of pixels: [0, W] x [0, H]; items on a lattice of steps 1 x 2: the box of its cells), its
  /// widths the periods; or the box of the widths `period` centred on that bounding box. Every item goes to
  /// the site nearest on the torus (ties to the lowest site index), a site moves to the centroid of its items
  /// taken across the faces (each item at its image nearest the site) and wraps into the box, and the nearest
  /// item, the moves and the relative radius are the torus's. The sites then tile: a picture stippled on its
  /// torus can be repeated without seams. Copies of a site (equal positions once wrapped) move apart first; a
  /// site without items wraps too. Items all at one position give a box of no width, which does not wrap
  /// (unless `period` is given). For 2D items, and for 3D items of intrinsic dimension 3 (volumes:
  /// intrinsic_dimension 3, or 0 and estimated); refused for other 3D items (a surface does not fill its
  /// box). Default false.
  bool periodic = false;
  /// With `periodic`, the periods, one per axis, instead of the automatic ones: for items that are no full
  /// lattice (the automatic widening is then one spacing estimated for all axes), or a torus larger than the
  /// items' box. Each in [1e-150, 1e150] and at least the items' extent along its axis; the torus is the box
  /// of these widths centred on the items' bounding box (sites come back wrapped into it), and its measure is
  /// the domain's unless domain_measure is given. An axis of the items' extent 0 then wraps too. Default
  /// empty: automatic. Given without `periodic`, refused (as the samplers' `period`).
  std::vector<double> period;
  /// Called after each iteration with its statistics and the sites' positions after the move; returning
  /// false stops there (early stopping on rho or on an oscillation the callback computes). Default: none.
  std::function<bool(Lloyd_iteration_statistics&, const std::vector<std::array<double, Dimension>>&)>
      on_iteration;
  Progress_callback progress;  ///< fraction of max_iterations done; returning false stops (sites so far kept)
};

/// The discrete bilateral Voronoi sets of some sites: bilateral_voronoi_assignment().
struct Bilateral_assignment {
  /// per item: the index of its site (nearest in xi, ties to the lowest index)
  std::vector<std::uint32_t> site;
  std::vector<double> mass;  ///< per site: the density of its items
  double energy = 0;         ///< sum over items of rho(x) xi(x, site)^2
};

/// Result of discrete_lloyd_step().
template <class Traits>
struct Discrete_lloyd_step_result {
  /// the moved sites (a site without mass stays where it was; on the torus, wrapped into the box)
  std::vector<Bilateral_site<Traits>> sites;
  Bilateral_assignment assignment;  ///< the assignment of the sites given to the step
  double max_move = 0;              ///< largest move
  double mean_move = 0;             ///< mean move
};

/// Result of discrete_bilateral_lloyd().
template <class Traits>
struct Discrete_lloyd_result {
  std::vector<Bilateral_site<Traits>> sites;  ///< final sites, in input order
  /// Per item: its site at the last iteration (with no iteration done: among the starting sites).
  std::vector<std::uint32_t> assignment;
  std::vector<double> mass;  ///< per site: the density of its items, as `assignment`
  /// Per site: the item nearest to its final position (Euclidean or on the torus, ties to the lowest index),
  /// whose feature a site that moved carries; with Site_update::snap_to_item, the item it sits on. The way
  /// back from a site to the user's item (its other fields). A site that never received an item keeps the
  /// feature it started with. Empty when there are no items.
  std::vector<std::size_t> items;
  /// One entry per iteration done, taken before its move (Lloyd_iteration_statistics): the final sites'
  /// relative radius is sampling_quality() of `sites`.
  std::vector<Lloyd_iteration_statistics> history;
  Lloyd_stop stop = Lloyd_stop::iteration_cap;  ///< why it stopped
  /// degenerate_input for no items, no sites or a density 0 on every item (nothing moves; with items and
  /// sites, `assignment`, `mass` (all 0) and `items` are those of the sites as given); interrupted when the
  /// progress callback stopped it.
  Status status = Status::success;
};

namespace internal {
/// \cond
// The torus of a box [lo, hi): the periods are its widths; an axis of width 0 does not wrap.
template <int D>
struct Box_torus {
  using Point = std::array<double, D>;
  Point lo{}, hi{}, period{};

  // p moved by whole periods into [lo, hi) along every axis that wraps.
  void wrap(Point& p) const {
    for (int k = 0; k < D; ++k) {
      if (!(period[k] > 0) || (p[k] >= lo[k] && p[k] < hi[k])) continue;
      const double x = lo[k] + torus_coordinate(p[k] - lo[k], period[k]);
      p[k] = x < hi[k] ? x : lo[k];
    }
  }

  // Appends to q (and to source, the index of the point each copies) the images of the first n points of q,
  // translated by whole periods, that lie within reach(j) of the box: every one, not only the nearest, so a
  // reach wider than a period sees them all.
  template <class Reach>
  void add_images(std::vector<Point>& q, std::vector<std::uint32_t>& source, std::size_t n,
                  Reach&& reach_of) const {
    for (std::size_t j = 0; j < n; ++j) {
      const Point p = q[j];
      const double reach = reach_of(j);
      std::array<std::vector<double>, D> offsets;  // per axis: 0, then the shifts within reach of the box
      std::size_t combinations = 1;
      for (int k = 0; k < D; ++k) {
        offsets[k].push_back(0.0);
        if (period[k] > 0) {
          const double m = std::ceil(reach / period[k]) + 1;
          for (double s = 1; s <= m; ++s)
            for (const double v : {s * period[k], -s * period[k]})
              if (std::max(lo[k] - (p[k] + v), p[k] + v - hi[k]) <= reach) offsets[k].push_back(v);
        }
        combinations *= offsets[k].size();
      }
      for (std::size_t c = 1; c < combinations; ++c) {
        Point g = p;
        double gap2 = 0;
        std::size_t code = c;
        for (int k = 0; k < D; ++k) {
          g[k] += offsets[k][code % offsets[k].size()];
          code /= offsets[k].size();
          const double gap = std::max({0.0, lo[k] - g[k], g[k] - hi[k]});
          gap2 += gap * gap;
        }
        if (gap2 > reach * reach) continue;
        q.push_back(g);
        source.push_back(static_cast<std::uint32_t>(j));
      }
    }
  }
};

// The items of a relaxation as positions and features, with a grid for nearest-item queries.
template <class Traits>
class Item_domain {
 public:
  static constexpr int D = Traits::dimension;
  using Point = std::array<double, D>;
  using Site = Bilateral_site<Traits>;

  template <class ItemRange>
  // `compared`: whether features are compared (finite sigma_feature); only then must each be at a finite
  // distance from itself (a zero normal is fine for Euclidean relaxation).
  Item_domain(const ItemRange& items, const Traits& traits, double domain_measure, const char* fn,
              bool compared)
      : S(items, traits, fn, compared), measure(domain_measure), compared_features(compared) {
    if (!(domain_measure >= 0) || !std::isfinite(domain_measure))
      FeatureRecon::internal::throw_invalid_argument(fn, "domain_measure must be finite and >= 0, got ",
                                                     domain_measure);
    if (S.size() > std::numeric_limits<std::uint32_t>::max() - 1)
      FeatureRecon::internal::throw_invalid_argument(fn, "too many items (", S.size(), ")");
    if (S.size() == 0) return;
    lo = hi = S.positions[0];
    for (const auto& p : S.positions)
      for (int k = 0; k < D; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    item_grid = Ring_grid<D>(lo, hi, double(S.size()));
    item_grid.assign(S.positions);
  }

  std::size_t items() const { return S.size(); }

  // Sites as items are checked: finite coordinates within +-1e100 (a site at 1e200 overflowed the grid's cell
  // arithmetic into an undefined float-to-integer cast) and, where features are compared, a feature at a
  // finite distance from itself (a site with a zero normal silently got no item), unless `check_features` is
  // false (the caller replaces the sites' features before reading them). Also: the span of the items and the
  // sites together in units of sigma_position at most 2^400 (a site at 1e100 with sigma_position 1e-110 was
  // infinitely far from every item, and tied with a nearer site).
  void check_sites(const std::vector<Site>& sites, const char* fn, double sigma_position,
                   bool check_features = true) const {
    if (sites.size() > std::numeric_limits<std::uint32_t>::max() - 1)
      FeatureRecon::internal::throw_invalid_argument(fn, "too many sites (", sites.size(), ")");
    Point slo = lo, shi = hi;
    if (S.size() == 0 && !sites.empty()) slo = shi = sites[0].position;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      for (int k = 0; k < D; ++k) {
        if (!std::isfinite(sites[i].position[k]))
          FeatureRecon::internal::throw_invalid_argument(fn, "site ", i, " has a non-finite coordinate (",
                                                         sites[i].position[k], ")");
        if (!(std::fabs(sites[i].position[k]) <= Sample_set<Traits>::max_coordinate))
          FeatureRecon::internal::throw_invalid_argument(fn, "site ", i, " has coordinate ",
                                                         sites[i].position[k],
                                                         " beyond +-1e100 (as items; scale the input)");
        slo[k] = std::min(slo[k], sites[i].position[k]);
        shi[k] = std::max(shi[k], sites[i].position[k]);
      }
      if (compared_features && check_features) {
        const double self = CGAL::to_double(S.feature_distance(sites[i].feature, sites[i].feature));
        if (!(self >= 0 && self < std::numeric_limits<double>::infinity()))
          FeatureRecon::internal::throw_invalid_argument(fn, "site ", i,
                                                         " has a feature at distance NaN from itself "
                                                         "(a zero normal, or NaN in the feature)");
      }
    }
    double extent = 0;
    for (int k = 0; k < D; ++k) extent = std::max(extent, shi[k] - slo[k]);
    check_position_scale(extent, sigma_position, fn);
  }

  // The item nearest to x (Euclidean; ties to the lowest index). \pre items() > 0.
  std::uint32_t nearest_item(const Point& x) const {
    double best;
    return item_grid.nearest(
        x, 1.0, [&](std::uint32_t j) { return std::sqrt(squared(x, S.positions[j])); }, best);
  }

  // The torus of a box around the items (set_torus()); the plain space unless `wraps`.
  bool wraps = false;
  Box_torus<D> torus;
  // The periods are the box's widths, or exactly the given ones (take_period()).
  void set_torus(const Point& box_lo, const Point& box_hi) {
    wraps = true;
    torus.lo = box_lo;
    torus.hi = box_hi;
    for (int k = 0; k < D; ++k) torus.period[k] = has_period ? given_period[k] : box_hi[k] - box_lo[k];
  }

  // Reads a relaxation's `period` option: refused without `periodic`, of another length than D, outside
  // [1e-150, 1e150] (torus_period()), shorter than the items' extent along its axis (the items must fit in
  // one period), with a box reaching beyond +-1e100 (as items and sites) or spanning more than 2^400
  // sigma_position (check_position_scale()). Empty: the periods are automatic (relaxation_box()).
  void take_period(const std::vector<double>& period, bool periodic, double sigma_position, const char* fn) {
    if (period.empty()) return;
    const std::array<double, std::size_t(D)> p = torus_period<std::size_t(D)>(period, periodic, fn);
    double largest = 0;
    for (int k = 0; k < D; ++k) {
      const double e = hi[k] - lo[k], from = lo[k] - (p[std::size_t(k)] - e) / 2;  // centred on the items
      if (S.size() > 0 && !(p[std::size_t(k)] >= e))
        FeatureRecon::internal::throw_invalid_argument(fn, "period[", k, "] = ", p[std::size_t(k)],
                                                       " is shorter than the items' extent along axis ", k,
                                                       " (", e, "): the items must fit in one period");
      if (!(std::fabs(from) <= Sample_set<Traits>::max_coordinate &&
            std::fabs(from + p[std::size_t(k)]) <= Sample_set<Traits>::max_coordinate))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "period[", k, "] = ", p[std::size_t(k)],
            " puts the torus's faces beyond +-1e100 (as items; scale the input)");
      given_period[k] = p[std::size_t(k)];
      given_lo[k] = from;
      largest = std::max(largest, p[std::size_t(k)]);
    }
    check_position_scale(largest, sigma_position, fn);
    has_period = true;
  }

  // The box of a relaxation (the torus of `periodic`, kernel_relaxation()'s bounding box): with a period
  // given (take_period()), the box of those widths centred on the items' bounding box; else that bounding box
  // widened by half the item spacing of each axis (axis_spacing(); a W x H image of pixels: [0, W] x [0, H]).
  // \pre items() > 0.
  void relaxation_box(Point& box_lo, Point& box_hi) const {
    if (has_period) {
      box_lo = given_lo;
      for (int k = 0; k < D; ++k) box_hi[k] = given_lo[k] + given_period[k];
      return;
    }
    const Point spacing = axis_spacing();
    for (int k = 0; k < D; ++k) {
      box_lo[k] = lo[k] - spacing[k] / 2;
      box_hi[k] = hi[k] + spacing[k] / 2;
    }
  }

  // nearest_item(), on the torus when the domain wraps: x is wrapped first and its images across the faces
  // compete (with x and the items in the box, the shifts -1, 0 and +1 of every axis reach them all; ties to
  // the lowest index). \pre items() > 0.
  std::uint32_t nearest_item_at(Point x) const {
    if (!wraps) return nearest_item(x);
    torus.wrap(x);
    auto nearest = [this](const Point& q, double& best) {
      return item_grid.nearest(
          q, 1.0, [&](std::uint32_t j) { return std::sqrt(squared(q, S.positions[j])); }, best);
    };
    double best;
    std::uint32_t near = nearest(x, best);
    std::size_t shifts = 1;
    for (int k = 0; k < D; ++k) shifts *= 3;
    for (std::size_t b = 1; b < shifts; ++b) {  // digit 0, 1, 2 of b: shift 0, +1, -1 along that axis
      Point q = x;
      double gap2 = 0;
      bool moved = true;
      std::size_t code = b;
      for (int k = 0; k < D; ++k, code /= 3) {
        const double s = code % 3 == 0 ? 0.0 : code % 3 == 1 ? 1.0 : -1.0;
        if (s != 0 && !(torus.period[k] > 0)) moved = false;
        q[k] += s * torus.period[k];
        const double gap = std::max({0.0, lo[k] - q[k], q[k] - hi[k]});
        gap2 += gap * gap;
      }
      if (!moved || gap2 > best * best) continue;  // no item of this image can be nearer
      double d;
      const std::uint32_t j = nearest(q, d);
      if (d < best || (d == best && j < near)) {
        best = d;
        near = j;
      }
    }
    return near;
  }

  static std::vector<Point> positions_of(const std::vector<Site>& sites, Point& flo, Point& fhi) {
    std::vector<Point> positions(sites.size());
    for (std::size_t s = 0; s < sites.size(); ++s) {
      positions[s] = sites[s].position;
      for (int k = 0; k < D; ++k) {
        flo[k] = std::min(flo[k], positions[s][k]);
        fhi[k] = std::max(fhi[k], positions[s][k]);
      }
    }
    return positions;
  }

  // Shortest distance between two sites at distinct positions (infinity for fewer than two distinct) and
  // whether two sites coincide.
  static double minimum_distance(const std::vector<Site>& sites, bool& coincide) {
    coincide = false;
    if (sites.size() < 2) return std::numeric_limits<double>::infinity();
    Point flo = sites[0].position, fhi = flo;
    const std::vector<Point> positions = positions_of(sites, flo, fhi);
    Ring_grid<D> grid(flo, fhi, double(sites.size()));
    grid.assign(positions);
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < sites.size(); ++s) {
      double best;
      grid.nearest(
          positions[s], 1.0,
          [&](std::uint32_t j) {
            if (j == s) return std::numeric_limits<double>::infinity();
            const double d = std::sqrt(squared(positions[s], positions[j]));
            if (d == 0) coincide = true;
            return d == 0 ? std::numeric_limits<double>::infinity() : d;
          },
          best);
      shortest = std::min(shortest, best);
    }
    return shortest;
  }

  // The spacing h of the items read as a grid filling their bounding box widened by h: the root of
  // prod_k (extent_k + h) = n h^D (h = 1 for a W x H image of pixels); 0 for one item or one position.
  double grid_spacing() const {
    const double n = double(S.size());
    double e_max = 0;
    for (int k = 0; k < D; ++k) e_max = std::max(e_max, hi[k] - lo[k]);
    if (!(n > 1) || !(e_max > 0)) return 0;
    // f(h) = sum log(e_k + h) - D log h - log n decreases from +inf to -log n < 0.
    auto f = [&](double h) {
      double v = -D * std::log(h) - std::log(n);
      for (int k = 0; k < D; ++k) v += std::log(hi[k] - lo[k] + h);
      return v;
    };
    double a = 0, b = e_max;
    while (f(b) > 0) b *= 2;
    for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
      const double m = 0.5 * (a + b);
      (m > 0 && f(m) > 0 ? a : b) = m;
    }
    // A full lattice (whole numbers of items along every axis whose product is n) gets its spacing exactly:
    // the bracket's end lies a few ulps off (1 + 4e-16 for a 30 x 30 image), which moved thresholds that
    // compare with it, such as kernel_relaxation()'s density blocks that just fit the kernel.
    std::size_t widest = 0;
    for (int k = 1; k < D; ++k)
      if (hi[k] - lo[k] > hi[widest] - lo[widest]) widest = std::size_t(k);
    const double steps = std::round((hi[widest] - lo[widest]) / b);
    if (steps >= 1) {
      const double h = (hi[widest] - lo[widest]) / steps;
      double product = 1;
      bool whole = true;
      for (int k = 0; k < D && whole; ++k) {
        const double count = (hi[k] - lo[k]) / h + 1, rounded = std::round(count);
        whole = std::abs(count - rounded) <= 1e-9 * rounded;
        product *= rounded;
      }
      if (whole && product == n) return h;
    }
    return b;
  }

  // The item spacing along each axis. Items on a full lattice (distinct, at every combination of n_k equally
  // spaced coordinates along axis k, prod n_k = n) have their steps e_k / (n_k - 1) along the axes of more
  // than one coordinate, so an anisotropic lattice (spacing 1 x 2) fills the box of its cells; every other
  // axis (one coordinate), and items that are no lattice, take grid_spacing(), as does a lattice whose steps
  // all lie within 1e-9 of it (relatively). O(n) once (the smallest positive offset from the box's corner
  // along each axis is its step; each item then has a cell of the lattice, all different), then cached.
  Point axis_spacing() const {
    if (!spacing_known) {
      axis_spacing_cache = lattice_steps();
      spacing_known = true;
    }
    return axis_spacing_cache;
  }
  Point lattice_steps() const {
    const double h = grid_spacing();
    Point steps;
    steps.fill(h);
    const std::size_t n = S.size();
    if (n < 2) return steps;
    Point offset;
    offset.fill(std::numeric_limits<double>::infinity());
    for (const Point& p : S.positions)
      for (int k = 0; k < D; ++k)
        if (p[k] > lo[k]) offset[k] = std::min(offset[k], p[k] - lo[k]);
    std::array<std::size_t, std::size_t(D)> count{};
    double product = 1;
    for (int k = 0; k < D; ++k) {
      const double e = hi[k] - lo[k], c = e > 0 ? std::round(e / offset[k]) + 1 : 1;
      if (!(c <= double(n))) return steps;
      count[std::size_t(k)] = std::size_t(c);
      product *= c;
    }
    if (product != double(n)) return steps;
    Point found = steps;
    bool isotropic = true;
    for (int k = 0; k < D; ++k)
      if (count[std::size_t(k)] > 1) {
        found[k] = (hi[k] - lo[k]) / double(count[std::size_t(k)] - 1);
        if (!(std::fabs(found[k] - h) <= 1e-9 * h)) isotropic = false;
      }
    if (isotropic) return steps;
    std::vector<char> taken(n, 0);  // each item in its own cell: every cell once
    for (const Point& p : S.positions) {
      std::size_t cell = 0;
      for (int k = D; k-- > 0;) {
        const double e = hi[k] - lo[k];
        std::size_t i = 0;
        if (count[std::size_t(k)] > 1) {
          const double at = std::round((p[k] - lo[k]) / found[k]);
          if (!(std::fabs(p[k] - (lo[k] + at * found[k])) <= 1e-9 * e && at >= 0 &&
                at <= double(count[std::size_t(k)] - 1)))
            return steps;  // off the lattice
          i = std::size_t(at);
        }
        cell = cell * count[std::size_t(k)] + i;
      }
      if (taken[cell]) return steps;  // a copy: some cell is empty
      taken[cell] = 1;
    }
    return found;
  }

  // d_hex = sqrt(2 A / (sqrt(3) n)) for n sites on the domain's area (2D, or the surface of 3D items); in a
  // volume (intrinsic 3) d_fcc = cbrt(sqrt(2) V / n).
  double packing_distance(std::size_t n) const {
    if (n == 0 || S.size() == 0) return 0;
    double m = measure;
    if ((intrinsic != 0 ? intrinsic : resolve_intrinsic_dimension(S, 0)) == 3) {
      if (m == 0) m = box_measure();
      return std::cbrt(std::sqrt(2.0) * m / double(n));
    }
    if (m == 0) {
      if constexpr (D == 2) {
        m = box_measure();
      } else {
        const std::vector<std::array<double, 3>> places = distinct_positions(S.positions);
        m = estimate_surface_area(places, Knn_3(places));
      }
    }
    return std::sqrt(2 * m / (std::sqrt(3.0) * double(n)));
  }

  // The measure of relaxation_box(): the product of the given periods, else of the extents widened by the
  // item spacing of each axis.
  double box_measure() const {
    double m = 1;
    if (has_period) {
      for (int k = 0; k < D; ++k) m *= given_period[k];
      return m;
    }
    const Point spacing = axis_spacing();
    for (int k = 0; k < D; ++k) m *= hi[k] - lo[k] + spacing[k];
    return m;
  }

  // rho of the sites: minimum distance over the packing distance (0 when two coincide).
  double relative_radius(const std::vector<Site>& sites, double packing) const {
    bool coincide = false;
    const double shortest = minimum_distance(sites, coincide);
    return (coincide || std::isinf(shortest) || packing == 0) ? 0.0 : shortest / packing;
  }

  // relative_radius(), on the torus when the domain wraps: the sites (wrapped) against the images of the
  // others within the shortest distance in the box (own images do not count).
  double relative_radius_at(const std::vector<Site>& sites, double packing) const {
    if (!wraps) return relative_radius(sites, packing);
    std::vector<Site> wrapped = sites;
    for (Site& site : wrapped) torus.wrap(site.position);
    bool coincide = false;
    const double plain = minimum_distance(wrapped, coincide);
    if (coincide || std::isinf(plain) || packing == 0) return 0.0;
    std::vector<Point> q;
    std::vector<std::uint32_t> source;
    for (std::size_t i = 0; i < wrapped.size(); ++i) {
      q.push_back(wrapped[i].position);
      source.push_back(static_cast<std::uint32_t>(i));
    }
    torus.add_images(q, source, wrapped.size(), [plain](std::size_t) { return plain; });
    Point flo = q[0], fhi = q[0];
    for (const auto& p : q)
      for (int k = 0; k < D; ++k) {
        flo[k] = std::min(flo[k], p[k]);
        fhi[k] = std::max(fhi[k], p[k]);
      }
    Ring_grid<D> grid(flo, fhi, double(q.size()));
    grid.assign(q);
    double shortest = plain;
    for (std::size_t i = 0; i < wrapped.size(); ++i) {
      double best;
      grid.nearest(
          q[i], 1.0,
          [&](std::uint32_t t) {
            return source[t] == i ? std::numeric_limits<double>::infinity() : std::sqrt(squared(q[i], q[t]));
          },
          best);
      shortest = std::min(shortest, best);
    }
    return shortest / packing;
  }

  static double squared(const Point& a, const Point& b) {
    double s = 0;
    for (int k = 0; k < D; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return s;
  }

  // 2 (images, surfaces) or 3 (volumes): the packing behind the relative radius.
  static int resolve_intrinsic_dimension(const Sample_set<Traits>& S, int requested) {
    if (requested != 0) return requested;
    if constexpr (D == 3) {
      if (S.size() >= 8 && affine_dimension<3>(S.positions) == 3) {
        const std::vector<std::array<double, 3>> places = distinct_positions(S.positions);
        return estimate_intrinsic_dimension(places, Knn_3(places));
      }
    }
    return 2;
  }

  Sample_set<Traits> S;
  double measure = 0;
  bool compared_features = true;  // features compared (finite sigma_feature): sites' features are checked too
  // 2 or 3; 0: estimated when the packing distance asks (not for every step of a stage call)
  int intrinsic = 0;
  Point lo{}, hi{};
  Ring_grid<D> item_grid;
  bool has_period = false;             // a `period` option was given (take_period())
  Point given_period{}, given_lo{};    // the periods and the torus's lower faces
  mutable bool spacing_known = false;  // axis_spacing()
  mutable Point axis_spacing_cache{};
};

// The domain, its density and the metric of one discrete Lloyd run.
template <class Traits>
class Discrete_lloyd_engine : public Item_domain<Traits> {
 public:
  static constexpr int D = Traits::dimension;
  using Base = Item_domain<Traits>;
  using Point = std::array<double, D>;
  using Site = Bilateral_site<Traits>;
  using Base::S;

  template <class ItemRange>
  Discrete_lloyd_engine(const ItemRange& items, const Discrete_lloyd_options<D>& o, const Traits& traits,
                        const char* fn)
      : Base(items, traits, o.domain_measure, fn, std::isfinite(o.sigma_feature)), options(o) {
    check_sigmas(o.sigma_position, o.sigma_feature, fn);  // the span: check_sites(), items and sites together
    check_domain(o.domain_measure, o.intrinsic_dimension, D, fn);
    this->intrinsic = o.intrinsic_dimension;
    if (!o.density.empty() && o.density.size() != S.size())
      FeatureRecon::internal::throw_invalid_argument(fn, "density has ", o.density.size(), " values for ",
                                                     S.size(), " items");
    for (std::size_t i = 0; i < o.density.size(); ++i)
      if (!(o.density[i] >= 0 && std::isfinite(o.density[i])))
        FeatureRecon::internal::throw_invalid_argument(fn, "density[", i, "] must be finite and >= 0, got ",
                                                       o.density[i]);
    if (!(o.energy_tolerance >= 0 && std::isfinite(o.energy_tolerance)) ||
        !(o.move_tolerance >= 0 && std::isfinite(o.move_tolerance)))
      FeatureRecon::internal::throw_invalid_argument(
          fn, "energy_tolerance and move_tolerance must be finite and >= 0, got ", o.energy_tolerance,
          " and ", o.move_tolerance);
    if (o.periodic && D == 3) {
      if (this->intrinsic == 0) this->intrinsic = Base::resolve_intrinsic_dimension(S, 0);
      if (this->intrinsic != 3)
        FeatureRecon::internal::throw_invalid_argument(
            fn, "periodic needs items that fill their box: 2D items, or 3D items of intrinsic dimension 3 (",
            o.intrinsic_dimension == 0 ? "estimated " : "intrinsic_dimension ", this->intrinsic, ")");
    }
    this->take_period(o.period, o.periodic, o.sigma_position, fn);
    if (o.periodic && S.size() > 0) {
      Point box_lo, box_hi;
      this->relaxation_box(box_lo, box_hi);
      this->set_torus(box_lo, box_hi);
    }
  }

  double density(std::size_t i) const { return options.density.empty() ? 1.0 : options.density[i]; }

  // The rings of cells and the sites the assignment's grid searches before it asks the kd-tree; in 3-D the
  // tree alone (200k items on a sphere, 5k sites: 141 -> 107 ms Euclidean, 661 -> 146 ms bilateral; in a
  // cube about the same), in the plane the rings first (uniform sites: about 20 % faster than the tree).
  static constexpr bool rings_first = D == 2;
  static constexpr std::int64_t ring_limit = 2;
  static constexpr std::size_t score_limit = 64;
  // Nodes of the kd-tree searched by position alone before the search starts again with the feature balls.
  static constexpr std::size_t balls_after = 64;

  // The assignment; on the torus also, per item, the shift from its site to the site's image nearest it
  // (`shift`, when given), each site wrapped into the box.
  Bilateral_assignment assign(const std::vector<Site>& given, std::vector<Point>* shift = nullptr) const {
    Bilateral_assignment a;
    a.site.assign(S.size(), 0);
    a.mass.assign(given.size(), 0.0);
    if (shift) shift->assign(S.size(), Point{});
    if (given.empty() || S.size() == 0) return a;
    std::vector<Site> wrapped;
    if (this->wraps) {
      wrapped = given;
      for (Site& site : wrapped) this->torus.wrap(site.position);
    }
    const std::vector<Site>& sites = this->wraps ? wrapped : given;
    Point flo = this->lo, fhi = this->hi;
    std::vector<Point> positions = Base::positions_of(sites, flo, fhi);
    // On the torus every site's images shifted by -1, 0 or +1 period along each axis that wraps, site by
    // site (so that the grid's ties to the lowest index are ties to the lowest site): with the items and the
    // sites in the box, they hold the image nearest each item.
    std::vector<std::uint32_t> source;
    if (this->wraps) {
      std::vector<Point> images;
      std::size_t shifts = 1;
      for (int k = 0; k < D; ++k) shifts *= 3;
      if (sites.size() > (std::numeric_limits<std::uint32_t>::max() - 1) / shifts)
        FeatureRecon::internal::throw_invalid_argument(
            S.fn, "too many sites on the torus (", sites.size(), "; at most ",
            (std::numeric_limits<std::uint32_t>::max() - 1) / shifts, ": each has ", shifts, " images)");
      for (std::size_t j = 0; j < sites.size(); ++j)
        for (std::size_t b = 0; b < shifts; ++b) {
          Point q = positions[j];
          bool moved = true;
          std::size_t code = b;
          for (int k = 0; k < D; ++k, code /= 3) {
            const double s = code % 3 == 0 ? 0.0 : code % 3 == 1 ? 1.0 : -1.0;
            if (s != 0 && !(this->torus.period[k] > 0)) moved = false;
            q[k] += s * this->torus.period[k];
          }
          if (!moved) continue;
          for (int k = 0; k < D; ++k) {
            flo[k] = std::min(flo[k], q[k]);
            fhi[k] = std::max(fhi[k], q[k]);
          }
          images.push_back(q);
          source.push_back(static_cast<std::uint32_t>(j));
        }
      positions.swap(images);
    }
    // A ring search around each item first (a few cells where the sites cover the items' box), the kd-tree
    // where that does not settle it (items far from every site: a dark logo on white; sites crowded into a
    // few cells). Positions spanning less than 1e-100 keep the full ring search: squared distances below
    // the normal range lose their digits in the score (a site at score 0 ties with one that is not), where
    // the grid's bound and the tree's exact box distances would part.
    double span = 0;
    for (int k = 0; k < D; ++k) span = std::max(span, fhi[k] - flo[k]);
    const bool tiny = span > 0 && span < 1e-100;
    Ring_grid<D> grid;
    if (tiny || rings_first) {
      grid = Ring_grid<D>(flo, fhi, double(positions.size()));
      grid.assign(positions);
    }
    const Nearest_tree<D> tree(tiny ? std::vector<Point>() : positions);
    auto site_of = [&](std::uint32_t t) { return this->wraps ? source[t] : t; };
    // Feature balls, where the traits declare the square root of the feature distance a metric
    // (FeaturePointTraits::feature_metric_error >= 0): per node of the tree, an upper bound of the feature
    // distance (the square root) from its first site to its others, sqrt(R + e) (1 + 1e-12) from their
    // largest computed squared distance R and the declared error e (infinity where one is not a distance).
    // An item's feature q then lies at least d(q, first) - radius from every site of the node (the triangle
    // inequality), and the node's bound becomes xi(|box|, that) instead of |box| / sigma_position: where
    // every site's feature is far from the item's (white pixels against the sites of a dark logo) the
    // exponential form, whose feature factor multiplies, otherwise scored nearly every site.
    constexpr double declared_error = FeatureRecon::internal::Feature_metric_error<Traits>::value;
    const bool balls = S.compared && declared_error >= 0 && !tiny;
    // The declared error, plus 2^-1000: squares below the normal range round by an absolute amount (up to
    // 2^-1075 each), which the relative margins do not cover (features 1e-162 apart: a review's repro).
    const double metric_error = declared_error + 0x1p-1000;
    std::vector<double> radius(balls ? tree.number_of_nodes() : 0);
    std::vector<std::uint32_t> pivot_of(radius.size());  // per node: the site of its first point
    const double infinity = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < radius.size(); ++v) {
      const auto [first, last] = tree.node_points(v);
      pivot_of[v] = site_of(*first);
      const typename Traits::Feature& pivot = sites[pivot_of[v]].feature;
      double r = 0;
      for (const std::uint32_t* t = first + 1; t != last && r < infinity; ++t) {
        const double d = CGAL::to_double(S.feature_distance(pivot, sites[site_of(*t)].feature));
        r = d >= 0 ? std::max(r, d) : infinity;  // NaN or negative: no bound
      }
      radius[v] = std::sqrt(r + metric_error) * (1 + 1e-12);
    }
    with_metric(options, [&](const auto& metric) {
      const double scale = metric.spatial_scale();
      std::uint32_t previous = Nearest_tree<D>::none;
      for (std::size_t i = 0; i < S.size(); ++i) {
        const Point& x = S.positions[i];
        auto score = [&](std::uint32_t u) {
          const std::uint32_t j = site_of(u);
          return metric(Base::squared(x, positions[u]),
                        S.compared ? checked_feature_distance(
                                         CGAL::to_double(S.feature_distance(S.features[i], sites[j].feature)),
                                         S.fn, "item", i, "site", j)
                                   : 0.0);
        };
        double best = std::numeric_limits<double>::infinity();
        bool complete = false;
        std::uint32_t t = Nearest_tree<D>::none;
        if (tiny) {
          t = grid.nearest(x, scale, score, best);
          complete = true;
        } else if (rings_first) {
          t = grid.nearest(x, scale, score, best, ring_limit, score_limit, complete);
        }
        // The hint: the best of the rings, else the previous item's site (an image's neighbour, most often).
        const std::uint32_t hint = t != Nearest_tree<D>::none ? t : previous;
        if (!complete && !balls) t = tree.nearest(x, scale, score, best, hint);
        if (!complete && balls) {
          // First by position alone, for balls_after nodes: most searches end there (a site of a feature
          // like the item's nearby), and there the feature distance to each node's first site cost more
          // than it saved (8-24 % more instructions: random greys, normals on a sphere or all equal). Then
          // again from the best site so far, with the balls: a node holds no site scoring at most slack
          // when xi(|box|^2, g^2) > slack, for g^2 below the computed squared feature distance to each of
          // its sites: g = q - radius, q = sqrt(D - e) (1 - 1e-12) from the computed squared distance D to
          // the node's first site; g squared, less 1e-12 of it and e again (the margins lie far above the
          // roundings). A node and its left child share their first site: its q is kept. The Gaussian form
          // compares squares (no square root per node) while the square of the slack keeps its digits.
          t = tree.nearest(x, scale, score, best, hint, typename Nearest_tree<D>::No_refusal(), balls_after,
                           complete);
          std::uint32_t known = Nearest_tree<D>::none;
          double q = -1;
          auto refuse = [&](std::uint32_t v, double squared_bound, double slack) {
            const std::uint32_t first = pivot_of[v];
            if (first != known) {
              known = first;
              const double d = CGAL::to_double(S.feature_distance(S.features[i], sites[first].feature));
              q = d >= 0 ? std::sqrt(std::max(0.0, d - metric_error)) * (1 - 1e-12) : -1;  // NaN: none
            }
            const double g = q - radius[v];
            if (!(g > 0)) return false;
            const double lower = std::max(0.0, g * g * (1 - 1e-12) - metric_error);
            return metric.exceeds(squared_bound, lower, slack);
          };
          if (!complete)
            t = tree.nearest(x, scale, score, best, t, refuse, Nearest_tree<D>::unlimited, complete);
        }
        previous = t;
        const std::uint32_t s = site_of(t);
        a.site[i] = s;
        a.mass[s] += density(i);
        a.energy += density(i) * best * best;
        if (shift && this->wraps)
          for (int k = 0; k < D; ++k) (*shift)[i][k] = positions[t][k] - sites[s].position[k];
      }
    });
    return a;
  }

  // The distance between two positions; on the torus the shortest between their images.
  double distance(const Point& a, const Point& b) const {
    if (!this->wraps) return std::sqrt(Base::squared(a, b));
    Point p = a, q = b;
    this->torus.wrap(p);
    this->torus.wrap(q);
    // Along an axis of period 0 the difference comes out negated: squared, the same.
    return std::sqrt(torus_squared_distance(p, q, this->torus.period));
  }

  Discrete_lloyd_step_result<Traits> step(const std::vector<Site>& sites) const {
    Discrete_lloyd_step_result<Traits> r;
    std::vector<Point> shift;
    r.assignment = assign(sites, this->wraps ? &shift : nullptr);
    // On the torus each item counts at its image nearest its site: the centroid of a cell across a face.
    std::vector<std::array<double, D>> sum(sites.size(), std::array<double, D>{});
    for (std::size_t i = 0; i < S.size(); ++i) {
      const double w = density(i);
      auto& acc = sum[r.assignment.site[i]];
      if (this->wraps)
        for (int k = 0; k < D; ++k) acc[k] += w * (S.positions[i][k] - shift[i][k]);
      else
        for (int k = 0; k < D; ++k) acc[k] += w * S.positions[i][k];
    }
    r.sites = sites;
    if (this->wraps)
      for (Site& site : r.sites) this->torus.wrap(site.position);
    double total_move = 0;
    for (std::size_t s = 0; s < sites.size(); ++s) {
      const double m = r.assignment.mass[s];
      if (!(m > 0)) continue;  // no item or no mass: the site stays
      Point c;
      for (int k = 0; k < D; ++k) c[k] = sum[s][k] / m;
      if (this->wraps) this->torus.wrap(c);
      const std::uint32_t near = this->nearest_item_at(c);
      if (options.update == Site_update::snap_to_item) {
        c = S.positions[near];
        if (this->wraps) this->torus.wrap(c);  // an item on the box's upper face (a period of the extent)
      }
      const double move = distance(c, sites[s].position);

      r.max_move = std::max(r.max_move, move);
      total_move += move;
      r.sites[s].position = c;
      r.sites[s].feature = S.features[near];
    }
    r.mean_move = sites.empty() ? 0.0 : total_move / double(sites.size());
    return r;
  }

  const Discrete_lloyd_options<D>& options;
};
/// \endcond
}  // namespace internal

namespace internal {
/// \cond
template <class I>
bool is_index(I i, std::size_t n) {
  if constexpr (std::is_signed<I>::value)
    if (i < 0) return false;
  return static_cast<std::size_t>(i) < n;
}
/// Whether R is a range of integers (not bool): indices into the items, as the index-start overloads take.
template <class R, class = void>
struct is_index_range : std::false_type {};
template <class R>
struct is_index_range<R, std::void_t<decltype(*std::begin(std::declval<const R&>()))>> {
  using value_type = std::decay_t<decltype(*std::begin(std::declval<const R&>()))>;
  static constexpr bool value = std::is_integral<value_type>::value && !std::is_same<value_type, bool>::value;
};
/// \endcond
}  // namespace internal

namespace internal {
/// \cond
/// sites_at_items() naming `fn` in its errors (the entry point the user called).
template <class ItemRange, class IndexRange, class Traits>
std::vector<Bilateral_site<Traits>> sites_at_items(const ItemRange& items, const IndexRange& indices,
                                                   const Traits& traits, const char* fn) {
  const Sample_set<Traits> S(items, traits, fn, false);  // features are only copied
  std::vector<Bilateral_site<Traits>> sites;
  std::size_t k = 0;
  for (const auto i : indices) {
    if (!is_index(i, S.size()))
      FeatureRecon::internal::throw_invalid_argument(fn, "indices[", k, "] = ", i, " is not an item index (",
                                                     S.size(), " items)");
    sites.push_back({S.positions[std::size_t(i)], S.features[std::size_t(i)]});
    ++k;
  }
  return sites;
}
/// \endcond
}  // namespace internal

/// The sites at some items: position and feature of items[indices[k]] (for starting from the output of
/// bilateral_dart_throwing() or weighted_sample_elimination()).
/// \param items the domain. \param indices indices into it (checked; throws naming the first bad one).
/// \param traits a model of FeaturePointTraits.
template <class ItemRange, class IndexRange, class Traits = Default_traits_t<ItemRange>>
std::vector<Bilateral_site<Traits>> sites_at_items(const ItemRange& items, const IndexRange& indices,
                                                   const Traits& traits = Traits()) {
  return internal::sites_at_items(items, indices, traits, "sites_at_items");
}

/// Stage 1: the discrete bilateral Voronoi sets (dissertation Sec. 2.2.2): every item goes to the site of
/// smallest xi (ties to the lowest site index). Each item's sites are searched by xi's spatial lower bound
/// |dp| / sigma_position: in the plane first in two rings of a grid of the sites (or until 64 sites are
/// scored), then in a kd-tree of the sites (same bound) where the rings do not settle it (sites covering a
/// small part of the items' box, as a dark logo on white; sites crowded into a few cells); in 3-D in the
/// tree alone; for positions spanning less than 1e-100 in the grid's full ring search. The result is that
/// of the brute-force search
/// (while squared distances over sigma_position^2 keep their digits: below about 1e-300 they round to 0 and
/// tie, and which of the tied sites each search reaches first is not the lowest index). The
/// spatial bound ignores features: it visits every site whose spatial term alone is below the item's best
/// xi. That is a few sites when the nearest one has a feature close to the item's; where every site's
/// feature is far from it (white pixels of a logo whose sites are all black) it is the sites within about
/// sigma_position times the feature term, and with the exponential form, whose feature factor multiplies
/// (exp(1 / 0.09) for sigma_feature 0.3), nearly all of them. Where the traits declare the square root of
/// the feature distance a metric (FeaturePointTraits::feature_metric_error; the ready traits do), a tree
/// search that runs past 64 nodes starts again with a bound of each node's features too (a ball around
/// the feature of its first site), which rules such sites out a node at a time (a step on a 1 MP logo with
/// the exponential form: 150 s -> 2 s). Features that do not follow position (random greys or normals)
/// still visit the sites within that reach.
/// \param items the domain. \param sites the sites (finite positions, checked; throws).
/// \param options metric and density (the iteration settings are not used). \param traits FeaturePointTraits.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Bilateral_assignment bilateral_voronoi_assignment(
    const ItemRange& items, const std::vector<Bilateral_site<Traits>>& sites,
    const Discrete_lloyd_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  const internal::Discrete_lloyd_engine<Traits> engine(items, options, traits,
                                                       "bilateral_voronoi_assignment");
  engine.check_sites(sites, "bilateral_voronoi_assignment", options.sigma_position);
  return engine.assign(sites);
}

/// Stage 2: one discrete bilateral Lloyd iteration: the assignment, then every site with mass moves to the
/// density-weighted centroid of its items' positions (Eqn 2.2) and takes the feature of the item nearest to
/// it (or snaps to that item, Site_update::snap_to_item). Same arguments as bilateral_voronoi_assignment().
/// \param items the domain. \param sites the sites. \param options metric, density and update rule.
/// \param traits FeaturePointTraits.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Discrete_lloyd_step_result<Traits> discrete_lloyd_step(
    const ItemRange& items, const std::vector<Bilateral_site<Traits>>& sites,
    const Discrete_lloyd_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  const internal::Discrete_lloyd_engine<Traits> engine(items, options, traits, "discrete_lloyd_step");
  engine.check_sites(sites, "discrete_lloyd_step", options.sigma_position);
  return engine.step(sites);
}

/// Discrete bilateral Lloyd relaxation (dissertation Sec. 2.2.2): discrete_lloyd_step() until a stopping
/// rule holds (iteration cap, relative energy decrease, largest move, the on_iteration callback), with the
/// energy, the moves and the relative radius of every iteration (Lloyd drifts towards a lattice: stop early
/// on rho or the oscillation through on_iteration). Deterministic: no randomness beyond the starting sites
/// (use a seeded sampler for those); ties go to the lowest index. Copies among the starting sites (equal
/// positions) first move apart by a hundredth of the packing distance (with max_iterations 0 the sites are
/// returned as given). With an infinite sigma_feature it is discrete (Euclidean, weighted) Lloyd, i.e.
/// weighted k-means of the items' positions.
/// \param items the domain: a range of items read through the traits (positions finite, checked).
/// \param sites the starting sites, e.g. sites_at_items() of a dart-throwing result (finite, checked).
/// \param options metric, density, update rule, stopping rules, callbacks (checked; throws naming the field).
/// \param traits a model of FeaturePointTraits.
/// \return the sites, the last assignment and the history. No items or no sites: degenerate_input, sites
///   returned unchanged.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Discrete_lloyd_result<Traits> discrete_bilateral_lloyd(
    const ItemRange& items, std::vector<Bilateral_site<Traits>> sites,
    const Discrete_lloyd_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  const char* fn = "discrete_bilateral_lloyd";
  const internal::Discrete_lloyd_engine<Traits> engine(items, options, traits, fn);
  engine.check_sites(sites, fn, options.sigma_position);
  Discrete_lloyd_result<Traits> result;
  if (engine.items() == 0 || sites.empty()) {
    result.sites = std::move(sites);
    result.assignment.assign(engine.items(), 0);
    result.mass.assign(result.sites.size(), 0.0);
    result.status = Status::degenerate_input;
    return result;
  }
  if (!options.density.empty() &&
      std::none_of(options.density.begin(), options.density.end(), [](double rho) { return rho > 0; })) {
    Bilateral_assignment a = engine.assign(sites);
    result.assignment = std::move(a.site);
    result.mass = std::move(a.mass);
    for (const auto& site : sites) result.items.push_back(engine.nearest_item_at(site.position));
    result.sites = std::move(sites);
    result.status = Status::degenerate_input;
    return result;
  }
  const double packing = engine.packing_distance(sites.size());
  // Copies of a site tie with it for every item and got none: where the first copy was already at its
  // centroid they stayed together for good. Every copy after the first moves by 1/100 of the packing distance
  // first.
  // On the torus the sites are wrapped first: a whole period apart they are copies.
  if (engine.wraps && options.max_iterations > 0)
    for (auto& site : sites) engine.torus.wrap(site.position);
  if (packing > 0 && std::isfinite(packing) &&
      options.max_iterations > 0)  // no iteration: the sites as given
    internal::separate_copies<Traits::dimension>(
        sites.size(), packing / 100, [&sites](std::size_t i) -> auto& { return sites[i].position; });
  double previous_energy = std::numeric_limits<double>::infinity();
  for (std::size_t it = 0;; ++it) {
    if (it == options.max_iterations) {
      result.stop = Lloyd_stop::iteration_cap;
      break;
    }
    if (!FeatureRecon::internal::report_progress(options.progress,
                                                 double(it) / double(options.max_iterations))) {
      result.stop = Lloyd_stop::interrupted;
      result.status = Status::interrupted;
      break;
    }
    auto step = engine.step(sites);
    Lloyd_iteration_statistics s;
    s.iteration = it + 1;
    s.energy = step.assignment.energy;
    s.max_move = step.max_move;
    s.mean_move = step.mean_move;
    s.relative_radius = engine.relative_radius_at(sites, packing);
    result.assignment = std::move(step.assignment.site);
    result.mass = std::move(step.assignment.mass);
    sites = std::move(step.sites);
    const bool keep_going = !options.on_iteration || [&] {
      std::vector<std::array<double, Traits::dimension>> positions(sites.size());
      for (std::size_t k = 0; k < sites.size(); ++k) positions[k] = sites[k].position;
      return options.on_iteration(s, positions);
    }();
    result.history.push_back(s);
    if (internal::iteration_stops(keep_going, s.max_move, options.move_tolerance, previous_energy,
                                  previous_energy - s.energy, options.energy_tolerance, result.stop))
      break;
    previous_energy = s.energy;
  }
  // No iteration (max_iterations 0, or stopped at once): the starting sites' sets.
  if (result.history.empty()) {
    Bilateral_assignment a = engine.assign(sites);
    result.assignment = std::move(a.site);
    result.mass = std::move(a.mass);
  }
  if (result.status != Status::interrupted)
    (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  result.items.reserve(sites.size());
  for (const auto& site : sites) result.items.push_back(engine.nearest_item_at(site.position));
  result.sites = std::move(sites);
  return result;
}

/// discrete_bilateral_lloyd() started at some items (indices into `items`, e.g. a sampler's output).
/// \param items the domain.
/// \param initial indices of the starting items: any range of integers (a braced list is a
///   std::vector<std::size_t>); checked as sites_at_items() checks them (throws naming the first bad one).
/// \param options as for discrete_bilateral_lloyd(). \param traits FeaturePointTraits.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>,
          class IndexRange = std::vector<std::size_t>,
          std::enable_if_t<internal::is_index_range<IndexRange>::value, int> = 0>
Discrete_lloyd_result<Traits> discrete_bilateral_lloyd(
    const ItemRange& items, const IndexRange& initial,
    const Discrete_lloyd_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  return discrete_bilateral_lloyd(
      items, internal::sites_at_items(items, initial, traits, "discrete_bilateral_lloyd"), options, traits);
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_DISCRETE_LLOYD_H
