// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "io/point_cloud_io.h"

#include "io/featurerecon_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/array.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace FeatureRecon {
namespace io {
namespace {
using K = CGAL::Epick;
using Pwn = std::pair<K::Point_3, K::Vector_3>;
using Point_map = CGAL::First_of_pair_property_map<Pwn>;
using Normal_map = CGAL::Second_of_pair_property_map<Pwn>;
using Pwnc = std::tuple<K::Point_3, K::Vector_3, std::array<unsigned char, 3>>;  // with a colour
using Point_of_tuple = CGAL::Nth_of_tuple_property_map<0, Pwnc>;
using Normal_of_tuple = CGAL::Nth_of_tuple_property_map<1, Pwnc>;
using Color_of_tuple = CGAL::Nth_of_tuple_property_map<2, Pwnc>;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Input_error(path + ": " + what);
}

/// A number of a point-cloud file: the whole token must parse (no "12abc"); inf and nan are refused later
/// with the point's index.
std::string at_line(const std::string& path, std::size_t line) {
  return path + ":" + std::to_string(line) + ": ";
}

/// XYZ: one point per line, `x y z` or `x y z nx ny nz`; every line has the count of the first; blank lines
/// and
/// '#' comments (also indented) are skipped.
void read_xyz(const std::string& path, Point_cloud& c) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  std::string line;
  std::size_t number = 0, columns = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::vector<std::string> t = line_tokens(line);
    if (t.empty()) continue;
    if (columns == 0) {
      if (t.size() != 3 && t.size() != 6)
        throw Input_error(at_line(path, number) +
                          "expected 3 or 6 numbers per line (x y z [nx ny nz]), got " +
                          std::to_string(t.size()));
      columns = t.size();
    } else if (t.size() != columns) {
      throw Input_error(at_line(path, number) + "point " + std::to_string(c.points.size()) + " has " +
                        std::to_string(t.size()) + " numbers, the first point has " +
                        std::to_string(columns));
    }
    std::array<double, 6> v{};
    for (std::size_t k = 0; k < columns; ++k)
      if (!parse_decimal(t[k], v[k]))
        throw Input_error(at_line(path, number) + "'" + t[k] + "' is not a number (point " +
                          std::to_string(c.points.size()) + ")");
    c.points.push_back({v[0], v[1], v[2]});
    c.lines.push_back(number);
    if (columns == 6) c.normals.push_back({v[3], v[4], v[5]});
  }
  if (in.bad()) fail(path, "read error");
}

/// OFF (Geomview): a header keyword [C][N]OFF, the counts `nv nf ne` (on the keyword's line or the next),
/// then nv vertex lines `x y z [nx ny nz] [colour]`; the faces are not needed and not read. The header's
/// count is checked against the file (a truncated file is an error), never trusted for an allocation.
void read_off(const std::string& path, Point_cloud& c) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  std::string line;
  std::size_t number = 0;
  std::vector<std::string> t;
  auto next = [&]() {
    while (std::getline(in, line)) {
      ++number;
      t = line_tokens(line);
      if (!t.empty()) return true;
    }
    if (in.bad()) fail(path, "read error");
    return false;
  };
  if (!next()) fail(path, "empty file (expected an OFF header)");
  std::string keyword = t[0];
  std::string prefix = keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0
                           ? keyword.substr(0, keyword.size() - 3)
                           : std::string("?");
  bool normals = false, colours = false;
  for (const char ch : prefix) {
    if (ch == 'N' && !normals)
      normals = true;
    else if (ch == 'C' && !colours)
      colours = true;
    else {
      throw Input_error(
          at_line(path, number) + "'" + keyword +
          "' is not a supported OFF header (OFF, NOFF, COFF or CNOFF; 4OFF, nOFF, STOFF are not)");
    }
  }
  t.erase(t.begin());
  if (!t.empty() && t[0] == "BINARY")
    throw Input_error(at_line(path, number) + "binary OFF is not supported");
  if (t.empty() && !next()) fail(path, "unexpected end of file (expected the counts 'vertices faces edges')");
  if (t.size() < 2 || t.size() > 3)
    throw Input_error(at_line(path, number) + "expected the counts 'vertices faces [edges]', got " +
                      std::to_string(t.size()) + " fields");
  const char* s = t[0].c_str();
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(s, &end, 10);
  if (t[0][0] == '-' || end == s || *end != '\0' || errno == ERANGE)
    throw Input_error(at_line(path, number) + "'" + t[0] + "' is not a vertex count");
  const std::size_t per_vertex = normals ? 6 : 3;
  c.colors_ignored = colours;
  c.points.reserve(static_cast<std::size_t>(std::min<unsigned long long>(n, 1u << 20)));
  for (unsigned long long i = 0; i < n; ++i) {
    if (!next())
      fail(path, "unexpected end of file after " + std::to_string(i) + " of " + std::to_string(n) +
                     " vertex lines");
    if (t.size() < per_vertex || (!colours && t.size() != per_vertex))
      throw Input_error(at_line(path, number) + "vertex " + std::to_string(i) + " must be " +
                        (normals ? "'x y z nx ny nz'" : "'x y z'") + (colours ? " and a colour" : "") +
                        ", got " + std::to_string(t.size()) + " fields");
    std::array<double, 6> v{};
    for (std::size_t k = 0; k < per_vertex; ++k)
      if (!parse_decimal(t[k], v[k]))
        throw Input_error(at_line(path, number) + "'" + t[k] + "' is not a number (vertex " +
                          std::to_string(i) + ")");
    c.points.push_back({v[0], v[1], v[2]});
    c.lines.push_back(number);
    if (normals) c.normals.push_back({v[3], v[4], v[5]});
  }
}

