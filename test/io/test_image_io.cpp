// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Image files: PNG, JPEG, PGM and PPM round trips, ASCII PNM, and errors that name the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <png.h>

#include "io/featurerecon_io.h"
#include "io/image_io.h"
#include "io/scratch_file.h"

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
  try {
    io::read_image(bad);
    FAIL() << "expected an error";
  } catch (const io::Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.png: not a readable PNG"), std::string::npos) << e.what();
  }
  const std::string jpg = scratch("bad.jpg");
  std::ofstream(jpg) << "not a jpeg";
  EXPECT_THROW(io::read_image(jpg), io::Input_error);
  EXPECT_THROW(io::read_image(scratch("x.gif")), io::Input_error);
  EXPECT_THROW(io::read_image(scratch("missing.pgm")), io::Input_error);
  // A short PGM: the bytes after the header count, not the file's (13 and 11 here).
  auto expect_short = [&](const std::string& name, const std::string& text, const std::string& message) {
    const std::string path = scratch(name);
    std::ofstream(path) << text;
    try {
      io::read_image(path);
      ADD_FAILURE() << name << " was read";
    } catch (const io::Input_error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
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
    try {
      io::read_image(path);
    } catch (const io::Input_error& e) {
      return std::string(e.what());
    }
    return std::string("read");
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
  EXPECT_NE(message_of(png).find("huge.png: corrupt PNG header: 30000 x 30000 pixels cannot be stored in "),
            std::string::npos)
      << message_of(png);
  // JPEG: the height and width of the start-of-frame segment (after FFC0, length, precision).
  const std::string jpg = scratch("huge.jpg");
  io::write_image(jpg, small);
  bytes = read_bytes(jpg);
  const std::size_t sof = bytes.find("\xff\xc0");
  ASSERT_NE(sof, std::string::npos);
  big_endian(bytes, sof + 5, 20000, 2);
  big_endian(bytes, sof + 7, 20000, 2);
  write_bytes(jpg, bytes);
  EXPECT_NE(message_of(jpg).find("huge.jpg: corrupt JPEG header: 20000 x 20000 pixels cannot be stored in "),
            std::string::npos)
      << message_of(jpg);
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
