// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <unordered_map>

#include "featurerecon_io.h"

namespace FeatureRecon {
namespace io {
namespace {

std::string pixel(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string size_text(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::array<double, 3> parse_colour(const std::string& c) {
  if (c == "black") return {0, 0, 0};
  if (c == "white") return {1, 1, 1};
  if (c.size() == 7 && c[0] == '#') {
    std::array<double, 3> out{};
    for (int k = 0; k < 3; ++k) {
      const std::string hex = c.substr(1 + 2 * k, 2);
      char* end = nullptr;
      const long v = std::strtol(hex.c_str(), &end, 16);
      if (*end != '\0') break;
      out[k] = v / 255.0;
      if (k == 2) return out;
    }
  }
  throw std::invalid_argument("Picture: colour '" + c + "' is not #rrggbb, black or white");
}

/// Distance from p to the segment ab.
double segment_distance(double px, double py, const std::array<double, 2>& a,
                        const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - a[0]) * dx + (py - a[1]) * dy) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(px - (a[0] + t * dx), py - (a[1] + t * dy));
}

bool all_finite(const std::vector<std::array<double, 2>>& points) {
  return std::all_of(points.begin(), points.end(), [](const std::array<double, 2>& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]);
  });
}

}  // namespace

bool is_picture_file(const std::string& path) {
  const std::string e = file_extension(path);
  return e == "svg" || e == "png" || e == "jpg" || e == "jpeg" || e == "pgm" || e == "ppm";
}

Picture::Picture(double width, double height) : m_width(width), m_height(height) {
  if (!(width > 0 && height > 0 && width <= 65536 && height <= 65536))
    throw std::invalid_argument("Picture: the page must be between 0 and 65536 pixels wide and high");
}

void Picture::disc(double x, double y, double radius, const std::string& colour) {
  parse_colour(colour);
  m_shapes.push_back({Kind::disc, {{x, y}}, radius, colour});
}

void Picture::line(double x1, double y1, double x2, double y2, double width, const std::string& colour) {
  parse_colour(colour);
  m_shapes.push_back({Kind::line, {{x1, y1}, {x2, y2}}, width, colour});
}

void Picture::polyline(const std::vector<std::array<double, 2>>& points, double width,
                       const std::string& colour) {
  parse_colour(colour);
  m_shapes.push_back({Kind::polyline, points, width, colour});
}

std::string Picture::svg() const {
  std::ostringstream os;
  // The viewBox makes the picture scale, not crop, where it is shown at another size.
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << pixel(m_width) << "\" height=\""
     << pixel(m_height) << "\" viewBox=\"0 0 " << pixel(m_width) << " " << pixel(m_height)
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const Shape& s : m_shapes) {
    if (!all_finite(s.points))
      continue;  // a point at infinity (coordinates beyond the largest double): not drawn
    switch (s.kind) {
      case Kind::disc:
        os << "<circle cx=\"" << pixel(s.points[0][0]) << "\" cy=\"" << pixel(s.points[0][1]) << "\" r=\""
           << size_text(s.size) << "\" fill=\"" << s.colour << "\"/>\n";
        break;
      case Kind::line:
        os << "<line x1=\"" << pixel(s.points[0][0]) << "\" y1=\"" << pixel(s.points[0][1]) << "\" x2=\""
           << pixel(s.points[1][0]) << "\" y2=\"" << pixel(s.points[1][1]) << "\" stroke=\"" << s.colour
           << "\" stroke-width=\"" << size_text(s.size) << "\"/>\n";
        break;
      case Kind::polyline:
        os << "<polyline fill=\"none\" stroke-width=\"" << size_text(s.size) << "\" stroke=\"" << s.colour
           << "\" points=\"";
        for (const auto& p : s.points) os << pixel(p[0]) << "," << pixel(p[1]) << " ";
        os << "\"/>\n";
        break;
    }
  }
  os << "</svg>\n";
  return os.str();
}

Image Picture::raster() const {
  Image out;
  out.width = static_cast<int>(std::ceil(m_width));
  out.height = static_cast<int>(std::ceil(m_height));
  out.channels = 3;
  const std::size_t w = static_cast<std::size_t>(out.width), h = static_cast<std::size_t>(out.height);
  std::vector<float> rgb(3 * w * h, 1.0f);
  auto blend = [&](std::size_t index, const std::array<double, 3>& c, double alpha) {
    for (int k = 0; k < 3; ++k)
      rgb[3 * index + k] = static_cast<float>(rgb[3 * index + k] * (1 - alpha) + c[k] * alpha);
  };
  // Calls visit(pixel index, coverage) for the pixels within `reach` of the box [x0, x1] x [y0, y1].
  auto for_pixels = [&](double x0, double y0, double x1, double y1, double reach, auto&& visit) {
    const long c0 = std::max(0L, static_cast<long>(std::floor(x0 - reach)));
    const long c1 = std::min(static_cast<long>(w) - 1, static_cast<long>(std::ceil(x1 + reach)));
    const long r0 = std::max(0L, static_cast<long>(std::floor(y0 - reach)));
    const long r1 = std::min(static_cast<long>(h) - 1, static_cast<long>(std::ceil(y1 + reach)));
    for (long r = r0; r <= r1; ++r)
      for (long c = c0; c <= c1; ++c)
        visit(static_cast<std::size_t>(r) * w + static_cast<std::size_t>(c), c + 0.5, r + 0.5);
  };
  // Coverage of a pixel whose centre lies at distance d from the skeleton of a shape of half-width `half`.
  auto coverage = [](double d, double half) { return std::min(1.0, std::max(0.0, half + 0.5 - d)); };
  for (const Shape& s : m_shapes) {
    const std::array<double, 3> colour = parse_colour(s.colour);
    if (!all_finite(s.points)) continue;  // not drawn, as in the SVG text
    if (s.kind == Kind::disc) {
      const auto& p = s.points[0];
      for_pixels(p[0], p[1], p[0], p[1], s.size + 1, [&](std::size_t i, double x, double y) {
        const double a = coverage(std::hypot(x - p[0], y - p[1]), s.size);
        if (a > 0) blend(i, colour, a);
      });
      continue;
    }
    // Lines and polylines: the largest coverage over the segments, so that joints are drawn once.
    std::unordered_map<std::size_t, double> cover;
    const double half = 0.5 * s.size;
    for (std::size_t k = 0; k + 1 < s.points.size(); ++k) {
      const auto& a = s.points[k];
      const auto& b = s.points[k + 1];
      for_pixels(std::min(a[0], b[0]), std::min(a[1], b[1]), std::max(a[0], b[0]), std::max(a[1], b[1]),
                 half + 1, [&](std::size_t i, double x, double y) {
                   const double c = coverage(segment_distance(x, y, a, b), half);
                   if (c > 0) {
                     double& slot = cover[i];
                     slot = std::max(slot, c);
                   }
                 });
    }
    for (const auto& [i, a] : cover) blend(i, colour, a);  // one blend per pixel: the order does not matter
  }
  out.data.resize(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i)
    out.data[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::min(1.0f, std::max(0.0f, rgb[i]))));
  return out;
}

void Picture::write(const std::string& path) const {
  const std::string e = file_extension(path);
  if (e == "svg") return write_text_file(path, svg());
  if (is_picture_file(path)) return write_image(path, raster());
  throw Input_error(path + ": unknown picture format '." + e +
                    "' (expected .svg, .png, .jpg, .jpeg, .pgm or .ppm)");
}

}  // namespace io
}  // namespace FeatureRecon
