// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "io/featurerecon_io.h"
#include "io/scratch_file.h"

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
  try {
    if (complex)
      io::read_complex(path);
    else
      io::read_points(path);
    ADD_FAILURE() << "expected an error containing '" << part << "'";
  } catch (const io::Input_error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
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
