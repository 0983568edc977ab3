// The issue's goal, as a test: on the benchmark pockets at full size (the L with islands,
// 100 x 80 mm, the same L without them, the star, and three outlines from real parts), the
// program the command line writes with the issue's own flags, read back and swept
// independently at the bench's resolution, holds the engagement within +-20 % of the target
// over at least 95 % of the cutting length, with no gouge, no full slot and under 0.5 mm^2 of
// reachable material left. The adaptive_test.cpp pockets are scaled down (and cut at 20 %
// stepover) to keep the suite short; these are the sizes bench/RESULTS-pocket.md reports.
// All six hold 95 %, by the sweep as corrected in session 49 (it read the arc lost where the
// tool runs along a wall differently on each side of the pocket, and missed the grazes of
// the skin the passes leave on the walls). Since session 57 (links keep twice the scallop
// height off the walls): Kiri:Moto 95.65 % (the closest), the L with islands 95.67 %
// (95.59 % from session 55, which rounded the passes' tight turns, 95.12 % from session 52,
// 94.98 % before, and 95.05 % before the sweep's correction, its floor until then), the
// plain L 97.47, the star 95.80, the PCB-vice bar 96.74, and a slice of opencamlib's mould
// cavity (ktoolcav.stl, added in session 56, a third real part no pocket code was tuned on)
// 96.66.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "cli/cli_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/core/vec.h"
#include "swarf/gcode/gcode.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

struct BenchmarkPocket {
  const char* name;
  const char* file;  // under tests/data/pocket; empty: written by the test, from make_json
  double diameter_mm;
  double stepover_mm;
  std::string (*make_json)() = nullptr;
};

constexpr double kWithinFloor = 0.95;  // the share of the cut that must lie within +-20 %

std::ostream& operator<<(std::ostream& os, const BenchmarkPocket& p) {
  return os << p.name;
}

// The bench's star: five points on R50 and five notches on R24, the first point on +y.
std::string star_json() {
  std::ostringstream os;
  os.precision(17);
  os << R"({"outer": [)";
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 == 0 ? 50.0 : 24.0;
    const double a = deg_to_rad(90.0 + 36.0 * k);
    os << (k ? ", " : "") << "[" << r * std::cos(a) << ", " << r * std::sin(a) << "]";
  }
  os << "]}";
  return os.str();
}

// The L of the bench without its islands (the issue lists the plain L apart).
std::string plain_l_json() {
  return R"({"outer": [[0, 0], [100, 0], [100, 40], [50, 40], [50, 80], [0, 80]]})";
}

// Runs the CLI on the pocket, reads its G-code back and sweeps it; checks that it is clean
// (no gouge past a checker pixel, no slot, under 0.5 mm^2 left). Empty when it could not run.
std::optional<testing::SweepReport> swept_cli_program(const BenchmarkPocket& bp) {
  testing::TempDir dir;
  std::string in;
  if (*bp.file) {
    in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/" + bp.file;
  } else {
    dir.write("pocket.json", bp.make_json());
    in = dir.file("pocket.json");
  }
  std::ostringstream flags;
  flags << "pocket " << in << " --tool flat:" << bp.diameter_mm << " --stepover " << bp.stepover_mm
        << " --depth 6 -o " << dir.file("out.nc");
  const auto run = testing::run_swarf(flags.str());
  auto pocket = read_pocket(in);
  auto program = read_gcode(dir.file("out.nc"));
  if (run.status != 0 || !pocket.ok() || !program.ok()) {
    ADD_FAILURE() << run.out << (pocket.ok() ? "" : pocket.status().to_string())
                  << (program.ok() ? "" : program.status().to_string());
    return std::nullopt;
  }
  // swarf_pocket_sweep's rule: 0.05 mm pixels, or a twentieth of the stepover where finer.
  const double r = 0.5 * bp.diameter_mm;
  const double target_deg = rad_to_deg(std::acos(1.0 - bp.stepover_mm / r));
  const double pixel = std::min(0.05, bp.stepover_mm / 20.0);
  const auto s = testing::sweep_check(pocket->region, r, *program, target_deg, pixel, 0.2);
  EXPECT_LE(s.max_gouge_mm, pixel);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  EXPECT_LT(s.residual_mm2, 0.5);
  return s;
}

class BenchmarkPockets : public ::testing::TestWithParam<BenchmarkPocket> {};

TEST_P(BenchmarkPockets, HoldTheBandOverNinetyFivePercentOfTheCut) {
  const auto s = swept_cli_program(GetParam());
  ASSERT_TRUE(s.has_value());
  std::printf("  %s: within +-20 %% over %.3f %% of %.0f mm of cut\n", GetParam().name,
              100.0 * s->within_20pct, s->cutting_length_mm);
  EXPECT_GE(s->within_20pct, kWithinFloor) << "cutting " << s->cutting_length_mm << " mm";
}

INSTANTIATE_TEST_SUITE_P(
    AtFullSize, BenchmarkPockets,
    ::testing::Values(BenchmarkPocket{"LWithIslands", "l_pocket_islands.json", 10.0, 1.0},
                      BenchmarkPocket{"KiriMoto", "kirimoto_pocket.json", 10.0, 1.0},
                      BenchmarkPocket{"PlainL", "", 10.0, 1.0, plain_l_json},
                      BenchmarkPocket{"Star", "", 10.0, 1.0, star_json},
                      BenchmarkPocket{"PcbViceBar", "pcbvicebar_slice.json", 6.0, 0.6},
                      BenchmarkPocket{"KtoolcavSlice", "ktoolcav_slice.json", 10.0, 1.0}),
    [](const ::testing::TestParamInfo<BenchmarkPocket>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace swarf
