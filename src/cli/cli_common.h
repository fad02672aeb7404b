// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_CLI_CLI_COMMON_H
#define FEATURERECON_SRC_CLI_CLI_COMMON_H

// Argument parsing and progress display shared by the subcommands of `featurerecon`.

#include <FeatureRecon/config.h>
#include <FeatureRecon/skeleton/geographic.h>
#include <FeatureRecon/skeleton/gps_traces.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../io/featurerecon_io.h"

namespace FeatureRecon {
namespace cli {

/// A bad command line: printed with a pointer to --help, exit status 2.
class Usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parsed `--name value` and `--flag` arguments of one subcommand.
class Arguments {
 public:
  /// \param flags options without a value; \param valued options with one value.
  Arguments(const std::vector<std::string>& args, const std::vector<std::string>& flags,
            const std::vector<std::string>& valued, std::size_t max_positional = 0);
  bool has(const std::string& name) const { return m_values.count(name) != 0; }
  std::string get(const std::string& name) const;  ///< throws Usage_error if missing
  std::string get_or(const std::string& name, const std::string& fallback) const;
  double get_double(const std::string& name) const;           ///< finite number
  double get_positive_double(const std::string& name) const;  ///< finite number > 0
  /// A scale (sigma) in [1e-150, 1e150], the range the library takes (its squares stay normal doubles).
  double get_scale(const std::string& name) const;
  long long get_int(const std::string& name) const;
  const std::vector<std::string>& positional() const { return m_positional; }
  const std::map<std::string, std::string>& values() const { return m_values; }  ///< option -> value

 private:
  std::map<std::string, std::string> m_values;
  std::vector<std::string> m_positional;
};

/// Progress of one stage on standard error: a live percentage on a terminal, and a closing line with the
/// elapsed time (unless quiet). Usable as a Progress_callback.
class Progress {
 public:
  Progress(std::string stage, bool quiet);
  bool operator()(double fraction);
  /// Prints "stage: done (details) in S s".
  void done(const std::string& details = "");
  double seconds() const;

 private:
  std::string m_stage;
  bool m_quiet, m_tty, m_finished = false, m_announced = false;
  std::chrono::steady_clock::time_point m_start, m_last;
};

/// The files one command writes, made to appear together. The constructor checks every given output option
/// before any work is done (a file name, not a directory, in an existing writable directory, no file named
/// twice; Usage_error naming the option otherwise). path() hands out a new temporary file beside the target
/// (same extension) for the writers; commit() renames them all into place once everything is written.
/// Destroyed without commit() (an error), it removes the temporaries: a failed run leaves neither partial
/// output nor a new vertices file beside an old edges file, and earlier files of the same names stay as they
/// were. A symbolic link is written through (the file it points to is replaced, the link stays); a device,
/// FIFO or the like
/// (/dev/null, /dev/stdout) is written in place, without a temporary. An output that is also an input
/// (another argument naming the same existing file) is refused.
class Outputs {
 public:
  Outputs(const Arguments& args, const std::vector<std::string>& options);
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  ~Outputs();
  bool has(const std::string& name) const { return m_targets.count(name) != 0; }
  /// The target file of an output option (for messages and JSON).
  const std::string& target(const std::string& name) const { return m_targets.at(name); }
  /// The temporary file to write the output of option `name` to (created on the first call).
  std::string path(const std::string& name);
  void commit();
  /// Refuses, before any work, an output of option `name` (when given) whose extension is none of
  /// `extensions` (lower case, without the dot); `what` names the kind of file in the message.
  void require_extension(const std::string& name, const std::vector<std::string>& extensions,
                         const std::string& what) const;
  /// Where the command prints its summary: standard output, unless an output is written there (`--out
  /// /dev/stdout`, a pipe or device standard output is): then standard error, so that the summary does not
  /// end up inside the output.
  std::FILE* summary_stream() const;
  /// `message` with every temporary file handed out by path() (in this run) replaced by its target, so that
  /// an error raised while writing names the file the user asked for.
  static std::string name_targets(std::string message);

