// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "featurerecon_io.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <regex>

namespace FeatureRecon {
namespace io {
namespace {

std::string where(const std::string& path, std::size_t line) {
  return path + ":" + std::to_string(line) + ": ";
}

double parse_double(const std::string& t, const std::string& path, std::size_t line, const char* what) {
  double x = 0;
  if (!parse_decimal(t, x))
    throw Input_error(where(path, line) + "'" + t + "' is not a number (" + what + ")");
  if (!std::isfinite(x)) throw Input_error(where(path, line) + what + " is not finite ('" + t + "')");
  return x;
}

unsigned long long parse_index(const std::string& t, const std::string& path, std::size_t line,
                               const char* what) {
  const char* s = t.c_str();
  char* end = nullptr;
  errno = 0;
  if (t.empty() || t[0] == '-' || t[0] == '+')
    throw Input_error(where(path, line) + "'" + t + "' is not a non-negative integer (" + what + ")");
  const unsigned long long x = std::strtoull(s, &end, 10);
  if (end == s || *end != '\0' || errno == ERANGE)
    throw Input_error(where(path, line) + "'" + t + "' is not a non-negative integer (" + what + ")");
  return x;
}

std::ifstream open_input(const std::string& path) {
  require_readable_file(path);
  std::ifstream in(path);
  if (!in) throw Input_error(path + ": cannot open for reading");
  return in;
}

/// std::getline that counts lines and drops a UTF-8 byte-order mark (some editors write one) from the first:
/// it made the first trip id another trip's, and the first vertex id "not a number". Stripped from the line
/// read, not skipped in the stream: a pipe (`<(command)`, /dev/stdin) can neither seek back nor always put
/// bytes back.
bool read_line(std::istream& in, std::string& line, std::size_t& number) {
  if (!std::getline(in, line)) return false;
  if (++number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
  return true;
}

/// After a read loop: a failure that is not the end of the file (an I/O error) is an error, not a short file.
void check_read(const std::ifstream& in, const std::string& path) {
  if (in.bad()) throw Input_error(path + ": read error");
}

/// Calls row(tokens, line number) for every line with tokens of a whitespace-separated file ('#' comments).
template <class Row>
void for_each_token_row(const std::string& path, Row row) {
  std::ifstream in = open_input(path);
  std::string line;
  std::size_t number = 0;
  std::vector<std::string> t;
  while (read_line(in, line, number)) {
    line_tokens(line, t);
    if (!t.empty()) row(t, number);
  }
  check_read(in, path);
}

}  // namespace

Point_file read_points(const std::string& path, const std::string& row, const std::string& value) {
  Point_file pf;
  for_each_token_row(path, [&](const std::vector<std::string>& t, std::size_t number) {
    if (pf.dimension == 0) pf.dimension = t.size();
    if (t.size() != pf.dimension)
      throw Input_error(where(path, number) + row + " has " + std::to_string(t.size()) + " " + value +
                        "s, the first " + row + " has " + std::to_string(pf.dimension));
    for (const std::string& s : t) pf.coordinates.push_back(parse_double(s, path, number, value.c_str()));
    pf.lines.push_back(number);
  });
  return pf;
}

Complex_file read_complex(const std::string& path) {
  std::ifstream in = open_input(path);
  Complex_file cf;
  std::string line;
  std::size_t number = 0;
  auto next = [&](std::vector<std::string>& t) {
    while (read_line(in, line, number)) {
      t = line_tokens(line);
      if (!t.empty()) return true;
    }
    check_read(in, path);
    return false;
  };
  std::vector<std::string> t;
  if (!next(t)) throw Input_error(path + ": empty file (expected a header line 'n m')");
  if (t.size() != 2) throw Input_error(where(path, number) + "header must be 'n m' (two integers)");
  const unsigned long long n = parse_index(t[0], path, number, "number of vertices");
  const unsigned long long m = parse_index(t[1], path, number, "number of simplices");
  if (n >= std::numeric_limits<skeleton::Vertex_index>::max())
    throw Input_error(where(path, number) + "too many vertices (" + t[0] + ")");
  cf.simplices_listed = m;
  // The header is not trusted for the allocation (a corrupt count would fail as bad_alloc): the vertex lines
  // grow the vectors.
  const std::size_t reserve = static_cast<std::size_t>(std::min<unsigned long long>(n, 1u << 20));
  cf.positions.reserve(reserve);
  cf.values.reserve(reserve);
  for (unsigned long long i = 0; i < n; ++i) {
    if (!next(t))
      throw Input_error(path + ": unexpected end of file after " + std::to_string(i) + " of " +
                        std::to_string(n) + " vertex lines");
    if (t.size() != 4)
      throw Input_error(where(path, number) + "vertex " + std::to_string(i) +
                        " must be 'x y z f' (4 numbers), got " + std::to_string(t.size()));
    cf.positions.push_back({parse_double(t[0], path, number, "x"), parse_double(t[1], path, number, "y"),
                            parse_double(t[2], path, number, "z")});
    cf.values.push_back(parse_double(t[3], path, number, "f"));
  }
  std::vector<skeleton::Edge> edges;
  std::vector<skeleton::Triangle> triangles;
  for (unsigned long long i = 0; i < m; ++i) {
    if (!next(t))
      throw Input_error(path + ": unexpected end of file after " + std::to_string(i) + " of " +
                        std::to_string(m) + " simplex lines");
    if (t.size() != 2 && t.size() != 3)
      throw Input_error(where(path, number) + "simplex " + std::to_string(i) +
                        " must list 2 or 3 vertex indices, got " + std::to_string(t.size()));
    std::array<skeleton::Vertex_index, 3> v{};
    for (std::size_t c = 0; c < t.size(); ++c) {
      const unsigned long long x = parse_index(t[c], path, number, "vertex index");
      if (x >= n)
        throw Input_error(where(path, number) + "vertex index " + t[c] + " out of range [0, " +
                          std::to_string(n) + ")");
      v[c] = static_cast<skeleton::Vertex_index>(x);
    }
    if (v[0] == v[1] || (t.size() == 3 && (v[1] == v[2] || v[0] == v[2])))
      throw Input_error(where(path, number) + "simplex " + std::to_string(i) + " repeats a vertex");
    if (t.size() == 2)
      edges.push_back({v[0], v[1]});
    else
      triangles.push_back({v[0], v[1], v[2]});
  }
  if (next(t))
    throw Input_error(where(path, number) + "unexpected content after the " + std::to_string(m) +
                      " simplices");
  cf.complex = skeleton::make_simplicial_complex_2(n, std::move(edges), std::move(triangles));
  return cf;
}

namespace {
std::vector<std::string> split_csv(const std::string& line) {
  // Fields are trimmed, not stripped: "1 00" stays two tokens and is refused as a number, not read as 100.
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string field =
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t first = field.find_first_not_of(" \t\r");
    out.push_back(first == std::string::npos
                      ? std::string()
                      : field.substr(first, field.find_last_not_of(" \t\r") - first + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}
}  // namespace

namespace {
/// Calls row(fields, line number) for every non-blank line of a comma-separated file ('#' comments).
template <class Row>
void for_each_csv_row(const std::string& path, Row row) {
  std::ifstream in = open_input(path);
  std::string line;
  std::size_t number = 0;
  while (read_line(in, line, number)) {
    const std::string body = line.substr(0, line.find('#'));
    if (body.find_first_not_of(" \t\r") == std::string::npos) continue;
    row(split_csv(body), number);
  }
  check_read(in, path);
}
}  // namespace

namespace {
/// A vertex id of a map file: an integer (a decimal with a zero fraction, as some tools write them, is
/// accepted when it is exact).
long long parse_id(const std::string& t, const std::string& path, std::size_t line,
                   const std::string& what = "vertex id") {
  const char* s = t.c_str();
  char* end = nullptr;
  errno = 0;
  const long long id = std::strtoll(s, &end, 10);
  if (end != s && *end == '\0') {
    if (errno == ERANGE) throw Input_error(where(path, line) + what + " '" + t + "' out of range");
    return id;
  }
  const double x = parse_double(t, path, line, what.c_str());
  if (x != std::floor(x)) throw Input_error(where(path, line) + what + " '" + t + "' is not an integer");
  // From 2^53 on, doubles skip integers: 9007199254740993.0 reads as 2^53, another id.
  if (std::fabs(x) >= 9007199254740992.0)
    throw Input_error(
        where(path, line) + what + " '" + t +
        "' is at least 2^53 in decimal notation, which cannot be read exactly (write the integer "
        "without a point or exponent)");
  return static_cast<long long>(x);
}
}  // namespace

Map_file read_map(const std::string& vertices_path, const std::string& edges_path) {
  Map_file m;
  std::map<long long, std::uint32_t> index;
  for_each_csv_row(vertices_path, [&](const std::vector<std::string>& t, std::size_t number) {
    if (t.size() != 3)
      throw Input_error(where(vertices_path, number) + "expected 'id,x,y', got " + std::to_string(t.size()) +
                        " fields");
    const long long id = parse_id(t[0], vertices_path, number);
    if (index.count(id)) throw Input_error(where(vertices_path, number) + "vertex id " + t[0] + " repeated");
    index[id] = static_cast<std::uint32_t>(m.positions.size());
    m.positions.push_back(
        {parse_double(t[1], vertices_path, number, "x"), parse_double(t[2], vertices_path, number, "y")});
    m.vertex_lines.push_back(number);
  });
  std::map<long long, std::size_t> edge_ids;  // id -> its line
  for_each_csv_row(edges_path, [&](const std::vector<std::string>& t, std::size_t number) {
    if (t.size() < 3 || t.size() > 4)
      throw Input_error(where(edges_path, number) + "expected 'id,v1,v2[,flag]', got " +
                        std::to_string(t.size()) + " fields");
    // A repeated edge id is most often two files joined into one.
    const auto [first, added] = edge_ids.emplace(parse_id(t[0], edges_path, number, "edge id"), number);
    if (!added)
      throw Input_error(where(edges_path, number) + "edge id " + t[0] + " repeated (first on line " +
                        std::to_string(first->second) + ")");
    std::array<std::uint32_t, 2> e{};
    for (int k = 0; k < 2; ++k) {
      const long long id = parse_id(t[1 + k], edges_path, number);
      const auto it = index.find(id);
      if (it == index.end()) throw Input_error(where(edges_path, number) + "unknown vertex id " + t[1 + k]);
      e[k] = it->second;
    }
    if (t.size() == 4)
      (void)parse_id(t[3], edges_path, number, "edge flag");  // read and ignored, but an integer
    if (e[0] == e[1] && m.self_loops++ == 0) m.first_self_loop_line = number;
    if (e[0] != e[1] && m.positions[e[0]] == m.positions[e[1]] && m.zero_length_edges++ == 0)
      m.first_zero_length_line = number;
    m.edges.push_back(e);
  });
  return m;
}

std::string Track_origin::where(std::size_t trip, std::size_t fix) const {
  return files[trip] + ":" + std::to_string(lines[trip][fix]);
}

std::string Track_origin::locate(const std::string& message) const {
  static const std::regex fix_of_trip("trip ([0-9]+), fix ([0-9]+)");
  std::smatch m;
  if (!std::regex_search(message, m, fix_of_trip)) return message;
  const unsigned long long t = std::stoull(m[1].str()), i = std::stoull(m[2].str());
  if (t >= trip_ids.size() || i >= lines[t].size()) return message;
  return message + " [" + where(t, i) + ", trip id '" + trip_ids[t] + "']";
}

namespace {
/// File names in natural order: runs of digits compare as numbers (trip_2 before trip_10; leading zeros
/// ignored, then the shorter run first), the rest byte by byte; equal under that, byte order decides.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      std::size_t ei = i, ej = j;
      while (ei < a.size() && digit(a[ei])) ++ei;
      while (ej < b.size() && digit(b[ej])) ++ej;
      std::size_t si = i, sj = j;  // the significant digits
      while (si + 1 < ei && a[si] == '0') ++si;
      while (sj + 1 < ej && b[sj] == '0') ++sj;
      if (ei - si != ej - sj) return ei - si < ej - sj;
      const int c = a.compare(si, ei - si, b, sj, ej - sj);
      if (c != 0) return c < 0;
      i = ei;
      j = ej;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  if (i < a.size() || j < b.size()) return j < b.size() && i == a.size();
  return a < b;
}

/// The fix of a tracks line whose x is token `first` (0: 'x y [t]' in a trip file; 1: 'trip_id x y [t]'). The
/// lines of a file all carry a time or none, as its first (`timed`: -1 before it); no time: the line number.
std::array<double, 3> read_fix(const std::vector<std::string>& t, std::size_t first, int& timed,
                               const std::string& file, std::size_t number) {
  const char* layout = first == 0 ? "x y" : "trip_id x y";
  if (t.size() < first + 2 || t.size() > first + 3)
    throw Input_error(where(file, number) + "expected '" + layout + " [t]'" +
                      (first == 0 ? " (a directory of tracks holds one trip per file)" : "") + ", got " +
                      std::to_string(t.size()) + " values");
  const bool has_time = t.size() == first + 3;
  if (timed < 0) timed = has_time ? 1 : 0;
  if (has_time != (timed == 1))
    throw Input_error(where(file, number) +
                      (timed ? std::string("no time t, but the first line has one ('") + layout + " t')"
                             : std::string("a time t, but the first line has none ('") + layout + "')"));
  return {parse_double(t[first], file, number, "x"), parse_double(t[first + 1], file, number, "y"),
          has_time ? parse_double(t[first + 2], file, number, "t") : static_cast<double>(number)};
}

/// The names of the `*.txt` regular files of a directory (`prefix`: its path ending in '/'), in natural
/// order.
std::vector<std::string> trip_files(const std::string& prefix) {
  const std::unique_ptr<DIR, int (*)(DIR*)> d(::opendir(prefix.c_str()), &::closedir);
  if (!d) throw Input_error(prefix + ": cannot read the directory (" + std::strerror(errno) + ")");
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(d.get())) {
    const std::string name = e->d_name;
    if (name.size() <= 4 || name[0] == '.' || file_extension(name) != "txt") continue;
    // A trip file that cannot be read (a broken link) is an error, not a trip left out without a word; an
    // entry gone since it was listed is left out.
    struct stat st {};
    const std::string file = prefix + name;
    if (::stat(file.c_str(), &st) != 0) {
      const std::string reason = std::strerror(errno);
      if (::lstat(file.c_str(), &st) != 0 && errno == ENOENT) continue;
      throw Input_error(file + ": cannot read this trip file (" + reason + ")");
    }
    if (S_ISREG(st.st_mode)) names.push_back(name);
  }
  std::sort(names.begin(), names.end(), natural_less);
  return names;
}
}  // namespace

/// What the tracks file `path` may be instead when its first row `t` (tokens, comments cut) fails to read
/// (appended to the error): gzip-compressed (the row starts with its two magic bytes), comma- or
/// semicolon-separated (a token holds one), or with a header line that lacks its '#' (x or y of the row is
/// not a number). Empty when none of these.
std::string tracks_hint(const std::vector<std::string>& t, const std::string& path) {
  if (!t.empty() && t[0].size() >= 2 && static_cast<unsigned char>(t[0][0]) == 0x1f &&
      static_cast<unsigned char>(t[0][1]) == 0x8b)
    return " (the file is gzip-compressed: decompress it first, e.g. 'gzip -dc " + path + " > tracks.txt')";
  for (const std::string& token : t)
    if (token.find(',') != std::string::npos || token.find(';') != std::string::npos)
      return " (values are separated by spaces or tabs, not by commas or semicolons)";
  double x = 0;
  for (std::size_t k = 1; k < t.size() && k < 3; ++k)
    if (!parse_decimal(t[k], x)) return " (a header line must begin with '#')";
  return "";
}

std::vector<std::vector<std::array<double, 3>>> read_track_trips(const std::string& path,
                                                                 Track_origin* origin) {
  std::vector<std::vector<std::array<double, 3>>> trips;
  struct stat st {};
  if (!path.empty() && ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    // One trip per file: lines 'x y [t]'.
    const std::string directory = path.back() == '/' ? path : path + "/";
    const std::vector<std::string> names = trip_files(directory);
    if (names.empty())
      throw Input_error(path +
                        ": a directory of tracks holds one trip per '*.txt' file (lines 'x y [t]'), "
                        "but it has none");
    for (const std::string& name : names) {
      const std::string file = directory + name;
      trips.emplace_back();
      auto& trip = trips.back();
      if (origin != nullptr) {
        origin->trip_ids.push_back(name.substr(0, name.size() - 4));
        origin->files.push_back(file);
        origin->lines.emplace_back();
      }
      int timed = -1;
      for_each_token_row(file, [&](const std::vector<std::string>& t, std::size_t number) {
        trip.push_back(read_fix(t, 0, timed, file, number));
        if (origin != nullptr) origin->lines.back().push_back(number);
      });
      if (origin != nullptr) origin->timed.push_back(timed == 1);  // each file decides for itself
    }
    return trips;
  }
  std::map<std::string, std::size_t> index;
  auto last = index.end();
  int timed = -1;  // whether the lines carry a time: decided by the first line, the same for all
  bool first_row = true;
  for_each_token_row(path, [&](const std::vector<std::string>& t, std::size_t number) {
    std::array<double, 3> fix;
    if (first_row) {  // the first row that fails says what the file may be instead
      first_row = false;
      try {
        fix = read_fix(t, 1, timed, path, number);
      } catch (const Input_error& e) {
        throw Input_error(e.what() + tracks_hint(t, path));
      }
    } else {
      fix = read_fix(t, 1, timed, path, number);
    }
    // A trip's lines usually follow each other: the last one's entry is tried first, and the map is only
    // searched (and a node made) on a change.
    if (last == index.end() || last->first != t[0]) {
      last = index.find(t[0]);
      if (last == index.end()) last = index.emplace(t[0], trips.size()).first;
    }
    if (last->second == trips.size()) {
      trips.emplace_back();
      if (origin != nullptr) {
        origin->trip_ids.push_back(t[0]);
        origin->files.push_back(path);
        origin->lines.emplace_back();
      }
    }
    if (origin != nullptr) origin->lines[last->second].push_back(number);
    trips[last->second].push_back(fix);
  });
  if (origin != nullptr) origin->timed.assign(trips.size(), timed == 1);  // the first line decides for all
  return trips;
}

void write_map(const std::string& vertices_path, const std::string& edges_path,
               const std::vector<std::array<double, 2>>& positions,
               const std::vector<std::array<std::uint32_t, 2>>& edges) {
  std::string v, e;
  char buf[128];
  for (std::size_t i = 0; i < positions.size(); ++i)
    v += std::to_string(i) + "," + format_double(positions[i][0]) + "," + format_double(positions[i][1]) +
         "\n";
  for (std::size_t i = 0; i < edges.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%zu,%u,%u\n", i, edges[i][0], edges[i][1]);
    e += buf;
  }
  write_text_file(vertices_path, v);
  write_text_file(edges_path, e);
}

namespace {
std::string system_reason() { return std::strerror(errno); }
}  // namespace

void require_readable_file(const std::string& path) {
  if (path.empty()) throw Input_error("an empty file name was given for reading");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw Input_error(path + ": cannot open for reading (" + system_reason() + ")");
  if (S_ISDIR(st.st_mode)) throw Input_error(path + ": is a directory, not a file");
}

std::string format_double(double x) {
  char buf[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (digits == 17 || std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

namespace {
// Temporaries not yet moved into place, for remove_temporaries_now(): fixed slots, so that a signal handler
// can read them while the program is anywhere (a slot is filled before it is counted, and emptied before
// reuse).
constexpr std::size_t temporary_slots = 64;
char registered[temporary_slots][PATH_MAX];
volatile std::sig_atomic_t slot_used[temporary_slots] = {};

void register_temporary(const std::string& name) {
  if (name.size() >= PATH_MAX) return;
  for (std::size_t i = 0; i < temporary_slots; ++i)
    if (!slot_used[i]) {
      std::memcpy(registered[i], name.c_str(), name.size() + 1);
      slot_used[i] = 1;
      return;
    }
}

void forget_temporary(const std::string& name) {
  for (std::size_t i = 0; i < temporary_slots; ++i)
    if (slot_used[i] && name == registered[i]) slot_used[i] = 0;
}
}  // namespace

void remove_temporaries_now() {
  for (std::size_t i = 0; i < temporary_slots; ++i)
    if (slot_used[i]) ::unlink(registered[i]);
}

std::string temporary_beside(const std::string& path) {
  if (path.empty()) throw std::runtime_error("an output file name is empty");
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string extension = file_extension(name);
  const std::string suffix = extension.empty() ? "" : "." + extension;
  std::string pattern = dir + "." + name + ".XXXXXX" + suffix;
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemps(buffer.data(), static_cast<int>(suffix.size()));
  if (fd < 0) throw std::runtime_error(path + ": cannot open for writing (" + system_reason() + ")");
  register_temporary(buffer.data());
  // mkstemps creates the file private (0600): give it the permissions a new file gets (0666 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  return std::string(buffer.data());
}

void discard_temporary(const std::string& temporary) {
  std::remove(temporary.c_str());
  forget_temporary(temporary);
}

void move_into_place(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = system_reason();
    discard_temporary(temporary);
    throw std::runtime_error(path + ": cannot write (" + reason + ")");
  }
  forget_temporary(temporary);
}

bool is_special_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

std::string write_destination(const std::string& path) {
  struct stat st {};
  char resolved[PATH_MAX];
  if (!(::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode))) return path;
  if (::realpath(path.c_str(), resolved) != nullptr) return resolved;
  // A dangling link: follow it by hand (relative targets from the link's directory), so that the file it
  // names is created and the link stays (it was replaced by a regular file).
  std::string at = path;
  for (int hops = 0; hops < 40 && ::lstat(at.c_str(), &st) == 0 && S_ISLNK(st.st_mode); ++hops) {
    char target[PATH_MAX];
    const ssize_t n = ::readlink(at.c_str(), target, sizeof target - 1);
    if (n < 0) return path;
    target[n] = '\0';
    const std::size_t slash = at.find_last_of('/');
    at = target[0] == '/' || slash == std::string::npos ? std::string(target)
                                                        : at.substr(0, slash + 1) + target;
  }
  return at;
}

void write_text_file(const std::string& path, const std::string& text) {
  // A device, FIFO or the like is written in place; a symbolic link is written through.
  const bool in_place = is_special_file(path);
  const std::string destination = in_place ? path : write_destination(path);
  const std::string tmp = in_place ? path : temporary_beside(destination);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    out.close();
    if (!out) {
      const std::string reason = system_reason();
      if (!in_place) discard_temporary(tmp);
      throw std::runtime_error(path + ": write failed (" + reason + ")");
    }
  }
  if (!in_place) move_into_place(tmp, destination);
}

void write_complex(const std::string& path, const skeleton::Simplicial_complex_2& k,
                   const std::vector<std::array<double, 3>>& positions, const std::vector<double>& values) {
  if (positions.size() != k.number_of_vertices || values.size() != k.number_of_vertices)
    throw std::invalid_argument("write_complex: positions and values must have one entry per vertex");
  // Edges implied by a triangle are not listed.
  std::vector<char> implied(k.edges.size(), 0);
  for (const skeleton::Triangle& t : k.triangles)
    for (const skeleton::Edge& e :
         {skeleton::Edge{t[0], t[1]}, skeleton::Edge{t[1], t[2]}, skeleton::Edge{t[0], t[2]}})
      implied[static_cast<std::size_t>(k.find_edge(e[0], e[1]))] = 1;
  std::size_t free_edges = 0;
  for (char c : implied) free_edges += c ? 0 : 1;
  std::string s;
  s.reserve(64 * k.number_of_vertices + 24 * (free_edges + k.triangles.size()));
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu %zu\n", k.number_of_vertices, free_edges + k.triangles.size());
  s += buf;
  for (std::size_t v = 0; v < k.number_of_vertices; ++v) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g\n", positions[v][0], positions[v][1],
                  positions[v][2], values[v]);
    s += buf;
  }
  for (std::size_t e = 0; e < k.edges.size(); ++e)
    if (!implied[e]) {
      std::snprintf(buf, sizeof buf, "%u %u\n", k.edges[e][0], k.edges[e][1]);
      s += buf;
    }
  for (const skeleton::Triangle& t : k.triangles) {
    std::snprintf(buf, sizeof buf, "%u %u %u\n", t[0], t[1], t[2]);
    s += buf;
  }
  write_text_file(path, s);
}

bool parse_decimal(const std::string& token, double& value) {
  const char* s = token.c_str();
  char* end = nullptr;
  value = std::strtod(s, &end);
  return end != s && *end == '\0' &&
         token.find_first_of("xX") == std::string::npos;  // strtod also reads 0x10
}

void line_tokens(const std::string& line, std::vector<std::string>& out) {
  // The whitespace of the "C" locale's isspace, which `std::istream >> std::string` used to split on (reading
  // two million tracks lines took half the time without the string stream). The strings already in
  // `out` are reused.
  auto space = [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
  };
  const std::size_t end = std::min(line.find('#'), line.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < end;) {
    if (space(line[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < end && !space(line[j])) ++j;
    if (count < out.size())
      out[count].assign(line, i, j - i);
    else
      out.emplace_back(line, i, j - i);
    ++count;
    i = j;
  }
  out.resize(count);
}

std::vector<std::string> line_tokens(const std::string& line) {
  std::vector<std::string> out;
  line_tokens(line, out);
  return out;
}

std::string file_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace io
}  // namespace FeatureRecon
