// SVG pocket reader: a small tokenizer over the elements a CAD or drawing program writes
// for flat outlines. Not a full XML parser: comments and CDATA are skipped, attributes are
// read from each element's start tag.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "pocket/geometry.h"
#include "pocket/pocket_input_internal.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {

namespace {

using pocket::append_arc;

struct Element {
  std::string name;
  std::string tag;  // the start tag text, attributes included
  std::size_t line = 1;
};

std::size_t line_of(std::string_view text, std::size_t pos) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < pos && i < text.size(); ++i)
    if (text[i] == '\n') ++line;
  return line;
}

std::vector<Element> elements(std::string_view text) {
  std::vector<Element> out;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string_view::npos) {
    if (text.substr(i, 4) == "<!--") {
      const std::size_t e = text.find("-->", i + 4);
      if (e == std::string_view::npos) break;
      i = e + 3;
      continue;
    }
    if (text.substr(i, 9) == "<![CDATA[") {
      const std::size_t e = text.find("]]>", i + 9);
      if (e == std::string_view::npos) break;
      i = e + 3;
      continue;
    }
    const std::size_t e = text.find('>', i);
    if (e == std::string_view::npos) break;
    std::size_t k = i + 1;
    while (k < e && (std::isalnum(static_cast<unsigned char>(text[k])) || text[k] == ':' ||
                     text[k] == '_' || text[k] == '-'))
      ++k;
    Element el{std::string(text.substr(i + 1, k - i - 1)), std::string(text.substr(k, e - k)),
               line_of(text, i)};
    out.push_back(std::move(el));
    i = e + 1;
  }
  return out;
}

// The value of attribute `name` in a start tag, if present.
bool attribute(const std::string& tag, const std::string& name, std::string& value) {
  std::size_t pos = 0;
  while ((pos = tag.find(name, pos)) != std::string::npos) {
    const bool starts = pos == 0 || std::isspace(static_cast<unsigned char>(tag[pos - 1]));
    std::size_t k = pos + name.size();
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k])))
      ++k;
    if (starts && k < tag.size() && tag[k] == '=') {
      ++k;
      while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k])))
        ++k;
      if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\'')) return false;
      const char q = tag[k];
      const std::size_t end = tag.find(q, k + 1);
      if (end == std::string::npos) return false;
      value = tag.substr(k + 1, end - k - 1);
      return true;
    }
    pos += name.size();
  }
  return false;
}

// Number and flag scanner for points="..." and d="..." (SVG number grammar: "1-2", ".5.5",
// "1e-3" and flags written without separators all occur in the wild).
class Scanner {
 public:
  explicit Scanner(const std::string& s) : s_(s) {}
  void skip() {
    while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])) || s_[i_] == ','))
      ++i_;
  }
  bool at_end() {
    skip();
    return i_ >= s_.size();
  }
  bool at_number() {
    skip();
    if (i_ >= s_.size()) return false;
    const char c = s_[i_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  }
  char command() {
    skip();
    return i_ < s_.size() ? s_[i_++] : '\0';
  }
  bool number(double& v) {
    skip();
    std::size_t k = i_;
    if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
    bool digits = false, dot = false;
    while (k < s_.size()) {
      const char c = s_[k];
      if (std::isdigit(static_cast<unsigned char>(c))) {
        digits = true;
      } else if (c == '.' && !dot) {
        dot = true;
      } else {
        break;
      }
      ++k;
    }
    if (!digits) return false;
    if (k < s_.size() && (s_[k] == 'e' || s_[k] == 'E')) {
      std::size_t e = k + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (e < s_.size() && std::isdigit(static_cast<unsigned char>(s_[e]))) {
        while (e < s_.size() && std::isdigit(static_cast<unsigned char>(s_[e])))
          ++e;
        k = e;
      }
    }
    v = std::strtod(s_.substr(i_, k - i_).c_str(), nullptr);
    i_ = k;
    return std::isfinite(v);
  }
  bool flag(bool& f) {
    skip();
    if (i_ < s_.size() && (s_[i_] == '0' || s_[i_] == '1')) {
      f = s_[i_++] == '1';
      return true;
    }
    return false;
  }

 private:
  const std::string& s_;
  std::size_t i_ = 0;
};

