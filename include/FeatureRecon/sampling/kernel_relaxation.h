// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_KERNEL_RELAXATION_H
#define FEATURERECON_SAMPLING_KERNEL_RELAXATION_H

/// \file
/// Kernel relaxation of a bilateral sampling (dissertation Sec. 2.1.2 and 2.2.2, "Kernel function"): the
/// global Gaussian energy over the bilateral distances of the sites,
///
///     E = (1/N) sum_i sum_{j != i} s_ij^k exp(-xi_ij^2 / (tau^2 s_ij^2)),
///     xi_ij^2 = |dp|^2 / sigma_p^2 + |deta|^2 / sigma_eta^2,
///
/// is lowered by gradient steps on the positions with its closed-form gradient
/// dE/dp_i = (2/N) sum_j s_ij^k exp(...) * (-2 (p_i - p_j) / (sigma_p^2 tau^2 s_ij^2)). Pairs farther apart
/// than `cutoff` kernel widths are ignored and the kernel is shifted to vanish there, so E is continuous. A
/// step is kept only when it lowers E with the features and scales held (then the next is longer), otherwise
/// it is halved and tried again. Features follow the positions: after each step every site takes the feature
/// of the item nearest to it. s_ij = min(s_i, s_j) is 1 for a constant density and adapts the kernel width to
/// a density (stippling); the factor s_ij^k (k the intrinsic dimension) balances the pressure between regions
/// of different scale, so the number of sites per area follows the density. In a box a site that crosses a
/// face is reflected back across it and mirrored ghost sites across the faces stand for the missing
/// neighbours outside, so the sites do not pile up on the boundary; on the torus of the box (periodic) a
/// site crossing a face comes back across the opposite one and sees the images of the others. Start from
/// dart throwing (sites_at_items() of bilateral_dart_throwing_count()), as the dissertation does: the
/// energy then falls quickly. When sites snap to items (point clouds on surfaces) each keeps a free position
/// within half an item spacing of its item, so small steps add up; the caller sees the items' positions.
/// Stages: kernel_energy() (energy and gradient) and kernel_relaxation() (the iterations).

#include <FeatureRecon/config.h>
#include <FeatureRecon/sampling/discrete_lloyd.h>
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
#include <stdexcept>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// Where the sites of kernel_relaxation() may go.
enum class Kernel_constraint {
  /// The bounding box of the items widened by half the item spacing of each axis (for a W x H image of
  /// pixels: [0, W] x [0, H]; items on a lattice of steps 1 x 2: the box of its cells): a site crossing a
  /// face is reflected back across it, and the sites see mirrored ghosts across its faces (with `periodic`
  /// the box is a torus instead: see there). For images and volumes.
  bounding_box,
  /// Every site moves to the item nearest to its new position (sites stay on the items: surfaces given by
  /// point clouds, subsets of the input).
  snap_to_item
};

