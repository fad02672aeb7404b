// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/featurerecon_io.h"
#include "io/point_cloud_io.h"
#include "io/scratch_file.h"
#include "io/skeleton_io.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using FeatureRecon::test::thrown_message;
using FeatureRecon::test::throws_with;

using namespace FeatureRecon;

namespace {
using test::scratch_path;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = scratch_path(name);
  std::ofstream(path) << text;
  return path;
}

void expect_error(const std::string& text, const std::string& part, bool complex = true) {
  const std::string path = write_temp("bad_input.txt", text);
  EXPECT_TRUE(throws_with<io::Input_error>(
      [&] {
        if (complex)
          io::read_complex(path);
        else
          io::read_points(path);
      },
      part));
}
}  // namespace

TEST(ExchangeFormat, RoundTripKeepsComplexAndValues) {
  const std::string path = write_temp("c.txt",
                                      "# a triangle with a dangling edge\n4 2\n0 0 0 0.5\n1 0 0 1\n0 1 0 2\n"
                                      "2 2 0 -1e-3\n\n0 1 2  # triangle\n2 3\n");
  const io::Complex_file c = io::read_complex(path);
  EXPECT_EQ(c.complex.number_of_vertices, 4u);
  EXPECT_EQ(c.complex.number_of_edges(), 4u);  // 3 implied + 1
  EXPECT_EQ(c.complex.number_of_triangles(), 1u);
  EXPECT_EQ(c.values, (std::vector<double>{0.5, 1, 2, -1e-3}));
  const std::string out = scratch_path("roundtrip.txt");
  io::write_complex(out, c.complex, c.positions, c.values);
  const io::Complex_file d = io::read_complex(out);
  EXPECT_EQ(d.complex.edges, c.complex.edges);
  EXPECT_EQ(d.complex.triangles, c.complex.triangles);
  EXPECT_EQ(d.values, c.values);
  EXPECT_EQ(d.positions, c.positions);
  EXPECT_EQ(d.simplices_listed, 2u);
}

TEST(ExchangeFormat, ErrorsNameTheLine) {
  expect_error("", "empty file");
  expect_error("2\n", ":1: header");
  expect_error("2 1\n0 0 0 0\n0 0 0\n0 1\n", ":3: vertex 1 must be 'x y z f'");
  expect_error("2 1\n0 0 0 0\n0 0 0 nan\n0 1\n", ":3: f is not finite");
  expect_error("2 1\n0 0 0 0\n0 0 0 x\n0 1\n", ":3: 'x' is not a number");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n0 2\n", ":4: vertex index 2 out of range");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n0 -1\n", ":4: '-1' is not a non-negative integer");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n1 1\n", ":4: simplex 0 repeats a vertex");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n0 1 1 0\n", ":4: simplex 0 must list 2 or 3");
  expect_error("2 2\n0 0 0 0\n0 0 0 1\n0 1\n", "unexpected end of file after 1 of 2 simplex lines");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n0 1\n1 0\n", ":5: unexpected content");
  EXPECT_THROW(io::read_complex("/nonexistent/file"), io::Input_error);
  // An empty name is said to be one (the message began ': cannot open').
  EXPECT_EQ(thrown_message<io::Input_error>([] { io::read_complex(""); }),
            "an empty file name was given for reading");
}

// line_tokens() splits on the whitespace of `std::istream >> std::string` in the "C" locale (space, \t, \n,
// \v, \f, \r) and drops everything from the first '#': the string stream it replaced is the oracle, on random
// lines of those bytes, '#', letters and a byte above 127. The overload that fills a vector reuses it: a line
// with fewer tokens leaves no stale ones.
TEST(LineTokens, SplitAsTheStringStreamDid) {
  auto by_stream = [](const std::string& line) {
    std::vector<std::string> out;
    std::istringstream is(line.substr(0, line.find('#')));
    std::string t;
    while (is >> t) out.push_back(t);
    return out;
  };
  EXPECT_EQ(io::line_tokens(" a\tbb\v\fc\r\n# d e"), (std::vector<std::string>{"a", "bb", "c"}));
  EXPECT_TRUE(io::line_tokens("").empty());
  EXPECT_TRUE(io::line_tokens(" \t\r").empty());
  EXPECT_TRUE(io::line_tokens("#a b").empty());
  EXPECT_EQ(io::line_tokens("x#y z"), (std::vector<std::string>{"x"}));
  const std::string alphabet = std::string(" \t\n\v\f\r#ab\xE9") + '\0';
  std::mt19937_64 rng(7);
  std::vector<std::string> reused;
  for (int trial = 0; trial < 20000; ++trial) {
    std::string line(rng() % 12, ' ');
    for (char& c : line) c = alphabet[rng() % alphabet.size()];
    EXPECT_EQ(io::line_tokens(line), by_stream(line)) << "trial " << trial;
    io::line_tokens(line, reused);
    EXPECT_EQ(reused, by_stream(line)) << "trial " << trial;
  }
}

