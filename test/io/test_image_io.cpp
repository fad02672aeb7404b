// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Image files: PNG, JPEG, PGM and PPM round trips, ASCII PNM, and errors that name the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <png.h>
// after <cstdio>: jpeglib.h needs FILE and size_t
#include <jpeglib.h>

#include "io/featurerecon_io.h"
#include "io/image_io.h"
#include "io/picture.h"
#include "io/scratch_file.h"
#include "test_utilities.h"

using FeatureRecon::test::contains;
using FeatureRecon::test::thrown_message;
using FeatureRecon::test::throws_with;

using namespace FeatureRecon;

namespace {
std::string scratch(const std::string& name) { return test::scratch_path(name); }

io::Image gradient(int channels, int cx = 7, int cy = 11) {
  io::Image im;
  im.width = 37;
  im.height = 21;
  im.channels = channels;
  for (int r = 0; r < im.height; ++r)
    for (int c = 0; c < im.width; ++c)
      for (int k = 0; k < channels; ++k) im.data.push_back(std::uint8_t((cx * c + cy * r + 80 * k) % 256));
  return im;
}
}  // namespace

TEST(ImageIo, LosslessRoundTrips) {
  for (const int channels : {1, 3})
    for (const std::string ext : {"png", "pgm", "ppm"}) {
      if ((ext == "pgm" && channels == 3) || (ext == "ppm" && channels == 1)) continue;
      const io::Image a = gradient(channels);
      const std::string path = scratch("g." + ext);
      io::write_image(path, a);
      const io::Image b = io::read_image(path);
      EXPECT_EQ(b.width, a.width);
      EXPECT_EQ(b.height, a.height);
      EXPECT_EQ(b.channels, a.channels) << ext;
      EXPECT_EQ(b.data, a.data) << ext << " " << channels;
    }
}

TEST(ImageIo, JpegIsCloseAndAsciiPnmReads) {
  const io::Image a = gradient(3, 2, 3);      // smooth (no wrap-around edges): what JPEG is made for
  const std::string path = scratch("g.JPG");  // extensions are case-insensitive
  io::write_image(path, a);
  const io::Image b = io::read_image(path);
  ASSERT_EQ(b.data.size(), a.data.size());
  double error = 0;
  for (std::size_t i = 0; i < a.data.size(); ++i) error += std::abs(int(a.data[i]) - int(b.data[i]));
  EXPECT_LT(error / double(a.data.size()), 5.0);  // quality 95 with chroma subsampling: 3.1 measured
  // ASCII PGM with a comment and a maximum value of 15 (rescaled to 0..255).
  const std::string pgm = scratch("a.pgm");
  std::ofstream(pgm) << "P2\n# a comment\n3 2\n15\n0 15 5\n10 1 15\n";
  const io::Image c = io::read_image(pgm);
  EXPECT_EQ(c.width, 3);
  EXPECT_EQ(c.channels, 1);
  EXPECT_EQ(c.at(1, 0), 255);
  EXPECT_EQ(c.at(2, 0), 85);
  EXPECT_EQ(c.at(0, 1), 170);
}

TEST(ImageIo, ErrorsNameTheFile) {
  const std::string bad = scratch("bad.png");
  std::ofstream(bad) << "not a png";
  EXPECT_TRUE(throws_with<io::Input_error>([&] { io::read_image(bad); }, "bad.png: not a readable PNG"));
  const std::string jpg = scratch("bad.jpg");
  std::ofstream(jpg) << "not a jpeg";
  EXPECT_THROW(io::read_image(jpg), io::Input_error);
  EXPECT_THROW(io::read_image(scratch("x.gif")), io::Input_error);
  EXPECT_THROW(io::read_image(scratch("missing.pgm")), io::Input_error);
  // A short PGM: the bytes after the header count, not the file's (13 and 11 here).
  auto expect_short = [&](const std::string& name, const std::string& text, const std::string& message) {
    const std::string path = scratch(name);
    std::ofstream(path) << text;
    EXPECT_TRUE(throws_with<io::Input_error>([&] { io::read_image(path); }, message));
  };
  expect_short("t.pgm", "P5\n4 4\n255\nab",
               "needs 16 bytes of pixel data or more, the file has 2 after its header");
  expect_short("header_only.pgm", "P5\n2 2\n255",  // the file ends with the maximum value
               "needs 4 bytes of pixel data or more, the file has 0 after its header");
  const std::string exact = scratch("exact.pgm");  // exactly the bytes needed: read
  std::ofstream(exact) << "P5\n2 2\n255\nabcd";
  EXPECT_EQ(io::read_image(exact).data, (std::vector<std::uint8_t>{'a', 'b', 'c', 'd'}));
}