/// Options of kernel_relaxation() and kernel_energy().
/// \tparam Dimension the items' dimension (2 or 3), the dimension of the positions on_iteration sees.
template <int Dimension>
struct Kernel_relaxation_options {
  double sigma_position = 1;  ///< spatial scale of xi; default 1
  /// feature scale; default infinity (Euclidean)
  double sigma_feature = std::numeric_limits<double>::infinity();
  /// tau, the kernel width in units of xi (the spatial width is tau sigma_position). Default 0:
  /// d_hex / (2 sigma_position) with d_hex = sqrt(2 A / (sqrt(3) N)), the spacing of N sites on a hexagonal
  /// lattice over the domain's area A (measured on 200 sites from dart throwing and from white noise, 100
  /// steps: rho 0.85 and 0.81 at d_hex / 2, 0.69 and 0.65 at d_hex, 0.79 and 0.73 at 0.3 d_hex).
  double kernel_width = 0;
  /// pairs farther apart than cutoff kernel widths are ignored (exp(-9) ~ 1e-4); default 3
  double cutoff = 3;
  /// Density rho of each item (>= 0, finite), aligned with the items. A site takes the scale
  /// s = (mean rho / rho_bar)^(1/k) of the item nearest to it, clamped to [1/8, 8] (k = 2 for images and
  /// surfaces, 3 for volumes), so sites crowd where rho is high (stippling: the darkness). rho_bar is rho
  /// averaged over about the kernel's footprint at that scale (blocks of cells of growing size around the
  /// item, widened while the block stays within the kernel width it gives): a thin dark line keeps its own
  /// density, a pattern finer than the kernel counts by its mean. Default empty: s = 1. A density 0 on every
  /// item has nothing to relax towards: kernel_relaxation() returns the sites as given with status
  /// degenerate_input (as lloyd_relaxation() and discrete_bilateral_lloyd() do); kernel_energy() takes s = 8
  /// everywhere, as where the density is low.
  std::vector<double> density;
  /// Where sites may go. Default: bounding_box for 2D items, snap_to_item for 3D items (surfaces).
  Kernel_constraint constraint =
      Dimension == 2 ? Kernel_constraint::bounding_box : Kernel_constraint::snap_to_item;
  /// The box (constraint bounding_box) is a torus, its periods the box's widths (a W x H image of pixels: W
  /// and H) or `period`: a site leaving across a face comes back across the opposite one, a site sees every
  /// image of the others (translated by whole periods, as far as the kernel reaches; never its own), the
  /// nearest item and the density average are taken across the faces too, and the relative radius measures
  /// torus distances. The sites then tile: a picture stippled on its torus can be repeated without seams.
  /// Copies of a site (equal positions once wrapped) move apart first. Items all at one position give a box
  /// of no width, which does not wrap (unless `period` is given). Refused with snap_to_item, and when the
  /// kernel's reach r (cutoff x spatial kernel width x the largest scale of any item) holds more than 4,096
  /// images of a site, prod_k (2 ceil(r / P_k) + 1). Default false.
  bool periodic = false;
  /// With `periodic`, the periods, one per axis, instead of the box's widths: for items that are no full
  /// lattice (the automatic widening is one spacing estimated for all axes), or a torus larger than the
  /// items' box. Each in [1e-150, 1e150] and at least the items' extent along its axis; the box is then that
  /// of these widths centred on the items' bounding box, and its measure the domain's unless domain_measure
  /// is given. Default empty: the box's widths. Given without `periodic`, refused.
  std::vector<double> period;
  std::size_t max_iterations = 100;  ///< iteration cap (accepted steps); default 100
  /// The first step length as a fraction of the distance to the neighbours (a single pair at distance d,
  /// close enough for the kernel to be ~1, moves apart by step * d); doubled or halved by the step control;
  /// default 0.25.
  double initial_step = 0.25;
  /// Stop when an accepted step lowers E by less than this fraction of E; default 1e-6.
  double energy_tolerance = 1e-6;
  /// stop when no site moved farther than this (units of the positions); default 0
  double move_tolerance = 0;
  /// Area (2D items, surfaces) or volume of the domain for the default kernel width and the relative radius;
  /// default 0: as discrete_bilateral_lloyd() estimates it.
  double domain_measure = 0;
  /// Called after each accepted step with its statistics and the sites' positions after the move; returning
  /// false stops there. Default: none.
  std::function<bool(Lloyd_iteration_statistics&, const std::vector<std::array<double, Dimension>>&)>
      on_iteration;
  Progress_callback progress;  ///< fraction of max_iterations done; returning false stops (sites so far kept)
};

/// The kernel energy of some sites and its gradient: kernel_energy().
/// \tparam Dimension the dimension of the positions.
template <int Dimension>
struct Kernel_energy {
  double energy = 0;                                    ///< E (including the ghost pairs in a box)
  std::vector<std::array<double, Dimension>> gradient;  ///< dE/dp_i per site, features and scales held fixed
  std::size_t pairs = 0;  ///< ordered pairs within the cut-off (ghosts included)
};

/// Result of kernel_relaxation().
template <class Traits>
struct Kernel_relaxation_result {
  std::vector<Bilateral_site<Traits>> sites;        ///< final sites, in input order (features follow)
  std::vector<Lloyd_iteration_statistics> history;  ///< one entry per accepted step, taken before it
  Lloyd_stop stop = Lloyd_stop::iteration_cap;      ///< why it stopped
  double kernel_width = 0;                          ///< tau used (units of xi)
  double step = 0;                                  ///< the step length the control ended with
  /// degenerate_input for no items, fewer than two sites, items without spatial extent or a density 0 on
  /// every item (nothing moves: the sites as given); interrupted when stopped.
  Status status = Status::success;
};

namespace internal {
/// \cond
template <class Traits>
class Kernel_engine : public Item_domain<Traits> {
 public:
  static constexpr int D = Traits::dimension;
  using Base = Item_domain<Traits>;
  using Point = std::array<double, D>;
  using Site = Bilateral_site<Traits>;
  using Base::S;