// SVG implementation notes F.6.5: endpoint to centre parameterization, then chords.
void append_svg_arc(std::vector<Vec2>& out, Vec2 p1, double rx, double ry, double phi_deg,
                    bool large, bool sweep, Vec2 p2, double tol) {
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx < 1e-12 || ry < 1e-12 || distance(p1, p2) < 1e-12) {
    out.push_back(p2);
    return;
  }
  const double phi = deg_to_rad(phi_deg);
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 d = (p1 - p2) * 0.5;
  const Vec2 q{c * d.x + s * d.y, -s * d.x + c * d.y};
  const double lambda = q.x * q.x / (rx * rx) + q.y * q.y / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
  const double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
  double k = den > 0.0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
  if (large == sweep) k = -k;
  const Vec2 cq{k * rx * q.y / ry, -k * ry * q.x / rx};
  const Vec2 mid = (p1 + p2) * 0.5;
  const Vec2 centre{c * cq.x - s * cq.y + mid.x, s * cq.x + c * cq.y + mid.y};
  const double t1 = std::atan2((q.y - cq.y) / ry, (q.x - cq.x) / rx);
  const double t2 = std::atan2((-q.y - cq.y) / ry, (-q.x - cq.x) / rx);
  double dt = t2 - t1;
  if (sweep && dt < 0) dt += 2 * kPi;
  if (!sweep && dt > 0) dt -= 2 * kPi;
  std::vector<Vec2> unit;
  append_arc(unit, {0, 0}, std::max(rx, ry), t1, t1 + dt, tol);
  const double r = std::max(rx, ry);
  for (std::size_t i = 0; i + 1 < unit.size(); ++i) {
    const double ex = unit[i].x / r * rx, ey = unit[i].y / r * ry;
    out.push_back({c * ex - s * ey + centre.x, s * ex + c * ey + centre.y});
  }
  out.push_back(p2);  // exact end point
}

// Bezier segments flattened by de Casteljau halving until the control points lie within
// tol of the chord (the curve lies in their hull, so it is then within tol of the chord).
void append_cubic(std::vector<Vec2>& out, Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double tol,
                  int depth = 0) {
  if (depth >= 18 || std::max(pocket::point_line_distance(p1, p0, p3),
                              pocket::point_line_distance(p2, p0, p3)) <= tol) {
    out.push_back(p3);
    return;
  }
  const Vec2 a = (p0 + p1) * 0.5, b = (p1 + p2) * 0.5, c = (p2 + p3) * 0.5;
  const Vec2 ab = (a + b) * 0.5, bc = (b + c) * 0.5, m = (ab + bc) * 0.5;
  append_cubic(out, p0, a, ab, m, tol, depth + 1);
  append_cubic(out, m, bc, c, p3, tol, depth + 1);
}

void append_quadratic(std::vector<Vec2>& out, Vec2 p0, Vec2 p1, Vec2 p2, double tol) {
  // Degree elevation: the same curve as a cubic.
  append_cubic(out, p0, p0 + (p1 - p0) * (2.0 / 3.0), p2 + (p1 - p2) * (2.0 / 3.0), p2, tol);
}

struct PathResult {
  std::vector<Ring> loops;
  std::string error;
};

