#include <gtest/gtest.h>

#include <png.h>

#include <sstream>
#include <string>

#include "swarf/report/image.h"
#include "swarf/report/plot.h"

namespace swarf {
namespace {

// Decodes PNG bytes with libpng's simplified API: an independent reader of what we wrote.
Image decode_png(const std::string& bytes) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&img, bytes.data(), bytes.size())) return {};
  img.format = PNG_FORMAT_RGB;
  Image out(static_cast<int>(img.width), static_cast<int>(img.height));
  if (!png_image_finish_read(&img, nullptr, out.pixels.data(), 0, nullptr)) return {};
  return out;
}

TEST(Png, DecodesBackToTheSamePixels) {
  Image im(7, 5);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      im.at(x, y) = {static_cast<std::uint8_t>(30 * x), static_cast<std::uint8_t>(40 * y), 7};
  const Image back = decode_png(png_bytes(im));
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      EXPECT_EQ(back.at(x, y).r, im.at(x, y).r);
      EXPECT_EQ(back.at(x, y).g, im.at(x, y).g);
      EXPECT_EQ(back.at(x, y).b, im.at(x, y).b);
    }
}

TEST(HeatColor, RunsFromBlueToRed) {
  EXPECT_GT(heat_color(0.0).b, 200);
  EXPECT_LT(heat_color(0.0).r, 50);
  EXPECT_GT(heat_color(1.0).r, 200);
  EXPECT_LT(heat_color(1.0).b, 50);
  EXPECT_EQ(heat_color(-3.0).b, heat_color(0.0).b);  // clamped
}

Toolpath square_path() {
  Toolpath tp;
  tp.rapid_to({0, 0, 5});
  tp.plunge_to(-1, 100);
  tp.feed_to({10, 0, -1}, 500);
  tp.feed_to({10, 10, -1}, 500);
  tp.arc_to({0, 10, -1}, {5, 10}, false, 500);
  tp.retract();
  return tp;
}

TEST(ToolpathCsv, OneRowPerMoveWithKinds) {
  const std::string csv = toolpath_csv(square_path());
  std::istringstream in(csv);
  std::string line;
  int rows = 0;
  std::getline(in, line);
  EXPECT_EQ(line, "index,kind,x,y,z,feed,cutting,engagement_deg,force_n");
  while (std::getline(in, line))
    ++rows;
  EXPECT_EQ(rows, 6);
  EXPECT_NE(csv.find(",plunge,"), std::string::npos);
  EXPECT_NE(csv.find(",arc,"), std::string::npos);
  EXPECT_EQ(csv.find("-0.0000"), std::string::npos);
}

TEST(ToolpathSvg, DrawsEveryKindAndTheBackground) {
  ToolpathPlotOptions opt;
  opt.background.rings.push_back({{-1, -1}, {11, -1}, {11, 11}, {-1, 11}});
  const std::string svg = toolpath_svg(square_path(), opt);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("#d62728"), std::string::npos);  // rapid
  EXPECT_NE(svg.find("#ff7f0e"), std::string::npos);  // plunge
  EXPECT_NE(svg.find("#2ca02c"), std::string::npos);  // arc
  EXPECT_NE(svg.find("fill=\"#eeeeee\""), std::string::npos);
}

TEST(LineChart, HasOnePolylinePerSeries) {
  Series a{"engagement", {0, 1, 2}, {10, 12, 11}, "#1f77b4"};
  Series b{"deviation", {0, 1, 2}, {1, 5, 2}, "#ff7f0e"};
  const std::string svg = line_chart_svg({a, b}, "t", "step", "deg");
  std::size_t count = 0;
  for (std::size_t p = svg.find("<polyline"); p != std::string::npos;
       p = svg.find("<polyline", p + 1))
    ++count;
  EXPECT_EQ(count, 2u);
}

}  // namespace
}  // namespace swarf
