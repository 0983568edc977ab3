// Raster pictures for reports (PNG through libpng) and a colour map.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/status.h"

namespace swarf {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

/// An RGB picture, row 0 at the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;

  Image() = default;
  Image(int w, int h, Rgb fill = {255, 255, 255})
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// The image encoded as PNG bytes.
std::string png_bytes(const Image& image);
/// Writes a PNG atomically.
Status write_png(const std::string& path, const Image& image);

/// Blue (t = 0) through green and yellow to red (t = 1); t is clamped.
Rgb heat_color(double t);

}  // namespace swarf