/// Size in bytes of a PLY scalar type, 0 for an unknown one.
std::size_t ply_type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

/// A binary PLY list count of `size` bytes (unsigned, or signed and >= 0; -1 when negative) in either byte
/// order.
long long ply_list_count(const unsigned char* b, std::size_t size, bool big_endian, bool is_signed) {
  unsigned long long v = 0;
  for (std::size_t k = 0; k < size; ++k)
    v |= static_cast<unsigned long long>(b[big_endian ? k : size - 1 - k]) << (8 * (size - 1 - k));
  if (is_signed && size < 8 && (v >> (8 * size - 1)) != 0) return -1;
  return static_cast<long long>(v);
}

/// The range of a PLY integer type ([low, high]); false for float and double.
bool ply_integer_range(const std::string& type, double& low, double& high) {
  const std::size_t size = ply_type_size(type);
  if (size == 0 || type.find("float") != std::string::npos || type == "double") return false;
  const bool is_unsigned = type[0] == 'u';
  const double span = std::ldexp(1.0, int(8 * size));
  low = is_unsigned ? 0.0 : -span / 2;
  high = is_unsigned ? span - 1 : span / 2 - 1;
  return true;
}

struct Ply_property {
  std::string name;
  std::string type;      // of the value (of each item for a list)
  bool integer = false;  // an integer type, of range [low, high] (ply_integer_range)
  double low = 0, high = 0;
  std::size_t size = 0;        // of the value (of each item for a list)
  std::size_t count_size = 0;  // of a list's count; 0 for a scalar
  bool count_signed = false;
};
struct Ply_element {
  std::string name;
  unsigned long long rows = 0;
  std::vector<Ply_property> properties;
};

