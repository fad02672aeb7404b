// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_PIXEL_DENSITY_H
#define FEATURERECON_SAMPLING_PIXEL_DENSITY_H

/// \file
/// A density that is constant on each pixel of an image, and the exact integrals of its mass, first and
/// second moments over polygons (the Voronoi cells of Lloyd relaxation), in time proportional to the number
/// of pixel sides the polygon's boundary crosses rather than to the number of pixels it covers.

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/internal/Large_array_allocator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace sampling {

/// Integrals of a density rho over a region R.
struct Density_moments {
  double mass = 0;      ///< integral of rho
  double moment_x = 0;  ///< integral of x rho
  double moment_y = 0;  ///< integral of y rho
  double moment_2 = 0;  ///< integral of (x^2 + y^2) rho
  /// Adds the integrals of another region (disjoint from this one). \param o the other region's integrals.
  Density_moments& operator+=(const Density_moments& o) {
    mass += o.mass;
    moment_x += o.moment_x;
    moment_y += o.moment_y;
    moment_2 += o.moment_2;
    return *this;
  }
  /// Removes the integrals of a region (the same boundary walked the other way). \param o its integrals.
  Density_moments& operator-=(const Density_moments& o) {
    mass -= o.mass;
    moment_x -= o.moment_x;
    moment_y -= o.moment_y;
    moment_2 -= o.moment_2;
    return *this;
  }
};

/// A non-negative density on the box [0, width) x [0, height), constant on each unit pixel: pixel (column,
/// row) is [column, column + 1) x [row, row + 1), the convention of Bilinear_image and Pixel_traits (x to the
/// right, y down). integrate() is exact up to rounding for any simple polygon inside the box: by Green's
/// theorem the integral of rho over a region is the boundary integral of F(x, y) dy with F the integral of
/// rho from 0 to x along the row, and likewise for the moments; F is read from per-row prefix sums, and each
/// piece of the boundary inside one pixel is integrated in closed form (Simpson's rule, exact for the cubic
/// integrands). Memory: 4 (width + 1) height doubles.
class Pixel_density {
 public:
  /// An empty density (box of size 0).
  Pixel_density() = default;

  /// \param width columns (>= 0). \param height rows (>= 0).
  /// \param values width * height densities, rows from the top; each finite and >= 0 (checked; throws
  ///   std::invalid_argument naming the first bad pixel), and small enough that their moments over the image
  ///   stay finite (checked; throws).
  Pixel_density(int width, int height, std::vector<double> values) : m_width(width), m_height(height) {
    const char* fn = "Pixel_density";
    if (width < 0 || height < 0)
      FeatureRecon::internal::throw_invalid_argument(fn, "width and height must be >= 0, got ", width, " x ",
                                                     height);
    const std::size_t w = std::size_t(width), h = std::size_t(height);
    if (values.size() != w * h)
      FeatureRecon::internal::throw_invalid_argument(fn, "values has ", values.size(), " entries, a ", width,
                                                     " x ", height, " density needs ", w * h);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!(std::isfinite(values[i]) && values[i] >= 0))
        FeatureRecon::internal::throw_invalid_argument(
            fn, "values[", i, "] (column ", i % std::max<std::size_t>(w, 1), ", row ",
            i / std::max<std::size_t>(w, 1), ") must be finite and >= 0, got ", values[i]);
    // Per row and pixel side k = 0..width: F, G, Q at x = k and the density of pixel k (0 past the last), one
    // 32-byte record, so a piece of boundary reads one cache line.
    m_prefix.resize(4 * (w + 1) * h);
    for (std::size_t row = 0; row < h; ++row) {
      double f = 0, g = 0, q = 0;
      double* p = &m_prefix[4 * (w + 1) * row];
      for (std::size_t column = 0; column <= w; ++column) {
        const double r = column < w ? values[row * w + column] : 0.0, k = double(column);
        p[4 * column] = f;
        p[4 * column + 1] = g;
        p[4 * column + 2] = q;
        p[4 * column + 3] = r;
        f += r;                            // integral of rho over [k, k + 1)
        g += r * (k + 0.5);                // integral of t rho
        q += r * (k * k + k + 1.0 / 3.0);  // integral of t^2 rho
      }
      m_total += p[4 * w];
      if (!std::isfinite(p[4 * w + 2]) ||
          !std::isfinite(m_total))  // q bounds f and g (t^2 + t + 1/3 >= 1/3, t)
        FeatureRecon::internal::throw_invalid_argument(
            fn, "the values are too large: their integrals over the image ", "(density times x^2 along row ",
            row, ", or the total) ", "overflow a double; scale them down (the density's scale ",
            "does not change a Lloyd step)");
    }
    // A constant density (plain Lloyd) has closed-form integrals along any segment: no pixel walk.
    if (!values.empty() &&
        std::all_of(values.begin(), values.end(), [&](double v) { return v == values[0]; }))
      m_constant = values[0];
  }

  /// A constant density 1 on the box [0, width) x [0, height) (plain, unweighted Lloyd relaxation).
  /// \param width columns (>= 0). \param height rows (>= 0).
  static Pixel_density uniform(int width, int height) {
    if (width < 0 || height < 0)
      FeatureRecon::internal::throw_invalid_argument(
          "Pixel_density::uniform", "width and height must be >= 0, got ", width, " x ", height);
    return Pixel_density(width, height, std::vector<double>(std::size_t(width) * std::size_t(height), 1.0));
  }

  int width() const { return m_width; }    ///< in pixels
  int height() const { return m_height; }  ///< in pixels
  /// The domain {x0, y0, x1, y1} = {0, 0, width, height}.
  std::array<double, 4> box() const { return {0.0, 0.0, double(m_width), double(m_height)}; }
  /// The density of pixel (column, row). \pre 0 <= column < width, 0 <= row < height.
  /// \param column from the left. \param row from the top.
  double value(int column, int row) const {
    return m_prefix[4 * ((std::size_t(m_width) + 1) * std::size_t(row) + std::size_t(column)) + 3];
  }
  /// The integral of the density over the whole box.
  double total_mass() const { return m_total; }
  /// True when every pixel has the same density (plain Lloyd): segments are then integrated in closed form.
  bool is_constant() const { return m_constant >= 0; }

  /// Adds the boundary integrals of the directed segment a -> b to `moments`. Summed over the edges of a
  /// counter-clockwise simple polygon inside the box (CGAL's orientation: positive determinant), they give
  /// the polygon's mass and moments; a clockwise polygon gives their negatives. Each edge contributes in time
  /// proportional to the number of pixel sides it crosses. \pre a and b lie in the box.
  /// \param ax, ay the start a. \param bx, by the end b. \param moments receives the integrals.
  void integrate_segment(double ax, double ay, double bx, double by, Density_moments& moments) const {
    const double dx = bx - ax, dy = by - ay;
    if (dy == 0 || m_width == 0 || m_height == 0) return;  // every integrand has the factor dy
    if (m_constant >= 0) {
      // F = c x, G = c x^2 / 2, S = c x^3 / 3 + y^2 c x: cubic along the segment, so one Simpson step is
      // exact.
      const double c = m_constant, xm = 0.5 * (ax + bx), ym = 0.5 * (ay + by), w = dy * (1.0 / 6.0);
      moments.mass += w * c * (ax + 4 * xm + bx);
      moments.moment_x += w * c * 0.5 * (ax * ax + 4 * xm * xm + bx * bx);
      moments.moment_y += w * c * (ay * ax + 4 * ym * xm + by * bx);
      moments.moment_2 += w * c *
                          ((ax * ax * ax + 4 * xm * xm * xm + bx * bx * bx) * (1.0 / 3.0) +
                           (ay * ay * ax + 4 * ym * ym * xm + by * by * bx));
      return;
    }
    // Parameters t in (0, 1) where the segment crosses a pixel side, walked in increasing order.
    const double inf = std::numeric_limits<double>::infinity();
    const double idx = dx != 0 ? 1 / dx : 0, idy = 1 / dy;
    const double sx = dx > 0 ? 1.0 : -1.0, sy = dy > 0 ? 1.0 : -1.0;
    double nx = 0, tx = inf;  // next vertical pixel side and its parameter
    if (dx != 0) {
      nx = dx > 0 ? floor_nonnegative(ax) + 1 : ceil_nonnegative(ax) - 1;
      tx = (nx - ax) * idx;
    }
    double ny = dy > 0 ? floor_nonnegative(ay) + 1 : ceil_nonnegative(ay) - 1;
    double ty = (ny - ay) * idy;
    double x0 = ax, y0 = ay;
    Integrands start;
    // F, G, Q are continuous in x along a row: a piece that starts where the last one crossed a vertical side
    // reuses its end values
    bool have_start = false;
    for (;;) {
      double x1 = bx, y1 = by;
      bool last = true, vertical = false, horizontal = false;
      if (tx < 1 && tx <= ty) {
        x1 = nx;  // exactly on the vertical side
        vertical = true;
        if (ty == tx) {
          y1 = ny;
          horizontal = true;
        } else {
          y1 = ay + tx * dy;
        }
        last = false;
      } else if (ty < 1) {
        y1 = ny;  // exactly on the horizontal side
        x1 = ax + ty * dx;
        horizontal = true;
        last = false;
      }
      if (y1 != y0) {
        const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
        const int column = std::min(std::max(int(xm), 0), m_width - 1);  // int() is floor() for xm >= 0
        const int row = std::min(std::max(int(ym), 0), m_height - 1);
        const Pixel px(*this, column, row);
        if (!have_start) start = px(x0, y0);
        const Integrands mid = px(xm, ym), end = px(x1, y1);
        const double w = (y1 - y0) * (1.0 / 6.0);
        moments.mass += w * (start.f + 4 * mid.f + end.f);
        moments.moment_x += w * (start.g + 4 * mid.g + end.g);
        moments.moment_y += w * (y0 * start.f + 4 * ym * mid.f + y1 * end.f);
        moments.moment_2 += w * (start.s + 4 * mid.s + end.s);
        start = end;
        have_start = vertical && !horizontal;
      } else {
        have_start = false;
      }
      if (last) break;
      if (vertical) {
        nx += sx;
        tx = (nx - ax) * idx;
      }
      if (horizontal) {
        ny += sy;
        ty = (ny - ay) * idy;
      }
      x0 = x1;
      y0 = y1;
    }
  }

  /// Mass and moments of the polygon with the given vertices (implicitly closed), counter-clockwise.
  /// \pre the polygon is simple and inside the box.
  /// \param polygon the vertices.
  Density_moments integrate(const std::vector<std::array<double, 2>>& polygon) const {
    Density_moments m;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto& a = polygon[i];
      const auto& b = polygon[(i + 1) % n];
      integrate_segment(a[0], a[1], b[0], b[1], m);
    }
    return m;
  }

 private:
  // Values at (x, y) of F, G and S = Q + y^2 F, where F, G, Q are the integrals of rho, t rho, t^2 rho from 0
  // to x along the row of y. Inside one pixel they are polynomials of degree 1, 2 and 3 in x, hence along a
  // straight piece in y, so Simpson's rule integrates them exactly.
  // floor and ceil for coordinates in the box (>= 0, below 2^31), without a call into libm.
  static double floor_nonnegative(double x) { return double(static_cast<long long>(x)); }
  static double ceil_nonnegative(double x) {
    const double f = double(static_cast<long long>(x));
    return f < x ? f + 1 : f;
  }

  struct Integrands {
    double f = 0, g = 0, s = 0;
  };
  struct Pixel {
    const double* p;
    double r, k;
    Pixel(const Pixel_density& d, int column, int row)
        : p(&d.m_prefix[4 * ((std::size_t(d.m_width) + 1) * std::size_t(row) + std::size_t(column))]),
          r(p[3]),
          k(column) {}
    Integrands operator()(double x, double y) const {
      const double u = x - k;
      Integrands v;
      v.f = p[0] + r * u;
      v.g = p[1] + r * u * (x + k) * 0.5;
      v.s = p[2] + r * u * (x * x + x * k + k * k) * (1.0 / 3.0) + y * y * v.f;
      return v;
    }
  };

  int m_width = 0, m_height = 0;
  // Huge pages: a boundary walk jumps a row (32 (width + 1) bytes) at every horizontal pixel side.
  // per row, per pixel side k = 0..width: F, G, Q at x = k, density of pixel k
  std::vector<double, FeatureRecon::internal::Large_array_allocator<double>> m_prefix;
  double m_total = 0;
  double m_constant = -1;  // the density when every pixel has the same one, else -1
};

}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_PIXEL_DENSITY_H
