#include "sweep_checker.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

namespace swarf::testing {

namespace {

bool inside_ring(const Ring& r, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    if ((r[i].y > p.y) != (r[j].y > p.y) &&
        p.x < (r[j].x - r[i].x) * (p.y - r[i].y) / (r[j].y - r[i].y) + r[i].x)
      in = !in;
  }
  return in;
}
// Even-odd over all rings: inside an outer ring and none of its islands, for a region of
// one part (outer ring, islands) or several.
bool inside(const PolygonSet& s, Vec2 p) {
  bool in = false;
  for (const Ring& r : s.rings)
    in = in != inside_ring(r, p);
  return in;
}
double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / std::max(norm_sq(ab), 1e-300), 0.0, 1.0);
  return norm(p - (a + ab * t));
}
double edge_distance(const PolygonSet& s, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Ring& r : s.rings)
    for (std::size_t i = 0; i < r.size(); ++i)
      best = std::min(best, segment_distance(p, r[i], r[(i + 1) % r.size()]));
  return best;
}
// Whether segments pq and ab cross (properly; touching counts as not).
bool segments_cross(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  auto side = [](Vec2 o, Vec2 u, Vec2 v) { return cross(u - o, v - o); };
  const double d1 = side(a, b, p), d2 = side(a, b, q), d3 = side(p, q, a), d4 = side(p, q, b);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
         d4 != 0;
}
enum class RingState : unsigned char { kBeyondWall, kEngaged, kOther, kUnknown };

struct Sample {
  Vec2 p;
  Vec2 dir;
  double ds;
  bool entry;
  std::size_t move = 0;  ///< index in the toolpath's moves
  bool rapid = false;    ///< a G0 along the floor: read for reversals only
};

// Points along the floor pass every `step` mm.
std::vector<Sample> floor_samples(const Toolpath& tp, double step) {
  double zmin = std::numeric_limits<double>::infinity();
  for (const Move& m : tp.moves)
    zmin = std::min(zmin, m.end.z);
  std::vector<Sample> out;
  Vec3 at = tp.moves.empty() ? Vec3{} : tp.moves.front().end;
  // The entry's closing pass at the floor, which the way down leaves to do: the full
  // circles round a helix's axis, or the pass back along a ramp's last leg (its wedge).
  // Any other floor move, arcs of a fitted path included, is cutting.
  enum class Closing { kNone, kHelix, kRamp } closing = Closing::kNone;
  // Points read back from G-code are rounded to its words (4 decimals): an arc's centre is
  // its start plus I and J, each rounded, so the same axis reads up to 2e-4 mm apart from
  // one arc to the next (random pocket 2419, ø3: a helix's closing circle 1e-4 off its
  // axis counted as 0.8 mm of full slot).
  constexpr double kSamePointMm = 1e-3;
  Vec3 descent_from{}, helix_axis{};
  // A straight move from a to b, sampled every `step` (its end included, its start not).
  auto line = [&](Vec2 a, Vec2 b, bool entry, std::size_t mi, bool rapid) {
    const double len = norm(b - a);
    if (len < 1e-12) return;
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int k = 1; k <= n; ++k)
      out.push_back(
          {a + (b - a) * (static_cast<double>(k) / n), (b - a) / len, len / n, entry, mi, rapid});
  };
  for (std::size_t mi = 0; mi < tp.moves.size(); ++mi) {
    const Move& m = tp.moves[mi];
    const Vec3 from = at;
    at = m.end;
    if (std::abs(m.end.z - zmin) > 1e-6 || m.kind == MoveKind::kRapid) {
      closing = Closing::kNone;
      // A rapid along the floor (another generator's keep-tool-down link) is motion all
      // the same: sampled for the reversals only.
      if (m.kind == MoveKind::kRapid && std::abs(m.end.z - zmin) <= 1e-6 &&
          std::abs(from.z - zmin) <= 1e-6)
        line(from.xy(), m.end.xy(), false, mi, true);
      continue;
    }
    if (std::abs(from.z - zmin) > 1e-6) {
      // Down to the floor (a plunge, a helix's or a ramp's last piece): the disk where it
      // arrives is cut even when no floor move follows (a plunge straight back up).
      out.push_back({m.end.xy(), {1.0, 0.0}, 0.0, true, mi});
      closing = m.kind == MoveKind::kHelix  ? Closing::kHelix
                : m.kind == MoveKind::kRamp ? Closing::kRamp
                                            : Closing::kNone;
      descent_from = from;
      helix_axis = m.center;
      continue;
    }
    const bool entry = (closing == Closing::kHelix && m.is_arc() &&
                        norm(m.center.xy() - helix_axis.xy()) < kSamePointMm) ||
                       (closing == Closing::kRamp && !m.is_arc() &&
                        norm(m.end.xy() - descent_from.xy()) < kSamePointMm);
    if (!entry) closing = Closing::kNone;
    if (m.is_arc()) {
      const Vec2 c = m.center.xy();
      const double r = norm(from.xy() - c);
      double a0 = std::atan2(from.y - c.y, from.x - c.x);
      double a1 = std::atan2(m.end.y - c.y, m.end.x - c.x);
      double sweep = a1 - a0;
      if (m.clockwise && sweep >= 0) sweep -= 2 * kPi;
      if (!m.clockwise && sweep <= 0) sweep += 2 * kPi;
      const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) * r / step)));
      for (int k = 1; k <= n; ++k) {
        const double a = a0 + sweep * k / n;
        const Vec2 tangent = Vec2{-std::sin(a), std::cos(a)} * (m.clockwise ? -1.0 : 1.0);
        out.push_back(
            {c + Vec2{std::cos(a), std::sin(a)} * r, tangent, std::abs(sweep) * r / n, entry, mi});
      }
      continue;
    }
    line(from.xy(), m.end.xy(), entry, mi, false);
  }
  return out;
}

}  // namespace

