// Contour-parallel pocketing with Clipper offsets (through swarf/polygon/polygon.h).
#include "swarf/pocket/contour_parallel.h"

#include <algorithm>
#include <cmath>

#include "pocket/geometry.h"
#include "pocket/wall_index.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

Status validate(const ContourParallelParams& p, const Tool& tool) {
  if (!(tool.diameter_mm > 0.0)) return bad_parameter("tool diameter must be positive");
  if (p.stepover_mm < 0.0 || p.stepover_mm > tool.diameter_mm)
    return bad_parameter("stepover_mm must be in (0, tool diameter] (0 = 10 % of it)");
  if (!(p.depth_mm > 0.0)) return bad_parameter("depth_mm must be positive");
  if (p.stepdown_mm < 0.0) return bad_parameter("stepdown_mm must not be negative");
  // The whole depth in one layer (stepdown 0) must fit the flutes, as in the adaptive op.
  if (p.stepdown_mm > tool.flute_length_mm ||
      (p.stepdown_mm == 0.0 && p.depth_mm > tool.flute_length_mm))
    return bad_parameter("stepdown exceeds the flute length of the tool");
  if (p.floor_stock_mm < 0.0 || p.floor_stock_mm >= p.depth_mm)
    return bad_parameter("floor_stock_mm must be in [0, depth_mm)");
  if (p.wall_stock_mm < 0.0) return bad_parameter("wall_stock_mm must not be negative");
  if (!(p.feed_mm_min > 0.0)) return bad_parameter("feeds must be positive mm/min");
  if (!(p.ramp_feed_mm_min >= 0.0))
    return bad_parameter("ramp_feed_mm_min must be >= 0 (0 = the cutting feed)");
  if (!(p.ramp_angle_deg > 0.0 && p.ramp_angle_deg <= 45.0))
    return bad_parameter("ramp_angle_deg must be in (0, 45] degrees");
  if (p.clearance_z_mm <= p.top_z_mm) return bad_parameter("clearance_z_mm must be above top_z_mm");
  return {};
}

namespace {

struct Loop {
  Ring pts;
  int level = 0;
  int part = 0;
};

// Is the straight centre move a -> b acceptable without lifting? It must keep the tool
// inside the free region (no gouge) and cut at most a step-over's worth of new material
// (the move from one ring to the next); anything more would slot through stock.
bool link_ok(const PolygonSet& free_region, const PolygonSet& cleared, Vec2 a, Vec2 b, double r,
             double stepover) {
  const double len = distance(a, b);
  const int n = std::max(1, static_cast<int>(std::ceil(len / 0.05)));
  for (int k = 0; k <= n; ++k)
    if (!contains(free_region, a + (b - a) * (static_cast<double>(k) / n))) return false;
  const std::vector<Polyline2> seg{{a, b}};
  const double fresh = area(subtract(inflate_polylines(seg, r), cleared));
  return fresh <= 2.0 * r * stepover * 1.5 + 1e-6;
}

}  // namespace

