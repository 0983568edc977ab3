// seed 001 section 4.2: cutting coefficients from test cuts, by linear least squares.
#include "swarf/sim/coefficients.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace swarf::sim {

namespace {

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r'))
    ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r'))
    --b;
  return std::string(s.substr(a, b - a));
}

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == ',') {
      out.push_back(trim(line.substr(start, i - start)));
      start = i + 1;
    }
  }
  return out;
}

bool parse_number(const std::string& s, double& v) {
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, v);
  return ec == std::errc() && p == end && std::isfinite(v);
}

}  // namespace

Result<std::vector<TestCut>> parse_test_cuts(std::string_view csv, std::string_view source,
                                             double tool_diameter_mm) {
  const std::array<const char*, 7> required = {
      "spindle_rpm", "feed_mm_min", "axial_depth_mm", "radial_depth_mm", "fx_n", "fy_n", "fz_n"};
  std::map<std::string, std::size_t> col;
  std::vector<TestCut> cuts;
  std::istringstream in{std::string(csv)};
  std::string line;
  int line_no = 0;
  bool have_header = false;
  const std::string src(source);
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = split(t);
    const std::string where = src + ":" + std::to_string(line_no);
    if (!have_header) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        col[cells[i]] = i;
      for (const char* name : required) {
        if (!col.count(name)) {
          return bad_input(where + ": header lacks column \"" + name +
                           "\" (need spindle_rpm, feed_mm_min, axial_depth_mm, radial_depth_mm, "
                           "fx_n, fy_n, fz_n[, mode])");
        }
      }
      have_header = true;
      continue;
    }
    std::array<double, 7> v{};
    for (std::size_t i = 0; i < required.size(); ++i) {
      const std::size_t c = col[required[i]];
      if (c >= cells.size() || !parse_number(cells[c], v[i])) {
        return bad_input(where + ": column \"" + required[i] + "\" is not a number");
      }
    }
    TestCut cut;
    cut.spindle_rpm = v[0];
    cut.feed_mm_min = v[1];
    cut.axial_depth_mm = v[2];
    cut.radial_depth_mm = v[3];
    cut.mean_force_n = {v[4], v[5], v[6]};
    if (!(cut.spindle_rpm > 0 && cut.feed_mm_min > 0 && cut.axial_depth_mm > 0 &&
          cut.radial_depth_mm > 0)) {
      return bad_input(where + ": spindle speed, feed and depths must be positive");
    }
    cut.mode = cut.radial_depth_mm >= tool_diameter_mm ? CutMode::kSlot : CutMode::kDown;
    if (col.count("mode") && col["mode"] < cells.size() && !cells[col["mode"]].empty()) {
      const std::string& m = cells[col["mode"]];
      if (m == "slot")
        cut.mode = CutMode::kSlot;
      else if (m == "up")
        cut.mode = CutMode::kUp;
      else if (m == "down")
        cut.mode = CutMode::kDown;
      else
        return bad_input(where + ": mode \"" + m + "\" is not slot, up or down");
    }
    cuts.push_back(cut);
  }
  if (cuts.empty()) return bad_input(src + ": no test cuts");
  return cuts;
}

Vec3 predicted_mean_force(const ForceModel& model, const TestCut& cut) {
  const double radius = model.cutter().radius_mm;
  const double ft = cut.feed_mm_min / (cut.spindle_rpm * model.cutter().flutes);
  const double wall = radius - cut.radial_depth_mm;  // distance of the side wall from the axis
  const ElementTable t = element_table(model, ft, {1, 0, 0}, [&](std::size_t, Vec3 p) {
    if (p.z > cut.axial_depth_mm) return false;
    switch (cut.mode) {
      case CutMode::kSlot:
        return true;
      case CutMode::kUp:
        return p.y >= wall;
      case CutMode::kDown:
        return p.y <= -wall;
    }
    return false;
  });
  return mean_force(model, t);
}

namespace {

// Solves min |A x - b| by Householder QR; A is rows x 6 (row-major). Returns false when
// a column is (numerically) dependent on the others.
bool least_squares6(std::vector<std::array<double, 6>> a, std::vector<double> b,
                    std::array<double, 6>& x) {
  const std::size_t m = a.size();
  constexpr int n = 6;
  std::array<double, n> diag{};
  double max_diag = 0.0;
  for (int j = 0; j < n; ++j) {
    double s = 0.0;
    for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
      s += a[i][j] * a[i][j];
    double alpha = std::sqrt(s);
    if (alpha == 0.0) return false;
    if (a[static_cast<std::size_t>(j)][j] > 0) alpha = -alpha;
    // v = a_j - alpha e_j, stored in place.
    a[static_cast<std::size_t>(j)][j] -= alpha;
    double vnorm2 = 0.0;
    for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
      vnorm2 += a[i][j] * a[i][j];
    for (int c = j + 1; c < n; ++c) {
      double d = 0.0;
      for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
        d += a[i][j] * a[i][c];
      const double f = 2.0 * d / vnorm2;
      for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
        a[i][c] -= f * a[i][j];
    }
    double d = 0.0;
    for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
      d += a[i][j] * b[i];
    const double f = 2.0 * d / vnorm2;
    for (std::size_t i = static_cast<std::size_t>(j); i < m; ++i)
      b[i] -= f * a[i][j];
    diag[j] = alpha;
    max_diag = std::max(max_diag, std::abs(alpha));
  }
  for (int j = 0; j < n; ++j) {
    if (std::abs(diag[j]) < 1e-9 * max_diag) return false;
  }
  for (int j = n - 1; j >= 0; --j) {
    double s = b[static_cast<std::size_t>(j)];
    for (int c = j + 1; c < n; ++c)
      s -= a[static_cast<std::size_t>(j)][c] * x[c];
    x[j] = s / diag[j];
  }
  return true;
}

}  // namespace

