// The resume search of the adaptive pocket (our addition to seed 000): where the tool
// goes on once a boundary round has ended with reachable material left, and where a one-way
// pass starts along a front.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "pocket/distance_transform.h"

namespace swarf::pocket {

namespace {

// The directions, every 15 degrees, in which find_resume looks for a resume point round a
// pixel (computed once: sin and cos were a quarter of a run that searched long).
const std::array<Vec2, 24> kRingDirs = [] {
  std::array<Vec2, 24> d{};
  for (int a = 0; a < 360; a += 15)
    d[static_cast<std::size_t>(a / 15)] = {std::cos(deg_to_rad(a)), std::sin(deg_to_rad(a))};
  return d;
}();

// Less material than this left in all ends the search over the whole stock (unless a
// quarter of a step's worth is less still; the windowed search keeps the quarter step): the stated
// residual tolerance is 0.1 mm^2 per corner.
constexpr double kCrumbsLeftMm2 = 0.25;

// Whether the tool may stand at c over cleared floor: no gouge, and no material within half
// a pixel beyond its disk (a resume point, and the front's standoff when a pass backs up it).
bool clear_centre(const Model& m, const PixelStock& stock, Vec2 c) {
  // Material at the pixel nearest c (within the disk) answers first: most points a resume
  // search tries in untouched material fail there, at the cost of one bit.
  const Vec2 q = m.grid.to_px(c);
  const int i = round_half_away(q.x), j = round_half_away(q.y);
  if (i >= 0 && j >= 0 && i < m.grid.width && j < m.grid.height && stock.material().get(i, j))
    return false;
  return !stock.gouges(c) && stock.material_in_disk(c, m.radius_mm + 0.5 * m.h, 0) == 0;
}

}  // namespace

// A tool position with no material in its disk has cleared floor all round it: not
// forbidden (so in the pocket) and no material. Its nearest pixel is one whose neighbours
// half a tool radius away on all four sides are cleared floor too (well inside the disk).
// The pixels no tool position covers are not: the band a pixel or two wide along the walls
// and the corners of every untouched pocket (a square corner's is R long along each wall
// but at most 0.41 R from it). The blocks holding such pixels, grown by the ring in blocks
// (and a block and a half for the pixels' places in their blocks), hold every pixel a
// resume at that ring can be found for. Coarse and cheap (word-wise scans of the image and
// the dilation of an image 64 times smaller), where trying the ring round every pixel of
// the untouched pockets of a drawing of many took 44 % of its run.
BitImage cleared_reach(const Model& m, const PixelStock& stock, double ring_mm) {
  const BitImage& mat = stock.material();
  constexpr int kB = 1 << kReachBlockShift;
  const int w = mat.width(), h = mat.height(), nw = mat.words_per_row();
  BitImage blocks((w + kB - 1) / kB, (h + kB - 1) / kB);
  // The span, and the nearest pixel's 0.71 pixel off the position, within the disk; with
  // pixels coarser than that (a --resolution far above the rule's) every block may.
  const int span = static_cast<int>(0.5 * m.radius_mm / m.h);
  if (span < 1) {
    for (int j = 0; j < blocks.height(); ++j)
      blocks.set_span(j, 0, blocks.width() - 1);
    return blocks;
  }
  auto floor_word = [&](int j, int wd) {
    if (j < 0 || j >= h || wd < 0 || wd >= nw) return std::uint64_t{0};
    // (The pocket's word keeps the bits past the image's last column clear.)
    return m.pocket.word(j, wd) & ~m.forbidden.word(j, wd) & ~mat.word(j, wd);
  };
  // The floor's bits of columns x0 .. x0 + 63 of row j.
  auto floor_bits = [&](int j, int x0) {
    const int wd = x0 >= 0 ? x0 / 64 : -((63 - x0) / 64);
    const int off = x0 - 64 * wd;
    const std::uint64_t lo = floor_word(j, wd);
    return off == 0 ? lo : (lo >> off) | (floor_word(j, wd + 1) << (64 - off));
  };
  for (int j = 0; j < h; ++j) {
    for (int wd = 0; wd < nw; ++wd) {
      std::uint64_t core = floor_word(j, wd);
      if (core == 0) continue;
      // Bit i: pixel 64 wd + i, and its neighbours `span` left, right, below and above.
      core &= floor_bits(j, 64 * wd - span) & floor_bits(j, 64 * wd + span) &
              floor_word(j - span, wd) & floor_word(j + span, wd);
      for (int k = 0; k < 64 / kB; ++k) {
        if (((core >> (kB * k)) & ((std::uint64_t{1} << kB) - 1)) != 0)
          blocks.set(wd * (64 / kB) + k, j >> kReachBlockShift, true);
      }
    }
  }
  return dilate_by_disk(blocks, (ring_mm / m.h + 1.0) / kB + 2.0);
}

bool find_resume(const Model& m, const PixelStock& stock, Vec2 from, Vec2& at, Vec2& dir, int& pi,
                 int& pj, BitImage& given_up, double window_mm) {
  const BitImage& mat = stock.material();
  // A window (> 0) limits the search to material near `from`.
  int wi0 = 0, wi1 = mat.width() - 1, wj0 = 0, wj1 = mat.height() - 1;
  if (window_mm > 0.0) {
    const Vec2 c = m.grid.to_px(from);
    const double w = window_mm / m.h;
    wi0 = std::max(0, static_cast<int>(c.x - w));
    wi1 = std::min(mat.width() - 1, static_cast<int>(c.x + w));
    wj0 = std::max(0, static_cast<int>(c.y - w));
    wj1 = std::min(mat.height() - 1, static_cast<int>(c.y + w));
    if (wi0 > wi1 || wj0 > wj1) return false;
  }
  struct Px {
    double d2;
    int i, j;
  };
  // Without a window the rounds go on (trying twice as many pixels each round, up to 4096)
  // until a resume is found or too little is left: with a fixed 16 rounds of the 64
  // nearest pixels, a wedge the tool cannot finish near `from` used them all up and the
  // material farther away was never tried (the random pocket sweep found 200 mm^2 left
  // that way).
  const int rounds = window_mm > 0.0 ? 16 : 1 << 30;
  std::vector<Px> px;
  auto nearer = [](const Px& a, const Px& b) {
    return a.d2 != b.d2 ? a.d2 < b.d2 : (a.j != b.j ? a.j < b.j : a.i < b.i);
  };
  // Without a window: the material pixels not given up, gathered from a square round `from`
  // and sorted nearest first (up to `sorted`), are kept from round to round; `next` is the
  // first not tried yet, and those up to `sure` are nearer than any pixel outside the
  // square. A round gathers anew (a square twice as wide) only when its pixels run past
  // `sure`. Each round gathered its square afresh: before the entry into an untouched
  // pocket of a drawing of many, the search tried all its pixels, 4096 a round, and
  // gathering took 82 % of the run (18 round pockets: 13.5 s). The pixels tried, and their
  // order, are the same.
  std::size_t next = 0, sure = 0, sorted = 0;
  BitImage reach;  // cleared_reach, from the second round without a window
  double square_px = 16.0;
  // Material not given up, less each round by what it tried (the material does not change
  // during the search).
  std::size_t total = window_mm > 0.0 ? 0 : mat.count_all_except(given_up);
  for (int round = 0; round < rounds; ++round) {
    std::size_t tries = 0;
    if (window_mm > 0.0) {
      px.clear();
      // In a window, every third pixel each way is plenty to find the nearest material.
      // Word-wise: the columns wi0, wi0 + 3, ... of a word starting at column 64 w are its
      // bits b with b = wi0 - 64 w (mod 3), one of three fixed patterns.
      constexpr std::array<std::uint64_t, 3> kEveryThird = {
          0x9249249249249249ull, 0x2492492492492492ull, 0x4924924924924924ull};
      for (int j = wj0; j <= wj1; j += 3) {
        if (mat.count(j, wi0, wi1) == 0) continue;
        for (int w = wi0 >> 6; w <= (wi1 >> 6); ++w) {
          std::uint64_t bits = mat.word(j, w) & ~given_up.word(j, w) &
                               kEveryThird[static_cast<std::size_t>(((wi0 - 64 * w) % 3 + 3) % 3)];
          if (w == (wi0 >> 6)) bits &= ~std::uint64_t{0} << static_cast<unsigned>(wi0 & 63);
          if (w == (wi1 >> 6)) bits &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - (wi1 & 63));
          for (; bits != 0; bits &= bits - 1) {
            const int i = 64 * w + __builtin_ctzll(bits);
            px.push_back({norm_sq(m.grid.to_world(i, j) - from), i, j});
          }
        }
      }
      if (static_cast<double>(px.size()) * m.h * m.h < 0.25 * m.stepover_mm * m.step_mm)
        return false;
      tries = std::min<std::size_t>(px.size(), 12);
      std::partial_sort(px.begin(), px.begin() + static_cast<std::ptrdiff_t>(tries), px.end(),
                        nearer);
    } else {
      // The nearest `tries` of all material pixels not given up, gathered from a square
      // round `from` that doubles until it holds that many within its inscribed circle
      // (every pixel outside the square is farther): the same pixels as sorting them all,
      // which gathered the whole stock (up to a million pixels) at every session's end.
      if (static_cast<double>(total) * m.h * m.h <
          std::min(0.25 * m.stepover_mm * m.step_mm, kCrumbsLeftMm2))
        return false;
      tries = std::min<std::size_t>(total, std::size_t{64} << std::min(round, 6));
      const Vec2 c = m.grid.to_px(from);
      while (sure - next < tries) {
        square_px *= 2.0;
        const double w = square_px;
        const int i0 = std::max(0, static_cast<int>(std::floor(c.x - w)));
        const int i1 = std::min(mat.width() - 1, static_cast<int>(std::ceil(c.x + w)));
        const int j0 = std::max(0, static_cast<int>(std::floor(c.y - w)));
        const int j1 = std::min(mat.height() - 1, static_cast<int>(std::ceil(c.y + w)));
        const bool all = i0 == 0 && j0 == 0 && i1 == mat.width() - 1 && j1 == mat.height() - 1;
        const double inside2 = (w * m.h) * (w * m.h) * (1.0 - 1e-9);
        px.clear();
        next = 0;
        for (int j = j0; j <= j1 && i0 <= i1; ++j) {
          if (mat.count(j, i0, i1) == 0) continue;
          mat.for_each_set(j, i0, i1, [&](int i) {
            if (given_up.get(i, j)) return;
            px.push_back({norm_sq(m.grid.to_world(i, j) - from), i, j});
          });
        }
        // Those within the inscribed circle first (all of them once the square holds the
        // whole stock); they are sorted as the rounds need them.
        const auto inside_end = all ? px.end()
                                    : std::partition(px.begin(), px.end(),
                                                     [&](const Px& q) { return q.d2 <= inside2; });
        sure = static_cast<std::size_t>(inside_end - px.begin());
        sorted = 0;
        if (all) break;
      }
      tries = std::min(tries, sure - next);
      // The first round on a gather sorts only its own pixels (it mostly finds a resume);
      // a second sorts the rest at once (sorting each round's pixels out of the rest went
      // over the rest again every round).
      if (sorted < next + tries) {
        const auto from_sorted = px.begin() + static_cast<std::ptrdiff_t>(sorted);
        const auto inside_end = px.begin() + static_cast<std::ptrdiff_t>(sure);
        if (sorted == 0) {
          sorted = next + tries;
          std::partial_sort(from_sorted, px.begin() + static_cast<std::ptrdiff_t>(sorted),
                            inside_end, nearer);
        } else {
          std::sort(from_sorted, inside_end, nearer);
          sorted = sure;
        }
      }
    }
    // A resume point is half a step out of reach of the pixel. Near the last cut (a
    // window), where that point is held back only by crumbs at the walls, a step and a step
    // and a half out along the same direction are tried too, once no pixel has the first:
    // in a channel a millimetre or two wider than the tool, cleared from its end by
    // crescents, the crescents leave slivers at the walls beside the front, and every point
    // half a step behind the front had a few of them in its disk. No resume was found near
    // the front; the tool followed the boundary of the cut round to the channel's other
    // front and back, a crescent at each with a retract between (random part-like pocket
    // 2446, a ring channel round a boss: 23 lifts and 167 s, now 1 and 110 s; pocket 1046:
    // 11 lifts, now 6). Allowed for any material in the way, the farther points changed
    // paths everywhere for no gain (49 random pockets: +57 s, +12 lifts).
    const int rings = window_mm > 0.0 ? 3 : 1;
    // Whether the material in the disk at c, if any, lies within a pixel or two (at least
    // kWallCrumbMm) of the walls (beyond the wall stock).
    auto wall_crumbs_only = [&](Vec2 c) {
      const double rr = m.radius_mm + 0.5 * m.h;
      constexpr int kMostCrumbPx = 24;
      if (stock.material_in_disk(c, rr, kMostCrumbPx) > kMostCrumbPx) return false;
      const double crumb = m.wall_stock_mm + std::max(kWallCrumbMm, 2.0 * m.h);
      const BitImage& img = stock.material();
      bool crumbs = true;
      for_disk(m.grid, c, rr, [&](int i, int j) {
        crumbs = crumbs && (!img.get(i, j) || m.walls.distance(m.grid.to_world(i, j)) <= crumb);
      });
      return crumbs;
    };
    // A search past its first round without a window is likely to be going through
    // material no resume reaches (an untouched pocket of several): its pixels far from all
    // cleared floor are given up untried from then on.
    if (window_mm <= 0.0 && round == 1)
      reach = cleared_reach(m, stock, m.radius_mm + 0.5 * m.step_mm);
    const std::size_t first = window_mm > 0.0 ? 0 : next;
    for (int ring_k = 0; ring_k < rings; ++ring_k) {
      const double ring = m.radius_mm + 0.5 * (1 + ring_k) * m.step_mm;
      for (std::size_t k = first; k < first + tries; ++k) {
        if (reach.width() > 0 &&
            !reach.get(px[k].i >> kReachBlockShift, px[k].j >> kReachBlockShift))
          continue;
        const Vec2 q = m.grid.to_world(px[k].i, px[k].j);
        for (int a = 0; a < 360; a += (window_mm > 0.0 ? 30 : 15)) {
          const Vec2 u = kRingDirs[static_cast<std::size_t>(a / 15)];
          const Vec2 c = q + u * ring;
          if (ring_k > 0) {
            const Vec2 c1 = q + u * (m.radius_mm + 0.5 * m.step_mm);
            if (stock.gouges(c1) || !wall_crumbs_only(c1)) continue;
          }
          if (!clear_centre(m, stock, c)) continue;
          at = c;
          dir = -u;
          pi = px[k].i;
          pj = px[k].j;
          return true;
        }
      }
    }
    for (std::size_t k = first; k < first + tries; ++k)
      given_up.set(px[k].i, px[k].j, true);
    next += tries;
    total -= std::min(total, tries);
  }
  return false;
}

