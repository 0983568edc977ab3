// Unmachinable regions (seed 001 section 3.2): inflate the tri-slice model by the tool radius,
// shrink it back by the same radius (both by Eq. (1)) and subtract the original. What is left
// is material a ball of that radius cannot reach: concave features tighter than the ball.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/report/image.h"
#include "swarf/trislice/model.h"
#include "swarf/trislice/offset.h"

namespace swarf {

struct RestOptions {
  double tool_radius_mm = 4.0;
  /// Families to analyse, indexed by Axis. The map keeps the heights where all of them hold
  /// residue (the xy family: a pitch-thick slab round each level holding some).
  std::array<bool, 3> families{true, true, true};
  /// Residues thinner than this are removed (an opening by half of it in each slice) and
  /// left out of the map: the faceting of the mesh and the arc tolerance leave slivers of a
  /// few micrometres along concave arcs of about the tool radius.
  double min_thickness_mm = 0.02;
  /// Only slices whose level lies in this box (per family, along its axis) are analysed;
  /// empty: all. Saves time when only a feature is of interest.
  Box3 region;
  /// Arc tolerance 5 um, every neighbour (the stride comes from convolution_tolerance_mm),
  /// slices simplified to 1 um before they are offset (a twentieth of min_thickness_mm).
  ConvolutionOptions convolution{0.005, 1, 0.001};
  /// Analyse the x family only over the xy family's residue (its bounds plus a pitch), and
  /// the y family only over where both hold some: the map and the points keep only what all
  /// families agree on, so they come out the same, sooner where the residue is local (a
  /// pocket part: half the time; the torus part -20 %). false: every slice of every family.
  bool prune_by_xy_residue = true;
  /// Normal error the closing may make between slices, mm: neighbours are read every
  /// floor(sqrt(8 r tol) / ds) slices (offset.h bound ds'^2 / (8 r) <= tol). 0 = every slice.
  double convolution_tolerance_mm = 0.005;
};
Status validate(const RestOptions& o);

struct RestRegions {
  /// Per family (indexed by Axis): the residue in each analysed slice (on the model's lattice,
  /// from first_level); families not analysed are empty.
  std::array<SliceFamily, 3> families;
  double pitch_mm = 0.1;
  Box3 bounds;  ///< of the model
};

/// Section 3.2, in parallel per slice.
Result<RestRegions> unmachinable_regions(const TriSliceModel& model, const RestOptions& options,
                                         const Context& ctx = default_context());

/// Vertical thickness of the residue of one vertical-family slice along the vertical line at
/// in-plane position `s` (x for the y family, y for the x family), mm.
double residue_thickness(const SliceFamily& family, std::size_t j, double s);

/// Top view of the residue: thickness (mm) per cell of `cell_mm` over the model's xy bounds;
/// row 0 at min y. Each cell's vertical line is read in every family analysed (the vertical
/// families at their slice nearest to the line) and the thickness is the length of the
/// heights at which all of them hold residue: a point is unmachinable only if the
/// representations agree (superposition, section 2.1). This removes the false residues a
/// family shows where a wall is nearly parallel to its planes (offset.h).
struct ThicknessMap {
  int nx = 0, ny = 0;
  double cell_mm = 0.1;
  Vec2 origin;
  std::vector<double> mm;   ///< nx * ny, row-major from min y
  double at(Vec2 p) const;  ///< cell containing p (0 outside)
  double max() const;
};
ThicknessMap thickness_map(const RestRegions& rest, double cell_mm);

/// The map as a picture (north up): white where thinner than `min_mm`, else blue (thin)
/// through red (the thickest residue).
Image thickness_image(const ThicknessMap& map, double min_mm);

/// The residue as points (ASCII PLY) a viewer can open: on each vertical line of a grid of
/// `spacing_mm`, points every `spacing_mm` over the heights the map counts (where all the
/// families analysed hold residue).
std::string residue_points_ply(const RestRegions& rest, double spacing_mm);

}  // namespace swarf
