// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_LLOYD_RELAXATION_H
#define FEATURERECON_SAMPLING_LLOYD_RELAXATION_H

/// \file
/// Lloyd relaxation towards a centroidal Voronoi tessellation (dissertation Sec. 2.1.2) of a box with a pixel
/// density: Voronoi cells from CGAL's Delaunay_triangulation_2 (exact predicates), clipped to the box, with
/// the density integrated exactly over the part of every pixel each cell covers. A constant density gives
/// plain Lloyd relaxation; the darkness of an image gives adaptive (weighted) Lloyd stippling (Secord 2002).
/// Stages: clipped_voronoi_cells() (the cells), Pixel_density::integrate() (their moments), lloyd_step()
/// (one iteration), lloyd_relaxation() (iterations with stopping rules and per-iteration statistics).

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/config.h>
#include <FeatureRecon/internal/parallel.h>
#include <FeatureRecon/point_traits.h>
#include <FeatureRecon/sampling/internal/box.h>
#include <FeatureRecon/sampling/internal/sample_set.h>
#include <FeatureRecon/sampling/pixel_density.h>
#include <FeatureRecon/sampling/sampling_options.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// A convex polygon, counter-clockwise (CGAL's orientation), vertices not repeated.
using Polygon_2d = std::vector<std::array<double, 2>>;

/// Options of lloyd_relaxation().
struct Lloyd_options {
  std::size_t max_iterations = 100;  ///< iteration cap; default 100
  /// Stop when (E_prev - E) / E_prev < energy_tolerance after an iteration; default 0 (never).
  double energy_tolerance = 0;
  /// Stop when no site moved farther than this (pixels); default 0 (never).
  double move_tolerance = 0;
  /// Called after each iteration with its statistics and the sites after the move (it may fill in the
  /// oscillation, which lloyd_relaxation() stores in the history); returning false stops there. Lloyd drifts
  /// towards a lattice, so blue-noise users stop early on rho or the oscillation. Default: none.
  std::function<bool(Lloyd_iteration_statistics&, const std::vector<std::array<double, 2>>&)> on_iteration;
  Progress_callback progress;  ///< fraction of max_iterations done; returning false stops (sites so far kept)
  /// Threads integrating the cells (the results do not depend on it); default 0: the hardware's concurrency
  /// for an image, one thread for a constant density (its closed-form integrals cost less than the threads).
  unsigned threads = 0;
  /// The density's box is a torus: cells are those of the sites and their images shifted by the box's sides
  /// (periodic_voronoi_cells()), the density is integrated over the parts of a cell in each shifted copy of
  /// the box, sites move to the centroids taken modulo the box, and moves and distances are those of the
  /// torus. A constant density gives the periodic centroidal Voronoi tessellations of the point-set analysis
  /// literature (blue-noise tiles); an image density a tileable stippling. Default false.
  bool periodic = false;
};

/// Result of lloyd_step().
struct Lloyd_step_result {
  /// per site: the centroid of its cell (the site itself when the cell has no mass)
  std::vector<std::array<double, 2>> centroids;
  std::vector<double> mass;  ///< per site: the density integral over its cell
  double energy = 0;         ///< CVT energy of the sites given to the step
  /// shortest distance between two sites at distinct positions (infinity for fewer than two)
  double minimum_distance = 0;
  std::size_t duplicates = 0;  ///< sites at the position of a lower-indexed site (their cells are empty)
};

/// Result of lloyd_relaxation().
struct Lloyd_result {
  std::vector<std::array<double, 2>> sites;  ///< final positions, in input order
  std::vector<double> mass;                  ///< density mass of each site's cell at the last iteration
  std::vector<Lloyd_iteration_statistics> history;  ///< one entry per iteration done
  Lloyd_stop stop = Lloyd_stop::iteration_cap;      ///< why it stopped
  /// degenerate_input for no sites, an empty box or a density that is zero everywhere (nothing moves);
  /// interrupted when the progress callback stopped it.
  Status status = Status::success;
};

namespace internal {
/// \cond
// A total order of a triangulation's vertices that does not depend on memory: their info (an index), then
// (for vertices that share one, the far corners of Voronoi_builder) their coordinates. Every rounded quantity
// is computed in an order fixed by it, because the faces' layout is not fixed: CGAL's vertex moves order
// faces by handle.
template <class Vertex_handle>
bool rank_less(Vertex_handle a, Vertex_handle b) {
  if (a->info() != b->info()) return a->info() < b->info();
  return a->point() < b->point();
}

// The incident face of v from which its Voronoi cell is walked: the one whose counter-clockwise-next edge
// around v goes to the lowest-ranked neighbour.
template <class Dt>
typename Dt::Face_circulator first_face(const Dt& dt, typename Dt::Vertex_handle v) {
  auto f = dt.incident_faces(v), end = f, best = f;
  typename Dt::Vertex_handle lowest = f->vertex(Dt::cw(f->index(v)));
  while (++f != end) {
    const typename Dt::Vertex_handle w = f->vertex(Dt::cw(f->index(v)));
    if (rank_less(w, lowest)) {
      lowest = w;
      best = f;
    }
  }
  return best;
}

// The circumcentre of a finite face, from its vertices in rank order (the rounding does not depend on how
// the face stores them).
template <class Dt>
std::array<double, 2> ranked_circumcenter(typename Dt::Face_handle f) {
  typename Dt::Vertex_handle a = f->vertex(0), b = f->vertex(1), c = f->vertex(2);
  if (rank_less(b, a)) std::swap(a, b);
  if (rank_less(c, b)) std::swap(b, c);
  if (rank_less(b, a)) std::swap(a, b);
  const auto q = CGAL::circumcenter(a->point(), b->point(), c->point());
  return {q.x(), q.y()};
}

// Buffers of move_by_flips(), kept between calls (allocating them anew costs page faults on every step).
template <class Dt>
struct Flip_workspace {
  std::vector<typename Dt::Point> old;
  std::vector<std::uint32_t> held;
  std::vector<char> is_held;
  std::vector<std::pair<typename Dt::Face_handle, int>> stack;
};

// Moves every vertex v of dt whose info is below `slots` to target(v->info()) (the others stay) and makes the
// triangulation Delaunay again. Vertices of triangles that would lose their counter-clockwise orientation
// (exact predicate) keep their old position for the flips and are moved afterwards one by one, in increasing
// info order, with CGAL's move_if_no_collision; handle(i) is the vertex of info i. Lawson flips (exact,
// perturbed in-circle test, as CGAL's insertion) restore the Delaunay property: the Delaunay triangulation
// with CGAL's symbolic perturbation is unique, so the order of the flips does not change the result. False
// (the triangulation is then unusable; the caller rebuilds it) when more than max_held vertices would be held
// or a move collides with another vertex.
template <class Dt, class Target, class Handle>
bool move_by_flips(Dt& dt, std::size_t slots, const Target& target, const Handle& handle,
                   std::size_t max_held, Flip_workspace<Dt>& work) {
  auto& old = work.old;
  old.resize(slots);
  // In the vertices' memory order (spatially sorted at the build), not the info order: far fewer cache
  // misses.
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const std::size_t i = v->info();
    if (i >= slots) continue;
    old[i] = v->point();
    v->set_point(target(i));
  }
  const auto orientation = dt.geom_traits().orientation_2_object();
  auto& held = work.held;
  auto& is_held = work.is_held;
  held.clear();
  is_held.assign(slots, 0);
  for (bool inverted = true; inverted;) {
    inverted = false;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      if (orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) == CGAL::POSITIVE)
        continue;
      inverted = true;
      for (int k = 0; k < 3; ++k) {
        const std::size_t i = f->vertex(k)->info();
        if (i >= slots || is_held[i]) continue;
        is_held[i] = 1;
        held.push_back(static_cast<std::uint32_t>(i));
        f->vertex(k)->set_point(old[i]);
      }
    }
    if (held.size() > max_held) return false;
  }
  // Lawson flips until every edge is locally Delaunay: one pass over the faces in container order, then
  // only the edges around the flipped ones (a stack), so no second full pass checks what did not change.
  auto& stack = work.stack;
  stack.clear();
  auto check = [&](typename Dt::Face_handle f, int i) {
    const auto g = f->neighbor(i);
    if (dt.is_infinite(f) || dt.is_infinite(g) ||
        dt.side_of_oriented_circle(g, f->vertex(i)->point(), true) != CGAL::ON_POSITIVE_SIDE)
      return;
    dt.flip(f, i);
    // The flipped edge now joins f's vertex i with the opposite vertex of g; its four outer edges may have
    // stopped being locally Delaunay.
    for (const typename Dt::Face_handle h : {f, g})
      for (int k = 0; k < 3; ++k) stack.emplace_back(h, k);
  };
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i) {
      // Each edge once, chosen by the infos of its ends (never by address).
      if (f->vertex(Dt::ccw(i))->info() < f->vertex(Dt::cw(i))->info()) check(f, i);
      while (!stack.empty()) {
        const auto [h, k] = stack.back();
        stack.pop_back();
        check(h, k);
      }
    }
  std::sort(held.begin(), held.end());  // a fixed order: the result does not depend on the face order
  for (const std::uint32_t i : held)
    if (dt.move_if_no_collision(handle(i), target(i)) != handle(i)) return false;
  return true;
}