Result<CoefficientFit> fit_coefficients(const std::vector<TestCut>& cuts,
                                        const CutterGeometry& cutter,
                                        const ForceModelOptions& options) {
  if (cuts.size() < 2) return bad_input("coefficient fit: need at least two test cuts");
  // Column c of the design matrix: the predicted mean forces with coefficient c = 1 and the
  // others 0 (the model is linear in the coefficients).
  std::array<std::vector<Vec3>, 6> unit;
  for (int c = 0; c < 6; ++c) {
    std::array<double, 6> kv{};
    kv[c] = 1.0;
    const CuttingCoefficients k{kv[0], kv[1], kv[2], kv[3], kv[4], kv[5]};
    for (const TestCut& cut : cuts) {
      CutterGeometry g = cutter;
      g.edge_length_mm = std::max(options.axial_step_mm, cut.axial_depth_mm);
      Result<ForceModel> model = ForceModel::create(g, k, options);
      if (!model.ok()) return model.status();
      unit[c].push_back(predicted_mean_force(*model, cut));
    }
  }
  // Scale columns to unit norm: cutting terms (N/mm^2) and edge terms (N/mm) differ by
  // orders of magnitude.
  std::array<double, 6> scale{};
  for (int c = 0; c < 6; ++c) {
    double s = 0.0;
    for (const Vec3& v : unit[c])
      s += norm_sq(v);
    scale[c] = s > 0.0 ? 1.0 / std::sqrt(s) : 0.0;
    if (s == 0.0) {
      return bad_input("coefficient fit: the test cuts do not load coefficient " +
                       std::to_string(c));
    }
  }
  std::vector<std::array<double, 6>> a;
  std::vector<double> b;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      std::array<double, 6> row{};
      for (int c = 0; c < 6; ++c)
        row[c] = unit[c][i][axis] * scale[c];
      a.push_back(row);
      b.push_back(cuts[i].mean_force_n[axis]);
    }
  }
  std::array<double, 6> x{};
  if (!least_squares6(a, b, x)) {
    return bad_input(
        "coefficient fit: the test cuts leave a coefficient undetermined (use at least two "
        "feeds per geometry so cutting and edge terms separate)");
  }
  CoefficientFit fit;
  fit.coefficients = {x[0] * scale[0], x[1] * scale[1], x[2] * scale[2],
                      x[3] * scale[3], x[4] * scale[4], x[5] * scale[5]};
  const std::array<double, 6> k = {fit.coefficients.ktc_n_mm2, fit.coefficients.kte_n_mm,
                                   fit.coefficients.krc_n_mm2, fit.coefficients.kre_n_mm,
                                   fit.coefficients.kac_n_mm2, fit.coefficients.kae_n_mm};
  double ss = 0.0;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    Vec3 p;
    for (int c = 0; c < 6; ++c)
      p += unit[c][i] * k[c];
    fit.predicted_n.push_back(p);
    const Vec3 r = cuts[i].mean_force_n - p;
    fit.residual_n.push_back(r);
    ss += norm_sq(r);
    fit.max_residual_n =
        std::max({fit.max_residual_n, std::abs(r.x), std::abs(r.y), std::abs(r.z)});
  }
  fit.rms_residual_n = std::sqrt(ss / (3.0 * static_cast<double>(cuts.size())));
  return fit;
}

std::string coefficients_to_json(const CuttingCoefficients& k) {
  nlohmann::json j;
  j["ktc_n_mm2"] = k.ktc_n_mm2;
  j["kte_n_mm"] = k.kte_n_mm;
  j["krc_n_mm2"] = k.krc_n_mm2;
  j["kre_n_mm"] = k.kre_n_mm;
  j["kac_n_mm2"] = k.kac_n_mm2;
  j["kae_n_mm"] = k.kae_n_mm;
  return j.dump(2) + "\n";
}

Result<CuttingCoefficients> parse_coefficients_json(std::string_view text,
                                                    std::string_view source) {
  const std::string src(source);
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return bad_input(src + ": not a JSON object");
  if (j.contains("coefficients") && j["coefficients"].is_object()) j = j["coefficients"];
  CuttingCoefficients k;
  const std::array<std::pair<const char*, double*>, 6> keys = {{{"ktc_n_mm2", &k.ktc_n_mm2},
                                                                {"kte_n_mm", &k.kte_n_mm},
                                                                {"krc_n_mm2", &k.krc_n_mm2},
                                                                {"kre_n_mm", &k.kre_n_mm},
                                                                {"kac_n_mm2", &k.kac_n_mm2},
                                                                {"kae_n_mm", &k.kae_n_mm}}};
  for (const auto& [name, dst] : keys) {
    if (!j.contains(name)) continue;
    if (!j[name].is_number()) return bad_input(src + ": \"" + name + "\" must be a number");
    *dst = j[name].get<double>();
    if (!std::isfinite(*dst)) return bad_input(src + ": \"" + name + "\" is not finite");
  }
  return k;
}

}  // namespace swarf::sim
