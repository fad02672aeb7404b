// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "cli_common.h"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>

#include "../io/featurerecon_io.h"

namespace FeatureRecon {
namespace cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::vector<std::string>& flags,
                     const std::vector<std::string>& valued, std::size_t max_positional) {
  auto known = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      std::string name = a.substr(2), value;
      const std::size_t eq = name.find('=');
      const bool inline_value = eq != std::string::npos;
      if (inline_value) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
      }
      if (m_values.count(name)) throw Usage_error("option --" + name + " given twice");
      if (known(flags, name)) {
        if (inline_value) throw Usage_error("option --" + name + " takes no value");
        m_values[name] = "";
      } else if (known(valued, name)) {
        if (!inline_value) {
          if (i + 1 >= args.size()) throw Usage_error("option --" + name + " needs a value");
          // "--radius --out x": the value was forgotten (a value starting with "--" goes as --radius=--x).
          if (args[i + 1].compare(0, 2, "--") == 0)
            throw Usage_error("option --" + name + " needs a value, got the option '" + args[i + 1] + "'");
          value = args[++i];
        }
        // "--out=" or "--out ''" (an unset shell variable): every valued option needs a value; a file name
        // that is empty was reported as, e.g., "give a file ending in .svg, got ''".
        if (value.empty()) throw Usage_error("option --" + name + " needs a value, got an empty one");
        m_values[name] = value;
      } else {
        throw Usage_error("unknown option '" + a + "'");
      }
    } else {
      if (m_positional.size() >= max_positional) throw Usage_error("unexpected argument '" + a + "'");
      m_positional.push_back(a);
    }
  }
}

std::string Arguments::get(const std::string& name) const {
  const auto it = m_values.find(name);
  if (it == m_values.end()) throw Usage_error("missing required option --" + name);
  return it->second;
}

std::string Arguments::get_or(const std::string& name, const std::string& fallback) const {
  const auto it = m_values.find(name);
  return it == m_values.end() ? fallback : it->second;
}

double Arguments::get_double(const std::string& name) const {
  const std::string s = get(name);
  double x = 0;
  if (!io::parse_decimal(s, x) || !std::isfinite(x))
    throw Usage_error("--" + name + " must be a finite number, got '" + s + "'");
  return x;
}

double Arguments::get_positive_double(const std::string& name) const {
  const double x = get_double(name);
  if (!(x > 0)) throw Usage_error("--" + name + " must be > 0, got '" + get(name) + "'");
  return x;
}

double Arguments::get_scale(const std::string& name) const {
  const double x = get_double(name);
  if (!(x >= 1e-150 && x <= 1e150))
    throw Usage_error("--" + name + " must be a scale in [1e-150, 1e150], got '" + get(name) + "'");
  return x;
}

long long Arguments::get_int(const std::string& name) const {
  const std::string s = get(name);
  char* end = nullptr;
  errno = 0;
  const long long x = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE)
    throw Usage_error("--" + name + " must be an integer, got '" + s + "'");
  return x;
}

Progress::Progress(std::string stage, bool quiet)
    : m_stage(std::move(stage)),
      m_quiet(quiet),
      m_tty(isatty(STDERR_FILENO) != 0),
      m_start(std::chrono::steady_clock::now()),
      m_last(m_start) {}

bool Progress::operator()(double fraction) {
  if (m_quiet) return true;
  if (!m_tty) {
    // Not a terminal: one line when the work starts (not before: input errors come first).
    if (!m_announced) std::fprintf(stderr, "%s ...\n", m_stage.c_str());
    m_announced = true;
    return true;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - m_last < std::chrono::milliseconds(200) && fraction < 1.0) return true;
  m_last = now;
  std::fprintf(stderr, "\r%s: %3d%%", m_stage.c_str(), static_cast<int>(std::lround(100 * fraction)));
  std::fflush(stderr);
  return true;
}

double Progress::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void Progress::done(const std::string& details) {
  if (m_finished) return;
  m_finished = true;
  if (m_quiet) return;
  std::fprintf(stderr, "%s%s: done%s%s%s in %.2f s\n", m_tty ? "\r" : "", m_stage.c_str(),
               details.empty() ? "" : " (", details.c_str(), details.empty() ? "" : ")", seconds());
}