struct Voronoi_builder {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
  struct Face_data {
    std::array<double, 2> circumcenter;  // the Voronoi vertex
    std::array<std::uint32_t, 3> site;   // vertex(k)->info(), cached so walks need not load the vertices
    bool inside;                         // it lies in the box
  };
  using Fb = CGAL::Triangulation_face_base_with_info_2<Face_data, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  static constexpr std::uint32_t dummy = std::numeric_limits<std::uint32_t>::max();

  Dt dt;
  std::vector<std::uint32_t> owner;  // per site: the lowest index at the same position (itself if unique)
  std::size_t duplicates = 0;
  std::size_t sites = 0;
  std::array<double, 4> frame{0, 0, 0, 0};
  std::vector<Dt::Vertex_handle> vertex;       // per site (owners only)
  std::size_t rebuilds = 0, flip_updates = 0;  // how each triangulation was made (for benchmarks and tests)
  // A Voronoi edge to integrate: from *p to *q, counter-clockwise around the lower-ranked of sites a and b.
  struct Edge_task {
    const std::array<double, 2>*p, *q;
    std::uint32_t a, b;  // the two sites (either may be a far corner)
  };
  // Buffers of one step, kept between iterations: allocating them anew costs page faults on every step.
  struct Workspace {
    std::vector<Edge_task> edges;
    Flip_workspace<Dt> flips;
    std::vector<char> interior;
    std::vector<std::uint32_t> ring_start, fill, boundary;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ring;
    std::vector<Polygon_2d> boundary_cells;
    std::vector<Density_moments> moments, edge_moments;
  } work;
  double minimum_distance = std::numeric_limits<double>::infinity();

