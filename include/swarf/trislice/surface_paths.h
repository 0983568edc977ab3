// Ball-end toolpaths from the tri-slice model (seed 001 section 3.1): scanning (raster)
// paths from the top of the model inflated by the tool radius, with the roughing scheme of
// Table 1, and contour (waterline) paths from its inflated xy slices. Positions are tool tips.
#pragma once

#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/mesh/mesh.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/toolpath.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/model.h"
#include "swarf/trislice/offset.h"

namespace swarf {

inline constexpr double kAuto = std::numeric_limits<double>::quiet_NaN();

struct ScanParams {
  Axis direction = Axis::kX;  ///< kX: lines at constant y, cutting along x; kY the other way
  bool zigzag = false;        ///< false: one-way (Table 1), every line in the + direction
  double stepover_mm = 0.25;  ///< radial depth of cut between lines (Table 1 finishing)
  double sampling_mm = 0.1;   ///< CL point spacing along a line before simplification
  /// Adaptive sampling along the lines (as OpenCAMLib's AdaptivePathDropCutter): the CL
  /// points lie on the sampling_mm lattice of the uniform grid, but only every
  /// 2^k-th one (2^k * sampling <= adaptive_max_step_mm, 2^k >= 8) is evaluated first; a stretch is
  /// halved, down to sampling_mm, while its evaluated midpoint leaves the chord by more than
  /// adaptive_tolerance_mm. false: every lattice point (the uniform grid). See
  /// docs/trislice.md for the argument and the test against the uniform grid.
  bool adaptive = true;
  double adaptive_max_step_mm = 1.6;
  double adaptive_tolerance_mm = 0.001;  ///< vertical, mm; the gouge it may leave
  /// The adaptive tolerance is raised to this fraction of the model's own error at its pitch,
  /// trislice_height_error_bound_mm (sampling a line finer than the model is accurate buys
  /// nothing): with 1 and a ø8 ball, 5.1 um at ds = 0.25 mm, 1.3 um at 0.125 mm, and the
  /// 1 um above at 0.05 mm and finer. 0: adaptive_tolerance_mm as given.
  double adaptive_model_fraction = 1.0;
  /// Adaptive only: below the lattice where a stretch steeper than 3:1 still leaves its
  /// chord by more than tol / 2 (normal to it), down to 2 um. Beside a wall the CL jumps, and
  /// the straight move between two lattice points across the jump ran through the wall's top
  /// (70 um into a block at 0.1 mm sampling); now at most the last step's width (2-4 um).
  /// Like vertex_mesh, an addition to the paper's path that the CLI turns on; false (the
  /// default): lattice points only.
  bool refine_steep = false;
  double stock_to_leave_mm = 0.0;
  Box2 region;                  ///< tool-axis area; empty: the model's xy bounds
  double tolerance_mm = 0.001;  ///< simplification of each line (chordal), 0 = keep all
  double feed_mm_min = 1000.0;
  double plunge_feed_mm_min = 300.0;
  double clearance_z_mm = kAuto;  ///< default: 5 mm above the model (or stock) top
  double floor_z_mm = kAuto;      ///< tip height where nothing lies under the tool: model bottom
  /// Optional: the part's mesh (must outlive the call). Its vertices and its fold edges (where
  /// the surface turns under as seen from above: wall rims, equators) then hold the ball up
  /// exactly as well. The slices miss a sharp convex vertex lying between them by up to about
  /// a pitch, a first-order error (a box corner off the slice lattice: 30 um vertical, 15 um
  /// into the part at pitch 0.05 mm, bench/surface_stress.sh), and a ball grazing a fold
  /// touches it over a patch narrower than the pitch, so it fell past it (5.9 mm on the
  /// Table 2 part at 0.05 mm); other edges and faces between slices cost only second-order
  /// errors. Both are points of the solid, so this never lifts the CL above the exact drop.
  /// nullptr: the tri-slice model alone (seed 001).
  const Mesh* vertex_mesh = nullptr;
};

/// Table 1 roughing: `layers` scans over the model inflated by r + margin + k * stepdown,
/// k = layers-1 down to 0, each clipped to the stock top.
struct RoughingParams {
  int layers = 5;
  double stepdown_mm = 2.0;     ///< axial depth of cut
  double stepover_mm = 2.0;     ///< radial depth of cut
  double margin_mm = 0.1;       ///< stock left for finishing
  double stock_top_mm = kAuto;  ///< default: the model top
  /// Roughing reads every k-th slice so that its pitch is at least this; 0 = every slice. Its
  /// error at 0.25 mm (offset.h bound 5 um for R = 4.1 mm; 28 um at the worst crease of the
  /// Table 2 part, less for the larger radii of the upper layers) is far inside the margin,
  /// and the queries with radii up to r + margin + 8 mm visit ~5x fewer slices than at 0.05.
  double min_pitch_mm = 0.25;
  /// CL spacing along roughing lines: the chord between two points of an offset surface of
  /// radius >= r + margin sags at most s^2 / (8 (r + margin)) (8 um at 0.5 mm, r = 4), far
  /// inside the margin. 0 = the scan's own sampling.
  double sampling_mm = 0.5;
  /// Adaptive tolerance of the roughing lines when ScanParams::adaptive (vertical, mm): far
  /// inside the margin, like the chord sag above.
  double adaptive_tolerance_mm = 0.005;
  double adaptive_max_step_mm = 8.0;  ///< first-pass CL spacing of the roughing lines
};

struct ContourParams {
  double stepdown_mm = 1.0;  ///< between waterline levels (tip heights)
  double stock_to_leave_mm = 0.0;
  int radial_passes = 1;  ///< rings per level: the offset contour and k * radial_step outside
  double radial_step_mm = 2.0;
  double top_z_mm = kAuto;     ///< highest tip level; default: model top - stepdown
  double bottom_z_mm = kAuto;  ///< lowest tip level; default: model bottom
  double arc_tolerance_mm = 0.001;
  double feed_mm_min = 1000.0;
  double plunge_feed_mm_min = 300.0;
  double clearance_z_mm = kAuto;
  /// Optional: the part's mesh (must outlive the call). The heights of its horizontal edges
  /// and of its peaks (vertices above all their neighbours) are then sliced as well: a
  /// feature that crosses no slice (the top edge of a step between two levels, a peak) is
  /// otherwise missed by up to a pitch, a first-order error (a block top off the lattice:
  /// the ball 20 um into the part at pitch 0.05 mm). nullptr: the tri-slice model alone.
  const Mesh* critical_mesh = nullptr;
};

/// offset.h's bound on how far Eq. (1) can leave the ball centre below the true offset
/// surface, ds^2 / (8 R sin^2(theta) n_z), at the tri-slice worst case: the best of the three
/// families sees every surface at theta >= 54.7 deg (normal (1, 1, 1) / sqrt 3, where also
/// n_z = 1 / sqrt 3), so 3 sqrt(3) ds^2 / (16 R). R = ball radius + offset, mm. It holds on
/// smooth parts of the surface; creases and walls parallel to a family escape it (offset.h).
double trislice_height_error_bound_mm(double pitch_mm, double radius_mm);

/// The adaptive tolerance a scan uses on a model of pitch `pitch_mm` with a ball of radius
/// `radius_mm` (+ offset): max(adaptive_tolerance_mm, adaptive_model_fraction x the bound).
double effective_adaptive_tolerance_mm(const ScanParams& p, double pitch_mm, double radius_mm);

Status validate(const ScanParams& p);
Status validate(const RoughingParams& p);
Status validate(const ContourParams& p);

/// CL lines (tool tips) of a scan at offset `extra_mm` above the part (stock to leave,
/// margin, roughing layer): the tool centre is the top of the model inflated by r + extra.
/// Lines in order, each in the + direction, points on the `sampling_mm` lattice: all of them,
/// or with `adaptive` those that the refinement needs (always the two ends). Parallel per
/// line; identical for any thread count.
Result<std::vector<std::vector<Vec3>>> scan_cl_lines(const TriSliceTop& top, const Box3& bounds,
                                                     double tool_radius_mm, double extra_mm,
                                                     const ScanParams& params,
                                                     const Context& ctx = default_context());

/// Finishing scan: one layer at the stock to leave. Needs a ball end mill.
Result<Toolpath> scan_finishing(const TriSliceModel& model, const TriSliceTop& top,
                                const Tool& tool, const ScanParams& params,
                                const Context& ctx = default_context());

/// The finishing toolpath from CL lines already computed by scan_cl_lines (at the params'
/// stock to leave), so a caller that also wants the raw CL points computes them once.
/// `ctx.threads`: lines are simplified in parallel; the toolpath does not depend on it.
Result<Toolpath> scan_finishing_from_lines(const TriSliceModel& model, const TriSliceTop& top,
                                           const Tool& tool, const ScanParams& params,
                                           std::vector<std::vector<Vec3>> lines,
                                           const Context& ctx = default_context());

/// The same finishing moves from CL lines (tool tips, each in the + direction) of any
/// source, e.g. the exact drop-cutter on a mesh without an inside: `cl_at` gives the tip
/// height for the zig-zag links, `clearance_z_mm` the rapid plane. Needs a ball end mill.
Result<Toolpath> scan_finishing_from_cl(std::vector<std::vector<Vec3>> lines, const Tool& tool,
                                        const ScanParams& params, double clearance_z_mm,
                                        std::string name, const std::function<double(Vec2)>& cl_at,
                                        const Context& ctx = default_context());

/// Roughing scan per Table 1 (its stepover replaces params.stepover_mm).
Result<Toolpath> scan_roughing(const TriSliceModel& model, const TriSliceTop& top, const Tool& tool,
                               const ScanParams& params, const RoughingParams& rough,
                               const Context& ctx = default_context());

/// Tool-centre region at tip height z for a ball of radius r_mm (3-axis: the ball's lower half
/// against the xy slices within r below the centre by Eq. (1), the shank cylinder against every
/// slice above it). Its boundary is the waterline at z.
PolygonSet waterline_region(const SliceFamily& xy, double tip_z, double r_mm,
                            const ConvolutionOptions& options = {});
/// The same with extra sections (e.g. at a mesh's critical heights): `extra_levels[k]` is the
/// height of `extra[k]`.
PolygonSet waterline_region(const SliceFamily& xy, double tip_z, double r_mm,
                            const ConvolutionOptions& options, std::span<const PolygonSet> extra,
                            std::span<const double> extra_levels);

/// Contour (waterline) paths, level by level from the top, outermost ring first.
Result<Toolpath> contour_paths(const TriSliceModel& model, const Tool& tool,
                               const ContourParams& params, const Context& ctx = default_context());

}  // namespace swarf