/// What would make CGAL misread a PLY file (or crash, or allocate what the file only claims), found before it
/// reads: the vertex element needs properties x, y, z (and nx, ny, nz all or none) of a floating-point type
/// (CGAL's reader crashes on integer coordinates); every element's data must be there as the header declares
/// it: in binary, every list count must fit in the bytes left (a count of 4e9 in an 80-byte file made CGAL
/// allocate 16 GB) and the data must be as long as the header says; in ASCII, every line of an element must
/// hold as many finite numbers as its properties (and list counts) declare (CGAL reads a line too long or too
/// short shifted onto the next rows). Colours are the vertex properties red, green, blue, all three of type
/// uchar (uint8); some of them, or another type, is a problem (they would be dropped without a word). Returns
/// the problem, or "" with `normals` and `colors` set. One pass over the file.
std::string ply_problem(const std::string& path, bool& normals, bool& colors) {
  std::ifstream in(path, std::ios::binary);
  std::string line, format;
  bool header = false;
  std::vector<Ply_element> elements;
  std::map<std::string, std::string> type_of;  // vertex property -> type
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> t = line_tokens(line);
    if (t.empty()) continue;
    if (t[0] == "end_header") {
      header = true;
      break;
    }
    if (t[0] == "format" && t.size() > 1) format = t[1];
    if (t[0] == "element" && t.size() > 2) {
      Ply_element e;
      e.name = t[1];
      char* rest = nullptr;
      errno = 0;
      e.rows = std::strtoull(t[2].c_str(), &rest, 10);
      if (*rest != '\0' || t[2][0] == '-' || errno == ERANGE)
        return "element " + t[1] + " has count '" + t[2] + "'";
      elements.push_back(e);
    }
    if (t[0] == "property" && t.size() > 2) {
      if (elements.empty()) return "a property comes before any element";
      Ply_property q;
      q.name = t.back();
      if (t[1] == "list") {
        if (t.size() != 5)
          return "property list of element " + elements.back().name +
                 " must be 'property list "
                 "COUNT_TYPE ITEM_TYPE NAME'";
        q.count_size = ply_type_size(t[2]);
        q.count_signed = t[2][0] != 'u';
        q.size = ply_type_size(t[3]);
        q.type = t[3];
        q.integer = ply_integer_range(q.type, q.low, q.high);
        if (q.count_size == 0 || t[2] == "float" || t[2] == "float32" || t[2] == "double" ||
            t[2] == "float64")
          return "list " + q.name + " has count type " + t[2] + " (an integer type needed)";
        if (q.size == 0) return "list " + q.name + " has item type " + t[3];
      } else {
        q.size = ply_type_size(t[1]);
        q.type = t[1];
        q.integer = ply_integer_range(q.type, q.low, q.high);
        if (q.size == 0) return "property " + q.name + " has type " + t[1];
      }
      if (elements.back().name == "vertex") type_of[q.name] = t[1];
      elements.back().properties.push_back(q);
    }
  }
  if (!header) return "the header has no end_header line";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"}) {
    const auto it = type_of.find(name);
    if (it == type_of.end()) {
      if (name[0] != 'n') return std::string("the vertex element has no property ") + name;
      continue;
    }
    const std::string& type = it->second;
    if (!(type == "float" || type == "double" || type == "float32" || type == "float64"))
      return std::string("vertex property ") + name + " is " + type +
             ": coordinates and normals must be float or "
             "double";
  }
  const int n = int(type_of.count("nx")) + int(type_of.count("ny")) + int(type_of.count("nz"));
  if (n != 0 && n != 3) return "the vertex element has only some of the normal properties nx, ny, nz";
  normals = n == 3;
  const int c = int(type_of.count("red")) + int(type_of.count("green")) + int(type_of.count("blue"));
  if (c != 0 && c != 3) return "the vertex element has only some of the colour properties red, green, blue";
  for (const char* name : {"red", "green", "blue"})
    if (c == 3 && type_of[name] != "uchar" && type_of[name] != "uint8")
      return std::string("vertex property ") + name + " is " + type_of[name] +
             ": colours must be uchar (0-255)";
  colors = c == 3;
  if (format == "binary_little_endian" || format == "binary_big_endian") {
    const bool big = format == "binary_big_endian";
    const std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    unsigned long long left = static_cast<unsigned long long>(in.tellg() - start);
    in.seekg(start);
    for (const Ply_element& e : elements) {
      bool lists = false;
      unsigned long long row = 0;  // bytes of a row without lists
      for (const Ply_property& q : e.properties) {
        lists = lists || q.count_size > 0;
        row += q.count_size > 0 ? 0 : q.size;
      }
      const std::string rows = e.name == "vertex" ? "vertices" : e.name + " rows";
      auto truncated = [&](unsigned long long i) {
        return "truncated: the data ends in row " + std::to_string(i) + " of " + std::to_string(e.rows) +
               " " + rows;
      };
      if (!lists) {  // one check for the whole element, without overflow
        if (row > 0 && e.rows > left / row)
          return "truncated: " + std::to_string(e.rows) + " " + rows + " of " + std::to_string(row) +
                 " bytes need " +
                 (e.rows > std::numeric_limits<unsigned long long>::max() / row
                      ? std::string("more than 2^64")
                      : std::to_string(e.rows * row)) +
                 " bytes of data, the file has " + std::to_string(left);
        left -= e.rows * row;
        in.seekg(static_cast<std::streamoff>(e.rows * row), std::ios::cur);
        continue;
      }
      unsigned char count[8];
      for (unsigned long long i = 0; i < e.rows; ++i)
        for (const Ply_property& q : e.properties) {
          if (q.count_size == 0) {
            if (left < q.size) return truncated(i);
            left -= q.size;
            // not seekg: that drops the read buffer every time
            in.ignore(static_cast<std::streamsize>(q.size));
            continue;
          }
          if (left < q.count_size || !in.read(reinterpret_cast<char*>(count), std::streamsize(q.count_size)))
            return truncated(i);
          left -= q.count_size;
          const long long items = ply_list_count(count, q.count_size, big, q.count_signed);
          if (items < 0)
            return "element " + e.name + " row " + std::to_string(i) + ": list " + q.name +
                   " has a negative count";
          if (static_cast<unsigned long long>(items) > left / q.size)
            return "element " + e.name + " row " + std::to_string(i) + ": list " + q.name + " claims " +
                   std::to_string(items) + " items, the file has " + std::to_string(left) + " bytes left";
          left -= static_cast<unsigned long long>(items) * q.size;
          in.ignore(static_cast<std::streamsize>(items * static_cast<long long>(q.size)));
        }
    }
    return "";
  }
  if (format != "ascii") return "format '" + format + "' (ascii, binary_little_endian or binary_big_endian)";
  for (const Ply_element& e : elements)
    for (unsigned long long i = 0; i < e.rows; ++i) {
      if (!std::getline(in, line))
        return "unexpected end of file after " + std::to_string(i) + " of " + std::to_string(e.rows) + " " +
               (e.name == "vertex" ? std::string("vertices") : e.name + " rows");
      const std::vector<std::string> t = line_tokens(line);
      const std::string what = e.name + " " + std::to_string(i);
      // Values the header declares for this line: one per scalar, a count and its items per list.
      std::size_t k = 0;
      bool lists = false;
      for (const Ply_property& q : e.properties) {
        std::size_t items = 1;
        if (q.count_size > 0) {
          lists = true;
          double c = 0;
          if (k >= t.size() || t[k].find_first_not_of("0123456789") != std::string::npos ||
              !parse_decimal(t[k], c))
            return what + ": list " + q.name + " has no count (a non-negative integer)";
          if (c > double(t.size() - k - 1))
            return what + " has " + std::to_string(t.size()) + " values, too few for the " + t[k] +
                   " items of its "
                   "list " +
                   q.name;
          items = static_cast<std::size_t>(c);
          ++k;
        }
        for (std::size_t m = 0; m < items; ++m, ++k) {
          double x = 0;
          if (k < t.size() && (!parse_decimal(t[k], x) || !std::isfinite(x)))
            return what + ": '" + t[k] + "' is not a finite number";
          // CGAL casts an ASCII integer to the declared type: a colour of 300 became 44, -1 became 255.
          if (k < t.size() && q.integer && !(x == std::floor(x) && x >= q.low && x <= q.high))
            return what + ": " + q.name + " is " + t[k] + ", not a " + q.type + " (an integer in [" +
                   format_double(q.low) + ", " + format_double(q.high) + "])";
        }
      }
      if (t.size() != k)
        return what + " has " + std::to_string(t.size()) + " values, the header declares " +
               std::to_string(k) + (lists ? "" : " properties");
    }
  return "";
}

