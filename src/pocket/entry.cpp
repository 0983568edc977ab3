// The resolved model (resolution rule, pixel stock set-up) and the entry: distance
// transform, medial axis, plunge point at its maximum, helix or ramp (seed 000 4.1, 4.2).
#include <algorithm>
#include <cmath>
#include <string>

#include "pocket/adaptive_internal.h"
#include "pocket/distance_transform.h"
#include "pocket/geometry.h"

namespace swarf::pocket {

namespace {

std::string mm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g mm", v);
  return b;
}

double clearance_mm(const Model& m, int i, int j) {
  return std::sqrt(static_cast<double>(m.clearance_sq[m.grid.index(i, j)])) * m.h;
}

void add_disk(const Grid& grid, Vec2 c, double r, BitImage& img) {
  for_disk(grid, c, r, [&](int i, int j) { img.set(i, j, true); });
}

// Tool positions with room where no pixel centre is free (our addition). The free set of
// the model is sampled at pixel centres, and a pixel centre's clearance reads up to about
// a pixel short of the exact one (the forbidden pixels keep half a pixel off the walls), so
// a patch of free positions narrower than that holds no free pixel: the material only it
// reaches was not material at all, silently left. Found by bench/pocket_random.sh, seed
// 317: a ø20 tool between a square island and a round wall 20.2 mm apart fits along a
// patch 0.22 mm wide and 8.8 mm long (0.11 mm of room each side), and 328 mm^2 behind it
// were never cut. Candidates are the ridge pixels of the clearance within two pixels of the
// radius and not within two pixels of a free pixel; each is moved, by a pattern search in
// its 3 x 3 pixel neighbourhood, to where the exact distance to the walls is largest, and
// kept when that is at least the radius plus the wall stock and the output's clearance of
// 2 um (a spot 0.4 um wider than a ø4, seed 140, is not worth a plunge), and its disk holds a
// quarter disk of pocket that no free pixel centre reaches. Less is the tip of a wedge the
// free pixels end short of (1-2 mm^2 with a ø10 tool on three random pockets), which the
// tip visits take anyway; as material of its own it only changed the path round it.
std::vector<Vec2> tight_centres(const Model& m, const BitImage& free_centres,
                                const BitImage& reach) {
  const double r_px = m.radius_mm / m.h;
  const double need = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  const double quarter_disk_px = 0.25 * kPi * r_px * r_px;
  std::vector<Vec2> out;
  // Pocket pixels in the tool's disk at c that no free pixel centre reaches.
  auto unreached = [&](Vec2 c) {
    int n = 0;
    for_disk(m.grid, c, m.radius_mm, [&](int pi, int pj) {
      n += m.pocket.get(pi, pj) && !m.forbidden.get(pi, pj) && !reach.get(pi, pj);
    });
    return n;
  };
  const std::vector<int> ridge =
      medial_axis(m.clearance_sq, m.grid.width, m.grid.height, std::max(0.0, r_px - 2.0));
  if (ridge.empty()) return out;
  const BitImage near = dilate_by_disk(free_centres, 2.0);
  for (int idx : ridge) {
    const int i = idx % m.grid.width, j = idx / m.grid.width;
    if (near.get(i, j)) continue;
    const Vec2 p = m.grid.to_world(i, j);
    Vec2 best = p;
    double best_d = m.walls.distance(p);
    for (double step = 0.5 * m.h; step > m.h / 64.0; step *= 0.5) {
      bool moved = true;
      while (moved) {
        moved = false;
        for (int k = 0; k < 8; ++k) {
          const double a = kPi / 4.0 * k;
          const Vec2 q = best + Vec2{std::cos(a), std::sin(a)} * step;
          if (std::fabs(q.x - p.x) > 1.5 * m.h || std::fabs(q.y - p.y) > 1.5 * m.h) continue;
          const double d = m.walls.distance(q);
          if (d > best_d) {
            best_d = d;
            best = q;
            moved = true;
          }
        }
      }
    }
    if (best_d < need || !m.walls.inside(best)) continue;
    if (unreached(best) >= quarter_disk_px) out.push_back(best);
  }
  // Patches of free positions with no free pixel centre at all, found exactly: each outer
  // ring of the pocket shrunk by `need` is one connected patch of tool centres (random pocket
  // 894: a ø20 below a round island, beside a square one and above a wall, fits in a patch
  // 0.2 x 0.3 mm with 0.05 mm of room, and the 49 mm^2 only it reaches were not material;
  // less than a quarter disk, so the ridge search above passed it by). Such a patch is no
  // wedge tip the path can reach from its free pixels, so any entry's worth is kept.
  const PolygonSet centres = offset(m.region, -need);
  const double min_px = std::max(16.0, 1.0 / (m.h * m.h));  // 1 mm^2
  for (const Ring& ring : centres.rings) {
    if (ring.size() < 3 || signed_area(ring) <= 0.0) continue;
    Box2 box;
    for (Vec2 v : ring)
      box.add(v);
    const Vec2 lo = m.grid.to_px(box.min), hi = m.grid.to_px(box.max);
    bool has_free = false;
    for (int j = std::max(0, static_cast<int>(std::floor(lo.y)));
         j <= std::min(m.grid.height - 1, static_cast<int>(std::ceil(hi.y))) && !has_free; ++j) {
      for (int i = std::max(0, static_cast<int>(std::floor(lo.x)));
           i <= std::min(m.grid.width - 1, static_cast<int>(std::ceil(hi.x))) && !has_free; ++i) {
        has_free = free_centres.get(i, j) && point_in_ring(ring, m.grid.to_world(i, j));
      }
    }
    if (has_free) continue;
    bool known = false;
    for (Vec2 c : out)
      known = known || point_in_ring(ring, c);
    if (known) continue;
    Vec2 c{0.0, 0.0};
    for (Vec2 v : ring)
      c = c + v;
    c = c / static_cast<double>(ring.size());
    if (!m.walls.inside(c) || m.walls.distance(c) < need) continue;
    if (unreached(c) >= min_px) out.push_back(c);
  }
  return out;
}

// The squared clearance (px^2) of the pixel nearest p; null outside the image.
const float* clearance_sq_near(const Model& m, Vec2 p) {
  const Vec2 q = m.grid.to_px(p);
  const int i = static_cast<int>(std::lround(q.x)), j = static_cast<int>(std::lround(q.y));
  if (i < 0 || j < 0 || i >= m.grid.width || j >= m.grid.height) return nullptr;
  return &m.clearance_sq[m.grid.index(i, j)];
}

}  // namespace