void trace_front_upstream(const Model& m, const PixelStock& stock, Vec2& at, Vec2& dir) {
  const double st = 2.0 * m.step_mm;
  // Turning by +a (in the paper's frame, sigma mirrors it) turns towards the material: for
  // climb it lies on the right of dir, so on the left of the way back.
  const double side = -static_cast<double>(m.sigma);
  Vec2 back = -dir;
  for (double gone = 0.0; gone < m.boundary_round_mm; gone += st) {
    int turn = 80;
    for (; turn >= -60; turn -= 10) {
      const Vec2 v = rotated(back, deg_to_rad(turn) * side);
      const Vec2 q = at + v * st;
      if (!clear_centre(m, stock, q)) continue;
      if (turn < 80) {
        at = q;
        back = v;
      }
      break;
    }
    // Free even turning hard towards the material: the front begins here. Nowhere free: a
    // wall or island in the way.
    if (turn == 80 || turn < -60) break;
  }
  dir = -back;
}

CentreComponents label_centre_components(const Model& m) {
  const int w = m.grid.width, h = m.grid.height;
  const auto is_free = [&](std::size_t q) {
    return m.free_centres.get(static_cast<int>(q % static_cast<std::size_t>(w)),
                              static_cast<int>(q / static_cast<std::size_t>(w)));
  };
  CentreComponents cc;
  cc.label.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), -1);
  std::vector<std::size_t> todo;
  for (std::size_t seed = 0; seed < cc.label.size(); ++seed) {
    if (cc.label[seed] >= 0 || !is_free(seed)) continue;
    const int id = static_cast<int>(cc.size.size());
    std::size_t n = 0;
    CentreComponents::Box b{w, h, -1, -1};
    cc.label[seed] = id;
    todo.push_back(seed);
    while (!todo.empty()) {
      const std::size_t q = todo.back();
      todo.pop_back();
      ++n;
      const int i = static_cast<int>(q % static_cast<std::size_t>(w));
      const int j = static_cast<int>(q / static_cast<std::size_t>(w));
      b = {std::min(b.i0, i), std::min(b.j0, j), std::max(b.i1, i), std::max(b.j1, j)};
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= w || jj >= h) continue;
          const std::size_t nq = m.grid.index(ii, jj);
          if (cc.label[nq] >= 0 || !m.free_centres.get(ii, jj)) continue;
          cc.label[nq] = id;
          todo.push_back(nq);
        }
      }
    }
    cc.size.push_back(n);
    cc.box.push_back(b);
    cc.free += n;
  }
  return cc;
}