PathResult parse_path(const std::string& d, double tol) {
  PathResult res;
  Scanner sc(d);
  std::vector<Vec2> cur;
  Vec2 pos{0, 0}, start{0, 0};
  Vec2 last_control{0, 0};  // second control point of the last C/S, control of the last Q/T
  char cmd = '\0', prev = '\0';
  auto close_loop = [&](bool explicit_close) {
    if (cur.size() >= 2) {
      if (!explicit_close && distance(cur.front(), cur.back()) > 1e-6) {
        res.error = "open subpath from (" + std::to_string(cur.front().x) + ", " +
                    std::to_string(cur.front().y) + ") to (" + std::to_string(cur.back().x) + ", " +
                    std::to_string(cur.back().y) + ") is not closed";
        return;
      }
      res.loops.push_back(cur);
    } else if (!cur.empty() && explicit_close) {
      res.error = "closed subpath with a single point";
      return;
    }
    cur.clear();
  };
  while (!sc.at_end() && res.error.empty()) {
    if (!sc.at_number()) {
      cmd = sc.command();
      if (cmd == 'Z' || cmd == 'z') {
        close_loop(true);
        pos = start;
        prev = 'Z';
        continue;
      }
    } else if (cmd == '\0' || cmd == 'Z' || cmd == 'z') {
      res.error = "number without a command";
      break;
    }
    const bool rel = std::islower(static_cast<unsigned char>(cmd)) != 0;
    const Vec2 base = rel ? pos : Vec2{0, 0};
    double a = 0, b = 0;
    switch (std::toupper(static_cast<unsigned char>(cmd))) {
      case 'M':
        if (!sc.number(a) || !sc.number(b)) {
          res.error = "M needs x y";
          break;
        }
        if (!cur.empty()) close_loop(false);
        if (!res.error.empty()) break;
        pos = base + Vec2{a, b};
        start = pos;
        cur.push_back(pos);
        cmd = rel ? 'l' : 'L';  // further pairs are line-tos
        break;
      case 'L':
        if (!sc.number(a) || !sc.number(b)) {
          res.error = "L needs x y";
          break;
        }
        pos = base + Vec2{a, b};
        cur.push_back(pos);
        break;
      case 'H':
        if (!sc.number(a)) {
          res.error = "H needs x";
          break;
        }
        pos = {rel ? pos.x + a : a, pos.y};
        cur.push_back(pos);
        break;
      case 'V':
        if (!sc.number(a)) {
          res.error = "V needs y";
          break;
        }
        pos = {pos.x, rel ? pos.y + a : a};
        cur.push_back(pos);
        break;
      case 'A': {
        double rx, ry, rot, x, y;
        bool large, sweep;
        if (!sc.number(rx) || !sc.number(ry) || !sc.number(rot) || !sc.flag(large) ||
            !sc.flag(sweep) || !sc.number(x) || !sc.number(y)) {
          res.error = "A needs rx ry rotation large-arc sweep x y";
          break;
        }
        if (cur.empty()) cur.push_back(pos);
        const Vec2 to = base + Vec2{x, y};
        append_svg_arc(cur, pos, rx, ry, rot, large, sweep, to, tol);
        pos = to;
        break;
      }
      case 'C':
      case 'S':
      case 'Q':
      case 'T': {
        // Bezier segments. S and T take their first control point as the reflection of the
        // previous segment's last one (the current point when the previous command was not
        // of their kind).
        const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
        const bool cubic = up == 'C' || up == 'S', smooth = up == 'S' || up == 'T';
        double v[6] = {0, 0, 0, 0, 0, 0};
        const int count = (cubic ? 4 : 2) + (smooth ? 0 : 2);
        bool ok = true;
        for (int k = 0; k < count && ok; ++k)
          ok = sc.number(v[k]);
        if (!ok) {
          res.error = std::string(1, up) + " needs " +
                      (up == 'C'   ? "x1 y1 x2 y2 x y"
                       : up == 'S' ? "x2 y2 x y"
                       : up == 'Q' ? "x1 y1 x y"
                                   : "x y");
          break;
        }
        if (cur.empty()) cur.push_back(pos);
        const bool after = cubic ? (prev == 'C' || prev == 'S') : (prev == 'Q' || prev == 'T');
        const Vec2 first =
            smooth ? (after ? pos * 2.0 - last_control : pos) : base + Vec2{v[0], v[1]};
        const int o = smooth ? 0 : 2;  // where the numbers after the first control point start
        const Vec2 to = base + Vec2{v[count - 2], v[count - 1]};
        if (cubic) {
          const Vec2 second = base + Vec2{v[o], v[o + 1]};
          append_cubic(cur, pos, first, second, to, tol);
          last_control = second;
        } else {
          append_quadratic(cur, pos, first, to, tol);
          last_control = first;
        }
        pos = to;
        break;
      }
      default:
        res.error = std::string("path command '") + cmd + "' is not supported";
    }
    prev = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
    if (cur.size() > 200000) res.error = "path too long";
  }
  if (res.error.empty() && !cur.empty()) close_loop(false);
  return res;
}

bool points_attr(const std::string& text, std::vector<Vec2>& pts) {
  Scanner sc(text);
  while (!sc.at_end()) {
    double x, y;
    if (!sc.number(x) || !sc.number(y)) return false;
    pts.push_back({x, y});
  }
  return true;
}

double num_attr(const std::string& tag, const char* name, bool& ok) {
  std::string v;
  if (!attribute(tag, name, v)) return 0.0;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || !std::isfinite(d)) ok = false;
  return d;
}

// A length with an absolute unit (mm, cm, in, pt, pc, px at 96 per inch) in mm; false for
// none, %, em or anything else (then the file's user units are taken as mm).
bool length_mm(const std::string& text, double& mm) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(v) || !(v > 0)) return false;
  std::string unit(end);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back())))
    unit.pop_back();
  const double per = unit == "mm"   ? 1.0
                     : unit == "cm" ? 10.0
                     : unit == "in" ? 25.4
                     : unit == "pt" ? 25.4 / 72.0
                     : unit == "pc" ? 25.4 / 6.0
                     : unit == "px" ? 25.4 / 96.0
                                    : 0.0;
  if (per == 0.0) return false;
  mm = v * per;
  return true;
}

