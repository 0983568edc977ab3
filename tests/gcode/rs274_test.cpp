// Every dialect through LinuxCNC's standalone RS-274/NGC interpreter (`rs274`, Debian
// package linuxcnc-uspace): it must accept the program without an error, and the motion it
// reports (its canonical STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED calls) must be the
// motion our own reader sees, move by move. That checks the writer's syntax and the
// reader's semantics (R signs, planes, G91, G20) against an independent interpreter.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>

#include "gcode/gcode_test_util.h"
#include "swarf/gcode/gcode.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

std::optional<std::string> find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

struct CanonMove {
  bool rapid = false;
  bool arc = false;
  Vec3 end;
  Vec3 center;       // arcs: plane coordinates
  int rotation = 0;  // arcs: > 0 counter-clockwise, < 0 clockwise
};

struct Rs274Run {
  int status = -1;
  std::string errors;  // stderr lines other than its "executing" banner
  std::vector<CanonMove> moves;
};

class Rs274 : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto found = find_on_path("rs274");
    if (!found) GTEST_SKIP() << "rs274 (LinuxCNC, Debian linuxcnc-uspace) is not on PATH";
    rs274_ = *found;
    dir_ = fs::temp_directory_path() / ("swarf_rs274_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream table(dir_ / "tools.tbl");
    for (int t = 1; t <= 20; ++t)
      table << "T" << t << " P" << t << " D6.000 Z+0.000 ;tool\n";
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  Rs274Run run(const std::string& program, const std::string& name) {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << program;
    const fs::path out = dir_ / (name + ".out"), err = dir_ / (name + ".err");
    // rs274 keeps state outside its arguments (shared memory, a parameter file in the
    // working folder): concurrent runs from parallel ctest corrupt each other. Serialise
    // them with a lock file and run each in its own folder.
    const std::string cmd = "cd '" + dir_.string() + "' && flock /tmp/swarf_rs274.lock '" + rs274_ +
                            "' -g -t '" + (dir_ / "tools.tbl").string() + "' '" + file.string() +
                            "' > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
    Rs274Run r;
    const int raw = std::system(cmd.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream e(err);
    for (std::string line; std::getline(e, line);) {
      if (!line.empty() && line != "executing") r.errors += line + "\n";
    }
    // "  31 N..... ARC_FEED(0.0000, -10.0000, 0.0000, 0.0000, -1, -1.0000, 0, 0, 0)"
    const std::regex call(R"(([A-Z_]+)\((.*)\))");
    double unit = 1.0;
    int plane = 0;  // 0 XY, 1 XZ (G18), 2 YZ (G19)
    std::ifstream o(out);
    for (std::string line; std::getline(o, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, call)) continue;
      const std::string fn = m[1];
      std::vector<double> a;
      std::stringstream args(m[2]);
      for (std::string tok; std::getline(args, tok, ',');) {
        try {
          a.push_back(std::stod(tok));
        } catch (...) {
          a.push_back(0.0);
        }
      }
      const std::string text = m[2];
      if (fn == "USE_LENGTH_UNITS") unit = text.find("INCHES") != std::string::npos ? 25.4 : 1.0;
      if (fn == "SELECT_PLANE") {
        plane = text.find("XZ") != std::string::npos
                    ? 1
                    : (text.find("YZ") != std::string::npos ? 2 : 0);
      }
      if ((fn == "STRAIGHT_TRAVERSE" || fn == "STRAIGHT_FEED") && a.size() >= 3) {
        r.moves.push_back({fn == "STRAIGHT_TRAVERSE", false, Vec3{a[0], a[1], a[2]} * unit, {}, 0});
      } else if (fn == "ARC_FEED" && a.size() >= 6) {
        CanonMove c;
        c.arc = true;
        c.rotation = static_cast<int>(a[4]);
        // ARC_FEED(first end, second end, first centre, second centre, rotation, axis end):
        // first/second are X/Y in G17, Z/X in G18, Y/Z in G19.
        if (plane == 0) {
          c.end = {a[0], a[1], a[5]};
          c.center = {a[2], a[3], 0.0};
        } else if (plane == 1) {
          c.end = {a[1], a[5], a[0]};
          c.center = {a[3], 0.0, a[2]};
        } else {
          c.end = {a[5], a[0], a[1]};
          c.center = {0.0, a[2], a[3]};
        }
        c.end *= unit;
        c.center *= unit;
        r.moves.push_back(c);
      }
    }
    return r;
  }

  /// rs274 accepts the program and moves exactly as our reader says.
  void expect_accepted_and_same_motion(const std::string& program, const std::string& name) {
    SCOPED_TRACE(name);
    const Rs274Run r = run(program, name);
    EXPECT_EQ(r.status, 0) << r.errors << "\n" << program.substr(0, 2000);
    EXPECT_EQ(r.errors, "");
    const auto ours = parse_gcode(program, name);
    ASSERT_TRUE(ours.ok()) << ours.status().message();
    ASSERT_EQ(r.moves.size(), ours->moves.size());
    ASSERT_FALSE(r.moves.empty());
    for (std::size_t i = 0; i < r.moves.size(); ++i) {
      SCOPED_TRACE("move " + std::to_string(i));
      const CanonMove& c = r.moves[i];
      const Move& m = ours->moves[i];
      // rs274 prints 4 decimals.
      EXPECT_LE(distance(c.end, m.end), 2e-4);
      EXPECT_EQ(c.rapid, m.kind == MoveKind::kRapid);
      EXPECT_EQ(c.arc, m.is_arc());
      if (c.arc && m.is_arc()) {
        EXPECT_EQ(c.rotation < 0, m.clockwise);
        const detail::PlaneAxes ax = detail::plane_axes(m.plane);
        EXPECT_NEAR(c.center[ax.u], m.center[ax.u], 2e-4);
        EXPECT_NEAR(c.center[ax.v], m.center[ax.v], 2e-4);
      }
    }
  }

  std::string rs274_;
  fs::path dir_;
};