void forget_given_up_near(const Model& m, const CentreComponents& cc, Vec2 centre,
                          BitImage& given_up) {
  const Vec2 q = m.grid.to_px(centre);
  const int i = static_cast<int>(std::lround(q.x)), j = static_cast<int>(std::lround(q.y));
  const bool on_grid = i >= 0 && j >= 0 && i < m.grid.width && j < m.grid.height;
  const int id = on_grid ? cc.label[m.grid.index(i, j)] : -1;
  if (id < 0 || cc.size[static_cast<std::size_t>(id)] == cc.free) {
    given_up = BitImage(m.grid.width, m.grid.height);
    return;
  }
  // The component's pixels, grown by what its cuts can change: the disks of its centres (R),
  // and the disks of resume points within R of those (2 R more), a step and two pixels.
  // Worked in a window round the component's box, its left edge on a word of the image
  // (over the whole image, a drawing of 100 round pockets spent a quarter of its run here).
  const double reach = (3.0 * m.radius_mm + m.step_mm) / m.h + 2.0;
  const int margin = static_cast<int>(std::ceil(reach)) + 1;
  const CentreComponents::Box& b = cc.box[static_cast<std::size_t>(id)];
  const int x0 = std::max(0, b.i0 - margin) / 64 * 64;
  const int x1 = std::min(m.grid.width - 1, b.i1 + margin);
  const int y0 = std::max(0, b.j0 - margin), y1 = std::min(m.grid.height - 1, b.j1 + margin);
  BitImage mine(x1 - x0 + 1, y1 - y0 + 1);
  for (int jj = b.j0; jj <= b.j1; ++jj) {
    for (int ii = b.i0; ii <= b.i1; ++ii) {
      if (cc.label[m.grid.index(ii, jj)] == id) mine.set(ii - x0, jj - y0, true);
    }
  }
  const BitImage near = dilate_by_disk(mine, reach);
  for (int jj = 0; jj < near.height(); ++jj) {
    for (int wd = 0; wd < near.words_per_row(); ++wd) {
      const int gw = x0 / 64 + wd;
      given_up.set_word(y0 + jj, gw, given_up.word(y0 + jj, gw) & ~near.word(jj, wd));
    }
  }
}

}  // namespace swarf::pocket
