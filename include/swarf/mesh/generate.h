// Analytic parts for tests, examples and benchmarks: shapes whose offsets, volumes and
// cross-sections are known in closed form. All closed and outward-oriented.
#pragma once

#include "swarf/mesh/mesh.h"

namespace swarf {

Mesh make_box(const Box3& box);
/// Upright cylinder, base centre `base`, `segments` sides (a polygonal prism).
Mesh make_cylinder(Vec3 base, double radius, double height, int segments = 64);
/// UV sphere with `segments` around the axis and segments/2 rings.
Mesh make_sphere(Vec3 center, double radius, int segments = 64);
/// Torus about the z axis: ring radius `major`, tube radius `minor`.
Mesh make_torus(Vec3 center, double major, double minor, int major_segments = 96,
                int minor_segments = 48);

/// The filleted torus test part of seed 001 (its Fig. 11): a torus ring resting on a square
/// plate, joined to the plate by concave fillets of `outer_fillet` (outside the ring) and
/// `inner_fillet` (inside) radius. Dimensions in mm; the plate top is z = 0.
struct FilletedTorusPart {
  double plate_size = 80.0;
  double plate_thickness = 10.0;
  double major_radius = 25.0;
  double minor_radius = 10.0;
  double outer_fillet = 4.0;
  double inner_fillet = 3.0;
  int segments = 128;  ///< around the z axis; the profile gets comparable resolution
};
Mesh make_filleted_torus_part(const FilletedTorusPart& part = {});

/// A box-shaped block of `size` with four rectangular bosses on top (seed 003's test part).
Mesh make_block_with_bosses(Vec3 size, double boss_size, double boss_height);

}  // namespace swarf