double clearance_at(const Model& m, Vec2 p) {
  const float* c = clearance_sq_near(m, p);
  return c == nullptr ? 0.0 : std::sqrt(static_cast<double>(*c)) * m.h - 0.71 * m.h;
}

bool far_from_walls(const Model& m, Vec2 a, Vec2 b, double reach) {
  // clearance_at(a) - 1.29 pixels - |ab| >= reach, without the square root (it runs for
  // most points of the path, several times).
  const float* c = clearance_sq_near(m, a);
  const double need_px = (reach + distance(a, b)) / m.h + 2.0;
  return c != nullptr && static_cast<double>(*c) >= need_px * need_px;
}

bool keeps_off_walls(const Model& m, Vec2 a, Vec2 b, double least) {
  return far_from_walls(m, a, b, least) || m.walls.segment_distance(a, b) >= least;
}

Result<Model> make_model(const Pocket& pocket, const Tool& tool, const AdaptiveParams& p) {
  Model m;
  m.radius_mm = tool.radius();
  const double r = m.radius_mm;
  m.stepover_mm = p.engagement_deg > 0.0 ? stepover_for_angle_mm(p.engagement_deg, r)
                  : p.stepover_mm > 0.0  ? p.stepover_mm
                                         : 0.1 * tool.diameter_mm;
  m.target_deg = engagement_angle_deg(m.stepover_mm, r);
  // The step (seed 000's delta_step, which the paper leaves open): a quarter of the
  // stepover, held within [D / 40, D / 20]. Measured (session 24, docs/pocket.md): against
  // D / 20 at every stepover, a ø10 at 10 % holds +-20 % over 94.7 % of the L's cut instead
  // of 92.4 % and its largest engagement falls 107 -> 79 degrees (the random batches: +0.5
  // to +0.8 points). Below D / 40 the wide stepovers (20-30 %) lift far more often (the L
  // at 20 %: 1 -> 32 lifts).
  const double longest_auto_step_mm = tool.diameter_mm / 20.0;
  m.step_mm = p.step_mm > 0.0
                  ? p.step_mm
                  : std::clamp(0.25 * m.stepover_mm, tool.diameter_mm / 40.0, longest_auto_step_mm);
  // Resolution rule (seed 000 section 3.2, made explicit): a straight step at the target
  // stepover removes stepover x step mm^2. The count is noisy by about the square root of
  // the pixels along the two crescent arcs; at >= 64 pixels per step that noise stays near
  // 3-5 %, well inside the +-10 % band. The tool radius must also span >= 40 pixels so
  // that the disk and the gouge margin (half a pixel) are accurate. h = the smaller of
  // sqrt(stepover x step / 64) and R / 40.
  m.rule_h =
      p.resolution_mm > 0.0 ? 0.0 : std::min(std::sqrt(m.stepover_mm * m.step_mm / 64.0), r / 40.0);
  m.h = p.resolution_mm > 0.0 ? p.resolution_mm : m.rule_h;

  Box2 box;
  for (const Ring& ring : pocket.region.rings) {
    for (Vec2 q : ring)
      box.add(q);
  }
  double margin_mm = r + m.step_mm + p.wall_stock_mm;
  auto pixels_at = [&](double h, double margin) {
    const Vec2 size = box.size() + Vec2{2.0 * (margin + 4.0 * h), 2.0 * (margin + 4.0 * h)};
    return (std::ceil(size.x / h) + 1.0) * (std::ceil(size.y / h) + 1.0);
  };
  // The pixel budget: a large pocket cut with a small tool (a 250 mm square with a 3 mm end
  // mill) would need more pixels than the budget at the rule's resolution. The automatic
  // resolution is then coarsened until it fits, as long as the disk still spans 20 pixels
  // and a straight step at the target still removes 16 (a count noisier by about half, still
  // inside the +-10 % band); beyond that, a clear error. An explicit resolution is not
  // changed.
  // The automatic step then grows back towards D / 20 to keep 64 pixels a step: at the
  // coarser pixel the quarter-stepover step's count is noisier and its path twice as long
  // (the L with a ø1 at 10 %, coarsened to 0.0118 mm: 16 s with the quarter step, 8.6 s
  // with the step grown to D / 20, 95.2 % within +-20 % by the sweep either way). The
  // image is sized for the step it may grow to.
  const bool auto_step = p.step_mm <= 0.0;
  const double budget_margin_mm =
      auto_step ? r + longest_auto_step_mm + p.wall_stock_mm : margin_mm;
  if (p.resolution_mm <= 0.0 && pixels_at(m.h, margin_mm) > p.max_pixels) {
    const double coarsest = std::min(r / 20.0, std::sqrt(m.stepover_mm * m.step_mm / 16.0));
    double h = m.h;
    for (int k = 0; k < 60 && pixels_at(h, budget_margin_mm) > p.max_pixels; ++k)
      h *= 1.02;
    if (h > coarsest) {
      return bad_parameter(
          "pocket " + pocket.source + ": " + mm(box.size().x) + " x " + mm(box.size().y) +
          " is too large for a " + mm(2.0 * r) + " tool within the pixel budget (" +
          std::to_string(static_cast<long long>(p.max_pixels)) + " pixels, resolution at least " +
          mm(coarsest) + "); split the pocket, use a larger tool or raise max_pixels");
    }
    m.h = h;
    if (auto_step) {
      m.step_mm = std::clamp(64.0 * h * h / m.stepover_mm, m.step_mm, longest_auto_step_mm);
      margin_mm = r + m.step_mm + p.wall_stock_mm;
    }
  }
  m.target_px = m.stepover_mm * m.step_mm / (m.h * m.h);
  m.tol_px = std::max(1.0, m.target_px * p.tolerance_pct / 100.0);
  m.cut_px = cut_threshold_px(m.target_px);
  m.theta_max_deg = static_cast<int>(std::lround(p.max_deviation_deg));
  m.sigma = p.climb ? -1 : 1;
  m.one_way = p.one_way;
  m.smooth_links = p.smooth_links;
  m.want_helix_mm = p.helix_radius_mm > 0.0 ? p.helix_radius_mm : 0.3 * 2.0 * r;
  m.straight_plunge = p.straight_plunge;
  m.link_lift_mm = std::max(2.0 * (p.wall_scallop_mm > 0.0 ? p.wall_scallop_mm : 0.1), m.h);

  m.grid = Grid::covering(box, m.h, margin_mm + 4.0 * m.h);
  if (static_cast<double>(m.grid.width) * m.grid.height > p.max_pixels) {
    return bad_parameter("pocket " + pocket.source + ": resolution " + mm(m.h) + " needs " +
                         std::to_string(static_cast<long long>(m.grid.width) * m.grid.height) +
                         " pixels, more than max_pixels (" +
                         std::to_string(static_cast<long long>(p.max_pixels)) +
                         "); raise resolution_mm or max_pixels");
  }
  m.pocket = rasterize(pocket.region, m.grid);
  // Forbidden: outside the pocket, or closer to a wall than wall stock + half a pixel, by
  // exact distance to the outline (the grid alone is only good to a pixel). The half pixel
  // keeps the true disk within about 0.2 pixel of the wall. Only pixels in the box of an
  // edge grown by that distance can be that close to it, so each edge tests just those.
  m.forbidden = BitImage(m.grid.width, m.grid.height);
  const double keep = p.wall_stock_mm + 0.5 * m.h;
  m.region = pocket.region;
  m.walls = WallIndex(m.region);
  m.wall_stock_mm = p.wall_stock_mm;
  for (int j = 0; j < m.grid.height; ++j) {
    for (int w = 0; w < m.pocket.words_per_row(); ++w)
      m.forbidden.set_word(j, w, ~m.pocket.word(j, w));
  }
  for (const Ring& ring : pocket.region.rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      const Vec2 lo = m.grid.to_px({std::min(a.x, b.x) - keep, std::min(a.y, b.y) - keep});
      const Vec2 hi = m.grid.to_px({std::max(a.x, b.x) + keep, std::max(a.y, b.y) + keep});
      const int i0 = std::max(0, static_cast<int>(std::floor(lo.x)));
      const int i1 = std::min(m.grid.width - 1, static_cast<int>(std::ceil(hi.x)));
      const int j0 = std::max(0, static_cast<int>(std::floor(lo.y)));
      const int j1 = std::min(m.grid.height - 1, static_cast<int>(std::ceil(hi.y)));
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          if (!m.forbidden.get(i, j) && point_segment_distance(m.grid.to_world(i, j), a, b) < keep)
            m.forbidden.set(i, j, true);
        }
      }
    }
  }
  m.clearance_sq = squared_distance_transform(m.forbidden, true);
  // Material is what the tool can reach: pixels within R of a centre whose disk is free.
  // Corners the tool cannot enter and the wall margin are not material, so they neither
  // count as engagement nor keep the tool searching near them.
  {
    const double r_px = r / m.h;
    m.free_centres = BitImage(m.grid.width, m.grid.height);
    for (int j = 0; j < m.grid.height; ++j) {
      for (int i = 0; i < m.grid.width; ++i) {
        if (std::sqrt(static_cast<double>(m.clearance_sq[m.grid.index(i, j)])) > r_px)
          m.free_centres.set(i, j, true);
      }
    }
    BitImage reach = dilate_by_disk(m.free_centres, r_px);
    m.tight_centres = tight_centres(m, m.free_centres, reach);
    for (Vec2 c : m.tight_centres)
      add_disk(m.grid, c, r, reach);
    m.material = BitImage(m.grid.width, m.grid.height);
    for (int j = 0; j < m.grid.height; ++j) {
      for (int w = 0; w < m.pocket.words_per_row(); ++w)
        m.material.set_word(j, w, m.pocket.word(j, w) & ~m.forbidden.word(j, w) & reach.word(j, w));
    }
  }
  double perim = 0.0;
  for (const Ring& ring : pocket.region.rings) {
    for (std::size_t k = 0; k < ring.size(); ++k)
      perim += distance(ring[k], ring[(k + 1) % ring.size()]);
  }
  m.boundary_round_mm =
      perim + 2.0 * kPi * r * static_cast<double>(pocket.island_count()) + 4.0 * r;
  double a = 0.0;
  for (const Ring& ring : pocket.region.rings)
    a += ring_area(ring);
  m.pocket_area_mm2 = a;
  return m;
}

