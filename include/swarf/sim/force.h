// The instantaneous rigid cutting-force model of seed 001 section 3.3 (Eq. 2-5, after
// Tlusty and MacNeil [29] and Altintas' ball-end formulation): the cutting edges of a flat,
// ball or bull-nose end mill are cut into elements along the axis (dz) and visited at
// rotation steps (dθ); each engaged element carries
//   dF_t = (K_tc h + K_te) db,  dF_r = (K_rc h + K_re) db,  dF_a = (K_ac h + K_ae) db
// with the uncut chip thickness h = f_t (n · f) (Eq. 3) and db the edge length of the element.
//
// Conventions (all forces act on the tool, machine axes, N):
// - The spindle turns clockwise seen from above (M3, right-hand cutter). An element's
//   angular position phi is measured counter-clockwise from +x; the tool turns so that phi
//   decreases with time. Altintas' immersion angle (clockwise from +y) is 90° - phi.
// - Element frame: outward surface normal n = (sinκ u_r, -cosκ) with u_r the radial unit
//   vector and κ the angle between the tool axis and n (90° on the cylinder, small near a
//   ball's tip); cutting velocity v = (sin phi, -cos phi, 0); meridian m = (-cosκ u_r, -sinκ).
//   dF = -dF_t v - dF_r n + dF_a m. This is Altintas' ball-end transformation; for κ = 90° it
//   gives Fx = -Ft cosθ - Fr sinθ, Fy = Ft sinθ - Fr cosθ (θ from +y) and Fz = -Fa. The
//   printed Eq. (4) of the paper has a sign slip in its F_y row; this frame is the one that
//   the paper's F_x and F_z rows and the literature agree on.
// - Helix lag: constant lead, psi(z) = z tan(β) / R (the standard ball-end formulation, also
//   used on the cylinder and the corner of a bull-nose); the edge at height z trails the tip.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/core/vec.h"
#include "swarf/tool/tool.h"

namespace swarf::sim {

/// Cutting coefficients of Eq. (2): cutting terms in N/mm^2, edge terms in N/mm.
/// Defaults are the paper's Table 4 (ø8 ball end mill in its validation material).
struct CuttingCoefficients {
  double ktc_n_mm2 = 935.62;
  double kte_n_mm = 2.0218;
  double krc_n_mm2 = 416.73;
  double kre_n_mm = 1.8238;
  double kac_n_mm2 = 2.72e-05;
  double kae_n_mm = 3.32e-06;
};

/// The cutter geometry the force model needs: a Tool plus the length of edge to model.
struct CutterGeometry {
  ToolKind kind = ToolKind::kBall;
  double radius_mm = 4.0;
  /// Corner radius: 0 flat, radius for ball, in (0, radius) for bull-nose.
  double corner_radius_mm = 4.0;
  int flutes = 2;
  double helix_deg = 30.0;
  /// Height of the cutting edges above the tip; no element is placed above it.
  double edge_length_mm = 20.0;
};
CutterGeometry cutter_from_tool(const Tool& tool);

struct ForceModelOptions {
  double axial_step_mm = 0.1;   ///< dz, the paper's axial resolution (Table 4)
  double angle_step_deg = 1.0;  ///< dθ, the paper's radial resolution (Table 4)
};

/// One axial element of an edge (the same for every flute).
struct EdgeLevel {
  double z_mm = 0.0;       ///< height of the element's midpoint above the tool tip
  double radius_mm = 0.0;  ///< distance of the midpoint from the axis
  double kappa_rad = 0.0;  ///< axial immersion angle κ between the axis and the normal
  double db_mm = 0.0;      ///< length of edge in the element (dz / sinκ in the limit)
  double lag_rad = 0.0;    ///< helix lag psi of the element
};

/// The discretised cutter. Angle index m of level k is the angular position
/// phi = lag_k - m dθ (mod 2π); at rotation step i flute j sits on index
/// (i + flute_offset(j)) mod steps_per_rev, so every visited point is an exact element.
class ForceModel {
 public:
  /// Validates the geometry and options (messages name the fault).
  static Result<ForceModel> create(const CutterGeometry& cutter, const CuttingCoefficients& k,
                                   const ForceModelOptions& options = {});

