// seed 001 section 3.3, Eq. (2)-(5): cutting-edge elements and their forces.
#include "swarf/sim/force.h"

#include "swarf/core/parallel.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace swarf::sim {

CutterGeometry cutter_from_tool(const Tool& tool) {
  CutterGeometry c;
  c.kind = tool.kind;
  c.radius_mm = tool.diameter_mm * 0.5;
  switch (tool.kind) {
    case ToolKind::kFlat:
      c.corner_radius_mm = 0.0;
      break;
    case ToolKind::kBall:
      c.corner_radius_mm = c.radius_mm;
      break;
    case ToolKind::kBull:
      c.corner_radius_mm = tool.corner_radius_mm;
      break;
  }
  c.flutes = tool.flutes;
  c.helix_deg = tool.helix_angle_deg;
  c.edge_length_mm = tool.flute_length_mm;
  return c;
}

namespace {

// Point of the cutting profile at corner angle alpha (0 at the bottom, π/2 where the corner
// meets the cylinder), as (radius, height, kappa). The corner is a quarter circle of radius
// rc centred at (R - rc, rc); kappa equals alpha there (seed 001 Fig. 10a for the ball).
struct ProfilePoint {
  double r, z, kappa;
};

ProfilePoint corner_point(double radius, double rc, double alpha) {
  return {radius - rc + rc * std::sin(alpha), rc - rc * std::cos(alpha), alpha};
}

// Corner angle at height z (z <= rc).
double corner_alpha(double rc, double z) {
  return std::acos(std::clamp((rc - z) / rc, -1.0, 1.0));
}

}  // namespace

Result<ForceModel> ForceModel::create(const CutterGeometry& cutter, const CuttingCoefficients& k,
                                      const ForceModelOptions& options) {
  if (!(cutter.radius_mm > 0.0)) {
    return bad_parameter("force model: tool radius " + std::to_string(cutter.radius_mm) +
                         " mm must be positive");
  }
  if (cutter.corner_radius_mm < 0.0 || cutter.corner_radius_mm > cutter.radius_mm + 1e-12) {
    return bad_parameter("force model: corner radius " + std::to_string(cutter.corner_radius_mm) +
                         " mm must lie in [0, tool radius]");
  }
  if (cutter.flutes < 1 || cutter.flutes > 32) {
    return bad_parameter("force model: flutes " + std::to_string(cutter.flutes) +
                         " must be in 1..32");
  }
  if (!(std::abs(cutter.helix_deg) < 80.0)) {
    return bad_parameter("force model: helix angle " + std::to_string(cutter.helix_deg) +
                         " deg must lie in (-80, 80)");
  }
  if (!(cutter.edge_length_mm > 0.0)) {
    return bad_parameter("force model: cutting edge length must be positive");
  }
  if (!(options.axial_step_mm > 0.0) || options.axial_step_mm > cutter.edge_length_mm) {
    return bad_parameter("force model: axial step " + std::to_string(options.axial_step_mm) +
                         " mm must be positive and at most the edge length");
  }
  if (!(options.angle_step_deg > 0.0) || options.angle_step_deg > 30.0) {
    return bad_parameter("force model: angle step " + std::to_string(options.angle_step_deg) +
                         " deg must lie in (0, 30]");
  }
  ForceModel m;
  m.cutter_ = cutter;
  if (cutter.kind == ToolKind::kFlat) m.cutter_.corner_radius_mm = 0.0;
  if (cutter.kind == ToolKind::kBall) m.cutter_.corner_radius_mm = cutter.radius_mm;
  m.k_ = k;
  m.steps_ = std::max(1, static_cast<int>(std::lround(360.0 / options.angle_step_deg)));
  m.dtheta_ = 2.0 * kPi / m.steps_;
  for (int j = 0; j < cutter.flutes; ++j) {
    m.flute_offsets_.push_back(
        static_cast<int>(std::lround(static_cast<double>(j) * m.steps_ / cutter.flutes)));
  }

  const double radius = m.cutter_.radius_mm;
  const double rc = m.cutter_.corner_radius_mm;
  const double tan_helix = std::tan(deg_to_rad(cutter.helix_deg));
  const double dz = options.axial_step_mm;
  const auto n_levels = static_cast<std::size_t>(std::ceil(cutter.edge_length_mm / dz - 1e-9));
  for (std::size_t i = 0; i < n_levels; ++i) {
    const double z0 = static_cast<double>(i) * dz;
    const double z1 = std::min(cutter.edge_length_mm, z0 + dz);
    // Edge length of the element measured along the profile, and its arc-length midpoint:
    // exact where the paper's dz / sinκ diverges at a ball's tip (doing better than Eq. 2
    // there; the two agree in the limit dz -> 0).
    double s_arc = 0.0, a0 = 0.0, a1 = 0.0;
    if (rc > 0.0 && z0 < rc) {
      a0 = corner_alpha(rc, z0);
      a1 = corner_alpha(rc, std::min(z1, rc));
      s_arc = rc * (a1 - a0);
    }
    const double s_cyl = std::max(0.0, z1 - std::max(z0, rc));
    const double s = s_arc + s_cyl;
    EdgeLevel lv;
    lv.db_mm = s;
    const double half = 0.5 * s;
    if (half < s_arc) {
      const ProfilePoint p = corner_point(radius, rc, a0 + half / rc);
      lv.z_mm = p.z;
      lv.radius_mm = p.r;
      lv.kappa_rad = p.kappa;
    } else {
      lv.z_mm = std::max(z0, rc) + (half - s_arc);
      lv.radius_mm = radius;
      lv.kappa_rad = 0.5 * kPi;
    }
    lv.lag_rad = lv.z_mm * tan_helix / radius;
    m.levels_.push_back(lv);
  }
  m.cos_.resize(m.levels_.size() * static_cast<std::size_t>(m.steps_));
  m.sin_.resize(m.cos_.size());
  for (std::size_t lv = 0; lv < m.levels_.size(); ++lv) {
    for (int i = 0; i < m.steps_; ++i) {
      const double phi = m.angle_of(lv, i);
      const std::size_t idx = lv * static_cast<std::size_t>(m.steps_) + static_cast<std::size_t>(i);
      m.cos_[idx] = std::cos(phi);
      m.sin_[idx] = std::sin(phi);
    }
  }
  return m;
}