// A header claiming more pixels than its file can hold is refused before anything is allocated (a 69-byte PNG
// claiming 30000 x 30000 took 2.6 GB, a 30 KB JPEG claiming 60000 x 60000 10.5 GB, before failing).
TEST(ImageIo, SizesTheFileCannotHoldAreRefused) {
  io::Image small;
  small.width = small.height = 64;
  small.channels = 1;
  small.data.assign(64 * 64, 200);
  auto read_bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  auto write_bytes = [](const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
  };
  auto big_endian = [](std::string& bytes, std::size_t at, unsigned value, int size) {
    for (int k = 0; k < size; ++k) bytes[at + k] = char((value >> (8 * (size - 1 - k))) & 0xff);
  };
  auto message_of = [](const std::string& path) {
    return thrown_message<io::Input_error>([&] { io::read_image(path); });
  };
  // PNG: IHDR (width, height at bytes 16-23) with its CRC recomputed, so that libpng accepts the header.
  const std::string png = scratch("huge.png");
  io::write_image(png, small);
  std::string bytes = read_bytes(png);
  ASSERT_EQ(bytes.substr(12, 4), "IHDR");
  big_endian(bytes, 16, 30000, 4);
  big_endian(bytes, 20, 30000, 4);
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 12; i < 29; ++i) {
    crc ^= static_cast<unsigned char>(bytes[i]);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  big_endian(bytes, 29, ~crc, 4);
  write_bytes(png, bytes);
  EXPECT_TRUE(
      contains(message_of(png), "huge.png: corrupt PNG header: 30000 x 30000 pixels cannot be stored in "));
  // JPEG: the height and width of the start-of-frame segment (after FFC0, length, precision).
  const std::string jpg = scratch("huge.jpg");
  io::write_image(jpg, small);
  bytes = read_bytes(jpg);
  const std::size_t sof = bytes.find("\xff\xc0");
  ASSERT_NE(sof, std::string::npos);
  big_endian(bytes, sof + 5, 20000, 2);
  big_endian(bytes, sof + 7, 20000, 2);
  write_bytes(jpg, bytes);
  EXPECT_TRUE(
      contains(message_of(jpg), "huge.jpg: corrupt JPEG header: 20000 x 20000 pixels cannot be stored in "));
  big_endian(bytes, sof + 5, 60000, 2);
  big_endian(bytes, sof + 7, 60000, 2);
  write_bytes(jpg, bytes);
  EXPECT_EQ(message_of(jpg), jpg + ": a 60000 x 60000 JPEG is beyond 2^30 pixels");
  // The images themselves read.
  io::write_image(png, small);
  EXPECT_EQ(io::read_image(png).width, 64);
}

TEST(ImageIo, SixteenBitPngHoldsEncodedValues) {
  // 16-bit files without gAMA (test/data/grey16.png: 0, 8000, 32768, 65535 and a white row; rgb16.png:
  // (32768, 0, 65535) and white) read as v / 257 rounded, as an 8-bit file of the same picture; libpng took
  // them for linear light and encoded them again (32768 read as 186, 8000 as 98).
  const io::Image grey = io::read_image(std::string(FEATURERECON_TEST_DATA_DIR) + "/grey16.png");
  ASSERT_EQ(grey.channels, 1);
  ASSERT_EQ(grey.data.size(), 8u);
  EXPECT_EQ(std::vector<int>(grey.data.begin(), grey.data.begin() + 4), (std::vector<int>{0, 31, 128, 255}));
  const io::Image rgb = io::read_image(std::string(FEATURERECON_TEST_DATA_DIR) + "/rgb16.png");
  ASSERT_EQ(rgb.channels, 3);
  EXPECT_EQ(std::vector<int>(rgb.data.begin(), rgb.data.end()),
            (std::vector<int>{128, 0, 255, 255, 255, 255}));
}