// An SVG transform, x' = a x + c y + e, y' = b x + d y + f (the matrix(a b c d e f) order).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  Affine then(const Affine& inner) const {  // this * inner: inner applies first
    return {a * inner.a + c * inner.b,     b * inner.a + d * inner.b,
            a * inner.c + c * inner.d,     b * inner.c + d * inner.d,
            a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
};

// A transform attribute: a list of matrix, translate, scale, rotate, skewX, skewY, applied
// right to left (the first one listed is the outermost). Empty string on success.
std::string parse_transform(const std::string& text, Affine& out) {
  out = Affine{};
  std::size_t i = 0;
  while (true) {
    while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ','))
      ++i;
    if (i >= text.size()) return {};
    std::size_t k = i;
    while (k < text.size() && std::isalpha(static_cast<unsigned char>(text[k])))
      ++k;
    const std::string name = text.substr(i, k - i);
    while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k])))
      ++k;
    if (k >= text.size() || text[k] != '(') return "malformed transform \"" + text + "\"";
    const std::size_t close = text.find(')', k);
    if (close == std::string::npos) return "unclosed ( in transform \"" + text + "\"";
    const std::string args_text = text.substr(k + 1, close - k - 1);
    Scanner sc(args_text);
    std::vector<double> v;
    double x = 0;
    while (!sc.at_end()) {
      if (!sc.number(x) || v.size() >= 6) return "malformed numbers in " + name + "(...)";
      v.push_back(x);
    }
    Affine t;
    const std::size_t n = v.size();
    if (name == "matrix" && n == 6) {
      t = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (name == "translate" && (n == 1 || n == 2)) {
      t.e = v[0];
      t.f = n == 2 ? v[1] : 0.0;
    } else if (name == "scale" && (n == 1 || n == 2)) {
      t.a = v[0];
      t.d = n == 2 ? v[1] : v[0];
    } else if (name == "rotate" && (n == 1 || n == 3)) {
      const double r = deg_to_rad(v[0]), cs = std::cos(r), sn = std::sin(r);
      t = {cs, sn, -sn, cs, 0, 0};
      if (n == 3) {  // about (cx, cy): translate(cx, cy) rotate(a) translate(-cx, -cy)
        const Affine to{1, 0, 0, 1, v[1], v[2]}, back{1, 0, 0, 1, -v[1], -v[2]};
        t = to.then(t).then(back);
      }
    } else if (name == "skewX" && n == 1) {
      t.c = std::tan(deg_to_rad(v[0]));
    } else if (name == "skewY" && n == 1) {
      t.b = std::tan(deg_to_rad(v[0]));
    } else {
      return "unsupported transform " + name + " with " + std::to_string(n) + " numbers";
    }
    out = out.then(t);
    i = close + 1;
  }
}

}  // namespace

