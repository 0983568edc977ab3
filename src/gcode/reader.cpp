// G-code reader for the subset Swarf writes and most CAM posts emit (RS-274/NGC, NIST IR
// 6556). Anything that would move the machine in a way this reader cannot follow (cutter
// compensation, canned cycles, stored positions, offsets set by the program) is an error
// naming the line, never a silently wrong toolpath.
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "swarf/gcode/gcode.h"
#include "toolpath/arc_geometry.h"

namespace swarf {
namespace {

constexpr double kMmPerInch = 25.4;
/// Larger numbers are typing errors, not machine coordinates, and would overflow later.
constexpr double kMaxValue = 1e9;
/// Start and end radii of an I/J/K arc may differ by this much before the program is
/// rejected (rounded coordinates in the file): max(abs, rel * radius). LinuxCNC is of the
/// same order.
constexpr double kArcRadiusTolMm = 0.01;
constexpr double kArcRadiusTolRel = 1e-3;
constexpr double kEpsMm = 1e-9;

/// "G2", "G91.1". Built by appending: GCC 12 reports a false -Wrestrict on
/// `"G" + std::to_string(n)` at -O3 (GCC bug 105329).
std::string fmt_g(int tenths) {
  std::string s = "G";
  s += std::to_string(tenths / 10);
  if (tenths % 10 != 0) {
    s += '.';
    s += std::to_string(tenths % 10);
  }
  return s;
}

class Reader {
 public:
  Reader(std::string_view source, const GcodeReadOptions& options)
      : source_(source),
        work_offset_(options.work_offset),
        g28_(options.g28_home),
        g30_(options.g30_home) {
    pos_ = options.start;
    tp_.name = std::string(source);
    tp_.spindle_rpm = 0.0;  // unknown until an S word
    tp_.coolant = Coolant::kOff;
    tp_.moves.clear();
  }

  Result<Toolpath> run(std::string_view text, const GcodeReadOptions& options) {
    std::size_t begin = 0;
    while (begin <= text.size() && !ended_) {
      std::size_t end = text.find('\n', begin);
      if (end == std::string_view::npos) end = text.size();
      ++line_;
      SWARF_RETURN_IF_ERROR(line(text.substr(begin, end - begin)));
      begin = end + 1;
    }
    // The clearance plane is taken as the highest point rapids reach.
    double clearance = options.start.z;
    for (const Move& m : tp_.moves) {
      if (m.kind == MoveKind::kRapid) clearance = std::max(clearance, m.end.z);
    }
    tp_.clearance_z_mm = clearance;
    return std::move(tp_);
  }

 private:
  Status error(const std::string& message) const {
    return bad_input(std::string(source_) + ":" + std::to_string(line_) + ": " + message);
  }

  /// Comments out, whitespace out (RS-274 ignores it, even inside numbers), upper case.
  Status clean(std::string_view raw, std::string& out) const {
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const char c = raw[i];
      if (c == ';') break;
      if (c == '(') {
        const std::size_t close = raw.find(')', i + 1);
        if (close == std::string_view::npos) return error("comment '(' without ')'");
        if (raw.substr(i + 1, close - i - 1).find('(') != std::string_view::npos) {
          return error("nested comment");
        }
        i = close;
        continue;
      }
      if (std::isspace(static_cast<unsigned char>(c))) continue;
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return {};
  }

  struct Words {
    std::vector<int> g;  // tenths: G90.1 = 901
    std::vector<int> m;
    std::array<std::optional<double>, 26> v;  // every other letter, by letter
    std::optional<double>& operator[](char letter) {
      return v[static_cast<std::size_t>(letter - 'A')];
    }
  };