TEST(ImageIo, TransparencyIsCompositedOntoWhite) {
  // A black vertical line on a fully transparent background (RGBA and grey + alpha): the background reads as
  // white paper (libpng composited it onto the zeroed buffer: black, so every pixel was ink), the line as
  // black, and a half-transparent black pixel as a middle grey.
  const int w = 16, h = 16;
  for (const bool colour : {true, false}) {
    const int channels = colour ? 4 : 2;
    std::vector<png_byte> pixels(static_cast<std::size_t>(w * h * channels), 0);  // black, transparent
    for (int r = 0; r < h; ++r) pixels[static_cast<std::size_t>((r * w + 8) * channels + channels - 1)] = 255;
    pixels[static_cast<std::size_t>((3 * w + 2) * channels + channels - 1)] = 128;  // half-transparent black
    png_image img;
    std::fill(reinterpret_cast<char*>(&img), reinterpret_cast<char*>(&img) + sizeof img, 0);
    img.version = PNG_IMAGE_VERSION;
    img.width = w;
    img.height = h;
    img.format = colour ? PNG_FORMAT_RGBA : PNG_FORMAT_GA;
    const std::string path = scratch(colour ? "rgba_line.png" : "ga_line.png");
    ASSERT_TRUE(png_image_write_to_file(&img, path.c_str(), 0, pixels.data(), 0, nullptr)) << img.message;
    const io::Image im = io::read_image(path);
    ASSERT_EQ(im.channels, colour ? 3 : 1);
    auto at = [&](int r, int c) { return int(im.data[static_cast<std::size_t>((r * w + c) * im.channels)]); };
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        if (r == 3 && c == 2) continue;
        EXPECT_EQ(at(r, c), c == 8 ? 0 : 255) << r << " " << c;
      }
    EXPECT_GT(at(3, 2), 40);  // composited in linear light: sRGB 188 for half coverage
    EXPECT_LT(at(3, 2), 230);
  }
}

