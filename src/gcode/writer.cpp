// G-code writer for four dialects (seed of the format: RS-274/NGC, NIST IR 6556). It knows
// nothing of strategies: it consumes Toolpaths (STYLE.md 5).
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "gcode/format.h"
#include "swarf/gcode/gcode.h"
#include "toolpath/arc_geometry.h"

namespace swarf {

std::string_view dialect_name(Dialect dialect) {
  switch (dialect) {
    case Dialect::kIso:
      return "iso";
    case Dialect::kFanuc:
      return "fanuc";
    case Dialect::kLinuxCnc:
      return "linuxcnc";
    case Dialect::kGrbl:
      return "grbl";
  }
  return "iso";
}

Result<Dialect> parse_dialect(std::string_view name) {
  std::string lower(name);
  for (char& c : lower)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (Dialect d : {Dialect::kIso, Dialect::kFanuc, Dialect::kLinuxCnc, Dialect::kGrbl}) {
    if (lower == dialect_name(d)) return d;
  }
  if (lower == "rs274" || lower == "ngc") return Dialect::kIso;
  return bad_parameter("unknown G-code dialect '" + std::string(name) +
                       "' (expected iso, fanuc, linuxcnc or grbl)");
}

namespace {

/// A letter and an integer ("T3", "G2"). Built by appending: GCC 12 reports a false
/// -Wrestrict on `"T" + std::to_string(n)` at -O3 (GCC bug 105329).
std::string word(char letter, long n) {
  std::string s(1, letter);
  s += std::to_string(n);
  return s;
}

/// Largest deviation of the lines that replace an arc grbl cannot run (helix, G18, G19).
constexpr double kGrblArcChordTolMm = 0.001;

class Writer {
 public:
  explicit Writer(const GcodeOptions& o) : o_(o) {
    decimals_ = std::clamp(o.decimals, 0, 9);
    line_numbers_ = o.line_numbers && o.dialect != Dialect::kGrbl;
    step_ = std::max(1, o.line_number_step);
    n_ = step_;
  }

  std::string run(std::span<const Toolpath> paths) {
    start_block();
    const Toolpath* prev = nullptr;
    for (const Toolpath& p : paths) {
      toolpath(p, prev);
      prev = &p;
    }
    end_block(prev);
    return std::move(out_);
  }

 private:
  bool fanuc() const { return o_.dialect == Dialect::kFanuc; }
  bool grbl() const { return o_.dialect == Dialect::kGrbl; }

  /// A comment safe for every dialect: no nested parentheses or line breaks, printable
  /// ASCII; upper case for Fanuc, whose older controls reject lower-case comments.
  std::string comment_text(std::string_view text) const {
    std::string s;
    for (char c : text) {
      if (c == '(') c = '[';
      if (c == ')') c = ']';
      if (c == '\n' || c == '\r' || c == '\t') c = ' ';
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
      if (fanuc()) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      s += c;
    }
    return "(" + s + ")";
  }

  void raw_line(std::string_view text) {
    out_ += text;
    out_ += '\n';
  }

  void comment(std::string_view text) { raw_line(comment_text(text)); }

  /// One block, with an N-word when asked for (Fanuc's 5-digit limit wraps around).
  void block(std::string_view words) {
    if (line_numbers_) {
      out_ += 'N';
      out_ += std::to_string(n_);
      out_ += ' ';
      n_ += step_;
      if (n_ > 99999) n_ = step_;
    }
    raw_line(words);
  }

  std::string num(double v) const { return detail::format_fixed(v, decimals_); }

  /// The value a control reads back from what we write, so later offsets (I, J, K) are
  /// measured from where the machine really is.
  static double read_back(const std::string& s) {
    double v = 0.0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return v;
  }

  void start_block() {
    switch (o_.dialect) {
      case Dialect::kFanuc: {
        raw_line("%");
        char buf[16];
        auto [end, ec] =
            std::to_chars(buf, buf + sizeof buf, std::clamp(o_.program_number, 1, 9999));
        std::string num_str(buf, end);
        num_str.insert(0, 4 - std::min<std::size_t>(4, num_str.size()), '0');
        std::string line = "O" + num_str;
        if (!o_.title.empty()) {
          line += ' ';
          line += comment_text(o_.title);
        }
        raw_line(line);
        block("G21 G90 G17 G40 G49 G80 G94 G54");
        break;
      }
      case Dialect::kLinuxCnc:
        if (!o_.title.empty()) comment(o_.title);
        block("G17 G21 G90 G94 G40 G49 G80 G54");
        block("G64 P" + num(std::max(0.0, o_.blend_tolerance_mm)));
        break;
      case Dialect::kGrbl:
        // Grbl has no G80 in its start-up needs (motion starts as G0) and no G64.
        if (!o_.title.empty()) comment(o_.title);
        block("G17 G21 G90 G94 G40 G49 G54");
        break;
      case Dialect::kIso:
        if (!o_.title.empty()) comment(o_.title);
        block("G21 G90 G17 G40 G49 G80 G94 G54");
        break;
    }
    plane_ = ArcPlane::kXY;
  }

