// The top of a tri-slice model inflated by a ball, evaluated point by point: the fast road
// to scanning paths (seed 001 section 3.1) without building whole inflated polygons.
//
// For a scan line y = y_i, the paper inflates the zx slice i by Eq. (1) and reads the ball
// centre off the top of the inflated polygon. The top of offset(P_j, rho) at x is
//   max over points (x', z') of P_j with |x' - x| <= rho of z' + sqrt(rho^2 - (x' - x)^2),
// i.e. a disc of radius rho dropped onto slice j in its own plane; the top of the union is the
// maximum over j. So the scan-line result of Eq. (1) is exactly: the highest ball centre over
// (x, y_i) such that, for every slice j, the disc of radius sqrt(r^2 - (y_i - y_j)^2) clears
// P_j. That is a 2D drop against the upward-facing edges of each slice, nothing else, with no
// polygon union at all. Written with the distance y - y_j instead of (i - j) ds it holds at
// any y, and for the family normal to x as well (with x - x_k): the same query on the yz
// family gives that family's inflated top at any point; LevelEnvelope below does it for the
// xy family. The model's top is the highest of the three answers (superposition, section
// 2.1): each family holds the walls nearly parallel to the others' planes, so together they
// bound the error of offset.h with theta >= 54.7 degrees everywhere.
//
// Per slice the upward edges are bucketed along the line in 0.5 mm bins carrying their highest z;
// blocks of 16 slices and super-blocks of 256 carry the highest z per 1 mm. A query visits slices
// nearest first and skips any block, slice or bin whose highest z + rho cannot beat the best centre
// so far.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/trislice/model.h"

namespace swarf {

class SliceEnvelope {
 public:
  /// Family must be normal to x or y. `bin_mm`: bin width along the slices. `stride` > 1
  /// reads every stride-th slice only (a coarser model for roughing).
  static SliceEnvelope build(const SliceFamily& family, double bin_mm = 0.5, int stride = 1);

  /// Highest centre height of a ball of radius r_mm over p that clears every slice of the
  /// family (Eq. (1) evaluated at p), or `at_least` when no slice rises above it.
  /// `hint` (optional) carries the segment that decided the previous query of a scan line in
  /// and out; it only speeds the query up, the answer does not depend on it.
  double centre_height(Vec2 p, double r_mm, double at_least, std::uint32_t* hint = nullptr) const;
  static constexpr std::uint32_t kNoHint = 0xffffffffu;
  /// The height that the hinted segment alone gives (-infinity for no hint): a lower bound.
  double hint_height(Vec2 p, double r_mm, std::uint32_t hint) const;

  std::size_t segment_count() const { return nseg_; }
  std::size_t memory_bytes() const;

 private:
  struct Seg {
    double s0, z0, s1, z1;  ///< along-line coordinate and height, s0 <= s1
    double ns, nz;          ///< upward unit normal (nz == 0 marks a vertical edge)
  };
  static double drop_on(const Seg& g, double s, double rho, double rho2);
  Axis axis_ = Axis::kY;
  double first_ = 0.0, pitch_ = 1.0;
  std::size_t n_ = 0;  ///< slices
  double smin_ = 0.0, bin_ = 1.0;
  int nb_ = 0;
  std::size_t nseg_ = 0;                 ///< upward edges (each copied into the bins it spans)
  std::vector<Seg> seg_;                 ///< CSR items over (slice, bin), in place
  std::vector<std::uint32_t> slice_of_;  ///< slice index of each item
  std::vector<std::uint32_t> start_;     ///< CSR over (slice, bin)
  /// Per (slice, bin): a line z <= a + b (s - bin centre) above every upward edge in the bin,
  /// and k = b / sqrt(1 + b^2) (where a disc's top over that line peaks). Much tighter than
  /// binmax_ on a slope, so slices near the contact are ruled out before their segments.
  /// top: the highest z in the bin (its box); kept beside the line so that a cell's two
  /// tests read one cache line.
  struct Line {
    double a, b, k, top;
  };
  std::vector<Line> line_;
  std::vector<Line> blockline_;   ///< per (block of kBlock slices, bin), above all its lines
  int nbc_ = 0;                   ///< coarse bins
  std::vector<double> supermax_;  ///< per (super-block of kBlock^2 slices, coarse bin)
  static constexpr std::size_t kBlock = 16;
  static constexpr std::size_t kCoarse = 1;  ///< fine bins per coarse bin
};

/// The xy family's share of the top: a ball centred over p at height zc touches the ring of
/// slice l (level z_l) when the ring comes within sqrt(R^2 - (zc - z_l)^2) of p, so it holds the
/// centre at z_l + sqrt(R^2 - d^2), d the horizontal distance from p to the ring. It is the
/// family that sees steep walls and the nesting of the ball in fillets of its own radius (the
/// vertical families see those at a grazing angle). Ring edges are listed in the cells of a
/// uniform xy grid that they cross, highest level first; a query walks the cells within R and
/// stops in each at the first level that cannot beat the best centre so far. Interiors of the
/// rings are not contacts: horizontal faces are held by the vertical families' slice tops.
class LevelEnvelope {
 public:
  static LevelEnvelope build(const SliceFamily& xy_family, double cell_mm = 1.0, int stride = 1);
  /// `hint` as for SliceEnvelope: the ring edge that decided the previous query.
  double centre_height(Vec2 p, double r_mm, double at_least, std::uint32_t* hint = nullptr) const;
  double hint_height(Vec2 p, double r_mm, std::uint32_t hint) const;
  std::size_t segment_count() const { return nseg_; }
  std::size_t memory_bytes() const;

