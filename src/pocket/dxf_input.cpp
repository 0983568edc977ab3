// ASCII DXF pocket reader: LWPOLYLINE and POLYLINE/VERTEX (bulges), LINE, ARC, CIRCLE,
// ELLIPSE and SPLINE (NURBS by control points) of the ENTITIES section, chained into closed
// loops.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pocket/geometry.h"
#include "pocket/pocket_input_internal.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {

namespace {

using pocket::append_arc;

struct Pair {
  int code = 0;
  std::string value;
  std::size_t line = 0;
};

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
    ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
    --b;
  return std::string(s.substr(a, b - a));
}

bool read_pairs(std::string_view text, std::vector<Pair>& out, std::string& error) {
  std::size_t pos = 0, line = 0;
  auto next_line = [&](std::string& l) {
    if (pos >= text.size()) return false;
    std::size_t e = text.find('\n', pos);
    if (e == std::string_view::npos) e = text.size();
    l = trim(text.substr(pos, e - pos));
    pos = e + 1;
    ++line;
    return true;
  };
  std::string code, value;
  while (next_line(code)) {
    if (code.empty() && pos >= text.size()) break;
    if (!next_line(value)) {
      error = "line " + std::to_string(line) + ": group code without a value";
      return false;
    }
    char* end = nullptr;
    const long c = std::strtol(code.c_str(), &end, 10);
    if (code.empty() || *end != '\0') {
      error = "line " + std::to_string(line - 1) + ": group code '" + code.substr(0, 20) +
              "' is not an integer (binary DXF is not supported)";
      return false;
    }
    out.push_back({static_cast<int>(c), value, line});
  }
  return true;
}

bool to_double(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && std::isfinite(v);
}

void append_bulge(std::vector<Vec2>& out, Vec2 p1, Vec2 p2, double bulge, double tol) {
  const double d = distance(p1, p2);
  if (std::abs(bulge) < 1e-12 || d < 1e-12) {
    out.push_back(p2);
    return;
  }
  // The bulge is tan(included angle / 4), positive counter-clockwise.
  const Vec2 c = p2 - p1;
  const Vec2 mid = (p1 + p2) * 0.5;
  const Vec2 centre = mid + perp(c / d) * (d * (1.0 - bulge * bulge) / (4.0 * bulge));
  const double r = distance(centre, p1);
  const double a0 = std::atan2(p1.y - centre.y, p1.x - centre.x);
  std::vector<Vec2> pts;
  append_arc(pts, centre, r, a0, a0 + 4.0 * std::atan(bulge), tol);
  pts.back() = p2;
  out.insert(out.end(), pts.begin(), pts.end());
}

// A NURBS curve (DXF SPLINE): de Boor's algorithm on the homogeneous control points.
struct Nurbs {
  int degree = 3;
  std::vector<double> knots;
  std::vector<Vec2> ctrl;
  std::vector<double> weights;  // empty: all 1
  Vec2 at(double t) const {
    const int p = degree;
    const int n = static_cast<int>(ctrl.size());
    int k = p;  // knot span: knots[k] <= t < knots[k + 1], clamped to the last one
    while (k + 1 < n && knots[static_cast<std::size_t>(k) + 1] <= t)
      ++k;
    std::vector<double> wx(static_cast<std::size_t>(p) + 1), wy(wx.size()), ww(wx.size());
    for (int j = 0; j <= p; ++j) {
      const std::size_t i = static_cast<std::size_t>(j + k - p);
      const double w = weights.empty() ? 1.0 : weights[i];
      wx[static_cast<std::size_t>(j)] = ctrl[i].x * w;
      wy[static_cast<std::size_t>(j)] = ctrl[i].y * w;
      ww[static_cast<std::size_t>(j)] = w;
    }
    for (int r = 1; r <= p; ++r) {
      for (int j = p; j >= r; --j) {
        const double lo = knots[static_cast<std::size_t>(j + k - p)];
        const double hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
        const double a = hi > lo ? (t - lo) / (hi - lo) : 0.0;
        const std::size_t u = static_cast<std::size_t>(j), v = u - 1;
        wx[u] = (1.0 - a) * wx[v] + a * wx[u];
        wy[u] = (1.0 - a) * wy[v] + a * wy[u];
        ww[u] = (1.0 - a) * ww[v] + a * ww[u];
      }
    }
    const std::size_t e = static_cast<std::size_t>(p);
    return {wx[e] / ww[e], wy[e] / ww[e]};
  }
};