  template <class ItemRange>
  Kernel_engine(const ItemRange& items, const Kernel_relaxation_options<D>& o, const Traits& traits,
                std::size_t sites, const char* fn, const Progress_callback& progress = {})
      : Base(items, traits, o.domain_measure, fn, std::isfinite(o.sigma_feature)), options(o) {
    check_sigmas(o.sigma_position, o.sigma_feature, fn);  // the span: check_sites(), items and sites together
    if (!(o.kernel_width >= 0) || !std::isfinite(o.kernel_width))
      FeatureRecon::internal::throw_invalid_argument(fn, "kernel_width must be finite and >= 0, got ",
                                                     o.kernel_width);
    if (!(o.cutoff > 0) || !std::isfinite(o.cutoff))
      FeatureRecon::internal::throw_invalid_argument(fn, "cutoff must be finite and > 0, got ", o.cutoff);
    if (!(o.initial_step > 0) || !std::isfinite(o.initial_step))
      FeatureRecon::internal::throw_invalid_argument(fn, "initial_step must be finite and > 0, got ",
                                                     o.initial_step);
    if (!(o.energy_tolerance >= 0 && std::isfinite(o.energy_tolerance)) ||
        !(o.move_tolerance >= 0 && std::isfinite(o.move_tolerance)))
      FeatureRecon::internal::throw_invalid_argument(
          fn, "energy_tolerance and move_tolerance must be finite and >= 0, got ", o.energy_tolerance,
          " and ", o.move_tolerance);
    if (!o.density.empty() && o.density.size() != S.size())
      FeatureRecon::internal::throw_invalid_argument(fn, "density has ", o.density.size(), " values for ",
                                                     S.size(), " items");
    double total = 0;
    for (std::size_t i = 0; i < o.density.size(); ++i) {
      if (!(o.density[i] >= 0 && std::isfinite(o.density[i])))
        FeatureRecon::internal::throw_invalid_argument(fn, "density[", i, "] must be finite and >= 0, got ",
                                                       o.density[i]);
      total += o.density[i];
    }
    zero_density = !o.density.empty() && !(total > 0);
    mean_density = o.density.empty() ? 1.0 : total / double(o.density.size());
    if (o.periodic && o.constraint != Kernel_constraint::bounding_box)
      FeatureRecon::internal::throw_invalid_argument(
          fn, "periodic needs constraint bounding_box (the torus is the box); snap_to_item has no torus");
    this->intrinsic = (D == 3 && o.constraint == Kernel_constraint::bounding_box) ? 3 : 2;
    this->take_period(o.period, o.periodic, o.sigma_position, fn);
    if (S.size() == 0) return;
    // The box: the items' bounding box widened by half the item spacing of each axis, or the period's.
    box_lo = this->lo;
    box_hi = this->hi;
    if (D == 3 && o.constraint == Kernel_constraint::snap_to_item) {
      double area = o.domain_measure;
      if (area == 0 && S.size() > 1) {
        if constexpr (D == 3) {
          const std::vector<std::array<double, 3>> places = distinct_positions(S.positions);
          area = estimate_surface_area(places, Knn_3(places));
        }
      }
      spacing = std::sqrt(area / double(S.size()));
      packing = sites == 0 ? 0.0 : std::sqrt(2 * area / (std::sqrt(3.0) * double(sites)));
      for (int k = 0; k < D; ++k) {
        box_lo[k] -= spacing / 2;
        box_hi[k] += spacing / 2;
      }
    } else {
      spacing = this->grid_spacing();
      packing = this->packing_distance(sites);
      this->relaxation_box(box_lo, box_hi);
    }
    tau = o.kernel_width > 0 ? o.kernel_width : packing / (2 * o.sigma_position);
    if (!(tau > 0)) tau = std::max(spacing, 1e-300) / o.sigma_position;
    if (o.periodic) this->set_torus(box_lo, box_hi);
    if (zero_density)
      local_density.assign(S.size(), 0.0);  // every scale 8 (scale_of()); nothing to average
    else if (!o.density.empty())
      smoothed = smooth_density(progress);
    if (o.periodic && smoothed) {
      // Every image within the kernel's reach is a ghost: at most prod_k (2 ceil(reach / P_k) + 1) per site,
      // the reach at the largest scale of any item.
      double largest = o.density.empty() ? 1.0 : 0.0;
      for (std::size_t i = 0; i < local_density.size(); ++i) largest = std::max(largest, scale_at(i));
      const double reach = o.cutoff * tau * o.sigma_position * largest;
      double images = 1, shortest = std::numeric_limits<double>::infinity();
      for (int k = 0; k < D; ++k)
        if (this->torus.period[k] > 0) {
          images *= 2 * std::ceil(reach / this->torus.period[k]) + 1;
          shortest = std::min(shortest, this->torus.period[k]);
        }
      if (!(images <= double(max_images)))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "periodic: the kernel reaches ", reach,
            " (cutoff x kernel width x sigma_position x the largest scale; the shortest period is ", shortest,
            "): up to ", images, " images of a site, more than ", max_images,
            "; lower kernel_width or cutoff, or use more sites");
    }
  }
  static constexpr std::size_t max_images = 4096;