  const CutterGeometry& cutter() const { return cutter_; }
  const CuttingCoefficients& coefficients() const { return k_; }
  const std::vector<EdgeLevel>& levels() const { return levels_; }
  /// Rotation steps per revolution, 360 / dθ rounded.
  int steps_per_rev() const { return steps_; }
  double angle_step_rad() const { return dtheta_; }
  /// Index offset of flute j (j * steps / flutes, rounded).
  int flute_offset(int flute) const { return flute_offsets_[static_cast<std::size_t>(flute)]; }
  /// Angular position (CCW from +x) of angle index m at level k, radians in [0, 2π).
  double angle_of(std::size_t level, int index) const;
  /// Element position relative to the tool tip and outward unit normal, at angle phi.
  Vec3 point(std::size_t level, double phi) const;
  Vec3 normal(std::size_t level, double phi) const;
  /// cos and sin of angle_of(level, index), precomputed.
  double cos_at(std::size_t level, int index) const {
    return cos_[level * static_cast<std::size_t>(steps_) + static_cast<std::size_t>(index)];
  }
  double sin_at(std::size_t level, int index) const {
    return sin_[level * static_cast<std::size_t>(steps_) + static_cast<std::size_t>(index)];
  }
  /// Force on the tool from one element at angle phi cutting a chip of thickness h (Eq. 2, 4).
  /// h <= 0 gives zero (the element is not cutting).
  Vec3 element_force(std::size_t level, double phi, double h_mm) const;
  /// The same split into the part proportional to h (cutting) and the edge part.
  void element_force_parts(std::size_t level, double phi, double h_mm, Vec3& cutting,
                           Vec3& edge) const;

 private:
  CutterGeometry cutter_;
  CuttingCoefficients k_;
  std::vector<EdgeLevel> levels_;
  std::vector<int> flute_offsets_;
  std::vector<double> cos_, sin_;  ///< of angle_of(k, m), levels x steps
  int steps_ = 360;
  double dtheta_ = 0.0;
};

/// Whether an element (position relative to the tool tip) lies in material.
using EngagementTest = std::function<bool(std::size_t level, Vec3 point_rel_tip)>;

/// Element forces of one tool position: table[k * steps + m] is the force of level k at angle
/// index m, zero where the element is outside material or its chip thickness is not positive.
/// Feed per tooth in mm, feed direction a unit vector (the tool's direction of travel).
struct ElementTable {
  std::vector<Vec3> cutting;  ///< parts proportional to the chip thickness
  std::vector<Vec3> edge;     ///< edge-force parts
  std::vector<unsigned char> engaged;
  /// Levels evaluated (the rest are zero): those that can reach the stock.
  std::size_t levels_used = 0;
};
/// `max_levels` limits the evaluation to the lowest levels (those that can reach material).
/// Levels are evaluated on `threads` threads (0: all cores; `inside` must then be safe to
/// call concurrently); the table does not depend on the thread count.
ElementTable element_table(const ForceModel& model, double feed_per_tooth_mm, Vec3 feed_dir,
                           const EngagementTest& inside, std::size_t max_levels = SIZE_MAX,
                           int threads = 1);

/// Total force (Eq. 5) at rotation step `step`: the sum over levels and flutes.
Vec3 total_force(const ForceModel& model, const ElementTable& table, long step);
/// Same, the cutting and edge parts separately.
void total_force_parts(const ForceModel& model, const ElementTable& table, long step, Vec3& cutting,
                       Vec3& edge);
/// Mean force over one revolution (all rotation steps) for a fixed engagement.
Vec3 mean_force(const ForceModel& model, const ElementTable& table);
/// Engaged arc of level k at this position: engaged angle indices times dθ, degrees.
double engaged_arc_deg(const ForceModel& model, const ElementTable& table, std::size_t level);

}  // namespace swarf::sim