namespace {
/// The message of reading `bytes` as the image file `name`, or "no exception".
std::string image_error(const std::string& name, const std::string& bytes) {
  const std::string path = scratch(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return thrown_message<io::Input_error>([&] { io::read_image(path); });
}
}  // namespace

// PGM/PPM: 8-bit maximum values only, pixel values within the maximum, sizes positive; values of a smaller
// maximum are rescaled to 0..255 rounded to nearest; ASCII data needs a digit and a separator a value but the
// last.
TEST(ImageIo, PnmHeadersAndValuesAreChecked) {
  EXPECT_TRUE(contains(image_error("deep.pgm", "P5\n1 1\n65535\n\x01\x02"),
                       "unsupported PGM/PPM maximum value 65535"));
  EXPECT_TRUE(contains(image_error("over.pgm", std::string("P5\n2 1\n100\n\x32\xc8")),
                       "pixel value 200 at byte 1 exceeds the maximum value 100"));
  EXPECT_TRUE(
      contains(image_error("zero.pgm", "P5\n0 1\n255\n"), "the width must be a positive integer, got '0'"));
  const std::string pgm = scratch("seven.pgm");
  std::ofstream(pgm) << "P2\n3 1\n7\n2 7 0";  // exactly 2n - 1 bytes after the header
  const io::Image im = io::read_image(pgm);
  EXPECT_EQ(std::vector<int>(im.data.begin(), im.data.end()),
            (std::vector<int>{73, 255, 0}));  // 2 * 255 / 7 = 72.9
}

TEST(ImageIo, GreyAndColourAreConvertedOnWriting) {
  // RGB written as PGM is its luma, as to_grey gives it (rounded: (0, 1, 0) is 0.587, grey 1); grey written
  // as PPM has three equal channels.
  io::Image rgb = gradient(3);
  rgb.data[0] = 0, rgb.data[1] = 1, rgb.data[2] = 0;
  const std::string pgm = scratch("luma.pgm");
  io::write_image(pgm, rgb);
  const io::Image grey = io::read_image(pgm);
  EXPECT_EQ(grey.channels, 1);
  EXPECT_EQ(grey.data, io::to_grey(rgb).data);
  EXPECT_EQ(grey.data[0], 1);
  // BT.601 weights: red 0.299, blue 0.114.
  io::Image red;
  red.width = red.height = 1;
  red.channels = 3;
  red.data = {255, 0, 0};
  EXPECT_EQ(io::to_grey(red).data, (std::vector<std::uint8_t>{76}));
  const std::string ppm = scratch("expanded.ppm");
  const io::Image g = gradient(1);
  io::write_image(ppm, g);
  const io::Image c = io::read_image(ppm);
  ASSERT_EQ(c.channels, 3);
  for (std::size_t i = 0; i < g.data.size(); ++i)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(c.data[3 * i + k], g.data[i]) << i << " " << k;
  // What is not an image of 1 or 3 channels and its size is refused.
  io::Image bad = gradient(1);
  bad.channels = 2;
  bad.data.resize(bad.data.size() * 2);  // the size of 2 channels
  EXPECT_THROW(io::write_image(scratch("bad.pgm"), bad), io::Input_error);
  bad = gradient(1);
  bad.width = 0;
  bad.data.clear();
  EXPECT_THROW(io::write_image(scratch("bad.pgm"), bad), io::Input_error);
}

TEST(ImageIo, JpegQualityAndTruncation) {
  const std::string path = scratch("q.jpg");
  io::write_image(path, gradient(3, 2, 3));
  std::ifstream in(path, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  // Quality 95: libjpeg scales the standard luminance table (DC 16) to 10 %, DC 2 (quality 75 gives 8).
  const std::size_t dqt = bytes.find("\xff\xdb");
  ASSERT_NE(dqt, std::string::npos);
  EXPECT_EQ(int(static_cast<unsigned char>(bytes[dqt + 5])), 2);
  // A file cut in its compressed data is an error, not a picture padded with grey.
  const std::size_t sos = bytes.find("\xff\xda");
  ASSERT_NE(sos, std::string::npos);
  const std::string cut = bytes.substr(0, sos + (bytes.size() - sos) / 2);
  EXPECT_TRUE(contains(image_error("cut.jpg", cut), "cut.jpg: not a readable JPEG ("));
  // Between 2^30 and 2^31 pixels: beyond the cap.
  std::string big = bytes;
  const std::size_t sof = big.find("\xff\xc0");
  ASSERT_NE(sof, std::string::npos);
  for (const std::size_t at : {sof + 5, sof + 7})
    big[at] = char(40000 >> 8), big[at + 1] = char(40000 & 0xff);
  EXPECT_TRUE(contains(image_error("big.jpg", big), "big.jpg: a 40000 x 40000 JPEG is beyond 2^30 pixels"));
}

TEST(ImageIo, CmykJpegIsRefused) {
  const std::string path = scratch("cmyk.jpg");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  jpeg_compress_struct info;
  jpeg_error_mgr error;
  info.err = jpeg_std_error(&error);
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, f);
  info.image_width = info.image_height = 8;
  info.input_components = 4;
  info.in_color_space = JCS_CMYK;
  jpeg_set_defaults(&info);
  jpeg_start_compress(&info, TRUE);
  std::vector<JSAMPLE> row(8 * 4, 100);
  JSAMPROW rows[1] = {row.data()};
  while (info.next_scanline < info.image_height) jpeg_write_scanlines(&info, rows, 1);
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::fclose(f);
  EXPECT_EQ(thrown_message<io::Input_error>([&] { io::read_image(path); }),
            path + ": CMYK JPEG images are not supported");
}

// Pictures: "#rrggbb", black or white; pages of 0 to 65536 pixels; the raster ceil(width) x ceil(height),
// each pixel covered by the distance of its centre to the shape (a disc's edge through a centre: half), a
// polyline's joints drawn once.
TEST(Picture, ColoursPagesAndCoverage) {
  io::Picture page(10.5, 5.2);
  EXPECT_THROW(page.disc(1, 1, 1, "#12345g"), std::invalid_argument);
  EXPECT_THROW(page.disc(1, 1, 1, "red"), std::invalid_argument);
  EXPECT_THROW(io::Picture(0, 10), std::invalid_argument);
  EXPECT_THROW(io::Picture(10, 70000), std::invalid_argument);
  const io::Image blank = page.raster();
  EXPECT_EQ(blank.width, 11);
  EXPECT_EQ(blank.height, 6);
  io::Picture disc(20, 20);
  disc.disc(10.5, 10.5, 3, "black");
  const io::Image d = disc.raster();
  EXPECT_EQ(d.at(10, 10), 0);
  EXPECT_EQ(d.at(13, 10), 128);  // centre (13.5, 10.5) on the edge
  EXPECT_EQ(d.at(15, 10), 255);
  io::Picture bend(20, 20), segment(20, 20);
  bend.polyline({{2, 10}, {10, 10}, {10, 2}}, 1, "black");
  segment.line(2, 10, 10, 10, 1, "black");
  const int joint = bend.raster().at(10, 10);
  EXPECT_LT(joint, 255);
  EXPECT_EQ(joint, segment.raster().at(10, 10));  // both segments reach it, as far as each alone
  EXPECT_TRUE(throws_with<io::Input_error>([&] { page.write(scratch("page.gif")); },
                                           "unknown picture format '.gif' (expected .svg, "));
}