 private:
  std::map<std::string, std::string> m_targets;               // option -> target file
  std::vector<std::pair<std::string, std::string>> m_staged;  // (target, temporary)
};

/// A file of --lonlat positions: its name ("" for an option not given), its points ({longitude, latitude} in
/// degrees) and the line of each point in it; for points from several files (a directory of tracks), `where`
/// gives "file:line" of point i instead.
struct Lonlat_source {
  std::string file;
  const std::vector<std::array<double, 2>>* points;
  const std::vector<std::size_t>* lines;
  std::function<std::string(std::size_t)> where = nullptr;
  std::string locate(std::size_t i) const {
    return where ? where(i) : file + ":" + std::to_string((*lines)[i]);
  }
};

/// --lonlat: the points of each source are checked (Input_error naming the file, the line and the values) and
/// the transverse Mercator centred on all of them is returned (Input_error naming the file and line of a
/// point too far from its central meridian: they span too much for one projection). The caller projects them.
skeleton::Transverse_mercator lonlat_projection(const std::vector<Lonlat_source>& sources);

/// --lonlat: every fix (a type with x and y, as skeleton::Gps_fix) of the trips from degrees to metres.
template <class Trips>
void project_trips(Trips& trips, const skeleton::Transverse_mercator& projection) {
  for (auto& trip : trips)
    for (auto& fix : trip) {
      const auto xy = projection.forward(fix.x, fix.y);
      fix.x = xy[0];
      fix.y = xy[1];
    }
}

/// GPS tracks as read by io::read_track_trips() (a file of lines 'trip_id x y t' or a directory of one-trip
/// files), with where each fix was read: messages name its file and line.
struct Track_input {
  std::vector<skeleton::Gps_trip> trips;
  io::Track_origin origin;
  std::vector<std::array<double, 2>> points;     ///< every fix's (x, y) as read, trip by trip (if kept)
  std::vector<std::array<std::uint32_t, 2>> at;  ///< (trip, fix) of each point (if kept)
  /// The points as a --lonlat source named `name`.
  Lonlat_source lonlat_source(const std::string& name) const {
    return {name, &points, nullptr, [this](std::size_t i) { return origin.where(at[i][0], at[i][1]); }};
  }
};
/// With `keep_points` false, `points` and `at` stay empty (no --lonlat source: they take 24 bytes a fix).
Track_input read_tracks(const std::string& path, bool keep_points = true);

/// Warns (standard error, "featurerecon COMMAND: warning: ...") when the tracks file `path` (not a directory)
/// holds several trips with fewer than two fixes a trip on average: most lines began with a trip id of their
/// own, as when one trip file of lines 'x y t' (the map-construction benchmark's trips/trip_N.txt) is given
/// instead of its directory.
void warn_few_fixes_per_trip(const char* command, const std::string& path, const Track_input& tracks);

/// Refuses (io::Input_error naming `path`) trips read in metres whose fixes look like longitude and latitude
/// in degrees: a median step between consecutive fixes of a trip below 0.01 with every fix within +-180 and
/// +-90. `median_step` is median_gps_step(trips).
void refuse_degree_tracks(const std::string& path, const std::vector<skeleton::Gps_trip>& trips,
                          double median_step);

/// Formats a double for JSON (17 significant digits; non-finite as null).
std::string json_number(double x);

/// A spacing statistic for JSON: null when its set is degenerate (too few samples, no area), where it is
/// undefined.
std::string json_statistic(double x, Status status);

/// Quotes a string for JSON (", \ and control characters escaped).
std::string json_string(const std::string& s);

/// `message` (an error of the library, which names its options by their fields) followed by the command-line
/// flag of every option field it names, e.g. "... (on the command line: sample_spacing is --sample-spacing)".
std::string name_option_flags(const std::string& message);

}  // namespace cli
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_CLI_CLI_COMMON_H