TEST(PointFile, AnyDimensionWithComments) {
  const io::Point_file p = io::read_points(write_temp("p.txt", "# header\n1 2 3 4 5\n\n6 7 8 9 10 # tail\n"));
  EXPECT_EQ(p.dimension, 5u);
  EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(p.lines, (std::vector<std::size_t>{2, 4}));
  EXPECT_EQ(io::read_points(write_temp("e.txt", "# nothing\n")).size(), 0u);
  expect_error("1 2\n3 4 5\n", ":2: point has 3 coordinates", false);
  expect_error("1 2\n3 inf\n", ":2: coordinate is not finite", false);
  expect_error("1 2\n3 4e\n", ":2: '4e' is not a number", false);
}

TEST(ScratchFiles, AreRemovedWhenTheTestEnds) {
  const std::string path = write_temp("scratch.txt", "x\n");
  ASSERT_TRUE(std::ifstream(path).good());
  auto& remover = test::Scratch_file_remover::instance();
  ASSERT_EQ(remover.pending().size(), 1u);
  // It is registered with gtest (Release hands back a listener only if it is in the list).
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  ASSERT_EQ(listeners.Release(&remover), &remover);
  listeners.Append(&remover);
  remover.OnTestEnd(*::testing::UnitTest::GetInstance()->current_test_info());  // what gtest calls at the end
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_TRUE(remover.pending().empty());
}

TEST(FormatDouble, ShortestThatReadsBackExactly) {
  EXPECT_EQ(io::format_double(447123.456), "447123.456");
  EXPECT_EQ(io::format_double(0.1), "0.1");
  EXPECT_EQ(io::format_double(-6.020081e-5), "-6.020081e-05");
  EXPECT_EQ(io::format_double(1e300), "1e+300");
  EXPECT_EQ(io::format_double(0.0), "0");
  EXPECT_EQ(io::format_double(0.1 + 0.2),
            "0.30000000000000004");  // 17 digits when 15 and 16 do not read back
  // Any finite double reads back as itself (random bit patterns, fixed seed).
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    const std::string s = io::format_double(x);
    ASSERT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
    ASSERT_LE(s.size(), 24u) << s;
  }
}

TEST(MapFile, RoundTripKeepsEveryBit) {
  const std::vector<std::array<double, 2>> positions{
      {447123.456, 4636005.123456789}, {1e-9, -3.0e-7}, {1e22, 0.0}};
  const std::vector<std::array<std::uint32_t, 2>> edges{{0, 1}, {1, 2}};
  const std::string v = scratch_path("map_v.txt"), e = scratch_path("map_e.txt");
  io::write_map(v, e, positions, edges);
  const io::Map_file m = io::read_map(v, e);
  EXPECT_EQ(m.positions, positions);
  EXPECT_EQ(m.edges, edges);
}

TEST(MapFile, IdsAreIntegers) {
  // Ids above 2^53 stay apart; an integral decimal is the integer; a fraction is refused with its line.
  const std::string v = write_temp("ids_v.txt", "9007199254740993,0,0\n9007199254740992,1,0\n7.0,2,0\n");
  const io::Map_file m =
      io::read_map(v, write_temp("ids_e.txt", "0,9007199254740992,9007199254740993\n1,7,9007199254740992\n"));
  EXPECT_EQ(m.edges, (std::vector<std::array<std::uint32_t, 2>>{{1, 0}, {2, 1}}));
  auto error_of = [&](const std::string& edges) {
    return thrown_message<io::Input_error>([&] { io::read_map(v, write_temp("ids_bad.txt", edges)); });
  };
  EXPECT_TRUE(contains(error_of("0,7,1.9\n"), "ids_bad.txt:1: vertex id '1.9' is not an integer"));
  EXPECT_TRUE(contains(error_of("\n0,7,8\n"), "ids_bad.txt:2: unknown vertex id 8"));
  EXPECT_TRUE(contains(error_of("0,7,99999999999999999999\n"), "out of range"));
}

TEST(InputFiles, DirectoriesAndMixedTracksAreRefused) {
  const std::string dir = scratch_path("a_directory");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  EXPECT_TRUE(throws_with<io::Input_error>([&] { io::read_points(dir); }, "is a directory"));
  ::rmdir(dir.c_str());
  // A track file gives a time on every line or on none.
  EXPECT_EQ(io::read_track_trips(write_temp("t_none.txt", "a 0 0\na 1 0\nb 5 5\n")).size(), 2u);
  EXPECT_TRUE(throws_with<io::Input_error>(
      [&] { io::read_track_trips(write_temp("t_mixed.txt", "a 0 0 1\na 1 0 2\nb 5 5\n")); },
      "t_mixed.txt:3: no time t"));
}

