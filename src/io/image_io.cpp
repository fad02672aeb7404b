// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "io/image_io.h"

#include <png.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include <jerror.h>
#include <jpeglib.h>

#include "io/featurerecon_io.h"

namespace FeatureRecon {
namespace io {
namespace {
[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Input_error(path + ": " + what);
}

struct File {
  std::FILE* f;
  File(const std::string& path, const char* mode) : f(std::fopen(path.c_str(), mode)) {}
  ~File() {
    if (f) std::fclose(f);
  }
};

/// A header whose size the file cannot hold is corrupt: refused before the pixels are allocated (a 69-byte
/// PNG claiming 30000 x 30000 pixels took 2.6 GB, a 30 KB JPEG claiming 60000 x 60000 10.5 GB). At most
/// `pixels_per_byte` pixels a byte of file (deflate packs at most 1032 bytes into one, eight 1-bit pixels to
/// a byte; a JPEG codes every 8 x 8 block in a bit or more) and 2^30 pixels in all.
void check_image_size(const std::string& path, const char* kind, unsigned long long width,
                      unsigned long long height, unsigned long long pixels_per_byte) {
  const unsigned long long pixels = width * height;
  const std::string size = std::to_string(width) + " x " + std::to_string(height);
  if (pixels > (1ull << 30)) fail(path, "a " + size + " " + kind + " is beyond 2^30 pixels");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
      pixels > pixels_per_byte * static_cast<unsigned long long>(st.st_size) + 4096)
    fail(path, std::string("corrupt ") + kind + " header: " + size + " pixels cannot be stored in " +
                   std::to_string(st.st_size) + " bytes");
}

Image read_png(const std::string& path) {
  png_image img;
  std::fill(reinterpret_cast<char*>(&img), reinterpret_cast<char*>(&img) + sizeof img, 0);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    fail(path, std::string("not a readable PNG (") + img.message + ")");
  try {
    check_image_size(path, "PNG", img.width, img.height, 8 * 1032);
  } catch (...) {
    png_image_free(&img);
    throw;
  }
  const bool colour = (img.format & PNG_FORMAT_FLAG_COLOR) != 0;
  img.format = colour ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;  // 8-bit
  // A 16-bit file without gAMA or sRGB chunk holds encoded values like an 8-bit one (v / 257 on the 8-bit
  // scale). libpng assumes linear light there and encoded it again: mid-grey 32768 read as 186, not 128.
  img.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  Image out;
  out.width = int(img.width);
  out.height = int(img.height);
  out.channels = colour ? 3 : 1;
  out.data.resize(PNG_IMAGE_SIZE(img));
  // Transparency is composited onto white, the paper a picture is drawn on (without a background libpng
  // composites onto the buffer, which was zero: a transparent background read as black ink).
  png_color white;
  white.red = white.green = white.blue = 255;
  if (!png_image_finish_read(&img, &white, out.data.data(), 0, nullptr)) {
    const std::string message = img.message;
    png_image_free(&img);
    fail(path, "PNG decoding failed (" + message + ")");
  }
  return out;
}

void write_png(const std::string& path, const Image& image) {
  png_image img;
  std::fill(reinterpret_cast<char*>(&img), reinterpret_cast<char*>(&img) + sizeof img, 0);
  img.version = PNG_IMAGE_VERSION;
  img.width = png_uint_32(image.width);
  img.height = png_uint_32(image.height);
  img.format = image.channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;
  if (!png_image_write_to_file(&img, path.c_str(), 0, image.data.data(), 0, nullptr))
    fail(path, std::string("cannot write PNG (") + img.message + ")");
}

struct Jpeg_error {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};
void jpeg_fail(j_common_ptr info) {
  Jpeg_error* e = reinterpret_cast<Jpeg_error*>(info->err);
  (*info->err->format_message)(info, e->message);
  std::longjmp(e->jump, 1);
}
/// Reading: the warnings that mean missing data (a truncated file: "premature end of JPEG file", "premature
/// end of data segment") are errors, or the file would decode to a picture padded with grey; other warnings
/// (such as extraneous bytes before a marker, which most viewers ignore) are not.
void jpeg_warning_fails(j_common_ptr info, int level) {
  if (level < 0 && (info->err->msg_code == JWRN_JPEG_EOF || info->err->msg_code == JWRN_HIT_MARKER))
    jpeg_fail(info);
}

Image read_jpeg(const std::string& path) {
  File file(path, "rb");
  if (!file.f) fail(path, "cannot open");
  jpeg_decompress_struct info;
  Jpeg_error error;
  info.err = jpeg_std_error(&error.base);
  error.base.error_exit = jpeg_fail;
  error.base.emit_message = jpeg_warning_fails;
  Image out;
  if (setjmp(error.jump)) {
    jpeg_destroy_decompress(&info);
    fail(path, std::string("not a readable JPEG (") + error.message + ")");
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, file.f);
  jpeg_read_header(&info, TRUE);
  try {
    check_image_size(path, "JPEG", info.image_width, info.image_height, 1024);
  } catch (...) {
    jpeg_destroy_decompress(&info);
    throw;
  }
  if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {
    jpeg_destroy_decompress(&info);
    fail(path, "CMYK JPEG images are not supported");
  }
  info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_start_decompress(&info);
  out.width = int(info.output_width);
  out.height = int(info.output_height);
  out.channels = int(info.output_components);
  out.data.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.data.data() +
                   std::size_t(info.output_scanline) * std::size_t(out.width) * std::size_t(out.channels);
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return out;
}

void write_jpeg(const std::string& path, const Image& image) {
  File file(path, "wb");
  if (!file.f) fail(path, "cannot write");
  jpeg_compress_struct info;
  Jpeg_error error;
  info.err = jpeg_std_error(&error.base);
  error.base.error_exit = jpeg_fail;
  if (setjmp(error.jump)) {
    jpeg_destroy_compress(&info);
    fail(path, std::string("cannot write JPEG (") + error.message + ")");
  }
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, file.f);
  info.image_width = JDIMENSION(image.width);
  info.image_height = JDIMENSION(image.height);
  info.input_components = image.channels;
  info.in_color_space = image.channels == 3 ? JCS_RGB : JCS_GRAYSCALE;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 95, TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row =
        const_cast<JSAMPROW>(image.data.data() + std::size_t(info.next_scanline) * std::size_t(image.width) *
                                                     std::size_t(image.channels));
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  if (std::fflush(file.f) != 0 || std::ferror(file.f))
    fail(path, "write failed (" + std::string(std::strerror(errno)) + ")");
}

/// PGM/PPM, binary (P5/P6) or ASCII (P2/P3), maximum value up to 255 (values are rescaled to 0..255). Every
/// header field and ASCII value must be a plain decimal integer; the size is checked against the file's
/// length before anything is allocated; a value above the maximum is an error (binary values too, not
/// wrapped).
Image read_pnm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  // The length of a regular file bounds what its header may ask for; a pipe's is unknown (read, not sized).
  struct stat st {};
  const bool sized = ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
  const unsigned long long file_size = sized ? static_cast<unsigned long long>(st.st_size) : 0;
  auto token = [&]() {
    std::string t;
    char c;
    while (in.get(c)) {
      if (c == '#' && t.empty()) {
        std::string comment;
        std::getline(in, comment);
        continue;
      }
      if (std::isspace(static_cast<unsigned char>(c))) {
        if (!t.empty()) break;
        continue;
      }
      t.push_back(c);
      if (t.size() > 64) break;  // no field of a PGM/PPM file is this long
    }
    return t;
  };
  // A non-negative decimal integer (at most `limit`), or -1.
  auto integer = [](const std::string& t, long long limit) -> long long {
    if (t.empty() || t.size() > 18) return -1;
    long long v = 0;
    for (const char c : t) {
      if (c < '0' || c > '9') return -1;
      v = 10 * v + (c - '0');
    }
    return v <= limit ? v : -1;
  };
  const std::string magic = token();
  if (magic != "P2" && magic != "P3" && magic != "P5" && magic != "P6")
    fail(path, "not a PGM/PPM file (magic '" + magic + "', expected P2, P3, P5 or P6)");
  const bool binary = magic == "P5" || magic == "P6";
  Image out;
  out.channels = (magic == "P3" || magic == "P6") ? 3 : 1;
  const char* const names[3] = {"width", "height", "maximum value"};
  long long header[3];
  for (int k = 0; k < 3; ++k) {
    const std::string t = token();
    header[k] = integer(t, std::numeric_limits<int>::max());
    if (header[k] <= 0)
      fail(path, std::string("bad PGM/PPM header: the ") + names[k] + " must be a positive integer, got '" +
                     t + "'");
  }
  if (header[2] > 255)
    fail(path,
         "unsupported PGM/PPM maximum value " + std::to_string(header[2]) + " (8-bit only, at most 255)");
  out.width = int(header[0]);
  out.height = int(header[1]);
  const long long max_value = header[2];
  const unsigned long long n =
      static_cast<unsigned long long>(header[0]) * static_cast<unsigned long long>(header[1]) * out.channels;
  // Binary data needs n bytes, ASCII data at least 2n - 1 (a digit and a separator per value). From a pipe,
  // at most 2^30 values are accepted.
  if (!sized && n > (1ull << 30))
    fail(path, "a " + std::to_string(out.width) + "x" + std::to_string(out.height) + " " + magic +
                   " image read from a pipe is beyond 2^30 values");
  // What follows the header (the whitespace that ends the maximum value is read with it; a header that ends
  // the file leaves the stream failed, and nothing follows).
  if (!in) in.clear(), in.seekg(0, std::ios::end);
  const std::streamoff at = in.tellg();
  const unsigned long long left = at >= 0 && static_cast<unsigned long long>(at) <= file_size
                                      ? file_size - static_cast<unsigned long long>(at)
                                      : file_size;
  if (sized && (n > left || (!binary && 2 * n - 1 > left)))
    fail(path, "truncated pixel data: a " + std::to_string(out.width) + "x" + std::to_string(out.height) +
                   " " + magic + " image needs " + std::to_string(binary ? n : 2 * n - 1) +
                   " bytes of pixel data or more, the file has " + std::to_string(left) +
                   " after its header");
  out.data.resize(static_cast<std::size_t>(n));
  if (binary) {
    if (!in.read(reinterpret_cast<char*>(out.data.data()), std::streamsize(n)))
      fail(path,
           "truncated pixel data (" + std::to_string(in.gcount()) + " of " + std::to_string(n) + " bytes)");
    for (std::size_t i = 0; i < out.data.size(); ++i)
      if (out.data[i] > max_value)
        fail(path, "pixel value " + std::to_string(out.data[i]) + " at byte " + std::to_string(i) +
                       " exceeds the maximum value " + std::to_string(max_value));
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string t = token();
      if (t.empty())
        fail(path, "truncated pixel data (value " + std::to_string(i) + " of " + std::to_string(n) + ")");
      const long long v = integer(t, max_value);
      if (v < 0)
        fail(path, "pixel value " + std::to_string(i) + " '" + t + "' is not an integer in [0, " +
                       std::to_string(max_value) + "]");
      out.data[i] = std::uint8_t(v);
    }
  }
  if (max_value != 255)
    for (auto& v : out.data) v = std::uint8_t((long(v) * 255 + max_value / 2) / max_value);
  return out;
}