/// PLY through CGAL; what CGAL reports on std::cerr, or what ply_problem finds, becomes the reason of an
/// error.
void read_ply(const std::string& path, Point_cloud& c) {
  bool normals = false, colors = false;
  const std::string problem = ply_problem(path, normals, colors);
  if (!problem.empty()) fail(path, "not a readable PLY point cloud (" + problem + ")");
  std::vector<Pwnc> pwn;
  std::ostringstream messages;
  std::streambuf* const saved = std::cerr.rdbuf(messages.rdbuf());
  bool ok = false;
  try {
    std::ifstream in(path, std::ios::binary);
    auto color_reader = [] {  // CGAL takes the handlers as rvalues
      return std::make_tuple(
          Color_of_tuple(), CGAL::Construct_array(), CGAL::IO::PLY_property<unsigned char>("red"),
          CGAL::IO::PLY_property<unsigned char>("green"), CGAL::IO::PLY_property<unsigned char>("blue"));
    };
    auto rows = std::back_inserter(pwn);
    auto points = [] { return CGAL::IO::make_ply_point_reader(Point_of_tuple()); };
    auto normal_reader = [] { return CGAL::IO::make_ply_normal_reader(Normal_of_tuple()); };
    if (normals && colors)
      ok = CGAL::IO::read_PLY_with_properties(in, rows, points(), normal_reader(), color_reader());
    else if (normals)
      ok = CGAL::IO::read_PLY_with_properties(in, rows, points(), normal_reader());
    else if (colors)
      ok = CGAL::IO::read_PLY_with_properties(in, rows, points(), color_reader());
    else
      ok = CGAL::IO::read_PLY_with_properties(in, rows, points());
  } catch (...) {
    std::cerr.rdbuf(saved);
    throw;
  }
  std::cerr.rdbuf(saved);
  if (!ok) {
    std::string reason = messages.str();
    while (!reason.empty() && std::isspace(static_cast<unsigned char>(reason.back()))) reason.pop_back();
    for (char& ch : reason)
      if (ch == '\n') ch = ';';
    fail(path, "not a readable PLY point cloud" + (reason.empty() ? std::string() : " (" + reason + ")"));
  }
  c.points.reserve(pwn.size());
  for (const auto& [p, n, color] : pwn) {
    c.points.push_back({p.x(), p.y(), p.z()});
    if (normals) c.normals.push_back({n.x(), n.y(), n.z()});
    if (colors) c.colors.push_back(color);
  }
}
}  // namespace