double ForceModel::angle_of(std::size_t level, int index) const {
  double phi = std::fmod(levels_[level].lag_rad - index * dtheta_, 2.0 * kPi);
  if (phi < 0.0) phi += 2.0 * kPi;
  return phi;
}

Vec3 ForceModel::point(std::size_t level, double phi) const {
  const EdgeLevel& lv = levels_[level];
  return {lv.radius_mm * std::cos(phi), lv.radius_mm * std::sin(phi), lv.z_mm};
}

Vec3 ForceModel::normal(std::size_t level, double phi) const {
  const double sk = std::sin(levels_[level].kappa_rad), ck = std::cos(levels_[level].kappa_rad);
  return {sk * std::cos(phi), sk * std::sin(phi), -ck};
}

void ForceModel::element_force_parts(std::size_t level, double phi, double h_mm, Vec3& cutting,
                                     Vec3& edge) const {
  if (!(h_mm > 0.0)) {
    cutting = edge = {};
    return;
  }
  const EdgeLevel& lv = levels_[level];
  const double sk = std::sin(lv.kappa_rad), ck = std::cos(lv.kappa_rad);
  const double cp = std::cos(phi), sp = std::sin(phi);
  const Vec3 v{sp, -cp, 0.0};               // cutting velocity (clockwise spindle)
  const Vec3 n{sk * cp, sk * sp, -ck};      // outward normal
  const Vec3 mer{-ck * cp, -ck * sp, -sk};  // meridian (axial force direction)
  // seed 001 Eq. (2) with the edge term of dF_t being K_te (the print has K_re), and Eq. (4)
  // as a vector sum in the element frame.
  const double db = lv.db_mm;
  cutting = (v * (-k_.ktc_n_mm2) - n * k_.krc_n_mm2 + mer * k_.kac_n_mm2) * (h_mm * db);
  edge = (v * (-k_.kte_n_mm) - n * k_.kre_n_mm + mer * k_.kae_n_mm) * db;
}

