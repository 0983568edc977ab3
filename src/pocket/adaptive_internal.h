// Internals of the adaptive pocket strategy, shared by its parts: the resolved model
// (entry.cpp), the move chooser (move_chooser.cpp), post-processing and linking
// (path_postprocess.cpp) and the driver (adaptive.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "pocket/pixel_stock.h"
#include "pocket/wall_index.h"
#include "swarf/core/context.h"
#include "swarf/pocket/adaptive.h"

namespace swarf::pocket {

/// The feed of keep-tool-down links: AdaptiveParams::link_feed_mm_min, or the rapid rate.
inline double link_feed_mm_min(const AdaptiveParams& p) {
  return p.link_feed_mm_min > 0.0 ? p.link_feed_mm_min : p.rapid_mm_min;
}

/// The least a step must remove to count as cutting (4 % of the target, at least 2 pixels):
/// Model::cut_px, and the summary's split of cutting from air length.
inline double cut_threshold_px(double target_px) {
  return std::max(2.0, 0.04 * target_px);
}

/// Everything derived from pocket, tool and parameters before the first move.
struct Model {
  double radius_mm = 0.0;    ///< tool radius
  double step_mm = 0.0;      ///< seed 000 delta_step
  double h = 0.0;            ///< pixel size
  double rule_h = 0.0;       ///< the resolution rule's pixel size (0: given explicitly)
  double stepover_mm = 0.0;  ///< target radial stepover
  double target_deg = 0.0;
  double target_px = 0.0;  ///< seed 000 eps_tar: pixels removed by one straight step
  double tol_px = 0.0;     ///< seed 000 delta_tol
  double cut_px = 0.0;     ///< a step removing more than this is a cutting step
  int theta_max_deg = 90;
  /// +1: material on the left (the paper's scan order); -1: mirrored, for climb milling.
  int sigma = -1;
  bool one_way = false;            ///< AdaptiveParams::one_way
  bool smooth_links = false;       ///< AdaptiveParams::smooth_links
  double boundary_round_mm = 0.0;  ///< a full boundary traversal, for termination
  double want_helix_mm = 0.0;      ///< helix radius asked for (it shrinks where less fits)
  bool straight_plunge = true;     ///< AdaptiveParams::straight_plunge
  /// How far a link over cleared floor keeps the tool's edge off a wall it runs along,
  /// beyond the wall stock (path_postprocess.cpp): what the passes leave on a wall lies
  /// below the pixels, the scallops between the arrivals of fronts that meet it at an angle
  /// (up to wall_scallop_mm high; higher ones are taken off by wall_rides.cpp) and a skin of
  /// up to half a pixel, and a link on the wall's exact offset grazes all of it at the link
  /// feed (session 48: the PCB-vice bar's links and rides along its diagonal walls, 133 mm at
  /// 3-5 degrees by a sweep at half the default pixel). Twice wall_scallop_mm (0.2 mm where
  /// that is 0), and at least a pixel: past the skin, and four times the default
  /// simplification tolerance, so that the lift survives it. Until session 57 it was once
  /// wall_scallop_mm, and links grazed the tips of the scallops as high as that: the sweep
  /// read links along a wall at 4-15 degrees (1.6 % of the cutting length of a gear at ø10,
  /// 10 %; with the lift doubled 1.0 %, the band 93.6 -> 94.2 %, and the links that cut
  /// nothing now run at the link feed). Not more than a pixel where the pixel is larger:
  /// the scallops under the pixels are then as high, and twice the pixel left them (random
  /// pocket 2033, ø16 at 40 %: 0.18 mm^2 against 0.08).
  double link_lift_mm = 0.2;
  PolygonSet region;           ///< the pocket (outer ring, islands), exact
  WallIndex walls;             ///< region's edges on a grid, for the exact-geometry checks
  double wall_stock_mm = 0.0;  ///< left on walls and islands
  double pocket_area_mm2 = 0.0;
  Grid grid;
  BitImage pocket;     ///< pixel centres inside the pocket
  BitImage forbidden;  ///< pixel centres the tool disk may not cover
  BitImage material;   ///< initial material: pocket pixels some free tool position covers
  std::vector<float> clearance_sq;  ///< squared distance to the nearest forbidden pixel, px^2
  BitImage free_centres;  ///< pixel centres the tool may stand on: clearance over its radius
  /// Exact tool positions clear of the walls (wall stock included) in patches too narrow to
  /// hold a free pixel centre; their disks are material, and straight plunges may go there.
  std::vector<Vec2> tight_centres;
};

Result<Model> make_model(const Pocket& pocket, const Tool& tool, const AdaptiveParams& params);
/// The pixels' clearance at a point, mm: its nearest pixel centre's distance to the nearest
/// forbidden pixel, less half a pixel's diagonal, so that a point judged free really is (the
/// disk test of the stock is the final word); 0 outside the image (entry.cpp).
double clearance_at(const Model& model, Vec2 p);
/// Whether the move a-b keeps `reach` off every wall by the pixels' clearance alone (which
/// reads within two pixels of the exact distance): such a move needs no exact query.
/// False says nothing; the exact walls decide (entry.cpp).
bool far_from_walls(const Model& model, Vec2 a, Vec2 b, double reach);
/// Whether the move a-b keeps at least `least` off every wall: by the pixels where they
/// tell (far_from_walls), else by the exact walls (entry.cpp).
bool keeps_off_walls(const Model& model, Vec2 a, Vec2 b, double least);

struct Entry {
  Vec2 centre;                   ///< plunge point
  double helix_radius_mm = 0.0;  ///< 0 for a ramp
  Vec2 ramp_a, ramp_b;           ///< ramp segment (tool centre), when a ramp
  Vec2 start;                    ///< where the adaptive moves begin
  double start_angle_rad = 0.0;  ///< their first direction
  /// Straight down at the plunge feed, no helix or ramp: for a new entry where the inner
  /// half of the tool's disk is over cleared floor (the end teeth near the rim cut), or,
  /// with `solid`, where no helix or ramp fits (AdaptiveParams::straight_plunge).
  bool plunge = false;
  bool solid = false;  ///< a plunge into uncut material
};

/// Up to `count` entries at maxima of the medial axis, best (widest) first.
/// kToolTooLarge / kNoEntryFound when there is none.
Result<std::vector<Entry>> find_entries(const Model& model, int count);
/// The medial-axis pixels (indices into the grid) at least min_clearance_px from every
/// forbidden pixel, widest first.
std::vector<int> entry_axis(const Model& model, double min_clearance_px);
/// The medial axis new entries are sought on (entry_axis), with the helix or ramp that fits
/// at each pixel worked out when first needed: it depends on the model alone, and a
/// pocket of many chambers asks for it at every new entry.
struct EntryAxis {
  std::vector<int> pixels;
  /// Per pixel: -1 not worked out yet, 0 no helix or ramp fits, 1 `entry` holds it.
  std::vector<std::int8_t> fits;
  std::vector<Entry> entry;
};
EntryAxis make_entry_axis(const Model& model, double min_clearance_px);
/// An entry for material the cleared area cannot lead to: a plunge where the disk holds the
/// most of `stock`'s material (at least min_px) over a cleared inner half, else the
/// medial-axis pixel whose helix or ramp takes the most. False when there is none.
bool find_entry_for_material(const Model& model, const PixelStock& stock, EntryAxis& axis,
                             int min_px, Entry& entry);
/// Clears the entry hole or slot in the stock.
void cut_entry(PixelStock& stock, const Model& model, const Entry& entry,
               CutVisitor visit = nullptr, void* user = nullptr);
PixelStock fresh_stock(const Model& model);

/// The raw path of Algorithms 1-5: points, and per segment i (pts[i] -> pts[i+1]) the
/// pixels it removed and how it was chosen.
struct RawPath {
  std::vector<Vec2> pts;
  std::vector<int> eng;
  std::vector<StepKind> kind;
  /// The segment is a resume after a finished boundary round: not travelled, linked later.
  std::vector<bool> jump;
  /// For a jump: the index in `entries` of a new helix/ramp entry made there, else -1.
  std::vector<int> entry;
};
/// `entries`: the first is where the path starts; the others are used, in order, for parts
/// of the pocket the tool cannot reach from the cleared area (beyond a neck narrower than
/// the tool) once nothing else is left.
/// Entries made on the way (find_entry_for_material) are appended to `entries`.
Result<RawPath> generate_raw_path(const Model& model, PixelStock& stock,
                                  std::vector<Entry>& entries, const Context& ctx);

/// std::lround for |x| < 2^31 (halves away from zero), inline: the libm call cost 1 % of a
/// pocket's run in the slot test, and about 5 % of a plate of chambers' in the resume
/// search. x minus its truncation is exact.
inline int round_half_away(double x) {
  const int t = static_cast<int>(x);
  const double f = x - t;
  return t + (f >= 0.5 ? 1 : 0) - (f <= -0.5 ? 1 : 0);
}

/// Crumbs this close to the walls (beyond the wall stock) are not put back: the stated
/// residual tolerance leaves them, and chasing them cost the benchmark L three lifts.
constexpr double kWallCrumbMm = 0.25;

/// Where to resume after the boundary round ended with reachable material left (our
/// addition: the paper stops, which leaves material behind islands or beyond a narrow
/// neck). Tries the remaining material pixels nearest to `from` that are not in `given_up`;
/// a resume point is a free, already cleared centre just out of reach of the pixel, facing
/// it. Pixels for which no such point exists are added to `given_up` (so the search
/// terminates). They stay material: a path that passes them still sees and cuts them (when
/// they were taken out of the stock instead, a later pass went through them as if through
/// cleared space, and the final path, re-simulated, cut them in a full slot).
/// `window_mm` > 0 limits the search to the material within that of `from` (0: the whole
/// stock).
bool find_resume(const Model& model, const PixelStock& stock, Vec2 from, Vec2& at, Vec2& dir,
                 int& pi, int& pj, BitImage& given_up, double window_mm = 0.0);

/// The free tool centres (Model::free_centres) by connected component (8 neighbours): a label per
/// pixel, -1 where not free, and the pixels of each component.
struct CentreComponents {
  std::vector<int> label;
  std::vector<std::size_t> size;
  /// Per component, the pixel box holding it: columns i0..i1, rows j0..j1.
  struct Box {
    int i0, j0, i1, j1;
  };
  std::vector<Box> box;
  std::size_t free = 0;  ///< free pixels in all
};
CentreComponents label_centre_components(const Model& model);

/// Replaces the straight cutting moves either side of each turn of more than `max_turn_deg`
/// by pieces of a centripetal Catmull-Rom curve through the same points, each piece turning
/// about `max_turn_deg` at most (8 pieces a move at most). Moves next to a corner (a turn
/// over 60 degrees), moves with an end within two pixels of the walls' offset, and moves
/// whose pieces would come within a pixel of it (exact geometry) stay straight. Every point
/// of the path stays where it was (corner_smoothing.cpp).
void smooth_cutting_corners(const Model& model, Toolpath& tp, double max_turn_deg);

/// Blocks of 2^kReachBlockShift pixels a side, for cleared_reach.
constexpr int kReachBlockShift = 3;
/// Per block of pixels (pixel (i, j) in block (i >> kReachBlockShift, j >> kReachBlockShift)):
/// whether a tool position with no material in its disk, the resume search's test, may lie
/// within `ring_mm` of a pixel of it. A pixel whose block is unset has no resume at that
/// ring; a set block may (our addition, resume_search.cpp).
BitImage cleared_reach(const Model& model, const PixelStock& stock, double ring_mm);

/// After a new entry at `centre`: clears `given_up` where the tool, working from the entry's
/// component of free centres, may change what a resume finds (material within 3 R and a step
/// of it); all of it where the entry is not on a free pixel or its component holds every
/// free centre (our addition, resume_search.cpp).
void forget_given_up_near(const Model& model, const CentreComponents& components, Vec2 centre,
                          BitImage& given_up);

/// One way (AdaptiveParams::one_way): from a free point `at` beside the material front,
/// facing along it in the milling direction `dir`, backs up the front (against dir, hugging
/// it at a standoff of about half a pixel, in steps of two delta_step) to where it begins: a
/// wall or island in the way, or the front turning away. `at` and `dir` become that point and
/// the direction along the front there, so the pass runs the front's whole length. Without
/// it the resume point was the material nearest the last pass's start, often the far end
/// of a front where it meets a wall: a pass of one step, then another resume (the L: 844
/// resumes, 2.4 s, 81 % within +-20 %).
void trace_front_upstream(const Model& model, const PixelStock& stock, Vec2& at, Vec2& dir);

/// The linked path: points and per segment its kind; `jump[i]` marks a segment travelled
/// by retracting, moving at the clearance plane and coming down again.
struct LinkedPath {
  std::vector<Vec2> pts;
  std::vector<StepKind> kind;
  std::vector<bool> jump;
  std::vector<int> entry;  ///< per segment: a jump that enters anew at entries[i], else -1
  /// Points of the visits into the tips of the tool centres' region (wall_reach.cpp) and of
  /// the scallop rides' dabs (wall_rides.cpp): beyond the free pixel centres, whose disks
  /// alone make the initial material; the re-simulation adds what their disks cover.
  std::vector<Vec2> beyond_free;
  /// Where moves that cut by design end: those of the scallop rides and dabs that take the
  /// scallops (wall_rides.cpp) and the tip visits' last move into the tip (wall_reach.cpp).
  /// They run at the cutting feed whatever the re-simulation reads (its pixels see less of
  /// a wall sliver, or of what earlier passes left in a tip, than is there).
  std::vector<Vec2> design_cut_ends;
  int trochoid_groups = 0;
  int boundary_groups = 0;
};
struct LinkCosts {
  double feed_mm_min = 1000.0;       ///< cutting
  double link_feed_mm_min = 5000.0;  ///< keep-tool-down links over cleared floor
  double rapid_mm_min = 5000.0;
  double lift_mm = 10.0;  ///< from the floor up to the clearance plane
  /// The last part of the way down after a retract, at the plunge feed (from 1 mm above
  /// the previous layer's floor).
  double descent_mm = 1.0;
  double plunge_feed_mm_min = 300.0;
  int smoothing_iterations = 2;
};
/// A retract as the output makes it, in minutes: up to the clearance plane, `across_mm` over
/// and most of the way down at the rapid rate, the last descent_mm at the plunge feed.
inline double retract_minutes(const LinkCosts& c, double across_mm) {
  return (2.0 * c.lift_mm - c.descent_mm + across_mm) / c.rapid_mm_min +
         c.descent_mm / c.plunge_feed_mm_min;
}
LinkedPath postprocess(const Model& model, const std::vector<Entry>& entries, const RawPath& raw,
                       const LinkCosts& costs);

/// With AdaptiveParams::smooth_links: a link from a (reached from before_a) to b (left
/// towards after_b) that does not turn back on either cut, where the straight line would
/// by 120 degrees or more. The shortest Dubins path among a few turning radii and corners
/// that keeps off the walls by exact geometry, cuts nothing of `stock` and turns by at most
/// 120 degrees within any millimetre (smooth_link.cpp). Appends its points after a, b last,
/// and returns true; false (nothing appended) where the straight line does not turn back,
/// or no such path is found.
bool smooth_link(const Model& model, const PixelStock& stock, Vec2 before_a, Vec2 a, Vec2 b,
                 Vec2 after_b, std::vector<Vec2>& out);

/// Takes off the scallops the path leaves on the walls (wall_rides.cpp): each group of
/// material `after` (the re-simulated stock) holds against a wall higher than scallop_mm
/// gets dabs square to the wall, or a ride along it, spliced into the path as a visit from
/// the last move near it (or, with no way there, appended after the path's end). False when
/// there is none (the path is unchanged).
bool ride_walls_over_scallops(const Model& model, const PixelStock& after, double scallop_mm,
                              LinkedPath& lp);

/// Puts the points of passes along a wall onto its exact offset (wall_reach.cpp).
void snap_to_wall_offset(const Model& model, LinkedPath& lp);
/// Adds visits to the tips of the tool centres' region the path stops short of
/// (wall_reach.cpp); their points go to lp.beyond_free.
void reach_into_tips(const Model& model, LinkedPath& lp);
/// Leaves out the steps back along a wall that the next cut turns round from and passes
/// (wall_reach.cpp).
void drop_spurs(const Model& model, LinkedPath& lp);
/// Splits moves between points on a wall's offset that sag into the wall where the offset
/// is an arc, with midpoints on it (wall_reach.cpp).
void keep_chords_off_walls(const Model& model, LinkedPath& lp);

/// What a kept output move removes in the re-simulation: pixels, path length, its angle
/// (degrees), whether it is a link (removes at most cut_px a step) and whether it may go at
/// the link feed (at most graze_px a step); and whether it is the first move out of the
/// hole of a straight plunge into uncut material.
struct KeptMove {
  double px = 0.0, len = 0.0, deg = 0.0;
  bool link = true, fast = true;
  bool out_of_hole = false;
};
/// A run of kept moves first..last (indices into `keep`, each move keep[q - 1] -> keep[q])
/// that cut a full slot: a neck barely wider than the tool (neck_plunges.cpp). Runs are
/// moves removing 160 degrees or more, or 110 degrees or more with under four pixels of room
/// beside the tool (0.2 mm or longer), or 110 degrees or more between walls within a
/// millimetre of the tool on both sides (1 mm or longer), or 110 degrees or more out of a
/// straight plunge's hole (however short); pieces of such
/// runs less than a tool radius of path apart, between close walls all the way, are one,
/// and a neck's run takes in moves of 100 degrees or more (and 1.25x the target) within a
/// tool radius of path of it, between close walls.
/// The removal angles neck_runs judges by (neck_plunges.cpp says why): a full slot
/// anywhere, and a heavy cut between close walls. The output simplification keeps moves
/// apart where a step crosses either, so a move's average does not hide them.
constexpr double kNeckSlotDeg = 160.0, kNeckTightDeg = 110.0;
/// Walls within `r` of p on both sides along the line through p of direction n (both points
/// at r outside the pocket).
bool walled(const WallIndex& walls, Vec2 p, Vec2 n, double r);
/// walled() along any of `lines` lines through p, evenly spread over 180 degrees.
bool walled_on_any_line(const WallIndex& walls, Vec2 p, int lines, double r);
struct NeckRun {
  std::size_t first = 0, last = 0;
  double length_mm = 0.0;
};
std::vector<NeckRun> neck_runs(const Model& model, const LinkedPath& lp,
                               const std::vector<std::size_t>& keep,
                               const std::vector<KeptMove>& kept);
/// Where to plunge along a neck's path `way` (its first point already cut): evenly spaced,
/// at most `spacing` apart along it, the last at its end; each with the index of the point
/// of `way` it follows or sits on.
struct NeckPlunge {
  std::size_t after = 0;
  Vec2 at;
};
std::vector<NeckPlunge> neck_plunge_points(const std::vector<Vec2>& way, double spacing);
/// A run of kept moves first..last (as NeckRun) looping along a channel whose room beside
/// the tool is within one or two band depths (channel_plunges.cpp): replaced by plunges
/// along one wall's offset, then passes along the channel from its end back to its start,
/// each taking a strip of the room at the target engagement, on the milling side.
struct ChannelRun {
  std::size_t first = 0, last = 0;
  std::vector<Vec2> holes;                ///< the plunges, in order from the run's start
  std::vector<std::vector<Vec2>> passes;  ///< in cutting order, each from the run's end back
  std::vector<Vec2> cusp_pass;            ///< then along the holes' wall from the start, its cusps
  double room_mm = 0.0;                   ///< the channel's median room beside the tool
};
/// Channel runs outside `necks`; `via` are the kept moves' wall-keeping points.
std::vector<ChannelRun> channel_runs(const Model& model, const LinkedPath& lp,
                                     const std::vector<std::size_t>& keep,
                                     const std::vector<KeptMove>& kept,
                                     const std::vector<std::vector<Vec2>>& via,
                                     const std::vector<NeckRun>& necks);

/// One step of what replaces a channel run: a plunge at a hole (from above the layer), a
/// cutting move, or a move back through the cleared channel at the link feed.
struct ChannelStep {
  enum class Kind { kPlunge, kCut, kLink };
  Kind kind = Kind::kCut;
  Vec2 to;
};
/// What replaces run c, in order, ending at `end` (where its loops ended): the plunges, the
/// passes from the run's end back to its start (between two, the way back at the link
/// feed), the cusp pass. The emission writes it, its time is reckoned from it and the check
/// that it leaves nothing cuts it.
std::vector<ChannelStep> channel_steps(const ChannelRun& c, Vec2 end);

/// The feeds a channel run's time is reckoned at (mm/min), and how deep its plunges go (mm).
struct ChannelFeeds {
  double feed = 0.0, link = 0.0, plunge = 0.0, rapid = 0.0, dive_mm = 0.0;
};
/// Seconds at the feeds for run c's loops (the kept moves it replaces).
double channel_loops_time_s(const ChannelRun& c, const std::vector<KeptMove>& kept,
                            const ChannelFeeds& f);
/// Seconds at the feeds for what replaces run c, from `from` (where the run starts) to `to`
/// (where it ends): the plunges and rapids between them, the passes, the cusp pass.
double channel_plunges_time_s(const ChannelRun& c, Vec2 from, Vec2 to, const ChannelFeeds& f);

/// The runs (in path order) whose replacement leaves no more than crumbs of material that
/// the path cut: lp simulated on `stock` (the re-simulation's starting stock) with every run
/// replaced, and a run dropped where over 0.1 mm^2 that was cut before (not set in
/// `left_before`, the re-simulation's stock after the path) is left within reach of its
/// loops.
std::vector<ChannelRun> runs_leaving_nothing(const Model& model, PixelStock stock,
                                             const std::vector<Entry>& entries,
                                             const LinkedPath& lp,
                                             const std::vector<std::size_t>& keep,
                                             std::vector<ChannelRun> runs,
                                             const BitImage& left_before);

/// Ramer-Douglas-Peucker on [first, last]: indices kept, ends included. With `chord_ok`, a
/// chord (a, b) within the tolerance is also kept only when chord_ok(a, b) says it may be.
void simplify_indices(const std::vector<Vec2>& pts, std::size_t first, std::size_t last, double tol,
                      std::vector<std::size_t>& keep,
                      const std::function<bool(std::size_t, std::size_t)>& chord_ok = {});

}  // namespace swarf::pocket