// A directory holds one trip per *.txt file (the map-construction benchmark's trips/trip_N.txt): trips in the
// natural order of the names, each file's stem its id, lines 'x y [t]' (no t: the line number), other entries
// not read; an empty file is a trip without fixes.
TEST(InputFiles, ADirectoryOfTripFiles) {
  const std::string dir = scratch_path("trips");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  struct Remove_all {  // whatever a failure leaves inside
    std::string path;
    ~Remove_all() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  } remove_all{dir};
  std::vector<std::string> made;
  auto put = [&](const std::string& name, const std::string& text) {
    made.push_back(dir + "/" + name);
    std::ofstream(made.back()) << text;
  };
  put("trip_10.txt", "0 0 5\n1 0 6\n");
  put("trip_2.txt", "# x y\n3 3\n\n4 4\n");
  put("Trip_1.TXT", "7 7 1\r\n");
  put("empty.txt", "");
  put("notes.md", "not a trip\n");
  put(".hidden.txt", "not a trip either\n");
  const std::string sub = dir + "/sub.txt";
  ASSERT_EQ(::mkdir(sub.c_str(), 0700), 0);
  io::Track_origin origin;
  const auto trips = io::read_track_trips(dir + "/", &origin);
  EXPECT_EQ(origin.trip_ids, (std::vector<std::string>{"Trip_1", "empty", "trip_2", "trip_10"}));
  ASSERT_EQ(trips.size(), 4u);
  EXPECT_EQ(trips[0], (std::vector<std::array<double, 3>>{{7, 7, 1}}));
  EXPECT_TRUE(trips[1].empty());
  EXPECT_EQ(trips[2], (std::vector<std::array<double, 3>>{{3, 3, 2}, {4, 4, 4}}));
  EXPECT_EQ(trips[3], (std::vector<std::array<double, 3>>{{0, 0, 5}, {1, 0, 6}}));
  EXPECT_EQ(origin.files[3], dir + "/trip_10.txt");
  EXPECT_EQ(origin.where(2, 1), dir + "/trip_2.txt:4");
  EXPECT_EQ(origin.locate("f: trip 3, fix 1 is bad"),
            "f: trip 3, fix 1 is bad [" + dir + "/trip_10.txt:2, trip id 'trip_10']");
  auto error_of = [&] { return thrown_message<io::Input_error>([&] { io::read_track_trips(dir); }); };
  put("trip_3.txt", "1 2 3 4\n");  // the one-file format inside a directory
  EXPECT_TRUE(contains(error_of(), "trip_3.txt:1: expected 'x y [t]'"));
  put("trip_3.txt", "1 2 3\n1 2\n");
  EXPECT_TRUE(contains(error_of(), "trip_3.txt:2: no time t"));
  std::remove(made.back().c_str());
  made.pop_back();
  made.push_back(dir + "/trip_4.txt");  // a broken link is named, not left out
  ASSERT_EQ(::symlink((dir + "/nowhere").c_str(), made.back().c_str()), 0);
  EXPECT_TRUE(contains(error_of(), "trip_4.txt: cannot read this trip file"));
  for (const std::string& f : made) std::remove(f.c_str());
  ::rmdir(sub.c_str());
  // A directory without trip files.
  EXPECT_TRUE(contains(error_of(), "holds one trip per '*.txt' file (lines 'x y [t]'), but it has none"));
  ::rmdir(dir.c_str());
}

TEST(WriteTextFile, UsesATemporaryOfItsOwn) {
  // The old fixed name PATH.tmp belonged to the user.
  const std::string path = scratch_path("written.txt");
  const std::string user_tmp = write_temp("written.txt.tmp", "precious\n");
  io::write_text_file(path, "new\n");
  std::string line;
  std::getline(std::ifstream(path), line);
  EXPECT_EQ(line, "new");
  std::getline(std::ifstream(user_tmp), line);
  EXPECT_EQ(line, "precious");
  // A temporary keeps the extension (writers that choose the format by extension still do), and fails with
  // the reason.
  const std::string tmp = io::temporary_beside(scratch_path("picture.png"));
  EXPECT_EQ(io::file_extension(tmp), "png");
  const std::string name = tmp.substr(tmp.find_last_of('/') + 1);
  EXPECT_EQ(name[0], '.') << tmp;
  EXPECT_TRUE(contains(name, "picture.png.")) << tmp;
  std::remove(tmp.c_str());
  EXPECT_TRUE(throws_with<std::runtime_error>([&] { io::write_text_file("/nonexistent_dir/x.txt", "x"); },
                                              "No such file or directory"));
}