  void tool_change(const Toolpath& p, const Toolpath* prev) {
    std::string desc = word('T', p.tool_number);
    if (p.tool_diameter_mm > 0.0) desc += " D" + detail::format_fixed(p.tool_diameter_mm, 3);
    if (!p.tool_description.empty()) desc += " " + p.tool_description;
    const bool same_tool = prev && prev->tool_number == p.tool_number;
    if (grbl()) {
      // Grbl has no tool changer (no M6, no T word): the operator changes the tool
      // during an M0 pause, after the spindle stops.
      if (!prev) {
        comment("tool " + desc);
      } else if (!same_tool) {
        block("M5");
        spindle_on_ = false;
        comment("change tool to " + desc + ", then resume");
        block("M0");
        forget_position();
      }
      return;
    }
    if (same_tool) return;
    if (prev) {
      block("M5");
      spindle_on_ = false;
    }
    comment("tool change: " + desc);
    block(word('T', p.tool_number) + " M6");
    block("G43 " + word('H', p.tool_number));
    forget_position();
  }

  /// A tool change may move the machine (changer position, operator jogging): nothing
  /// modal about the position is trusted afterwards.
  void forget_position() {
    pos_known_ = {};
    motion_ = -1;
  }

  void toolpath(const Toolpath& p, const Toolpath* prev) {
    if (!p.name.empty()) comment(p.name);
    tool_change(p, prev);
    const long rpm = std::lround(std::max(0.0, p.spindle_rpm));
    if (!spindle_on_ || rpm != rpm_) {
      block(word('S', rpm) + " M3");
      spindle_on_ = true;
      rpm_ = rpm;
    }
    if (!coolant_known_ || coolant_ != p.coolant) {
      block(p.coolant == Coolant::kFlood ? "M8" : (p.coolant == Coolant::kMist ? "M7" : "M9"));
      coolant_known_ = true;
      coolant_ = p.coolant;
    }
    // Safe approach: straight up to clearance before the first move in XY, wherever the
    // previous tool or the operator left the machine.
    clearance_ = p.clearance_z_mm;
    rapid_z(clearance_);
    for (std::size_t i = 0; i < p.moves.size(); ++i) {
      const Move& m = p.moves[i];
      if (i == 0 && m.kind == MoveKind::kRapid && m.end.z < clearance_) {
        // The first move starts from wherever the machine was (Toolpath::moves): go
        // across at clearance, then down, rather than diagonally down through anything.
        Move across = m;
        across.end.z = clearance_;
        linear(across);
      }
      move(m);
    }
    if (!pos_known_[2] || pos_[2] < clearance_) rapid_z(clearance_);
  }

  void end_block(const Toolpath* last) {
    if (!last) rapid_z(clearance_);
    block("M5");
    block("M9");
    block(o_.dialect == Dialect::kLinuxCnc ? "M2" : "M30");
    if (fanuc()) raw_line("%");
  }

  void rapid_z(double z) {
    std::string axes;
    axis_word(axes, 2, z, false);
    if (axes.empty()) return;
    std::string words = motion_word(0);
    if (!words.empty()) words += ' ';
    block(words + axes);
  }

  std::string motion_word(int g) {
    if (g == motion_) return {};
    motion_ = g;
    return word('G', g);
  }

  /// Appends " X..." when the written value changes (or always, when forced).
  void axis_word(std::string& words, int axis, double v, bool force) {
    static constexpr std::array<char, 3> kNames{'X', 'Y', 'Z'};
    const std::string s = num(v);
    if (!force && pos_known_[axis] && s == last_[axis]) return;
    if (!words.empty()) words += ' ';
    words += kNames[static_cast<std::size_t>(axis)];
    words += s;
    last_[axis] = s;
    pos_[axis] = read_back(s);
    pos_known_[axis] = true;
  }

