// Adaptive pocketing (seed 000, Chakraborty, Panda, Umap 2024): a simulation-driven
// curvilinear toolpath with near-constant tool engagement, computed on a CPU pixel stock.
// The tool is moved in small equal steps; each step goes in the direction, within a
// maximum deviation from the last one, whose engagement (material pixels removed) is
// closest to the target (Algorithms 1-3), follows the boundary where no cutting move
// exists (Algorithms 4-5), and the raw path is post-processed (Algorithms 6-8), smoothed,
// linked and re-simulated.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/pocket/pocket_input.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/postprocess.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {

/// Parameters in machinist terms. Zero means "choose automatically" where noted; every
/// value is checked by validate(AdaptiveParams) in one place.
struct AdaptiveParams {
  /// Target radial engagement: give the angle, or the radial stepover (the angle is then
  /// acos(1 - stepover / R)). Both 0: stepover 10 % of the tool diameter.
  double engagement_deg = 0.0;
  double stepover_mm = 0.0;
  /// Band around the target engagement accepted without searching further (seed 000
  /// Algorithm 3's delta_tol), percent of the target.
  double tolerance_pct = 10.0;
  /// Length of one path step (seed 000 delta_step), mm; 0 = a quarter of the stepover
  /// within [D / 40, D / 20].
  double step_mm = 0.0;
  /// Largest change of direction between two steps (seed 000 theta_max, Algorithm 5), deg.
  double max_deviation_deg = 90.0;
  /// Pixel size of the simulation, mm; 0 = the rule of section 3.2 (see docs/pocket.md).
  double resolution_mm = 0.0;
  /// Largest simulation image, pixels. The automatic resolution is coarsened to fit it (down
  /// to 20 pixels across the tool radius and 16 per straight step at the target).
  double max_pixels = 6e7;
  /// Climb milling (material on the right of the feed direction, spindle M3).
  bool climb = true;
  /// Every pass in the milling direction `climb` says (Fusion 360's "both ways" off): a pass
  /// that would go on with the material on the other side ends, and the next starts where
  /// the front beside the last pass begins, reached over the cleared floor. Off (seed 000):
  /// the chooser takes the move nearest the target on either side, so passes that end
  /// against a wall come back the other way. On costs path time and CPU (docs/pocket.md).
  bool one_way = false;
  /// Links that would turn back on a pass (the straight line from a pass's end reversing its
  /// heading, or the next pass's) are flown as loops over the cleared floor instead: a
  /// Dubins path of arcs and straights that keeps off the walls and cuts nothing. Fewer
  /// reversals (the machine stops less), at some path length (docs/pocket.md).
  bool smooth_links = false;
  /// Where a cutting pass turns by more than a few degrees between two output moves (up to
  /// 60), its moves there become pieces of a curve through the same points, each turning at
  /// most 15 % of the target engagement (2-6 degrees): the contact arc no longer jumps by
  /// the whole turn at every step's end. More, shorter moves; no point of the path moves.
  bool smooth_corners = true;

  double depth_mm = 6.0;        ///< pocket depth below top_z_mm
  double stepdown_mm = 0.0;     ///< depth of cut per layer; 0 = the whole depth at once
  double floor_stock_mm = 0.0;  ///< left on the floor
  double wall_stock_mm = 0.0;   ///< left on walls and islands
  double top_z_mm = 0.0;        ///< top of the stock
  double clearance_z_mm = 5.0;  ///< rapid plane above the stock