  // The scale of a site at item `near`, from the density around that item (smooth_density()).
  double scale_at(std::uint32_t near) const {
    if (options.density.empty()) return 1.0;
    return scale_of(local_density[near]);
  }
  double scale_of(double rho) const {
    if (!(rho > 0)) return 8.0;
    const double x = mean_density / rho;  // sqrt and cbrt: exact or nearly, and far cheaper than pow
    return std::min(8.0, std::max(0.125, intrinsic == 2 ? std::sqrt(x) : std::cbrt(x)));
  }

  // local_density[i]: the density averaged over the kernel's core at item i, at the scale that density gives.
  // Level 0 is the item alone; level l >= 1 the 3^D block of cells of side c_l = 2^(l-1) x the item spacing
  // (anchored at the box corner) around the item's cell. An item takes level l while the block fits in one
  // kernel width, 3 c_l <= w0 s(level l's mean) (w0 the spatial kernel width at scale 1); the first failure
  // ends the climb. A thin dark line keeps the density of its own pixels (its small kernel sees only them); a
  // pattern finer than the kernel counts by its mean: on a picture whose columns alternate black and white
  // the density of the one pixel under a site switched the scale between 0.7 and 8 from one pixel to the next
  // (now 0.87 and 1.22), the energy jumped from 0.23 to 150 in a step and 24 of 40 sites were pushed into the
  // corners. Deterministic (cells sorted by their integer coordinates, sums in index order).
  // Returns false when `progress` (asked with 0 at every level and every 65,536 items) says stop. Dense
  // arrays of cells where they hold at most about 4 per item (images, volumes: 2048 x 2048 pixels in 0.3 s a
  // level), else cells sorted by their coordinates. An extent above 2^40 cells of a level skips that level.
  bool smooth_density(const Progress_callback& progress) {
    const std::size_t m = S.size();
    local_density.assign(options.density.begin(), options.density.end());
    const double w0 = tau * options.sigma_position;
    if (!(spacing > 0) || !(w0 > 0) || !std::isfinite(w0)) return true;
    double extent = 0;
    for (int k = 0; k < D; ++k) extent = std::max(extent, box_hi[k] - box_lo[k]);
    using Key = std::array<std::int64_t, D>;
    std::vector<char> climbing(m, 1);
    std::vector<Key> key(m), cell;
    std::vector<std::uint32_t> order;
    std::vector<double> sum;
    std::vector<std::size_t> count;
    std::size_t blocks = 1;
    for (int k = 0; k < D; ++k) blocks *= 3;
    auto asked = [&](std::size_t i) {
      return i % 65536 != 0 || FeatureRecon::internal::report_progress(progress, 0.0);
    };
    // Cells wider than the extent or than any kernel (8 w0) add nothing; coordinates stay below 2^41.
    for (double side = spacing; 3 * side <= 8 * w0 && side <= 2 * extent; side *= 2) {
      if (!(extent / side < 0x1p40)) continue;
      if (!FeatureRecon::internal::report_progress(progress, 0.0)) return false;
      Key dims{};
      double cells = 1;
      for (int k = 0; k < D; ++k) {
        // On the torus the last cell (maybe partial) borders the first: no empty cell past the box, also
        // where the period is a whole number of cells but for rounding (12 items 0.1
        // apart: 1.2000000000000002 / 0.1 = 12.000000000000002 cells).
        if (options.periodic) {
          const double across = this->torus.period[k] / side, whole = std::round(across);
          dims[k] = std::max<std::int64_t>(
              1, static_cast<std::int64_t>(std::abs(across - whole) <= 1e-9 * whole ? whole
                                                                                    : std::ceil(across)));
        } else {
          dims[k] = static_cast<std::int64_t>(std::floor((box_hi[k] - box_lo[k]) / side)) + 1;
        }
        cells *= double(dims[k]);
      }
      for (std::size_t i = 0; i < m; ++i)
        for (int k = 0; k < D; ++k)
          key[i][k] = std::min(dims[k] - 1, static_cast<std::int64_t>(std::max(
                                                0.0, std::floor((S.positions[i][k] - box_lo[k]) / side))));
      const bool dense = cells <= 4.0 * double(m) + 64;
      // Sums over a cell's items in index order (both paths).
      auto index_of = [&dims](const Key& q) {
        std::size_t at = 0;
        for (int k = D; k-- > 0;) at = at * std::size_t(dims[k]) + std::size_t(q[k]);
        return at;
      };
      if (dense) {
        sum.assign(std::size_t(cells), 0.0);
        count.assign(std::size_t(cells), 0);
        for (std::size_t i = 0; i < m; ++i) {
          sum[index_of(key[i])] += options.density[i];
          ++count[index_of(key[i])];
        }
      } else {
        order.resize(m);
        for (std::size_t i = 0; i < m; ++i) order[i] = static_cast<std::uint32_t>(i);
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
          return key[a] < key[b] || (key[a] == key[b] && a < b);
        });
        cell.clear();
        sum.clear();
        count.clear();
        for (const std::uint32_t i : order) {
          if (cell.empty() || cell.back() != key[i]) {
            cell.push_back(key[i]);
            sum.push_back(0);
            count.push_back(0);
          }
          sum.back() += options.density[i];
          ++count.back();
        }
      }
      bool any = false;
      for (std::size_t i = 0; i < m; ++i) {
        if (!asked(i)) return false;
        if (!climbing[i]) continue;
        double total = 0;
        std::size_t n = 0;
        for (std::size_t b = 0; b < blocks; ++b) {
          Key q = key[i];
          std::size_t code = b;
          bool inside = true;
          for (int k = 0; k < D; ++k, code /= 3) {
            const std::int64_t step = std::int64_t(code % 3) - 1;
            if (options.periodic) {  // across the faces; a row of 1 or 2 cells is counted once
              if ((dims[k] == 1 && step != 0) || (dims[k] == 2 && step == 1)) inside = false;
              q[k] = (q[k] + step + dims[k]) % dims[k];
            } else {
              q[k] += step;
              inside = inside && q[k] >= 0 && q[k] < dims[k];
            }
          }
          if (!inside) continue;
          if (dense) {
            total += sum[index_of(q)];
            n += count[index_of(q)];
          } else {
            const auto at = std::lower_bound(cell.begin(), cell.end(), q);
            if (at == cell.end() || *at != q) continue;
            total += sum[std::size_t(at - cell.begin())];
            n += count[std::size_t(at - cell.begin())];
          }
        }
        const double rho = total / double(n);  // n >= 1: the item's own cell
        if (3 * side <= w0 * scale_of(rho)) {
          local_density[i] = rho;
          any = true;
        } else {
          climbing[i] = 0;
        }
      }
      if (!any) break;
    }
    return true;
  }

  // A position brought into the box: back across the opposite face on the torus, reflected back across the
  // faces it crossed (the ghosts' mirror) as often as it takes in the box; unchanged when snapping.
  void place(Point& p) const {
    if (options.periodic) {
      this->torus.wrap(p);
      return;
    }
    if (options.constraint == Kernel_constraint::snap_to_item) return;
    for (int k = 0; k < D; ++k) {
      const double width = box_hi[k] - box_lo[k];
      if (p[k] >= box_lo[k] && p[k] <= box_hi[k]) continue;
      if (!(width > 0)) {
        p[k] = box_lo[k];
        continue;
      }
      double t = std::fmod(p[k] - box_lo[k], 2 * width);  // exact
      if (t < 0) t += 2 * width;
      if (t > width) t = 2 * width - t;
      p[k] = std::min(box_hi[k], std::max(box_lo[k], box_lo[k] + t));
    }
  }

  // Features and scales of sites at these positions (the constraint applied first).
  // The constraint and the features: reflects into the box, or (snapping) keeps each site within half an item
  // spacing of its item, the item nearest to it unless a lower-index site took that one (then the nearest
  // free item; with more sites than items the extra ones share). Features and scales are those of the items.
  // With snapping `item` receives each site's item (the position reported to the caller).
  void settle(std::vector<Site>& sites, std::vector<double>& scales, std::vector<std::uint32_t>& item) const {
    scales.resize(sites.size());
    item.resize(sites.size());
    const bool snap = options.constraint == Kernel_constraint::snap_to_item;
    std::vector<char> taken(snap ? S.size() : 0, 0);
    std::size_t free_items = S.size();
    for (std::size_t i = 0; i < sites.size(); ++i) {
      auto& p = sites[i].position;
      place(p);
      std::uint32_t near = this->nearest_item_at(p);
      if (near >=
          S.size())  // a non-finite position: never after the checks above, but never read past the end
        throw std::runtime_error("kernel_relaxation: a site has no nearest item (non-finite position)");
      if (snap) {
        if (taken[near] && free_items > 0) {
          double best;
          near = this->item_grid.nearest(
              p, 1.0,
              [&](std::uint32_t j) {
                return taken[j] ? std::numeric_limits<double>::max()
                                : std::sqrt(Base::squared(p, S.positions[j]));
              },
              best);
        }
        if (!taken[near]) --free_items;
        taken[near] = 1;
        const double d = std::sqrt(Base::squared(p, S.positions[near])), limit = spacing / 2;
        const double t = d > limit ? limit / d : 1.0;
        for (int k = 0; k < D; ++k) p[k] = S.positions[near][k] + t * (p[k] - S.positions[near][k]);
      }
      item[i] = near;
      sites[i].feature = S.features[near];
      scales[i] = scale_at(near);
    }
  }

  // E and (optionally) its gradient, features and scales fixed.
  Kernel_energy<D> energy(const std::vector<Site>& sites, const std::vector<double>& scales,
                          bool gradient) const {
    Kernel_energy<D> out;
    const std::size_t n = sites.size();
    if (gradient) out.gradient.assign(n, Point{});
    if (n == 0) return out;
    const double w0 = tau * options.sigma_position;  // spatial width at scale 1
    double s_max = 0;
    for (const double s : scales) s_max = std::max(s_max, s);
    // Real sites, then ghosts: mirror images across the box faces of the sites near them, or on the torus the
    // sites (wrapped) and their images across the faces within the kernel's reach.
    std::vector<Point> q;
    std::vector<std::uint32_t> source;
    q.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      q.push_back(sites[i].position);
      if (options.periodic) this->torus.wrap(q.back());
      source.push_back(static_cast<std::uint32_t>(i));
    }
    if (options.periodic) {
      this->torus.add_images(q, source, n, [&](std::size_t j) { return options.cutoff * w0 * scales[j]; });
    } else if (options.constraint == Kernel_constraint::bounding_box) {
      for (std::size_t j = 0; j < n; ++j) {
        const double reach = options.cutoff * w0 * scales[j];
        for (int k = 0; k < D; ++k)
          for (const double face : {box_lo[k], box_hi[k]}) {
            const double x = sites[j].position[k];
            if (std::abs(x - face) < reach) {
              Point g = sites[j].position;
              g[k] = 2 * face - x;
              q.push_back(g);
              source.push_back(static_cast<std::uint32_t>(j));
            }
          }
      }
    }
    Point flo = q[0], fhi = q[0];
    for (const auto& p : q)
      for (int k = 0; k < D; ++k) {
        flo[k] = std::min(flo[k], p[k]);
        fhi[k] = std::max(fhi[k], p[k]);
      }
    double volume = 1;
    for (int k = 0; k < D; ++k) volume *= std::max(fhi[k] - flo[k], options.cutoff * w0);
    // Cells about the cutoff radius wide, but never more than about 4 per point: a tiny kernel width or one
    // far site asked for volume / (cutoff w)^D cells (a 64 x 64 image at width 1e-4: std::bad_alloc).
    const double cells = std::min(volume / std::pow(options.cutoff * w0, D), 4.0 * double(q.size()) + 16);
    Ring_grid<D> grid(flo, fhi, std::max(1.0, cells));
    grid.assign(q);
    const double inv_sp2 = 1.0 / (options.sigma_position * options.sigma_position);
    const bool features = !std::isinf(options.sigma_feature);
    const double inv_sf2 = features ? 1.0 / (options.sigma_feature * options.sigma_feature) : 0.0;
    const double inv_tau2 = 1.0 / (tau * tau);
    const double cutoff2 = options.cutoff * options.cutoff;
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Point& p = q[i];
      const double radius = options.cutoff * w0 * scales[i];
      Point g{};
      double row = 0;
      grid.for_each_within(p, radius, [&](std::uint32_t t) {
        if (t == i) return;
        const std::uint32_t j = source[t];
        if (options.periodic && j == i) return;  // a site's own images are not other sites
        const double s = std::min(scales[i], scales[j]);
        double d2 = 0;
        for (int k = 0; k < D; ++k) d2 += (p[k] - q[t][k]) * (p[k] - q[t][k]);
        const double w = options.cutoff * w0 * s;
        if (d2 > w * w) return;
        const double f2 = features
                              ? checked_feature_distance(
                                    CGAL::to_double(S.feature_distance(sites[i].feature, sites[j].feature)),
                                    S.fn, "site", i, "site", j) *
                                    inv_sf2
                              : 0.0;
        const double a = inv_tau2 / (s * s);
        const double weight = std::pow(s, intrinsic);
        // The kernel minus its value at the cut-off distance (same features), so E is continuous.
        const double e = weight * std::exp(-(d2 * inv_sp2 + f2) * a);
        row += e - weight * std::exp(-(cutoff2 + f2 * a));
        ++out.pairs;
        if (gradient) {
          const double c = -2 * e * inv_sp2 * inv_tau2 / (s * s);
          for (int k = 0; k < D; ++k) g[k] += c * (p[k] - q[t][k]);
        }
      });
      total += row;
      if (gradient)
        for (int k = 0; k < D; ++k) out.gradient[i][k] = 2 * g[k] / double(n);
    }
    out.energy = total / double(n);
    return out;
  }

  const Kernel_relaxation_options<D>& options;
  double mean_density = 1;
  bool zero_density = false;  // a density 0 on every item (kernel_relaxation(): degenerate_input)
  using Base::intrinsic;
  Point box_lo{}, box_hi{};
  double spacing = 0;  // of the items
  double packing = 0;
  double tau = 1;
  std::vector<double> local_density;  // smooth_density()
  bool smoothed = true;               // false: the progress callback stopped smooth_density()
};
/// \endcond
}  // namespace internal