Result<Pocket> parse_pocket_svg(std::string_view text, std::string_view source,
                                const CurveInputOptions& options) {
  const std::string src(source);
  const double tol = std::max(options.arc_tolerance_mm, 1e-6);
  std::vector<Ring> loops;
  bool saw_svg = false;
  // Transforms of the enclosing groups (<g transform=...>, as drawing programs write
  // layers), outermost first; each entry is the composition down to that group.
  std::vector<Affine> groups{Affine{}};
  for (const Element& el : elements(text)) {
    const std::string where = src + ":" + std::to_string(el.line) + ": <" + el.name + ">";
    std::string v;
    if (el.name == "svg" && !saw_svg) {
      saw_svg = true;
      // User units are mm, unless the root says otherwise: a viewBox together with a width
      // in an absolute unit (as drawing programs write them) scales user units to mm.
      std::string vb, wv, hv;
      if (attribute(el.tag, "viewBox", vb) && attribute(el.tag, "width", wv)) {
        std::vector<double> box;
        Scanner sc(vb);
        double x = 0;
        while (box.size() < 5 && sc.number(x))
          box.push_back(x);
        double w_mm = 0.0, h_mm = 0.0;
        if (box.size() != 4 || !(box[2] > 0) || !(box[3] > 0))
          return bad_input(where + ": malformed viewBox \"" + vb + "\"");
        if (length_mm(wv, w_mm)) {
          const double sx = w_mm / box[2];
          const double sy =
              attribute(el.tag, "height", hv) && length_mm(hv, h_mm) ? h_mm / box[3] : sx;
          groups[0] = Affine{sx, 0, 0, sy, -sx * box[0], -sy * box[1]};
        }
      }
      continue;
    }
    const bool self_closing = !el.tag.empty() && el.tag.back() == '/';
    if (el.name.empty() && el.tag.rfind("/g", 0) == 0 &&
        (el.tag.size() == 2 || !std::isalnum(static_cast<unsigned char>(el.tag[2])))) {
      if (groups.size() > 1) groups.pop_back();
      continue;
    }
    if (el.name == "g") {
      Affine t;
      if (attribute(el.tag, "transform", v)) {
        const std::string err = parse_transform(v, t);
        if (!err.empty()) return bad_input(where + ": " + err);
      }
      if (!self_closing) groups.push_back(groups.back().then(t));
      continue;
    }
    const bool shape = el.name == "polygon" || el.name == "polyline" || el.name == "path" ||
                       el.name == "rect" || el.name == "circle" || el.name == "ellipse";
    if (!shape) continue;
    Affine local;
    if (attribute(el.tag, "transform", v)) {
      const std::string err = parse_transform(v, local);
      if (!err.empty()) return bad_input(where + ": " + err);
    }
    const Affine xf = groups.back().then(local);
    // Curves are flattened before the transform: to keep tol after it, divide by its
    // largest stretch (the larger singular value of the linear part).
    const double p2 = xf.a * xf.a + xf.b * xf.b + xf.c * xf.c + xf.d * xf.d;
    const double det = xf.a * xf.d - xf.b * xf.c;
    const double stretch =
        std::sqrt(0.5 * (p2 + std::sqrt(std::max(0.0, p2 * p2 - 4 * det * det))));
    if (!(stretch > 1e-9) || !std::isfinite(stretch))
      return bad_input(where + ": the transform collapses the shape");
    const double etol = tol / std::max(1.0, stretch);
    const std::size_t first_new = loops.size();
    if (el.name == "polygon" || el.name == "polyline") {
      std::vector<Vec2> pts;
      if (!attribute(el.tag, "points", v) || !points_attr(v, pts))
        return bad_input(where + ": missing or malformed points attribute");
      if (el.name == "polyline" && (pts.size() < 2 || distance(pts.front(), pts.back()) > 1e-6))
        return bad_input(where + ": polyline is open (its last point is not its first)");
      loops.push_back(std::move(pts));
    } else if (el.name == "path") {
      if (!attribute(el.tag, "d", v)) return bad_input(where + ": missing d attribute");
      PathResult pr = parse_path(v, etol);
      if (!pr.error.empty()) return bad_input(where + ": " + pr.error);
      for (Ring& r : pr.loops)
        loops.push_back(std::move(r));
    } else if (el.name == "rect") {
      bool ok = true;
      const double x = num_attr(el.tag, "x", ok), y = num_attr(el.tag, "y", ok);
      const double w = num_attr(el.tag, "width", ok), h = num_attr(el.tag, "height", ok);
      if (!ok || w <= 0 || h <= 0) return bad_input(where + ": malformed x, y, width or height");
      loops.push_back({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}});
    } else if (el.name == "circle") {
      bool ok = true;
      const double cx = num_attr(el.tag, "cx", ok), cy = num_attr(el.tag, "cy", ok);
      const double r = num_attr(el.tag, "r", ok);
      if (!ok || r <= 0) return bad_input(where + ": malformed cx, cy or r");
      Ring ring;
      append_arc(ring, {cx, cy}, r, 0.0, 2 * kPi, etol);
      loops.push_back(std::move(ring));
    } else {
      bool ok = true;
      const double cx = num_attr(el.tag, "cx", ok), cy = num_attr(el.tag, "cy", ok);
      const double rx = num_attr(el.tag, "rx", ok), ry = num_attr(el.tag, "ry", ok);
      if (!ok || rx <= 0 || ry <= 0) return bad_input(where + ": malformed cx, cy, rx or ry");
      // A circle of the larger radius, flattened to the tolerance, squeezed along one axis.
      const double r = std::max(rx, ry);
      Ring unit;
      append_arc(unit, {0, 0}, r, 0.0, 2 * kPi, etol);
      Ring ring;
      for (const Vec2& q : unit)
        ring.push_back({cx + q.x * rx / r, cy + q.y * ry / r});
      loops.push_back(std::move(ring));
    }
    for (std::size_t k = first_new; k < loops.size(); ++k) {
      for (Vec2& q : loops[k])
        q = xf.apply(q);
    }
    if (loops.size() > 10000) return bad_input(src + ": more than 10000 outlines");
  }
  if (!saw_svg) return bad_input(src + ": no <svg> element");
  for (Ring& r : loops) {
    for (Vec2& p : r)
      p.y = -p.y;  // SVG's y axis points down
  }
  return pocket::pocket_from_loops(std::move(loops), source);
}

}  // namespace swarf