TEST(SkeletonPicture, PageResolvesTheFeatureSize) {
  // 3 pixels per feature size, the longer side within [1000, 4000]; without a usable length, 1000.
  EXPECT_EQ(io::skeleton_picture_long_side(400, 1), 1200.0);
  EXPECT_EQ(io::skeleton_picture_long_side(2000, 1.5), 4000.0);  // 2000 units at 1.5: exactly the cap
  EXPECT_EQ(io::skeleton_picture_long_side(2000, 1), 4000.0);
  EXPECT_EQ(io::skeleton_picture_long_side(300, 1), 1000.0);
  EXPECT_EQ(io::skeleton_picture_long_side(3923, 23.9), 1000.0);  // Chicago's traces: as before
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    EXPECT_EQ(io::skeleton_picture_long_side(400, bad), 1000.0) << bad;
    EXPECT_EQ(io::skeleton_picture_long_side(bad, 1), 1000.0) << bad;
  }
  // 100 points 1 apart on a line: at feature size 0.1 the page is 2970 pixels (+ 2 x 10 margin) and the
  // points 30 pixels apart; the feature size is 3 pixels, so the dots have a fifth of it as radius; at
  // feature size 1 the page is the least, 1000, and the dots the full radius 1.
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i < 100; ++i) points.push_back({double(i), 0.0});
  const skeleton::Skeleton_graph none;
  auto svg = [&](double feature_size, double long_side) {
    const std::string path = scratch_path("skeleton_picture.svg");
    io::write_skeleton_picture(path, points, none, {feature_size, long_side});
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  std::string text = svg(0.1, 0);
  EXPECT_TRUE(contains(text, "viewBox=\"0 0 2990.00 20.00\""));
  EXPECT_TRUE(contains(text, "<circle cx=\"40.00\" cy=\"10.00\" r=\"0.6\" fill=\"#c0c0c0\"/>"));
  text = svg(1, 0);
  EXPECT_TRUE(contains(text, "viewBox=\"0 0 1020.00 20.00\""));
  EXPECT_TRUE(contains(text, " r=\"1\" fill"));
  text = svg(0.5, 200);  // the page given: 200 pixels, the feature size 1 pixel, dots of the least radius 0.3
  EXPECT_TRUE(contains(text, "viewBox=\"0 0 220.00 20.00\""));
  EXPECT_TRUE(contains(text, " r=\"0.3\" fill"));
  // One position, or two so close that the page over their span is beyond the largest double: a square page,
  // the position in its centre, full marks.
  for (const double apart : {0.0, 1e-322}) {
    points = {{0.0, 0.0}, {apart, 0.0}};
    text = svg(1, 500);
    EXPECT_TRUE(contains(text, "viewBox=\"0 0 520.00 520.00\"")) << apart;
    EXPECT_TRUE(contains(text, "<circle cx=\"260.00\" cy=\"260.00\" r=\"1\"")) << apart;
  }
}

TEST(PointCloudIo, WrittenCloudsReadBackBitForBitWithTheShortestDigits) {
  // Every format, with and without normals, PLY also with colours: the cloud read back equals the one
  // written, double for double; the text holds "0.2071" (CGAL's writers printed 0.20710000000000001) and
  // 0.1 + 0.2 with the 17 digits it needs. Only the points asked for are written, in the order asked.
  io::Point_cloud cloud;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  cloud.points = {{0.2071, -0.0974, 0.1 + 0.2}, {1e-300, -4.9406564584124654e-324, 1e17}, {0, 0, 0}};
  for (int i = 0; i < 20; ++i) cloud.points.push_back({u(rng) * 1e6, u(rng), u(rng) * 1e-6});
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    cloud.normals.push_back({u(rng), u(rng), 0.5});
    cloud.colors.push_back({static_cast<unsigned char>(i), 255, static_cast<unsigned char>(7 * i)});
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = cloud.points.size(); i-- > 0;)
    if (i != 4) kept.push_back(i);
  for (const std::string ext : {"ply", "off", "xyz"})
    for (const bool normals : {true, false}) {
      io::Point_cloud c = cloud;
      if (!normals) c.normals.clear();
      const std::string path = scratch_path(std::string("cloud.") + ext);
      io::write_point_cloud(path, c, kept);
      const io::Point_cloud back = io::read_point_cloud(path);
      ASSERT_EQ(back.points.size(), kept.size()) << ext;
      EXPECT_EQ(back.has_normals(), normals) << ext;
      EXPECT_EQ(back.has_colors(), ext == "ply") << ext;  // OFF and XYZ have no colours
      for (std::size_t k = 0; k < kept.size(); ++k) {
        EXPECT_EQ(back.points[k], c.points[kept[k]]) << ext << " point " << k;
        if (normals) {
          EXPECT_EQ(back.normals[k], c.normals[kept[k]]) << ext << " normal " << k;
        }
        if (back.has_colors()) {
          EXPECT_EQ(back.colors[k], c.colors[kept[k]]) << ext << " colour " << k;
        }
      }
      std::ifstream in(path);
      const std::string text(std::istreambuf_iterator<char>(in), {});
      EXPECT_TRUE(contains(text, "0.2071 -0.0974 0.30000000000000004")) << ext;
      EXPECT_FALSE(contains(text, "0.20710000000000001")) << ext;
    }
  EXPECT_THROW(io::write_point_cloud(scratch_path("cloud.obj"), cloud, kept), io::Input_error);
}

// The exchange format holds exactly what its lines say: a header of two counts, vertex lines of four numbers,
// simplices of distinct vertices, counts that are plain non-negative integers below the index range. A line
// with more, or a count that does not fit, is refused with its line (or, at the end of the file, what was
// read).
TEST(ExchangeFormat, RefusesWhatTheFormatDoesNotHold) {
  expect_error("2 1 7\n0 0 0 0\n0 0 0 1\n0 1\n", ":1: header must be 'n m'");
  expect_error("1 0\n0 0 0 0 5\n", ":2: vertex 0 must be 'x y z f' (4 numbers), got 5");
  expect_error("3 0\n0 0 0 0\n", "unexpected end of file after 1 of 3 vertex lines");
  expect_error("3 1\n0 0 0 0\n0 0 0 1\n0 0 0 2\n0 1 0\n", ":5: simplex 0 repeats a vertex");
  expect_error("3 1\n0 0 0 0\n0 0 0 1\n0 0 0 2\n0 1 1\n", ":5: simplex 0 repeats a vertex");
  expect_error("2 1\n0 0 0 0\n0 0 0 1\n0 +1\n", ":4: '+1' is not a non-negative integer (vertex index)");
  expect_error("2 99999999999999999999\n0 0 0 0\n0 0 0 1\n",
               ":1: '99999999999999999999' is not a non-negative integer (number of simplices)");
  // The largest 32-bit index is not a vertex (n vertices have indices up to n - 1).
  expect_error("4294967295 0\n", ":1: too many vertices (4294967295)");
}

