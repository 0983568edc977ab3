// Vector pictures for reports: the toolpath seen from the top and line charts, as SVG.
#pragma once

#include <string>
#include <vector>

#include "swarf/polygon/polygon.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {

struct ToolpathPlotOptions {
  /// Drawn under the toolpath: pocket outline, part outline (grey).
  PolygonSet background;
  double width_px = 900.0;
  std::string title;
};
/// Top view of the toolpath, moves coloured by kind (rapids dashed red, feeds blue,
/// linking feeds grey, plunges/ramps/helices orange, arcs green).
std::string toolpath_svg(const Toolpath& path, const ToolpathPlotOptions& options = {});

struct Series {
  std::string name;
  std::vector<double> x;
  std::vector<double> y;
  std::string color = "#1f77b4";
};
/// A simple line chart with axes, ticks and a legend.
std::string line_chart_svg(const std::vector<Series>& series, const std::string& title,
                           const std::string& x_label, const std::string& y_label,
                           double width_px = 900.0, double height_px = 400.0);

/// The toolpath as CSV rows: index, kind, x, y, z, feed, cutting, engagement_deg, force_n.
std::string toolpath_csv(const Toolpath& path);

}  // namespace swarf