  // The Delaunay triangulation of the sites with four far corners, so every site is interior and its cell
  // bounded; the corners are 3 max(width, height) outside the box, farther from any box point than every
  // site, so the cells restricted to the box are those of the sites alone. When the previous call had the
  // same number of sites, no duplicates and the same box, the sites are moved in place: if every triangle
  // keeps its orientation (exact predicate) the triangulation stays valid and Lawson flips (exact, perturbed
  // in-circle test, as CGAL's insertion) make it Delaunay again; otherwise it is rebuilt.
  void build(const std::vector<std::array<double, 2>>& points, const std::array<double, 4>& box) {
    if (!(sites == points.size() && duplicates == 0 && box == frame && sites != 0 && move(points)))
      rebuild(points, box);
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const auto c = ranked_circumcenter<Dt>(f);
      f->info().circumcenter = c;
      f->info().site = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      f->info().inside = c[0] >= box[0] && c[0] <= box[2] && c[1] >= box[1] && c[1] <= box[3];
    }
    double shortest = std::numeric_limits<double>::infinity();
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const auto a = e->first->vertex(Dt::cw(e->second)), b = e->first->vertex(Dt::ccw(e->second));
      if (a->info() == dummy || b->info() == dummy) continue;
      shortest = std::min(shortest, CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
    }
    minimum_distance = std::sqrt(shortest);
  }

  void rebuild(const std::vector<std::array<double, 2>>& points, const std::array<double, 4>& box) {
    ++rebuilds;
    dt.clear();
    frame = box;
    sites = points.size();
    const std::size_t n = points.size();
    const double reach = 3 * std::max({box[2] - box[0], box[3] - box[1], 1.0});
    std::vector<std::pair<K::Point_2, std::uint32_t>> input;
    input.reserve(n + 4);
    for (std::size_t i = 0; i < n; ++i)
      input.emplace_back(K::Point_2(points[i][0], points[i][1]), std::uint32_t(i));
    const double xs[2] = {box[0] - reach, box[2] + reach}, ys[2] = {box[1] - reach, box[3] + reach};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) input.emplace_back(K::Point_2(xs[a], ys[b]), dummy);
    dt.insert(input.begin(), input.end());
    owner.resize(n);
    std::iota(owner.begin(), owner.end(), std::uint32_t(0));
    duplicates = n + 4 - dt.number_of_vertices();
    if (duplicates != 0) {
      // Equal positions share one vertex, whose info is whichever copy came last: give the cell to the lowest
      // index (a symbolic tie-break); the other copies get empty cells.
      std::vector<std::uint32_t> order(n);
      std::iota(order.begin(), order.end(), std::uint32_t(0));
      std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return points[a] != points[b] ? points[a] < points[b] : a < b;
      });
      for (std::size_t k = 1; k < n; ++k)
        if (points[order[k]] == points[order[k - 1]]) owner[order[k]] = owner[order[k - 1]];
      for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if (v->info() != dummy) v->info() = owner[v->info()];
    }
    vertex.assign(n, Dt::Vertex_handle());
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      if (v->info() != dummy) vertex[v->info()] = v;
  }

  // Moves every vertex to its site's new position (move_by_flips()). False (the caller rebuilds) when more
  // than an eighth of the vertices would be held back, or when a move collides with another site.
  bool move(const std::vector<std::array<double, 2>>& points) {
    const std::size_t n = points.size();
    if (!move_by_flips(
            dt, n, [&](std::size_t i) { return K::Point_2(points[i][0], points[i][1]); },
            [&](std::size_t i) { return vertex[i]; }, n / 8, work.flips))
      return false;
    ++flip_updates;
    return true;
  }

  // The cell of a vertex (a convex polygon, counter-clockwise, from first_face), clipped to the box; empty
  // when it misses the box.
  void cell(Dt::Vertex_handle v, const std::array<double, 4>& box, Polygon_2d& out,
            Polygon_2d& scratch) const {
    out.clear();
    auto f = first_face(dt, v), end = f;
    bool inside = true;
    do {
      inside = inside && f->info().inside;
      // Cocircular sites give faces with one circumcentre: a vertex once (Polygon_2d repeats none).
      if (out.empty() || f->info().circumcenter != out.back()) out.push_back(f->info().circumcenter);
    } while (++f != end);
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
    if (!inside) clip(box, out, scratch);
  }

  // Sutherland-Hodgman against the four sides of the box (convex polygon, so the result is one polygon).
  static void clip(const std::array<double, 4>& box, Polygon_2d& poly, Polygon_2d& scratch) {
    for (int side = 0; side < 4 && !poly.empty(); ++side) {
      const int axis = side & 1;    // 0: x, 1: y
      const bool lower = side < 2;  // keep coordinate >= box[axis] or <= box[2 + axis]
      const double bound = lower ? box[std::size_t(axis)] : box[std::size_t(2 + axis)];
      auto in = [&](const std::array<double, 2>& p) { return lower ? p[axis] >= bound : p[axis] <= bound; };
      scratch.clear();
      const std::size_t n = poly.size();
      for (std::size_t i = 0; i < n; ++i) {
        const auto& a = poly[i];
        const auto& b = poly[(i + 1) % n];
        const bool ia = in(a), ib = in(b);
        if (ia) scratch.push_back(a);
        if (ia != ib) {
          const double t = (bound - a[axis]) / (b[axis] - a[axis]);
          std::array<double, 2> p;
          p[axis] = bound;
          p[1 - axis] = a[1 - axis] + t * (b[1 - axis] - a[1 - axis]);
          // A vertex on the bound is its own crossing: (0, 0), (1, 1), (0, 1) in the unit box repeated (1,
          // 0).
          if (scratch.empty() || p != scratch.back()) scratch.push_back(p);
        }
      }
      if (scratch.size() > 1 && scratch.front() == scratch.back()) scratch.pop_back();
      std::swap(poly, scratch);
    }
  }
};

// Reads 2D sites through PointCoordinateTraits and checks that they lie in the box.
template <class PointRange, class Traits>
std::vector<std::array<double, 2>> read_sites(const PointRange& points, const std::array<double, 4>& box,
                                              const Traits& traits, const char* fn) {
  static_assert(FeatureRecon::internal::Is_point_coordinate_traits<Traits>::value,
                "FeatureRecon: lloyd_relaxation() and lloyd_step() read their sites through a "
                "PointCoordinateTraits model (dimension(p), coordinate(p, i); "
                "doc/concepts/PointCoordinateTraits.h), not a FeaturePointTraits model of the samplers' "
                "items: pass the sites' positions (e.g. std::array<double, 2>) with the default traits");
  std::vector<std::array<double, 2>> sites;
  if constexpr (FeatureRecon::internal::Is_point_coordinate_traits<Traits>::value) {  // else: the assert only
    std::size_t i = 0;
    for (const auto& p : points) {
      if (traits.dimension(p) != 2)
        FeatureRecon::internal::throw_invalid_argument(fn, "site ", i, " has ", traits.dimension(p),
                                                       " coordinates, expected 2");
      const std::array<double, 2> q{traits.coordinate(p, 0), traits.coordinate(p, 1)};
      if (!(std::isfinite(q[0]) && std::isfinite(q[1])))
        FeatureRecon::internal::throw_invalid_argument(fn, "site ", i, " has a non-finite coordinate");
      if (!(q[0] >= box[0] && q[0] <= box[2] && q[1] >= box[1] && q[1] <= box[3]))
        FeatureRecon::internal::throw_invalid_argument(fn, "site ", i, " (", q[0], ", ", q[1],
                                                       ") lies outside the box [", box[0], ", ", box[2],
                                                       "] x [", box[1], ", ", box[3], "]");
      sites.push_back(q);
      ++i;
    }
  }
  return sites;
}

// The masses of the sites' cells, the CVT energy (integral of rho |x - p|^2 = M2 - 2 p . M1 + |p|^2 M0 per
// cell, clamped at 0 against rounding) and the centroids, put into the domain by place(x, y), from the cells'
// moments. A copy of a site (owner[i] != i) has an empty cell and stays. A cell over zero density sums its
// edges' moments to rounding noise, not to 0: its "centroid" was that noise divided by noise, clamped to a
// corner of the box, where such sites then stacked (stippling's white corners). Masses below a billionth of
// the mean cell's count as empty (the site stays).
template <class Place>
void cell_centroids(const std::vector<std::array<double, 2>>& sites, const std::vector<std::uint32_t>& owner,
                    const std::vector<Density_moments>& moments, const Pixel_density& density,
                    Lloyd_step_result& r, Place place) {
  const std::size_t n = sites.size();
  const double negligible = 1e-9 * density.total_mass() / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (owner[i] != i) continue;
    const Density_moments& m = moments[i];
    const auto& p = sites[i];
    r.mass[i] = m.mass;
    r.energy += std::max(
        0.0, m.moment_2 - 2 * (p[0] * m.moment_x + p[1] * m.moment_y) + (p[0] * p[0] + p[1] * p[1]) * m.mass);
    if (m.mass > negligible) r.centroids[i] = place(m.moment_x / m.mass, m.moment_y / m.mass);
  }
}