PixelStock fresh_stock(const Model& m) {
  return PixelStock(m.grid, m.material, m.forbidden, m.radius_mm, &m.clearance_sq);
}

namespace {

Vec2 axis_point(const Model& m, int idx) {
  const int i = idx % m.grid.width, j = idx / m.grid.width;
  return m.grid.to_world(i, j);
}

// The smallest entry worth making instead of a straight plunge: a helix of a tenth of the
// tool radius, or a ramp twice that long, which sweeps a path as wide (before, the ramp
// needed only the helix's radius: whether a square 0.25 mm wider than a ø6 held a 0.3 mm
// "ramp" then turned on the pixel size, the finer pixels of a shorter step finding one
// where coarser ones did not). Twice the pixel at least, which the resolution rule's
// R / 40 keeps below both.
double min_helix_radius_mm(const Model& m) {
  return std::max(2.0 * m.h, 0.1 * m.radius_mm);
}
double min_ramp_length_mm(const Model& m) {
  return 2.0 * min_helix_radius_mm(m);
}

// Straight down at c, the moves starting there; `solid`: into uncut material.
Entry plunge_at(Vec2 c, bool solid) {
  Entry e;
  e.centre = c;
  e.start = c;
  e.plunge = true;
  e.solid = solid;
  return e;
}

// The entry at the medial-axis pixel idx: a helix where one of at least min_helix fits,
// else a ramp along the longest straight line of free centres through it (5 degree
// directions); false when neither fits.
bool entry_at(const Model& m, int idx, Entry& e) {
  const double r = m.radius_mm;
  const double min_helix = min_helix_radius_mm(m);
  const double min_ramp = min_ramp_length_mm(m);
  const int i = idx % m.grid.width, j = idx / m.grid.width;
  const Vec2 c = m.grid.to_world(i, j);
  const double room = clearance_mm(m, i, j) - r - m.h;  // helix radius that fits
  e = Entry{};
  e.centre = c;
  if (room >= min_helix) {
    e.helix_radius_mm = std::min(m.want_helix_mm, room);
    e.start = c + Vec2{e.helix_radius_mm, 0.0};
    // Moving counter-clockwise round the hole keeps the material on the right (climb).
    e.start_angle_rad = m.sigma < 0 ? kPi / 2 : -kPi / 2;
    return true;
  }
  double best_len = 0.0;
  Vec2 ba, bb;
  for (int deg = 0; deg < 180; deg += 5) {
    const Vec2 d{std::cos(deg_to_rad(deg)), std::sin(deg_to_rad(deg))};
    double t0 = 0.0, t1 = 0.0;
    while (t1 < 4.0 * r && clearance_at(m, c + d * (t1 + m.h)) > r)
      t1 += m.h;
    while (t0 < 4.0 * r && clearance_at(m, c - d * (t0 + m.h)) > r)
      t0 += m.h;
    if (t0 + t1 > best_len) {
      best_len = t0 + t1;
      ba = c - d * t0;
      bb = c + d * t1;
    }
  }
  // The pixel clearance can read up to about half a pixel long beside a curved wall (the
  // nearest forbidden pixel centre lies off the nearest wall point), so the ramp is held to
  // the exact walls, as every other move of the output: its ends come in a pixel at a time
  // until the whole line keeps the tool radius, wall stock and kWallClearanceMm off them
  // (session 15: random pocket seed 528, ø3, a new entry's ramp ended 4 um into a round
  // island by the sweep).
  const double need = r + m.wall_stock_mm + kWallClearanceMm;
  while (best_len >= min_ramp && m.walls.segment_distance(ba, bb) < need) {
    const Vec2 d = (bb - ba) * (m.h / best_len);
    if (m.walls.distance(ba) < m.walls.distance(bb)) {
      ba = ba + d;
    } else {
      bb = bb - d;
    }
    best_len = distance(ba, bb);
  }
  if (best_len < min_ramp) return false;
  e.ramp_a = ba;
  e.ramp_b = bb;
  e.start = bb;
  e.start_angle_rad = std::atan2(bb.y - ba.y, bb.x - ba.x);
  return true;
}

// The end of the line from `fixed` through `end`, pushed on along it by at most `span` as
// far as the whole line keeps `need` off the exact walls (bisection to 1 um).
Vec2 pushed_to_wall(const Model& m, Vec2 fixed, Vec2 end, double span, double need) {
  const Vec2 d = normalized(end - fixed);
  double lo = 0.0, hi = span;
  while (hi - lo > 1e-3) {
    const double mid = 0.5 * (lo + hi);
    (m.walls.segment_distance(fixed, end + d * mid) >= need ? lo : hi) = mid;
  }
  return end + d * lo;
}

// In a channel with room for one or two band-deep strips beside a ramp's slot, the first
// entry's ramp runs along one wall's offset: a ramp down its middle leaves two strips each
// half the room, thinner than the band's depth (a channel 8.8 mm wide, a ø8 at 10 %: two
// 0.4 mm strips cut at 26 degrees, 37 targeted, 45 % of the cut in the band by the sweep),
// where one along a wall leaves one strip the whole room thick (57 %). The strip is on the
// milling side of the way back along the ramp. Done on the first entries chosen only: the
// new-entry search scores candidates by what their ends' disks hold, and moved ramps there
// changed which it took (random pocket 714: a ramp of 80 legs, +11 s).
void ramp_along_a_wall(const Model& m, Entry& e) {
  if (e.helix_radius_mm > 0.0 || e.plunge) return;
  const double need = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  const Vec2 d = normalized(e.ramp_b - e.ramp_a);
  const Vec2 n = Vec2{-d.y, d.x} * (m.sigma < 0 ? -1.0 : 1.0);  // towards the wall kept to
  const double room_max =
      2.0 * stepover_for_angle_mm(std::min(1.2 * m.target_deg, 90.0), m.radius_mm);
  auto room_towards = [&](Vec2 side) {
    double lo = 0.0, hi = room_max + m.h;
    if (m.walls.segment_distance(e.ramp_a + side * hi, e.ramp_b + side * hi) >= need) return hi;
    while (hi - lo > 1e-4) {
      const double mid = 0.5 * (lo + hi);
      (m.walls.segment_distance(e.ramp_a + side * mid, e.ramp_b + side * mid) >= need ? lo : hi) =
          mid;
    }
    return lo;
  };
  const double to_wall = room_towards(n), away = room_towards(n * -1.0);
  if (!(to_wall > 0.0 && to_wall + away <= room_max)) return;
  e.ramp_a = e.ramp_a + n * to_wall;
  e.ramp_b = e.ramp_b + n * to_wall;
  e.start = e.ramp_b;
  // Then, where that strip is deep enough to be cut in the band, the ramp runs on along the
  // wall for as long as the channel lasts (the tool keeps to that wall's offset and the other
  // wall stays within the room), not the 4 R either way of a ramp elsewhere: its closing
  // pass at the floor leaves the one strip along the whole channel, which the moves cut in
  // the band, where the channel beyond a short ramp was cut by the chooser's tight loops
  // wall to wall. A thinner strip is cut below the band whatever the way: there the loops'
  // crescents keep more of the cut in it.
  if (to_wall + away < stepover_for_angle_mm(0.8 * m.target_deg, m.radius_mm)) return;
  auto in_channel = [&](Vec2 q) {
    return m.walls.distance(q + n * m.h) < need &&
           m.walls.distance(q - n * (room_max + m.h)) < need;
  };
  auto run_on = [&](Vec2 fixed, Vec2 end) {
    const Vec2 dir = normalized(end - fixed);
    for (;;) {
      const Vec2 next = end + dir * m.h;
      // The channel's end: on to the offset of the wall there.
      if (m.walls.segment_distance(fixed, next) < need)
        return pushed_to_wall(m, fixed, end, m.h, need);
      if (!in_channel(next)) return end;
      end = next;
    }
  };
  e.ramp_b = run_on(e.ramp_a, e.ramp_b);
  e.ramp_a = run_on(e.ramp_b, e.ramp_a);
  e.start = e.ramp_b;
}

// A chosen ramp's ends that stopped at a wall lie up to about a pixel short of the exact
// reach (the march above steps a pixel at a time); the output snaps the path beside a wall
// onto the exact offset, so the first move after such a ramp went on along it by that
// much, a full slot of up to a pixel (random pocket 3053, ø20 in a channel 2.1 mm wider:
// 0.17 mm). Each such end (nearer the centre than the 4 R cap) is pushed out along the
// line, by bisection on the exact walls, to within 1 um of that offset. Done on the entry
// chosen, not in entry_at: the new-entry search scores candidates by what their ends'
// disks hold, and ends reaching further there made it pick ramps for crumbs at the walls
// (+1 lift and about 10 s on 10 of 98 random pockets).
void reach_walls(const Model& m, Entry& e) {
  if (e.helix_radius_mm > 0.0 || e.plunge) return;
  const double need = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  auto reach = [&](Vec2 fixed, Vec2 end) {
    if (distance(e.centre, end) >= 4.0 * m.radius_mm - 1e-9) return end;
    return pushed_to_wall(m, fixed, end, 2.0 * m.h, need);
  };
  e.ramp_b = reach(e.ramp_a, e.ramp_b);
  e.ramp_a = reach(e.ramp_b, e.ramp_a);
  e.start = e.ramp_b;
}

}  // namespace