Point_cloud read_point_cloud(const std::string& path, bool allow_empty) {
  require_readable_file(path);  // a missing file or a directory says so, whatever its extension
  const std::string ext = file_extension(path);
  if (ext != "ply" && ext != "off" && ext != "xyz")
    fail(path, "unknown point-cloud format '." + ext + "' (expected .ply, .off or .xyz)");
  Point_cloud c;
  if (ext == "ply")
    read_ply(path, c);
  else if (ext == "off")
    read_off(path, c);
  else
    read_xyz(path, c);
  if (c.points.empty() && !allow_empty) fail(path, "no points");
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const auto& p = c.points[i];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
      throw Input_error(c.locate(path, i) + " has a non-finite coordinate");
    if (c.has_normals()) {
      const auto& n = c.normals[i];
      if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])))
        throw Input_error(c.locate(path, i) + " has a normal with a non-finite component");
    }
  }
  return c;
}

void write_point_cloud(const std::string& path, const Point_cloud& cloud,
                       const std::vector<std::size_t>& indices) {
  const std::string ext = file_extension(path);
  if (ext != "ply" && ext != "off" && ext != "xyz")
    throw Input_error(path + ": unknown point-cloud format '." + ext + "' (expected .ply, .off or .xyz)");
  // Written here, not by CGAL's writers: those print 17 significant digits ("0.20710000000000001" for the
  // input's "0.2071"); format_double() prints the shortest that reads back as the same double.
  const bool normals = cloud.has_normals(), colors = cloud.has_colors() && ext == "ply";
  std::ofstream out(path, std::ios::binary);
  std::string text;  // written out in pieces of about 1 MB, not held whole
  const auto flush = [&] {
    out.write(text.data(), std::streamsize(text.size()));
    text.clear();
  };
  if (ext == "ply") {
    text = "ply\nformat ascii 1.0\ncomment Generated by FeatureRecon\nelement vertex " +
           std::to_string(indices.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
    if (normals) text += "property double nx\nproperty double ny\nproperty double nz\n";
    if (colors) text += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    text += "end_header\n";
  } else if (ext == "off") {
    text = std::string(normals ? "NOFF" : "OFF") + "\n" + std::to_string(indices.size()) + " 0 0\n";
  }
  for (const std::size_t i : indices) {
    const auto& p = cloud.points[i];
    text += format_double(p[0]) + ' ' + format_double(p[1]) + ' ' + format_double(p[2]);
    if (normals) {
      const auto& n = cloud.normals[i];
      text += ' ' + format_double(n[0]) + ' ' + format_double(n[1]) + ' ' + format_double(n[2]);
    }
    if (colors)
      for (const unsigned char c : cloud.colors[i]) text += ' ' + std::to_string(unsigned(c));
    text += '\n';
    if (text.size() >= (std::size_t(1) << 20)) flush();
  }
  flush();
  if (!(out && out.flush())) throw Input_error(path + ": cannot write");
}

void estimate_normals(Point_cloud& cloud, unsigned neighbors, const std::function<void(double)>& progress) {
  // Copies of a position share its normal: the fit runs on the distinct positions (a neighbourhood of 18
  // copies of one point has no plane, and the jet fit crashed on it: 30 copies among 500 points). Too few
  // distinct positions for a fit (fewer than 6, or no neighbourhood spanning a plane) keep (0, 0, 1).
  const std::size_t n = cloud.points.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&cloud](std::size_t a, std::size_t b) {
    return cloud.points[a] < cloud.points[b] || (cloud.points[a] == cloud.points[b] && a < b);
  });
  std::vector<std::size_t> first(n);  // each point's first copy (by index)
  for (std::size_t t = 0; t < n; ++t)
    first[order[t]] =
        t > 0 && cloud.points[order[t]] == cloud.points[order[t - 1]] ? first[order[t - 1]] : order[t];
  // The distinct positions in input order (without copies the fit sees the cloud as before, in its order).
  std::vector<std::size_t> position_of(n);  // index of each point's position among the distinct ones
  std::vector<Pwn> pwn;
  for (std::size_t i = 0; i < n; ++i) {
    if (first[i] != i) {
      position_of[i] = position_of[first[i]];
      continue;
    }
    const auto& p = cloud.points[i];
    position_of[i] = pwn.size();
    pwn.push_back({K::Point_3(p[0], p[1], p[2]), K::Vector_3(0, 0, 0)});
  }
  cloud.normals.assign(n, {0, 0, 1});
  if (pwn.size() < 6) return;
  const unsigned k = static_cast<unsigned>(std::min<std::size_t>(neighbors, pwn.size() - 1));
  // The fit reports its fraction done (most of the time: 19 s for 400,000 points), the orientation none.
  const std::function<bool(double)> report = [&progress](double t) {
    if (progress) progress(0.9 * t);
    return true;
  };
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(
      pwn, k, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).callback(report));
  if (progress) progress(0.9);
  // mst_orient_normals reorders the range: orient tuples that remember the indices.
  using Indexed = std::tuple<K::Point_3, K::Vector_3, std::size_t>;
  std::vector<Indexed> indexed;
  indexed.reserve(pwn.size());
  for (std::size_t i = 0; i < pwn.size(); ++i) {
    const K::Vector_3& v = pwn[i].second;  // a fit without a plane (collinear neighbours) can leave NaN
    const bool finite = std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
    indexed.emplace_back(pwn[i].first, finite ? v : K::Vector_3(0, 0, 1), i);
  }
  CGAL::mst_orient_normals(indexed, k,
                           CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Indexed>())
                               .normal_map(CGAL::Nth_of_tuple_property_map<1, Indexed>()));
  std::vector<std::array<double, 3>> normal_of(pwn.size(), {0, 0, 1});
  for (const auto& [p, v, i] : indexed) {
    (void)p;
    const double len = std::sqrt(v.squared_length());
    if (len > 0 && std::isfinite(len)) normal_of[i] = {v.x() / len, v.y() / len, v.z() / len};
  }
  for (std::size_t i = 0; i < n; ++i) cloud.normals[i] = normal_of[position_of[i]];
}

}  // namespace io
}  // namespace FeatureRecon