// The density moments of the sites' Voronoi cells, into work.moments (per site; zero for a site without a
// vertex), from a triangulation whose finite faces carry their circumcentre, their vertices' infos and
// whether the circumcentre lies in the box (Voronoi_builder::Face_data). site_of(info) is the site whose cell
// a vertex is, or `none` (far corners, images of sites); info_of(site) is the info of that site's vertex. A
// cell whose Voronoi vertices all lie in the box (an interior cell) is integrated edge by edge: each Voronoi
// edge next to an interior cell once, counter-clockwise around its lower-ranked (lower info) side, added to
// that side and subtracted from the other. The other cells are walked, sequentially (cell(v, polygon,
// scratch)), and integrated whole (whole(polygon)). The integrals run in parallel, each into its own slot,
// and the sums have a fixed order, so the result does not depend on the number of threads.
template <class SiteOf, class InfoOf, class Cell, class Whole>
void integrate_voronoi_cells(const Voronoi_builder::Dt& dt, std::size_t n, const SiteOf& site_of,
                             const InfoOf& info_of, const Cell& cell, const Whole& whole,
                             const Pixel_density& density, unsigned threads,
                             Voronoi_builder::Workspace& work) {
  using Dt = Voronoi_builder::Dt;
  constexpr std::uint32_t none = Voronoi_builder::dummy;
  std::vector<char>& interior = work.interior;
  interior.assign(n, 0);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const std::uint32_t i = site_of(v->info());
    if (i != none) interior[i] = 1;
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    if (!f->info().inside)
      for (const std::uint32_t k : f->info().site) {
        const std::uint32_t i = site_of(k);
        if (i != none) interior[i] = 0;
      }
  using Edge_task = Voronoi_builder::Edge_task;
  std::vector<Edge_task>& edges = work.edges;
  edges.clear();
  // per interior site: its edges (counts, then offsets)
  std::vector<std::uint32_t>& ring_start = work.ring_start;
  ring_start.assign(n + 1, 0);
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int i = e->second;
    const auto g = f->neighbor(i);
    // An edge with an infinite face lies on the hull, next to no interior cell; the cache is for finite
    // faces.
    if (dt.is_infinite(f) || dt.is_infinite(g)) continue;
    const std::uint32_t a = f->info().site[std::size_t(Dt::ccw(i))],
                        b = f->info().site[std::size_t(Dt::cw(i))];
    const std::uint32_t sa = site_of(a), sb = site_of(b);
    const bool ia = sa != none && interior[sa], ib = sb != none && interior[sb];
    if (!ia && !ib) continue;
    // Around a counter-clockwise, g comes just before f: the edge runs c(g) -> c(f) on a's cell.
    const bool from_a = a < b;  // rank_less: the infos differ (at least one is a site's own vertex)
    if (ia) ++ring_start[sa + 1];
    if (ib) ++ring_start[sb + 1];
    edges.push_back({&(from_a ? g : f)->info().circumcenter, &(from_a ? f : g)->info().circumcenter, a, b});
  }
  // Each interior cell's edges as (neighbour, edge) pairs, summed later in increasing neighbour order: a
  // fixed order that needs no walk around the cell (the walks were bound by cache misses on the faces).
  for (std::size_t i = 0; i < n; ++i) ring_start[i + 1] += ring_start[i];
  auto& ring = work.ring;
  ring.resize(ring_start[n]);
  {
    std::vector<std::uint32_t>& fill = work.fill;
    fill.assign(ring_start.begin(), ring_start.end() - 1);
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const std::uint32_t a = edges[k].a, b = edges[k].b, sa = site_of(a), sb = site_of(b);
      if (sa != none && interior[sa]) ring[fill[sa]++] = {b, static_cast<std::uint32_t>(k)};
      if (sb != none && interior[sb]) ring[fill[sb]++] = {a, static_cast<std::uint32_t>(k)};
    }
  }
  // The other cells, walked sequentially (the walks follow the triangulation's circulators).
  std::vector<std::uint32_t>& boundary = work.boundary;
  std::vector<Polygon_2d>& boundary_cells = work.boundary_cells;
  boundary.clear();
  std::size_t boundary_count = 0;
  {
    Polygon_2d scratch;
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      const std::uint32_t i = site_of(v->info());
      if (i == none || interior[i]) continue;
      if (boundary_cells.size() <= boundary_count) boundary_cells.emplace_back();
      cell(v, boundary_cells[boundary_count++], scratch);
      boundary.push_back(i);
    }
  }
  std::vector<Density_moments>& moments = work.moments;
  std::vector<Density_moments>& edge_moments = work.edge_moments;
  moments.assign(n, Density_moments());
  edge_moments.assign(edges.size(), Density_moments());
  const std::size_t tasks = edges.size() + boundary.size();
  FeatureRecon::internal::parallel_blocks(tasks, threads, 2048, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      if (k < edges.size()) {
        const Edge_task& t = edges[k];
        density.integrate_segment((*t.p)[0], (*t.p)[1], (*t.q)[0], (*t.q)[1], edge_moments[k]);
      } else {
        moments[boundary[k - edges.size()]] = whole(boundary_cells[k - edges.size()]);
      }
    }
  });
  // Interior cells: their edges summed in increasing order of the neighbour's info, each with the sign of its
  // walk (counter-clockwise around the lower info).
  FeatureRecon::internal::parallel_blocks(n, threads, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t a = begin; a < end; ++a) {
      if (ring_start[a] == ring_start[a + 1]) continue;
      const auto first = ring.begin() + ring_start[a], last = ring.begin() + ring_start[a + 1];
      std::sort(first, last);
      const std::uint32_t own = info_of(static_cast<std::uint32_t>(a));
      Density_moments& sum = moments[a];
      for (auto it = first; it != last; ++it) {
        if (own < it->first)
          sum += edge_moments[it->second];
        else
          sum -= edge_moments[it->second];
      }
    }
  });
}

// One Lloyd step on checked sites (integrate_voronoi_cells(): the cells that touch the box are clipped).
inline Lloyd_step_result lloyd_step_impl(const std::vector<std::array<double, 2>>& sites,
                                         const Pixel_density& density, Voronoi_builder& voronoi,
                                         unsigned threads) {
  Lloyd_step_result r;
  const std::size_t n = sites.size();
  r.centroids = sites;
  r.mass.assign(n, 0.0);
  r.minimum_distance = std::numeric_limits<double>::infinity();
  if (n == 0) return r;
  const auto box = density.box();
  if (threads == 0 && density.is_constant()) threads = 1;
  voronoi.build(sites, box);
  r.duplicates = voronoi.duplicates;
  r.minimum_distance = voronoi.minimum_distance;
  integrate_voronoi_cells(
      voronoi.dt, n, [](std::uint32_t info) { return info; }, [](std::uint32_t i) { return i; },
      [&](Voronoi_builder::Dt::Vertex_handle v, Polygon_2d& out, Polygon_2d& scratch) {
        voronoi.cell(v, box, out, scratch);
      },
      [&](const Polygon_2d& cell) { return density.integrate(cell); }, density, threads, voronoi.work);
  // The centroid lies in the convex cell, inside the box; clamped against rounding.
  cell_centroids(sites, voronoi.owner, voronoi.work.moments, density, r, [&](double x, double y) {
    return std::array<double, 2>{std::min(std::max(x, box[0]), box[2]),
                                 std::min(std::max(y, box[1]), box[3])};
  });
  return r;
}