std::vector<int> entry_axis(const Model& m, double min_clearance_px) {
  // Medial axis pixels whose disk fits (seed 000 Fig. 3), widest first.
  std::vector<int> axis =
      medial_axis(m.clearance_sq, m.grid.width, m.grid.height, min_clearance_px);
  std::stable_sort(axis.begin(), axis.end(),
                   [&](int a, int b) { return m.clearance_sq[a] > m.clearance_sq[b]; });
  return axis;
}

EntryAxis make_entry_axis(const Model& m, double min_clearance_px) {
  EntryAxis a;
  a.pixels = entry_axis(m, min_clearance_px);
  a.fits.assign(a.pixels.size(), -1);
  a.entry.resize(a.pixels.size());
  return a;
}

Result<std::vector<Entry>> find_entries(const Model& m, int count) {
  const double r = m.radius_mm;
  const std::vector<int> order = entry_axis(m, m.radius_mm / m.h + 1.0);
  if (order.empty()) {
    double best = 0.0;
    for (float v : m.clearance_sq)
      best = std::max(best, static_cast<double>(v));
    return Status(Error::kToolTooLarge,
                  "the " + mm(2 * r) + " tool fits nowhere in the pocket (widest point " +
                      mm(2 * std::sqrt(best) * m.h) + " across, wall stock included)");
  }
  std::vector<Entry> out;
  std::vector<Vec2> chosen;
  for (int idx : order) {
    if (static_cast<int>(out.size()) >= count) break;
    const Vec2 c = axis_point(m, idx);
    bool far = true;
    for (Vec2 q : chosen)
      far = far && distance(q, c) > 2.0 * r + 2.0 * m.want_helix_mm;
    if (!far) continue;
    Entry e;
    if (!entry_at(m, idx, e)) continue;
    ramp_along_a_wall(m, e);
    reach_walls(m, e);
    chosen.push_back(c);
    out.push_back(e);
  }
  if (out.empty() && m.straight_plunge) {
    // No room to helix or ramp anywhere: straight down at the widest point (a pocket barely
    // wider than the tool). A helix of the few hundredths of a millimetre that fit would
    // cut the same full circle.
    out.push_back(plunge_at(axis_point(m, order.front()), true));
  }
  if (out.empty()) {
    const Vec2 c = axis_point(m, order.front());
    char b[96];
    std::snprintf(b, sizeof b, "(%.3f, %.3f)", c.x, c.y);
    return Status(Error::kNoEntryFound, "the tool fits at " + std::string(b) +
                                            " but there is no room for a helix of " +
                                            mm(min_helix_radius_mm(m)) + " radius or a ramp " +
                                            mm(min_ramp_length_mm(m)) + " long)");
  }
  return out;
}

