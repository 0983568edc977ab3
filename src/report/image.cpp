#include "swarf/report/image.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "swarf/core/io.h"

namespace swarf {

namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void no_flush(png_structp /*png*/) {}

}  // namespace

std::string png_bytes(const Image& image) {
  std::string out;
  if (image.width <= 0 || image.height <= 0) return out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr) {
    png_destroy_write_struct(&png, &info);
    return {};
  }
  // libpng reports failures by longjmp; nothing here owns resources that need unwinding.
  if (setjmp(png_jmpbuf(png))) {  // NOLINT(cert-err52-cpp)
    png_destroy_write_struct(&png, &info);
    return {};
  }
  png_set_write_fn(png, &out, append_to_string, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  static_assert(sizeof(Rgb) == 3, "Rgb must be packed as three bytes");
  for (int y = 0; y < image.height; ++y) {
    const Rgb* row = &image.pixels[static_cast<std::size_t>(y) * image.width];
    png_write_row(png, reinterpret_cast<png_const_bytep>(row));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

Status write_png(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0)
    return {Error::kInternal, path + ": cannot write an empty image"};
  std::string bytes = png_bytes(image);
  if (bytes.empty()) return {Error::kIo, path + ": PNG encoding failed"};
  return write_file_atomic(path, bytes);
}

Rgb heat_color(double t) {
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0);
  // Piecewise-linear blue -> cyan -> green -> yellow -> red.
  static constexpr double kStops[5][3] = {
      {0, 0, 255}, {0, 200, 255}, {0, 200, 0}, {255, 220, 0}, {220, 0, 0}};
  const double f = t * 4.0;
  const int i = std::min(3, static_cast<int>(f));
  const double u = f - i;
  auto mix = [&](int c) {
    return static_cast<std::uint8_t>(std::lround(kStops[i][c] * (1 - u) + kStops[i + 1][c] * u));
  };
  return {mix(0), mix(1), mix(2)};
}

}  // namespace swarf