// The Voronoi cells of sites on the torus of the box [x0, x1) x [y0, y1) (periods W = x1 - x0, H = y1 - y0):
// the Delaunay triangulation (CGAL, exact predicates) of the distinct sites and of their images p + (s W, t
// H), s, t in {-1, 0, 1}, that lie within `band` of the box. A site's cell is that of the torus when no
// image missing from the triangulation can lie in the circumcircle of a triangle around it: every such
// circle lies within the band. The band starts at 3 hexagonal spacings and doubles until that holds for
// every site, up to the whole period (all eight copies; then the cells are those of the tiling). Each cell
// is the polygon of its triangles' circumcentres around the site itself, counter-clockwise from the face
// towards its lowest-ranked neighbour (first_face()), and may reach out of the box.
// Four far corners close the triangulation, so its hull never moves. The triangulation is kept: when the
// next call has as many sites, no copies and the same box, the vertices
// move (move_by_flips()), those of a site that crossed a face taking the label of the image they are now
// nearest, images that leave the band are removed and those that enter it inserted. The result is the
// triangulation a rebuild at the same band gives (the Delaunay triangulation with CGAL's symbolic
// perturbation is unique; where four points are cocircular, a vertex moved by move_if_no_collision may leave
// another split of their circle), and the cells do not depend on the band, so the cells are those of a fresh
// build.
struct Periodic_voronoi {
  using K = Voronoi_builder::K;
  using Dt = Voronoi_builder::Dt;    // vertex info: 9 i + code of the image
  std::vector<std::uint32_t> owner;  // per site: the lowest index at the same position
  std::size_t duplicates = 0;
  double minimum_distance = std::numeric_limits<double>::infinity();  // between distinct sites, on the torus
  std::size_t widenings = 0;                                          // band doublings (for tests)
  std::size_t rebuilds = 0, flip_updates = 0;  // how each triangulation was made (for benchmarks and tests)
  std::size_t relabelled = 0, inserted = 0, removed = 0;  // images of the flip updates (for tests)

  Dt dt;
  std::vector<Dt::Vertex_handle> handle;      // per 9 i + code: its vertex, or none
  std::vector<std::array<double, 2>> placed;  // the sites of the triangulation (none at the same position)
  std::array<double, 4> frame{0, 0, 0, 0};
  double band = 0;
  bool reusable = false;
  Voronoi_builder::Workspace work;

  // The image `code` (s + 1) + 3 (t + 1) of p: p + (s W, t H).
  static std::array<double, 2> image(const std::array<double, 2>& p, std::uint32_t code, double W, double H) {
    return {p[0] + (double(code % 3) - 1) * W, p[1] + (double(code / 3) - 1) * H};
  }
  static constexpr std::uint32_t dummy = Voronoi_builder::dummy;  // the far corners' info
  // Whether a vertex is a site itself (not an image, not a far corner).
  static bool is_site(std::uint32_t info) { return info != dummy && info % 9 == 4; }
  static bool within(const std::array<double, 2>& q, const std::array<double, 4>& box, double reach) {
    return q[0] >= box[0] - reach && q[0] <= box[2] + reach && q[1] >= box[1] - reach &&
           q[1] <= box[3] + reach;
  }

