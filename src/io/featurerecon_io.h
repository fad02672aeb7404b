// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_IO_FEATURERECON_IO_H
#define FEATURERECON_SRC_IO_FEATURERECON_IO_H

// File formats of the featurerecon program (compiled once in src/, never needed by the headers).

#include <FeatureRecon/skeleton/Simplicial_complex_2.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace FeatureRecon {
namespace io {

/// A malformed or unreadable input file; the message names the file and the line.
class Input_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Points of any dimension, one per line, whitespace-separated coordinates; '#' starts a comment,
/// blank lines are skipped. Throws Input_error naming the line of a bad number, a non-finite value or a
/// line whose dimension differs from the first point's. `row` and `value` name them in messages (a distance
/// matrix: "row", "distance").
struct Point_file {
  std::size_t dimension = 0;
  std::vector<double> coordinates;  ///< row-major, dimension per point
  std::vector<std::size_t> lines;   ///< source line of each point
  std::size_t size() const { return dimension == 0 ? 0 : coordinates.size() / dimension; }
};
Point_file read_points(const std::string& path, const std::string& row = "point",
                       const std::string& value = "coordinate");

/// The complex exchange format: first line `n m`; then n lines `x y z f`; then m lines of 2 or 3
/// zero-based vertex indices (edges and triangles; the edges of a triangle are implied). '#' comments
/// and blank lines are allowed anywhere.
struct Complex_file {
  skeleton::Simplicial_complex_2 complex;        ///< canonical
  std::vector<std::array<double, 3>> positions;  ///< x y z of each vertex
  std::vector<double> values;                    ///< f of each vertex
  std::size_t simplices_listed = 0;              ///< m of the header
};
Complex_file read_complex(const std::string& path);

/// Writes the exchange format atomically (a temporary file renamed into place): edges that are a face of
/// a listed triangle are not listed (they are implied). Throws std::runtime_error if it cannot write.
void write_complex(const std::string& path, const skeleton::Simplicial_complex_2& k,
                   const std::vector<std::array<double, 3>>& positions, const std::vector<double>& values);

/// A road map in the map-construction benchmark's format: a vertex file of lines `id,x,y` and an edge file
/// of lines `id,v1,v2[,flag]` (v1, v2 are vertex ids). Returns positions and edges by vertex index.
/// Throws Input_error naming the file and line of a malformed line, a repeated vertex or edge id, or an
/// unknown vertex id.
struct Map_file {
  std::vector<std::array<double, 2>> positions;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::size_t self_loops = 0;  ///< edges from a vertex to itself (kept in `edges`; they have no length)
  std::size_t first_self_loop_line = 0;  ///< line of the first of them in the edge file (0: none)
  /// edges between two vertices at one position (kept in `edges`; they have no length either)
  std::size_t zero_length_edges = 0;
  std::size_t first_zero_length_line = 0;  ///< line of the first of them in the edge file (0: none)
  std::vector<std::size_t> vertex_lines;   ///< the line of each vertex in the vertex file
};
Map_file read_map(const std::string& vertices_path, const std::string& edges_path);

/// Where the trips of read_track_trips() come from: each trip's id and file, and the line of each of its
/// fixes.
struct Track_origin {
  std::vector<std::string> trip_ids;
  std::vector<std::string> files;  ///< the file each trip was read from (the path given, or a file in it)
  std::vector<std::vector<std::size_t>> lines;
  /// Per trip, whether its fixes were read with times (else a fix's time is its line number).
  std::vector<char> timed;
  /// "file:line" of fix `fix` of trip `trip`.
  std::string where(std::size_t trip, std::size_t fix) const;
  /// Appends to a message that names "trip T, fix I" (indices as read) the file, line and trip id; else
  /// returns it.
  std::string locate(const std::string& message) const;
};

/// GPS tracks grouped by trip, each a list of (x, y, t) in file order. `path` is either
/// - a file of lines `trip_id x y t` (whitespace-separated, '#' comments): trips in order of first
///   appearance, trip ids any token; or
/// - a directory with one trip per `*.txt` file (the map-construction benchmark's trips/trip_N.txt), lines
///   `x y t`: trips in the natural order of the file names (trip_2 before trip_10), each file's name without
///   `.txt` its trip id, an empty file a trip without fixes. Other files in it are not read; a `*.txt` entry
///   that cannot be read (a broken link) is an error.
/// A missing t (every line of a file without it) is the line number (file order). With `origin`, also where
/// each fix came from. Throws Input_error naming the file and line of a malformed line, or a directory
/// without `*.txt` files.
std::vector<std::vector<std::array<double, 3>>> read_track_trips(const std::string& path,
                                                                 Track_origin* origin = nullptr);

/// Writes a road map in the benchmark's format (vertices `id,x,y`, edges `id,v1,v2`), each file atomically.
void write_map(const std::string& vertices_path, const std::string& edges_path,
               const std::vector<std::array<double, 2>>& positions,
               const std::vector<std::array<std::uint32_t, 2>>& edges);

/// The extension of a file name, lower case, without the dot ("" when there is none).
std::string file_extension(const std::string& path);

/// The whitespace-separated tokens of a text line, without its '#' comment (a trailing CR is whitespace).
std::vector<std::string> line_tokens(const std::string& line);
/// The same tokens written into `out` (its strings reused: no allocation per line once they are long enough).
void line_tokens(const std::string& line, std::vector<std::string>& out);

/// Reads `token` as a decimal number (what strtod takes, except hexadecimal such as 0x10); true when all of
/// it is one. The value may be infinite or NaN ("inf", "nan"): callers that need finite numbers check.
bool parse_decimal(const std::string& token, double& value);

/// Writes `text` to `path` atomically: to a new temporary file beside it, renamed into place (an existing
/// file of any other name is never touched). Throws std::runtime_error with the system's reason if it cannot.
void write_text_file(const std::string& path, const std::string& text);

/// Throws Input_error unless `path` exists and is not a directory (std::ifstream opens a directory on Linux
/// and then reads nothing, which would pass for an empty file).
void require_readable_file(const std::string& path);

/// The shortest of 15, 16 or 17 significant digits that reads back as exactly `x` ("447123.456", not
/// "447123.45600000001"): coordinates keep every bit at any scale.
std::string format_double(double x);

/// Creates a new, empty file beside `path` (same directory, a unique hidden name ending in the same
/// extension, so that writers which choose the format by extension still do) and returns its name. Throws
/// std::runtime_error with the system's reason if the directory does not take it. The name is registered for
/// remove_temporaries_now() until move_into_place() or discard_temporary() takes it.
std::string temporary_beside(const std::string& path);

/// Renames `temporary` to `path` (same file system, atomic); on failure removes the temporary and throws.
void move_into_place(const std::string& temporary, const std::string& path);

/// Removes a temporary that will not be moved into place.
void discard_temporary(const std::string& temporary);

/// Removes every registered temporary; async-signal-safe (for a SIGINT or SIGTERM handler).
void remove_temporaries_now();

/// True when `path` exists and is not a regular file (after symbolic links): a device such as /dev/null, a
/// FIFO, a socket, /dev/stdout. Such outputs are written in place: renaming a temporary over them would
/// replace them.
bool is_special_file(const std::string& path);

/// Where a write to `path` should land: the file a symbolic link points to (so that the link stays a link),
/// else `path` itself.
std::string write_destination(const std::string& path);

}  // namespace io
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_IO_FEATURERECON_IO_H