namespace {

// Points a plunge entry's first move towards the material in its disk: the mean direction
// of those pixels.
void aim_at_material(const Model& m, const PixelStock& stock, Entry& e) {
  const Vec2 q = m.grid.to_px(e.centre);
  Vec2 sum{0.0, 0.0};
  for_disk(m.grid, e.centre, m.radius_mm, [&](int i, int j) {
    if (stock.material().get(i, j)) sum = sum + normalized(Vec2{i - q.x, j - q.y + 1e-12});
  });
  e.start_angle_rad = std::atan2(sum.y, sum.x);
}

}  // namespace

bool find_entry_for_material(const Model& m, const PixelStock& stock, EntryAxis& axis, int min_px,
                             Entry& e) {
  const double r = m.radius_mm;
  // A plunge first: where the inner half of the disk is already cleared, going straight
  // down only loads the end teeth near the rim, and costs a retract and a plunge instead
  // of a helix from the top (the material given up on is mostly the skin of a wedge or a
  // corner next to cleared floor).
  int best_px = min_px - 1;
  bool found = false;
  for (int idx : axis.pixels) {
    const Vec2 c = axis_point(m, idx);
    if (stock.material_in_disk(c, 0.5 * r, 0) > 0) continue;
    const int px = stock.material_in_disk(c, r);
    if (px > best_px) {
      best_px = px;
      e = plunge_at(c, false);
      found = true;
    }
  }
  if (found) {
    aim_at_material(m, stock, e);
    return true;
  }
  best_px = min_px - 1;
  for (std::size_t k = 0; k < axis.pixels.size(); ++k) {
    const int idx = axis.pixels[k];
    const Vec2 c = axis_point(m, idx);
    // A ramp reaches at most 4 R either way.
    if (stock.material_in_disk(c, 5.0 * r, 0) == 0) continue;
    // Worked out once per pixel (a third of the run on a plate of 132 chambers, each new
    // entry trying the ramps of every pixel near material).
    if (axis.fits[k] < 0) axis.fits[k] = entry_at(m, idx, axis.entry[k]) ? 1 : 0;
    if (axis.fits[k] == 0) continue;
    const Entry& cand = axis.entry[k];
    // What the entry takes: the helix's hole, or the most of the disks at the ramp's ends
    // and middle (a ramp runs along a wedge into its tip, where the material is).
    const int px =
        cand.helix_radius_mm > 0.0
            ? stock.material_in_disk(c, r + cand.helix_radius_mm)
            : std::max({stock.material_in_disk(cand.ramp_a, r),
                        stock.material_in_disk(cand.ramp_b, r), stock.material_in_disk(c, r)});
    if (px > best_px) {
      best_px = px;
      found = true;
      e = cand;
    }
  }
  if (found) reach_walls(m, e);
  if (found || !m.straight_plunge) return found;
  // Our addition: no helix or ramp fits where the material is. Straight down where the disk
  // takes the most of it, if that is at least a quarter of a disk (the slivers such a plunge
  // leaves round it are not worth a plunge each). The candidates are the medial axis of
  // every free centre, not only of those with 0.75 pixel of room (the axis above): the walls
  // are checked by exact geometry instead. Found by bench/pocket_random.sh: seed 118 kept a
  // chamber behind a neck half as wide as the tool, which the tool reaches with 0.06 mm to
  // spare (28.6 mm^2, a whole disk); seed 144 (a ø20 with 0.25 mm pixels) 179 mm^2 behind a
  // patch of centres with 0.15 mm of room beyond the radius, less than the axis's margin.
  const std::vector<int> tight = entry_axis(m, r / m.h);
  best_px = std::max(best_px, static_cast<int>(0.25 * kPi * r * r / (m.h * m.h)));
  for (int idx : tight) {
    const Vec2 c = axis_point(m, idx);
    const int px = stock.material_in_disk(c, r);
    if (px <= best_px) continue;
    if (m.walls.distance(c) < r + m.wall_stock_mm + kWallClearanceMm) continue;
    best_px = px;
    e = plunge_at(c, true);
    found = true;
  }
  // Then the tool positions between pixel centres (make_model), checked exactly there. What
  // their disks reach nothing else does (no free pixel centre within two pixels), so any
  // entry's worth of it is taken, not only a quarter disk.
  if (!found) best_px = min_px - 1;
  for (Vec2 c : m.tight_centres) {
    const int px = stock.material_in_disk(c, r);
    if (px <= best_px) continue;
    best_px = px;
    e = plunge_at(c, true);
    found = true;
  }
  if (found) aim_at_material(m, stock, e);
  return found;
}