TEST(ExchangeFormat, WrittenNumbersReadBackExactly) {
  // write_complex prints 17 significant digits: every position and value reads back bit for bit.
  const std::vector<std::array<double, 3>> positions{{0.1 + 0.2, 1.0 / 3, -2e-310},
                                                     {1e23, 447123.456, 5e-324}};
  const std::vector<double> values{2.0 / 3, -0.1};
  const std::string path = scratch_path("exact.txt");
  io::write_complex(path, skeleton::make_simplicial_complex_2(2, {{0, 1}}, {}), positions, values);
  const io::Complex_file c = io::read_complex(path);
  EXPECT_EQ(c.positions, positions);
  EXPECT_EQ(c.values, values);
  EXPECT_EQ(c.complex.number_of_edges(), 1u);
}

TEST(PointFile, HexadecimalIsNotANumber) {
  // strtod reads 0x10 as 16; the point files take decimals only.
  expect_error("1 2\n0x10 1\n", ":2: '0x10' is not a number (coordinate)", false);
}

TEST(FormatDouble, FifteenDigitsWhenTheyReadBack) {
  // The shortest of 15, 16 and 17 digits: 1e23 and the least denormal read back from 15, whose 16-digit forms
  // are longer ("9.999999999999999e+22", "4.940656458412465e-324").
  EXPECT_EQ(io::format_double(1e23), "1e+23");
  EXPECT_EQ(io::format_double(4.9406564584124654e-324), "4.94065645841247e-324");
}

TEST(FileExtension, OnlyTheFileNameCounts) {
  // A dot in a directory name is not an extension; extensions are lower case.
  EXPECT_EQ(io::file_extension("/data.d/points"), "");
  EXPECT_EQ(io::file_extension("/data.d/cloud.XYZ"), "xyz");
  EXPECT_EQ(io::file_extension("cloud.tar.PLY"), "ply");
}

// Map files: fields are trimmed (spaces, tabs, the CR of a CRLF file), '#' starts a comment and blank lines
// are skipped; vertex_lines are the lines of the file.
TEST(MapFile, FieldsAreTrimmedAndCommentsSkipped) {
  const std::string v = write_temp("trim_v.txt", "# id,x,y\r\n0, 1.5 ,\t2\r\n\r\n1,3,4  # corner\r\n");
  const io::Map_file m = io::read_map(v, write_temp("trim_e.txt", " 5 , 1 , 0 , 1\r\n"));
  EXPECT_EQ(m.positions, (std::vector<std::array<double, 2>>{{1.5, 2}, {3, 4}}));
  EXPECT_EQ(m.edges, (std::vector<std::array<std::uint32_t, 2>>{{1, 0}}));
  EXPECT_EQ(m.vertex_lines, (std::vector<std::size_t>{2, 4}));
}

TEST(MapFile, RepeatedVertexIdsAndInexactIdsAreRefused) {
  auto error_of = [](const std::string& vertices, const std::string& edges) {
    return thrown_message<io::Input_error>(
        [&] { io::read_map(write_temp("rep_v.txt", vertices), write_temp("rep_e.txt", edges)); });
  };
  EXPECT_TRUE(contains(error_of("0,0,0\n1,1,1\n0,2,2\n", ""), "rep_v.txt:3: vertex id 0 repeated"));
  // 9007199254740993.0 reads as the double 2^53 (integers beyond 2^53 are not all doubles): taken as the id
  // 9007199254740992 it named another vertex. A decimal id is accepted only below 2^53, where it is exact.
  const std::string big = "9007199254740993.0,0,0\n9007199254740992,1,0\n";
  EXPECT_TRUE(contains(error_of(big, ""),
                       "rep_v.txt:1: vertex id '9007199254740993.0' is at least 2^53 in decimal notation"));
  EXPECT_EQ(
      error_of("9007199254740991.0,0,0\n9007199254740990,1,0\n", "0,9007199254740991,9007199254740990\n"),
      "no exception");
}

TEST(MapFile, SelfLoopsAndZeroLengthEdgesAreCountedWithTheirFirstLine) {
  // Vertices 1 and 2 share a position; edges 1 and 3 are self-loops, 2 and 4 have length zero.
  const io::Map_file m = io::read_map(write_temp("z_v.txt", "0,0,0\n1,10,0\n2,10,0\n"),
                                      write_temp("z_e.txt", "0,0,1\n1,0,0\n2,1,2\n3,1,1\n4,2,1\n"));
  EXPECT_EQ(m.edges.size(), 5u);  // all kept
  EXPECT_EQ(m.self_loops, 2u);
  EXPECT_EQ(m.first_self_loop_line, 2u);
  EXPECT_EQ(m.zero_length_edges, 2u);  // self-loops are not counted again
  EXPECT_EQ(m.first_zero_length_line, 3u);
}