  double feed_mm_min = 1000.0;        ///< cutting feed
  double plunge_feed_mm_min = 300.0;  ///< straight plunges (necks, entries with no room)
  /// Helix and ramp entries' feed along their path; 0 = feed_mm_min. Their descent per unit
  /// of path is tan(ramp_angle_deg), so the axial load is small (a 3 degree helix of the
  /// default radius drops 1 mm a turn); FreeCAD's Adaptive (helix arcs) and Fusion 360's
  /// defaults ramp at the cutting feed too. Before session 23 entries ran at the plunge
  /// feed: a ø10 took 30 s to helix into a 6 mm pocket at the defaults, now 9 s.
  double ramp_feed_mm_min = 0.0;
  double rapid_mm_min = 5000.0;  ///< for time estimates (retract or stay down)
  /// Feed of the keep-tool-down links over cleared floor (output moves that the
  /// re-simulation finds removing nothing, or so little that the chip at this feed is no
  /// thicker than a target step's at feed_mm_min), straight G1 moves; 0 = rapid_mm_min. A
  /// machine whose rapids are dog-legged is safe with it: the moves are interpolated.
  double link_feed_mm_min = 0.0;
  double ramp_angle_deg = 3.0;  ///< descent angle of helix and ramp entries (ramp_feed_mm_min)
  /// Helix radius (tool centre), mm; 0 = 0.3 x tool diameter, reduced to what fits.
  double helix_radius_mm = 0.0;
  /// Plunge points tried along the medial axis; the fastest toolpath wins.
  int plunge_candidates = 1;
  /// Where the tool fits but has no room for a helix or a ramp (a lobe behind a neck
  /// narrower than the tool, a pocket barely wider than it), go straight down into the
  /// material at the plunge feed, which needs a centre-cutting end mill; and where the path
  /// would slot through a neck as wide as the tool, plunge through it in crescents instead.
  /// false: such material is left (material_left_mm2), a pocket with no other way in is an
  /// error, and necks are slotted.
  bool straight_plunge = true;
  /// Where the path would loop along a channel whose room beside the tool is within one or
  /// two band depths (the contact of such loops swings from nothing to half the tool),
  /// plunge along one wall's offset in crescents instead, take the strip left along the
  /// other wall as a side cut in the band and the cusps between the holes after
  /// (AdaptiveResult::channel_plunges; needs straight_plunge). Each such run is replaced
  /// only where that is no slower at the feeds than its loops (a small tool plunging deep
  /// at the plunge feed is slower).
  bool channel_plunge = true;
  int smoothing_iterations = 2;  ///< Chaikin passes over link joins (seed 000 6.6)
  /// Scallops higher than this, mm, that the passes leave where they meet a wall or island
  /// at an angle are taken off by short dabs square to it (or a ride along it); 0 = none.
  /// Links over the cleared floor keep twice this off the walls they run along (0.2 mm
  /// where it is 0, at least a pixel), clear of the lower scallops left there.
  double wall_scallop_mm = 0.1;
  /// Douglas-Peucker tolerance of the output, mm; 0 = a quarter of the pixel size.
  double simplify_tolerance_mm = 0.0;
  /// Fill AdaptiveResult::cut_map (the report picture's bitmap, 4 bytes a pixel: 10 MB for
  /// the benchmark L). false leaves it empty; the path is the same.
  bool cut_map = true;
};

/// Checks ranges; the message names the parameter and its unit.
Status validate(const AdaptiveParams& params, const Tool& tool);

enum class StepKind : std::uint8_t { kCut, kBoundary, kLink };

/// One step of the final (re-simulated) 2D path, for the per-step CSV and plots.
struct AdaptiveStep {
  Vec2 position;  ///< end of the step, mm
  StepKind kind = StepKind::kCut;
  int engagement_px = 0;        ///< material pixels removed by this step
  double engagement_deg = 0.0;  ///< equivalent engagement angle of that count
  double deviation_deg = 0.0;   ///< turn from the previous step's direction
  double length_mm = 0.0;
  /// In a neck barely wider than the tool that the output plunges through rather than
  /// cuts as a pass (AdaptiveResult::neck_plunges): not a cut of the path, so out of the
  /// engagement figures; its engagement is what the pass would have been.
  bool plunged = false;
};

/// The simulation bitmap after the final path, for the report picture: per pixel 0 =
/// outside the pocket, 1 = material left, 2 = cut by an entry (the first or a later one),
/// 3 + k = cut by step k.
struct CutMap {
  Vec2 origin;
  double pixel_mm = 0.0;
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> cells;
};