void write_pnm(const std::string& path, const Image& image, bool colour) {
  std::ofstream out(path, std::ios::binary);
  if (!out) fail(path, "cannot write");
  out << (colour ? "P6" : "P5") << '\n' << image.width << ' ' << image.height << "\n255\n";
  if (colour && image.channels == 1) {
    for (const std::uint8_t v : image.data) out.put(char(v)).put(char(v)).put(char(v));
  } else if (!colour && image.channels == 3) {
    for (std::size_t i = 0; i < image.data.size(); i += 3)
      out.put(char((299 * image.data[i] + 587 * image.data[i + 1] + 114 * image.data[i + 2] + 500) / 1000));
  } else {
    out.write(reinterpret_cast<const char*>(image.data.data()), std::streamsize(image.data.size()));
  }
  out.flush();
  if (!out) fail(path, "write failed (" + std::string(std::strerror(errno)) + ")");
}
}  // namespace

Image read_image(const std::string& path) {
  require_readable_file(path);
  const std::string e = file_extension(path);
  if (e == "png") return read_png(path);
  if (e == "jpg" || e == "jpeg") return read_jpeg(path);
  if (e == "pgm" || e == "ppm" || e == "pnm") return read_pnm(path);
  fail(path, "unknown image format '." + e + "' (expected .png, .jpg, .jpeg, .pgm or .ppm)");
}

void write_image(const std::string& path, const Image& image) {
  if (!(image.channels == 1 || image.channels == 3) || image.width <= 0 || image.height <= 0 ||
      image.data.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
    fail(path, "malformed image (size or channels)");
  const std::string e = file_extension(path);
  if (e == "png") return write_png(path, image);
  if (e == "jpg" || e == "jpeg") return write_jpeg(path, image);
  if (e == "pgm") return write_pnm(path, image, false);
  if (e == "ppm") return write_pnm(path, image, true);
  fail(path, "unknown image format '." + e + "' (expected .png, .jpg, .jpeg, .pgm or .ppm)");
}

Image to_grey(const Image& image) {
  if (image.channels == 1) return image;
  Image g;
  g.width = image.width;
  g.height = image.height;
  g.channels = 1;
  g.data.resize(std::size_t(image.width) * std::size_t(image.height));
  for (std::size_t i = 0; i < g.data.size(); ++i) {
    const double y =
        0.299 * image.data[3 * i] + 0.587 * image.data[3 * i + 1] + 0.114 * image.data[3 * i + 2];
    g.data[i] = static_cast<std::uint8_t>(std::lround(y));
  }
  return g;
}

}  // namespace io
}  // namespace FeatureRecon