namespace {
/// 1 or 2 when `path` names the process's standard output or error (/dev/stdout, /dev/fd/1,
/// /proc/self/fd/1, and the same for 2), else 0. Such a path, opened anew, is the file behind the descriptor:
/// replaced by a rename (or truncated by an open) it loses what the shell wrote there before and after.
int standard_descriptor(const std::string& path) {
  if (path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1") return 1;
  if (path == "/dev/stderr" || path == "/dev/fd/2" || path == "/proc/self/fd/2") return 2;
  return 0;
}
}  // namespace

Outputs::Outputs(const Arguments& args, const std::vector<std::string>& options) {
  std::map<std::string, std::string> targets;  // resolved path -> option
  for (const std::string& name : options) {
    if (!args.has(name)) continue;
    const std::string path = args.get(name);
    m_targets[name] = path;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
      throw Usage_error("--" + name + ": " + path + " is a directory");
    // Standard output or error is written through its descriptor at commit(); a device, FIFO or the like
    // (/dev/null) is written in place, not replaced.
    if (standard_descriptor(path) != 0 || io::is_special_file(path)) continue;
    // A symbolic link is written through: the file it points to is replaced, in that file's directory.
    const std::string destination = io::write_destination(path);
    if (::lstat(destination.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
      throw Usage_error("--" + name + ": " + path + " is a loop of symbolic links");
    const std::size_t slash = destination.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "."
                            : slash == 0               ? "/"
                                                       : destination.substr(0, slash);
    if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
      throw Usage_error("--" + name + ": the directory " + dir + " of " + path + " does not exist");
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
      throw Usage_error("--" + name + ": cannot write into the directory " + dir + " (" +
                        std::strerror(errno) + ")");
    // The same file may be spelt two ways (v.txt and ./v.txt, a symbolic link): compare resolved paths.
    char resolved[PATH_MAX];
    std::string key = destination;
    if (::realpath(destination.c_str(), resolved) != nullptr)
      key = resolved;
    else if (::realpath(dir.c_str(), resolved) != nullptr)
      key = std::string(resolved) + "/" + destination.substr(slash == std::string::npos ? 0 : slash + 1);
    const auto known = targets.emplace(key, name);
    if (!known.second)
      throw Usage_error("--" + name + ": " + path + " is also written by --" + known.first->second);
  }
  // An output that is one of the inputs (any other argument naming the same existing file) would destroy it.
  for (const auto& [name, path] : m_targets) {
    struct stat out {};
    if (::stat(path.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) continue;
    auto same = [&out](const std::string& other) {
      struct stat in {};
      return ::stat(other.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino;
    };
    // A number given to an option that takes one (--radius 0.6) names no input, whatever files exist; the
    // options that read files are compared whatever their value (an input named 12 stays an input).
    static const std::set<std::string> file_inputs{"points",  "tracks", "distance-matrix", "graph",
                                                   "complex", "input",  "crop-to-tracks"};
    double number = 0;
    for (const auto& [option, value] : args.values())
      if (m_targets.count(option) == 0 &&
          (file_inputs.count(option) > 0 || !io::parse_decimal(value, number)) && same(value))
        throw Usage_error("--" + name + ": " + path + " is also the input --" + option);
    for (const std::string& value : args.positional())
      if (same(value)) throw Usage_error("--" + name + ": " + path + " is also the input " + value);
  }
}

void Outputs::require_extension(const std::string& name, const std::vector<std::string>& extensions,
                                const std::string& what) const {
  const auto it = m_targets.find(name);
  if (it == m_targets.end()) return;
  const std::string e = io::file_extension(it->second);
  if (std::find(extensions.begin(), extensions.end(), e) != extensions.end()) return;
  std::string list;
  for (std::size_t i = 0; i < extensions.size(); ++i)
    list += (i == 0 ? "." : i + 1 == extensions.size() ? " or ." : ", .") + extensions[i];
  throw Usage_error("--" + name + " writes " + what + ": give a file ending in " + list + ", got '" +
                    it->second + "'");
}

namespace {
/// (target, temporary) of every temporary handed out, for name_targets.
std::vector<std::pair<std::string, std::string>>& issued_temporaries() {
  static std::vector<std::pair<std::string, std::string>> issued;
  return issued;
}
}  // namespace

std::FILE* Outputs::summary_stream() const {
  struct stat out {};
  if (::fstat(STDOUT_FILENO, &out) != 0) return stdout;
  for (const auto& target : m_targets) {
    struct stat st {};
    if (::stat(target.second.c_str(), &st) == 0 && st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      return stderr;
  }
  return stdout;
}

std::string Outputs::name_targets(std::string message) {
  for (const auto& [target, temporary] : issued_temporaries())
    for (std::size_t at = message.find(temporary); at != std::string::npos;
         at = message.find(temporary, at + target.size()))
      message.replace(at, temporary.size(), target);
  return message;
}

Outputs::~Outputs() {
  for (const auto& f : m_staged) io::discard_temporary(f.second);
}

std::string Outputs::path(const std::string& name) {
  const auto it = m_targets.find(name);
  if (it == m_targets.end()) throw std::logic_error("Outputs::path: --" + name + " is not a checked output");
  if (const int fd = standard_descriptor(it->second); fd != 0) {  // staged, copied to the descriptor
    for (const auto& f : m_staged)
      if (f.first == it->second) return f.second;
    m_staged.emplace_back(
        it->second, io::temporary_beside(std::string(P_tmpdir) + "/featurerecon-fd" + std::to_string(fd)));
    return m_staged.back().second;
  }
  if (io::is_special_file(it->second)) return it->second;  // written in place
  const std::string destination = io::write_destination(it->second);
  for (const auto& f : m_staged)
    if (f.first == destination) return f.second;
  m_staged.emplace_back(destination, io::temporary_beside(destination));
  issued_temporaries().emplace_back(it->second, m_staged.back().second);
  return m_staged.back().second;
}

void Outputs::commit() {
  // Renames cannot be undone, but they fail only in odd cases (the directory vanished): the writing, which
  // fails for full disks and the like, is over by now.
  for (const auto& f : m_staged) {
    if (const int fd = standard_descriptor(f.first); fd != 0) {
      // Appended where the descriptor stands (after what the shell wrote before), in place.
      std::fflush(fd == 1 ? stdout : stderr);
      std::FILE* in = std::fopen(f.second.c_str(), "rb");
      bool ok = in != nullptr;
      char buffer[1 << 16];
      for (std::size_t n = 0; ok && (n = std::fread(buffer, 1, sizeof buffer, in)) > 0;)
        for (std::size_t done = 0; ok && done < n;) {
          const ssize_t w = ::write(fd, buffer + done, n - done);
          if (w < 0 && errno == EINTR) continue;
          ok = w > 0;
          done += ok ? static_cast<std::size_t>(w) : 0;
        }
      const std::string reason = std::strerror(errno);
      if (in != nullptr) std::fclose(in);
      io::discard_temporary(f.second);
      if (!ok) throw std::runtime_error(f.first + ": cannot write (" + reason + ")");
      continue;
    }
    io::move_into_place(f.second, f.first);
  }
  m_staged.clear();
}

namespace {
/// Length of the valid UTF-8 sequence starting at s[i] (1 to 4), or 0 when the bytes there are not one.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto at = [&s](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char u = at(i);
  std::size_t n = 0;
  unsigned char lo = 0x80,
                hi = 0xBF;  // range of the second byte (no overlong forms, no surrogates, <= U+10FFFF)
  if (u < 0x80) return 1;
  if (u >= 0xC2 && u <= 0xDF)
    n = 2;
  else if (u >= 0xE0 && u <= 0xEF)
    n = 3, lo = u == 0xE0 ? 0xA0 : 0x80, hi = u == 0xED ? 0x9F : 0xBF;
  else if (u >= 0xF0 && u <= 0xF4)
    n = 4, lo = u == 0xF0 ? 0x90 : 0x80, hi = u == 0xF4 ? 0x8F : 0xBF;
  else
    return 0;
  if (i + n > s.size() || at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xBF) return 0;
  return n;
}
}  // namespace

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else if (const std::size_t n = utf8_length(s, i); n > 1) {  // a character beyond ASCII, as it is
      out.append(s, i, n);
      i += n;
      continue;
    } else if (n == 0) {  // a byte that is no UTF-8 (a file name in Latin-1): the replacement character
      out += "\\ufffd";
    } else {
      out += c;
    }
    ++i;
  }
  return out + "\"";
}

std::string json_statistic(double x, Status status) {
  return json_number(status == Status::degenerate_input ? std::nan("") : x);
}

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[64];
  // The shortest of 15, 16 and 17 significant digits that reads back as x (0.6, not 0.59999999999999998).
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

Track_input read_tracks(const std::string& path, bool keep_points) {
  Track_input r;
  const auto read = io::read_track_trips(path, &r.origin);
  r.trips.resize(read.size());
  for (std::size_t t = 0; t < read.size(); ++t)
    for (std::size_t i = 0; i < read[t].size(); ++i) {
      const auto& f = read[t][i];
      r.trips[t].push_back({f[0], f[1], f[2]});
      if (!keep_points) continue;
      r.points.push_back({f[0], f[1]});
      r.at.push_back({static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(i)});
    }
  return r;
}

void warn_few_fixes_per_trip(const char* command, const std::string& path, const Track_input& tracks) {
  // Only for a file (a directory's trips are its files), with at least two trips.
  if (tracks.trips.size() < 2 || tracks.origin.files.empty() || tracks.origin.files[0] != path) return;
  std::size_t fixes = 0;
  for (const auto& trip : tracks.trips) fixes += trip.size();
  if (fixes >= 2 * tracks.trips.size()) return;
  std::fprintf(stderr,
               "featurerecon %s: warning: %s: its %zu fixes make %zu trips, fewer than two a trip (the first "
               "value of each line is its trip id: 'trip_id x y t', or 'trip_id x y' without times). If the "
               "file is one trip of lines 'x y t' (the map-construction benchmark's trips/trip_N.txt), give "
               "its directory\n",
               command, path.c_str(), fixes, tracks.trips.size());
}

void refuse_degree_tracks(const std::string& path, const std::vector<skeleton::Gps_trip>& trips,
                          double median_step) {
  if (!(median_step > 0 && median_step < 0.01)) return;
  for (const skeleton::Gps_trip& trip : trips)
    for (const skeleton::Gps_fix& f : trip)
      if (!(std::abs(f.x) <= 180 && std::abs(f.y) <= 90)) return;
  throw io::Input_error(path + ": the fixes look like longitude and latitude in degrees (median step " +
                        json_number(median_step) +
                        ", all within +-180 and +-90), but the tracks are read in metres: give --lonlat, or "
                        "project them to metres first");
}

skeleton::Transverse_mercator lonlat_projection(const std::vector<Lonlat_source>& sources) {
  std::vector<std::array<double, 2>> all;
  for (const Lonlat_source& source : sources)
    for (std::size_t i = 0; i < source.points->size(); ++i) {
      const double lon = (*source.points)[i][0], lat = (*source.points)[i][1];
      if (!(lon >= -180 && lon <= 180 && lat >= -90 && lat <= 90))
        throw io::Input_error(source.locate(i) + ": --lonlat: (" + io::format_double(lon) + ", " +
                              io::format_double(lat) +
                              ") is not a longitude in [-180, 180] and a latitude in [-90, 90]");
      all.push_back((*source.points)[i]);
    }
  try {
    return skeleton::local_transverse_mercator(all);
  } catch (const std::invalid_argument& e) {
    const std::string what = std::string(e.what()).substr(std::string("local_transverse_mercator: ").size());
    // The projection numbers the points of all the files together ("point N (longitude ..."): name the file
    // and the line instead.
    std::size_t index = 0;
    if (std::sscanf(what.c_str(), "point %zu ", &index) == 1)
      for (const Lonlat_source& source : sources) {
        if (index < source.points->size())
          throw io::Input_error(source.locate(index) + ": --lonlat: " + what.substr(what.find(' ', 6) + 1));
        index -= source.points->size();
      }
    std::string files;  // the files given (an option not given has no name)
    for (const Lonlat_source& source : sources)
      if (!source.file.empty()) files += (files.empty() ? "" : ", ") + source.file;
    throw io::Input_error(files + ": --lonlat: " + what);
  }
}

std::string name_option_flags(const std::string& message) {
  // The option fields that commands set from a flag of another name (fields of Skeleton_options,
  // Road_map_options, Gps_trace_options, Embedding_options and Synthetic_city_options).
  static const std::pair<const char*, const char*> flags[] = {
      {"max_triangles", "--max-triangles"},
      {"sample_spacing", "--sample-spacing"},
      {"max_link_gap", "--link-gap"},
      {"heading_tolerance", "--heading-tolerance"},
      {"min_relative_density", "--min-density"},
      {"min_lateral_density", "--min-lateral-density"},
      {"density_radius", "--density-radius"},
      {"density_heading_tolerance", "--density-heading-tolerance"},
      {"segment_support", "--segment-support"},
      {"segment_turn_tolerance", "--segment-turn-tolerance"},
      {"min_straight_confirmed_fraction", "--straight-confirmed"},
      {"min_confirmed_fraction", "--min-confirmed"},
      {"stand_down_path_factor", "--stand-down-path"},
      {"quiet_end_fixes", "--quiet-ends"},
      {"local_support_fixes", "--local-support"},
      {"min_local_support", "--min-local-support"},
      {"merge_distance", "--merge"},
      {"branch_merge_distance", "--branch-merge"},
      {"repair_distance", "--repair"},
      {"prune_height", "--prune"},
      {"level_width", "--level-width"},
      {"max_gap", "--max-gap"},
      {"smoothing_iterations", "--smoothing"},
      // Synthetic_city_options (synthetic-city)
      {"sampling_interval", "--interval"},
      {"block_width", "--block-width"},
      {"block_height", "--block-height"},
      {"trip_bias", "--bias"},
      {"missing_streets", "--missing"},
      {"lane_offset", "--lane-offset"},
  };
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string named;
  for (const auto& [field, flag] : flags) {
    const std::string f = field;
    bool found = false;
    for (std::size_t at = message.find(f); at != std::string::npos && !found; at = message.find(f, at + 1))
      found = (at == 0 || !word(message[at - 1])) &&
              (at + f.size() == message.size() || !word(message[at + f.size()]));
    if (found) named += (named.empty() ? "" : ", ") + f + " is " + flag;
  }
  return named.empty() ? message : message + " (on the command line: " + named + ")";
}

}  // namespace cli
}  // namespace FeatureRecon