// A bound on one curve's flattened points (a hostile file could otherwise ask for 2^16 per
// knot span); the result is then rejected.
constexpr std::size_t kMaxCurvePoints = 1000000;

// Samples f on [t0, t1] (f(t0) already in out) until every piece's midpoint and quarter
// points lie within tol of its chord; appends up to f(t1).
template <class F>
void sample_curve(std::vector<Vec2>& out, const F& f, double t0, Vec2 p0, double t1, Vec2 p1,
                  double tol, int depth = 0) {
  const double tm = 0.5 * (t0 + t1);
  const Vec2 pm = f(tm);
  auto off = [&](Vec2 q) { return pocket::point_line_distance(q, p0, p1); };
  const bool flat =
      off(pm) <= tol && off(f(0.5 * (t0 + tm))) <= tol && off(f(0.5 * (tm + t1))) <= tol;
  if (depth >= 16 || flat || out.size() > kMaxCurvePoints) {
    out.push_back(p1);
    return;
  }
  sample_curve(out, f, t0, p0, tm, pm, tol, depth + 1);
  sample_curve(out, f, tm, pm, t1, p1, tol, depth + 1);
}

std::string fmt(Vec2 p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.6g, %.6g)", p.x, p.y);
  return b;
}

// Millimetres per drawing unit for the HEADER's $INSUNITS (AutoCAD's codes); 0 where the
// code names no length unit Swarf accepts. Unitless drawings (0) are taken as mm, as before.
double mm_per_insunit(long code) {
  switch (code) {
    case 0:
    case 4:
      return 1.0;  // unitless, millimetres
    case 1:
      return 25.4;  // inches
    case 2:
      return 304.8;  // feet
    case 5:
      return 10.0;  // centimetres
    case 6:
      return 1000.0;  // metres
    case 8:
      return 25.4e-6;  // microinches
    case 9:
      return 0.0254;  // mils
    case 10:
      return 914.4;  // yards
    case 13:
      return 1e-3;  // microns
    case 14:
      return 100.0;  // decimetres
    default:
      return 0.0;
  }
}

}  // namespace