  Status parse_words(const std::string& b, Words& w) const {
    std::size_t i = 0;
    while (i < b.size()) {
      const char letter = b[i];
      if (letter == '#' || letter == '[') {
        return error("parameters and expressions (# and [ ]) are not supported");
      }
      if (letter < 'A' || letter > 'Z') return error(std::string("unexpected '") + letter + "'");
      ++i;
      const std::size_t num_begin = i;
      if (i < b.size() && (b[i] == '+' || b[i] == '-')) ++i;
      std::size_t digits = 0;
      while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i])))
        ++i, ++digits;
      if (i < b.size() && b[i] == '.') {
        ++i;
        while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i])))
          ++i, ++digits;
      }
      if (digits == 0) return error(std::string("word ") + letter + " without a number");
      std::size_t from = num_begin;
      if (b[from] == '+') ++from;
      double value = 0.0;
      const auto [ptr, ec] = std::from_chars(b.data() + from, b.data() + i, value);
      if (ec != std::errc() || ptr != b.data() + i || !(std::abs(value) <= kMaxValue)) {
        return error(std::string("bad number in word ") + letter +
                     b.substr(num_begin, i - num_begin));
      }
      const double tenths = value * 10.0;
      const long rounded = std::lround(tenths);
      switch (letter) {
        case 'G':
          if (std::abs(tenths - static_cast<double>(rounded)) > 1e-6) {
            return error("unsupported G-code G" + b.substr(num_begin, i - num_begin));
          }
          w.g.push_back(static_cast<int>(rounded));
          break;
        case 'M':
          if (rounded % 10 != 0 || std::abs(tenths - static_cast<double>(rounded)) > 1e-6) {
            return error("unsupported M-code M" + b.substr(num_begin, i - num_begin));
          }
          w.m.push_back(static_cast<int>(rounded / 10));
          break;
        case 'N':
          break;  // line numbers carry no meaning for motion
        case 'A':
        case 'B':
        case 'C':
        case 'U':
        case 'V':
        case 'W':
          return error(std::string("axis ") + letter + " is not supported (X, Y, Z only)");
        case 'O':
          return error("O-word in the middle of a block");
        case 'D':
        case 'F':
        case 'H':
        case 'I':
        case 'J':
        case 'K':
        case 'L':
        case 'P':
        case 'Q':
        case 'R':
        case 'S':
        case 'T':
        case 'X':
        case 'Y':
        case 'Z':
          if (w[letter]) return error(std::string("two ") + letter + " words in one block");
          w[letter] = value;
          break;
        default:
          return error(std::string("unsupported word ") + letter);
      }
    }
    return {};
  }

  Status line(std::string_view raw) {
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    std::string b;
    SWARF_RETURN_IF_ERROR(clean(raw, b));
    // Block delete: executed, as LinuxCNC does with its switch off (its default).
    if (!b.empty() && b[0] == '/') b.erase(0, 1);
    if (b.empty() || b[0] == '%') return {};  // tape start / end marks
    if (b[0] == 'O') {
      // A Fanuc program number is fine; LinuxCNC's O-word subroutines and loops are not.
      std::size_t i = 1;
      while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i])))
        ++i;
      if (i == 1 || i != b.size()) {
        return error("O-word '" + b + "': subroutines and control flow are not supported");
      }
      return {};
    }
    if (b.find_first_of("#[") != std::string::npos) {
      return error("parameters and expressions (# and [ ]) are not supported");
    }
    Words w;
    SWARF_RETURN_IF_ERROR(parse_words(b, w));
    return execute(w);
  }

  Status modal_g(int g, int& motion_words) {
    switch (g) {
      case 0:
      case 10:
      case 20:
      case 30:
        ++motion_words;
        motion_ = g / 10;
        return {};
      case 800:
        ++motion_words;
        motion_ = -1;
        return {};
      case 40:   // dwell
      case 400:  // cutter compensation off
      case 430:
      case 431:
      case 432:
      case 490:  // tool length offsets: positions stay the tool tip's
      case 540:
      case 550:
      case 560:
      case 570:
      case 580:
      case 590:
      case 591:
      case 592:
      case 593:  // work offsets: the program's coordinates are what we read
      case 610:
      case 611:
      case 640:  // path control
      case 940:  // feed per minute (the only feed mode read)
      case 980:
      case 990:  // canned-cycle return levels, harmless without cycles
        return {};
      case 170:
        plane_ = ArcPlane::kXY;
        return {};
      case 180:
        plane_ = ArcPlane::kZX;
        return {};
      case 190:
        plane_ = ArcPlane::kYZ;
        return {};
      case 200:
        unit_ = kMmPerInch;
        return {};
      case 210:
        unit_ = 1.0;
        return {};
      case 900:
        absolute_ = true;
        return {};
      case 910:
        absolute_ = false;
        return {};
      case 901:
        arc_absolute_ = true;
        return {};
      case 911:
        arc_absolute_ = false;
        return {};
      case 410:
      case 420:
      case 411:
      case 421:
        return error(fmt_g(g) +
                     " (cutter radius compensation) is not supported: the tool "
                     "centre path would differ from the programmed one");
      case 730:
      case 760:
      case 810:
      case 820:
      case 830:
      case 840:
      case 850:
      case 860:
      case 870:
      case 880:
      case 890:
        return error(fmt_g(g) + " (canned cycle) is not supported");
      case 280:
      case 300:  // return to a stored position (non-modal, uses the axis words)
        ++motion_words;
        home_move_ = g / 10;
        return {};
      case 281:
        g28_ = pos_ + work_offset_;
        return {};
      case 301:
        g30_ = pos_ + work_offset_;
        return {};
      case 530:  // this block's axis words are machine coordinates
        machine_coords_ = true;
        return {};
      case 100:
      case 920:
      case 921:
      case 922:
      case 923:
        return error(fmt_g(g) + " changes coordinate offsets, which is not supported");
      case 930:
      case 950:
        return error(fmt_g(g) + ": only feed per minute (G94) is supported");
      default:
        return error("unsupported G-code " + fmt_g(g));
    }
  }

  Status execute(Words& w) {
    // RS-274/NGC order of execution: units, modes and feed before motion.
    int motion_words = 0;
    bool g80 = false;
    home_move_ = 0;
    machine_coords_ = false;
    for (int g : w.g) {
      SWARF_RETURN_IF_ERROR(modal_g(g, motion_words));
      g80 = g80 || g == 800;
    }
    if (motion_words > 1) return error("two motion G-codes in one block");
    if (auto f = w['F']) {
      if (*f < 0.0) return error("negative feed rate F");
      feed_ = *f * unit_;
    }
    if (auto s = w['S']) {
      if (*s < 0.0) return error("negative spindle speed S");
      if (tp_.spindle_rpm == 0.0) tp_.spindle_rpm = *s;
    }
    if (auto t = w['T']) {
      if (*t < 0.0 || *t != std::floor(*t)) return error("tool number T must be a whole number");
      if (!tool_seen_) tp_.tool_number = static_cast<int>(*t);
      tool_seen_ = true;
    }
    bool end = false;
    for (int m : w.m) {
      if ((m == 7 || m == 8) && !coolant_seen_) {
        tp_.coolant = m == 7 ? Coolant::kMist : Coolant::kFlood;
        coolant_seen_ = true;
      }
      end = end || m == 2 || m == 30;
    }
    const bool has_axes = w['X'] || w['Y'] || w['Z'];
    const bool has_arc_words = w['I'] || w['J'] || w['K'] || w['R'];
    const bool dwell = std::find(w.g.begin(), w.g.end(), 40) != w.g.end();
    if (home_move_ != 0) {
      SWARF_RETURN_IF_ERROR(return_home(w));
      ended_ = end;
      return {};
    }
    if (machine_coords_ && (motion_ < 0 || motion_ > 1)) {
      return error("G53 needs G0 or G1 active");
    }
    if (has_axes && !dwell) {
      if (g80) return error("axis words with G80 (motion cancelled)");
      if (motion_ < 0) return error("axis words without a motion mode (G0, G1, G2 or G3)");
      SWARF_RETURN_IF_ERROR(motion(w));
    } else if (motion_words == 1 && (motion_ == 2 || motion_ == 3) && has_arc_words) {
      SWARF_RETURN_IF_ERROR(motion(w));  // a full circle: I, J, K without an end point
    }
    ended_ = end;
    return {};
  }

  // G28 / G30: a rapid to the intermediate point given by the axis words (in the current
  // distance mode; where the tool is when there are none), then a rapid of those axes (all
  // three when none is given) to the stored position. As LinuxCNC does, checked by rs274.
  Status return_home(Words& w) {
    if (w['I'] || w['J'] || w['K'] || w['R']) return error("I, J, K or R word with G28/G30");
    const Vec3 home = (home_move_ == 28 ? g28_ : g30_) - work_offset_;
    static constexpr std::array<char, 3> kAxes{'X', 'Y', 'Z'};
    Vec3 mid = pos_, end = home;
    bool any = false;
    for (int a = 0; a < 3; ++a) {
      if (auto v = w[kAxes[static_cast<std::size_t>(a)]]) {
        mid[a] = absolute_ ? *v * unit_ : pos_[a] + *v * unit_;
        any = true;
      }
    }
    if (any) {
      for (int a = 0; a < 3; ++a)
        if (!w[kAxes[static_cast<std::size_t>(a)]]) end[a] = mid[a];
    }
    push_rapid(mid);
    push_rapid(end);
    return {};
  }

  void push_rapid(Vec3 to) {
    Move m;
    m.kind = MoveKind::kRapid;
    m.cutting = false;
    m.end = to;
    m.feed_mm_min = feed_;
    tp_.moves.push_back(m);
    pos_ = to;
  }

  Status motion(Words& w) {
    Vec3 target = pos_;
    static constexpr std::array<char, 3> kAxes{'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
      if (auto v = w[kAxes[static_cast<std::size_t>(a)]]) {
        target[a] = machine_coords_ ? *v * unit_ - work_offset_[a]
                    : absolute_     ? *v * unit_
                                    : pos_[a] + *v * unit_;
      }
    }
    Move m;
    m.end = target;
    m.feed_mm_min = feed_;
    if (motion_ == 0) {
      m.kind = MoveKind::kRapid;
      m.cutting = false;
      if (w['I'] || w['J'] || w['K'] || w['R']) return error("I, J, K or R word with G0");
    } else {
      if (!(feed_ > 0.0)) return error(fmt_g(motion_ * 10) + " without a feed rate (F)");
      if (motion_ == 1) {
        if (w['I'] || w['J'] || w['K'] || w['R']) return error("I, J, K or R word with G1");
        const double dz = target.z - pos_.z;
        const double dxy = distance(target.xy(), pos_.xy());
        m.kind =
            dz < -kEpsMm ? (dxy > kEpsMm ? MoveKind::kRamp : MoveKind::kPlunge) : MoveKind::kFeed;
      } else {
        SWARF_RETURN_IF_ERROR(arc(w, m));
      }
    }
    tp_.moves.push_back(m);
    pos_ = target;
    return {};
  }

  Status arc(Words& w, Move& m) {
    const std::string name = fmt_g(motion_ * 10);
    const detail::PlaneAxes ax = detail::plane_axes(plane_);
    static constexpr std::array<char, 3> kOffsets{'I', 'J', 'K'};
    const char normal_word = kOffsets[static_cast<std::size_t>(ax.w)];
    if (w[normal_word]) {
      return error(std::string(1, normal_word) + " word in a " +
                   (plane_ == ArcPlane::kXY ? "G17" : (plane_ == ArcPlane::kZX ? "G18" : "G19")) +
                   " arc");
    }
    const char ou = kOffsets[static_cast<std::size_t>(ax.u)];
    const char ov = kOffsets[static_cast<std::size_t>(ax.v)];
    m.clockwise = motion_ == 2;
    m.plane = plane_;
    const Vec2 s{pos_[ax.u], pos_[ax.v]};
    const Vec2 e{m.end[ax.u], m.end[ax.v]};
    Vec2 c;
    if (auto r_word = w['R']) {
      if (w[ou] || w[ov]) return error(name + " with both R and I, J, K");
      // Radius format: R > 0 the arc of at most 180 degrees, R < 0 the longer one. The
      // centre lies on the chord's bisector, left of it for a short counter-clockwise arc.
      const double r = *r_word * unit_;
      const Vec2 d = e - s;
      const double chord = norm(d);
      if (chord < kEpsMm) return error(name + " with R and the same start and end point");
      const double half = 0.5 * chord;
      if (std::abs(r) < half - kArcRadiusTolMm) {
        return error(name + " radius R is smaller than half the distance to the end point");
      }
      const double h = std::sqrt(std::max(0.0, r * r - half * half));
      const double side = (m.clockwise ? -1.0 : 1.0) * (r > 0.0 ? 1.0 : -1.0);
      c = (s + e) * 0.5 + perp(d) / chord * (side * h);
    } else if (w[ou] || w[ov]) {
      const double iu = w[ou].value_or(0.0) * unit_;
      const double iv = w[ov].value_or(0.0) * unit_;
      c = arc_absolute_ ? Vec2{iu, iv} : s + Vec2{iu, iv};
      const double rs = distance(s, c), re = distance(e, c);
      if (rs < kEpsMm) return error(name + " with a zero radius (centre at the start point)");
      if (std::abs(rs - re) > std::max(kArcRadiusTolMm, kArcRadiusTolRel * rs)) {
        return error(name + ": the end point is " + std::to_string(std::abs(rs - re)) +
                     " mm off the arc's circle");
      }
    } else {
      return error(name + " without I, J, K or R");
    }
    m.center = pos_;
    m.center[ax.u] = c.x;
    m.center[ax.v] = c.y;
    m.kind = std::abs(m.end[ax.w] - pos_[ax.w]) > kEpsMm ? MoveKind::kHelix : MoveKind::kArc;
    return {};
  }

  std::string_view source_;
  Vec3 work_offset_;             ///< machine coordinates of the program origin
  Vec3 g28_, g30_;               ///< stored positions, machine coordinates
  int home_move_ = 0;            ///< 28 or 30 in a block that returns home
  bool machine_coords_ = false;  ///< G53 in this block
  int line_ = 0;
  Toolpath tp_;
  Vec3 pos_;
  double unit_ = 1.0;  ///< mm per program unit
  bool absolute_ = true;
  bool arc_absolute_ = false;  ///< G90.1; RS-274's default is incremental I, J, K (G91.1)
  ArcPlane plane_ = ArcPlane::kXY;
  int motion_ = -1;  ///< 0..3, -1 before any or after G80
  double feed_ = 0.0;
  bool tool_seen_ = false;
  bool coolant_seen_ = false;
  bool ended_ = false;
};

}  // namespace

Result<Toolpath> parse_gcode(std::string_view text, std::string_view source_name,
                             const GcodeReadOptions& options) {
  return Reader(source_name, options).run(text, options);
}

Result<Toolpath> read_gcode(const std::string& path, const GcodeReadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(Error::kIo, path + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Status(Error::kIo, path + ": read error");
  return parse_gcode(ss.str(), path, options);
}

}  // namespace swarf