TEST_F(Rs274, AcceptsEveryDialectAndAgreesWithOurReader) {
  Toolpath first = testing::sample_path();
  Toolpath second = testing::sample_path();
  second.tool_number = 5;
  second.coolant = Coolant::kMist;
  const Toolpath both[] = {first, second};
  for (Dialect d : testing::kAllDialects) {
    for (bool numbers : {false, true}) {
      GcodeOptions o;
      o.dialect = d;
      o.line_numbers = numbers;
      o.title = "rs274 check";
      expect_accepted_and_same_motion(
          write_gcode(both, o), std::string(dialect_name(d)) + (numbers ? "_n" : "") + ".ngc");
    }
  }
}

TEST_F(Rs274, AcceptsRandomPaths) {
  std::mt19937 rng(4242);
  for (int trial = 0; trial < 3; ++trial) {
    const Toolpath p = testing::random_path(rng, 60);
    for (Dialect d : testing::kAllDialects) {
      GcodeOptions o;
      o.dialect = d;
      expect_accepted_and_same_motion(write_gcode(p, o), "random" + std::to_string(trial) + "_" +
                                                             std::string(dialect_name(d)) + ".ngc");
    }
  }
}

TEST_F(Rs274, ReaderSemanticsMatchLinuxCnc) {
  // Hand-written input the writer never produces: R arcs of both signs and directions,
  // other planes, incremental distances, inches, absolute arc centres.
  expect_accepted_and_same_motion(
      "G21 G90 G17 G0 X10 Y0 Z0\n"
      "G3 X0 Y10 R10 F100\n G0 X10 Y0\n G3 X0 Y10 R-10\n"
      "G0 X10 Y0\n G2 X0 Y10 R10\n G0 X10 Y0\n g2 x0 y10 r-10\n"
      "G0 X10 Y0 Z0\n G18 G2 X0 Z10 I-10 K0\n"
      "G19 G3 Y5 Z15 J0 K5\n"
      "G17 G90.1 G3 X-10 Y5 I-5 J5\n"
      "G91.1 G91 G2 X10 Y10 I0 J10\n"
      "G1 X1 Y-1 Z-2\n"
      "G90 G20 G0 X1 Y1 Z1\n G1 X1.5 F10\n G2 X2.5 Y1 I0.5 J0\n"
      "G21 M2\n",
      "reader.ngc");
}

TEST_F(Rs274, HomeReturnsAndMachineCoordinatesMatchLinuxCnc) {
  // LinuxCNC's defaults: G54 offset 0 and stored G28/G30 positions 0 (our defaults too).
  expect_accepted_and_same_motion(
      "G21 G90 G17 G0 X10 Y5 Z2\n"
      "G1 Z-3 F200\n"
      "G91 G28 Z0\n"
      "G90 G28 X4 Y3\n"
      "G0 X7 Y8 Z9\n"
      "G53 G0 Z20\n"
      "G53 G1 X1 Y1 F300\n"
      "G28.1\n"
      "G0 X0 Y0 Z5\n"
      "G28\n"
      "G30 Z12\n"
      "M2\n",
      "home.ngc");
}

TEST_F(Rs274, HandWrittenDataFileMatchesLinuxCnc) {
  std::ifstream in(SWARF_TEST_DATA_DIR "/gcode/rounded_rectangle.ngc");
  std::stringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  expect_accepted_and_same_motion(text.str(), "rounded_rectangle.ngc");
}

}  // namespace
}  // namespace swarf