Result<Pocket> parse_pocket_dxf(std::string_view text, std::string_view source,
                                const CurveInputOptions& options) {
  const std::string src(source);
  std::vector<Pair> pairs;
  std::string error;
  if (!read_pairs(text, pairs, error)) return bad_input(src + ": " + error);
  // The drawing's unit ($INSUNITS in the HEADER section): coordinates are scaled to mm, and
  // the tolerances (mm) are used in drawing units until then. A drawing in inches read as mm
  // would come out 25.4 times too small.
  double unit_mm = 1.0;
  for (std::size_t k = 0; k + 1 < pairs.size(); ++k) {
    if (pairs[k].code == 0 && pairs[k].value == "SECTION" && pairs[k + 1].code == 2 &&
        pairs[k + 1].value == "ENTITIES")
      break;
    if (pairs[k].code != 9 || pairs[k].value != "$INSUNITS") continue;
    char* end = nullptr;
    const long code = std::strtol(pairs[k + 1].value.c_str(), &end, 10);
    unit_mm = pairs[k + 1].code == 70 && *end == '\0' ? mm_per_insunit(code) : 0.0;
    if (unit_mm <= 0.0) {
      return bad_input(src + ":" + std::to_string(pairs[k + 1].line) + ": $INSUNITS '" +
                       pairs[k + 1].value.substr(0, 20) +
                       "' is not a length unit Swarf reads (0, 1, 2, 4, 5, 6, 8, 9, 10, 13, 14)");
    }
  }
  const double tol = std::max(options.arc_tolerance_mm, 1e-6) / unit_mm;
  const double join = std::max(options.join_tolerance_mm, 1e-9) / unit_mm;
  // Find the ENTITIES section.
  std::size_t i = 0;
  for (; i + 1 < pairs.size(); ++i) {
    if (pairs[i].code == 0 && pairs[i].value == "SECTION" && pairs[i + 1].code == 2 &&
        pairs[i + 1].value == "ENTITIES")
      break;
  }
  if (i + 1 >= pairs.size()) return bad_input(src + ": no ENTITIES section");
  i += 2;
  std::vector<Ring> loops;
  std::vector<std::vector<Vec2>> chains;
  std::vector<std::size_t> chain_lines;
  auto add_polyline = [&](const std::vector<Vec2>& verts, const std::vector<double>& bulges,
                          bool closed, std::size_t line) {
    std::vector<Vec2> pts{verts[0]};
    for (std::size_t k = 0; k + 1 < verts.size(); ++k)
      append_bulge(pts, verts[k], verts[k + 1], bulges[k], tol);
    if (closed) {
      append_bulge(pts, verts.back(), verts[0], bulges.back(), tol);
      pts.pop_back();
      loops.push_back(std::move(pts));
    } else {
      chains.push_back(std::move(pts));
      chain_lines.push_back(line);
    }
  };
  while (i < pairs.size()) {
    if (pairs[i].code != 0) {
      ++i;
      continue;
    }
    const std::string type = pairs[i].value;
    const std::size_t line = pairs[i].line;
    if (type == "ENDSEC" || type == "EOF") break;
    std::size_t j = i + 1;
    std::vector<Pair> body;
    while (j < pairs.size() && pairs[j].code != 0)
      body.push_back(pairs[j++]);
    i = j;
    const std::string where = src + ":" + std::to_string(line) + ": " + type;
    auto num = [&](const Pair& p, double& v) { return to_double(p.value, v); };
    if (type == "LWPOLYLINE") {
      std::vector<Vec2> verts;
      std::vector<double> bulges;
      int flags = 0;
      for (std::size_t k = 0; k < body.size(); ++k) {
        double v = 0;
        const Pair& p = body[k];
        if (p.code == 70) flags = std::atoi(p.value.c_str());
        if (p.code == 10) {
          if (!num(p, v)) return bad_input(where + ": bad x at line " + std::to_string(p.line));
          verts.push_back({v, 0.0});
          bulges.push_back(0.0);
        } else if (p.code == 20 && !verts.empty()) {
          if (!num(p, v)) return bad_input(where + ": bad y at line " + std::to_string(p.line));
          verts.back().y = v;
        } else if (p.code == 42 && !bulges.empty()) {
          if (!num(p, v)) return bad_input(where + ": bad bulge at line " + std::to_string(p.line));
          bulges.back() = v;
        }
        if (verts.size() > 200000) return bad_input(where + ": too many vertices");
      }
      if (verts.size() < 2) return bad_input(where + ": fewer than 2 vertices");
      add_polyline(verts, bulges, (flags & 1) != 0, line);
    } else if (type == "POLYLINE") {
      // The older form (R12): VERTEX entities follow until SEQEND.
      int flags = 0;
      for (const Pair& p : body)
        if (p.code == 70) flags = std::atoi(p.value.c_str());
      std::vector<Vec2> verts;
      std::vector<double> bulges;
      while (i < pairs.size() && pairs[i].code == 0 && pairs[i].value == "VERTEX") {
        std::size_t k = i + 1;
        Vec2 v{0, 0};
        double bulge = 0.0, x = 0.0;
        int vflags = 0;
        for (; k < pairs.size() && pairs[k].code != 0; ++k) {
          const Pair& p = pairs[k];
          if (p.code == 10 || p.code == 20 || p.code == 42) {
            if (!num(p, x))
              return bad_input(where + ": bad VERTEX number at line " + std::to_string(p.line));
            (p.code == 10 ? v.x : p.code == 20 ? v.y : bulge) = x;
          } else if (p.code == 70) {
            vflags = std::atoi(p.value.c_str());
          }
        }
        i = k;
        if ((vflags & 16) != 0) continue;  // a spline frame control point, not on the curve
        verts.push_back(v);
        bulges.push_back(bulge);
        if (verts.size() > 200000) return bad_input(where + ": too many vertices");
      }
      if (i < pairs.size() && pairs[i].code == 0 && pairs[i].value == "SEQEND") ++i;
      if (verts.size() < 2) return bad_input(where + ": fewer than 2 vertices");
      add_polyline(verts, bulges, (flags & 1) != 0, line);
    } else if (type == "ELLIPSE") {
      double cx = 0, cy = 0, mx = 0, my = 0, ratio = 1, t0 = 0, t1 = 2 * kPi;
      for (const Pair& p : body) {
        double v = 0;
        if (p.code != 10 && p.code != 20 && p.code != 11 && p.code != 21 && p.code != 40 &&
            p.code != 41 && p.code != 42)
          continue;
        if (!num(p, v)) return bad_input(where + ": bad number at line " + std::to_string(p.line));
        (p.code == 10   ? cx
         : p.code == 20 ? cy
         : p.code == 11 ? mx
         : p.code == 21 ? my
         : p.code == 40 ? ratio
         : p.code == 41 ? t0
                        : t1) = v;
      }
      const double a = std::hypot(mx, my);
      if (!(a > 0.0) || !(ratio > 0.0) || ratio > 1.0 + 1e-9)
        return bad_input(where + ": needs a major axis and a ratio in (0, 1]");
      const Vec2 u{mx / a, my / a}, w = perp(u);
      const double b = a * ratio;
      auto at = [&](double t) {
        return Vec2{cx, cy} + u * (a * std::cos(t)) + w * (b * std::sin(t));
      };
      // Parameters modulo a turn (a loop adding turns would never end for 1e72).
      double sweep = std::fmod(t1 - t0, 2 * kPi);
      if (sweep <= 0.0) sweep += 2 * kPi;
      t0 = std::fmod(t0, 2 * kPi);
      const bool full = std::abs(sweep - 2 * kPi) < 1e-9;
      std::vector<Vec2> pts{at(t0)};
      // In quarters, so no piece's three test points can all miss its bulge.
      const int pieces = 4 * static_cast<int>(std::ceil(sweep / (0.5 * kPi)));
      for (int k = 0; k < pieces; ++k) {
        const double ta = t0 + sweep * k / pieces, tb = t0 + sweep * (k + 1) / pieces;
        sample_curve(pts, at, ta, pts.back(), tb, at(tb), tol);
      }
      if (full) {
        pts.pop_back();
        loops.push_back(std::move(pts));
      } else {
        chains.push_back(std::move(pts));
        chain_lines.push_back(line);
      }
    } else if (type == "SPLINE") {
      Nurbs c;
      int flags = 0;
      std::vector<Vec2> fit;
      for (const Pair& p : body) {
        double v = 0;
        if (p.code == 70) flags = std::atoi(p.value.c_str());
        if (p.code == 71) c.degree = std::atoi(p.value.c_str());
        if (p.code != 10 && p.code != 20 && p.code != 40 && p.code != 41 && p.code != 11 &&
            p.code != 21)
          continue;
        if (!num(p, v)) return bad_input(where + ": bad number at line " + std::to_string(p.line));
        if (p.code == 40) c.knots.push_back(v);
        if (p.code == 41) c.weights.push_back(v);
        if (p.code == 10) c.ctrl.push_back({v, 0.0});
        if (p.code == 20 && !c.ctrl.empty()) c.ctrl.back().y = v;
        if (p.code == 11) fit.push_back({v, 0.0});
        if (p.code == 21 && !fit.empty()) fit.back().y = v;
        if (c.ctrl.size() + c.knots.size() + fit.size() > 200000)
          return bad_input(where + ": too many points");
      }
      const std::size_t n = c.ctrl.size();
      const bool ok = c.degree >= 1 && c.degree <= 11 && n > static_cast<std::size_t>(c.degree) &&
                      c.knots.size() == n + static_cast<std::size_t>(c.degree) + 1 &&
                      (c.weights.empty() || c.weights.size() == n) &&
                      std::is_sorted(c.knots.begin(), c.knots.end());
      if (!ok) {
        return bad_input(where +
                         ": needs degree + 1 <= control points and knots = control points "
                         "+ degree + 1, non-decreasing (fit-point-only splines are not "
                         "supported: " +
                         std::to_string(fit.size()) + " fit points)");
      }
      for (double w : c.weights)
        if (!(w > 0.0)) return bad_input(where + ": weights must be positive");
      const double ta = c.knots[static_cast<std::size_t>(c.degree)];
      auto at = [&](double t) { return c.at(t); };
      std::vector<Vec2> pts{at(ta)};
      for (std::size_t k = static_cast<std::size_t>(c.degree); k < n; ++k) {  // per knot span
        const double u0 = c.knots[k], u1 = c.knots[k + 1];
        if (!(u1 > u0)) continue;
        // The last span's end, evaluated just inside it (de Boor's span search is half-open).
        const double e = k + 1 == n ? u1 - 1e-12 * std::max(1.0, std::abs(u1)) : u1;
        sample_curve(pts, at, u0, pts.back(), e, at(e), tol);
      }
      if (pts.size() > kMaxCurvePoints) return bad_input(where + ": too many points");
      if ((flags & 1) != 0 || distance(pts.front(), pts.back()) <= join) {
        pts.pop_back();
        loops.push_back(std::move(pts));
      } else {
        chains.push_back(std::move(pts));
        chain_lines.push_back(line);
      }
    } else if (type == "LINE" || type == "ARC" || type == "CIRCLE") {
      double x = 0, y = 0, x1 = 0, y1 = 0, r = 0, a0 = 0, a1 = 360;
      for (const Pair& p : body) {
        double v = 0;
        const bool wanted = p.code == 10 || p.code == 20 || p.code == 11 || p.code == 21 ||
                            p.code == 40 || p.code == 50 || p.code == 51;
        if (!wanted) continue;
        if (!num(p, v)) return bad_input(where + ": bad number at line " + std::to_string(p.line));
        switch (p.code) {
          case 10:
            x = v;
            break;
          case 20:
            y = v;
            break;
          case 11:
            x1 = v;
            break;
          case 21:
            y1 = v;
            break;
          case 40:
            r = v;
            break;
          case 50:
            a0 = v;
            break;
          default:
            a1 = v;
            break;
        }
      }
      if (type == "LINE") {
        chains.push_back({{x, y}, {x1, y1}});
        chain_lines.push_back(line);
        continue;
      }
      if (!(r > 0.0)) return bad_input(where + ": radius must be positive");
      if (type == "CIRCLE") {
        Ring ring;
        append_arc(ring, {x, y}, r, 0.0, 2 * kPi, tol);
        loops.push_back(std::move(ring));
        continue;
      }
      // ARC: counter-clockwise from start angle to end angle, degrees.
      double sweep = std::fmod(a1 - a0, 360.0);
      if (sweep <= 0.0) sweep += 360.0;
      a0 = std::fmod(a0, 360.0);
      const double s = deg_to_rad(a0);
      std::vector<Vec2> pts{{x + r * std::cos(s), y + r * std::sin(s)}};
      append_arc(pts, {x, y}, r, s, s + deg_to_rad(sweep), tol);
      chains.push_back(std::move(pts));
      chain_lines.push_back(line);
    }
    if (chains.size() + loops.size() > 100000) return bad_input(src + ": too many entities");
  }
  // Chain open pieces end to end. Greedy: a loop closes when its end meets its start.
  std::vector<bool> used(chains.size(), false);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (used[c]) continue;
    used[c] = true;
    std::vector<Vec2> loop = chains[c];
    while (distance(loop.front(), loop.back()) > join || loop.size() < 3) {
      bool found = false;
      for (std::size_t k = 0; k < chains.size() && !found; ++k) {
        if (used[k]) continue;
        const auto& ch = chains[k];
        if (distance(ch.front(), loop.back()) <= join) {
          loop.insert(loop.end(), ch.begin() + 1, ch.end());
          found = true;
        } else if (distance(ch.back(), loop.back()) <= join) {
          loop.insert(loop.end(), ch.rbegin() + 1, ch.rend());
          found = true;
        }
        if (found) used[k] = true;
      }
      if (!found) {
        if (loop.size() >= 3 && distance(loop.front(), loop.back()) <= join) break;
        return bad_input(src + ":" + std::to_string(chain_lines[c]) +
                         ": open outline: the chain starting at " + fmt(loop.front()) +
                         " ends at " + fmt(loop.back()) + " with nothing joining it");
      }
    }
    loop.pop_back();  // the closing point repeats the first
    loops.push_back(std::move(loop));
  }
  if (unit_mm != 1.0) {
    for (Ring& loop : loops) {
      for (Vec2& q : loop)
        q = q * unit_mm;
    }
  }
  return pocket::pocket_from_loops(std::move(loops), source);
}

}  // namespace swarf