  void build(const std::vector<std::array<double, 2>>& sites, const std::array<double, 4>& box) {
    const std::size_t n = sites.size();
    const double W = box[2] - box[0], H = box[3] - box[1];
    owner.resize(n);
    // The sites sorted by position, then index (contiguous records: an indirect sort missed the cache).
    std::vector<std::pair<std::array<double, 2>, std::uint32_t>> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = {sites[i], static_cast<std::uint32_t>(i)};
    std::sort(order.begin(), order.end());
    duplicates = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const bool copy = k > 0 && order[k].first == order[k - 1].first;
      owner[order[k].second] = copy ? owner[order[k - 1].second] : order[k].second;
      duplicates += copy ? 1 : 0;
    }
    const double distinct = double(n - duplicates), whole = std::max(W, H);
    bool ready = false;
    if (reusable && duplicates == 0 && placed.size() == n && box == frame) {
      if (update(sites, box)) {
        ++flip_updates;
        ready = prepare_faces(box) || band >= whole;
        if (!ready) {
          band = std::min(2 * band, whole);
          ++widenings;
        }
      } else {
        band = std::min(whole, 3 * std::sqrt(2 * W * H / (std::sqrt(3.0) * distinct)));
      }
    } else {
      band = std::min(whole, 3 * std::sqrt(2 * W * H / (std::sqrt(3.0) * distinct)));
    }
    while (!ready) {
      rebuild(sites, box);
      if (prepare_faces(box) || band >= whole) break;
      band = std::min(2 * band, whole);
      ++widenings;
    }
    placed = sites;
    frame = box;
    reusable = duplicates == 0 && dt.dimension() == 2;
    // The shortest distance between a site and a neighbour that is not its own image.
    double shortest = std::numeric_limits<double>::infinity();
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const auto a = e->first->vertex(Dt::ccw(e->second)), b = e->first->vertex(Dt::cw(e->second));
      if ((is_site(a->info()) || is_site(b->info())) && a->info() != dummy && b->info() != dummy &&
          a->info() / 9 != b->info() / 9)
        shortest = std::min(shortest, CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
    }
    minimum_distance = std::sqrt(shortest);
  }

  void rebuild(const std::vector<std::array<double, 2>>& sites, const std::array<double, 4>& box) {
    ++rebuilds;
    const double W = box[2] - box[0], H = box[3] - box[1];
    std::vector<std::pair<K::Point_2, std::uint32_t>> points;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (owner[i] != i) continue;
      for (std::uint32_t code = 0; code < 9; ++code) {
        const std::array<double, 2> q = image(sites[i], code, W, H);
        if (code != 4 && !within(q, box, band)) continue;
        points.push_back({K::Point_2(q[0], q[1]), static_cast<std::uint32_t>(9 * i + code)});
      }
    }
    // Four far corners, as Voronoi_builder's, 3 max(W, H, 1) outside the box (the images lie within one
    // period of it): the hull stays fixed while the sites and images move, so triangles that keep their
    // orientation keep the triangulation valid (moving hull vertices broke its convexity).
    const double reach = 3 * std::max({W, H, 1.0});
    const double xs[2] = {box[0] - reach, box[2] + reach}, ys[2] = {box[1] - reach, box[3] + reach};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) points.push_back({K::Point_2(xs[a], ys[b]), dummy});
    dt.clear();
    dt.insert(points.begin(), points.end());
    handle.assign(9 * sites.size(), Dt::Vertex_handle());
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      if (v->info() != dummy) handle[v->info()] = v;
  }

  // The triangulation of the last call moved to `sites` (same number, none at the same position, same box);
  // false when the triangulation has to be rebuilt.
  bool update(const std::vector<std::array<double, 2>>& sites, const std::array<double, 4>& box) {
    const std::size_t n = sites.size();
    const double W = box[2] - box[0], H = box[3] - box[1];
    std::vector<Dt::Vertex_handle> next(9 * n, Dt::Vertex_handle());
    std::vector<Dt::Vertex_handle> leaving;
    std::vector<std::pair<K::Point_2, std::uint32_t>> entering;
    for (std::size_t i = 0; i < n; ++i) {
      // A site that crossed a face is nearest its old place as the image one period over: each of its
      // vertices takes the label of the image it is now nearest.
      const double dx = placed[i][0] - sites[i][0], dy = placed[i][1] - sites[i][1];
      const int sx = dx > W / 2 ? 1 : dx < -W / 2 ? -1 : 0, sy = dy > H / 2 ? 1 : dy < -H / 2 ? -1 : 0;
      relabelled += (sx != 0 || sy != 0) ? 1 : 0;
      for (std::uint32_t code = 0; code < 9; ++code) {
        const Dt::Vertex_handle v = handle[9 * i + code];
        if (v == Dt::Vertex_handle()) continue;
        const int s = int(code % 3) - 1 + sx, t = int(code / 3) - 1 + sy;
        const std::uint32_t moved = std::uint32_t(s + 1) + 3 * std::uint32_t(t + 1);
        if (s < -1 || s > 1 || t < -1 || t > 1 ||
            (moved != 4 && !within(image(sites[i], moved, W, H), box, band)))
          leaving.push_back(v);
        else
          next[9 * i + moved] = v;
      }
      for (std::uint32_t code = 0; code < 9; ++code) {
        if (next[9 * i + code] != Dt::Vertex_handle()) continue;
        const std::array<double, 2> q = image(sites[i], code, W, H);
        if (code == 4 || within(q, box, band))
          entering.push_back({K::Point_2(q[0], q[1]), static_cast<std::uint32_t>(9 * i + code)});
      }
    }
    const std::size_t kept = dt.number_of_vertices() - leaving.size();
    for (const Dt::Vertex_handle v : leaving) dt.remove(v);
    removed += leaving.size();
    if (dt.dimension() != 2) return false;
    handle.swap(next);
    for (std::size_t k = 0; k < handle.size(); ++k)
      if (handle[k] != Dt::Vertex_handle()) handle[k]->info() = static_cast<std::uint32_t>(k);
    if (!move_by_flips(
            dt, handle.size(),
            [&](std::size_t k) {
              const std::array<double, 2> q = image(sites[k / 9], std::uint32_t(k % 9), W, H);
              return K::Point_2(q[0], q[1]);
            },
            [&](std::size_t k) { return handle[k]; }, kept / 8, work.flips))
      return false;
    if (!entering.empty()) {
      dt.insert(entering.begin(), entering.end());
      inserted += entering.size();
      if (dt.number_of_vertices() != kept + entering.size()) return false;  // an image on another point
      for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if (v->info() != dummy) handle[v->info()] = v;
    }
    return true;
  }

  // Caches each finite face's circumcentre, its vertices' infos and whether the circumcentre lies in the box
  // (Voronoi_builder::Face_data); false when a triangle around a site has a far corner or a circumcircle
  // that reaches beyond the band (the sites and images within it span too little), so that a missing image
  // could change its cell.
  bool prepare_faces(const std::array<double, 4>& box) {
    bool complete = true;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const std::array<double, 2> c = ranked_circumcenter<Dt>(f);
      auto& d = f->info();
      d.circumcenter = c;
      d.site = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      d.inside = c[0] >= box[0] && c[0] <= box[2] && c[1] >= box[1] && c[1] <= box[3];
      if (!complete || !(is_site(d.site[0]) || is_site(d.site[1]) || is_site(d.site[2]))) continue;
      // A far corner lies beyond the band, so its circle does too; checked by name all the same.
      const K::Point_2& p = f->vertex(0)->point();
      const double dx = c[0] - p.x(), dy = c[1] - p.y(), r = std::sqrt(dx * dx + dy * dy);
      complete = d.site[0] != dummy && d.site[1] != dummy && d.site[2] != dummy &&
                 c[0] - r >= box[0] - band && c[0] + r <= box[2] + band && c[1] - r >= box[1] - band &&
                 c[1] + r <= box[3] + band;
    }
    return complete;
  }

  // The cell of a site's vertex: the circumcentres of its triangles, counter-clockwise from first_face().
  void cell(Dt::Vertex_handle v, Polygon_2d& out) const {
    out.clear();
    auto f = first_face(dt, v), end = f;
    do {
      const std::array<double, 2>& q = f->info().circumcenter;
      if (out.empty() || q != out.back()) out.push_back(q);  // cocircular sites: one vertex
    } while (++f != end);
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  }

  // Every site's cell (empty for copies).
  std::vector<Polygon_2d> cells() const {
    std::vector<Polygon_2d> all(owner.size());
    for (std::size_t i = 0; i < owner.size(); ++i)
      if (owner[i] == i) cell(handle[9 * i + 4], all[i]);
    return all;
  }
};

// Mass and moments of a cell on the torus: the parts of the polygon in the nine copies of the box shifted by
// multiples of its sides, each shifted back into the box, integrated there and its moments moved to the
// polygon's own frame (M1 + t M0, M2 + 2 t . M1 + |t|^2 M0 for the shift t), summed in a fixed order.
inline Density_moments periodic_cell_moments(const Polygon_2d& cell, const Pixel_density& density) {
  const std::array<double, 4> box = density.box();
  const double W = box[2] - box[0], H = box[3] - box[1];
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& q : cell)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], q[std::size_t(k)]);
      hi[k] = std::max(hi[k], q[std::size_t(k)]);
    }
  Density_moments sum;
  Polygon_2d piece, scratch;
  for (int ty = -1; ty <= 1; ++ty)
    for (int tx = -1; tx <= 1; ++tx) {
      const double sx = tx * W, sy = ty * H;
      const std::array<double, 4> copy{box[0] + sx, box[1] + sy, box[2] + sx, box[3] + sy};
      if (hi[0] <= copy[0] || lo[0] >= copy[2] || hi[1] <= copy[1] || lo[1] >= copy[3]) continue;
      piece = cell;
      Voronoi_builder::clip(copy, piece, scratch);
      if (piece.size() < 3) continue;
      for (auto& q : piece) {  // back into the box (clamped against the rounding of the shift)
        q[0] = std::min(std::max(q[0] - sx, box[0]), box[2]);
        q[1] = std::min(std::max(q[1] - sy, box[1]), box[3]);
      }
      const Density_moments m = density.integrate(piece);
      sum.moment_2 += m.moment_2 + 2 * (sx * m.moment_x + sy * m.moment_y) + (sx * sx + sy * sy) * m.mass;
      sum.moment_x += m.moment_x + sx * m.mass;
      sum.moment_y += m.moment_y + sy * m.mass;
      sum.mass += m.mass;
    }
  return sum;
}