// A track file: trips in order of first appearance, a missing time the line number, and each fix's line.
TEST(InputFiles, TrackFileOrigins) {
  const std::string path = write_temp("origins.txt", "# trips\ncar9 0 0\ncar2 1 1\n\ncar9 2 2\n");
  io::Track_origin origin;
  const auto trips = io::read_track_trips(path, &origin);
  EXPECT_EQ(origin.trip_ids, (std::vector<std::string>{"car9", "car2"}));
  ASSERT_EQ(trips.size(), 2u);
  EXPECT_EQ(trips[0], (std::vector<std::array<double, 3>>{{0, 0, 2}, {2, 2, 5}}));
  EXPECT_EQ(origin.where(0, 1), path + ":5");
  EXPECT_EQ(origin.where(1, 0), path + ":3");
}

TEST(InputFiles, OnlyTheFirstLineLosesAByteOrderMark) {
  // An editor's byte-order mark begins the file; further on the bytes are data: a trip id that begins with
  // them is another trip than the id without them.
  io::Track_origin origin;
  const auto trips = io::read_track_trips(write_temp("bom_trips.txt",
                                                     "\xEF\xBB\xBF"
                                                     "a 0 0\n\xEF\xBB\xBF"
                                                     "a 1 1\na 2 2\n"),
                                          &origin);
  EXPECT_EQ(origin.trip_ids, (std::vector<std::string>{"a",
                                                       "\xEF\xBB\xBF"
                                                       "a"}));
  ASSERT_EQ(trips.size(), 2u);
  EXPECT_EQ(trips[0], (std::vector<std::array<double, 3>>{{0, 0, 1}, {2, 2, 3}}));
}

// Trip files in natural order: digit runs compare as numbers with leading zeros ignored (trip_002 before
// trip_10), names equal as numbers in byte order (trip_01 before trip_1); a one-character name is a trip too.
TEST(InputFiles, TripFilesInNaturalOrder) {
  const std::string dir = scratch_path("natural");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  const std::vector<std::string> names{"trip_10", "trip_002", "trip_1", "7", "trip_01"};
  for (const std::string& name : names) std::ofstream(dir + "/" + name + ".txt") << "0 0\n";
  io::Track_origin origin;
  const auto trips = io::read_track_trips(dir, &origin);
  for (const std::string& name : names) std::remove((dir + "/" + name + ".txt").c_str());
  ::rmdir(dir.c_str());
  EXPECT_EQ(origin.trip_ids, (std::vector<std::string>{"7", "trip_01", "trip_1", "trip_002", "trip_10"}));
  EXPECT_EQ(trips.size(), 5u);
}