 private:
  struct Seg {
    double x0, y0, ex, ey, z;  ///< start, end - start (as the queries use it), level
  };
  static double drop_on(const Seg& g, Vec2 p, double r2);
  std::size_t nseg_ = 0;
  std::vector<Seg> seg_;  ///< CSR items over the cells, in place, highest level first
  Vec2 origin_;
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;
  std::vector<double> cellmax_;     ///< highest level per cell (-infinity when empty)
  static constexpr int kSuper = 4;  ///< cells per side of a super-cell
  int nsx_ = 0, nsy_ = 0;
  std::vector<double> supermax_;  ///< highest level per super-cell
};

/// Per-scan-line state that speeds up consecutive queries (see SliceEnvelope::centre_height).
struct ScanHint {
  std::uint32_t primary = SliceEnvelope::kNoHint;
  std::uint32_t secondary = SliceEnvelope::kNoHint;
  std::uint32_t level = SliceEnvelope::kNoHint;
};

/// The three families of a model queried together (the xy family only when it was sliced).
class TriSliceTop {
 public:
  /// `bin_mm`: bin width of the vertical families along their slices; 0 = auto_bin_mm of the
  /// pitch read. The answers do not depend on it (it only changes what the bounds prune).
  /// `threads`: the three families are indexed in parallel (0 = all cores); the index does
  /// not depend on it.
  static TriSliceTop build(const TriSliceModel& model, double bin_mm = 0.0, int stride = 1,
                           int threads = 0);
  /// The fastest bin width measured on the Table 2 part with a ø8 ball: 1 mm for pitches of
  /// 0.05 mm and coarser, 0.5 mm finer (bench/RESULTS-trislice.md, third round).
  static double auto_bin_mm(double pitch_mm) { return pitch_mm >= 0.05 - 1e-9 ? 1.0 : 0.5; }
  /// Cell size of the level index, likewise: 2 mm at pitches of 0.05 mm and coarser, 1 mm
  /// finer. A cell holds about cell x (ring length per mm^2) x (levels) edges: with few levels
  /// the cells a query walks cost more than their edges, with many the other way round
  /// (bench/RESULTS-trislice.md, session 14). The answers do not depend on it.
  static double auto_level_cell_mm(double pitch_mm) { return pitch_mm >= 0.05 - 1e-9 ? 2.0 : 1.0; }
  /// Ball-centre height over p for a ball of radius r_mm, -infinity when nothing is below.
  /// `primary` is asked first (its slices run along the scan line: Eq. (1) exactly there).
  double centre_height(Vec2 p, double r_mm, Axis primary = Axis::kY,
                       ScanHint* hint = nullptr) const;
  const SliceEnvelope& family(Axis a) const { return a == Axis::kX ? x_ : y_; }
  const LevelEnvelope& levels() const { return z_; }
  /// Spacing of the slices the index reads: the model's pitch times the stride, mm.
  double pitch_mm() const { return pitch_; }
  std::size_t memory_bytes() const {
    return x_.memory_bytes() + y_.memory_bytes() + z_.memory_bytes();
  }

 private:
  SliceEnvelope x_, y_;
  LevelEnvelope z_;
  double pitch_ = 0.0;
};

}  // namespace swarf