Vec3 ForceModel::element_force(std::size_t level, double phi, double h_mm) const {
  Vec3 c, e;
  element_force_parts(level, phi, h_mm, c, e);
  return c + e;
}

ElementTable element_table(const ForceModel& model, double feed_per_tooth_mm, Vec3 feed_dir,
                           const EngagementTest& inside, std::size_t max_levels, int threads) {
  const std::size_t steps = static_cast<std::size_t>(model.steps_per_rev());
  const std::size_t used = std::min(max_levels, model.levels().size());
  const std::size_t n = used * steps;
  ElementTable t;
  t.levels_used = used;
  t.cutting.assign(n, Vec3{});
  t.edge.assign(n, Vec3{});
  t.engaged.assign(n, 0);
  // Each level writes only its own rows of the table.
  auto level = [&](std::size_t k) {
    const EdgeLevel& lv = model.levels()[k];
    const double sk = std::sin(lv.kappa_rad), ck = std::cos(lv.kappa_rad);
    for (std::size_t m = 0; m < steps; ++m) {
      const double c = model.cos_at(k, static_cast<int>(m)),
                   s = model.sin_at(k, static_cast<int>(m));
      // seed 001 Eq. (3): h = S_t (n · f); only elements facing the feed cut.
      const double h =
          feed_per_tooth_mm * (sk * (c * feed_dir.x + s * feed_dir.y) - ck * feed_dir.z);
      if (!(h > 0.0)) continue;
      if (!inside(k, {lv.radius_mm * c, lv.radius_mm * s, lv.z_mm})) continue;
      const std::size_t idx = k * steps + m;
      // Eq. (2) and (4) as in element_force_parts, with the precomputed cos and sin.
      const Vec3 v{s, -c, 0.0}, nrm{sk * c, sk * s, -ck}, mer{-ck * c, -ck * s, -sk};
      const CuttingCoefficients& kc = model.coefficients();
      t.cutting[idx] =
          (v * (-kc.ktc_n_mm2) - nrm * kc.krc_n_mm2 + mer * kc.kac_n_mm2) * (h * lv.db_mm);
      t.edge[idx] = (v * (-kc.kte_n_mm) - nrm * kc.kre_n_mm + mer * kc.kae_n_mm) * lv.db_mm;
      t.engaged[idx] = 1;
    }
  };
  if (threads == 1 || used < 8) {
    for (std::size_t k = 0; k < used; ++k)
      level(k);
  } else {
    parallel_for(used, threads, level);
  }
  return t;
}

void total_force_parts(const ForceModel& model, const ElementTable& table, long step, Vec3& cutting,
                       Vec3& edge) {
  const long steps = model.steps_per_rev();
  cutting = edge = {};
  const std::size_t n_levels = table.levels_used;
  for (int j = 0; j < model.cutter().flutes; ++j) {
    long m = (step + model.flute_offset(j)) % steps;
    if (m < 0) m += steps;
    for (std::size_t k = 0; k < n_levels; ++k) {
      const std::size_t idx = k * static_cast<std::size_t>(steps) + static_cast<std::size_t>(m);
      cutting += table.cutting[idx];
      edge += table.edge[idx];
    }
  }
}

Vec3 total_force(const ForceModel& model, const ElementTable& table, long step) {
  Vec3 c, e;
  total_force_parts(model, table, step, c, e);
  return c + e;
}

Vec3 mean_force(const ForceModel& model, const ElementTable& table) {
  // Over a revolution every flute visits every index once, so the mean is the table's sum
  // times flutes / steps.
  Vec3 sum;
  for (std::size_t i = 0; i < table.cutting.size(); ++i)
    sum += table.cutting[i] + table.edge[i];
  return sum * (static_cast<double>(model.cutter().flutes) / model.steps_per_rev());
}

double engaged_arc_deg(const ForceModel& model, const ElementTable& table, std::size_t level) {
  const std::size_t steps = static_cast<std::size_t>(model.steps_per_rev());
  std::size_t count = 0;
  for (std::size_t m = 0; m < steps; ++m)
    count += table.engaged[level * steps + m];
  return rad_to_deg(static_cast<double>(count) * model.angle_step_rad());
}

}  // namespace swarf::sim