void cut_entry(PixelStock& stock, const Model& m, const Entry& e, CutVisitor visit, void* user) {
  if (e.plunge) {
    stock.stamp(e.centre, visit, user);
    return;
  }
  if (e.helix_radius_mm > 0.0) {
    stock.stamp(e.centre, visit, user);
    const int n = std::max(8, static_cast<int>(std::ceil(2 * kPi * e.helix_radius_mm / m.h)));
    Vec2 prev = e.centre;
    for (int k = 0; k <= n; ++k) {
      const double a = 2 * kPi * k / n;
      const Vec2 p = e.centre + Vec2{std::cos(a), std::sin(a)} * e.helix_radius_mm;
      stock.cut(k == 0 ? Vec2{1e9, 1e9} : prev, p, visit, user);
      prev = p;
    }
    return;
  }
  const double len = distance(e.ramp_a, e.ramp_b);
  const int n = std::max(1, static_cast<int>(std::ceil(len / m.h)));
  Vec2 prev{1e9, 1e9};
  for (int k = 0; k <= n; ++k) {
    const Vec2 p = e.ramp_a + (e.ramp_b - e.ramp_a) * (static_cast<double>(k) / n);
    stock.cut(prev, p, visit, user);
    prev = p;
  }
}

}  // namespace swarf::pocket