Result<ContourParallelResult> contour_parallel_pocket(const Pocket& pocket, const Tool& tool,
                                                      const ContourParallelParams& p,
                                                      const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(p, tool));
  const double r = tool.radius();
  const double step = p.stepover_mm > 0.0 ? p.stepover_mm : 0.1 * tool.diameter_mm;
  OffsetOptions oo;
  oo.arc_tolerance_mm = p.arc_tolerance_mm;
  const PolygonSet free_region = offset(pocket.region, -(r + p.wall_stock_mm), oo);
  if (free_region.empty())
    return Status(Error::kToolTooLarge, pocket.source + ": the " +
                                            std::to_string(tool.diameter_mm) +
                                            " mm tool fits nowhere in the pocket");
  // Rings per connected part of the free region, level 0 at the wall.
  const pocket::WallIndex walls(pocket.region);
  std::vector<Loop> loops;
  const auto parts = connected_parts(free_region);
  for (std::size_t pi = 0; pi < parts.size(); ++pi) {
    PolygonSet level = parts[pi];
    for (int lv = 0; !level.empty() && lv < 100000; ++lv) {
      if (ctx.cancelled()) return Status(Error::kCancelled, "contour-parallel cancelled");
      for (const Ring& ring : level.rings) {
        Loop l{ring, lv, static_cast<int>(pi)};
        // Climb: material on the right. Rings round material that lies outside them (the
        // pocket's outer rings) run counter-clockwise; normalized holes are clockwise, so
        // every ring keeps its orientation for climb and is reversed for conventional.
        if (!p.climb) std::reverse(l.pts.begin(), l.pts.end());
        if (lv == 0) {
          // The rings next to the walls: their round joins are chords of arcs round the walls'
          // convex corners (an island's vertex) and cut in by up to the arc tolerance (5-11 um
          // by the sweep); each such edge goes through its middle pushed 2 um off the wall.
          Ring kept;
          std::vector<Vec2> via;
          for (std::size_t k = 0; k < l.pts.size(); ++k) {
            kept.push_back(l.pts[k]);
            via.clear();
            pocket::keep_off_walls(walls, r + p.wall_stock_mm, pocket::kWallClearanceMm, l.pts[k],
                                   l.pts[(k + 1) % l.pts.size()], via);
            kept.insert(kept.end(), via.begin(), via.end());
          }
          l.pts = std::move(kept);
        }
        loops.push_back(std::move(l));
      }
      level = offset(level, -step, oo);
    }
  }
  std::stable_sort(loops.begin(), loops.end(), [&](const Loop& a, const Loop& b) {
    if (a.part != b.part) return a.part < b.part;
    return p.inside_out ? a.level > b.level : a.level < b.level;
  });

  ContourParallelResult res;
  Toolpath& tp = res.toolpath;
  tp.name = "contour-parallel pocket";
  tp.tool_number = tool.number;
  tp.tool_description = tool.description();
  tp.tool_diameter_mm = tool.diameter_mm;
  tp.clearance_z_mm = p.clearance_z_mm;
  const double bottom = p.top_z_mm - p.depth_mm + p.floor_stock_mm;
  const double total = p.top_z_mm - bottom;
  const double sd = p.stepdown_mm > 0.0 ? p.stepdown_mm : total;
  const int layers = std::max(1, static_cast<int>(std::ceil(total / sd - 1e-9)));
  res.rings = static_cast<int>(loops.size());
  const double tan_a = std::tan(deg_to_rad(p.ramp_angle_deg));
  const double ramp_feed = p.ramp_feed_mm_min > 0.0 ? p.ramp_feed_mm_min : p.feed_mm_min;
  int retracts = 0;
  for (int layer = 1; layer <= layers; ++layer) {
    const double z = layer == layers ? bottom : p.top_z_mm - sd * layer;
    const double z_top = layer == 1 ? p.top_z_mm : p.top_z_mm - sd * (layer - 1);
    PolygonSet cleared;
    bool down = false;
    Vec2 at;
    for (std::size_t li = 0; li < loops.size(); ++li) {
      const Ring& ring = loops[li].pts;
      // Start at the ring point nearest to the tool.
      std::size_t s = 0;
      if (down) {
        double best = 1e300;
        for (std::size_t k = 0; k < ring.size(); ++k)
          if (distance(ring[k], at) < best) {
            best = distance(ring[k], at);
            s = k;
          }
      }
      const Vec2 start = ring[s];
      if (down && link_ok(free_region, cleared, at, start, r, step)) {
        tp.feed_to(to_vec3(start, z), p.feed_mm_min, true);
      } else {
        if (down) {
          ++retracts;
          tp.retract();
        }
        // Entry: a helix about the ring's start point as large as the free region allows
        // (up to a quarter of the diameter); where none fits (rings next to the wall),
        // a ramp along the ring itself, which lies in the free region by construction.
        const double room =
            contains(free_region, start) ? distance_to_boundary(free_region, start) : 0.0;
        const double hr = std::min(0.25 * tool.diameter_mm, 0.9 * room);
        if (hr >= 0.05 * tool.diameter_mm) {
          const Vec2 centre = start;
          const Vec2 h0 = centre + Vec2{hr, 0.0};
          tp.rapid_to(to_vec3(h0, p.clearance_z_mm));
          tp.rapid_to(to_vec3(h0, z_top + 1.0));
          double zz = z_top + 1.0;
          const double per_turn = 2 * kPi * hr * tan_a;
          while (zz > z + 1e-9) {
            zz = std::max(z, zz - 0.5 * per_turn);
            tp.arc_to(to_vec3(centre * 2.0 - h0, zz), centre, !p.climb, ramp_feed);
            zz = std::max(z, zz - 0.5 * per_turn);
            tp.arc_to(to_vec3(h0, zz), centre, !p.climb, ramp_feed);
          }
          tp.arc_to(to_vec3(centre * 2.0 - h0, z), centre, !p.climb, ramp_feed);
          tp.arc_to(to_vec3(h0, z), centre, !p.climb, ramp_feed);
          tp.feed_to(to_vec3(start, z), p.feed_mm_min, true);
          Ring disk;
          for (int k = 0; k < 32; ++k)
            disk.push_back(centre +
                           Vec2{std::cos(k * kPi / 16), std::sin(k * kPi / 16)} * (hr + r));
          cleared = unite(cleared, PolygonSet{{disk}});
        } else {
          tp.rapid_to(to_vec3(start, p.clearance_z_mm));
          tp.rapid_to(to_vec3(start, z_top + 1.0));
          double zz = z_top + 1.0;
          std::size_t k = s;
          for (int guard = 0; zz > z + 1e-9 && guard < 1000000; ++guard) {
            const Vec2 a = ring[k % ring.size()], b = ring[(k + 1) % ring.size()];
            zz = std::max(z, zz - distance(a, b) * tan_a);
            tp.ramp_to(to_vec3(b, zz), ramp_feed);
            ++k;
          }
          // Back to the start along the ring at depth (the ramp left material above).
          for (; k % ring.size() != s; ++k)
            tp.feed_to(to_vec3(ring[(k + 1) % ring.size()], z), p.feed_mm_min, true);
        }
        down = true;
      }
      for (std::size_t k = 1; k <= ring.size(); ++k)
        tp.feed_to(to_vec3(ring[(s + k) % ring.size()], z), p.feed_mm_min, true);
      at = start;
      Polyline2 closed(ring.begin(), ring.end());
      closed.push_back(ring.front());
      const std::vector<Polyline2> lines{closed};
      cleared = unite(cleared, inflate_polylines(lines, r, oo));
    }
    tp.retract();
  }
  res.retracts_per_layer = retracts / layers;
  return res;
}

}  // namespace swarf