TEST(WriteTextFile, ANewFileGetsTheUsualPermissions) {
  // The temporary is created private (0600); the file in place has what a new file gets: 0666 less the umask.
  const mode_t mask = ::umask(022);
  const std::string path = scratch_path("mode.txt");
  io::write_text_file(path, "x\n");
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST(WriteTextFile, ALinkIsWrittenThroughAndAFifoInPlace) {
  // A symbolic link stays a link, its target gets the text.
  const std::string target = write_temp("target.txt", "old\n"), link = scratch_path("link.txt");
  ASSERT_EQ(::symlink(target.c_str(), link.c_str()), 0);
  io::write_text_file(link, "new\n");
  struct stat st {};
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
  std::string line;
  std::getline(std::ifstream(target), line);
  EXPECT_EQ(line, "new");
  // A FIFO is written into, not replaced by a file (a reader is open, and the text fits in the pipe).
  const std::string fifo = scratch_path("fifo.txt");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  io::write_text_file(fifo, "through\n");
  char buffer[32] = {};
  const ssize_t n = ::read(reader, buffer, sizeof buffer - 1);
  ::close(reader);
  EXPECT_EQ(std::string(buffer, n > 0 ? std::size_t(n) : 0), "through\n");
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

namespace {
/// Two nodes and one arc from node 0 to node 1 along `polyline` (whose ends are the nodes' positions).
skeleton::Skeleton_graph one_arc(const std::vector<std::array<double, 3>>& polyline) {
  skeleton::Skeleton_graph g(2);
  g[0].position = polyline.front();
  g[0].type = skeleton::minimum;
  g[1].position = polyline.back();
  g[1].value = 2.5;
  g[1].type = skeleton::maximum;
  skeleton::Skeleton_arc arc;
  arc.polyline = polyline;
  arc.members = {0, 1, 2, 3};  // a count other than the polyline's points
  arc.upper = 1;
  boost::add_edge(0, 1, arc, g);
  return g;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

TEST(SkeletonFiles, GraphMLGeoJsonAndPlyHoldTheGraph) {
  const skeleton::Skeleton_graph g = one_arc({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  const std::string graphml = scratch_path("g.graphml"), geojson = scratch_path("g.geojson"),
                    ply = scratch_path("g.ply");
  io::write_skeleton_graphml(graphml, g);
  io::write_skeleton_geojson(geojson, g);
  io::write_skeleton_ply(ply, g);
  std::string text = text_of(graphml);
  EXPECT_TRUE(
      contains(text,
               "<node id=\"n1\"><data key=\"x\">2</data><data key=\"y\">0</data><data key=\"z\">0</data>"
               "<data key=\"value\">2.5</data><data key=\"type\">maximum</data></node>"));
  // The edge names its nodes by their ids, its polyline is "x y z;x y z;...", members the count of its
  // members.
  EXPECT_TRUE(contains(text,
                       "<edge id=\"e0\" source=\"n0\" target=\"n1\"><data key=\"polyline\">0 0 0;1 1 0;2 0 0"
                       "</data><data key=\"members\">4</data></edge>"));
  text = text_of(geojson);
  EXPECT_TRUE(
      contains(text,
               "{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1], [2, 0]]}, \"properties\": "
               "{\"kind\": \"arc\", \"members\": 4}}"));
  EXPECT_TRUE(
      contains(text,
               "\"coordinates\": [2, 0]}, \"properties\": {\"kind\": \"node\", \"type\": \"maximum\", "
               "\"value\": 2.5}}"));
  // PLY: the nodes are vertices 0 and 1, the arc's interior point vertex 2; edges by zero-based vertex index.
  text = text_of(ply);
  EXPECT_TRUE(contains(text, "element vertex 3\n"));
  EXPECT_TRUE(contains(text, "element edge 2\n"));
  EXPECT_TRUE(contains(text, "end_header\n0 0 0\n2 0 0\n1 1 0\n0 2\n2 1\n"));
}

TEST(SkeletonFiles, GeoJsonCutsAtTheAntimeridianOnlyBeyond180Degrees) {
  auto lines_of = [](const std::vector<std::array<double, 3>>& polyline) {
    const std::string path = scratch_path("ll.geojson");
    io::write_skeleton_geojson(path, one_arc(polyline), true);
    const std::string text = text_of(path);
    const std::size_t from = text.find("\"geometry\": "), to = text.find(", \"properties\"");
    return from == std::string::npos || to == std::string::npos ? text
                                                                : text.substr(from + 12, to - from - 12);
  };
  // From 179 E to 178 W: across the antimeridian, cut at the latitude a third of the way (1 of 3 degrees).
  EXPECT_EQ(
      lines_of({{179, 10, 0}, {-178, 13, 0}}),
      "{\"type\": \"MultiLineString\", \"coordinates\": [[[179, 10], [180, 11]], [[-180, 11], [-178, 13]]]}");
  // A step of exactly 180 degrees is not "more than 180": not cut.
  EXPECT_EQ(lines_of({{0, 0, 0}, {180, 5, 0}}),
            "{\"type\": \"LineString\", \"coordinates\": [[0, 0], [180, 5]]}");
  // A line that starts on +180 and goes east starts at -180: a part of one position is no line.
  EXPECT_EQ(lines_of({{180, 0, 0}, {-170, 0, 0}}),
            "{\"type\": \"LineString\", \"coordinates\": [[-180, 0], [-170, 0]]}");
}

TEST(SkeletonPicture, MarksAreScaledToTheFeatureSizeAndNonFinitePointsLeftOut) {
  const skeleton::Skeleton_graph g = one_arc({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  const std::string path = scratch_path("marks.svg");
  // No feature size: arcs 2 pixels wide, nodes of radius 3.
  io::write_skeleton_picture(path, {}, g);
  std::string text = text_of(path);
  EXPECT_TRUE(contains(text, "stroke-width=\"2\""));
  EXPECT_TRUE(contains(text, " r=\"3\" fill=\"black\""));
  // 2 units on 100 pixels: a feature size of 0.06 is 3 pixels, arcs and nodes a half of it.
  io::write_skeleton_picture(path, {}, g, {0.06, 100});
  text = text_of(path);
  EXPECT_TRUE(contains(text, "stroke-width=\"1.5\""));
  EXPECT_TRUE(contains(text, " r=\"1.5\" fill=\"black\""));
  // Points with a non-finite coordinate are neither drawn nor part of the page's extent.
  const double inf = HUGE_VAL;
  io::write_skeleton_picture(path, {{0, 0}, {1, 1}, {inf, 0}, {std::nan(""), 1}}, skeleton::Skeleton_graph(),
                             {1, 100});
  text = text_of(path);
  EXPECT_TRUE(contains(text, "viewBox=\"0 0 120.00 120.00\""));
  EXPECT_EQ(text.find("<circle", text.find("<circle", text.find("<circle") + 1) + 1), std::string::npos)
      << text;
  EXPECT_FALSE(contains(text, "inf"));
  EXPECT_FALSE(contains(text, "nan"));
}

TEST(SkeletonFiles, MapComparisonCsvNamesEachPartner) {
  skeleton::Map_comparison_result r;
  r.ground_truth_sample_list = {{{0, 0}, 90}, {{1.5, 0}, 270}};
  r.reconstruction_sample_list = {{{0, 0.25}, 45}};
  r.ground_truth_partner = {0, -1};
  r.reconstruction_partner = {0};
  const std::string path = scratch_path("samples.csv");
  io::write_map_comparison_csv(path, r);
  EXPECT_EQ(text_of(path),
            "map,index,x,y,bearing,partner\ntruth,0,0,0,90,0\ntruth,1,1.5,0,270,-1\nreconstruction,0,0,0.25,"
            "45,0\n");
}

namespace {
/// The message of reading `text` as the point cloud `name` (its extension the format), or "no exception".
std::string cloud_error(const std::string& name, const std::string& text) {
  const std::string path = write_temp(name, text);
  return thrown_message<io::Input_error>([&] { io::read_point_cloud(path); });
}
}  // namespace

// Each refusal of a point-cloud reader names the file, the line of a text file and the problem.
TEST(PointCloudIo, XyzAndOffLinesHoldWhatTheirHeaderSays) {
  EXPECT_TRUE(contains(cloud_error("four.xyz", "0 0 0 1\n"), "four.xyz:1: expected 3 or 6 numbers per line"));
  EXPECT_TRUE(contains(cloud_error("ragged.xyz", "0 0 0\n1 1 1 0 0 1\n"),
                       "ragged.xyz:2: point 1 has 6 numbers, the first point has 3"));
  EXPECT_TRUE(
      contains(cloud_error("word.xyz", "0 0 0\n1 abc 1\n"), "word.xyz:2: 'abc' is not a number (point 1)"));
  EXPECT_TRUE(contains(cloud_error("normal.xyz", "0 0 0 0 0 1\n1 1 1 nan 0 1\n"),
                       "normal.xyz:2: point 1 has a normal with a non-finite component"));
  EXPECT_TRUE(contains(cloud_error("none.xyz", "# nothing\n"), "none.xyz: no points"));
  EXPECT_TRUE(contains(cloud_error("4.off", "4OFF\n1 0 0\n0 0 0 0\n"),
                       "4.off:1: '4OFF' is not a supported OFF header"));
  EXPECT_TRUE(contains(cloud_error("b.off", "OFF BINARY\n"), "b.off:1: binary OFF is not supported"));
  EXPECT_TRUE(contains(cloud_error("long.off", "OFF\n1 0 0\n0 0 0 5\n"),
                       "long.off:3: vertex 0 must be 'x y z', got 4"));
  EXPECT_TRUE(contains(cloud_error("minus.off", "OFF\n-1 0 0\n"), "minus.off:2: '-1' is not a vertex count"));
  // The lines of the points of a text file, for messages about them.
  const std::string path = write_temp("lines.xyz", "# header\n0 0 0\n\n1 1 1\n");
  const io::Point_cloud c = io::read_point_cloud(path);
  EXPECT_EQ(c.lines, (std::vector<std::size_t>{2, 4}));
  EXPECT_EQ(c.locate(path, 1), path + ":4: point 1");
}

TEST(PointCloudIo, PlyHeadersAndBinaryDataAreChecked) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n";
  EXPECT_TRUE(
      contains(cloud_error("noz.ply", head + "end_header\n0 0\n"), "(the vertex element has no property z)"));
  EXPECT_TRUE(
      contains(cloud_error("nx.ply", head + "property float z\nproperty float nx\nend_header\n0 0 0 1\n"),
               "(the vertex element has only some of the normal properties nx, ny, nz)"));
  EXPECT_TRUE(contains(cloud_error("open.ply", head + "property float z\n0 0 0\n"),
                       "(the header has no end_header line)"));
  // Binary: data exactly as long as the header declares is read; list counts in the file's byte order.
  auto binary = [](bool big, const std::string& list_type, std::uint16_t count) {
    std::string s = std::string("ply\nformat binary_") + (big ? "big" : "little") +
                    "_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list " +
                    list_type + " int vertex_indices\nend_header\n";
    auto put = [&](std::uint32_t v, int size) {
      for (int k = 0; k < size; ++k) s += char((v >> (8 * (big ? size - 1 - k : k))) & 0xff);
    };
    const float xyz[6] = {0, 1, 2, 3, 4, 5};
    for (const float f : xyz) {
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      put(bits, 4);
    }
    put(count, list_type == "ushort" ? 2 : 1);
    for (int k = 0; k < 2; ++k) put(std::uint32_t(k), 4);
    return s;
  };
  for (const bool big : {true, false}) {
    const std::string path = write_temp(big ? "big.ply" : "little.ply", binary(big, "ushort", 2));
    const io::Point_cloud c = io::read_point_cloud(path);
    EXPECT_EQ(c.points, (std::vector<std::array<double, 3>>{{0, 1, 2}, {3, 4, 5}})) << big;
  }
  EXPECT_TRUE(contains(cloud_error("negative.ply", binary(false, "char", 0xff)),
                       "(element face row 0: list vertex_indices has a negative count)"));
}

TEST(PointCloudIo, AFailedWriteIsAnError) {
  io::Point_cloud cloud;
  cloud.points = {{0, 0, 0}};
  EXPECT_THROW(io::write_point_cloud("/nonexistent_dir/cloud.xyz", cloud, {0}), io::Input_error);
}