struct AdaptiveResult {
  Toolpath toolpath;
  std::vector<AdaptiveStep> steps;  ///< one layer's 2D path (all layers repeat it)
  CutMap cut_map;
  double resolution_mm = 0.0;
  /// The resolution rule's pixel (0 when resolution_mm was given): when resolution_mm is
  /// larger, the pixel budget (AdaptiveParams::max_pixels) coarsened it.
  double rule_resolution_mm = 0.0;
  double step_mm = 0.0;
  double target_engagement_deg = 0.0;
  double target_engagement_px = 0.0;
  Vec2 plunge_point;
  double helix_radius_mm = 0.0;  ///< 0 when the entry is a ramp
  /// Plunge points tried along the medial axis (AdaptiveParams::plunge_candidates, seed 000
  /// 4.1) and the estimated time of each one's 2D path, s; `chosen_candidate` is the one
  /// kept (the fastest; plunge_point is its point).
  std::vector<Vec2> candidate_plunge_points;
  std::vector<double> candidate_time_s;
  int chosen_candidate = 0;
  int layers = 0;
  int retracts_per_layer = 0;
  int trochoid_groups = 0;
  int boundary_groups = 0;
  double material_left_mm2 = 0.0;  ///< reachable material the path leaves, per the simulation
  /// Entries straight down into uncut material (AdaptiveParams::straight_plunge): places, not
  /// counting their repeats on lower layers.
  int straight_plunges = 0;
  /// Necks barely wider than the tool, where every way through is a full slot, plunged
  /// through instead (AdaptiveParams::straight_plunge): plunges per layer (their path's
  /// steps are AdaptiveStep::plunged; their length is AdaptiveSummary::plunged_length_mm).
  int neck_plunges = 0;
  /// Channels plunged along a wall and side-milled (AdaptiveParams::channel_plunge): how
  /// many, and their plunges per layer (their path's steps are AdaptiveStep::plunged too).
  int channels = 0;
  int channel_plunges = 0;
  double gouge_steps = 0;  ///< steps whose disk reaches past a wall (exact geometry; 0 expected)
};

/// Computes the adaptive pocket toolpath. Errors: kBadParameter, kToolTooLarge (the tool
/// fits nowhere in the pocket), kNoEntryFound (it fits but cannot helix or ramp in, and
/// AdaptiveParams::straight_plunge is off),
/// kCancelled.
Result<AdaptiveResult> adaptive_pocket(const Pocket& pocket, const Tool& tool,
                                       const AdaptiveParams& params,
                                       const Context& ctx = default_context());

/// fit_arcs for a pocket toolpath that keeps the tool off the pocket's walls: an arc is
/// only fitted where no point of it comes nearer a wall or an island than tool radius + wall
/// stock (exact arc-to-edge distance); elsewhere the lines stay. The plain fit, 5 um from
/// the points, could run a few um into a wall the path rides 2 um off.
Toolpath fit_pocket_arcs(const Toolpath& path, const Pocket& pocket, double tool_radius_mm,
                         double wall_stock_mm, ArcFitOptions options = {});

/// Engagement angle of a radial stepover on a tool of radius R: acos(1 - stepover / R), deg.
double engagement_angle_deg(double stepover_mm, double tool_radius_mm);
/// The inverse: R (1 - cos angle).
double stepover_for_angle_mm(double engagement_deg, double tool_radius_mm);

/// Summary figures of a result: lengths, time, engagement statistics over cutting steps.
struct AdaptiveSummary {
  double cutting_length_mm = 0.0;
  double air_length_mm = 0.0;
  /// Necks plunged through (AdaptiveStep::plunged): neither cutting nor air length.
  double plunged_length_mm = 0.0;
  /// Cutting steps at the feed, the others at the link feed, necks at both (the cusps
  /// between the plunges at the feed, then the pass in the air), all layers; the plunges and
  /// retracts are not counted (machining_time_s of the toolpath's metrics counts them).
  double time_s = 0.0;
  double engagement_mean_deg = 0.0;
  double engagement_p5_deg = 0.0;
  double engagement_p95_deg = 0.0;
  double max_deviation_deg = 0.0;  ///< over cutting steps
  /// Fraction of the cutting length whose engagement is within +-20 % of the target.
  double within_20pct = 0.0;
};
AdaptiveSummary summarize(const AdaptiveResult& result, const AdaptiveParams& params);
/// "cutting 1234.5 mm, air 56.7 mm, time 83.2 s, engagement mean/p5/p95 36.1/30.2/40.0 deg,
/// max deviation 12.0 deg"
std::string summary_line(const AdaptiveSummary& summary);
/// Per-step CSV: index,x,y,kind,engagement_px,engagement_deg,deviation_deg,length_mm.
std::string steps_csv(const AdaptiveResult& result);

}  // namespace swarf
