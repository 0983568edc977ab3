#include "swarf/report/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace swarf {

namespace {

std::string fmt(double v, int decimals = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s(buf);
  if (s == "-0" || s.rfind("-0.", 0) == 0) {
    // "-0.000" -> "0.000": avoid a negative zero in text outputs.
    bool all_zero =
        std::all_of(s.begin() + 1, s.end(), [](char c) { return c == '0' || c == '.'; });
    if (all_zero) s.erase(0, 1);
  }
  return s;
}

std::string escape_xml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

struct MoveStyle {
  const char* color;
  const char* dash;
  double width;
};

MoveStyle style_of(const Move& m) {
  switch (m.kind) {
    case MoveKind::kRapid:
      return {"#d62728", "4,3", 0.6};
    case MoveKind::kPlunge:
    case MoveKind::kRamp:
    case MoveKind::kHelix:
      return {"#ff7f0e", "", 1.2};
    case MoveKind::kArc:
      return {m.cutting ? "#2ca02c" : "#999999", "", 1.0};
    case MoveKind::kFeed:
      return {m.cutting ? "#1f77b4" : "#999999", m.cutting ? "" : "2,2", 0.8};
  }
  return {"#000000", "", 1.0};
}

}  // namespace

std::string toolpath_svg(const Toolpath& path, const ToolpathPlotOptions& options) {
  Box2 box = bounds(options.background);
  for (const Move& m : path.moves)
    box.add(m.end.xy());
  if (box.empty()) box = Box2{{0, 0}, {1, 1}};
  const double margin = 0.04 * std::max({box.size().x, box.size().y, 1.0});
  box = box.inflated(margin);
  const double w = options.width_px;
  const double scale = w / std::max(box.size().x, 1e-9);
  const double h = std::max(50.0, box.size().y * scale);
  auto X = [&](double x) { return fmt((x - box.min.x) * scale, 2); };
  auto Y = [&](double y) { return fmt((box.max.y - y) * scale, 2); };

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(w, 0) << "\" height=\""
    << fmt(h + 30, 0) << "\" viewBox=\"0 0 " << fmt(w, 0) << " " << fmt(h + 30, 0) << "\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!options.background.empty()) {
    o << "<path fill=\"#eeeeee\" stroke=\"#555555\" stroke-width=\"1\" fill-rule=\"evenodd\" d=\"";
    for (const Ring& r : options.background.rings) {
      for (std::size_t i = 0; i < r.size(); ++i)
        o << (i == 0 ? "M" : "L") << X(r[i].x) << "," << Y(r[i].y) << " ";
      o << "Z ";
    }
    o << "\"/>\n";
  }
  // One polyline per run of moves with the same style keeps the file small.
  Vec3 pos = path.moves.empty() ? Vec3{} : path.moves.front().end;
  std::size_t i = 0;
  while (i < path.moves.size()) {
    const MoveStyle st = style_of(path.moves[i]);
    o << "<polyline fill=\"none\" stroke=\"" << st.color << "\" stroke-width=\"" << st.width
      << "\"";
    if (*st.dash) o << " stroke-dasharray=\"" << st.dash << "\"";
    o << " points=\"" << X(pos.x) << "," << Y(pos.y);
    while (i < path.moves.size()) {
      const Move& m = path.moves[i];
      const MoveStyle s2 = style_of(m);
      if (s2.color != st.color || s2.dash != st.dash) break;
      const double step = m.is_arc() ? std::max(0.05, 2.0 / scale) : 1e30;
      for (const Vec3& p : sample_move(pos, m, step))
        o << " " << X(p.x) << "," << Y(p.y);
      pos = m.end;
      ++i;
    }
    o << "\"/>\n";
  }
  o << "<text x=\"8\" y=\"" << fmt(h + 20, 0) << "\" font-family=\"sans-serif\" font-size=\"13\">"
    << escape_xml(options.title.empty() ? path.name : options.title)
    << "  [blue: cutting, green: arcs, orange: entry, grey: links, red dashed: rapids]</text>\n";
  o << "</svg>\n";
  return o.str();
}