SweepReport sweep_check(const PolygonSet& region, double R, const Toolpath& path, double target_deg,
                        double h, double tol, std::vector<SweepSample>* samples_out,
                        double removal_window_mm, std::vector<Vec2>* residual_out) {
  SweepReport rep;
  Box2 box;
  for (const Ring& r : region.rings)
    for (Vec2 p : r)
      box.add(p);
  box = box.inflated(R + 2 * h);
  const int w = static_cast<int>(std::ceil(box.size().x / h)) + 1;
  const int ht = static_cast<int>(std::ceil(box.size().y / h)) + 1;
  auto centre = [&](int i, int j) { return box.min + Vec2{i * h, j * h}; };
  // 0 outside, 1 material, 2 cut. Row by row: a cell is inside when an odd number of the
  // region's edge crossings of its row lie to its right (the even-odd rule of inside(),
  // with the same crossing test and the same arithmetic, so the same cells).
  std::vector<unsigned char> cell(static_cast<std::size_t>(w) * ht, 0);
  std::vector<double> crossings;
  for (int j = 0; j < ht; ++j) {
    const double y = box.min.y + j * h;
    crossings.clear();
    for (const Ring& r : region.rings)
      for (std::size_t a = 0, b = r.size() - 1; a < r.size(); b = a++)
        if ((r[a].y > y) != (r[b].y > y))
          crossings.push_back((r[b].x - r[a].x) * (y - r[a].y) / (r[b].y - r[a].y) + r[a].x);
    std::sort(crossings.begin(), crossings.end());
    std::size_t right = 0;  // crossings at or left of the cell: x < crossing counts those right
    for (int i = 0; i < w; ++i) {
      const double x = box.min.x + i * h;
      while (right < crossings.size() && !(x < crossings[right]))
        ++right;
      if ((crossings.size() - right) % 2 == 1) cell[static_cast<std::size_t>(j) * w + i] = 1;
    }
  }
  // Distance to the walls, exact where it matters: it is compared with R (the opening) and
  // with tol (the residual), so cells farther than both from every edge keep "far". Blocks
  // of cells farther than that (by their centre's distance less their half diagonal) are
  // skipped, and the rest measure against the edges near their block only.
  // Cells outside the pocket get theirs too (the engagement's ring asks which side of a
  // wall a point within a pixel of it lies on). Each block also keeps the edges that pass
  // within two pixels of it, for that.
  constexpr float kFar = std::numeric_limits<float>::max();
  std::vector<float> wall_d(cell.size(), kFar);
  constexpr int kBlock = 16;
  const int blocks_x = (w + kBlock - 1) / kBlock;
  std::vector<std::vector<std::pair<Vec2, Vec2>>> block_edges(static_cast<std::size_t>(blocks_x) *
                                                              ((ht + kBlock - 1) / kBlock));
  auto block_of = [&](int i, int j) {
    return static_cast<std::size_t>(j / kBlock) * blocks_x + i / kBlock;
  };
  {
    const double near = std::max(R, tol) + 2 * h;
    const double half_diag = kBlock * h * std::sqrt(2.0) / 2;
    std::vector<std::pair<Vec2, Vec2>> edges, local;
    for (const Ring& r : region.rings)
      for (std::size_t i = 0; i < r.size(); ++i)
        edges.push_back({r[i], r[(i + 1) % r.size()]});
    for (int bj = 0; bj < ht; bj += kBlock)
      for (int bi = 0; bi < w; bi += kBlock) {
        const Vec2 mid = centre(bi, bj) + Vec2{0.5 * (kBlock - 1) * h, 0.5 * (kBlock - 1) * h};
        local.clear();
        for (const auto& e : edges) {
          const double dist = segment_distance(mid, e.first, e.second);
          if (dist <= near + half_diag) local.push_back(e);
          if (dist <= 2 * h + half_diag) block_edges[block_of(bi, bj)].push_back(e);
        }
        if (local.empty()) continue;
        for (int j = bj; j < std::min(ht, bj + kBlock); ++j)
          for (int i = bi; i < std::min(w, bi + kBlock); ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            double best = std::numeric_limits<double>::infinity();
            for (const auto& e : local)
              best = std::min(best, segment_distance(centre(i, j), e.first, e.second));
            if (best <= near) wall_d[k] = static_cast<float>(best);
          }
      }
  }
  // The cell nearest to q, as (i, j); false where it lies off the image.
  auto nearest_cell = [&](Vec2 q, int& i, int& j) {
    i = static_cast<int>(std::lround((q.x - box.min.x) / h));
    j = static_cast<int>(std::lround((q.y - box.min.y) / h));
    return i >= 0 && j >= 0 && i < w && j < ht;
  };
  // Whether a point lies in the pocket, exactly: its cell's side, or within a pixel of a
  // wall the side of a cell centre off the edges (one on an edge has its side by the fill's
  // half-open rule, not the point's: this cell or a neighbour), changed by each edge
  // between the two. (i, j): the point's cell.
  auto point_inside = [&](Vec2 q, int i, int j) {
    const std::size_t c = static_cast<std::size_t>(j) * w + i;
    if (!(wall_d[c] < h)) return cell[c] != 0;
    int ri = i, rj = j;
    for (int n = 0; n < 9 && wall_d[static_cast<std::size_t>(rj) * w + ri] < 1e-9; ++n) {
      ri = std::clamp(i + n % 3 - 1, 0, w - 1);
      rj = std::clamp(j + n / 3 - 1, 0, ht - 1);
    }
    bool in = cell[static_cast<std::size_t>(rj) * w + ri] != 0;
    const Vec2 cc = centre(ri, rj);
    for (const auto& [a, b] : block_edges[block_of(i, j)])
      if (segments_cross(cc, q, a, b)) in = !in;
    return in;
  };
  // The tool disk stamped on an image: the cells whose centres lie within R that hold
  // `from` become `to`. Each call visits, row by row, only the cells outside the previous
  // call's disk on the same image: those inside it hold `from` no longer (nothing else
  // writes `from` back), so the count is the brute-force one at a fraction of the cost.
  struct Stamper {
    std::vector<unsigned char>* img;
    unsigned char from, to;
    bool has_last = false;
    Vec2 last{};
  };
  auto row_span = [&](Vec2 c, int j, int& i0, int& i1) {
    const double dy = box.min.y + j * h - c.y;
    const double half = std::sqrt(std::max(0.0, R * R - dy * dy));
    i0 = std::max(0, static_cast<int>(std::ceil((c.x - half - box.min.x) / h)));
    i1 = std::min(w - 1, static_cast<int>(std::floor((c.x + half - box.min.x) / h)));
  };
  auto rows = [&](Vec2 c, int& j0, int& j1) {
    j0 = std::max(0, static_cast<int>(std::ceil((c.y - R - box.min.y) / h)));
    j1 = std::min(ht - 1, static_cast<int>(std::floor((c.y + R - box.min.y) / h)));
  };
  auto stamp = [&](Stamper& st, Vec2 c) -> int {
    std::vector<unsigned char>& img = *st.img;
    int changed = 0;
    int j0 = 0, j1 = -1, l0 = 0, l1 = -1;
    rows(c, j0, j1);
    if (st.has_last) rows(st.last, l0, l1);
    auto visit = [&](int j, int i0, int i1) {
      for (int i = i0; i <= i1; ++i) {
        unsigned char& v = img[static_cast<std::size_t>(j) * w + i];
        if (v == st.from) {
          v = st.to;
          ++changed;
        }
      }
    };
    for (int j = j0; j <= j1; ++j) {
      int i0 = 0, i1 = -1;
      row_span(c, j, i0, i1);
      int a0 = 0, a1 = -1;
      if (st.has_last && j >= l0 && j <= l1) row_span(st.last, j, a0, a1);
      if (a0 > a1) {
        visit(j, i0, i1);
      } else {
        visit(j, i0, std::min(i1, a0 - 1));
        visit(j, std::max(i0, a1 + 1), i1);
      }
    }
    st.has_last = true;
    st.last = c;
    return changed;
  };
  const std::vector<Sample> samples = floor_samples(path, 0.5 * h);
  // What the program removes at some point: the arc counts contact with that material
  // only. A hair the tool never removes (closer to a wall than half a checker pixel beyond
  // the tool's edge, or the corner material no tool position reaches) touches the ring the
  // arc is read on without being engaged.
  std::vector<unsigned char> ever = cell;
  Stamper ever_stamper{&ever, 1, 2};
  for (const Sample& s : samples)
    stamp(ever_stamper, s.p);
  Stamper cut_stamper{&cell, 1, 2};
  double within = 0.0, within_any = 0.0, cutting_any = 0.0;
  // Removal measure (seed 000's definition: the material a move removes): area removed
  // over a window of path, as the stepover of a straight cut, as an angle.
  double win_len = 0.0, win_area = 0.0, within_removal = 0.0;
  Vec2 last{1e300, 1e300};
  double climb_mm = 0.0, one_sided_mm = 0.0;
  // The floor pass's headings over the last kTurnWindowMm of a connected stretch: a
  // heading more than kReversalDeg from the oldest one there is a reversal.
  constexpr double kTurnWindowMm = 1.0, kReversalDeg = 135.0;
  std::deque<std::pair<double, Vec2>> window;  // (path length so far, heading)
  double along = 0.0;
  auto flush = [&] {
    if (win_len <= 0.0) return;
    const double stepover = win_area / win_len;
    const double eng = rad_to_deg(std::acos(std::clamp(1.0 - stepover / R, -1.0, 1.0)));
    if (eng > 2.0) {
      rep.removal_cutting_length_mm += win_len;
      if (std::abs(eng - target_deg) <= 0.2 * target_deg) within_removal += win_len;
    }
    win_len = 0.0;
    win_area = 0.0;
  };
  for (const Sample& s : samples) {
    const double d = edge_distance(region, s.p);
    const double gouge = inside(region, s.p) ? R - d : R + d;
    rep.max_gouge_mm = std::max(rep.max_gouge_mm, gouge);
    double sample_eng = -1.0;
    if (!s.entry && !s.rapid) {
      // Engagement: front half of a circle just outside the tool, 1 degree apart, ring
      // sample k (0..179) at k - 89.5 degrees from the heading. Along a wall the circle would
      // cross the wall before the tool's edge does (acos(R / (R + h/2)), 5.7 degrees for a
      // ø10 at 0.05 mm), and which cells there count as inside depends on the wall's side and
      // slant: the same ride read 34-35 degrees along the bottom and left walls of a
      // rectangle and 26-27 along the top and right ones (session 47). Near a wall each ring
      // point's side is found by exact geometry, and a ray whose ring point lies beyond the
      // wall while the tool's edge does not reads as the material next to it along the ring:
      // a ride's band runs on to the wall, an arrival's sliver too (below).
      const double rr = R + 0.5 * h;
      const double base = std::atan2(s.dir.y, s.dir.x);
      std::array<RingState, 180> ring{};
      int n_any = 0;
      for (int k = 0; k < 180; ++k) {
        const double a = base + deg_to_rad(k - 89.5);
        const Vec2 u{std::cos(a), std::sin(a)};
        const Vec2 q = s.p + u * rr;
        int i = 0, j = 0;
        if (!nearest_cell(q, i, j)) {
          ring[k] = RingState::kBeyondWall;
          continue;
        }
        const std::size_t c = static_cast<std::size_t>(j) * w + i;
        n_any += cell[c] == 1 ? 1 : 0;
        if (wall_d[c] < h && !point_inside(q, i, j)) {
          // Beyond the wall while the tool's edge is not: the material between them is
          // thinner than half a pixel, and no cell reads it (the runs below).
          const Vec2 edge = s.p + u * R;
          int ei = 0, ej = 0;
          ring[k] = nearest_cell(edge, ei, ej) && point_inside(edge, ei, ej)
                        ? RingState::kUnknown
                        : RingState::kBeyondWall;
          continue;
        }
        // A point inside whose cell is not (within half a pixel of the wall) is not known
        // either.
        ring[k] = cell[c] == 0                   ? RingState::kUnknown
                  : cell[c] == 1 && ever[c] == 2 ? RingState::kEngaged
                                                 : RingState::kOther;
      }
      // A gap of one or two cut samples between engaged ones (or ones not known yet) is the
      // ring's rounding to cells: towards the sides of the front half the ring runs within
      // h/2 of the disks already swept, and a cell up to h/sqrt(2) nearer the tool than its
      // point can lie in one (a ride along a wall at 30 degrees lost 3-12 degrees of its
      // band so). Filled, it splits no run.
      auto engaged_or_unknown = [&](int k) {
        return k >= 0 && k < 180 &&
               (ring[k] == RingState::kEngaged || ring[k] == RingState::kUnknown);
      };
      for (int k = 1; k < 179; ++k) {
        if (ring[k] != RingState::kOther || !engaged_or_unknown(k - 1)) continue;
        const int next = engaged_or_unknown(k + 1)                                       ? k + 1
                         : ring[k + 1] == RingState::kOther && engaged_or_unknown(k + 2) ? k + 2
                                                                                         : -1;
        for (int t = k; t < next; ++t)
          ring[t] = RingState::kEngaged;  // the gap's end is engaged or unknown: nothing chains
      }
      // Runs of engaged samples and samples not known (beyond a wall the tool's edge has not
      // reached). A run with nothing engaged reads nothing. A run whose unknown samples lie
      // at one end, against the wall, and whose other end meets cut material is material
      // along the wall, read from that other end: its edge lies (R + h/2) cos(phi) from the
      // centre along the wall's normal, phi the end's angle from that normal, and the tool's
      // edge meets it acos((R + h/2) cos(phi) / R) from the normal (exact for a band along a
      // straight wall, however thin: a hair the ring touches at one cell reads its few
      // degrees, not the whole unknown stretch), never more than its length. Any other run
      // reads its length.
      double eng = 0.0, eng_left = 0.0;
      for (int k = 0; k < 180;) {
        if (ring[k] != RingState::kEngaged && ring[k] != RingState::kUnknown) {
          ++k;
          continue;
        }
        int e = k, engaged = 0, left = 0;
        for (; e < 180 && (ring[e] == RingState::kEngaged || ring[e] == RingState::kUnknown); ++e) {
          engaged += ring[e] == RingState::kEngaged ? 1 : 0;
          left += e >= 90 ? 1 : 0;
        }
        --e;
        const int size = e - k + 1;
        double read = engaged > 0 ? size : 0.0;
        if (engaged > 0 && engaged < size) {
          int unknown_lo = 0, unknown_hi = 0;
          while (ring[k + unknown_lo] == RingState::kUnknown)
            ++unknown_lo;
          while (ring[e - unknown_hi] == RingState::kUnknown)
            ++unknown_hi;
          const bool wall_lo =
              unknown_lo > 0 && unknown_hi == 0 && e < 179 && unknown_lo + engaged == size;
          const bool wall_hi =
              unknown_hi > 0 && unknown_lo == 0 && k > 0 && unknown_hi + engaged == size;
          if (wall_lo || wall_hi) {
            // The wall: the edge nearest to the outermost unknown sample's ring point.
            const int out_k = wall_lo ? k : e;
            const double a = base + deg_to_rad(out_k - 89.5);
            const Vec2 q = s.p + Vec2{std::cos(a), std::sin(a)} * rr;
            int qi = 0, qj = 0;
            nearest_cell(q, qi, qj);
            qi = std::clamp(qi, 0, w - 1);
            qj = std::clamp(qj, 0, ht - 1);
            double best = std::numeric_limits<double>::infinity();
            Vec2 foot{};
            for (const auto& [ea, eb] : block_edges[block_of(qi, qj)]) {
              const double dist = segment_distance(q, ea, eb);
              if (dist < best) {
                best = dist;
                const Vec2 ab = eb - ea;
                foot = ea + ab * (dot(s.p - ea, ab) / std::max(norm_sq(ab), 1e-300));
              }
            }
            const double line_d = norm(foot - s.p);
            if (best < h && line_d > 1e-9) {
              const Vec2 nrm = (foot - s.p) / line_d;
              const double far = base + deg_to_rad(wall_lo ? e - 89.0 : k - 90.0);
              const double x =
                  rr * dot(nrm, Vec2{std::cos(far), std::sin(far)});  // (R + h/2) cos(phi)
              // Never more than the run with its unknown stretch (a wall whose normal lies
              // elsewhere, as round an island's corner, is not the band's).
              read = std::min(read, rad_to_deg(std::acos(std::clamp(x / R, -1.0, 1.0))));
            }
          }
        }
        eng += read;
        eng_left += size > 0 ? read * left / size : 0.0;  // counter-clockwise of the heading
        k = e + 1;
      }
      if (n_any > 2) {
        cutting_any += s.ds;
        if (std::abs(n_any - target_deg) <= 0.2 * target_deg) within_any += s.ds;
      }
      sample_eng = eng;
      if (eng > 2.0) {
        rep.cutting_length_mm += s.ds;
        if (std::abs(eng - target_deg) <= 0.2 * target_deg) within += s.ds;
        rep.max_engagement_deg = std::max(rep.max_engagement_deg, eng);
        if (eng >= 170.0) rep.slot_length_mm += s.ds;
        const double eng_right = eng - eng_left;
        if (3 * std::max(eng_left, eng_right) >= 2 * eng) {
          one_sided_mm += s.ds;
          climb_mm += eng_right > eng_left ? s.ds : 0.0;
        }
      }
    }
    // Whether this sample goes on from the last one (not an entry, not after a gap).
    const bool joined = !s.entry && norm(s.p - last) <= 2.0 * s.ds + 1e-9;
    // Reversals, over connected stretches of the floor pass.
    if (!joined) {
      window.clear();
    } else {
      rep.floor_length_mm += s.ds;
      along += s.ds;
      window.push_back({along, s.dir});
      while (window.front().first < along - kTurnWindowMm)
        window.pop_front();
      const double turn =
          rad_to_deg(std::acos(std::clamp(dot(window.front().second, s.dir), -1.0, 1.0)));
      if (turn > kReversalDeg) {
        ++rep.reversals;
        window.clear();
      }
    }
    if (!joined || s.rapid) flush();
    last = s.p;
    if (s.rapid) continue;
    const int removed = stamp(cut_stamper, s.p);
    if (samples_out != nullptr)
      samples_out->push_back({s.p, s.ds, sample_eng, d, s.move, removed * h * h});
    if (!s.entry) {
      win_len += s.ds;
      win_area += removed * h * h;
      if (win_len >= removal_window_mm) flush();
    }
  }
  flush();
  if (rep.cutting_length_mm > 0) rep.within_20pct = within / rep.cutting_length_mm;
  if (cutting_any > 0) rep.within_20pct_any_material = within_any / cutting_any;
  if (one_sided_mm > 0) rep.climb_share = climb_mm / one_sided_mm;
  if (rep.removal_cutting_length_mm > 0)
    rep.within_20pct_removal = within_removal / rep.removal_cutting_length_mm;
  // Opening of the pocket by the disk: union of disks at centres >= R from every wall.
  std::vector<unsigned char> reach(cell.size(), 0);
  Stamper reach_stamper{&reach, 0, 1};
  for (int j = 0; j < ht; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      if (cell[k] == 0 || wall_d[k] < R) continue;
      // Only centres next to a non-centre matter (the rest lie inside their disks).
      bool edge = false;
      for (int dj = -1; dj <= 1 && !edge; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const std::size_t q = static_cast<std::size_t>(j + dj) * w + (i + di);
          if (cell[q] == 0 || wall_d[q] < R) edge = true;
        }
      if (edge)
        stamp(reach_stamper, centre(i, j));
      else
        reach[k] = 1;
    }
  for (std::size_t k = 0; k < cell.size(); ++k) {
    if (cell[k] == 0) continue;
    if (reach[k] == 0) {
      rep.unreachable_mm2 += h * h;
    } else if (cell[k] == 1 && wall_d[k] > tol) {
      rep.residual_mm2 += h * h;
      if (residual_out != nullptr)
        residual_out->push_back(centre(static_cast<int>(k % w), static_cast<int>(k / w)));
    }
  }
  return rep;
}

}  // namespace swarf::testing