// A coordinate x of the torus [low, low + period): x taken modulo the period.
inline double wrap_into(double x, double low, double period) {
  if (x >= low && x < low + period) return x;  // as given: distinct sites stay distinct
  const double t = x - period * std::floor((x - low) / period);
  return t >= low && t < low + period ? t : low;
}

// One Lloyd step on the torus of the density's box, on checked sites (inside the box; x1 or y1 is taken as
// x0 or y0).
inline Lloyd_step_result periodic_lloyd_step_impl(const std::vector<std::array<double, 2>>& given,
                                                  const Pixel_density& density, Periodic_voronoi& voronoi,
                                                  unsigned threads) {
  Lloyd_step_result r;
  const std::size_t n = given.size();
  const std::array<double, 4> box = density.box();
  const double W = box[2] - box[0], H = box[3] - box[1];
  std::vector<std::array<double, 2>> sites = given;
  for (auto& p : sites) p = {wrap_into(p[0], box[0], W), wrap_into(p[1], box[1], H)};
  r.centroids = sites;
  r.mass.assign(n, 0.0);
  r.minimum_distance = std::numeric_limits<double>::infinity();
  if (n == 0 || !(W > 0 && H > 0)) return r;
  voronoi.build(sites, box);
  r.duplicates = voronoi.duplicates;
  r.minimum_distance = voronoi.minimum_distance;
  if (threads == 0 && density.is_constant()) threads = 1;
  // A cell inside the box is integrated edge by edge, a cell across its faces in pieces on the torus.
  constexpr std::uint32_t none = Voronoi_builder::dummy;
  integrate_voronoi_cells(
      voronoi.dt, n, [](std::uint32_t info) { return Periodic_voronoi::is_site(info) ? info / 9 : none; },
      [](std::uint32_t i) { return 9 * i + 4; },
      [&](Voronoi_builder::Dt::Vertex_handle v, Polygon_2d& out, Polygon_2d&) { voronoi.cell(v, out); },
      [&](const Polygon_2d& cell) { return periodic_cell_moments(cell, density); }, density, threads,
      voronoi.work);
  cell_centroids(sites, voronoi.owner, voronoi.work.moments, density, r, [&](double x, double y) {
    return std::array<double, 2>{wrap_into(x, box[0], W), wrap_into(y, box[1], H)};
  });
  return r;
}
/// \endcond
}  // namespace internal

/// The Voronoi cells of the sites clipped to the box [x0, x1] x [y0, y1], from CGAL's
/// Delaunay_triangulation_2 (exact predicates; the Voronoi vertices are the circumcentres, computed in
/// double). Sites at the position of a lower-indexed site get an empty cell (ties go to the lowest index).
/// \tparam PointRange a range of 2D points. \tparam Traits a model of PointCoordinateTraits.
/// \param points the sites, inside the box.
/// \param box {x0, y0, x1, y1}, finite with x0 <= x1 and y0 <= y1 (checked; throws).
/// \param traits reads the sites' coordinates.
/// \throws std::invalid_argument naming the site for a site that is not 2D, not finite or outside the box.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::decay<
                                decltype(*std::begin(std::declval<const PointRange&>()))>::type>>
std::vector<Polygon_2d> clipped_voronoi_cells(const PointRange& points, const std::array<double, 4>& box,
                                              const Traits& traits = Traits()) {
  const char* fn = "clipped_voronoi_cells";
  const auto b = internal::check_box(box, fn);
  const auto sites = internal::read_sites(points, b, traits, fn);
  std::vector<Polygon_2d> cells(sites.size());
  if (sites.empty()) return cells;
  internal::Voronoi_builder voronoi;
  voronoi.build(sites, b);
  Polygon_2d scratch;
  for (auto v = voronoi.dt.finite_vertices_begin(); v != voronoi.dt.finite_vertices_end(); ++v)
    if (v->info() != internal::Voronoi_builder::dummy) voronoi.cell(v, b, cells[v->info()], scratch);
  return cells;
}

/// One Lloyd iteration: the centroid of every site's Voronoi cell (clipped to the density's box) under the
/// pixel density, the cell masses and the CVT energy of the given sites. The cells are integrated on the
/// hardware's threads; the result is the same bit for bit on any number of threads.
/// \tparam PointRange a range of 2D points. \tparam Traits a model of PointCoordinateTraits.
/// \param points the sites, inside the density's box.
/// \param density the density and its box.
/// \param traits reads the sites' coordinates.
/// \throws std::invalid_argument naming the site for a site that is not 2D, not finite or outside the box.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::decay<
                                decltype(*std::begin(std::declval<const PointRange&>()))>::type>>
Lloyd_step_result lloyd_step(const PointRange& points, const Pixel_density& density,
                             const Traits& traits = Traits()) {
  const auto sites = internal::read_sites(points, density.box(), traits, "lloyd_step");
  internal::Voronoi_builder voronoi;
  return internal::lloyd_step_impl(sites, density, voronoi, 0);
}

/// The Voronoi cells of the sites on the torus of the box [x0, x1) x [y0, y1): those of the sites and of
/// their images shifted by multiples of the box's sides, from CGAL's Delaunay_triangulation_2 (exact
/// predicates; circumcentres in double). Each cell is a convex polygon around its site, counter-clockwise,
/// and may reach out of the box (its parts in the shifted copies of the box belong to the torus's cell). A
/// site on x1 or y1 is the one on x0 or y0. Sites at the position of a lower-indexed site get an empty cell.
/// \tparam PointRange a range of 2D points. \tparam Traits a model of PointCoordinateTraits.
/// \param points the sites, inside the box.
/// \param box {x0, y0, x1, y1}, finite with x0 < x1 and y0 < y1 (checked; throws).
/// \param traits reads the sites' coordinates.
/// \throws std::invalid_argument naming the site for a site that is not 2D, not finite or outside the box,
///   and for a box of zero width or height.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::decay<
                                decltype(*std::begin(std::declval<const PointRange&>()))>::type>>
std::vector<Polygon_2d> periodic_voronoi_cells(const PointRange& points, const std::array<double, 4>& box,
                                               const Traits& traits = Traits()) {
  const char* fn = "periodic_voronoi_cells";
  const auto b = internal::check_box(box, fn);
  if (!(b[0] < b[2] && b[1] < b[3]))
    FeatureRecon::internal::throw_invalid_argument(fn, "the box of a torus needs x0 < x1 and y0 < y1");
  std::vector<std::array<double, 2>> sites = internal::read_sites(points, b, traits, fn);
  for (auto& p : sites)
    p = {internal::wrap_into(p[0], b[0], b[2] - b[0]), internal::wrap_into(p[1], b[1], b[3] - b[1])};
  if (sites.empty()) return {};
  internal::Periodic_voronoi voronoi;
  voronoi.build(sites, b);
  return voronoi.cells();
}