std::string line_chart_svg(const std::vector<Series>& series, const std::string& title,
                           const std::string& x_label, const std::string& y_label, double width_px,
                           double height_px) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Series& s : series) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (x0 > x1) {
    x0 = 0;
    x1 = 1;
    y0 = 0;
    y1 = 1;
  }
  if (x1 - x0 < 1e-12) x1 = x0 + 1;
  if (y1 - y0 < 1e-12) {
    y1 += 1;
    y0 -= 1;
  }
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  const double left = 70, right = 20, top = 35, bottom = 50;
  const double pw = width_px - left - right, ph = height_px - top - bottom;
  auto X = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return top + (y1 - y) / (y1 - y0) * ph; };

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width_px, 0) << "\" height=\""
    << fmt(height_px, 0) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << fmt(width_px / 2, 0)
    << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << escape_xml(title) << "</text>\n"
    << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << fmt(pw, 1) << "\" height=\""
    << fmt(ph, 1) << "\" fill=\"none\" stroke=\"#333\"/>\n";
  for (int k = 0; k <= 5; ++k) {
    const double xv = x0 + (x1 - x0) * k / 5.0, yv = y0 + (y1 - y0) * k / 5.0;
    o << "<text x=\"" << fmt(X(xv), 1) << "\" y=\"" << fmt(top + ph + 16, 1)
      << "\" text-anchor=\"middle\">" << fmt(xv, 2) << "</text>\n"
      << "<text x=\"" << fmt(left - 6, 1) << "\" y=\"" << fmt(Y(yv) + 4, 1)
      << "\" text-anchor=\"end\">" << fmt(yv, 2) << "</text>\n"
      << "<line x1=\"" << left << "\" x2=\"" << fmt(left + pw, 1) << "\" y1=\"" << fmt(Y(yv), 1)
      << "\" y2=\"" << fmt(Y(yv), 1) << "\" stroke=\"#ddd\"/>\n";
  }
  o << "<text x=\"" << fmt(left + pw / 2, 0) << "\" y=\"" << fmt(height_px - 10, 0)
    << "\" text-anchor=\"middle\">" << escape_xml(x_label) << "</text>\n"
    << "<text transform=\"translate(16," << fmt(top + ph / 2, 0)
    << ") rotate(-90)\" text-anchor=\"middle\">" << escape_xml(y_label) << "</text>\n";
  int legend = 0;
  for (const Series& s : series) {
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1\" points=\"";
    // Thin very long series to about two points per pixel column.
    const std::size_t n = std::min(s.x.size(), s.y.size());
    const std::size_t stride = std::max<std::size_t>(1, n / static_cast<std::size_t>(2 * pw));
    for (std::size_t i = 0; i < n; i += stride)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        o << fmt(X(s.x[i]), 1) << "," << fmt(Y(s.y[i]), 1) << " ";
    o << "\"/>\n";
    o << "<rect x=\"" << fmt(left + 10 + 150 * legend, 0) << "\" y=\"" << fmt(top + 6, 0)
      << "\" width=\"12\" height=\"3\" fill=\"" << s.color << "\"/><text x=\""
      << fmt(left + 26 + 150 * legend, 0) << "\" y=\"" << fmt(top + 11, 0) << "\">"
      << escape_xml(s.name) << "</text>\n";
    ++legend;
  }
  o << "</svg>\n";
  return o.str();
}

std::string toolpath_csv(const Toolpath& path) {
  std::ostringstream o;
  o << "index,kind,x,y,z,feed,cutting,engagement_deg,force_n\n";
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& m = path.moves[i];
    o << i << "," << move_kind_name(m.kind) << "," << fmt(m.end.x, 4) << "," << fmt(m.end.y, 4)
      << "," << fmt(m.end.z, 4) << "," << fmt(m.kind == MoveKind::kRapid ? 0.0 : m.feed_mm_min, 1)
      << "," << (m.cutting && m.kind != MoveKind::kRapid ? 1 : 0) << ",";
    if (std::isfinite(m.engagement_deg)) o << fmt(m.engagement_deg, 2);
    o << ",";
    if (std::isfinite(m.force_n)) o << fmt(m.force_n, 2);
    o << "\n";
  }
  return o.str();
}

}  // namespace swarf