  void feed_word(std::string& words, double feed) {
    const std::string s = detail::format_fixed(std::max(0.0, feed), 1);
    if (s == last_feed_) return;
    last_feed_ = s;
    words += " F" + s;
  }

  void linear(const Move& m) {
    const bool rapid = m.kind == MoveKind::kRapid;
    std::string axes;
    for (int a = 0; a < 3; ++a)
      axis_word(axes, a, m.end[a], false);
    if (axes.empty()) return;  // nothing moves once rounded
    std::string words = motion_word(rapid ? 0 : 1);
    if (!words.empty()) words += ' ';
    words += axes;
    if (!rapid) feed_word(words, m.feed_mm_min);
    block(words);
  }

  void move(const Move& m) {
    if (!m.is_arc()) return linear(m);
    const Vec3 start{pos_[0], pos_[1], pos_[2]};
    const detail::ArcGeometry g = detail::arc_geometry(start, m);
    // A helix is an arc whose written normal coordinate changes (start is the rounded
    // position the control knows).
    const bool helix = num(m.end[g.axes.w]) != num(start[g.axes.w]);
    const bool grbl_cannot = grbl() && (m.plane != ArcPlane::kXY || helix);
    // Equal start and end once rounded would make a full circle of what was a sliver.
    const bool sliver = std::abs(g.sweep) < kPi && num(start[g.axes.u]) == num(m.end[g.axes.u]) &&
                        num(start[g.axes.v]) == num(m.end[g.axes.v]);
    if (grbl_cannot || sliver) return linearise(m, g);
    std::string words;
    if (m.plane != plane_) {
      plane_ = m.plane;
      words = m.plane == ArcPlane::kXY ? "G17" : (m.plane == ArcPlane::kZX ? "G18" : "G19");
    }
    const std::string g_word = motion_word(m.clockwise ? 2 : 3);
    if (!g_word.empty()) words += (words.empty() ? "" : " ") + g_word;
    std::string axes;
    // Both plane axes always, so the arc's end never rests on modal state.
    for (int a = 0; a < 3; ++a) {
      axis_word(axes, a, m.end[a], a == g.axes.u || a == g.axes.v);
    }
    if (!words.empty()) words += ' ';
    words += axes;
    // Centre as I, J, K increments from the start the control knows (RS-274 default
    // G91.1); R is never written: it is ambiguous near 180 degrees and cannot do 360.
    static constexpr std::array<char, 3> kOffsetNames{'I', 'J', 'K'};
    for (int a : {std::min(g.axes.u, g.axes.v), std::max(g.axes.u, g.axes.v)}) {
      words += ' ';
      words += kOffsetNames[static_cast<std::size_t>(a)];
      words += num(m.center[a] - start[a]);
    }
    feed_word(words, m.feed_mm_min);
    block(words);
  }

  /// Lines within kGrblArcChordTolMm of the arc: the sagitta of a chord spanning angle t
  /// of radius r is r (1 - cos(t / 2)).
  void linearise(const Move& m, const detail::ArcGeometry& g) {
    const double r = std::max(g.start_radius, g.end_radius);
    double n = 1.0;
    if (r > kGrblArcChordTolMm) {
      const double max_step = 2.0 * std::acos(1.0 - kGrblArcChordTolMm / r);
      n = std::clamp(std::ceil(std::abs(g.sweep) / max_step), 1.0, 1e6);
    }
    const auto count = static_cast<int>(n);
    Move line = m;
    line.kind = MoveKind::kFeed;
    for (int i = 1; i <= count; ++i) {
      line.end = i == count ? m.end : detail::arc_point(g, static_cast<double>(i) / count);
      linear(line);
    }
  }

  const GcodeOptions& o_;
  std::string out_;
  int decimals_ = 4;
  bool line_numbers_ = false;
  int step_ = 10;
  int n_ = 10;
  int motion_ = -1;
  ArcPlane plane_ = ArcPlane::kXY;
  std::array<double, 3> pos_{};
  std::array<bool, 3> pos_known_{};
  std::array<std::string, 3> last_;
  std::string last_feed_;
  bool spindle_on_ = false;
  long rpm_ = 0;
  bool coolant_known_ = false;
  Coolant coolant_ = Coolant::kOff;
  double clearance_ = 5.0;
};

}  // namespace

std::string write_gcode(std::span<const Toolpath> paths, const GcodeOptions& options) {
  return Writer(options).run(paths);
}

std::string write_gcode(const Toolpath& path, const GcodeOptions& options) {
  return write_gcode(std::span<const Toolpath>(&path, 1), options);
}

}  // namespace swarf