/// One Lloyd iteration on the torus of the density's box (Lloyd_options::periodic): the centroid of every
/// site's periodic Voronoi cell under the density (taken modulo the box), the cell masses and the CVT energy
/// of the given sites, with distances of the torus. The result is the same bit for bit on any number of
/// threads.
/// \tparam PointRange a range of 2D points. \tparam Traits a model of PointCoordinateTraits.
/// \param points the sites, inside the density's box.
/// \param density the density and its box.
/// \param traits reads the sites' coordinates.
/// \throws std::invalid_argument naming the site for a site that is not 2D, not finite or outside the box.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::decay<
                                decltype(*std::begin(std::declval<const PointRange&>()))>::type>>
Lloyd_step_result periodic_lloyd_step(const PointRange& points, const Pixel_density& density,
                                      const Traits& traits = Traits()) {
  const auto sites = internal::read_sites(points, density.box(), traits, "periodic_lloyd_step");
  internal::Periodic_voronoi voronoi;
  return internal::periodic_lloyd_step_impl(sites, density, voronoi, 0);
}

/// Lloyd relaxation of the sites under the pixel density: each iteration moves every site to the centroid of
/// its Voronoi cell (clipped to the density's box, density integrated exactly per pixel). Stops at
/// max_iterations, when the relative energy decrease or the largest move falls below its tolerance, or when
/// on_iteration returns false. Copies of a site (equal positions) first move apart by a hundredth of the
/// hexagonal spacing, kept inside the box. With `options.periodic` the box is a torus
/// (periodic_lloyd_step()): the triangulation holds the sites and their images near the faces, and is kept
/// between iterations as well (each step gives what periodic_lloyd_step() gives, bit for bit unless four
/// sites or images are cocircular, where the triangulation may split their circle otherwise). Deterministic:
/// the same sites give bit-identical output. O(N log N + C) per iteration for N sites whose cell boundaries
/// cross C pixel sides.
/// \tparam PointRange a range of 2D points (the initial sites, for example from dart throwing).
/// \tparam Traits a model of PointCoordinateTraits.
/// \param points the initial sites, inside the density's box.
/// \param density the density and its box.
/// \param options iteration cap, tolerances, per-iteration callback and progress.
/// \param traits reads the sites' coordinates.
/// \throws std::invalid_argument naming the site for a site that is not 2D, not finite or outside the box,
///   or for a negative or non-finite tolerance.
template <class PointRange, class Traits = Point_coordinate_traits<typename std::decay<
                                decltype(*std::begin(std::declval<const PointRange&>()))>::type>>
Lloyd_result lloyd_relaxation(const PointRange& points, const Pixel_density& density,
                              const Lloyd_options& options = {}, const Traits& traits = Traits()) {
  const char* fn = "lloyd_relaxation";
  if (!(std::isfinite(options.energy_tolerance) && options.energy_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "energy_tolerance must be finite and >= 0, got ",
                                                   options.energy_tolerance);
  if (!(std::isfinite(options.move_tolerance) && options.move_tolerance >= 0))
    FeatureRecon::internal::throw_invalid_argument(fn, "move_tolerance must be finite and >= 0, got ",
                                                   options.move_tolerance);
  Lloyd_result result;
  result.sites = internal::read_sites(points, density.box(), traits, fn);
  const std::size_t n = result.sites.size();
  result.mass.assign(n, 0.0);
  if (n == 0 || density.width() == 0 || density.height() == 0 || !(density.total_mass() > 0)) {
    result.status = Status::degenerate_input;
    return result;
  }
  const double area = double(density.width()) * double(density.height());
  const double hexagonal = std::sqrt(2 * area / (std::sqrt(3.0) * double(n)));
  // Copies of a site have empty cells and stay: where the first copy is already at its centroid they stayed
  // together for good. Every copy after the first moves by d_hex / 100 first (as kernel_relaxation() does).
  if (options.max_iterations > 0) {  // no iteration: the sites as given
    const std::array<double, 4> b = density.box();
    if (options.periodic)  // a site on x1 or y1 is the one on x0 or y0: a copy to separate
      for (auto& p : result.sites)
        p = {internal::wrap_into(p[0], b[0], b[2] - b[0]), internal::wrap_into(p[1], b[1], b[3] - b[1])};
    const std::array<double, 2> lo{b[0], b[1]}, hi{b[2], b[3]};
    internal::separate_copies<2>(
        n, hexagonal / 100, [&result](std::size_t i) -> auto& { return result.sites[i]; }, &lo, &hi);
  }
  internal::Voronoi_builder voronoi;
  internal::Periodic_voronoi periodic_voronoi;
  double previous_energy = std::numeric_limits<double>::infinity();
  for (std::size_t it = 0; it < options.max_iterations; ++it) {
    if (!FeatureRecon::internal::report_progress(options.progress,
                                                 double(it) / double(options.max_iterations))) {
      result.stop = Lloyd_stop::interrupted;
      result.status = Status::interrupted;
      return result;
    }
    Lloyd_step_result step =
        options.periodic
            ? internal::periodic_lloyd_step_impl(result.sites, density, periodic_voronoi, options.threads)
            : internal::lloyd_step_impl(result.sites, density, voronoi, options.threads);
    Lloyd_iteration_statistics s;
    s.iteration = it + 1;
    s.energy = step.energy;
    s.relative_radius = n < 2                               ? 0.0
                        : std::isinf(step.minimum_distance) ? 0.0
                                                            : step.minimum_distance / hexagonal;
    if (step.duplicates != 0) s.relative_radius = 0;
    double total_move = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double dx = std::abs(step.centroids[i][0] - result.sites[i][0]),
             dy = std::abs(step.centroids[i][1] - result.sites[i][1]);
      if (options.periodic) {  // the move on the torus (a site may cross a face)
        dx = std::min(dx, double(density.width()) - dx);
        dy = std::min(dy, double(density.height()) - dy);
      }
      const double d = std::hypot(dx, dy);
      s.max_move = std::max(s.max_move, d);
      total_move += d;
    }
    s.mean_move = total_move / double(n);
    result.sites = std::move(step.centroids);
    result.mass = std::move(step.mass);
    bool go_on = true;
    if (options.on_iteration) go_on = options.on_iteration(s, result.sites);
    result.history.push_back(s);
    if (internal::iteration_stops(go_on, s.max_move, options.move_tolerance, previous_energy,
                                  previous_energy - s.energy, options.energy_tolerance, result.stop))
      break;
    previous_energy = s.energy;
  }
  (void)FeatureRecon::internal::report_progress(options.progress, 1.0);
  return result;
}

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_LLOYD_RELAXATION_H