/// Stage 1: the kernel energy E of some sites and its gradient with respect to the positions (features and
/// scales held at their values: they are piecewise constant in the positions). The sites are used as given
/// (not moved into the box, features not refreshed; on the torus a site counts where it wraps to).
/// \param items the domain (for the kernel width, the box and the density).
/// \param sites the sites (finite, checked).
/// \param options metric, kernel width, cut-off, density, constraint. \param traits FeaturePointTraits.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Kernel_energy<Traits::dimension> kernel_energy(
    const ItemRange& items, const std::vector<Bilateral_site<Traits>>& sites,
    const Kernel_relaxation_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  const internal::Kernel_engine<Traits> engine(items, options, traits, sites.size(), "kernel_energy");
  engine.check_sites(sites, "kernel_energy", options.sigma_position);
  std::vector<double> scales(sites.size(), 1.0);
  if (engine.items() > 0)
    for (std::size_t i = 0; i < sites.size(); ++i)
      scales[i] = engine.scale_at(engine.nearest_item_at(sites[i].position));
  return engine.energy(sites, scales, true);
}

/// Kernel relaxation (dissertation Sec. 2.2.2): gradient steps on the kernel energy with step control,
/// features following the positions, until a stopping rule holds (iteration cap, relative energy decrease,
/// largest move, no descent, the on_iteration callback). Each site moves by -step (w_i^2 N / 4) dE/dp_i (w_i
/// its spatial kernel width), at most w_i per step, a descent direction that moves an isolated close pair
/// apart by about step times its distance; copies of a site (equal positions) first move apart by a hundredth
/// of the kernel width;
/// a step that does not lower E is halved (up to 30 times, then the run stops with no_descent),
/// an accepted one makes the next 1.25 times longer. Deterministic: no randomness beyond the starting sites.
/// \param items the domain: a range of items read through the traits (positions finite, checked).
/// \param sites the starting sites, e.g. sites_at_items() of a dart-throwing result (finite, checked).
/// \param options metric, kernel, density, constraint, step control, stopping rules (checked; throws naming
///   the field).
/// \param traits a model of FeaturePointTraits.
/// \return the sites and the history. No items, fewer than two sites, or items without spatial extent (all at
///   one position): degenerate_input, sites unchanged.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>>
Kernel_relaxation_result<Traits> kernel_relaxation(
    const ItemRange& items, std::vector<Bilateral_site<Traits>> sites,
    const Kernel_relaxation_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  constexpr int D = Traits::dimension;
  const char* fn = "kernel_relaxation";
  const internal::Kernel_engine<Traits> engine(items, options, traits, sites.size(), fn, options.progress);
  // The features are taken from the items (settle()), never read.
  engine.check_sites(sites, fn, options.sigma_position, false);
  Kernel_relaxation_result<Traits> result;
  result.kernel_width = engine.tau;
  result.step = options.initial_step;
  const double w0 = engine.tau * options.sigma_position;
  // Items without spatial extent (all at one place, or so close that the kernel's 1 / width^2 overflows): no
  // scale to relax on.
  const bool no_extent = !(engine.spacing > 0) || !std::isfinite(1.0 / (engine.tau * engine.tau)) ||
                         !std::isfinite(1.0 / (w0 * w0));
  if (engine.items() == 0 || sites.size() < 2 || no_extent || engine.zero_density) {
    result.sites = std::move(sites);
    result.status = Status::degenerate_input;
    return result;
  }
  if (!engine.smoothed) {  // stopped while the density was averaged: the sites as given
    result.sites = std::move(sites);
    result.stop = Lloyd_stop::interrupted;
    result.status = Status::interrupted;
    return result;
  }
  // Coincident sites have no gradient between them: every copy after the first (in index order) moves by
  // w0 / 100 along a direction fixed by its index (golden-angle spiral), then the energy separates them.
  // Copies are told in the box (sites a whole period apart on the torus, or mirror images of each other
  // across a face, coincide there).
  for (auto& site : sites) engine.place(site.position);
  internal::separate_copies<D>(
      sites.size(), w0 / 100, [&sites](std::size_t i) -> auto& { return sites[i].position; });
  std::vector<double> scales;
  std::vector<std::uint32_t> item;
  engine.settle(sites, scales, item);
  auto current = engine.energy(sites, scales, true);
  double step = options.initial_step;
  std::vector<Bilateral_site<Traits>> trial;
  std::vector<double> trial_scales;
  std::vector<std::uint32_t> trial_item;
  std::vector<double> step_length;  // of each site in the trial step
  std::vector<Bilateral_site<Traits>> frozen;
  // Whether features or scales can change with the positions (else one energy pass per step).
  const bool refresh = !std::isinf(options.sigma_feature) || !options.density.empty();
  const bool snap = options.constraint == Kernel_constraint::snap_to_item;
  // The sites as the caller sees them: snapped to their items.
  auto reported = [&](const std::vector<Bilateral_site<Traits>>& free, const std::vector<std::uint32_t>& at) {
    std::vector<Bilateral_site<Traits>> out = free;
    if (snap)
      for (std::size_t i = 0; i < out.size(); ++i) out[i].position = engine.S.positions[at[i]];
    return out;
  };
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
    bool accepted = false;
    Kernel_energy<D> next;
    double max_move = 0, total_move = 0, decrease = 0;
    for (int attempt = 0; attempt < 30 && !accepted; ++attempt) {
      trial = sites;
      step_length.assign(sites.size(), 0.0);
      for (std::size_t i = 0; i < sites.size(); ++i) {
        const double w = w0 * scales[i];
        const double f = step * w * w * double(sites.size()) / 4;
        double len = 0;
        std::array<double, D> d;
        for (int k = 0; k < D; ++k) {
          d[k] = -f * current.gradient[i][k];
          len += d[k] * d[k];
        }
        len = std::sqrt(len);
        const double cap = w;  // never more than a kernel width per step
        const double shrink = len > cap ? cap / len : 1.0;
        for (int k = 0; k < D; ++k) trial[i].position[k] += shrink * d[k];
        step_length[i] = shrink * len;
      }
      engine.settle(trial, trial_scales, trial_item);
      // The step must lower E with the features and scales it started from (E jumps where a site's nearest
      // item changes); they are refreshed after it.
      frozen = trial;
      for (std::size_t i = 0; i < sites.size(); ++i) frozen[i].feature = sites[i].feature;
      auto probe = engine.energy(frozen, scales, !refresh);
      if (probe.energy < current.energy) {
        accepted = true;
        decrease = current.energy - probe.energy;
        next = refresh ? engine.energy(trial, trial_scales, true) : std::move(probe);
      } else {
        step /= 2;
      }
    }
    if (!accepted) {
      result.stop = Lloyd_stop::no_descent;
      break;
    }
    for (std::size_t i = 0; i < sites.size(); ++i) {
      // On the torus a site moves by its step (its position may come back across a face).
      const double m =
          options.periodic
              ? step_length[i]
              : std::sqrt(internal::Item_domain<Traits>::squared(trial[i].position, sites[i].position));
      max_move = std::max(max_move, m);
      total_move += m;
    }
    Lloyd_iteration_statistics s;
    s.iteration = it + 1;
    s.energy = current.energy;
    s.max_move = max_move;
    s.mean_move = total_move / double(sites.size());
    s.relative_radius = engine.relative_radius_at(snap ? reported(sites, item) : sites, engine.packing);
    const double previous = current.energy;  // the step lowered it by `decrease`
    sites.swap(trial);
    scales.swap(trial_scales);
    item.swap(trial_item);
    current = std::move(next);
    step = std::min(step * 1.25, 4.0);
    const bool keep_going = !options.on_iteration || [&] {
      std::vector<std::array<double, D>> positions(sites.size());
      for (std::size_t k = 0; k < sites.size(); ++k)
        positions[k] = snap ? engine.S.positions[item[k]] : sites[k].position;
      return options.on_iteration(s, positions);
    }();
    result.history.push_back(s);
    if (internal::iteration_stops(keep_going, s.max_move, options.move_tolerance, previous, decrease,
                                  options.energy_tolerance, result.stop))
      break;
  }
  if (result.status != Status::interrupted)
    (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  result.sites = reported(sites, item);
  result.step = step;
  return result;
}

/// kernel_relaxation() started at some items (indices into `items`, e.g. bilateral_dart_throwing_count()'s
/// output).
/// \param items the domain.
/// \param initial indices of the starting items: any range of integers (a braced list is a
///   std::vector<std::size_t>); checked as sites_at_items() checks them (throws naming the first bad one).
/// \param options as for kernel_relaxation(). \param traits FeaturePointTraits.
template <class ItemRange, class Traits = Default_traits_t<ItemRange>,
          class IndexRange = std::vector<std::size_t>,
          std::enable_if_t<internal::is_index_range<IndexRange>::value, int> = 0>
Kernel_relaxation_result<Traits> kernel_relaxation(
    const ItemRange& items, const IndexRange& initial,
    const Kernel_relaxation_options<Traits::dimension>& options = {}, const Traits& traits = Traits()) {
  return kernel_relaxation(items, internal::sites_at_items(items, initial, traits, "kernel_relaxation"),
                           options, traits);
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_KERNEL_RELAXATION_H
